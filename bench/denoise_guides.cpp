// denoise_guides.cpp: what each guide buys the denoise preset: relMSE of
// `denoise` on every scene of the reference set with growing subsets of the
// guides, and the floor albedo demodulation would hit (the reference's
// irradiance remodulated with the noisy albedo), printed as the markdown
// table in docs/denoise.md.
//
// Usage: denoise_guides REFSET_DIR [SPP]   (e.g. build/bin/denoise_guides build/refset 16)
#include <mcdenoise/mcdenoise.h>

#include "support/render_file.h"

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

using testimg::Render;

/// A named subset of a render's guides.
struct GuideSubset {
    const char* name;
    mcdenoise::Guides (*pick)(const Render&);
};

const std::vector<GuideSubset>& subsets()
{
    static const std::vector<GuideSubset> all = {
        { "beauty only", [](const Render&) { return mcdenoise::Guides {}; } },
        { "+ halves", [](const Render& r) {
              mcdenoise::Guides g;
              g.half_a = &r.half_a;
              g.half_b = &r.half_b;
              return g;
          } },
        { "+ variance", [](const Render& r) {
              mcdenoise::Guides g;
              g.variance = &r.variance;
              return g;
          } },
        { "+ variance, normal, depth", [](const Render& r) {
              mcdenoise::Guides g;
              g.variance = &r.variance;
              g.normal   = &r.normal;
              g.depth    = &r.depth;
              return g;
          } },
        { "+ variance, normal, depth, albedo", [](const Render& r) {
              mcdenoise::Guides g = r.guides();
              g.object_id = g.half_a = g.half_b = nullptr;
              return g;
          } },
        { "every guide (+ object id)", [](const Render& r) { return r.guides(); } },
    };
    return all;
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc < 2) {
        std::fprintf(stderr, "usage: denoise_guides REFSET_DIR [SPP]\n");
        return 2;
    }
    const std::string dir = argv[1];
    const std::string spp = argc > 2 ? argv[2] : "16";
    const char* scenes[]  = { "cornell", "mirrors", "textured", "dof", "interior" };
    std::vector<Render> noisy, refs;
    for (const char* scene : scenes) {
        noisy.push_back(testimg::read_render(dir + "/" + scene + "_" + spp + ".exr"));
        refs.push_back(testimg::read_render(dir + "/" + scene + "_ref.exr"));
        for (const Render* r : { &noisy.back(), &refs.back() })
            if (!r->error.empty()) {
                std::fprintf(stderr, "denoise_guides: %s\n", r->error.c_str());
                return 1;
            }
    }
    std::printf("| denoise with (relMSE, %s spp) |", spp.c_str());
    for (const char* scene : scenes)
        std::printf(" %s |", scene);
    std::printf("\n|---|");
    for (size_t i = 0; i < std::size(scenes); ++i)
        std::printf("---|");
    std::printf("\n| raw render |");
    for (size_t i = 0; i < std::size(scenes); ++i)
        std::printf(" %.5f |", mcdenoise::rel_mse(noisy[i].beauty, refs[i].beauty));
    std::printf("\n");
    for (const GuideSubset& subset : subsets()) {
        std::printf("| %s |", subset.name);
        for (size_t i = 0; i < std::size(scenes); ++i) {
            const OIIO::ImageBuf out = mcdenoise::denoise(noisy[i].beauty, subset.pick(noisy[i]));
            if (out.has_error()) {
                std::fprintf(stderr, "denoise_guides: %s\n", out.geterror().c_str());
                return 1;
            }
            std::printf(" %.5f |", mcdenoise::rel_mse(out, refs[i].beauty));
        }
        std::printf("\n");
    }
    std::printf("| reference irradiance x noisy albedo (demodulation's floor) |");
    for (size_t i = 0; i < std::size(scenes); ++i) {
        const OIIO::ImageBuf irradiance = mcdenoise::demodulate(refs[i].beauty, refs[i].albedo);
        const OIIO::ImageBuf floor = mcdenoise::remodulate(irradiance, noisy[i].albedo);
        std::printf(" %.5f |", mcdenoise::rel_mse(floor, refs[i].beauty));
    }
    std::printf("\n");
    return 0;
}
