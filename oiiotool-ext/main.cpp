// main.cpp: mcdtool's entry point: freed memory is kept for the next frame,
// temp files are removed on SIGINT and SIGTERM, then the program runs
// (driver.h).
#include "cleanup.h"
#include "driver.h"
#include "freed_memory.h"

#include <string>
#include <vector>

int main(int argc, char* argv[])
{
    mcdtool::keep_freed_memory_for_the_next_frame();
    mcdtool::install_interrupt_cleanup();
    return mcdtool::run_mcdtool(std::vector<std::string>(argv + 1, argv + argc));
}
