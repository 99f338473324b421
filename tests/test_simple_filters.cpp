// test_simple_filters.cpp: mean, median and gaussian against the tests'
// brute-force implementation of docs/filters.md, on random images of many shapes,
// pixel types and data windows, with non-finite values (thread counts and
// ROI splits: test_determinism.cpp).
#include <mcdenoise/mcdenoise.h>

#include "reference/spec_reference.h"
#include "support/test_images.h"

#include <gtest/gtest.h>

#include <ostream>

#include <cmath>
#include <string>

namespace {

using OIIO::ImageBuf;
using OIIO::ROI;
using OIIO::TypeDesc;

using BoolForm = bool (*)(ImageBuf&, const ImageBuf&, int, ROI, int);

struct SimpleFilter {
    std::string name;
    BoolForm run;
    spec::Spatial spatial;
    spec::Reduce reduce;
};

// GoogleTest prints a filter by its name (so CTest names stay short).
void PrintTo(const SimpleFilter& f, std::ostream* os) { *os << f.name; }

const SimpleFilter filters[] = {
    { "mean", static_cast<BoolForm>(mcdenoise::mean), spec::Spatial::box,
      spec::Reduce::weighted_mean },
    { "median", static_cast<BoolForm>(mcdenoise::median), spec::Spatial::box,
      spec::Reduce::median },
    { "gaussian", static_cast<BoolForm>(mcdenoise::gaussian), spec::Spatial::binomial,
      spec::Reduce::weighted_mean },
};

// Runs `f` on `img` over `roi` and checks every value against the reference:
// medians exactly (they are selections), means to double-rounding accuracy.
void expect_matches_spec(const SimpleFilter& f, const ImageBuf& img, int size,
                         ROI roi = {}, int nthreads = 0)
{
    ImageBuf dst;
    ASSERT_TRUE(f.run(dst, img, size, roi, nthreads)) << f.name << ": " << dst.geterror();
    if (!roi.defined())
        roi = img.roi();
    roi.chend = std::min(roi.chend, img.nchannels());
    const std::vector<double> want = spec::filter(spec::from_imagebuf(img), roi, size,
                                                  f.spatial, f.reduce, spec::all_viable,
                                                  spec::unit_weight);
    const std::vector<float> got = testimg::pixels(dst, roi);
    ASSERT_EQ(got.size(), want.size());
    int reported = 0;
    for (size_t i = 0; i < got.size() && reported < 5; ++i) {
        const double tol = f.reduce == spec::Reduce::median
                               ? 0.0
                               : 1e-6 * std::max(1.0, std::abs(want[i]));
        const double expected = f.reduce == spec::Reduce::median ? double(float(want[i]))
                                                                 : want[i];
        if (std::abs(double(got[i]) - expected) > tol) {
            ADD_FAILURE() << f.name << " size " << size << " value " << i << ": got "
                          << got[i] << ", docs/filters.md says " << want[i];
            ++reported;
        }
    }
}

class SimpleFilters : public ::testing::TestWithParam<SimpleFilter> {};

TEST_P(SimpleFilters, EverySizeFrom1To15OnASmallImage)
{
    const ImageBuf img = testimg::random_image(23, 17, 3, 1, 0.0f, 4.0f);
    for (int size = 1; size <= 15; size += 2)
        expect_matches_spec(GetParam(), img, size);
}

TEST_P(SimpleFilters, SizeOneIsTheIdentity)
{
    const ImageBuf img = testimg::random_image(9, 7, 4, 2);
    ImageBuf dst;
    ASSERT_TRUE(GetParam().run(dst, img, 1, {}, 0));
    EXPECT_TRUE(testimg::bit_identical(dst, img));
}

TEST_P(SimpleFilters, WindowsLargerThanTheImage)
{
    expect_matches_spec(GetParam(), testimg::random_image(50, 37, 2, 3), 41);
    expect_matches_spec(GetParam(), testimg::random_image(20, 10, 1, 4), 255);
}

TEST_P(SimpleFilters, LargerImageAcrossSlidingSumRestartsAndSimdBatches)
{
    const ImageBuf img = testimg::random_image(203, 141, 3, 5, -1.0f, 100.0f);
    for (int size : { 3, 7, 9, 11 })
        expect_matches_spec(GetParam(), img, size);
}

TEST_P(SimpleFilters, StrictSubRoiMatchesSpecAndTheFullImageBitForBit)
{
    const ImageBuf img = testimg::random_image(120, 90, 4, 6);
    const ROI roi(17, 90, 9, 77, 0, 1, 1, 3);
    expect_matches_spec(GetParam(), img, 7, roi);
    ImageBuf part, whole;
    ASSERT_TRUE(GetParam().run(part, img, 7, roi, 0));
    ASSERT_TRUE(GetParam().run(whole, img, 7, {}, 0));
    EXPECT_EQ(testimg::pixels(part, roi), testimg::pixels(whole, roi));
}

TEST_P(SimpleFilters, DataWindowWithNonZeroOrigin)
{
    const ImageBuf img = testimg::random_image(71, 66, 3, 7, 0.0f, 1.0f, TypeDesc::FLOAT,
                                               -13, 21);
    expect_matches_spec(GetParam(), img, 5);
    expect_matches_spec(GetParam(), img, 7, ROI(-10, 30, 25, 80, 0, 1, 0, 3));
}

TEST_P(SimpleFilters, HalfAndUint8Inputs)
{
    for (TypeDesc format : { TypeDesc::HALF, TypeDesc::UINT8 }) {
        const ImageBuf img = testimg::random_image(80, 70, 3, 8, 0.0f, 1.0f, format);
        expect_matches_spec(GetParam(), img, 3);
        expect_matches_spec(GetParam(), img, 7);
    }
}

TEST_P(SimpleFilters, NonFiniteValuesNeverPropagate)
{
    ImageBuf img = testimg::random_image(97, 83, 3, 9);
    testimg::sprinkle_nonfinite(img, 0.05, 10);
    for (int size : { 1, 3, 7, 13 })
        expect_matches_spec(GetParam(), img, size);
    ImageBuf dst;
    ASSERT_TRUE(GetParam().run(dst, img, 7, {}, 0));
    for (float v : testimg::pixels(dst))
        ASSERT_TRUE(std::isfinite(v));
}

TEST_P(SimpleFilters, WindowsWithNoFiniteValueGiveZeroAndAreCounted)
{
    ImageBuf img = testimg::random_image(30, 20, 1, 11);
    testimg::sprinkle_nonfinite(img, 1.0, 12);
    ImageBuf dst;
    ASSERT_TRUE(GetParam().run(dst, img, 3, {}, 0));
    for (float v : testimg::pixels(dst))
        ASSERT_EQ(v, 0.0f);
    EXPECT_EQ(dst.spec().get_int_attribute("mcdenoise:empty_windows"), 30 * 20);
}

TEST_P(SimpleFilters, InPlaceEqualsOutOfPlace)
{
    ImageBuf img = testimg::random_image(64, 48, 3, 16);
    ImageBuf expected;
    ASSERT_TRUE(GetParam().run(expected, img, 5, {}, 0));
    ASSERT_TRUE(GetParam().run(img, img, 5, {}, 0));
    EXPECT_TRUE(testimg::bit_identical(img, expected));
}

INSTANTIATE_TEST_SUITE_P(Spec, SimpleFilters, ::testing::ValuesIn(filters),
                         [](const auto& info) { return info.param.name; });

TEST(ValueForm, EqualsTheBoolForm)
{
    const ImageBuf img = testimg::random_image(40, 30, 3, 17);
    ImageBuf a, b, c;
    mcdenoise::mean(a, img, 5);
    mcdenoise::median(b, img, 5);
    mcdenoise::gaussian(c, img, 5);
    EXPECT_TRUE(testimg::bit_identical(mcdenoise::mean(img, 5), a));
    EXPECT_TRUE(testimg::bit_identical(mcdenoise::median(img, 5), b));
    EXPECT_TRUE(testimg::bit_identical(mcdenoise::gaussian(img, 5), c));
}

TEST(Median, EvenCountsAtCornersAverageTheTwoMiddleValues)
{
    // 3x3 window at corner (0, 0) of this image holds 4 values: 1, 2, 4, 8.
    OIIO::ImageSpec spec(2, 2, 1, TypeDesc::FLOAT);
    ImageBuf img(spec);
    const float v[4] = { 1.0f, 2.0f, 4.0f, 8.0f };
    img.set_pixels(img.roi(), TypeDesc::FLOAT, v);
    const std::vector<float> out = testimg::pixels(mcdenoise::median(img, 3));
    EXPECT_EQ(out, std::vector<float>({ 3.0f, 3.0f, 3.0f, 3.0f }));
}

TEST(Gaussian, HandComputedThreeByThree)
{
    // Center of a 3x3 image with a single 16 in the middle: weight 4 of 16.
    OIIO::ImageSpec spec(3, 3, 1, TypeDesc::FLOAT);
    ImageBuf img(spec);
    float v[9] = {};
    v[4] = 16.0f;
    img.set_pixels(img.roi(), TypeDesc::FLOAT, v);
    const std::vector<float> out = testimg::pixels(mcdenoise::gaussian(img, 3));
    EXPECT_FLOAT_EQ(out[4], 4.0f);
    // Corner (0,0): weights 4,2,2,1 over its clipped window; 16 has weight 1.
    EXPECT_FLOAT_EQ(out[0], 16.0f / 9.0f);
}

}  // namespace
