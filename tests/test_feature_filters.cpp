// test_feature_filters.cpp: the feature-guided filters (cross_bilateral,
// atrous, nlmeans) and albedo (de)modulation against the tests' brute-force
// double-precision implementation of their contract, on random beauty with
// structured guides in several pixel types, non-finite values, odd data
// windows, sub-ROIs and channel ranges; bit-identical across threads and ROI
// splits; hand-computed tiny cases; and every error leaving dst untouched.
#include <mcdenoise/mcdenoise.h>

#include "reference/feature_reference.h"
#include "support/guide_images.h"
#include "support/test_images.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <string>

namespace {

using OIIO::ImageBuf;
using OIIO::ImageSpec;
using OIIO::ROI;
using OIIO::TypeDesc;

// Largest |value| of the random beauties below: the scale of the errors.
constexpr float value_scale = 4.0f;
// Tolerance relative to `value_scale` (and to the values of the hand-computed cases). The library weighs in float with
// OIIO's fast_exp (at most 230 ulp, 1.4e-5 relative, off the exact exp): a
// weighted mean moves by at most that relative weight error times the
// spread of the values it mixes, plus float sums of at most a few hundred
// terms (~1e-6). Atrous compounds this over its iterations.
constexpr double tolerance = 5e-5;
// The hand-computed cases mix values at most 5 apart: 1.4e-5 * 5 < 1e-4.
constexpr double hand_tolerance = 1e-4;

ImageBuf from_values(int w, int h, int nc, const std::vector<float>& v,
                     TypeDesc format = TypeDesc::FLOAT, int x0 = 0, int y0 = 0)
{
    ImageSpec spec(w, h, nc, format);
    spec.x = x0;
    spec.y = y0;
    ImageBuf img(spec);
    img.set_pixels(img.roi(), TypeDesc::FLOAT, v.data());
    return img;
}

// Depths: a ramp with noise, plus background written every way renderers
// do: +Inf, NaN, 0 (Cycles' Denoising Depth, Tungsten), 1e10, and negative.
ImageBuf odd_depths(int w, int h, uint32_t seed, int x0, int y0)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const float specials[] = { INFINITY, NAN, 0.0f, 1e10f, -2.0f };
    std::vector<float> v(size_t(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            v[size_t(y) * w + x] = rng() % 7 == 0 ? specials[rng() % 5]
                                                  : 1.0f + 0.3f * x + 0.5f * u(rng);
    return from_values(w, h, 1, v, TypeDesc::FLOAT, x0, y0);
}

// Random values in [lo, hi) with some NaN (and, if `negatives`, some < 0).
ImageBuf noisy_guide(int w, int h, int nc, uint32_t seed, float lo, float hi, int x0, int y0,
                     TypeDesc format = TypeDesc::FLOAT)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(lo, hi);
    std::vector<float> v(size_t(w) * h * nc);
    for (float& a : v)
        a = rng() % 17 == 0 ? (rng() % 2 ? NAN : -0.5f) : u(rng);
    return from_values(w, h, nc, v, format, x0, y0);
}

// One test scene: beauty and every guide, with both views of them.
struct Scene {
    ImageBuf beauty, ids, normals, depth, albedo, variance;
    spec::Image sbeauty, sids, snormals, sdepth, salbedo, svariance;

