// bench_scene.cpp: reading the benchmarks' testrender scene once, in a
// process that keeps freed memory as mcdtool does.
#include "bench_scene.h"

#include "freed_memory.h"

#include <cstdio>
#include <cstdlib>

namespace benchimg {

const testimg::Render& bench_scene(const char* program)
{
    static const testimg::Render r = [program] {
        // Repeated calls then time the filters, not glibc giving their
        // planes back to the kernel between calls (as mcdtool's frames).
        mcdtool::keep_freed_memory_for_the_next_frame();
        const char* path = std::getenv("MCD_BENCH_SCENE");
        testimg::Render loaded = testimg::read_render(path ? path : "");
        if (!loaded.error.empty()) {
            std::fprintf(stderr, "%s: set MCD_BENCH_SCENE to a testrender file (%s)\n", program,
                         loaded.error.c_str());
            std::exit(2);
        }
        return loaded;
    }();
    return r;
}

}  // namespace benchimg
