// test_denoise.cpp: clamp_fireflies against a brute-force reading of its
// header, by hand on tiny images, and the denoise preset's contract
// (guides, errors, determinism). Its quality is in test_quality.cpp.
#include <mcdenoise/mcdenoise.h>

#include "support/guide_images.h"
#include "support/test_images.h"

#include <OpenImageIO/imagebufalgo.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace {

using OIIO::ImageBuf;
using OIIO::ROI;
namespace IBA = OIIO::ImageBufAlgo;

// Luminance as features.h defines it for an RGB(A) pixel.
double luminance(const ImageBuf& img, int x, int y)
{
    const double w[3] = { 0.2126, 0.7152, 0.0722 };
    double l = 0.0;
    for (int c = 0; c < 3; ++c) {
        const float v = img.getchannel(x, y, 0, c);
        l += w[c] * (std::isfinite(v) ? v : 0.0);
    }
    return l;
}

// clamp_fireflies as its header words it, pixel by pixel, in double.
ImageBuf reference_clamp(const ImageBuf& beauty, const ImageBuf* ids, double factor, int radius)
{
    const ROI dw = beauty.roi();
    ImageBuf out(beauty.spec());
    IBA::copy(out, beauty, OIIO::TypeDesc::FLOAT);
    for (int y = dw.ybegin; y < dw.yend; ++y)
        for (int x = dw.xbegin; x < dw.xend; ++x) {
            std::vector<double> lums;
            for (int qy = std::max(dw.ybegin, y - radius); qy <= std::min(dw.yend - 1, y + radius); ++qy)
                for (int qx = std::max(dw.xbegin, x - radius); qx <= std::min(dw.xend - 1, x + radius); ++qx) {
                    const bool same = !ids
                                      || std::lround(ids->getchannel(qx, qy, 0, 0))
                                             == std::lround(ids->getchannel(x, y, 0, 0));
                    if ((qx != x || qy != y) && same)
                        lums.push_back(luminance(beauty, qx, qy));
                }
            if (lums.empty())
                continue;
            std::sort(lums.begin(), lums.end());
            const double bound = factor * lums[(3 * (lums.size() - 1)) / 4];
            const double l     = luminance(beauty, x, y);
            if (!(l > bound))
                continue;
            const double scale = bound > 0 ? bound / l : 0.0;
            std::vector<float> px(size_t(beauty.nchannels()));
            beauty.getpixel(x, y, px.data(), int(px.size()));
            for (int c = 0; c < 3; ++c)
                if (std::isfinite(px[size_t(c)]))
                    px[size_t(c)] = float(px[size_t(c)] * scale);
            out.setpixel(x, y, px.data(), int(px.size()));
        }
    return out;
}

// A render-like image: smooth values with a few fireflies 50x brighter.
ImageBuf with_fireflies(int w, int h, int nc, uint32_t seed, int x0 = 0, int y0 = 0)
{
    ImageBuf img = testimg::random_image(w, h, nc, seed, 0.2f, 0.6f, OIIO::TypeDesc::FLOAT, x0, y0);
    for (int i = 0; i < w * h / 20; ++i) {
        const int x = x0 + int((seed * 7919u + unsigned(i) * 104729u) % unsigned(w));
        const int y = y0 + int((seed * 31u + unsigned(i) * 1299709u) % unsigned(h));
        std::vector<float> px(static_cast<size_t>(nc));
        img.getpixel(x, y, px.data(), nc);
        for (int c = 0; c < std::min(nc, 3); ++c)
            px[size_t(c)] *= 50.0f;
        img.setpixel(x, y, px.data(), nc);
    }
    return img;
}

void expect_close(const ImageBuf& got, const ImageBuf& want)
{
    ASSERT_FALSE(got.has_error()) << got.geterror();
    ASSERT_EQ(got.roi(), want.roi());
    const std::vector<float> a = testimg::pixels(got), b = testimg::pixels(want);
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i) {
        if (!std::isfinite(b[i])) {
            EXPECT_TRUE(std::isnan(b[i]) ? std::isnan(a[i]) : a[i] == b[i]) << "value " << i;
            continue;
        }
        EXPECT_NEAR(a[i], b[i], 1e-5 * std::max(1.0f, std::fabs(b[i]))) << "value " << i;
    }
}

