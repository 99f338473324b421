// test_denoise_network.cpp: the contract of denoise_network
// (mcdenoise/denoise_network.h) beyond its numbers, which
// check_rt_pipeline.py compares with an independent reference: tiled
// output equal to whole-image output, further channels and the ROI, in
// place, the weights chosen per quality and guides, and every bad input
// refused with a message naming it (a missing folder, a missing, truncated
// or corrupt weight file, too few channels, a guide that does not cover).
// FAILS when the weights are missing: run scripts/fetch-weights.
#include <mcdenoise/mcdenoise.h>

#include "support/test_images.h"

#include <OpenImageIO/imagebufalgo.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

using OIIO::ImageBuf;
using OIIO::ROI;
namespace fs = std::filesystem;

std::string weights_dir()
{
    const char* dir = std::getenv("MCD_WEIGHTS_DIR");
    return dir && *dir ? dir : MCD_WEIGHTS_DIR_DEFAULT;
}

mcdenoise::NetworkOptions options(mcdenoise::NetworkQuality quality)
{
    mcdenoise::NetworkOptions o;
    o.quality     = quality;
    o.weights_dir = weights_dir();
    return o;
}

/// A smooth HDR image times uniform noise: something the network works on.
/// Channels past the third keep the random values.
ImageBuf noisy_render(int width, int height, int nchannels, uint32_t seed)
{
    ImageBuf img = testimg::random_image(width, height, nchannels, seed);
    std::vector<float> px(static_cast<size_t>(nchannels));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            img.getpixel(x, y, px.data(), nchannels);
            for (int c = 0; c < std::min(nchannels, 3); ++c) {
                const float base = 0.5f + 0.4f * std::sin(0.01f * float(x + 20 * c)) * std::cos(0.013f * float(y));
                px[size_t(c)]    = 4.0f * base * (0.5f + px[size_t(c)]);
            }
            img.setpixel(x, y, px.data(), nchannels);
        }
    return img;
}

/// The largest |a - b| / (|b| + 0.01) over channels 0-2.
double worst_relative(const ImageBuf& a, const ImageBuf& b)
{
    double worst = 0;
    for (int y = b.ybegin(); y < b.yend(); ++y)
        for (int x = b.xbegin(); x < b.xend(); ++x)
            for (int c = 0; c < 3; ++c) {
                const double va = a.getchannel(x, y, 0, c), vb = b.getchannel(x, y, 0, c);
                worst = std::max(worst, std::abs(va - vb) / (std::abs(vb) + 0.01));
            }
    return worst;
}

TEST(DenoiseNetwork, TiledEqualsWholeImage)
{
    // 1000 x 820: with a budget of 1 byte the plan takes its smallest tiles
    // under a memory limit, 384 px sides (four overlaps of 96 px): 5 x 4 of
    // them, ceil((1000 - 192) / 192) by ceil((820 - 192) / 192).
    const ImageBuf beauty = noisy_render(1000, 820, 3, 1);
    auto whole_options    = options(mcdenoise::NetworkQuality::fast);
    auto tiled_options    = whole_options;
    tiled_options.memory_limit = 1;
    int tiles                  = 0;
    tiled_options.on_progress  = [&](double) { ++tiles; };
    const ImageBuf whole = mcdenoise::denoise_network(beauty, {}, whole_options);
    const ImageBuf tiled = mcdenoise::denoise_network(beauty, {}, tiled_options);
    ASSERT_FALSE(whole.has_error()) << whole.geterror();
    ASSERT_FALSE(tiled.has_error()) << tiled.geterror();
    EXPECT_EQ(tiles, 20);
    EXPECT_LE(worst_relative(tiled, whole), 1e-5);
    EXPECT_GT(worst_relative(whole, beauty), 0.05) << "the network changed nothing: the check is empty";
}

TEST(DenoiseNetwork, KeepsFurtherChannelsAndTheRoi)
{
    ImageBuf beauty = noisy_render(64, 48, 4, 2);
    const ROI roi(8, 40, 4, 36, 0, 1, 0, 4);
    ImageBuf dst = mcdenoise::denoise_network(beauty, {}, options(mcdenoise::NetworkQuality::fast), roi);
    ASSERT_FALSE(dst.has_error()) << dst.geterror();
    EXPECT_EQ(dst.roi(), roi);
    for (int y = roi.ybegin; y < roi.yend; ++y)
        for (int x = roi.xbegin; x < roi.xend; ++x)
            ASSERT_EQ(dst.getchannel(x, y, 0, 3), beauty.getchannel(x, y, 0, 3));
    EXPECT_EQ(dst.spec().get_string_attribute("mcdenoise:network"), "rt_hdr_small.tza");
    // In place equals into a new image.
    ImageBuf in_place = beauty;
    ASSERT_TRUE(mcdenoise::denoise_network(in_place, in_place, {}, options(mcdenoise::NetworkQuality::fast)));
    const ImageBuf fresh = mcdenoise::denoise_network(beauty, {}, options(mcdenoise::NetworkQuality::fast));
    EXPECT_TRUE(testimg::bit_identical(in_place, fresh));
}

