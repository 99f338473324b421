// test_data_windows.cpp: every filter of the table (support/filter_table.h)
// on renders whose data window differs from the display window: overscan
// (larger, negative origin), a crop (smaller, inside), an origin far from 0;
// and on guides whose data windows cover the beauty's with a margin of
// other values. The result keeps the beauty's data and display windows, and
// its pixels equal those of the same pixels at origin 0 with exactly
// fitting guides (filtering depends only on the data window's contents).
#include "support/filter_table.h"
#include "support/guide_images.h"
#include "support/test_images.h"

#include <OpenImageIO/imagebufalgo.h>
#include <gtest/gtest.h>

namespace {

using OIIO::ImageBuf;
using OIIO::ROI;
using testfilters::FilterRow;
using testfilters::GuideSet;

constexpr int width = 61, height = 47;

/// `img` with its data window moved to (x0, y0) and display window set to
/// `display` (pixels unchanged).
ImageBuf placed(const ImageBuf& img, int x0, int y0, const ROI& display)
{
    ImageBuf out;
    out.copy(img);
    out.set_origin(x0, y0);
    out.set_full(display.xbegin, display.xend, display.ybegin, display.yend, 0, 1);
    return out;
}

/// Every guide of `g` moved to (x0, y0).
GuideSet placed(const GuideSet& g, int x0, int y0)
{
    const ROI any(0, 1, 0, 1);
    return { placed(g.object_id, x0, y0, any), placed(g.reflect_id, x0, y0, any),
             placed(g.normal, x0, y0, any),    placed(g.depth, x0, y0, any),
             placed(g.albedo, x0, y0, any),    placed(g.variance, x0, y0, any) };
}

/// A copy of `img` over `roi` grown by `margin` on every side, the margin
/// filled with `fill` (another object, another normal...).
ImageBuf padded(const ImageBuf& img, int margin, float fill)
{
    ROI grown = img.roi();
    grown.xbegin -= margin;
    grown.ybegin -= margin;
    grown.xend += margin;
    grown.yend += margin;
    OIIO::ImageSpec spec = img.spec();
    spec.x = grown.xbegin;
    spec.y = grown.ybegin;
    spec.width = grown.width();
    spec.height = grown.height();
    ImageBuf out(spec);
    std::vector<float> value(size_t(img.nchannels()), fill);
    OIIO::ImageBufAlgo::fill(out, value);
    OIIO::ImageBufAlgo::paste(out, img.xbegin(), img.ybegin(), 0, 0, img);
    return out;
}

class DataWindows : public ::testing::TestWithParam<FilterRow> {
protected:
    ImageBuf beauty = testimg::random_image(width, height, 3, 31, 0.0f, 10.0f);
    GuideSet guides = testimg::guide_set(width, height, 32);

    /// The filter's result at origin 0 with exactly fitting guides.
    ImageBuf reference() const
    {
        ImageBuf dst;
        EXPECT_TRUE(GetParam().run(dst, beauty, guides, 5, {}, 0)) << dst.geterror();
        return dst;
    }

    /// Runs at data window origin (x0, y0) with display window `display`
    /// and checks windows and pixels against reference().
    void expect_same_as_reference(int x0, int y0, const ROI& display) const
    {
        const ImageBuf moved = placed(beauty, x0, y0, display);
        ImageBuf dst;
        ASSERT_TRUE(GetParam().run(dst, moved, placed(guides, x0, y0), 5, {}, 0)) << dst.geterror();
        EXPECT_EQ(dst.roi(), moved.roi());
        const ROI full = dst.roi_full();
        EXPECT_EQ(ROI(full.xbegin, full.xend, full.ybegin, full.yend), display);
        EXPECT_EQ(testimg::pixels(dst), testimg::pixels(reference()));
    }
};

TEST_P(DataWindows, OverscanLargerThanTheDisplayWindow)
{
    // Data window x [-6, 55) y [-4, 43) around a 49 x 39 display window.
    expect_same_as_reference(-6, -4, ROI(0, 49, 0, 39));
}

TEST_P(DataWindows, CropSmallerThanTheDisplayWindow)
{
    expect_same_as_reference(20, 11, ROI(0, 1920, 0, 1080));
}

TEST_P(DataWindows, OriginFarFromZero)
{
    expect_same_as_reference(-100003, 77777, ROI(-100000, -99950, 77770, 77800));
}

TEST_P(DataWindows, GuidesCoveringWithAMarginGiveTheSameResult)
{
    const GuideSet wide = { padded(guides.object_id, 7, 99.0f), padded(guides.reflect_id, 3, 5.0f),
                            padded(guides.normal, 4, -1.0f),    padded(guides.depth, 6, 0.5f),
                            padded(guides.albedo, 2, 7.0f),     padded(guides.variance, 9, 3.0f) };
    ImageBuf dst;
    ASSERT_TRUE(GetParam().run(dst, beauty, wide, 5, {}, 0)) << dst.geterror();
    EXPECT_EQ(dst.roi(), beauty.roi());
    EXPECT_EQ(testimg::pixels(dst), testimg::pixels(reference()));
}

/// The filters that read a guide, for the checks of guides against the beauty.
class GuidedDataWindows : public DataWindows {};

bool reads_a_guide(const FilterRow& row) { return row.guides != 0; }

TEST_P(GuidedDataWindows, GuidesShortOfTheBeautyAreRefused)
{
    const ImageBuf moved = placed(beauty, 1, 0, beauty.roi_full());
    ImageBuf dst;
    EXPECT_FALSE(GetParam().run(dst, moved, guides, 5, {}, 0));
    EXPECT_NE(dst.geterror().find("does not cover"), std::string::npos) << dst.geterror();
    EXPECT_FALSE(dst.initialized());
}

INSTANTIATE_TEST_SUITE_P(EveryFilter, DataWindows, ::testing::ValuesIn(testfilters::filter_table()),
                         [](const auto& info) { return std::string(info.param.name); });
INSTANTIATE_TEST_SUITE_P(EveryGuidedFilter, GuidedDataWindows, ::testing::ValuesIn(testfilters::filter_rows(reads_a_guide)),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