TEST(ClampFireflies, ScalesALoneBrightPixelToTwiceItsNeighbours)
{
    ImageBuf img(OIIO::ImageSpec(3, 3, 3, OIIO::TypeDesc::FLOAT));
    const float one[3] = { 1, 1, 1 }, ten[3] = { 10, 10, 10 };
    IBA::fill(img, one);
    img.setpixel(1, 1, ten);
    // Neighbours: eight luminances of 1; the 75th percentile is 1, the bound 2.
    const ImageBuf out = mcdenoise::clamp_fireflies(img, {}, 2.0f, 1);
    ASSERT_FALSE(out.has_error()) << out.geterror();
    EXPECT_FLOAT_EQ(out.getchannel(1, 1, 0, 0), 2.0f);
    EXPECT_FLOAT_EQ(out.getchannel(1, 1, 0, 2), 2.0f);
    EXPECT_FLOAT_EQ(out.getchannel(0, 0, 0, 1), 1.0f);
}

TEST(ClampFireflies, JudgesAPixelOnlyAgainstItsOwnObject)
{
    ImageBuf img(OIIO::ImageSpec(3, 3, 3, OIIO::TypeDesc::FLOAT));
    ImageBuf ids(OIIO::ImageSpec(3, 3, 1, OIIO::TypeDesc::FLOAT));
    const float one[3] = { 1, 1, 1 }, ten[3] = { 10, 10, 10 }, other = 7.0f;
    IBA::fill(img, one);
    IBA::zero(ids);
    img.setpixel(1, 1, ten);
    ids.setpixel(1, 1, &other);  // alone in its object: nothing to compare with
    mcdenoise::Guides guides;
    guides.object_id = &ids;
    const ImageBuf out = mcdenoise::clamp_fireflies(img, guides, 2.0f, 1);
    EXPECT_FLOAT_EQ(out.getchannel(1, 1, 0, 0), 10.0f);
}

TEST(ClampFireflies, MatchesTheBruteForceRule)
{
    for (int radius : { 1, 2, 4 }) {
        const ImageBuf beauty = with_fireflies(29, 21, 4, 3u + unsigned(radius), 5, -3);
        const ImageBuf ids    = testimg::block_ids(29, 21, 9u, OIIO::TypeDesc::HALF, 5, -3);
        mcdenoise::Guides guides;
        guides.object_id = &ids;
        expect_close(mcdenoise::clamp_fireflies(beauty, guides, 2.5f, radius),
                     reference_clamp(beauty, &ids, 2.5, radius));
        expect_close(mcdenoise::clamp_fireflies(beauty, {}, 1.0f, radius),
                     reference_clamp(beauty, nullptr, 1.0, radius));
    }
}

TEST(ClampFireflies, PassesNonFiniteValuesThrough)
{
    ImageBuf beauty = with_fireflies(17, 13, 3, 5u);
    testimg::sprinkle_nonfinite(beauty, 0.1, 6u);
    expect_close(mcdenoise::clamp_fireflies(beauty, {}, 2.0f, 2),
                 reference_clamp(beauty, nullptr, 2.0, 2));
}

TEST(ClampFireflies, BadParametersLeaveDstUntouched)
{
    const ImageBuf beauty = with_fireflies(8, 8, 3, 1u);
    const ImageBuf ids3   = testimg::random_image(8, 8, 3, 2u);
    mcdenoise::Guides bad;
    bad.object_id = &ids3;
    for (auto run : { +[](ImageBuf& d, const ImageBuf& b, const mcdenoise::Guides& g) {
                         return mcdenoise::clamp_fireflies(d, b, g, 0.5f, 2);
                     },
                      +[](ImageBuf& d, const ImageBuf& b, const mcdenoise::Guides& g) {
                          return mcdenoise::clamp_fireflies(d, b, g, 2.0f, 0);
                      },
                      +[](ImageBuf& d, const ImageBuf& b, const mcdenoise::Guides& g) {
                          return mcdenoise::clamp_fireflies(d, b, g, 2.0f, 8);
                      } }) {
        ImageBuf dst = testimg::random_image(8, 8, 3, 4u);
        const std::vector<float> before = testimg::pixels(dst);
        EXPECT_FALSE(run(dst, beauty, {}));
        EXPECT_TRUE(dst.has_error());
        EXPECT_EQ(testimg::pixels(dst), before);
    }
    ImageBuf dst;
    EXPECT_FALSE(mcdenoise::clamp_fireflies(dst, beauty, bad));
    EXPECT_NE(dst.geterror().find("object_id"), std::string::npos) << dst.geterror();
}