TEST(DenoiseNetwork, ChoosesOidnsWeights)
{
    const ImageBuf beauty = noisy_render(32, 32, 3, 3);
    const ImageBuf albedo = testimg::random_image(32, 32, 3, 4);
    const ImageBuf normal = testimg::random_image(32, 32, 3, 5);
    const struct {
        mcdenoise::NetworkQuality quality;
        bool albedo, normal, prefilter;
        const char* networks;
    } cases[] = {
        { mcdenoise::NetworkQuality::high, true, true, true,
          "rt_hdr_calb_cnrm_large.tza,rt_alb_large.tza,rt_nrm_large.tza" },
        { mcdenoise::NetworkQuality::balanced, true, true, true, "rt_hdr_calb_cnrm.tza,rt_alb.tza,rt_nrm.tza" },
        { mcdenoise::NetworkQuality::fast, true, true, true, "rt_hdr_calb_cnrm_small.tza,rt_alb.tza,rt_nrm.tza" },
        { mcdenoise::NetworkQuality::high, true, true, false, "rt_hdr_alb_nrm.tza" },
        { mcdenoise::NetworkQuality::high, true, false, true, "rt_hdr_alb.tza,rt_alb_large.tza" },
        { mcdenoise::NetworkQuality::high, false, true, true, "rt_hdr.tza" },
        { mcdenoise::NetworkQuality::fast, false, false, true, "rt_hdr_small.tza" },
    };
    for (const auto& c : cases) {
        mcdenoise::Guides guides;
        guides.albedo  = c.albedo ? &albedo : nullptr;
        guides.normal  = c.normal ? &normal : nullptr;
        auto o         = options(c.quality);
        o.prefilter_guides = c.prefilter;
        const ImageBuf dst = mcdenoise::denoise_network(beauty, guides, o);
        ASSERT_FALSE(dst.has_error()) << dst.geterror();
        EXPECT_EQ(dst.spec().get_string_attribute("mcdenoise:network"), c.networks);
    }
}

/// A temporary folder of weights: the real ones, one of them damaged.
struct DamagedWeights {
    fs::path dir = fs::temp_directory_path() / ("mcd_weights_" + std::to_string(getpid()));
    DamagedWeights(const std::string& damaged, size_t keep_bytes)
    {
        fs::create_directories(dir);
        for (const auto& entry : fs::directory_iterator(weights_dir()))
            if (entry.path().extension() == ".tza" && entry.path().filename() != damaged)
                fs::copy_file(entry.path(), dir / entry.path().filename(), fs::copy_options::overwrite_existing);
        std::ifstream in(fs::path(weights_dir()) / damaged, std::ios::binary);
        std::vector<char> bytes(keep_bytes);
        in.read(bytes.data(), std::streamsize(bytes.size()));
        if (keep_bytes > 0)
            std::ofstream(dir / damaged, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
    }
    ~DamagedWeights() { fs::remove_all(dir); }
};

void expect_refused(const ImageBuf& beauty, const mcdenoise::Guides& guides,
                    const mcdenoise::NetworkOptions& o, const std::vector<std::string>& words)
{
    ImageBuf dst;
    EXPECT_FALSE(mcdenoise::denoise_network(dst, beauty, guides, o));
    const std::string error = dst.geterror();
    EXPECT_FALSE(dst.initialized()) << "a refused call must leave dst untouched";
    for (const std::string& word : words)
        EXPECT_NE(error.find(word), std::string::npos) << "'" << word << "' not in: " << error;
}

TEST(DenoiseNetwork, RefusesBadInputByName)
{
    const ImageBuf beauty = noisy_render(32, 32, 3, 6);
    auto o               = options(mcdenoise::NetworkQuality::fast);
    o.weights_dir        = "/nonexistent/weights";
    expect_refused(beauty, {}, o, { "/nonexistent/weights" });
    {
        DamagedWeights missing("rt_hdr_small.tza", 0);
        o.weights_dir = missing.dir.string();
        expect_refused(beauty, {}, o, { "rt_hdr_small.tza", "fetch-weights" });
    }
    {
        DamagedWeights truncated("rt_hdr_small.tza", 5000);
        o.weights_dir = truncated.dir.string();
        expect_refused(beauty, {}, o, { "rt_hdr_small.tza", "fetch-weights" });
    }
    const ImageBuf grey = noisy_render(32, 32, 2, 7);
    expect_refused(grey, {}, options(mcdenoise::NetworkQuality::fast), { "3 channels" });
    const ImageBuf small_albedo = testimg::random_image(16, 16, 3, 8);
    mcdenoise::Guides guides;
    guides.albedo = &small_albedo;
    expect_refused(beauty, guides, options(mcdenoise::NetworkQuality::fast), { "albedo" });
}

}  // namespace
