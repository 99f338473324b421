// test_frame_warp.cpp: which carried pixels `carry_frame` calls faithful
// (frame_warp.h), against a brute-force reading of its rule on small
// hand-made frames: quadratic colours moved by a fraction of a pixel,
// whose bilinear samples err by exactly what the second differences say;
// faithful where that error is at most half the noise's standard
// deviation in every channel and the 4x4 pixels around the point lie in
// the frame; every pixel carried in place faithful, however curved.
#include "shots/frame_warp.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace {

using OIIO::ROI;
namespace mcd = mcdenoise;

const ROI dw(0, 16, 0, 12);
constexpr float noise_variance = 0.01f;  // a standard deviation of 0.1
constexpr float cx = 8.0f, cy = 6.0f;    // the quadratics' centre

// Channel c's colour at (x, y): a[c] (x - cx)^2 + b[c] (y - cy)^2 plus a
// ramp (which bilinear sampling carries exactly).
float colour_at(const float* a, const float* b, int c, float x, float y)
{
    return 0.5f + 0.01f * float(c + 1) * x + a[c] * (x - cx) * (x - cx) + b[c] * (y - cy) * (y - cy);
}

// The faithful plane of a frame of those colours carried one frame on by a
// uniform motion of (mx, my) pixels.
mcd::Plane<float> carried_faithful(const float* a, const float* b, float mx, float my)
{
    mcd::FeatureInputs src { { mcd::Planes<float>(dw, 1, 0.0f), mcd::IdPlane() },
                             { mcd::Planes<float>(dw, 3), mcd::Plane<float>(dw, 0.0f) },
                             { mcd::Planes<float>(dw, 3, noise_variance),
                               mcd::Plane<float>(dw, noise_variance) },
                             mcd::Planes<float>(dw, 3, 0.0f) };
    for (int c = 0; c < 3; ++c)
        for (int y = dw.ybegin; y < dw.yend; ++y)
            for (int x = dw.xbegin; x < dw.xend; ++x)
                *src.colour.colour.from(c, x, y) = colour_at(a, b, c, float(x), float(y));
    // Cycles' convention: the next frame's pixel is at (x - Z, y + W).
    mcd::GuideChannels motion(dw, 4, 0.0f);
    std::fill(motion.values[2].begin(), motion.values[2].end(), -mx);
    std::fill(motion.values[3].begin(), motion.values[3].end(), my);
    const mcd::Planes<float> excess(dw, 3, 0.0f);
    const mcd::CarriedFrame f = mcd::carry_frame(src, excess, dw, { &motion }, 1, { dw, dw, dw },
                                                 2);
    return f.faithful;
}

// The rule read brute force: at (x, y) moved by (mx, my) (0 < mx, my < 1),
// the bilinear sample of each channel against the quadratic's value there,
// each error at most half the noise's deviation, the 4x4 pixels inside.
float expected(const float* a, const float* b, float mx, float my, int x, int y)
{
    if (x - 1 < dw.xbegin || x + 2 >= dw.xend || y - 1 < dw.ybegin || y + 2 >= dw.yend)
        return 0.0f;
    for (int c = 0; c < 3; ++c) {
        const auto f = [&](float u, float v) { return colour_at(a, b, c, u, v); };
        const float X = float(x), Y = float(y);
        const float sample = (1 - mx) * (1 - my) * f(X, Y) + mx * (1 - my) * f(X + 1, Y)
                             + (1 - mx) * my * f(X, Y + 1) + mx * my * f(X + 1, Y + 1);
        if (std::abs(sample - f(X + mx, Y + my)) > 0.5f * std::sqrt(noise_variance))
            return 0.0f;
    }
    return 1.0f;
}

void expect_rule(const float* a, const float* b, float mx, float my)
{
    const mcd::Plane<float> got = carried_faithful(a, b, mx, my);
    for (int y = dw.ybegin; y < dw.yend; ++y)
        for (int x = dw.xbegin; x < dw.xend; ++x)
            EXPECT_EQ(got.at(x, y), expected(a, b, mx, my, x, y)) << "at " << x << ", " << y;
}

}  // namespace

TEST(FrameWarp, ResampledPixelIsFaithfulWhereItsErrorIsWithinHalfTheNoise)
{
    // Moved by (0.3, 0.2): the bilinear error 0.21 a + 0.16 b per channel,
    // against the allowed 0.05: 0.0475, 0.032 and 0.0105.
    const float a[3] = { 0.15f, 0.0f, 0.05f }, b[3] = { 0.1f, 0.2f, 0.0f };
    expect_rule(a, b, 0.3f, 0.2f);
    EXPECT_EQ(carried_faithful(a, b, 0.3f, 0.2f).at(5, 5), 1.0f);
    const float negative_a[3] = { -0.15f, 0.0f, -0.05f }, negative_b[3] = { -0.1f, -0.2f, 0.0f };
    expect_rule(negative_a, negative_b, 0.3f, 0.2f);
    EXPECT_EQ(carried_faithful(negative_a, negative_b, 0.3f, 0.2f).at(5, 5), 1.0f);
}

TEST(FrameWarp, ResampledPixelIsNotFaithfulWhereOneChannelErrsMore)
{
    // The first channel's error 0.042 + 0.016 = 0.058 > 0.05.
    const float a[3] = { 0.2f, 0.0f, 0.0f }, b[3] = { 0.1f, 0.0f, 0.0f };
    expect_rule(a, b, 0.3f, 0.2f);
    EXPECT_EQ(carried_faithful(a, b, 0.3f, 0.2f).at(5, 5), 0.0f);
    // The same curvature moved by half a pixel the other way: 0.25 (0.2 +
    // 0.1) = 0.075, not faithful; by a tenth (the cell from x - 1, 0.9 of
    // the way): 0.09 (0.2 + 0.1) = 0.027, faithful.
    EXPECT_EQ(carried_faithful(a, b, -0.5f, -0.5f).at(5, 5), 0.0f);
    EXPECT_EQ(carried_faithful(a, b, -0.1f, -0.1f).at(5, 5), 1.0f);
}

TEST(FrameWarp, CurvaturesOfOppositeSignsCountBothWays)
{
    // The sample's error is 0.21 a + 0.16 b = 0.042 - 0.032 = 0.010, but
    // the rule bounds it by 0.21 |a| + 0.16 |b| = 0.074: not faithful.
    const float a[3] = { 0.2f, 0.0f, 0.0f }, b[3] = { -0.2f, 0.0f, 0.0f };
    EXPECT_EQ(carried_faithful(a, b, 0.3f, 0.2f).at(5, 5), 0.0f);
}

TEST(FrameWarp, PixelCarriedInPlaceIsFaithfulEverywhere)
{
    const float a[3] = { 5.0f, 1.0f, 2.0f }, b[3] = { 3.0f, 0.0f, 4.0f };
    const mcd::Plane<float> got = carried_faithful(a, b, 0.0f, 0.0f);
    EXPECT_TRUE(std::all_of(got.values.begin(), got.values.end(), [](float v) { return v == 1.0f; }));
}
