// freed_memory.h: how mcdtool (and the benchmarks that time what it does)
// keep freed memory for the next frame.
#pragma once

#if defined(__GLIBC__)
#    include <malloc.h>
#endif

namespace mcdtool {

/// Every frame of a sequence allocates the same large buffers (pixels,
/// guide planes, results). glibc gives blocks above 128 KiB-32 MiB back to
/// the kernel when they are freed, so each frame touched fresh pages again:
/// page faults were three quarters of `--gaussian 3` on a 1080p frame
/// (docs/notes/benchmarks.md). Served from the heap and never trimmed, the
/// next frame reuses the same pages; the peak is what one frame needs anyway.
inline void keep_freed_memory_for_the_next_frame()
{
#if defined(__GLIBC__)
    mallopt(M_MMAP_MAX, 0);
    mallopt(M_TRIM_THRESHOLD, -1);
#endif
}

}  // namespace mcdtool
