// bench_scene.cpp: reading the benchmarks' testrender scene once.
#include "bench_scene.h"

#include <cstdio>
#include <cstdlib>

namespace benchimg {

const testimg::Render& bench_scene(const char* program)
{
    static const testimg::Render r = [program] {
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
