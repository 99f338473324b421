// test_energy_outliers.cpp: denoise's energy-keeping outlier step against a
// brute-force reading of energy_outliers.h: the split of a firefly into what
// is averaged and what is given back, the two ways it is given back (the
// wide Gaussian of a known firefly; the window weights of an unjudged
// outlier, filters.md's NL-means formula in double, and their tap from the
// average), pixel by pixel.
#include "denoise/energy_outliers.h"

#include "features/feature_field.h"
#include "features/nlmeans_layers.h"

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

// The wide spread of a data window.
mcdenoise::ExcessWeights wide(const ROI& dw)
{
    mcdenoise::ExcessWeights w;
    w.wide        = true;
    w.data_window = dw;
    return w;
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

TEST(SpreadWide, IsTheNormalisedGaussianSplatAndKeepsEveryPixelsExcess)
{
    const ROI dw(5, 75, -3, 57, 0, 1, 0, 4);
    const mcdenoise::Planes<float> e = sparse_excess(dw);
    const ImageBuf spread = mcdenoise::spread_excess(wide(dw), e, dw, 4, 1);
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

TEST(SpreadWide, DoesNotDependOnTheRoi)
{
    const ROI dw(0, 90, 0, 70, 0, 1, 0, 3);
    const mcdenoise::Planes<float> e = sparse_excess(dw);
    const ImageBuf whole = mcdenoise::spread_excess(wide(dw), e, dw, 3, 2);
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
    const ImageBuf piece = mcdenoise::spread_excess(wide(dw), grown_part, part, 3, 1);
    for (int y = part.ybegin; y < part.yend; ++y)
        for (int x = part.xbegin; x < part.xend; ++x)
            for (int c = 0; c < 3; ++c)
                EXPECT_EQ(piece.getchannel(x, y, 0, c), whole.getchannel(x, y, 0, c));
}

// Sparse excess on a data window that does not start at 0, and hand-made
// weights for its sources: radius 2, each window's weights a fixed pattern
// scaled to sum 1 (as `excess_weights` leaves them).
struct Scatter {
    mcdenoise::Planes<float> excess;
    mcdenoise::ExcessWeights weights;
};
Scatter sparse_scatter(const ROI& dw)
{
    Scatter s { mcdenoise::Planes<float>(dw, 3, 0.0f), {} };
    s.weights.radius = 2;
    for (int y = dw.ybegin; y < dw.yend; ++y)
        for (int x = dw.xbegin; x < dw.xend; ++x) {
            if ((x * 7 + y * 13) % 23 != 0)
                continue;
            for (int c = 0; c < 3; ++c)
                s.excess.values[size_t(c)][s.excess.offset(x, y)] = float(1 + x % 5 + 3 * c);
            s.weights.sources.push_back({ x, y });
            std::vector<float> w(25);
            double sum = 0.0;
            for (int k = 0; k < 25; ++k) {
                const int dx = k % 5 - 2, dy = k / 5 - 2;
                const bool inside = x + dx >= dw.xbegin && x + dx < dw.xend
                                    && y + dy >= dw.ybegin && y + dy < dw.yend;
                w[size_t(k)] = inside ? float(1 + (k * 5 + x) % 7) : 0.0f;
                sum += w[size_t(k)];
            }
            for (float v : w)
                s.weights.weights.push_back(float(v / sum));
        }
    return s;
}

TEST(SpreadOverWindows, GivesEachSourcesExcessOverItsWindowWhole)
{
    const ROI dw(5, 45, -3, 27, 0, 1, 0, 4);
    const Scatter s = sparse_scatter(dw);
    ASSERT_GT(s.weights.sources.size(), 20u);
    const ImageBuf spread = mcdenoise::spread_excess(s.weights, s.excess, dw, 4, 2);
    ASSERT_EQ(spread.nchannels(), 4);
    double total[3] = {}, given[3] = {};
    for (int y = dw.ybegin; y < dw.yend; ++y)
        for (int x = dw.xbegin; x < dw.xend; ++x) {
            for (int c = 0; c < 3; ++c) {
                double want = 0.0;
                for (size_t k = 0; k < s.weights.sources.size(); ++k) {
                    const auto [qx, qy] = s.weights.sources[k];
                    if (std::abs(qx - x) <= 2 && std::abs(qy - y) <= 2)
                        want += double(s.excess.values[size_t(c)][s.excess.offset(qx, qy)])
                                * s.weights.weights[k * 25 + size_t((y - qy + 2) * 5 + x - qx + 2)];
                }
                const float got = spread.getchannel(x, y, 0, c);
                EXPECT_NEAR(got, want, 1e-5 * (1.0 + want)) << x << "," << y << " c" << c;
                total[c] += got;
                given[c] += s.excess.values[size_t(c)][s.excess.offset(x, y)];
            }
            EXPECT_EQ(spread.getchannel(x, y, 0, 3), 0.0f);
        }
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(total[c], given[c], 1e-5 * given[c]);
}

TEST(SpreadOverWindows, DoesNotDependOnTheRoi)
{
    const ROI dw(0, 60, 0, 40, 0, 1, 0, 3);
    const Scatter s = sparse_scatter(dw);
    const ImageBuf whole = mcdenoise::spread_excess(s.weights, s.excess, dw, 3, 2);
    const ROI part(20, 37, 11, 30, 0, 1, 0, 3);
    const ImageBuf piece = mcdenoise::spread_excess(s.weights, s.excess, part, 3, 1);
    for (int y = part.ybegin; y < part.yend; ++y)
        for (int x = part.xbegin; x < part.xend; ++x)
            for (int c = 0; c < 3; ++c)
                EXPECT_EQ(piece.getchannel(x, y, 0, c), whole.getchannel(x, y, 0, c));
}

// The normalised window weights of every source of `excess` in `region`,
// each weighed alone (`fill_outside` of everything).
mcdenoise::ExcessWeights window_weights_of(const mcdenoise::Planes<float>& excess,
                                           const ROI& region, const mcdenoise::NlmFrame& own,
                                           const mcdenoise::FeatureInputs& planes, const ROI& dw,
                                           int f, float strength)
{
    mcdenoise::ExcessWeights w = mcdenoise::excess_sources(excess, region, own.search_radius);
    mcdenoise::fill_outside(w, ROI(0, 0, 0, 0), own, planes.colour, planes.variance, dw, f,
                            strength, 2);
    mcdenoise::normalise_weights(w);
    return w;
}

// The NL-means weight of filters.md for pixel p and its neighbour q of a
// colour image `u` with variance `v` (no feature guides), in double.
double nlmeans_weight(const ImageBuf& u, double v, int px, int py, int qx, int qy, int f, double k)
{
    if (px == qx && py == qy)
        return 1.0;
    const ROI dw = u.roi();
    double d = 0.0;
    int n    = 0;
    for (int ny = -f; ny <= f; ++ny)
        for (int nx = -f; nx <= f; ++nx) {
            const int ax = px + nx, ay = py + ny, bx = qx + nx, by = qy + ny;
            if (!dw.contains(ax, ay) || !dw.contains(bx, by))
                continue;
            for (int c = 0; c < 3; ++c) {
                const double t = double(u.getchannel(ax, ay, 0, c)) - u.getchannel(bx, by, 0, c);
                d += (t * t - 2.0 * v) / (1e-10 + k * k * 2.0 * v) / 3.0;
            }
            ++n;
        }
    return std::exp(-std::max(0.0, d / n));
}

TEST(ExcessWeights, AreEachSourcesOwnNlmeansWeightsScaledToSumOne)
{
    const ImageBuf beauty = testimg::random_image(17, 13, 3, 5);
    const ROI dw          = beauty.roi();
    ImageBuf variance(OIIO::ImageSpec(17, 13, 1, OIIO::TypeDesc::FLOAT));
    IBA::fill(variance, { 0.05f });
    mcdenoise::Guides guides;
    guides.variance = &variance;
    ImageBuf dst;
    mcdenoise::FeatureInputs planes;
    ASSERT_TRUE(mcdenoise::load_feature_inputs("test", dst, beauty, guides, {}, dw, dw, 1, planes))
        << dst.geterror();
    mcdenoise::Planes<float> excess(dw, 3, 0.0f);
    const int r = 3, f = 1;
    const float strength = 0.6f;
    for (const auto& [x, y] : { std::pair(0, 0), std::pair(8, 6), std::pair(16, 3) })
        excess.values[1][excess.offset(x, y)] = 2.0f;
    const mcdenoise::NlmFrame own { &planes.colour,   &planes.variance, &planes.features,
                                    &planes.features, &planes.values,   nullptr, r, true };
    const mcdenoise::ExcessWeights w = window_weights_of(excess, dw, own, planes, dw, f, strength);
    ASSERT_EQ(w.sources.size(), 3u);
    EXPECT_EQ(w.sources[1].x, 16);  // row by row
    EXPECT_EQ(w.sources[2].y, 6);
    for (size_t k = 0; k < w.sources.size(); ++k) {
        const auto [px, py] = w.sources[k];
        std::vector<double> want(size_t((2 * r + 1) * (2 * r + 1)), 0.0);
        double sum = 0.0;
        for (int dy = -r; dy <= r; ++dy)
            for (int dx = -r; dx <= r; ++dx)
                if (dw.contains(px + dx, py + dy)) {
                    double& v = want[size_t((dy + r) * (2 * r + 1) + dx + r)];
                    v = nlmeans_weight(beauty, 0.05, px, py, px + dx, py + dy, f, strength);
                    sum += v;
                }
        for (size_t j = 0; j < want.size(); ++j)
            EXPECT_NEAR(w.weights[k * want.size() + j], want[j] / sum, 1e-5)
                << px << "," << py << " offset " << j;
    }
}

TEST(ExcessWeights, TheAveragesTapGivesTheWindowWeightsExactly)
{
    const ImageBuf beauty = testimg::random_image(23, 19, 3, 8);
    const ImageBuf albedo = testimg::random_image(23, 19, 3, 9, 0.2f, 0.4f);
    ImageBuf variance(OIIO::ImageSpec(23, 19, 1, OIIO::TypeDesc::FLOAT));
    IBA::fill(variance, { 0.05f });
    mcdenoise::Guides guides;
    guides.albedo   = &albedo;
    guides.variance = &variance;
    const ROI dw = beauty.roi();
    mcdenoise::Planes<float> excess(dw, 3, 0.0f);
    for (int k = 0; k < 30; ++k)
        excess.values[size_t(k % 3)][excess.offset((k * 7) % 23, (k * 5) % 19)] = 1.0f;
    const int r = 4, f = 1;
    const float strength = 0.7f;
    const mcdenoise::FeatureSigmas sigmas { 0.3f, 0.6f, 1.0f };
    mcdenoise::ExcessWeights tapped = mcdenoise::excess_sources(excess, dw, r);
    const mcdenoise::WeightTap tap  = mcdenoise::weight_tap(tapped, dw);
    ImageBuf out;
    std::vector<ImageBuf> no_layers;
    ASSERT_TRUE(mcdenoise::nlmeans_layers(out, no_layers, beauty, {}, {}, guides, r, f, strength,
                                          sigmas, dw, 2, &tap))
        << out.geterror();
    mcdenoise::normalise_weights(tapped);
    ImageBuf dst;
    mcdenoise::FeatureInputs planes;
    ASSERT_TRUE(mcdenoise::load_feature_inputs("test", dst, beauty, guides, sigmas, dw, dw, 1, planes))
        << dst.geterror();
    const mcdenoise::NlmFrame own { &planes.colour,   &planes.variance, &planes.features,
                                    &planes.features, &planes.values,   nullptr, r, true };
    const mcdenoise::ExcessWeights direct
        = window_weights_of(excess, dw, own, planes, dw, f, strength);
    ASSERT_GT(tapped.sources.size(), 20u);
    ASSERT_EQ(tapped.weights.size(), direct.weights.size());
    size_t between = 0;  // weights neither 0 nor 1: the comparison means something
    for (size_t j = 0; j < direct.weights.size(); ++j) {
        EXPECT_EQ(tapped.weights[j], direct.weights[j]) << j;
        between += direct.weights[j] > 0.01f && direct.weights[j] < 0.99f;
    }
    EXPECT_GT(between, direct.weights.size() / 4);
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
