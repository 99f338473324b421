// main.cpp: mcdtool's entry point: freed memory is kept for the next frame,
// temp files are removed on SIGINT and SIGTERM, then the program runs
// (driver.h).
#include "cleanup.h"
#include "driver.h"

#include <string>
#include <vector>

#if defined(__GLIBC__)
#    include <malloc.h>
#endif

namespace {

/// Every frame of a sequence allocates the same large buffers (pixels,
/// guide planes, results). glibc gives blocks above 128 KiB-32 MiB back to
/// the kernel when they are freed, so each frame touched fresh pages again:
/// page faults were three quarters of `--gaussian 3` on a 1080p frame
/// (docs/benchmarks.md). Served from the heap and never trimmed, the next
/// frame reuses the same pages; the peak is what one frame needs anyway.
void keep_freed_memory_for_the_next_frame()
{
#if defined(__GLIBC__)
    mallopt(M_MMAP_MAX, 0);
    mallopt(M_TRIM_THRESHOLD, -1);
#endif
}

}  // namespace

int main(int argc, char* argv[])
{
    keep_freed_memory_for_the_next_frame();
    mcdtool::install_interrupt_cleanup();
    return mcdtool::run_mcdtool(std::vector<std::string>(argv + 1, argv + argc));
}
