// test_extreme_values.cpp: every window filter of the table
// (support/filter_table.h) keeps huge finite values finite. A weighted mean
// or median of finite values lies between their extremes, so a beauty of
// values near FLT_MAX of both signs must give finite pixels, and a beauty
// holding one huge value everywhere must give that value back (within a few
// float steps, clamped to the range sums take) wherever a filter only
// averages the beauty.
#include "support/filter_table.h"
#include "support/guide_images.h"
#include "support/test_images.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

namespace {

using OIIO::ImageBuf;
using testfilters::FilterRow;

constexpr int width = 61, height = 47;
constexpr float huge = std::numeric_limits<float>::max();

/// A 3-channel beauty whose values are each +-FLT_MAX, +-1e38 or an
/// ordinary value, so window sums overflow float unless they are guarded.
ImageBuf huge_mixed_beauty()
{
    const float choices[] = { huge, -huge, 1e38f, -1e38f, 0.5f };
    std::mt19937 rng(31);
    ImageBuf beauty = testimg::random_image(width, height, 3, 30);
    std::vector<float> values(size_t(width) * height * 3);
    for (float& v : values)
        v = choices[rng() % 5];
    beauty.set_pixels(beauty.roi(), OIIO::TypeDesc::FLOAT, values.data());
    return beauty;
}

/// The index of the first non-finite value, or -1.
long first_nonfinite(const std::vector<float>& values)
{
    for (size_t i = 0; i < values.size(); ++i)
        if (!std::isfinite(values[i]))
            return long(i);
    return -1;
}

/// True for the rows whose result is a weighted mean or median of beauty
/// values alone (no division by albedo, no variance estimate from them).
bool averages_the_beauty(const FilterRow& row)
{
    for (const char* other : { "denoise", "demodulate", "clamp_fireflies" })
        if (std::strcmp(row.name, other) == 0)
            return false;
    return !row.per_pixel;
}

/// True for the rows that filter over windows (per-pixel operations may
/// overflow huge values by contract).
bool filters_windows(const FilterRow& row) { return !row.per_pixel; }

class ExtremeValues : public ::testing::TestWithParam<FilterRow> {};
class ConstantBeauty : public ::testing::TestWithParam<FilterRow> {};

TEST_P(ExtremeValues, HugeValuesOfBothSignsGiveFinitePixels)
{
    const ImageBuf beauty = huge_mixed_beauty();
    const testfilters::GuideSet guides = testimg::guide_set(width, height, 32);
    for (int size : { 3, 9 }) {
        ImageBuf result;
        ASSERT_TRUE(GetParam().run(result, beauty, guides, size, {}, 2)) << result.geterror();
        const std::vector<float> got = testimg::pixels(result);
        const long at = first_nonfinite(got);
        EXPECT_EQ(at, -1) << "size " << size << ": value " << at << " is "
                          << (at >= 0 ? got[size_t(at)] : 0.0f);
    }
}

/// The result of `row` (size 9) on a beauty holding `value` everywhere.
std::vector<float> filter_constant(const FilterRow& row, float value)
{
    ImageBuf beauty = testimg::random_image(width, height, 3, 33);
    const std::vector<float> values(size_t(width) * height * 3, value);
    beauty.set_pixels(beauty.roi(), OIIO::TypeDesc::FLOAT, values.data());
    ImageBuf result;
    EXPECT_TRUE(row.run(result, beauty, testimg::guide_set(width, height, 34), 9, {}, 2))
        << result.geterror();
    return testimg::pixels(result);
}

TEST_P(ConstantBeauty, ComesBackClampedToTheSummedRange)
{
    const bool median = std::strstr(GetParam().name, "median") != nullptr;
    // 2^100 is mcdenoise::max_summed_magnitude (pixel_block.h): sums clamp
    // to it, medians do not sum.
    const float limit = 0x1p100f;
    for (float value : { 1e30f, -1e30f, huge, -huge }) {
        const float want = median ? value : std::clamp(value, -limit, limit);
        const std::vector<float> got = filter_constant(GetParam(), value);
        for (size_t i = 0; i < got.size(); ++i)
            ASSERT_NEAR(got[i] / want, 1.0f, 1e-6f) << "value " << i << " is " << got[i] << " for "
                                                     << value;
    }
}

INSTANTIATE_TEST_SUITE_P(EveryWindowFilter, ExtremeValues,
                         ::testing::ValuesIn(testfilters::filter_rows(filters_windows)),
                         [](const auto& info) { return std::string(info.param.name); });
INSTANTIATE_TEST_SUITE_P(EveryAverageOfTheBeauty, ConstantBeauty,
                         ::testing::ValuesIn(testfilters::filter_rows(averages_the_beauty)),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
