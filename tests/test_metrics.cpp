// test_metrics.cpp: relMSE, MSE, PSNR and SSIM against values computed by
// hand on tiny images, non-finite pixels counted, errors reported, and the
// same numbers for any thread count.
#include <mcdenoise/mcdenoise.h>

#include "support/test_images.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace {

using OIIO::ImageBuf;
using OIIO::ImageSpec;
using OIIO::ROI;

ImageBuf make_image(int w, int h, int nch, const std::vector<float>& values, int x0 = 0,
                    int y0 = 0)
{
    ImageSpec spec(w, h, nch, OIIO::TypeDesc::FLOAT);
    spec.x = x0;
    spec.y = y0;
    ImageBuf img(spec);
    img.set_pixels(img.roi(), OIIO::TypeDesc::FLOAT, values.data());
    return img;
}

ImageBuf constant_image(int w, int h, int nch, float v)
{
    return make_image(w, h, nch, std::vector<float>(size_t(w * h * nch), v));
}

// Two RGB pixels. Squared errors: pixel 0 (0.1, 0, -0.2)^2, pixel 1 (0.1, 0, 0)^2.
const std::vector<float> two_ref = { 0.5f, 0.5f, 0.5f, 0.0f, 0.0f, 0.0f };
const std::vector<float> two_res = { 0.6f, 0.5f, 0.3f, 0.1f, 0.0f, 0.0f };

TEST(Metrics, MseRelMseAndPsnrByHand)
{
    const ImageBuf ref = make_image(2, 1, 3, two_ref);
    const ImageBuf res = make_image(2, 1, 3, two_res);
    const mcdenoise::ImageComparison c = mcdenoise::compare_images(res, ref);
    ASSERT_TRUE(c.ok) << c.error;
    // MSE = (0.01 + 0 + 0.04 + 0.01 + 0 + 0) / 6 = 0.01
    EXPECT_NEAR(c.mse, 0.01, 1e-8);
    // relMSE = (0.01/0.26 + 0.04/0.26 + 0.01/0.01) / 6
    EXPECT_NEAR(c.rel_mse, (0.05 / 0.26 + 1.0) / 6.0, 1e-7);
    // PSNR = 10 log10(1 / 0.01) = 20 dB
    EXPECT_NEAR(c.psnr, 20.0, 1e-5);
    EXPECT_EQ(c.pixels, 2);
    EXPECT_EQ(c.nonfinite, 0);
    EXPECT_NEAR(mcdenoise::mse(res, ref), c.mse, 0);
    EXPECT_NEAR(mcdenoise::rel_mse(res, ref), c.rel_mse, 0);
    EXPECT_NEAR(mcdenoise::psnr(res, ref), c.psnr, 0);
    EXPECT_NEAR(mcdenoise::ssim(res, ref), c.ssim, 0);
}

// HDR values: the reference holds an emitter at 40, the result misses it
// by 10 (MSE far above 1). PSNR is on values clamped to [0, 1]: only the
// 0.2 error of the other pixel counts, so it stays positive.
TEST(Metrics, PsnrOnHdrIsOnValuesClampedToThePeak)
{
    const ImageBuf ref = make_image(2, 1, 3, { 40.0f, 40.0f, 40.0f, 0.5f, 0.5f, 0.5f });
    const ImageBuf res = make_image(2, 1, 3, { 30.0f, 30.0f, 30.0f, 0.7f, 0.7f, 0.7f });
    const mcdenoise::ImageComparison c = mcdenoise::compare_images(res, ref);
    ASSERT_TRUE(c.ok) << c.error;
    EXPECT_GT(c.mse, 1.0);
    // clamped: (0 + 0 + 0 + 0.04 * 3) / 6 = 0.02 -> 10 log10(1 / 0.02)
    EXPECT_NEAR(c.psnr, 10.0 * std::log10(1.0 / 0.02), 1e-5);
    EXPECT_GT(c.psnr, 0.0);
}

TEST(Metrics, IdenticalImages)
{
    const ImageBuf a = testimg::random_image(23, 17, 3, 5);
    const mcdenoise::ImageComparison c = mcdenoise::compare_images(a, a);
    ASSERT_TRUE(c.ok) << c.error;
    EXPECT_EQ(c.mse, 0.0);
    EXPECT_EQ(c.rel_mse, 0.0);
    EXPECT_TRUE(std::isinf(c.psnr) && c.psnr > 0);
    EXPECT_NEAR(c.ssim, 1.0, 1e-12);
}

