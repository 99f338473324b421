// aov_speed.cpp: what each extra light pass costs `denoise_layers`: the
// fastest of a few runs of `denoise` on a testrender frame's beauty, then of
// `denoise_layers` with 1, 2 and 4 of its 3-channel passes, printed as the
// table of docs/benchmarks.md.
//
// Usage: aov_speed FILE.exr [THREADS [RUNS]]   (a `testrender --passes` render)
#include <mcdenoise/mcdenoise.h>

#include "support/render_file.h"

#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

/// The fastest of `runs` calls of `fn`, in seconds.
template<class Fn>
double fastest(int runs, Fn&& fn)
{
    double best = 1e30;
    for (int i = 0; i < runs; ++i) {
        const auto start = std::chrono::steady_clock::now();
        fn();
        best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    return best;
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc < 2) {
        std::fprintf(stderr, "usage: aov_speed FILE.exr [THREADS [RUNS]]\n");
        return 2;
    }
    const int threads = argc > 2 ? std::atoi(argv[2]) : 1;
    const int runs    = argc > 3 ? std::atoi(argv[3]) : 3;
    const testimg::Render r = testimg::read_render(argv[1]);
    if (!r.error.empty()) {
        std::fprintf(stderr, "aov_speed: %s\n", r.error.c_str());
        return 1;
    }
    mcdenoise::Guides guides = r.guides();
    guides.object_id = nullptr;
    OIIO::ImageBuf file(argv[1]);
    std::vector<OIIO::ImageBuf> passes;
    for (const char* name : { "DiffInd", "DiffDir", "GlossInd", "GlossDir" }) {
        const std::string p = name;
        passes.push_back(OIIO::ImageBufAlgo::channels(file, 3, {}, {}, { p + ".R", p + ".G", p + ".B" }));
        if (passes.back().has_error() || !passes.back().initialized()) {
            std::fprintf(stderr, "aov_speed: %s has no %s pass\n", argv[1], name);
            return 1;
        }
    }
    const double alone = fastest(runs, [&] { mcdenoise::denoise(r.beauty, guides, {}, threads); });
    std::printf("| layers | seconds | added per layer (of the beauty's time) |\n|---|---|---|\n");
    std::printf("| 0 (`denoise`) | %.3f | |\n", alone);
    for (size_t n : { size_t(1), size_t(2), size_t(4) }) {
        std::vector<const OIIO::ImageBuf*> layers;
        for (size_t i = 0; i < n; ++i)
            layers.push_back(&passes[i]);
        const double t = fastest(runs, [&] {
            mcdenoise::denoise_layers(r.beauty, layers, guides, {}, threads);
        });
        std::printf("| %zu | %.3f | %.1f %% |\n", n, t, 100.0 * (t - alone) / alone / double(n));
    }
    return 0;
}
