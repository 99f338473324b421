// denoise_table.cpp: the measurements of docs/denoise.md's energy and
// quality tables: for every scene of a testrender reference set at 4, 16, 64
// and 256 spp, the relMSE of the raw render, of the previous preset
// (clamp_fireflies, then nlmeans, every guide) and of `denoise`, the frame
// mean and the energy of the reference's brightest 0.5% of pixels each
// keeps, and the summary figures the issue targets.
//
// Usage: denoise_table REFSET_DIR   (e.g. build/bin/denoise_table build/refset)
#include <mcdenoise/mcdenoise.h>

#include "support/energy.h"
#include "support/render_file.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

using OIIO::ImageBuf;
using testimg::previous_preset;
using testimg::Render;

const char* const scenes[] = { "cornell", "mirrors", "textured", "dof",
                               "interior", "metal",  "bokeh",    "dim" };
const int spps[]           = { 4, 16, 64, 256 };

struct Row {
    double raw, previous, denoised, mean_prev, mean_new, top_prev, top_new;
};

}  // namespace

int main(int argc, char** argv)
{
    if (argc < 2) {
        std::fprintf(stderr, "usage: denoise_table REFSET_DIR\n");
        return 2;
    }
    const std::string dir = argv[1];
    std::printf("| scene | spp | raw | previous preset | denoise | previous / denoise | "
                "frame mean: previous | denoise | brightest 0.5%%: previous | denoise |\n"
                "|---|---|---|---|---|---|---|---|---|---|\n");
    double log_gain = 0.0;
    int gains = 0, below_256 = 0, below_64 = 0, worse_than_raw = 0;
    for (const char* scene : scenes) {
        const Render ref = testimg::read_render(dir + "/" + scene + "_ref.exr");
        if (!ref.error.empty()) {
            std::fprintf(stderr, "denoise_table: %s\n", ref.error.c_str());
            return 1;
        }
        std::vector<Row> rows;
        for (int spp : spps) {
            const Render r = testimg::read_render(dir + "/" + scene + "_" + std::to_string(spp)
                                                  + ".exr");
            if (!r.error.empty()) {
                std::fprintf(stderr, "denoise_table: %s\n", r.error.c_str());
                return 1;
            }
            const ImageBuf prev = previous_preset(r);
            const ImageBuf out  = mcdenoise::denoise(r.beauty, r.guides());
            const Row row { mcdenoise::rel_mse(r.beauty, ref.beauty),
                            mcdenoise::rel_mse(prev, ref.beauty),
                            mcdenoise::rel_mse(out, ref.beauty),
                            testimg::frame_mean_ratio(prev, ref.beauty),
                            testimg::frame_mean_ratio(out, ref.beauty),
                            testimg::brightest_energy_ratio(prev, ref.beauty),
                            testimg::brightest_energy_ratio(out, ref.beauty) };
            rows.push_back(row);
            std::printf("| %s | %d | %.5f | %.5f | %.5f | %.2f | %.3f | %.3f | %.3f | %.3f |\n",
                        scene, spp, row.raw, row.previous, row.denoised,
                        row.previous / row.denoised, row.mean_prev, row.mean_new, row.top_prev,
                        row.top_new);
            if (spp <= 64) {
                log_gain += std::log(row.previous / row.denoised);
                ++gains;
            }
            if (spp >= 64)
                worse_than_raw += row.denoised > row.raw;
        }
        below_256 += rows[1].denoised < rows[3].raw;
        below_64 += rows[1].denoised < rows[2].raw;
    }
    const int n = int(sizeof(scenes) / sizeof(scenes[0]));
    std::printf("\n- previous / denoise, geometric mean over scenes at 4, 16, 64 spp: %.3f\n"
                "- 16 spp denoise below raw 256 spp: %d of %d scenes; below raw 64 spp: %d of %d\n"
                "- denoise worse than its input at 64 or 256 spp: %d of %d cases\n",
                std::exp(log_gain / gains), below_256, n, below_64, n, worse_than_raw, 2 * n);
    return 0;
}
