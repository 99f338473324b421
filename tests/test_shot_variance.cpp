// test_shot_variance.cpp: the noise a shot measures of itself
// (shot_variance.h) against a brute-force reading of its rule on small
// hand-made frames: the spread of the frames that agree with the centre,
// never below a frame's own variance; a neighbour left out where it was
// moved, where its features differ or where its box mean disagrees (a
// moving shadow); the own variance where fewer than three frames agree.
#include "shots/shot_variance.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace {

using OIIO::ROI;
namespace mcd = mcdenoise;

constexpr int side = 16;
const ROI dw(0, side, 0, side);
constexpr float own_variance = 0.01f;

// One frame's planes: a flat colour `base` with `peak` added at (px, py),
// the variance `own_variance`, one feature dimension `feature`, in place
// everywhere.
struct Frame {
    mcd::ColourField colour { mcd::Planes<float>(dw, 3), mcd::Plane<float>(dw) };
    mcd::VarianceField variance { mcd::Planes<float>(dw, 3, own_variance),
                                  mcd::Plane<float>(dw, own_variance) };
    mcd::FeatureField features { mcd::Planes<float>(dw, 1), mcd::IdPlane() };
    mcd::Plane<float> in_place { dw, 1.0f };

    Frame(float base, float peak, float feature, int px, int py)
    {
        for (int c = 0; c < 3; ++c)
            for (int y = 0; y < side; ++y)
                for (int x = 0; x < side; ++x)
                    *colour.colour.from(c, x, y) = base + (x == px && y == py ? peak : 0.0f);
        std::fill(features.dims.values[0].begin(), features.dims.values[0].end(), feature);
    }
};

std::vector<mcd::NlmFrame> nlm_frames(const std::vector<Frame>& frames)
{
    std::vector<mcd::NlmFrame> out;
    for (const Frame& f : frames)
        out.push_back({ &f.colour, &f.variance, &f.features, &frames[0].features, nullptr,
                        nullptr, 1, out.empty() });
    return out;
}

std::vector<mcd::VarianceField> measure(const std::vector<Frame>& frames)
{
    std::vector<const mcd::Plane<float>*> in_place;
    for (size_t k = 1; k < frames.size(); ++k)
        in_place.push_back(&frames[k].in_place);
    return mcd::shot_variance(nlm_frames(frames), in_place, dw, dw, 2);
}

// The sample variance of `v`, at least the own variance.
float expected(const std::vector<double>& v)
{
    double mean = 0.0, ss = 0.0;
    for (double x : v)
        mean += x / double(v.size());
    for (double x : v)
        ss += (x - mean) * (x - mean);
    return std::max(own_variance, float(ss / double(v.size() - 1)));
}

constexpr int px = 7, py = 8;

}  // namespace

TEST(ShotVariance, IsTheSpreadOfTheFramesThatAgree)
{
    const std::vector<Frame> frames { { 0.5f, 0.4f, 0.0f, px, py }, { 0.5f, 0.0f, 0.0f, px, py },
                                      { 0.5f, -0.2f, 0.0f, px, py }, { 0.5f, 0.1f, 0.0f, px, py } };
    const auto got = measure(frames);
    ASSERT_EQ(got.size(), frames.size());
    const float want = expected({ 0.9, 0.5, 0.3, 0.6 });
    ASSERT_GT(want, 4.0f * own_variance);
    for (const mcd::VarianceField& v : got)
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(*v.colour.from(c, px, py), want, 1e-6f);
            EXPECT_EQ(*v.colour.from(c, px + 1, py), own_variance);  // no spread there
        }
    // The luminance variance of features.h: sum of the weights squared
    // times each channel's.
    EXPECT_NEAR(got[0].luminance.at(px, py),
                want * (0.2126f * 0.2126f + 0.7152f * 0.7152f + 0.0722f * 0.0722f), 1e-6f);
}

TEST(ShotVariance, LeavesOutAMovedNeighbourAndAnotherSurface)
{
    std::vector<Frame> frames { { 0.5f, 0.4f, 0.0f, px, py }, { 0.5f, 0.0f, 0.0f, px, py },
                                { 0.5f, -0.2f, 0.0f, px, py }, { 0.5f, 0.1f, 0.0f, px, py },
                                { 0.5f, 0.3f, 3.0f, px, py } };  // features apart: weight exp(-9)
    frames[2].in_place.at(px, py) = 0.0f;                       // resampled there
    EXPECT_NEAR(*measure(frames)[1].colour.from(1, px, py), expected({ 0.9, 0.5, 0.6 }), 1e-6f);
}

TEST(ShotVariance, LeavesOutANeighbourWhoseBoxMeanDisagrees)
{
    // Frame 3 is 0.1 brighter everywhere (a shadow moved off): over the
    // box its mean differs by 0.1, far beyond the noise of a mean of
    // own_variance; frame 2 by 0.01, within it.
    const std::vector<Frame> frames { { 0.5f, 0.4f, 0.0f, px, py }, { 0.5f, 0.0f, 0.0f, px, py },
                                      { 0.51f, -0.2f, 0.0f, px, py }, { 0.6f, 0.1f, 0.0f, px, py } };
    EXPECT_NEAR(*measure(frames)[0].colour.from(0, px, py), expected({ 0.9, 0.5, 0.31 }), 1e-6f);
}

TEST(ShotVariance, KeepsTheOwnVarianceWhereFewerThanThreeAgree)
{
    std::vector<Frame> frames { { 0.5f, 0.4f, 0.0f, px, py }, { 0.5f, 0.0f, 0.0f, px, py },
                                { 0.5f, -0.2f, 0.0f, px, py } };
    frames[2].in_place.at(px, py) = 0.0f;
    for (const mcd::VarianceField& v : measure(frames))
        EXPECT_EQ(*v.colour.from(2, px, py), own_variance);
}
