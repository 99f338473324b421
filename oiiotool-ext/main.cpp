// main.cpp: mcdtool's entry point: temp files are removed on SIGINT and
// SIGTERM, then the program runs (driver.h).
#include "cleanup.h"
#include "driver.h"

#include <string>
#include <vector>

int main(int argc, char* argv[])
{
    mcdtool::install_interrupt_cleanup();
    return mcdtool::run_mcdtool(std::vector<std::string>(argv + 1, argv + argc));
}
