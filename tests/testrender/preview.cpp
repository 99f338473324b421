// preview.cpp: testrender_preview, which turns testrender EXRs into the PNG
// pictures of docs/testrender.md: beauty tiles in sRGB side by side, one
// file's AOVs (albedo, normals, depth, id and reflid false-coloured), its
// light passes, or the motion of several frames.
//
//   testrender_preview [--exposure E] --beauty A.exr [B.exr ...] -o sheet.png
//   testrender_preview --aovs A.exr -o sheet.png
//   testrender_preview [--exposure E] --passes A.exr -o sheet.png
//   testrender_preview --motion A.exr [B.exr ...] -o sheet.png
#include "rng.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace {

using OIIO::ImageBuf;
namespace IBA = OIIO::ImageBufAlgo;

ImageBuf select(const ImageBuf& src, const std::vector<std::string>& names)
{
    std::vector<int> order;
    for (const std::string& n : names)
        order.push_back(src.spec().channelindex(n));
    for (int c : order)
        if (c < 0)
            return {};
    return IBA::channels(src, int(order.size()), order);
}

/// Linear RGB to 8-bit-ready sRGB in [0, 1], after 2^exposure.
ImageBuf to_srgb(const ImageBuf& rgb, float exposure)
{
    ImageBuf scaled = IBA::mul(rgb, std::pow(2.0f, exposure));
    ImageBuf display = IBA::colorconvert(scaled, "linear", "sRGB");
    return IBA::clamp(display, 0.0f, 1.0f);
}

/// A pleasant, distinct colour per object id; black for negative ids.
void id_colour(float id, float* rgb)
{
    if (!(id >= 0)) {
        rgb[0] = rgb[1] = rgb[2] = 0;
        return;
    }
    const uint64_t h = testrender::mix64(uint64_t(std::lround(id)) + 12345);
    for (int c = 0; c < 3; ++c)
        rgb[c] = 0.25f + 0.75f * float((h >> (16 * c)) & 0xffff) / 65535.0f;
}

ImageBuf false_colour_ids(const ImageBuf& src, const std::string& channel)
{
    const int c = src.spec().channelindex(channel);
    ImageBuf out(OIIO::ImageSpec(src.spec().width, src.spec().height, 3, OIIO::TypeDesc::FLOAT));
    for (int y = 0; y < src.spec().height; ++y)
        for (int x = 0; x < src.spec().width; ++x) {
            float rgb[3];
            id_colour(src.getchannel(x, y, 0, c), rgb);
            out.setpixel(x, y, rgb, 3);
        }
    return out;
}

ImageBuf depth_grey(const ImageBuf& src)
{
    const int c = src.spec().channelindex("Z");
    float lo = std::numeric_limits<float>::max(), hi = 0;
    for (int y = 0; y < src.spec().height; ++y)
        for (int x = 0; x < src.spec().width; ++x) {
            const float z = src.getchannel(x, y, 0, c);
            if (std::isfinite(z)) {
                lo = std::min(lo, z);
                hi = std::max(hi, z);
            }
        }
    ImageBuf out(OIIO::ImageSpec(src.spec().width, src.spec().height, 3, OIIO::TypeDesc::FLOAT));
    for (int y = 0; y < src.spec().height; ++y)
        for (int x = 0; x < src.spec().width; ++x) {
            const float z = src.getchannel(x, y, 0, c);
            // near is white, far is dark grey, misses are black
            const float g = std::isfinite(z) ? 1.0f - 0.8f * (z - lo) / std::max(hi - lo, 1e-6f) : 0;
            const float rgb[3] = { g, g, g };
            out.setpixel(x, y, rgb, 3);
        }
    return out;
}

ImageBuf normals_rgb(const ImageBuf& src)
{
    ImageBuf n = select(src, { "N.X", "N.Y", "N.Z" });
    return IBA::clamp(IBA::mad(n, 0.5f, 0.5f), 0.0f, 1.0f);
}

/// The light passes the --passes sheet shows, left to right.
const char* const sheet_passes[] = { "DiffCol", "DiffDir", "DiffInd", "GlossCol", "GlossDir",
                                     "GlossInd", "TransInd", "Emit",    "Env" };

/// Motion vectors per pixel that saturate the --motion colours.
constexpr float motion_full_scale = 12;

/// The previous-frame motion (X, Y) as colour: red = X, green = Y, each
/// 0.5 + value / (2 full scale); 0.5 grey is no motion.
ImageBuf motion_rgb(const ImageBuf& src)
{
    const ImageBuf xy = select(src, { "motion.X", "motion.Y", "motion.Y" });
    const float k = 0.5f / motion_full_scale;
    const float scale[3] = { k, k, 0 }, offset[3] = { 0.5f, 0.5f, 0.5f };
    return IBA::clamp(IBA::mad(xy, OIIO::cspan<float>(scale), OIIO::cspan<float>(offset)), 0.0f,
                      1.0f);
}

int fail(const std::string& message)
{
    std::fprintf(stderr, "testrender_preview: error: %s\n", message.c_str());
    return 2;
}

}  // namespace

int main(int argc, char** argv)
{
    std::string mode, output;
    std::vector<std::string> inputs;
    float exposure = 0;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--beauty" || arg == "--aovs" || arg == "--passes" || arg == "--motion")
            mode = arg;
        else if (arg == "-o" && i + 1 < argc)
            output = argv[++i];
        else if (arg == "--exposure" && i + 1 < argc)
            exposure = std::stof(argv[++i]);
        else
            inputs.push_back(arg);
    }
    if (mode.empty() || output.empty() || inputs.empty())
        return fail("usage: testrender_preview [--exposure E] (--beauty A.exr [B.exr ...] | "
                    "--aovs A.exr | --passes A.exr | --motion A.exr [B.exr ...]) -o out.png");
    std::vector<ImageBuf> tiles;
    for (const std::string& in : inputs) {
        ImageBuf src(in);
        if (!src.read(0, 0, true, OIIO::TypeDesc::FLOAT))
            return fail(in + ": " + src.geterror());
        if (mode == "--beauty") {
            tiles.push_back(to_srgb(select(src, { "R", "G", "B" }), exposure));
        } else if (mode == "--passes") {
            for (const char* pass : sheet_passes) {
                const std::string p = pass;
                ImageBuf rgb = select(src, { p + ".R", p + ".G", p + ".B" });
                if (!rgb.initialized())
                    return fail(in + ": no " + p + " (render with --passes)");
                tiles.push_back(to_srgb(rgb, exposure));
            }
        } else if (mode == "--motion") {
            tiles.push_back(motion_rgb(src));
        } else {
            tiles.push_back(to_srgb(select(src, { "albedo.R", "albedo.G", "albedo.B" }), 0));
            tiles.push_back(normals_rgb(src));
            tiles.push_back(depth_grey(src));
            tiles.push_back(false_colour_ids(src, "id"));
            tiles.push_back(false_colour_ids(src, "reflid"));
        }
    }
    const int w = tiles[0].spec().width, h = tiles[0].spec().height;
    ImageBuf sheet(OIIO::ImageSpec(w * int(tiles.size()), h, 3, OIIO::TypeDesc::FLOAT));
    IBA::zero(sheet);
    for (size_t t = 0; t < tiles.size(); ++t)
        IBA::paste(sheet, int(t) * w, 0, 0, 0, tiles[t]);
    if (!sheet.write(output, OIIO::TypeDesc::UINT8))
        return fail(output + ": " + sheet.geterror());
    return 0;
}
