// test_guided_filters.cpp: the object, BRDF and normal filters against the
// tests' brute-force implementation of docs/filters.md's rules, on random beauty with
// structured guides stored in several pixel types, with non-finite values,
// odd data windows; and their error checks (thread counts and ROI splits:
// test_determinism.cpp).
#include <mcdenoise/mcdenoise.h>

#include "reference/spec_reference.h"
#include "support/guide_images.h"
#include "support/test_images.h"

#include <OpenImageIO/imagebufalgo.h>
#include <gtest/gtest.h>

#include <ostream>

#include <cmath>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

namespace {

using OIIO::ImageBuf;
using OIIO::ROI;
using OIIO::TypeDesc;

// The guides of one test image, and docs/filters.md's reading of them.
struct Guides {
    ImageBuf ids, reflect, normals;
};

struct SpecGuides {
    spec::Image ids, reflect, normals;

    int64_t id(int x, int y) const
    {
        const double v = ids.at(x, y, 0);
        return std::isnan(v) ? -1 : int64_t(std::nearbyint(v));
    }
    int64_t reflect_id(int x, int y) const
    {
        const double v = reflect.at(x, y, 0);
        return std::isnan(v) || v < 0 ? -1 : int64_t(std::nearbyint(v));
    }
    // max(0, dot) of normalised normals; missing (zero) normals per docs/filters.md.
    double normal_weight(int px, int py, int qx, int qy) const
    {
        double a[3], b[3], la = 0, lb = 0;
        for (int c = 0; c < 3; ++c) {
            a[c] = normals.at(px, py, c);
            b[c] = normals.at(qx, qy, c);
            la += a[c] * a[c];
            lb += b[c] * b[c];
        }
        if (la == 0 || lb == 0)
            return la == lb ? 1.0 : 0.0;
        const double dot = (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) / std::sqrt(la * lb);
        return std::max(0.0, dot);
    }
};

using Run = std::function<bool(ImageBuf&, const ImageBuf&, const Guides&, int, ROI, int)>;
using MakeViable = std::function<spec::Viable(const SpecGuides&)>;
using MakeWeight = std::function<spec::GuideWeight(const SpecGuides&)>;

struct GuidedFilter {
    std::string name;
    Run run;
    spec::Spatial spatial;
    spec::Reduce reduce;
    MakeViable viable;
    MakeWeight weight;
};

// GoogleTest prints a filter by its name (so CTest names stay short).
void PrintTo(const GuidedFilter& f, std::ostream* os) { *os << f.name; }

spec::Viable same_object(const SpecGuides& g)
{
    return [&g](int px, int py, int qx, int qy) { return g.id(qx, qy) == g.id(px, py); };
}

spec::Viable brdf_rule(const SpecGuides& g)
{
    return [&g](int px, int py, int qx, int qy) {
        if (g.id(qx, qy) != g.id(px, py))
            return false;
        return g.reflect_id(px, py) < 0 || g.reflect_id(qx, qy) == g.reflect_id(px, py);
    };
}

spec::GuideWeight unit(const SpecGuides&) { return spec::unit_weight; }

spec::GuideWeight by_normal(const SpecGuides& g)
{
    return [&g](int px, int py, int qx, int qy) { return g.normal_weight(px, py, qx, qy); };
}

const GuidedFilter filters[] = {
    { "object_mean",
      [](ImageBuf& d, const ImageBuf& b, const Guides& g, int s, ROI r, int n) {
          return mcdenoise::object_mean(d, b, g.ids, s, r, n);
      },
      spec::Spatial::box, spec::Reduce::weighted_mean, same_object, unit },
    { "object_median",
      [](ImageBuf& d, const ImageBuf& b, const Guides& g, int s, ROI r, int n) {
          return mcdenoise::object_median(d, b, g.ids, s, r, n);
      },
      spec::Spatial::box, spec::Reduce::median, same_object, unit },
    { "object_gaussian",
      [](ImageBuf& d, const ImageBuf& b, const Guides& g, int s, ROI r, int n) {
          return mcdenoise::object_gaussian(d, b, g.ids, s, r, n);
      },
      spec::Spatial::binomial, spec::Reduce::weighted_mean, same_object, unit },
    { "brdf_mean",
      [](ImageBuf& d, const ImageBuf& b, const Guides& g, int s, ROI r, int n) {
          return mcdenoise::brdf_mean(d, b, g.ids, g.reflect, s, r, n);
      },
      spec::Spatial::box, spec::Reduce::weighted_mean, brdf_rule, unit },
    { "brdf_gaussian",
      [](ImageBuf& d, const ImageBuf& b, const Guides& g, int s, ROI r, int n) {
          return mcdenoise::brdf_gaussian(d, b, g.ids, g.reflect, s, r, n);
      },
      spec::Spatial::binomial, spec::Reduce::weighted_mean, brdf_rule, unit },
    { "brdf_median",
      [](ImageBuf& d, const ImageBuf& b, const Guides& g, int s, ROI r, int n) {
          return mcdenoise::brdf_median(d, b, g.ids, g.reflect, s, r, n);
      },
      spec::Spatial::box, spec::Reduce::median, brdf_rule, unit },
    { "normal_mean",
      [](ImageBuf& d, const ImageBuf& b, const Guides& g, int s, ROI r, int n) {
          return mcdenoise::normal_mean(d, b, g.ids, g.normals, s, r, n);
      },
      spec::Spatial::box, spec::Reduce::weighted_mean, same_object, by_normal },
    { "normal_gaussian",
      [](ImageBuf& d, const ImageBuf& b, const Guides& g, int s, ROI r, int n) {
          return mcdenoise::normal_gaussian(d, b, g.ids, g.normals, s, r, n);
      },
      spec::Spatial::binomial, spec::Reduce::weighted_mean, same_object, by_normal },
};

Guides make_guides(int w, int h, uint32_t seed, TypeDesc id_format = TypeDesc::FLOAT,
                   int x0 = 0, int y0 = 0)
{
    return { testimg::block_ids(w, h, seed, id_format, x0, y0),
             testimg::block_reflect_ids(w, h, seed + 1, x0, y0),
             testimg::wavy_normals(w, h, seed + 2, x0, y0) };
}

void expect_matches_spec(const GuidedFilter& f, const ImageBuf& beauty, const Guides& g,
                         int size, ROI roi = {}, int nthreads = 0)
{
    ImageBuf dst;
    ASSERT_TRUE(f.run(dst, beauty, g, size, roi, nthreads)) << f.name << ": " << dst.geterror();
    if (!roi.defined())
        roi = beauty.roi();
    const SpecGuides sg { spec::ids_from_imagebuf(g.ids), spec::ids_from_imagebuf(g.reflect),
                          spec::from_imagebuf(g.normals) };
    const std::vector<double> want = spec::filter(spec::from_imagebuf(beauty), roi, size,
                                                  f.spatial, f.reduce, f.viable(sg),
                                                  f.weight(sg));
    const std::vector<float> got = testimg::pixels(dst, roi);
    ASSERT_EQ(got.size(), want.size());
    int reported = 0;
    for (size_t i = 0; i < got.size() && reported < 5; ++i) {
        const bool median = f.reduce == spec::Reduce::median;
        const double expected = median ? double(float(want[i])) : want[i];
        const double tol = median ? 0.0 : 2e-6 * std::max(1.0, std::abs(want[i]));
        if (std::abs(double(got[i]) - expected) > tol) {
            ADD_FAILURE() << f.name << " size " << size << " value " << i << ": got " << got[i]
                          << ", docs/filters.md says " << want[i];
            ++reported;
        }
    }
}

class GuidedFilters : public ::testing::TestWithParam<GuidedFilter> {};

TEST_P(GuidedFilters, MatchSpecForSizes1To11)
{
    const ImageBuf beauty = testimg::random_image(61, 47, 3, 1, 0.0f, 5.0f);
    const Guides g        = make_guides(61, 47, 2);
    for (int size : { 1, 3, 5, 7, 11 })
        expect_matches_spec(GetParam(), beauty, g, size);
}

TEST_P(GuidedFilters, MatchSpecForWideWindows)
{
    // Wide enough for sliding box sums, fast rows in segments and long runs
    // of edge pixels.
    const int w = 96, h = 71;
    const ImageBuf beauty = testimg::random_image(w, h, 3, 40, 0.0f, 5.0f);
    std::vector<float> ids(size_t(w) * h), reflect(size_t(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {  // large objects: a slanted edge and a band
            ids[size_t(y) * w + x]     = float(x + y / 3 < 50 ? 1 : y > 45 ? 2 : 3);
            reflect[size_t(y) * w + x] = x > 60 && y < 30 ? float((x / 12) % 2) : -1.0f;
        }
    Guides g = make_guides(w, h, 41);
    g.ids     = testimg::from_values(w, h, 1, TypeDesc::FLOAT, 0, 0, ids);
    g.reflect = testimg::from_values(w, h, 1, TypeDesc::FLOAT, 0, 0, reflect);
    for (int size : { 13, 21 })
        expect_matches_spec(GetParam(), beauty, g, size);
}

TEST_P(GuidedFilters, EachPixelAloneGivesItsBitsInTheWholeImage)
{
    // A one-pixel ROI sums its window apart (pixel by pixel for each
    // offset); in the whole image the same pixel may share window columns
    // with a run of its key. Both must give the same bits.
    const ImageBuf beauty = testimg::random_image(61, 47, 3, 42, 0.0f, 5.0f);
    const Guides g        = make_guides(61, 47, 43);
    for (int size : { 3, 7 }) {
        ImageBuf whole;
        ASSERT_TRUE(GetParam().run(whole, beauty, g, size, {}, 1)) << whole.geterror();
        for (int y = 0; y < 47; y += 2)
            for (int x = y % 3; x < 61; x += 3) {
                const ROI pixel(x, x + 1, y, y + 1, 0, 1, 0, 3);
                ImageBuf alone;
                ASSERT_TRUE(GetParam().run(alone, beauty, g, size, pixel, 1)) << alone.geterror();
                ASSERT_EQ(testimg::pixels(alone, pixel), testimg::pixels(whole, pixel))
                    << "pixel (" << x << ", " << y << ") size " << size;
            }
    }
}

TEST_P(GuidedFilters, IdsStoredAsFloatHalfAndWholeNumbers)
{
    // Integer pixel types hold the ids themselves (an Arnold ID pass is
    // uint32), not values OIIO would scale to [0, 1]: every type gives the
    // float ids' result.
    const ImageBuf beauty = testimg::random_image(40, 33, 3, 3);
    ImageBuf as_float;
    ASSERT_TRUE(GetParam().run(as_float, beauty, make_guides(40, 33, 4), 5, {}, 0));
    for (TypeDesc format : { TypeDesc::FLOAT, TypeDesc::HALF, TypeDesc::UINT8, TypeDesc::UINT16,
                             TypeDesc::UINT32, TypeDesc::INT32 }) {
        const Guides g = make_guides(40, 33, 4, format);
        expect_matches_spec(GetParam(), beauty, g, 5);
        ImageBuf dst;
        ASSERT_TRUE(GetParam().run(dst, beauty, g, 5, {}, 0)) << dst.geterror();
        EXPECT_EQ(testimg::pixels(dst, dst.roi()), testimg::pixels(as_float, as_float.roi()))
            << GetParam().name << " with ids stored as " << format;
    }
}

TEST_P(GuidedFilters, IdsRoundAsSpecSaysAcrossTheirRange)
{
    // Blocks of ids that round half to even, NaN, the ends of 32 bits and
    // beyond (which take the renumbering path), stored as float and double.
    const double choices[] = { 2.4, 2.5, 3.5, -0.5, -2.5, 7.49, std::nan(""), 2147483520.0,
                               -2147483648.0, 3e9, -3e9, 1e15, -1e15 };
    const int w = 53, h = 41;
    std::vector<float> ids(size_t(w) * h), reflect(size_t(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t block = size_t((x / 6) * 5 + (y / 5) * 3);  // reflect: finer
            const size_t facet = size_t(((x + 1) / 3) * 7 + ((y + 2) / 2) * 2);
            ids[size_t(y) * w + x]     = float(choices[block % std::size(choices)]);
            reflect[size_t(y) * w + x] = float(choices[facet % std::size(choices)]);
        }
    const ImageBuf beauty = testimg::random_image(w, h, 3, 44, 0.0f, 5.0f);
    for (TypeDesc format : { TypeDesc::FLOAT, TypeDesc::DOUBLE }) {
        Guides g  = make_guides(w, h, 45);
        g.ids     = testimg::from_values(w, h, 1, format, 0, 0, ids);
        g.reflect = testimg::from_values(w, h, 1, format, 0, 0, reflect);
        expect_matches_spec(GetParam(), beauty, g, 5);
    }
}

TEST_P(GuidedFilters, NonFiniteBeautyNeverPropagates)
{
    ImageBuf beauty = testimg::random_image(70, 52, 3, 5);
    testimg::sprinkle_nonfinite(beauty, 0.04, 6);
    const Guides g = make_guides(70, 52, 7);
    expect_matches_spec(GetParam(), beauty, g, 3);
    expect_matches_spec(GetParam(), beauty, g, 7);
}

TEST_P(GuidedFilters, SmoothCurvedSurfacesMatchSpecAtEverySize)
{
    // A sphere-like normal field (no two neighbours alike, every window
    // smooth enough for the normal filters' dot-weighted sums), two objects
    // and a sprinkle of non-finite values: windows up to 21 wide, clipped at
    // every edge.
    const int w = 83, h = 64;
    ImageBuf beauty = testimg::random_image(w, h, 3, 51, 0.0f, 5.0f);
    testimg::sprinkle_nonfinite(beauty, 0.02, 52);
    std::vector<float> ids(size_t(w) * h), normals(size_t(w) * h * 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * w + x;
            ids[i]         = float(x < 2 * y ? 4 : 9);
            const float n[3] = { float(x - 30) / 40.0f, float(y - 20) / 40.0f, 1.0f };
            std::copy(n, n + 3, normals.begin() + std::ptrdiff_t(i) * 3);
        }
    Guides g   = make_guides(w, h, 53);
    g.ids      = testimg::from_values(w, h, 1, TypeDesc::FLOAT, 0, 0, ids);
    g.normals  = testimg::from_values(w, h, 3, TypeDesc::FLOAT, 0, 0, normals);
    for (int size : { 3, 7, 13, 21 })
        expect_matches_spec(GetParam(), beauty, g, size);
}

TEST_P(GuidedFilters, NonZeroOriginAndStrictSubRoi)
{
    const ImageBuf beauty = testimg::random_image(64, 50, 3, 8, 0.0f, 1.0f, TypeDesc::FLOAT,
                                                  -9, 13);
    const Guides g = make_guides(64, 50, 9, TypeDesc::FLOAT, -9, 13);
    expect_matches_spec(GetParam(), beauty, g, 5, ROI(-3, 40, 20, 55, 0, 1, 1, 3));
}

TEST_P(GuidedFilters, GuidesWithLargerDataWindowsGiveTheSameResult)
{
    const ImageBuf beauty = testimg::random_image(48, 40, 3, 10);
    const Guides big      = make_guides(60, 55, 11, TypeDesc::FLOAT, -6, -5);
    Guides cropped;
    cropped.ids     = OIIO::ImageBufAlgo::cut(big.ids, ROI(0, 48, 0, 40));
    cropped.reflect = OIIO::ImageBufAlgo::cut(big.reflect, ROI(0, 48, 0, 40));
    cropped.normals = OIIO::ImageBufAlgo::cut(big.normals, ROI(0, 48, 0, 40));
    ImageBuf a, b;
    ASSERT_TRUE(GetParam().run(a, beauty, big, 5, {}, 0)) << a.geterror();
    ASSERT_TRUE(GetParam().run(b, beauty, cropped, 5, {}, 0)) << b.geterror();
    EXPECT_TRUE(testimg::bit_identical(a, b));
    expect_matches_spec(GetParam(), beauty, cropped, 5);
}

// The ids moved beyond 32 bits, keeping equality and sign: each id rounded
// to r, then r >= 0 becomes r + 2^40 and r < 0 becomes r - 2^40 (stored as
// double, exact; NaN stays NaN).
ImageBuf beyond_32_bits(const ImageBuf& ids)
{
    ImageBuf wide(OIIO::ImageSpec(ids.spec().width, ids.spec().height, 1, TypeDesc::DOUBLE));
    wide.set_origin(ids.spec().x, ids.spec().y);
    constexpr double shift = 1099511627776.0;  // 2^40
    for (OIIO::ImageBuf::Iterator<double, double> out(wide); !out.done(); ++out) {
        const double r = std::nearbyint(ids.getchannel(out.x(), out.y(), 0, 0));
        out[0]         = r >= 0.0 ? r + shift : r - shift;
    }
    return wide;
}

TEST_P(GuidedFilters, IdsBeyond32BitsFilterAsTheirSmallTwins)
{
    const ImageBuf beauty = testimg::random_image(45, 38, 3, 30);
    const Guides small    = make_guides(45, 38, 31);
    Guides wide           = small;
    wide.ids              = beyond_32_bits(small.ids);
    wide.reflect          = beyond_32_bits(small.reflect);
    ImageBuf a, b;
    ASSERT_TRUE(GetParam().run(a, beauty, small, 5, {}, 0)) << a.geterror();
    ASSERT_TRUE(GetParam().run(b, beauty, wide, 5, {}, 0)) << b.geterror();
    EXPECT_TRUE(testimg::bit_identical(a, b));
}

TEST_P(GuidedFilters, RejectsBadGuidesAndLeavesDstAlone)
{
    const ImageBuf beauty = testimg::random_image(32, 24, 3, 15);
    const Guides good     = make_guides(32, 24, 16);
    auto expect_rejected  = [&](const Guides& g, const std::string& words) {
        ImageBuf dst = testimg::random_image(5, 5, 3, 17);
        const std::vector<float> before = testimg::pixels(dst);
        EXPECT_FALSE(GetParam().run(dst, beauty, g, 3, {}, 0)) << words;
        EXPECT_NE(dst.geterror().find(words), std::string::npos) << dst.geterror();
        EXPECT_EQ(testimg::pixels(dst), before);
    };
    Guides three_channel_ids = good;
    three_channel_ids.ids    = testimg::random_image(32, 24, 3, 18);
    expect_rejected(three_channel_ids, "object_id has 3 channels, expected 1");
    Guides small_ids = good;
    small_ids.ids    = testimg::block_ids(31, 24, 19);
    expect_rejected(small_ids, "object_id data window");
    Guides shifted = good;
    shifted.ids    = testimg::block_ids(32, 24, 19, TypeDesc::FLOAT, 1, 0);
    expect_rejected(shifted, "does not cover the ROI");
    Guides empty_ids = good;
    empty_ids.ids.clear();
    expect_rejected(empty_ids, "object_id image is empty");
}

INSTANTIATE_TEST_SUITE_P(Spec, GuidedFilters, ::testing::ValuesIn(filters),
                         [](const auto& info) { return info.param.name; });

TEST(GuidedErrors, BadSecondGuidesAreNamed)
{
    const ImageBuf beauty = testimg::random_image(20, 20, 3, 1);
    const Guides g        = make_guides(20, 20, 2);
    ImageBuf dst;
    EXPECT_FALSE(mcdenoise::brdf_mean(dst, beauty, g.ids, g.normals, 3));
    EXPECT_NE(dst.geterror().find("brdf_mean: reflect_id has 3 channels"), std::string::npos)
        << dst.geterror();
    EXPECT_FALSE(mcdenoise::normal_mean(dst, beauty, g.ids, g.ids, 3));
    EXPECT_NE(dst.geterror().find("normal_mean: normal has 1 channel, expected 3"),
              std::string::npos)
        << dst.geterror();
    EXPECT_FALSE(mcdenoise::object_median(dst, beauty, g.ids, 8));
    EXPECT_NE(dst.geterror().find("object_median: size must be odd"), std::string::npos);
}

TEST(GuidedFilters, UniformObjectWindowsMatchTheSimpleFilter)
{
    // One object everywhere: every window is viable, so each object filter
    // equals its simple filter bit for bit (the shared fast path).
    const ImageBuf beauty = testimg::random_image(90, 70, 3, 20);
    ImageBuf one_object(OIIO::ImageSpec(90, 70, 1, TypeDesc::FLOAT));
    OIIO::ImageBufAlgo::fill(one_object, { 4.0f });
    EXPECT_TRUE(testimg::bit_identical(mcdenoise::object_mean(beauty, one_object, 7),
                                       mcdenoise::mean(beauty, 7)));
    EXPECT_TRUE(testimg::bit_identical(mcdenoise::object_median(beauty, one_object, 7),
                                       mcdenoise::median(beauty, 7)));
    EXPECT_TRUE(testimg::bit_identical(mcdenoise::object_gaussian(beauty, one_object, 7),
                                       mcdenoise::gaussian(beauty, 7)));
}

}  // namespace
