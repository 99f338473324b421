// test_layer_sums.cpp: reconcile_sum on hand-computed one-pixel cases:
// the difference shared in proportion to colour^2 x error within each
// term's noise, the rest by each term's part of the rebuild, never below
// zero, divided by a term's colour, and nothing changed where the raw
// terms do not rebuild the raw beauty.
#include "passes/layer_sums.h"

#include <gtest/gtest.h>

#include <initializer_list>
#include <vector>

namespace {

using OIIO::ImageBuf;

/// A 1x1 float image with `values` (one per channel).
ImageBuf pixel(std::initializer_list<float> values)
{
    ImageBuf img(OIIO::ImageSpec(1, 1, int(values.size()), OIIO::TypeDesc::FLOAT));
    img.setpixel(0, 0, values.begin(), int(values.size()));
    return img;
}

/// A one-pixel block of `image`.
mcdenoise::PixelBlock block(const ImageBuf& image)
{
    mcdenoise::PixelBlock out;
    EXPECT_TRUE(mcdenoise::load_block(image, image.roi(), out));
    return out;
}

/// One-channel terms over one pixel: results, raw values, errors, colours.
struct Terms {
    std::vector<ImageBuf> results, raws, colour_images;
    std::vector<mcdenoise::PixelBlock> raw_blocks, colour_blocks;
    std::vector<mcdenoise::Plane<float>> errors;

    Terms(std::initializer_list<float> results_, std::initializer_list<float> raws_,
          std::initializer_list<float> errors_, std::initializer_list<float> colours = {})
    {
        for (float v : results_)
            results.push_back(pixel({ v }));
        for (float v : raws_)
            raws.push_back(pixel({ v }));
        for (float v : colours)
            colour_images.push_back(pixel({ v }));
        for (float e : errors_)
            errors.emplace_back(OIIO::ROI(0, 1, 0, 1), e);
        for (const ImageBuf& r : raws)
            raw_blocks.push_back(block(r));
        for (const ImageBuf& c : colour_images)
            colour_blocks.push_back(block(c));
    }

    /// Reconcile to `beauty`, the raw beauty being `raw_beauty`.
    void reconcile(float beauty, float raw_beauty)
    {
        std::vector<mcdenoise::SumTerm> terms;
        for (size_t i = 0; i < results.size(); ++i)
            terms.push_back({ &results[i], &raw_blocks[i],
                              colour_blocks.empty() ? nullptr : &colour_blocks[i], &errors[i] });
        const ImageBuf raw = pixel({ raw_beauty });
        mcdenoise::reconcile_sum(pixel({ beauty }), block(raw), terms, 1);
    }

    float operator[](size_t i) const { return results[i].getchannel(0, 0, 0, 0); }
};

TEST(ReconcileSum, TheDifferenceGoesInProportionToEachTermsError)
{
    // delta 10 - (2 + 4) = 4, errors 1 and 3: +1 and +3, both within
    // 2 sigma (2 and 3.46)
    Terms t({ 2, 4 }, { 1, 2 }, { 1, 3 });
    t.reconcile(10, 3);
    EXPECT_FLOAT_EQ(t[0], 3.0f);
    EXPECT_FLOAT_EQ(t[1], 7.0f);
}

TEST(ReconcileSum, WithinEachTermsNoiseFirstThenBeyond)
{
    // delta 8, errors 1 and 1 (reach 2 each): first round +2 and +2 (the
    // shares of 4 stop at the reach), then the 4 left by their parts of
    // the rebuild, 3 : 3: +2 and +2
    Terms t({ 1, 1 }, { 1, 1 }, { 1, 1 });
    t.reconcile(10, 2);
    EXPECT_FLOAT_EQ(t[0], 5.0f);
    EXPECT_FLOAT_EQ(t[1], 5.0f);
    // a term with no error stays while another can take it all within
    // its noise: delta 1, reach of the second 2 x sqrt(4) = 4
    Terms u({ 3, 1 }, { 3, 1 }, { 0, 4 });
    u.reconcile(5, 4);
    EXPECT_FLOAT_EQ(u[0], 3.0f);
    EXPECT_FLOAT_EQ(u[1], 2.0f);
}

TEST(ReconcileSum, BeyondTheirNoiseTheTermsTakeTheRestByTheirPartOfTheRebuild)
{
    // delta 12 - 8 = 4, errors 0.01 (reach 0.2 each): first +0.2 each,
    // then the 3.6 left by 6.2 : 2.2, a gain on the rebuild
    Terms t({ 6, 2 }, { 6, 2 }, { 0.01f, 0.01f });
    t.reconcile(12, 8);
    EXPECT_NEAR(t[0], 6.2 + 3.6 * 6.2 / 8.4, 1e-5);
    EXPECT_NEAR(t[1], 2.2 + 3.6 * 2.2 / 8.4, 1e-5);
}

TEST(ReconcileSum, NoTermIsPushedBelowZero)
{
    // delta 1 - (2 + 4) = -5, errors 1 and 1: -2.5 each would take the
    // first below 0; it stops at 0 and the second takes the other -3
    Terms t({ 2, 4 }, { 2, 4 }, { 1, 1 });
    t.reconcile(1, 6);
    EXPECT_FLOAT_EQ(t[0], 0.0f);
    EXPECT_FLOAT_EQ(t[1], 1.0f);
}

TEST(ReconcileSum, SharesAreDividedByTheColour)
{
    // beauty 0.5 x 2 + 1 = 2 raw; denoised beauty 4, delta 2; weights
    // colour^2 x error: 0.25 x 4 = 1 and 1 x 1 = 1: 1 each in the
    // beauty's units, so the first moves by 1 / 0.5 = 2 (its reach is
    // 2 x 2 / 0.5 = 8) and the second by 1 (reach 2)
    Terms t({ 2, 1 }, { 2, 1 }, { 4, 1 }, { 0.5f, 1.0f });
    t.reconcile(4, 2);
    EXPECT_FLOAT_EQ(t[0], 4.0f);
    EXPECT_FLOAT_EQ(t[1], 2.0f);
    EXPECT_FLOAT_EQ(0.5f * t[0] + t[1], 4.0f);
}

TEST(ReconcileSum, NothingChangesWhereTheRawTermsDoNotRebuildTheRawBeauty)
{
    Terms t({ 2, 4 }, { 1, 2 }, { 1, 3 });
    t.reconcile(10, 3.1f);  // 1 + 2 is 3, 3.3 % off
    EXPECT_FLOAT_EQ(t[0], 2.0f);
    EXPECT_FLOAT_EQ(t[1], 4.0f);
}

TEST(ReconcileSum, WithNoErrorTheTermsWithLightTakeTheDifference)
{
    // every error 0: shares by |colour x value|, 1 : 3 : 0
    Terms t({ 1, 3, 0 }, { 1, 3, 0 }, { 0, 0, 0 });
    t.reconcile(8, 4);
    EXPECT_FLOAT_EQ(t[0], 2.0f);
    EXPECT_FLOAT_EQ(t[1], 6.0f);
    EXPECT_FLOAT_EQ(t[2], 0.0f);
}

}  // namespace