// A small render-like set: beauty with fireflies and every guide.
struct SmallRender {
    ImageBuf beauty, ids, normal, depth, albedo, variance, half_a, half_b;
    SmallRender(int w, int h)
        : beauty(with_fireflies(w, h, 3, 11u, 2, 1))
        , ids(testimg::block_ids(w, h, 12u, OIIO::TypeDesc::FLOAT, 2, 1))
        , normal(testimg::wavy_normals(w, h, 13u, 2, 1))
        , depth(testimg::random_image(w, h, 1, 14u, 1.0f, 5.0f, OIIO::TypeDesc::FLOAT, 2, 1))
        , albedo(testimg::random_image(w, h, 3, 15u, 0.0f, 1.0f, OIIO::TypeDesc::FLOAT, 2, 1))
        , variance(testimg::random_image(w, h, 3, 16u, 0.0f, 0.01f, OIIO::TypeDesc::FLOAT, 2, 1))
        , half_a(testimg::random_image(w, h, 3, 17u, 0.2f, 0.6f, OIIO::TypeDesc::FLOAT, 2, 1))
        , half_b(testimg::random_image(w, h, 3, 18u, 0.2f, 0.6f, OIIO::TypeDesc::FLOAT, 2, 1))
    {
    }
    mcdenoise::Guides guides() const
    {
        return { &ids, &normal, &depth, &albedo, &variance, &half_a, &half_b };
    }
};

TEST(Denoise, IsDeterministicAcrossThreadsAndRoiSplits)
{
    const SmallRender r(37, 29);
    mcdenoise::Guides no_variance = r.guides();
    no_variance.variance          = nullptr;
    for (const mcdenoise::Guides& g : { r.guides(), no_variance, mcdenoise::Guides {} }) {
        const ImageBuf one = mcdenoise::denoise(r.beauty, g, {}, 1);
        ASSERT_FALSE(one.has_error()) << one.geterror();
        for (int n : { 2, 7 })
            EXPECT_TRUE(testimg::bit_identical(mcdenoise::denoise(r.beauty, g, {}, n), one));
        ImageBuf split(one.spec());
        const ROI dw = r.beauty.roi();
        ROI top = dw, bottom = dw;
        top.yend = bottom.ybegin = dw.ybegin + 11;
        ASSERT_TRUE(mcdenoise::denoise(split, r.beauty, g, top, 2)) << split.geterror();
        ASSERT_TRUE(mcdenoise::denoise(split, r.beauty, g, bottom, 2)) << split.geterror();
        EXPECT_TRUE(testimg::bit_identical(split, one));
    }
}

TEST(Denoise, RecordsTheGuidesItUsed)
{
    const SmallRender r(16, 12);
    mcdenoise::Guides g;
    g.normal = &r.normal;
    g.albedo = &r.albedo;
    const ImageBuf out = mcdenoise::denoise(r.beauty, g);
    ASSERT_FALSE(out.has_error()) << out.geterror();
    EXPECT_EQ(out.spec().get_string_attribute("mcdenoise:denoise_guides"), "normal,albedo");
    EXPECT_EQ(mcdenoise::denoise(r.beauty)
                  .spec()
                  .get_string_attribute("mcdenoise:denoise_guides", "unset"),
              "");
}

TEST(Denoise, LowersTheNoiseOfAFlatImage)
{
    // Constant 0.5 plus noise of known variance: the error must drop.
    const int w = 48, h = 40;
    const ImageBuf noise = testimg::random_image(w, h, 3, 21u, -0.2f, 0.2f);
    const ImageBuf flat  = IBA::fill({ 0.5f, 0.5f, 0.5f }, noise.roi());
    const ImageBuf noisy = IBA::add(flat, noise);
    ImageBuf variance    = IBA::fill({ 0.04f / 3, 0.04f / 3, 0.04f / 3 }, noise.roi());
    mcdenoise::Guides g;
    g.variance = &variance;
    for (const mcdenoise::Guides& guides : { g, mcdenoise::Guides {} }) {
        const ImageBuf out = mcdenoise::denoise(noisy, guides);
        EXPECT_LT(mcdenoise::mse(out, flat), 0.1 * mcdenoise::mse(noisy, flat));
    }
}

// The sum of a channel over an image.
double channel_sum(const ImageBuf& img, int c)
{
    return IBA::computePixelStats(img).sum[size_t(c)];
}

