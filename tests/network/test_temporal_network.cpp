// test_temporal_network.cpp: the contract of the network's cross-frame
// denoise (denoise_network of NetworkFrames, mcdenoise/denoise_network.h):
// with no neighbours exactly the frame's own network result; on a still
// shot a convex average of the frames' results, closer to the truth than
// the frame's own; an object that moved without a motion guide leaves no
// trail; every bad frame refused with a message naming it.
// FAILS when the weights are missing: run scripts/fetch-weights.
#include <mcdenoise/mcdenoise.h>

#include "support/test_images.h"

#include <OpenImageIO/imagebufalgo.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

namespace {

using OIIO::ImageBuf;
using OIIO::ROI;
namespace IBA = OIIO::ImageBufAlgo;

constexpr int size = 64;

mcdenoise::NetworkOptions options()
{
    mcdenoise::NetworkOptions o;
    o.quality = mcdenoise::NetworkQuality::fast;
    const char* dir = std::getenv("MCD_WEIGHTS_DIR");
    o.weights_dir   = dir && *dir ? dir : MCD_WEIGHTS_DIR_DEFAULT;
    return o;
}

/// The noise-free frame: smooth shading with a sharp-edged bright square
/// `shift` pixels right of (20, 20), RGBA.
ImageBuf truth(float gain, int shift = 0)
{
    ImageBuf img(OIIO::ImageSpec(size, size, 4, OIIO::TypeDesc::FLOAT));
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const bool square = x >= 20 + shift && x < 44 + shift && y >= 20 && y < 44;
            const float base  = gain * (square ? 2.0f : 0.3f + 0.2f * std::sin(0.1f * float(x + y)));
            const float px[4] = { base, 0.8f * base, 0.6f * base, 1.0f };
            img.setpixel(x, y, px, 4);
        }
    return img;
}

/// `clean` with each colour value times an independent gamma-like factor
/// of mean 1 (a few samples' worth of noise), seeded by `seed`.
ImageBuf noisy(const ImageBuf& clean, uint32_t seed)
{
    ImageBuf img(clean.spec());
    std::mt19937 rng(seed);
    std::gamma_distribution<float> sample(4.0f, 0.25f);
    float px[4];
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            clean.getpixel(x, y, px, 4);
            for (int c = 0; c < 3; ++c)
                px[c] *= sample(rng);
            img.setpixel(x, y, px, 4);
        }
    return img;
}

/// relMSE of `a` against `ref` over the pixels of `region` (colour).
double rel_mse(const ImageBuf& a, const ImageBuf& ref, const ROI& region = ROI(0, size, 0, size))
{
    double sum = 0;
    for (int y = region.ybegin; y < region.yend; ++y)
        for (int x = region.xbegin; x < region.xend; ++x)
            for (int c = 0; c < 3; ++c) {
                const double r = ref.getchannel(x, y, 0, c), d = a.getchannel(x, y, 0, c) - r;
                sum += d * d / (r * r + 0.01);
            }
    return sum / (3.0 * double(region.npixels()));
}

bool identical(const ImageBuf& a, const ImageBuf& b)
{
    const IBA::CompareResults r = IBA::compare(a, b, 0.0f, 0.0f);
    return r.nfail == 0 && r.maxerror == 0.0;
}

/// A shot of `frames` noisy renders of `clean` (seeds 1, 2, ...).
struct Shot {
    std::vector<ImageBuf> beauties;
    std::vector<mcdenoise::NetworkFrame> frames;

    Shot(const std::vector<ImageBuf>& cleans)
    {
        for (size_t i = 0; i < cleans.size(); ++i)
            beauties.push_back(noisy(cleans[i], uint32_t(i + 1)));
        for (const ImageBuf& b : beauties)
            frames.push_back(mcdenoise::prepare_network_frame({ &b, {} }, options()));
    }
};

TEST(TemporalNetwork, NoNeighboursIsTheFramesOwnResult)
{
    const ImageBuf beauty = noisy(truth(1.0f), 7);
    const ImageBuf alone  = mcdenoise::denoise_network(beauty, {}, options());
    ASSERT_FALSE(alone.has_error()) << alone.geterror();
    const ImageBuf inputs = mcdenoise::denoise_network(mcdenoise::FrameInput { &beauty, {} }, {}, {},
                                                       options());
    const mcdenoise::NetworkFrame frame = mcdenoise::prepare_network_frame({ &beauty, {} }, options());
    const ImageBuf prepared = mcdenoise::denoise_network(frame, {}, {});
    ASSERT_FALSE(inputs.has_error()) << inputs.geterror();
    ASSERT_FALSE(prepared.has_error()) << prepared.geterror();
    EXPECT_TRUE(identical(inputs, alone));
    EXPECT_TRUE(identical(prepared, alone));
    EXPECT_EQ(prepared.spec().get_int_attribute("mcdenoise:denoise_frames"), 1);
}