TEST(Metrics, SsimOfConstantImagesByHand)
{
    // No variance anywhere: SSIM = (2 mx my + C1) / (mx^2 + my^2 + C1) at every pixel.
    // Grey RGB has luminance equal to its value (the Rec.709 weights sum to 1).
    const ImageBuf res = constant_image(16, 16, 3, 0.5f);
    const ImageBuf ref = constant_image(16, 16, 3, 0.25f);
    const double c1 = 0.01 * 0.01;
    const double expected = (2 * 0.5 * 0.25 + c1) / (0.25 + 0.0625 + c1);
    EXPECT_NEAR(mcdenoise::ssim(res, ref), expected, 1e-12);
}

TEST(Metrics, SsimOfTwoPixelsByHand)
{
    // One channel, pixels x = (0, 1) against y = (0, 0.5). Each pixel's window
    // is clipped to the two pixels: weights 1 for itself and g = exp(-1/(2*1.5^2))
    // for the other, normalised.
    const ImageBuf res = make_image(2, 1, 1, { 0.0f, 1.0f });
    const ImageBuf ref = make_image(2, 1, 1, { 0.0f, 0.5f });
    const double g = std::exp(-1.0 / (2 * 1.5 * 1.5));
    const double c1 = 1e-4, c2 = 9e-4;
    // SSIM of a window with unnormalised weights a0 on pixel 0 and a1 on pixel 1
    auto ssim_at = [&](double a0, double a1) {
        const double w1 = a1 / (a0 + a1);  // pixel 0 holds zeros in both images
        const double mx = w1 * 1.0, my = w1 * 0.5;
        const double vx = w1 * 1.0 - mx * mx;
        const double vy = w1 * 0.25 - my * my;
        const double cxy = w1 * 0.5 - mx * my;
        return ((2 * mx * my + c1) * (2 * cxy + c2)) / ((mx * mx + my * my + c1) * (vx + vy + c2));
    };
    const double expected = 0.5 * (ssim_at(1.0, g) + ssim_at(g, 1.0));
    EXPECT_NEAR(mcdenoise::ssim(res, ref), expected, 1e-12);
}

TEST(Metrics, NonFinitePixelsAreCountedAndLeftOut)
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    // the two pixels of the hand test, plus a NaN in the result and an Inf in the reference
    std::vector<float> ref = two_ref, res = two_res;
    ref.insert(ref.end(), { 0.2f, inf, 0.2f, 0.3f, 0.3f, 0.3f });
    res.insert(res.end(), { 0.2f, 0.2f, 0.2f, 0.3f, nan, 0.3f });
    const mcdenoise::ImageComparison c = mcdenoise::compare_images(make_image(4, 1, 3, res),
                                                                   make_image(4, 1, 3, ref));
    ASSERT_TRUE(c.ok) << c.error;
    EXPECT_EQ(c.nonfinite, 2);
    EXPECT_EQ(c.pixels, 2);
    EXPECT_NEAR(c.mse, 0.01, 1e-8);
    EXPECT_NEAR(c.rel_mse, (0.05 / 0.26 + 1.0) / 6.0, 1e-7);
    EXPECT_TRUE(std::isfinite(c.ssim));
}

TEST(Metrics, AllNonFiniteGivesNaN)
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const mcdenoise::ImageComparison c = mcdenoise::compare_images(
        make_image(2, 1, 1, { nan, nan }), make_image(2, 1, 1, { 0.0f, 0.0f }));
    ASSERT_TRUE(c.ok);
    EXPECT_EQ(c.nonfinite, 2);
    EXPECT_TRUE(std::isnan(c.mse) && std::isnan(c.rel_mse) && std::isnan(c.ssim));
}