TEST(Denoise, SpreadsAKnownFireflysExcessWide)
{
    // A flat 0.5 with one pixel 100x brighter whose variance says it is a
    // firefly: the clamp alone would take 98% of that pixel's energy (1.2%
    // of the frame's); denoise gives it back and puts no blotch where the
    // firefly was.
    ImageBuf img = IBA::fill({ 0.5f, 0.5f, 0.5f }, ROI(0, 64, 0, 64, 0, 1, 0, 3));
    const float bright[3] = { 50.0f, 50.0f, 50.0f };
    img.setpixel(30, 33, bright);
    ImageBuf variance = IBA::fill({ 1e-4f }, ROI(0, 64, 0, 64, 0, 1, 0, 1));
    const float noisy[1] = { 1e4f };
    variance.setpixel(30, 33, noisy);
    mcdenoise::Guides g;
    g.variance = &variance;
    const ImageBuf out = mcdenoise::denoise(img, g);
    ASSERT_FALSE(out.has_error()) << out.geterror();
    const ImageBuf clamped = mcdenoise::clamp_fireflies(img, {}, 2.0f, 2);
    for (int c = 0; c < 3; ++c) {
        const double taken = channel_sum(img, c) - channel_sum(clamped, c);
        EXPECT_GT(taken, 0.01 * channel_sum(img, c));
        EXPECT_NEAR(channel_sum(out, c), channel_sum(img, c), 0.02 * taken);
    }
    EXPECT_LT(IBA::computePixelStats(out).max[0], 1.0f);
}

TEST(Denoise, GivesAnUnjudgedOutliersExcessBackWithinItsOwnWindow)
{
    // No variance, no halves: a bright pixel on a noisy surface gives its
    // excess to the pixels of its search window (radius 5) its average
    // found alike, and to none beyond: the result equals that of the same
    // image with the pixel already at the clamp's bound, plus the excess,
    // inside the window only.
    ImageBuf img = testimg::random_image(48, 40, 3, 12u, 0.4f, 0.6f);
    const float bright[3] = { 50.0f, 40.0f, 30.0f };
    img.setpixel(20, 17, bright);
    const ImageBuf at_bound = [&] {
        ImageBuf b = img;
        std::vector<float> v(3);
        mcdenoise::clamp_fireflies(img, {}, 2.0f, 2).getpixel(20, 17, v.data());
        b.setpixel(20, 17, v.data());
        return b;
    }();
    const ImageBuf out = mcdenoise::denoise(img), base = mcdenoise::denoise(at_bound);
    ASSERT_FALSE(out.has_error() || base.has_error()) << out.geterror() << base.geterror();
    double given = 0.0;
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 48; ++x) {
            const double d = out.getchannel(x, y, 0, 0) - base.getchannel(x, y, 0, 0);
            if (std::abs(x - 20) > 5 || std::abs(y - 17) > 5) {
                ASSERT_EQ(d, 0.0) << x << "," << y;
            }
            given += d;
        }
    EXPECT_NEAR(given, 50.0 - at_bound.getchannel(20, 17, 0, 0), 1e-3);
    EXPECT_LT(out.getchannel(20, 17, 0, 0), 25.0f);  // shared out, not kept
}

TEST(Denoise, KeepsAHighlightItsVarianceVouchesFor)
{
    // The same bright pixel with a variance guide that says every pixel's
    // samples agree: it is a highlight, not a firefly, and stays.
    ImageBuf img = IBA::fill({ 0.5f, 0.5f, 0.5f }, ROI(0, 32, 0, 32, 0, 1, 0, 3));
    const float bright[3] = { 50.0f, 50.0f, 50.0f };
    img.setpixel(12, 17, bright);
    const ImageBuf variance = IBA::fill({ 1e-4f }, img.roi());
    mcdenoise::Guides g;
    g.variance = &variance;
    const ImageBuf out = mcdenoise::denoise(img, g);
    ASSERT_FALSE(out.has_error()) << out.geterror();
    EXPECT_NEAR(out.getchannel(12, 17, 0, 0), 50.0f, 0.5f);
    EXPECT_NEAR(out.getchannel(0, 0, 0, 0), 0.5f, 1e-4f);
}

TEST(Denoise, RejectsUnpairedOrMisfitGuidesAndLeavesDstUntouched)
{
    const SmallRender r(16, 12);
    const ImageBuf small = testimg::random_image(8, 8, 3, 30u);
    mcdenoise::Guides only_a;
    only_a.half_a = &r.half_a;
    mcdenoise::Guides small_albedo;
    small_albedo.albedo = &small;
    mcdenoise::Guides small_half = r.guides();
    small_half.half_b            = &small;
    for (const auto& [guides, needle] :
         { std::pair { only_a, "half_b" }, std::pair { small_albedo, "albedo" },
           std::pair { small_half, "half_b" } }) {
        ImageBuf dst = testimg::random_image(16, 12, 3, 31u, 0.0f, 1.0f,
                                             OIIO::TypeDesc::FLOAT, 2, 1);
        const std::vector<float> before = testimg::pixels(dst);
        EXPECT_FALSE(mcdenoise::denoise(dst, r.beauty, guides));
        EXPECT_NE(dst.geterror().find(needle), std::string::npos) << dst.geterror();
        EXPECT_EQ(testimg::pixels(dst), before);
    }
}

}  // namespace
