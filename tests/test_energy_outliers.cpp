// test_energy_outliers.cpp: denoise's energy-keeping outlier step against a
// brute-force reading of energy_outliers.h: the split of a firefly into what
// is averaged and what is spread, and the spread itself, in double, pixel by
// pixel.
#include "energy_outliers.h"

#include <mcdenoise/fireflies.h>

#include "support/test_images.h"

#include <OpenImageIO/imagebufalgo.h>
#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

namespace {

using OIIO::ImageBuf;
using OIIO::ROI;
namespace IBA = OIIO::ImageBufAlgo;
using mcdenoise::excess_spread_radius;
using mcdenoise::excess_spread_sigma;

double gauss(int t)
{
    return std::exp(-double(t) * t / (2.0 * double(excess_spread_sigma) * excess_spread_sigma));
}

// The sum of g over [lo, hi) around q, as the header defines n(q) per axis.
double coverage(int q, int lo, int hi)
{
    double s = 0.0;
    for (int p = std::max(lo, q - excess_spread_radius);
         p <= std::min(hi - 1, q + excess_spread_radius); ++p)
        s += gauss(p - q);
    return s;
}

// Sparse excess on a data window that does not start at 0.
mcdenoise::Planes<float> sparse_excess(const ROI& dw)
{
    mcdenoise::Planes<float> e(dw, 3, 0.0f);
    for (int i = 0; i < 25; ++i) {
        const int x = dw.xbegin + (i * 37) % dw.width(), y = dw.ybegin + (i * 53) % dw.height();
        for (int c = 0; c < 3; ++c)
            e.values[size_t(c)][e.offset(x, y)] = float(1 + i + 3 * c);
    }
    return e;
}

TEST(SpreadExcess, IsTheNormalisedGaussianSplatAndKeepsEveryPixelsExcess)
{
    const ROI dw(5, 75, -3, 57, 0, 1, 0, 4);
    const mcdenoise::Planes<float> e = sparse_excess(dw);
    const ImageBuf spread = mcdenoise::spread_excess(e, dw, dw, 4, 1);
    ASSERT_EQ(spread.nchannels(), 4);
    std::vector<std::pair<int, int>> sources;
    for (int y = dw.ybegin; y < dw.yend; ++y)
        for (int x = dw.xbegin; x < dw.xend; ++x)
            if (e.values[0][e.offset(x, y)] != 0.0f)
                sources.emplace_back(x, y);
    ASSERT_GT(sources.size(), 10u);
    double total[3] = {}, given[3] = {};
    for (int y = dw.ybegin; y < dw.yend; ++y)
        for (int x = dw.xbegin; x < dw.xend; ++x) {
            for (int c = 0; c < 3; ++c) {
                double want = 0.0;
                for (const auto& [qx, qy] : sources) {
                    const double v = e.values[size_t(c)][e.offset(qx, qy)];
                    if (std::abs(qx - x) <= excess_spread_radius
                        && std::abs(qy - y) <= excess_spread_radius)
                        want += v * gauss(x - qx) * gauss(y - qy)
                                / (coverage(qx, dw.xbegin, dw.xend)
                                   * coverage(qy, dw.ybegin, dw.yend));
                }
                const float got = spread.getchannel(x, y, 0, c);
                EXPECT_NEAR(got, want, 1e-5 * (1.0 + want)) << x << "," << y << " c" << c;
                total[c] += got;
                given[c] += e.values[size_t(c)][e.offset(x, y)];
            }
            EXPECT_EQ(spread.getchannel(x, y, 0, 3), 0.0f);
        }
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(total[c], given[c], 1e-5 * given[c]);
}

TEST(SpreadExcess, DoesNotDependOnTheRoi)
{
    const ROI dw(0, 90, 0, 70, 0, 1, 0, 3);
    const mcdenoise::Planes<float> e = sparse_excess(dw);
    const ImageBuf whole = mcdenoise::spread_excess(e, dw, dw, 3, 2);
    const ROI part(20, 50, 30, 41, 0, 1, 0, 3);
    const mcdenoise::Planes<float> grown_part = [&] {
        const ROI g(0, 80, 0, 70, 0, 1, 0, 3);  // part grown by 30, clipped
        mcdenoise::Planes<float> p(g, 3, 0.0f);
        for (int c = 0; c < 3; ++c)
            for (int y = g.ybegin; y < g.yend; ++y)
                for (int x = g.xbegin; x < g.xend; ++x)
                    p.values[size_t(c)][p.offset(x, y)] = e.values[size_t(c)][e.offset(x, y)];
        return p;
    }();
    const ImageBuf piece = mcdenoise::spread_excess(grown_part, part, dw, 3, 1);
    for (int y = part.ybegin; y < part.yend; ++y)
        for (int x = part.xbegin; x < part.xend; ++x)
            for (int c = 0; c < 3; ++c)
                EXPECT_EQ(piece.getchannel(x, y, 0, c), whole.getchannel(x, y, 0, c));
}

// A flat image with a pixel 100x brighter; `variance` (if not null) the
// variance guide.
struct SplitResult {
    ImageBuf kept;
    mcdenoise::Planes<float> excess;
};
SplitResult split(const ImageBuf& beauty, const ImageBuf* variance)
{
    SplitResult r;
    ImageBuf dst;
    EXPECT_TRUE(mcdenoise::split_outliers("test", dst, beauty, variance,
                                          2.0f, 2, beauty.roi(), 1, r.kept, r.excess))
        << dst.geterror();
    return r;
}

ImageBuf firefly_image()
{
    ImageBuf img(OIIO::ImageSpec(9, 9, 4, OIIO::TypeDesc::FLOAT));
    const float flat[4] = { 0.5f, 0.5f, 0.5f, 1.0f }, bright[4] = { 50.0f, 40.0f, 30.0f, 1.0f };
    IBA::fill(img, flat);
    img.setpixel(4, 4, bright);
    return img;
}

TEST(SplitOutliers, TakesTheFireflysExcessOverTheClampsBound)
{
    const ImageBuf img = firefly_image();
    const SplitResult r = split(img, nullptr);
    const ImageBuf clamped = mcdenoise::clamp_fireflies(img, {}, 2.0f, 2);
    for (int c = 0; c < 4; ++c)
        EXPECT_EQ(r.kept.getchannel(4, 4, 0, c), clamped.getchannel(4, 4, 0, c));
    ASSERT_EQ(r.excess.nchannels(), 4);
    EXPECT_EQ(r.excess.values[3][r.excess.offset(4, 4)], 0.0f);  // alpha: nothing taken
    for (int c = 0; c < 3; ++c) {
        EXPECT_FLOAT_EQ(r.excess.values[size_t(c)][r.excess.offset(4, 4)],
                        img.getchannel(4, 4, 0, c) - clamped.getchannel(4, 4, 0, c));
        EXPECT_EQ(r.excess.values[size_t(c)][r.excess.offset(3, 4)], 0.0f);
    }
}

TEST(SplitOutliers, KeepsAHighlightItsMeasuredNoiseVouchesFor)
{
    const ImageBuf img     = firefly_image();
    const ImageBuf clamped = mcdenoise::clamp_fireflies(img, {}, 2.0f, 2);
    // Luminance 41.4 against the bound 1: an excess of 40.4, and its noise
    // sigma 1 (the samples agree: kept) or 30 (a firefly: clamped).
    for (const float v : { 1.0f, 900.0f }) {
        ImageBuf variance(OIIO::ImageSpec(9, 9, 1, OIIO::TypeDesc::FLOAT));
        const float lum_var = v / (0.2126f * 0.2126f + 0.7152f * 0.7152f + 0.0722f * 0.0722f);
        IBA::fill(variance, { lum_var });
        const SplitResult r = split(img, &variance);
        const bool kept = v < 100.0f;
        EXPECT_EQ(r.kept.getchannel(4, 4, 0, 0), kept ? 50.0f : clamped.getchannel(4, 4, 0, 0));
        EXPECT_EQ(r.excess.values[0][r.excess.offset(4, 4)] == 0.0f, kept) << v;
    }
}

}  // namespace
