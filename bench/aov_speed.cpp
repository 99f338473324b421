// aov_speed.cpp: what each extra light pass costs `denoise_layers`: the
// fastest of a few runs of `denoise` on a testrender frame's beauty, then of
// `denoise_layers` with 1, 2, 4 and all 8 of its 3-channel light passes,
// each with its rebuild's colour pass as mcdtool passes them (run in turn,
// the fastest of each kept), printed as the table of docs/aovs.md. Only
// all 8 rebuild the beauty, so only there are the passes corrected to add
// up (every pixel); with fewer the rebuild is checked and fails.
//
// Usage: aov_speed FILE.exr [THREADS [RUNS]]   (a `testrender --passes` render)
#include <mcdenoise/mcdenoise.h>

#include "support/render_file.h"

#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <utility>
#include <vector>

namespace {

/// CPU seconds of the process (every thread), which other programs on a
/// busy machine change far less than the wall time.
double cpu_seconds()
{
    timespec t {};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

/// Wall and CPU seconds of one call of `fn`.
template<class Fn>
std::pair<double, double> seconds(Fn&& fn)
{
    const auto start = std::chrono::steady_clock::now();
    const double cpu = cpu_seconds();
    fn();
    return { std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
             cpu_seconds() - cpu };
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
    const auto pass = [&](const std::string& p) {
        return OIIO::ImageBufAlgo::channels(file, 3, {}, {}, { p + ".R", p + ".G", p + ".B" });
    };
    // the light passes, and the colour each is multiplied by in the rebuild
    const std::vector<std::pair<std::string, std::string>> names = {
        { "DiffInd", "DiffCol" },   { "DiffDir", "DiffCol" },   { "GlossInd", "GlossCol" },
        { "GlossDir", "GlossCol" }, { "TransInd", "TransCol" }, { "TransDir", "TransCol" },
        { "Emit", "" },             { "Env", "" },
    };
    std::vector<OIIO::ImageBuf> passes, colours;
    for (const auto& [name, colour] : names) {
        passes.push_back(pass(name));
        colours.push_back(colour.empty() ? OIIO::ImageBuf() : pass(colour));
        if (passes.back().has_error() || !passes.back().initialized() || colours.back().has_error()) {
            std::fprintf(stderr, "aov_speed: %s has no %s pass or its colour\n", argv[1], name.c_str());
            return 1;
        }
    }
    // Round-robin over the configurations, the fastest run of each kept,
    // so a load that changes during the run hits them all alike.
    const std::vector<size_t> counts = { 0, 1, 2, 4, 8 };
    std::vector<double> best(counts.size(), 1e30), best_cpu(counts.size(), 1e30);
    for (int run = 0; run < runs; ++run)
        for (size_t k = 0; k < counts.size(); ++k) {
            std::vector<const OIIO::ImageBuf*> layers;
            std::vector<mcdenoise::LayerTerm> terms;
            for (size_t i = 0; i < counts[k]; ++i) {
                layers.push_back(&passes[i]);
                terms.push_back({ 0, colours[i].initialized() ? &colours[i] : nullptr });
            }
            const auto [wall, cpu] = seconds([&] {
                if (layers.empty())
                    mcdenoise::denoise(r.beauty, guides, {}, threads);
                else
                    mcdenoise::denoise_layers(r.beauty, layers, guides, terms, {}, threads);
            });
            best[k]     = std::min(best[k], wall);
            best_cpu[k] = std::min(best_cpu[k], cpu);
        }
    std::printf("| layers | wall s | added per layer (wall) | CPU s | added per layer (CPU) |\n"
                "|---|---|---|---|---|\n");
    std::printf("| 0 (`denoise`) | %.3f | | %.3f | |\n", best[0], best_cpu[0]);
    const auto added = [&](const std::vector<double>& t, size_t k) {
        return 100.0 * (t[k] - t[0]) / t[0] / double(counts[k]);
    };
    for (size_t k = 1; k < counts.size(); ++k)
        std::printf("| %zu | %.3f | %.1f %% | %.3f | %.1f %% |\n", counts[k], best[k], added(best, k),
                    best_cpu[k], added(best_cpu, k));
    return 0;
}
