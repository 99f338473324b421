// quality_table.cpp: relMSE against the reference of every report filter at
// sizes 3 and 7 and the report's best chain, for each scene of a testrender
// reference set; prints a markdown table per scene (and, on `mirrors`, the
// relMSE over the specular pixels).
// Usage: quality_table REFSET_DIR [SPP...]
#include <mcdenoise/mcdenoise.h>

#include "support/render_file.h"

#include <OpenImageIO/imagebufalgo.h>

#include <cstdio>
#include <string>
#include <vector>

namespace {

const char* scenes[] = { "cornell", "mirrors", "textured", "dof", "interior" };

void print_scene(const std::string& dir, const std::string& scene, const std::vector<int>& spps)
{
    const testimg::Render ref = testimg::read_render(dir + "/" + scene + "_ref.exr");
    if (!ref.error.empty()) {
        std::fprintf(stderr, "quality_table: %s\n", ref.error.c_str());
        return;
    }
    std::vector<testimg::Render> renders;
    for (int spp : spps)
        renders.push_back(testimg::read_render(dir + "/" + scene + "_" + std::to_string(spp) + ".exr"));
    const bool mirrors = scene == "mirrors";
    OIIO::ImageBuf specular;
    if (mirrors)
        specular = OIIO::ImageBufAlgo::add(ref.reflect_id, 1.0f);  // 0 where reflid == -1
    const OIIO::ImageBuf inside = testimg::single_object_pixels(ref.object_id, 3);

    std::printf("\n### %s\n\n| filter |", scene.c_str());
    for (int spp : spps)
        std::printf(" %d spp | away from edges |%s", spp, mirrors ? " specular |" : "");
    std::printf("\n|---|");
    for (size_t i = 0; i < spps.size(); ++i)
        std::printf("---|---|%s", mirrors ? "---|" : "");
    std::printf("\n");
    auto row = [&](const std::string& name, auto&& filter) {
        std::printf("| %s |", name.c_str());
        for (const testimg::Render& r : renders) {
            const OIIO::ImageBuf out = filter(r);
            std::printf(" %.5f |", mcdenoise::rel_mse(out, ref.beauty));
            std::printf(" %.5f |", testimg::masked_rel_mse(out, ref.beauty, inside));
            if (mirrors)
                std::printf(" %.5f |", testimg::masked_rel_mse(out, ref.beauty, specular));
        }
        std::printf("\n");
    };
    row("raw", [](const testimg::Render& r) { return r.beauty; });
    for (const testimg::NamedFilter& f : testimg::report_filters())
        row(f.name, f.run);
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc < 2) {
        std::fprintf(stderr, "usage: quality_table REFSET_DIR [SPP...]\n");
        return 2;
    }
    std::vector<int> spps;
    for (int i = 2; i < argc; ++i)
        spps.push_back(std::atoi(argv[i]));
    if (spps.empty())
        spps = { 16, 32 };
    for (const char* scene : scenes)
        print_scene(argv[1], scene, spps);
    return 0;
}
