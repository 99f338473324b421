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
        std::printf(" | %.5f | %.5f | %.5f |\n", m.temporal, m.flicker, m.region);
    }
}

// The pictures side by side, sRGB, each scaled up `zoom` times.
bool write_strip(const std::vector<ImageBuf>& pictures, const std::string& path, int zoom)
{
    const OIIO::ROI one = pictures.front().roi();
    ImageBuf strip(OIIO::ImageSpec(one.width() * int(pictures.size()), one.height(), 3,
                                   OIIO::TypeDesc::FLOAT));
    for (size_t i = 0; i < pictures.size(); ++i)
        IBA::paste(strip, one.width() * int(i), 0, 0, 0, pictures[i], OIIO::ROI(one.xbegin, one.xend, one.ybegin, one.yend, 0, 1, 0, 3));
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
        if (!write_strip(pictures, out + "/temporal_object.png", 2)) {
            std::fprintf(stderr, "temporal_table: could not write %s/temporal_object.png\n",
                         out.c_str());
            return 1;
        }
    }
    return 0;
}
