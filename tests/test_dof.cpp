// test_dof.cpp: the depth-of-field filter: its focus map checked exactly on
// hand-built depth ramps (the report's 10 levels), its range rules, its
// errors, and its result against a per-pixel brute-force object mean.
#include <mcdenoise/mcdenoise.h>

#include "reference/spec_reference.h"
#include "support/guide_images.h"
#include "support/test_images.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using OIIO::ImageBuf;
using OIIO::ROI;
using OIIO::TypeDesc;

// A depth image whose columns hold `depths`, `rows` rows tall.
ImageBuf depth_columns(const std::vector<float>& depths, int rows = 2)
{
    const int w = int(depths.size());
    ImageBuf img(OIIO::ImageSpec(w, rows, 1, TypeDesc::FLOAT));
    std::vector<float> v;
    for (int y = 0; y < rows; ++y)
        v.insert(v.end(), depths.begin(), depths.end());
    img.set_pixels(img.roi(), TypeDesc::FLOAT, v.data());
    return img;
}

std::vector<float> first_row(const ImageBuf& img)
{
    std::vector<float> all = testimg::pixels(img);
    return std::vector<float>(all.begin(), all.begin() + img.spec().width);
}

// Ten depths evenly spread front to back: one per level.
std::vector<float> ramp() { return { 2, 2.5, 3, 3.5, 4, 4.5, 5, 5.5, 6, 6.5 }; }

TEST(DofFocusMap, ReportsTenLevelsFocusedFront)
{
    const ImageBuf map = mcdenoise::dof_focus_map(depth_columns(ramp()), 10, 0);
    ASSERT_FALSE(map.has_error()) << map.geterror();
    EXPECT_EQ(first_row(map),
              std::vector<float>({ 1, 3, 5, 7, 9, 11, 13, 15, 17, 19 }));
}

TEST(DofFocusMap, ReportsCenterAndBackFocus)
{
    EXPECT_EQ(first_row(mcdenoise::dof_focus_map(depth_columns(ramp()), 10, 4)),
              std::vector<float>({ 9, 7, 5, 3, 1, 3, 5, 7, 9, 11 }));
    EXPECT_EQ(first_row(mcdenoise::dof_focus_map(depth_columns(ramp()), 10, 9)),
              std::vector<float>({ 19, 17, 15, 13, 11, 9, 7, 5, 3, 1 }));
}

TEST(DofFocusMap, InfinitelyFarPixelsTakeTheLastLevel)
{
    const float inf = std::numeric_limits<float>::infinity();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    // Finite range [1, 3]; 1e10 (Cycles' background), inf and NaN are far.
    const ImageBuf map = mcdenoise::dof_focus_map(depth_columns({ 1, 2, 3, 1e10f, inf, nan }),
                                                  4, 0);
    EXPECT_EQ(first_row(map), std::vector<float>({ 1, 5, 7, 7, 7, 7 }));
}

TEST(DofFocusMap, ExplicitRangeClamps)
{
    // Range [2, 4] over 4 levels: 1 and 2 -> level 0, 3 -> 2, 4 and 9 -> 3.
    const ImageBuf map = mcdenoise::dof_focus_map(depth_columns({ 1, 2, 3, 4, 9 }), 4, 0,
                                                  2.0f, 4.0f);
    EXPECT_EQ(first_row(map), std::vector<float>({ 1, 1, 5, 7, 7 }));
}

TEST(DofFocusMap, FlatDepthIsAllLevelZero)
{
    const ImageBuf map = mcdenoise::dof_focus_map(depth_columns({ 5, 5, 5 }), 3, 1);
    EXPECT_EQ(first_row(map), std::vector<float>({ 3, 3, 3 }));
}

TEST(DofFocusMap, TheRangeIsTheWholeImagesNotTheRois)
{
    const ImageBuf depth = depth_columns(ramp());
    const ImageBuf part  = mcdenoise::dof_focus_map(depth, 10, 0, 0, 0, ROI(5, 10, 0, 2));
    ASSERT_FALSE(part.has_error()) << part.geterror();
    EXPECT_EQ(testimg::pixels(part, ROI(5, 10, 0, 1, 0, 1, 0, 1)),
              std::vector<float>({ 11, 13, 15, 17, 19 }));
}

