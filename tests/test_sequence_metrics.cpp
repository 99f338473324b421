// test_sequence_metrics.cpp: per-frame relMSE, temporal error and flicker
// against a brute-force computation straight from their definitions
// (all frames in memory, two-pass variance), a case small enough to do by
// hand, non-finite pixels left out, errors reported, the frame-by-frame
// form equal to the all-at-once one, and the same numbers for any thread
// count.
#include <mcdenoise/mcdenoise.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {

using OIIO::ImageBuf;
using OIIO::ImageSpec;
using OIIO::ROI;

constexpr double eps = mcdenoise::rel_mse_epsilon;

ImageBuf make_image(int w, int h, int nch, const std::vector<float>& values, int x0 = 0, int y0 = 0)
{
    ImageSpec spec(w, h, nch, OIIO::TypeDesc::FLOAT);
    spec.x = x0;
    spec.y = y0;
    ImageBuf img(spec);
    img.set_pixels(img.roi(), OIIO::TypeDesc::FLOAT, values.data());
    return img;
}

/// A shot of `frames` w x h x nch frames: a smooth picture that drifts,
/// plus noise of amplitude `noise` drawn from `seed`.
std::vector<std::vector<float>> shot(int frames, int w, int h, int nch, float noise, unsigned seed)
{
    std::mt19937 rng(seed);
    std::normal_distribution<float> gauss(0.0f, noise);
    std::vector<std::vector<float>> out(static_cast<size_t>(frames));
    for (int t = 0; t < frames; ++t)
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                for (int c = 0; c < nch; ++c)
                    out[size_t(t)].push_back(0.3f + 0.2f * std::sin(0.4f * float(x + t) + float(c))
                                             + 0.1f * float(y) / float(h) + gauss(rng));
    return out;
}

/// The three figures straight from the definitions, over the first `nch`
/// channels, every value finite.
struct Brute {
    std::vector<double> frame_rel_mse;
    double temporal = 0, flicker = 0;
};

Brute brute_force(const std::vector<std::vector<float>>& x, const std::vector<std::vector<float>>& r)
{
    Brute b;
    const size_t n = x.size(), values = x[0].size();
    for (size_t t = 0; t < n; ++t) {
        double sum = 0;
        for (size_t i = 0; i < values; ++i) {
            const double d = double(x[t][i]) - double(r[t][i]);
            sum += d * d / (double(r[t][i]) * double(r[t][i]) + eps);
        }
        b.frame_rel_mse.push_back(sum / double(values));
    }
    for (size_t t = 1; t < n; ++t) {
        double sum = 0;
        for (size_t i = 0; i < values; ++i) {
            const double dx = double(x[t][i]) - double(x[t - 1][i]);
            const double dr = double(r[t][i]) - double(r[t - 1][i]);
            sum += (dx - dr) * (dx - dr) / (dr * dr + eps);
        }
        b.temporal += sum / double(values) / double(n - 1);
    }
    for (size_t i = 0; i < values; ++i) {
        double mean = 0, reference = 0, variance = 0;
        for (size_t t = 0; t < n; ++t) {
            mean += double(x[t][i]) / double(n);
            reference += double(r[t][i]) / double(n);
        }
        for (size_t t = 0; t < n; ++t)
            variance += (double(x[t][i]) - mean) * (double(x[t][i]) - mean) / double(n);
        b.flicker += variance / (reference * reference + eps) / double(values);
    }
    return b;
}

std::vector<ImageBuf> images(const std::vector<std::vector<float>>& frames, int w, int h, int nch)
{
    std::vector<ImageBuf> out;
    for (const auto& f : frames)
        out.push_back(make_image(w, h, nch, f));
    return out;
}

std::vector<const ImageBuf*> pointers(const std::vector<ImageBuf>& frames)
{
    std::vector<const ImageBuf*> out;
    for (const ImageBuf& f : frames)
        out.push_back(&f);
    return out;
}

