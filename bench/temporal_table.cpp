// temporal_table.cpp: the figures of docs/temporal.md: every method on the
// shot set's three shots, as Markdown tables; with --figures DIR also the
// CSV of one static-shot pixel over the frames and the moving-object
// pictures (PNG) that bench/temporal_figures.py turns into docs images.
//
// Usage: temporal_table SHOTSET_DIR [--figures DIR]
#include "support/shot.h"
#include "support/shot_figures.h"

#include <OpenImageIO/imagebufalgo.h>

#include <cstdio>
#include <fstream>
#include <string>

namespace {

using OIIO::ImageBuf;
namespace IBA = OIIO::ImageBufAlgo;

void print_table(const testimg::ShotFigures& f)
{
    std::printf("\n%s, N = %d, frames", f.shot.c_str(), f.n);
    for (int t : f.evaluated)
        std::printf(" %d", t);
    std::printf("\n\n| method | relMSE | per frame | temporal error | flicker | region relMSE |\n"
                "|---|---|---|---|---|---|\n");
    const auto all = testimg::methods(f);
    for (size_t k = 0; k < all.size(); ++k) {
        const testimg::MethodFigures& m = *all[k];
        std::printf("| %s | %.5f |", testimg::method_names()[k].c_str(), m.rel_mse);
        for (double r : m.frame_rel_mse)
            std::printf(" %.4f", r);
        // "-" where the shot does not measure it
        const auto cell = [](bool measured, double v) {
            if (measured)
                std::printf(" %.5f |", v);
            else
                std::printf(" - |");
        };
        std::printf(" |");
        cell(f.evaluated.size() > 1, m.temporal);
        cell(m.flicker > 0.0, m.flicker);
        cell(m.region > 0.0, m.region);
        std::printf("\n");
    }
}

// The `crop` of the pictures side by side, sRGB, scaled up `zoom` times.
bool write_strip(const std::vector<ImageBuf>& pictures, const OIIO::ROI& crop,
                 const std::string& path, int zoom)
{
    ImageBuf strip(OIIO::ImageSpec(crop.width() * int(pictures.size()), crop.height(), 3,
                                   OIIO::TypeDesc::FLOAT));
    for (size_t i = 0; i < pictures.size(); ++i)
        IBA::paste(strip, crop.width() * int(i), 0, 0, 0, IBA::cut(pictures[i], crop));
    const OIIO::ROI big(0, strip.spec().width * zoom, 0, strip.spec().height * zoom, 0, 1, 0, 3);
    ImageBuf out = IBA::resize(IBA::colorconvert(IBA::clamp(strip, 0.0f, 1.0f), "linear", "sRGB"),
                               "box", 0, big);
    return out.write(path, OIIO::TypeDesc::UINT8);
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc != 2 && !(argc == 4 && std::string(argv[2]) == "--figures")) {
        std::fprintf(stderr, "usage: temporal_table SHOTSET_DIR [--figures DIR]\n");
        return 2;
    }
    const std::string dir = argv[1];
    const testimg::ShotFigures shots[] = { testimg::static_figures(dir),
                                           testimg::truck_figures(dir),
                                           testimg::object_figures(dir) };
    for (const auto& f : shots) {
        if (!f.error.empty()) {
            std::fprintf(stderr, "temporal_table: %s: %s\n", f.shot.c_str(), f.error.c_str());
            return 1;
        }
        print_table(f);
    }
    if (argc == 4) {
        const std::string out = argv[3];
        std::ofstream(out + "/temporal_pixel.csv") << testimg::static_pixel_csv(dir, 30, 60, 1);
        std::vector<ImageBuf> pictures = shots[2].pictures;
        pictures.erase(pictures.begin() + 4);  // the cross-frame denoise without motion
        // the sphere at frame 2 and where it and its shadow were (96x96 shots)
        const OIIO::ROI around_sphere(28, 92, 44, 92, 0, 1, 0, 3);
        if (!write_strip(pictures, around_sphere, out + "/temporal_object.png", 3)) {
            std::fprintf(stderr, "temporal_table: could not write %s/temporal_object.png\n",
                         out.c_str());
            return 1;
        }
    }
    return 0;
}