TEST(TemporalNetwork, StillShotAveragesTheFramesResults)
{
    const ImageBuf clean = truth(1.0f);
    const Shot shot({ clean, clean, clean });
    for (const mcdenoise::NetworkFrame& f : shot.frames)
        ASSERT_TRUE(f.denoised) << f.error;
    const ImageBuf out = mcdenoise::denoise_network(shot.frames[1], { shot.frames[0], shot.frames[2] },
                                                    { -1, 1 });
    ASSERT_FALSE(out.has_error()) << out.geterror();
    EXPECT_EQ(out.spec().get_int_attribute("mcdenoise:denoise_frames"), 3);
    // A convex average of the three results at every pixel and channel.
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
            for (int c = 0; c < 4; ++c) {
                float lo = 1e30f, hi = -1e30f;
                for (const mcdenoise::NetworkFrame& f : shot.frames) {
                    lo = std::min(lo, f.denoised->getchannel(x, y, 0, c));
                    hi = std::max(hi, f.denoised->getchannel(x, y, 0, c));
                }
                const float v = out.getchannel(x, y, 0, c);
                ASSERT_GE(v, lo - 1e-6f * std::abs(lo)) << x << "," << y << " channel " << c;
                ASSERT_LE(v, hi + 1e-6f * std::abs(hi)) << x << "," << y << " channel " << c;
            }
    // Closer to the truth than the frame's own result: the frames' errors
    // are independent.
    const double own = rel_mse(*shot.frames[1].denoised, clean), shared = rel_mse(out, clean);
    EXPECT_LT(shared, 0.8 * own) << "own " << own << ", across frames " << shared;
}

TEST(TemporalNetwork, MovedObjectLeavesNoTrail)
{
    // The neighbour's bright square sits 12 pixels further right, with no
    // motion guide to say so: where only the neighbour has it, the result
    // is no worse than the frame's own (relMSE within 1.1x, the issue's
    // bound for pixels a motion uncovers); a trail of the square would be
    // many times worse.
    const ImageBuf clean = truth(1.0f);
    const Shot shot({ clean, truth(1.0f, 12) });
    const ImageBuf out = mcdenoise::denoise_network(shot.frames[0], { shot.frames[1] }, { 1 });
    ASSERT_FALSE(out.has_error()) << out.geterror();
    const ROI trail(44, 56, 20, 44);
    const double own = rel_mse(*shot.frames[0].denoised, clean, trail), across = rel_mse(out, clean, trail);
    EXPECT_LE(across, 1.1 * own) << "own " << own << ", across frames " << across;
}

TEST(TemporalNetwork, BadFramesAreNamed)
{
    const Shot shot({ truth(1.0f), truth(1.0f) });
    mcdenoise::NetworkFrame missing = shot.frames[1];
    missing.denoised.reset();
    ImageBuf out = mcdenoise::denoise_network(shot.frames[0], { missing }, { 1 });
    EXPECT_NE(out.geterror().find("neighbour frame at offset 1: no network result"), std::string::npos)
        << out.geterror();
    mcdenoise::NetworkFrame cropped = shot.frames[1];
    cropped.denoised = std::make_shared<ImageBuf>(IBA::cut(*shot.frames[1].denoised, ROI(0, 32, 0, 32, 0, 1, 0, 4)));
    out = mcdenoise::denoise_network(shot.frames[0], { cropped }, { 1 });
    EXPECT_NE(out.geterror().find("neighbour frame at offset 1: its network result does not cover its data window"),
              std::string::npos)
        << out.geterror();
    out = mcdenoise::denoise_network(shot.frames[0], { shot.frames[1] }, { 0 });
    EXPECT_NE(out.geterror().find("offsets must be non-zero and distinct"), std::string::npos) << out.geterror();
    const mcdenoise::NetworkFrame bad = mcdenoise::prepare_network_frame({ nullptr, {} }, options());
    EXPECT_FALSE(bad.denoised);
    EXPECT_FALSE(bad.error.empty());
    out = mcdenoise::denoise_network(bad, { shot.frames[1] }, { 1 });
    EXPECT_NE(out.geterror().find("centre frame"), std::string::npos) << out.geterror();
}

}  // namespace