    Scene(int w, int h, int nc, uint32_t seed, int x0 = 0, int y0 = 0,
          TypeDesc id_format = TypeDesc::FLOAT, int albedo_nc = 3, int variance_nc = 3,
          double nonfinite = 0.0)
    {
        beauty = testimg::random_image(w, h, nc, seed, 0.0f, value_scale, TypeDesc::FLOAT, x0,
                                       y0);
        if (nonfinite > 0)
            testimg::sprinkle_nonfinite(beauty, nonfinite, seed + 9);
        ids      = testimg::block_ids(w, h, seed + 1, id_format, x0, y0);
        normals  = testimg::wavy_normals(w, h, seed + 2, x0, y0);
        depth    = odd_depths(w, h, seed + 3, x0, y0);
        albedo   = noisy_guide(w, h, albedo_nc, seed + 4, 0.0f, 1.0f, x0, y0);
        variance = noisy_guide(w, h, variance_nc, seed + 5, 0.0f, 0.3f, x0, y0);
        sbeauty   = spec::from_imagebuf(beauty);
        sids      = spec::ids_from_imagebuf(ids);
        snormals  = spec::from_imagebuf(normals);
        sdepth    = spec::from_imagebuf(depth);
        salbedo   = spec::from_imagebuf(albedo);
        svariance = spec::from_imagebuf(variance);
    }
};

// Which guides a run passes.
struct Use {
    bool ids = true, normals = true, depth = true, albedo = true, variance = true;
};

mcdenoise::Guides guides_of(const Scene& s, Use u)
{
    mcdenoise::Guides g;
    g.object_id = u.ids ? &s.ids : nullptr;
    g.normal    = u.normals ? &s.normals : nullptr;
    g.depth     = u.depth ? &s.depth : nullptr;
    g.albedo    = u.albedo ? &s.albedo : nullptr;
    g.variance  = u.variance ? &s.variance : nullptr;
    return g;
}

featref::Guides ref_guides_of(const Scene& s, Use u)
{
    featref::Guides g;
    g.object_id = u.ids ? &s.sids : nullptr;
    g.normal    = u.normals ? &s.snormals : nullptr;
    g.depth     = u.depth ? &s.sdepth : nullptr;
    g.albedo    = u.albedo ? &s.salbedo : nullptr;
    g.variance  = u.variance ? &s.svariance : nullptr;
    return g;
}

void expect_close(const ImageBuf& got_img, const std::vector<double>& want, ROI roi,
                  double tol, const std::string& what)
{
    const std::vector<float> got = testimg::pixels(got_img, roi);
    ASSERT_EQ(got.size(), want.size()) << what;
    int reported = 0;
    for (size_t i = 0; i < got.size(); ++i) {
        const double err = std::abs(double(got[i]) - want[i]);
        if (!(err <= tol * value_scale) && reported++ < 5)
            ADD_FAILURE() << what << ": value " << i << " got " << got[i] << ", want "
                          << want[i];
    }
}

int empty_windows(const ImageBuf& img)
{
    return img.spec().get_int_attribute("mcdenoise:empty_windows", 0);
}

// ---------------------------------------------------------------- cross_bilateral

void check_cross_bilateral(const Scene& s, Use u, int size, float ss, float sc,
                           mcdenoise::FeatureSigmas sig, ROI roi, const std::string& what)
{
    ImageBuf dst;
    ASSERT_TRUE(mcdenoise::cross_bilateral(dst, s.beauty, guides_of(s, u), size, ss, sc, sig,
                                           roi))
        << dst.geterror();
    if (!roi.defined())
        roi = s.beauty.roi();
    long empty = 0;
    const auto want = featref::cross_bilateral(
        s.sbeauty, ref_guides_of(s, u), size, ss, sc,
        { sig.albedo, sig.normal, sig.depth }, roi, &empty);
    expect_close(dst, want, roi, tolerance, what);
    EXPECT_EQ(empty_windows(dst), empty) << what;
}

TEST(CrossBilateral, MatchesReferenceForSizesAndGuides)
{
    const Scene s(23, 17, 3, 1, -5, 7);
    for (int size : { 1, 3, 7, 11 }) {
        check_cross_bilateral(s, {}, size, 2.0f, 0.0f, {}, {}, "all guides " + std::to_string(size));
        check_cross_bilateral(s, { false, false, false, false, false }, size, 1.5f, 0.0f, {},
                              {}, "no guide " + std::to_string(size));
        check_cross_bilateral(s, {}, size, 3.0f, 0.7f, { 0.2f, 0.5f, 0.3f }, {},
                              "colour " + std::to_string(size));
    }
    check_cross_bilateral(s, { true, false, true, false, false }, 5, 2.0f, 0.5f, {}, {},
                          "ids and depth");
    check_cross_bilateral(s, {}, 5, 2.0f, 0.0f, { 0.0f, -1.0f, 0.2f }, {},
                          "albedo and normal sigmas off");
}

TEST(CrossBilateral, IdsAsFloatHalfUint32AndOneChannelAlbedo)
{
    for (TypeDesc f : { TypeDesc::FLOAT, TypeDesc::HALF, TypeDesc::UINT32 }) {
        const Scene s(19, 13, 3, 11, 0, 0, f, 1, 1);
        check_cross_bilateral(s, {}, 5, 2.0f, 0.4f, {}, {}, std::string("ids ") + f.c_str());
    }
}

TEST(CrossBilateral, NonFiniteBeautyOddChannelsAndSubRoi)
{
    const Scene s(23, 17, 4, 21, 3, -4, TypeDesc::FLOAT, 3, 1, 0.08);
    check_cross_bilateral(s, {}, 7, 2.0f, 0.6f, {}, {}, "non-finite");
    check_cross_bilateral(s, {}, 5, 2.0f, 0.0f, {}, ROI(6, 20, -1, 9, 0, 1, 1, 4), "sub-ROI");
    const Scene grey(17, 11, 1, 22, 0, 0, TypeDesc::FLOAT, 1, 1, 0.05);
    check_cross_bilateral(grey, {}, 5, 2.0f, 0.3f, {}, {}, "one channel");
}

TEST(CrossBilateral, HandComputedThreePixels)
{
    // 3x1, no guides, size 3, sigma_spatial 1: neighbours weigh exp(-1/2).
    const ImageBuf beauty = from_values(3, 1, 1, { 1.0f, 2.0f, 6.0f });
    ImageBuf dst = mcdenoise::cross_bilateral(beauty, {}, 3, 1.0f);
    const double e = std::exp(-0.5);
    const std::vector<float> got = testimg::pixels(dst);
    EXPECT_NEAR(got[0], (1 + e * 2) / (1 + e), hand_tolerance);
    EXPECT_NEAR(got[1], (2 + e * (1 + 6)) / (1 + 2 * e), hand_tolerance);
    EXPECT_NEAR(got[2], (6 + e * 2) / (1 + e), hand_tolerance);
    // Depths 1, e, and 0 (infinitely far): sigma_depth 1 gives a depth
    // weight exp(-1/2) between the first two; the third is ln(1e9) away.
    const ImageBuf depth = from_values(3, 1, 1, { 1.0f, float(std::exp(1.0)), 0.0f });
    mcdenoise::Guides g;
    g.depth = &depth;
    dst = mcdenoise::cross_bilateral(beauty, g, 3, 1.0f, 0.0f, { 0.1f, 0.3f, 1.0f });
    const double far = std::exp(-0.5 - 0.5 * std::pow(std::log(1e9) - 1.0, 2));
    EXPECT_NEAR(testimg::pixels(dst)[1], (2 + e * e * 1 + far * 6) / (1 + e * e + far), hand_tolerance);
}

// ---------------------------------------------------------------- atrous

void check_atrous(const Scene& s, Use u, int iterations, float sl, ROI roi,
                  const std::string& what)
{
    ImageBuf dst;
    ASSERT_TRUE(mcdenoise::atrous(dst, s.beauty, guides_of(s, u), iterations, sl, {}, roi))
        << dst.geterror();
    if (!roi.defined())
        roi = s.beauty.roi();
    long empty = 0;
    const auto want = featref::atrous(s.sbeauty, ref_guides_of(s, u), iterations, sl, {}, roi,
                                      &empty);
    expect_close(dst, want, roi, tolerance, what);
    EXPECT_EQ(empty_windows(dst), empty) << what;
}

TEST(Atrous, MatchesReferenceForIterations)
{
    const Scene s(23, 17, 3, 31, -3, 2);
    for (int it : { 1, 2, 3, 4 }) {
        check_atrous(s, {}, it, 4.0f, {}, "all guides " + std::to_string(it));
        check_atrous(s, { true, true, true, true, false }, it, 4.0f, {},
                     "estimated variance " + std::to_string(it));
        check_atrous(s, { false, false, false, false, false }, it, 0.0f, {},
                     "no weights " + std::to_string(it));
    }
}

TEST(Atrous, OneChannelVarianceNonFiniteAndSubRoi)
{
    const Scene s(23, 17, 4, 41, 5, 5, TypeDesc::HALF, 1, 1, 0.06);
    check_atrous(s, {}, 3, 4.0f, {}, "non-finite");
    check_atrous(s, { true, false, true, true, false }, 3, 2.0f, ROI(9, 21, 8, 19, 0, 1, 2, 4),
                 "sub-ROI, alpha channels");
    const Scene grey(15, 12, 2, 42, 0, 0, TypeDesc::UINT32, 3, 3, 0.05);
    check_atrous(grey, {}, 2, 4.0f, {}, "two channels");
}

TEST(Atrous, HandComputedThreePixels)
{
    // 3x1, one iteration, no luminance or feature weight: the B3 taps in x
    // (the row's only ky is 0, whose 3/8 cancels).
    const ImageBuf beauty = from_values(3, 1, 1, { 1.0f, 2.0f, 6.0f });
    const ImageBuf dst    = mcdenoise::atrous(beauty, {}, 1, 0.0f);
    const std::vector<float> got = testimg::pixels(dst);
    EXPECT_NEAR(got[0], (3.0 / 8 * 1 + 1.0 / 4 * 2 + 1.0 / 16 * 6) / (3.0 / 8 + 1.0 / 4 + 1.0 / 16),
                hand_tolerance);
    EXPECT_NEAR(got[1], (3.0 / 8 * 2 + 1.0 / 4 * 7) / (3.0 / 8 + 1.0 / 2), hand_tolerance);
}

// ---------------------------------------------------------------- nlmeans

void check_nlmeans(const Scene& s, Use u, int r, int f, float k, ROI roi,
                   const std::string& what)
{
    ImageBuf dst;
    ASSERT_TRUE(mcdenoise::nlmeans(dst, s.beauty, guides_of(s, u), r, f, k, {}, roi))
        << dst.geterror();
    if (!roi.defined())
        roi = s.beauty.roi();
    long empty = 0;
    const auto want = featref::nlmeans(s.sbeauty, ref_guides_of(s, u), r, f, k, {}, roi, &empty);
    expect_close(dst, want, roi, tolerance, what);
    EXPECT_EQ(empty_windows(dst), empty) << what;
}

TEST(Nlmeans, MatchesReferenceForRadii)
{
    const Scene s(23, 17, 3, 51, -7, 4);
    for (int r : { 0, 1, 3, 5 })
        for (int f : { 0, 1, 2 }) {
            const std::string tag = std::to_string(r) + "/" + std::to_string(f);
            check_nlmeans(s, {}, r, f, mcdenoise::default_nlmeans_strength, {},
                          "all guides " + tag);
            check_nlmeans(s, { false, false, false, false, false }, r, f, 1.0f, {},
                          "estimated variance, no features " + tag);
        }
}

TEST(Nlmeans, OneChannelGuidesNonFiniteAndSubRoi)
{
    const Scene s(23, 17, 4, 61, 2, 3, TypeDesc::UINT32, 1, 1, 0.07);
    check_nlmeans(s, {}, 3, 1, mcdenoise::default_nlmeans_strength, {}, "non-finite");
    check_nlmeans(s, { true, true, false, true, false }, 4, 2, 0.8f,
                  ROI(5, 19, 6, 17, 0, 1, 1, 3), "sub-ROI");
    const Scene grey(13, 11, 1, 62, 0, 0, TypeDesc::FLOAT, 1, 3, 0.05);
    check_nlmeans(grey, {}, 3, 1, mcdenoise::default_nlmeans_strength, {}, "one channel");
}

TEST(Nlmeans, HandComputedTwoPixels)
{
    // 2x1, patch radius 0, variance 0.5 and 0.25: the neighbour's distance is
    // ((1 - 2)^2 - (v_p + min)) / (1e-10 + k^2 (v_p + v_q)) with k = 1.
    const ImageBuf beauty   = from_values(2, 1, 1, { 1.0f, 2.0f });
    const ImageBuf variance = from_values(2, 1, 1, { 0.5f, 0.25f });
    mcdenoise::Guides g;
    g.variance = &variance;
    const std::vector<float> got = testimg::pixels(mcdenoise::nlmeans(beauty, g, 1, 0, 1.0f));
    const double w0 = std::exp(-(1.0 - (0.5 + 0.25)) / (1e-10 + 0.75));
    const double w1 = std::exp(-(1.0 - (0.25 + 0.25)) / (1e-10 + 0.75));
    EXPECT_NEAR(got[0], (1 + w0 * 2) / (1 + w0), hand_tolerance);
    EXPECT_NEAR(got[1], (2 + w1 * 1) / (1 + w1), hand_tolerance);
}

// ---------------------------------------------------------------- demodulate

TEST(Demodulate, MatchesReferenceAndRoundTrips)
{
    for (int anc : { 3, 1 }) {
        const Scene s(23, 17, 4, 71, -2, 9, TypeDesc::FLOAT, anc, 3, 0.05);
        const ROI roi = s.beauty.roi();
        const ImageBuf d = mcdenoise::demodulate(s.beauty, s.albedo, 0.02f);
        ASSERT_FALSE(d.has_error()) << d.geterror();
        const auto want = featref::modulate(s.sbeauty, s.salbedo, 0.02f, true, roi);
        const std::vector<float> got = testimg::pixels(d, roi);
        for (size_t i = 0; i < got.size(); ++i) {
            if (std::isfinite(want[i])) {
                ASSERT_NEAR(got[i], want[i], 1e-6 * std::max(1.0, std::abs(want[i]))) << i;
            } else {
                ASSERT_EQ(std::isnan(got[i]), std::isnan(want[i])) << i;
                if (!std::isnan(want[i])) {
                    ASSERT_EQ(double(got[i]), want[i]) << i;
                }
            }
        }
        const ImageBuf back = mcdenoise::remodulate(d, s.albedo, 0.02f);
        const std::vector<float> orig = testimg::pixels(s.beauty, roi), again = testimg::pixels(back, roi);
        for (size_t i = 0; i < orig.size(); ++i) {
            if (std::isfinite(orig[i])) {
                ASSERT_NEAR(again[i], orig[i], 2e-6 * std::max(1.0f, std::abs(orig[i]))) << i;
            }
        }
        const ROI sub(0, 9, 10, 20, 0, 1, 2, 4);
        const auto rwant = featref::modulate(s.sbeauty, s.salbedo, 0.5, false, sub);
        const ImageBuf r = mcdenoise::remodulate(s.beauty, s.albedo, 0.5f, sub);
        const std::vector<float> rgot = testimg::pixels(r, sub);
        for (size_t i = 0; i < rgot.size(); ++i) {
            if (std::isfinite(rwant[i])) {
                ASSERT_NEAR(rgot[i], rwant[i], 1e-6 * std::max(1.0, std::abs(rwant[i]))) << i;
            }
        }
    }
}

// ---------------------------------------------------------------- common

using Run = std::function<bool(ImageBuf&, const ImageBuf&, const mcdenoise::Guides&, ROI, int)>;

struct Named {
    std::string name;
    Run run;
};

std::vector<Named> all_filters()
{
    return {
        { "cross_bilateral",
          [](ImageBuf& d, const ImageBuf& b, const mcdenoise::Guides& g, ROI r, int n) {
              return mcdenoise::cross_bilateral(d, b, g, 7, 2.0f, 0.5f, {}, r, n);
          } },
        { "atrous",
          [](ImageBuf& d, const ImageBuf& b, const mcdenoise::Guides& g, ROI r, int n) {
              return mcdenoise::atrous(d, b, g, 3, 4.0f, {}, r, n);
          } },
        { "nlmeans",
          [](ImageBuf& d, const ImageBuf& b, const mcdenoise::Guides& g, ROI r, int n) {
              return mcdenoise::nlmeans(d, b, g, 4, 1, mcdenoise::default_nlmeans_strength, {},
                                        r, n);
          } },
        { "demodulate",
          [](ImageBuf& d, const ImageBuf& b, const mcdenoise::Guides& g, ROI r, int n) {
              return mcdenoise::demodulate(d, b, *g.albedo, 0.01f, r, n);
          } },
    };
}

TEST(FeatureFilters, BitIdenticalForThreadsAndRoiSplits)
{
    const Scene s(61, 47, 4, 81, -3, 5, TypeDesc::FLOAT, 3, 3, 0.03);
    for (bool with_variance : { true, false }) {
        Use u;
        u.variance = with_variance;
        const mcdenoise::Guides g = guides_of(s, u);
        for (const Named& f : all_filters()) {
            ImageBuf one;
            ASSERT_TRUE(f.run(one, s.beauty, g, {}, 1)) << f.name << one.geterror();
            for (int n : { 2, 7 }) {
                ImageBuf many;
                ASSERT_TRUE(f.run(many, s.beauty, g, {}, n)) << f.name;
                EXPECT_TRUE(testimg::bit_identical(one, many)) << f.name << " threads " << n;
            }
            // Four uneven tiles filtered into one preallocated image.
            ImageBuf tiled(one.spec());
            const ROI dw = s.beauty.roi();
            const int mx = dw.xbegin + 17, my = dw.ybegin + 30;
            for (ROI t : { ROI(dw.xbegin, mx, dw.ybegin, my), ROI(mx, dw.xend, dw.ybegin, my),
                           ROI(dw.xbegin, mx, my, dw.yend), ROI(mx, dw.xend, my, dw.yend) }) {
                t.chbegin = 0;
                t.chend   = 4;
                ASSERT_TRUE(f.run(tiled, s.beauty, g, t, 2)) << f.name << tiled.geterror();
            }
            EXPECT_TRUE(testimg::bit_identical(one, tiled)) << f.name << " tiles";
        }
    }
}

TEST(FeatureFilters, InPlaceAndValueForm)
{
    const Scene s(23, 17, 3, 91);
    const mcdenoise::Guides g = guides_of(s, {});
    for (const Named& f : all_filters()) {
        ImageBuf want;
        ASSERT_TRUE(f.run(want, s.beauty, g, {}, 0)) << f.name;
        ImageBuf img;
        img.copy(s.beauty);
        ASSERT_TRUE(f.run(img, img, g, {}, 0)) << f.name << img.geterror();
        EXPECT_TRUE(testimg::bit_identical(want, img)) << f.name << " in place";
    }
    const ImageBuf bad = mcdenoise::nlmeans(s.beauty, g, -1);
    EXPECT_TRUE(bad.has_error());
}

// Every error: false, a message naming the problem, dst untouched.
void expect_error(const std::function<bool(ImageBuf&)>& run, const std::string& needle)
{
    ImageBuf dst = testimg::random_image(8, 8, 3, 99);
    const std::vector<float> before = testimg::pixels(dst);
    EXPECT_FALSE(run(dst)) << needle;
    EXPECT_NE(dst.geterror(false).find(needle), std::string::npos)
        << "'" << dst.geterror(false) << "' does not mention " << needle;
    EXPECT_EQ(testimg::pixels(dst), before) << needle << " changed dst";
}

TEST(FeatureFilters, ErrorsLeaveDstUntouched)
{
    const Scene s(23, 17, 3, 101, 0, 0);
    const Scene small(10, 10, 3, 102, 0, 0);
    const ImageBuf two = testimg::random_image(23, 17, 2, 103);
    const ImageBuf& b  = s.beauty;
    const mcdenoise::Guides g = guides_of(s, {});
    using namespace mcdenoise;
    expect_error([&](ImageBuf& d) { return cross_bilateral(d, b, g, 4); }, "odd");
    expect_error([&](ImageBuf& d) { return cross_bilateral(d, b, g, 257); }, "size");
    expect_error([&](ImageBuf& d) { return cross_bilateral(d, b, g, 3, 0.0f); }, "sigma_spatial");
    expect_error([&](ImageBuf& d) { return atrous(d, b, g, 0); }, "iterations");
    expect_error([&](ImageBuf& d) { return atrous(d, b, g, 11); }, "iterations");
    expect_error([&](ImageBuf& d) { return nlmeans(d, b, g, 128); }, "search_radius");
    expect_error([&](ImageBuf& d) { return nlmeans(d, b, g, 3, 8); }, "patch_radius");
    expect_error([&](ImageBuf& d) { return nlmeans(d, b, g, 3, 1, 0.0f); }, "strength");
    expect_error([&](ImageBuf& d) { return demodulate(d, b, s.albedo, 0.0f); }, "epsilon");
    expect_error([&](ImageBuf& d) { return remodulate(d, b, s.albedo, -1.0f); }, "epsilon");
    expect_error([&](ImageBuf& d) { return demodulate(d, b, two); }, "albedo has 2 channels");
    expect_error([&](ImageBuf& d) { return demodulate(d, b, small.albedo); }, "albedo data window");
    const float strength = default_nlmeans_strength;
    expect_error([&](ImageBuf& d) { return nlmeans(d, b, g, 3, 1, strength, {}, ROI(0, 30, 0, 5)); },
                 "ROI");
    // Each guide: a wrong channel count, then not covering the ROI.
    const ImageBuf* Guides::*members[] = { &Guides::object_id, &Guides::normal, &Guides::depth,
                                           &Guides::albedo, &Guides::variance };
    const char* names[] = { "object_id", "normal", "depth", "albedo", "variance" };
    const ImageBuf* smalls[] = { &small.ids, &small.normals, &small.depth, &small.albedo,
                                 &small.variance };
    for (int i = 0; i < 5; ++i) {
        Guides wrong = g;
        wrong.*members[i] = &two;
        for (const Named& f : all_filters()) {
            if (f.name == "demodulate")
                continue;
            expect_error([&](ImageBuf& d) { return f.run(d, b, wrong, {}, 0); },
                         std::string(names[i]) + " has 2 channels");
            Guides uncovering = g;
            uncovering.*members[i] = smalls[i];
            expect_error([&](ImageBuf& d) { return f.run(d, b, uncovering, {}, 0); },
                         std::string(names[i]) + " data window");
            // A guide that covers a small ROI is enough for it.
            ImageBuf ok;
            EXPECT_TRUE(f.run(ok, b, uncovering, ROI(2, 8, 1, 9, 0, 1, 0, 3), 0))
                << f.name << " " << ok.geterror();
        }
    }
}

}  // namespace