TEST(SequenceMetrics, MatchTheBruteForceDefinitions)
{
    const int w = 13, h = 9, nch = 3, frames = 5;
    const auto x = shot(frames, w, h, nch, 0.05f, 1);
    const auto r = shot(frames, w, h, nch, 0.01f, 2);
    const Brute b = brute_force(x, r);
    const auto xs = images(x, w, h, nch), rs = images(r, w, h, nch);
    const mcdenoise::SequenceComparison s = mcdenoise::compare_sequence(pointers(xs), pointers(rs));
    ASSERT_TRUE(s.ok) << s.error;
    ASSERT_EQ(s.frames, frames);
    ASSERT_EQ(s.frame_rel_mse.size(), size_t(frames));
    double mean = 0;
    for (int t = 0; t < frames; ++t) {
        EXPECT_NEAR(s.frame_rel_mse[size_t(t)], b.frame_rel_mse[size_t(t)], 1e-9 * b.frame_rel_mse[size_t(t)]);
        mean += b.frame_rel_mse[size_t(t)] / frames;
    }
    EXPECT_NEAR(s.mean_rel_mse, mean, 1e-9 * mean);
    EXPECT_NEAR(s.temporal_error, b.temporal, 1e-9 * b.temporal);
    EXPECT_NEAR(s.flicker, b.flicker, 1e-9 * b.flicker);
    EXPECT_EQ(s.pixels, w * h);
    EXPECT_EQ(mcdenoise::temporal_error(pointers(xs), pointers(rs)), s.temporal_error);
    EXPECT_EQ(mcdenoise::flicker(pointers(xs), pointers(rs)), s.flicker);
}

// Two frames of one pixel, one channel, by hand: result 0.5 then 0.7,
// reference 0.5 then 0.6. Temporal: (0.2 - 0.1)^2 / (0.01 + 0.01) = 0.5.
// Flicker: variance of (0.5, 0.7) = 0.01, reference mean 0.55:
// 0.01 / (0.3025 + 0.01) = 0.032.
TEST(SequenceMetrics, TwoFramesByHand)
{
    const ImageBuf x0 = make_image(1, 1, 1, { 0.5f }), x1 = make_image(1, 1, 1, { 0.7f });
    const ImageBuf r0 = make_image(1, 1, 1, { 0.5f }), r1 = make_image(1, 1, 1, { 0.6f });
    const auto s = mcdenoise::compare_sequence({ &x0, &x1 }, { &r0, &r1 });
    ASSERT_TRUE(s.ok) << s.error;
    EXPECT_NEAR(s.frame_rel_mse[0], 0.0, 1e-12);
    EXPECT_NEAR(s.frame_rel_mse[1], 0.01 / (0.36 + 0.01), 1e-6);
    EXPECT_NEAR(s.temporal_error, 0.5, 1e-5);
    EXPECT_NEAR(s.flicker, 0.01 / 0.3125, 1e-6);
}

TEST(SequenceMetrics, AStillCorrectResultHasNoTemporalErrorAndNoFlicker)
{
    const int w = 6, h = 4, nch = 3;
    const auto r = shot(1, w, h, nch, 0.0f, 3);
    const std::vector<std::vector<float>> same = { r[0], r[0], r[0] };
    const auto xs = images(same, w, h, nch);
    const auto s = mcdenoise::compare_sequence(pointers(xs), pointers(xs));
    ASSERT_TRUE(s.ok) << s.error;
    EXPECT_EQ(s.temporal_error, 0.0);
    EXPECT_EQ(s.flicker, 0.0);
    EXPECT_EQ(s.mean_rel_mse, 0.0);
}