TEST(DofErrors, LevelsAndFocusAreChecked)
{
    const ImageBuf depth  = depth_columns(ramp());
    const ImageBuf beauty = testimg::random_image(10, 2, 3, 1);
    const ImageBuf ids    = testimg::block_ids(10, 2, 2);
    for (auto [levels, focus] : { std::pair { 0, 0 }, { 5, 5 }, { 5, -1 } }) {
        ImageBuf dst;
        EXPECT_FALSE(mcdenoise::dof(dst, beauty, ids, depth, levels, focus));
        EXPECT_NE(dst.geterror().find("dof: need levels >= 1"), std::string::npos)
            << dst.geterror();
        EXPECT_FALSE(dst.initialized());
    }
    ImageBuf dst;
    EXPECT_FALSE(mcdenoise::dof(dst, beauty, ids, depth, 129, 0));
    EXPECT_NE(dst.geterror().find("window side of 257"), std::string::npos) << dst.geterror();
    EXPECT_FALSE(mcdenoise::dof(dst, beauty, ids, beauty, 10, 0));
    EXPECT_NE(dst.geterror().find("dof: depth has 3 channels"), std::string::npos)
        << dst.geterror();
}

// Depth increasing down the image with some far background.
ImageBuf depth_rows(int w, int h)
{
    ImageBuf img(OIIO::ImageSpec(w, h, 1, TypeDesc::FLOAT));
    std::vector<float> v(size_t(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            v[size_t(y) * w + x] = (x + y) % 17 == 0 ? 1e10f : 1.0f + 0.25f * y + 0.01f * x;
    img.set_pixels(img.roi(), TypeDesc::FLOAT, v.data());
    return img;
}

TEST(Dof, EachPixelIsTheObjectMeanOfItsOwnSide)
{
    ImageBuf beauty = testimg::random_image(45, 38, 3, 3, 0.0f, 2.0f);
    testimg::sprinkle_nonfinite(beauty, 0.01, 4);
    const ImageBuf ids   = testimg::block_ids(45, 38, 5);
    const ImageBuf depth = depth_rows(45, 38);
    const int levels = 6, focus = 2;
    ImageBuf dst;
    ASSERT_TRUE(mcdenoise::dof(dst, beauty, ids, depth, levels, focus)) << dst.geterror();
    const ImageBuf map = mcdenoise::dof_focus_map(depth, levels, focus);

    const spec::Image b = spec::from_imagebuf(beauty), id = spec::ids_from_imagebuf(ids);
    const spec::Image sides = spec::from_imagebuf(map);
    auto same = [&](int px, int py, int qx, int qy) {
        return std::nearbyint(id.at(qx, qy, 0)) == std::nearbyint(id.at(px, py, 0));
    };
    for (int y = 0; y < 38; ++y)
        for (int x = 0; x < 45; ++x) {
            const ROI one(x, x + 1, y, y + 1, 0, 1, 0, 3);
            const std::vector<double> want
                = spec::filter(b, one, int(sides.at(x, y, 0)), spec::Spatial::box,
                               spec::Reduce::weighted_mean, same, spec::unit_weight);
            const std::vector<float> got = testimg::pixels(dst, one);
            for (int c = 0; c < 3; ++c)
                ASSERT_NEAR(got[c], want[c], 2e-6 * std::max(1.0, std::abs(want[c])))
                    << "pixel " << x << "," << y << " side " << sides.at(x, y, 0);
        }
}

TEST(Dof, BitIdenticalAcrossThreadsAndSplits)
{
    const ImageBuf beauty = testimg::random_image(120, 100, 3, 6);
    const ImageBuf ids    = testimg::block_ids(120, 100, 7);
    const ImageBuf depth  = depth_rows(120, 100);
    ImageBuf one, seven, top;
    ASSERT_TRUE(mcdenoise::dof(one, beauty, ids, depth, 10, 0, 0, 0, {}, 1));
    ASSERT_TRUE(mcdenoise::dof(seven, beauty, ids, depth, 10, 0, 0, 0, {}, 7));
    EXPECT_TRUE(testimg::bit_identical(one, seven));
    const ROI part(0, 120, 0, 43, 0, 1, 0, 3);
    ASSERT_TRUE(mcdenoise::dof(top, beauty, ids, depth, 10, 0, 0, 0, part, 2));
    EXPECT_EQ(testimg::pixels(top, part), testimg::pixels(one, part));
}

}  // namespace
