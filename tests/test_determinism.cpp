// test_determinism.cpp: every filter of the table (support/filter_table.h)
// gives bit-identical pixels on 1, 2 and 16 threads and for any split of
// the ROI into pieces filtered separately, with non-finite values in the
// beauty. A new filter is covered by its row in the table.
#include "support/filter_table.h"
#include "support/guide_images.h"
#include "support/test_images.h"

#include <gtest/gtest.h>

#include <cstring>

namespace {

using OIIO::ImageBuf;
using OIIO::ROI;
using testfilters::FilterRow;

/// An odd-sized beauty (so thread chunks and SIMD batches do not line up)
/// with a sprinkle of NaN and infinities, and every guide.
struct Scene {
    ImageBuf beauty = testimg::random_image(157, 131, 3, 21, 0.0f, 40.0f, OIIO::TypeDesc::FLOAT, -5, 8);
    testfilters::GuideSet guides = testimg::guide_set(157, 131, 22, -5, 8);
    Scene() { testimg::sprinkle_nonfinite(beauty, 0.003, 23); }
};

/// The first index where `a` and `b` differ bit for bit (NaN payloads
/// included), or -1.
long first_difference(const std::vector<float>& a, const std::vector<float>& b)
{
    if (a.size() != b.size())
        return 0;
    for (size_t i = 0; i < a.size(); ++i)
        if (std::memcmp(&a[i], &b[i], sizeof(float)) != 0)
            return long(i);
    return -1;
}

class Determinism : public ::testing::TestWithParam<FilterRow> {};

TEST_P(Determinism, OneTwoAndSixteenThreadsAreBitIdentical)
{
    const Scene scene;
    for (int size : { 3, 9 }) {
        ImageBuf one, two, sixteen;
        ASSERT_TRUE(GetParam().run(one, scene.beauty, scene.guides, size, {}, 1)) << one.geterror();
        ASSERT_TRUE(GetParam().run(two, scene.beauty, scene.guides, size, {}, 2)) << two.geterror();
        ASSERT_TRUE(GetParam().run(sixteen, scene.beauty, scene.guides, size, {}, 16)) << sixteen.geterror();
        EXPECT_TRUE(testimg::bit_identical(one, two)) << "size " << size;
        EXPECT_TRUE(testimg::bit_identical(one, sixteen)) << "size " << size;
    }
}

TEST_P(Determinism, AnyRoiSplitGivesTheSamePixels)
{
    const Scene scene;
    const ROI dw = scene.beauty.roi();
    ImageBuf whole;
    ASSERT_TRUE(GetParam().run(whole, scene.beauty, scene.guides, 7, {}, 1)) << whole.geterror();
    std::vector<ROI> pieces;
    for (int split : { 1, 37, 64, 65, 130 }) {
        const int y = dw.ybegin + split, x = dw.xbegin + split;
        pieces.push_back(ROI(dw.xbegin, dw.xend, dw.ybegin, y, 0, 1, 0, 3));
        pieces.push_back(ROI(dw.xbegin, dw.xend, y, dw.yend, 0, 1, 0, 3));
        pieces.push_back(ROI(dw.xbegin, x, dw.ybegin, dw.yend, 0, 1, 0, 3));
        pieces.push_back(ROI(x, dw.xend, dw.ybegin, dw.yend, 0, 1, 0, 3));
    }
    pieces.push_back(ROI(dw.xbegin + 40, dw.xbegin + 41, dw.ybegin + 50, dw.ybegin + 51, 0, 1, 0, 3));
    pieces.push_back(ROI(dw.xbegin + 3, dw.xend - 11, dw.ybegin + 17, dw.yend - 2, 0, 1, 1, 3));
    for (const ROI& piece : pieces) {
        for (int nthreads : { 1, 16 }) {
            ImageBuf part;
            ASSERT_TRUE(GetParam().run(part, scene.beauty, scene.guides, 7, piece, nthreads)) << part.geterror();
            const std::vector<float> got = testimg::pixels(part, piece), want = testimg::pixels(whole, piece);
            const long at = first_difference(got, want);
            EXPECT_EQ(at, -1) << "value " << at << ": " << (at >= 0 ? got[size_t(at)] : 0.0f) << " vs "
                              << (at >= 0 ? want[size_t(at)] : 0.0f) << " in x [" << piece.xbegin << ", " << piece.xend << ") y [" << piece.ybegin << ", " << piece.yend
                << ") on " << nthreads << " threads";
        }
    }
}

INSTANTIATE_TEST_SUITE_P(EveryFilter, Determinism, ::testing::ValuesIn(testfilters::filter_table()),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