TEST(SequenceMetrics, FrameByFrameEqualsAllAtOnceForAnyThreadCount)
{
    const int w = 40, h = 33, nch = 4, frames = 4;
    const auto xs = images(shot(frames, w, h, nch, 0.1f, 4), w, h, nch);
    const auto rs = images(shot(frames, w, h, nch, 0.02f, 5), w, h, nch);
    const auto all = mcdenoise::compare_sequence(pointers(xs), pointers(rs), {}, 1);
    ASSERT_TRUE(all.ok) << all.error;
    for (int threads : { 0, 2, 3, 7 }) {
        mcdenoise::SequenceSums sums = mcdenoise::start_sequence({}, threads);
        for (int t = 0; t < frames; ++t)
            ASSERT_TRUE(mcdenoise::add_sequence_frame(sums, xs[size_t(t)], rs[size_t(t)]));
        const auto fed = mcdenoise::sequence_comparison(sums);
        EXPECT_EQ(fed.temporal_error, all.temporal_error) << threads;
        EXPECT_EQ(fed.flicker, all.flicker) << threads;
        EXPECT_EQ(fed.frame_rel_mse, all.frame_rel_mse) << threads;
    }
}

TEST(SequenceMetrics, NonFinitePixelsAreLeftOut)
{
    const int w = 5, h = 3, nch = 3, frames = 3;
    auto x = shot(frames, w, h, nch, 0.05f, 6);
    const auto r = shot(frames, w, h, nch, 0.01f, 7);
    auto clean_x = x, clean_r = r;
    // pixel 4 is NaN in frame 1 of the result: out of the pairs (0,1) and
    // (1,2) and of the flicker; compared with the shot without pixel 4
    x[1][4 * nch + 1] = std::numeric_limits<float>::quiet_NaN();
    for (auto* frames_of : { &clean_x, &clean_r })
        for (auto& f : *frames_of)
            f.erase(f.begin() + 4 * nch, f.begin() + 5 * nch);
    const Brute b = brute_force(clean_x, clean_r);
    const auto xs = images(x, w, h, nch), rs = images(r, w, h, nch);
    const auto s = mcdenoise::compare_sequence(pointers(xs), pointers(rs));
    ASSERT_TRUE(s.ok) << s.error;
    EXPECT_NEAR(s.temporal_error, b.temporal, 1e-9 * b.temporal);
    EXPECT_NEAR(s.flicker, b.flicker, 1e-9 * b.flicker);
    EXPECT_EQ(s.pixels, w * h - 1);
    EXPECT_NEAR(s.frame_rel_mse[1], b.frame_rel_mse[1], 1e-9 * b.frame_rel_mse[1]);
}

TEST(SequenceMetrics, OneFrameHasNoTemporalFigures)
{
    const ImageBuf x = make_image(1, 1, 1, { 0.5f });
    const auto s = mcdenoise::compare_sequence({ &x }, { &x });
    ASSERT_TRUE(s.ok) << s.error;
    EXPECT_TRUE(std::isnan(s.temporal_error));
    EXPECT_TRUE(std::isnan(s.flicker));
    EXPECT_EQ(s.mean_rel_mse, 0.0);
}

TEST(SequenceMetrics, ErrorsNameTheFrame)
{
    const ImageBuf a = make_image(4, 4, 3, std::vector<float>(48, 0.5f));
    const ImageBuf shifted = make_image(4, 4, 3, std::vector<float>(48, 0.5f), 2, 0);
    const ImageBuf grey = make_image(4, 4, 1, std::vector<float>(16, 0.5f));
    auto s = mcdenoise::compare_sequence({ &a, &shifted }, { &a, &a });
    EXPECT_FALSE(s.ok);
    EXPECT_NE(s.error.find("frame 1"), std::string::npos) << s.error;
    EXPECT_NE(s.error.find("does not cover"), std::string::npos) << s.error;
    s = mcdenoise::compare_sequence({ &a, &grey }, { &a, &a });
    EXPECT_FALSE(s.ok);
    EXPECT_NE(s.error.find("frame 1"), std::string::npos) << s.error;
    s = mcdenoise::compare_sequence({ &a, &a }, { &a });
    EXPECT_FALSE(s.ok);
    EXPECT_NE(s.error.find("2 result frames but 1"), std::string::npos) << s.error;
    s = mcdenoise::compare_sequence({}, {});
    EXPECT_FALSE(s.ok);
    EXPECT_TRUE(std::isnan(mcdenoise::flicker({}, {})));
}

}  // namespace