TEST(Metrics, DefaultRoiIsFirstThreeChannels)
{
    // the fourth channel differs wildly but is not compared by default
    const ImageBuf res = make_image(1, 1, 4, { 0.5f, 0.5f, 0.5f, 100.0f });
    const ImageBuf ref = make_image(1, 1, 4, { 0.5f, 0.5f, 0.5f, 0.0f });
    EXPECT_EQ(mcdenoise::mse(res, ref), 0.0);
    // an explicit ROI on channel 3 only: (100 - 0)^2
    EXPECT_NEAR(mcdenoise::mse(res, ref, ROI(0, 1, 0, 1, 0, 1, 3, 4)), 10000.0, 1e-9);
    // a single-channel image compares its one channel
    EXPECT_NEAR(mcdenoise::mse(make_image(1, 1, 1, { 0.5f }), make_image(1, 1, 1, { 0.25f })),
                0.0625, 1e-12);
}

TEST(Metrics, PixelsAreMatchedByCoordinates)
{
    // the reference's data window starts at x = -1; its pixel at x = 0 and 1 match
    const ImageBuf ref = make_image(4, 1, 3,
                                    { 9.f, 9.f, 9.f, 0.5f, 0.5f, 0.5f, 0.f, 0.f, 0.f, 9.f, 9.f, 9.f },
                                    -1, 0);
    const ImageBuf res = make_image(2, 1, 3, two_res);
    const mcdenoise::ImageComparison c = mcdenoise::compare_images(res, ref);
    ASSERT_TRUE(c.ok) << c.error;
    EXPECT_NEAR(c.mse, 0.01, 1e-8);
    // a ROI inside both: only pixel 1
    EXPECT_NEAR(mcdenoise::mse(res, ref, ROI(1, 2, 0, 1)), 0.01 / 3, 1e-8);
}

void expect_error(const ImageBuf& res, const ImageBuf& ref, ROI roi, const std::string& words)
{
    const mcdenoise::ImageComparison c = mcdenoise::compare_images(res, ref, roi);
    EXPECT_FALSE(c.ok);
    EXPECT_NE(c.error.find("compare_images"), std::string::npos) << c.error;
    EXPECT_NE(c.error.find(words), std::string::npos) << c.error;
    EXPECT_TRUE(std::isnan(mcdenoise::rel_mse(res, ref, roi)));
}

TEST(Metrics, ErrorsAreReported)
{
    const ImageBuf a = testimg::random_image(8, 8, 3, 1);
    expect_error(ImageBuf(), a, {}, "result image is empty");
    expect_error(a, ImageBuf(), {}, "reference image is empty");
    expect_error(a, testimg::random_image(8, 6, 3, 2), {}, "does not cover");
    expect_error(a, testimg::random_image(6, 8, 3, 2), {}, "does not cover");
    expect_error(a, a, ROI(4, 12, 0, 8), "result image's data window");
    expect_error(a, testimg::random_image(8, 8, 1, 2), {}, "channels");
    expect_error(a, a, ROI(2, 2, 0, 8), "empty");
    expect_error(ImageBuf("/nonexistent/never.exr"), a, {}, "empty");
}

TEST(Metrics, SameNumbersForAnyThreadCount)
{
    ImageBuf res = testimg::random_image(301, 257, 3, 11);
    const ImageBuf ref = testimg::random_image(301, 257, 3, 12);
    testimg::sprinkle_nonfinite(res, 0.01, 3);
    const mcdenoise::ImageComparison one = mcdenoise::compare_images(res, ref, {}, 1);
    ASSERT_TRUE(one.ok) << one.error;
    EXPECT_GT(one.nonfinite, 0);
    for (int threads : { 0, 2, 7 }) {
        const mcdenoise::ImageComparison c = mcdenoise::compare_images(res, ref, {}, threads);
        EXPECT_EQ(c.mse, one.mse);
        EXPECT_EQ(c.rel_mse, one.rel_mse);
        EXPECT_EQ(c.ssim, one.ssim);
        EXPECT_EQ(c.nonfinite, one.nonfinite);
    }
}

TEST(Metrics, HalfImagesAreReadAsFloat)
{
    const ImageBuf ref = testimg::random_image(9, 9, 3, 21);
    ImageBuf half_copy = testimg::random_image(9, 9, 3, 21, 0.0f, 1.0f, OIIO::TypeDesc::HALF);
    const double e = mcdenoise::mse(half_copy, ref);
    EXPECT_GT(e, 0.0);    // rounding to half is an error
    EXPECT_LT(e, 1e-6);   // but a tiny one
}

}  // namespace
