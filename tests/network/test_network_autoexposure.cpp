// test_network_autoexposure.cpp: OIDN's autoexposure (network/
// autoexposure.h) against a brute-force reimplementation in double written
// plainly here, on random HDR images of sizes that are and are not
// multiples of 16, with RGB and RGBA pixels and padded rows; black,
// constant, NaN, negative and infinite pixels; bins at the threshold.
#include "network/autoexposure.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {

using namespace mcdenoise;

/// An RGB image with its pixels `channels` floats apart and `row_pad`
/// unused floats after each row.
struct Image {
    int width, height, channels, row_pad;
    std::vector<float> values;

    Image(int w, int h, int c = 3, int pad = 0)
        : width(w)
        , height(h)
        , channels(c)
        , row_pad(pad)
        , values(size_t(h) * size_t(w * c + pad), 0.f)
    {
    }
    std::ptrdiff_t row_stride() const { return width * channels + row_pad; }
    float* at(int x, int y) { return values.data() + y * row_stride() + x * channels; }
    const float* at(int x, int y) const { return values.data() + y * row_stride() + x * channels; }
    RgbIn view() const { return { values.data(), width, height, channels, row_stride() }; }
    void fill(float r, float g, float b)
    {
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                at(x, y)[0] = r;
                at(x, y)[1] = g;
                at(x, y)[2] = b;
            }
    }
};

/// Random HDR values: log-uniform over 1e-6 to 1e4, with one pixel in 8
/// black.
Image random_image(int w, int h, int c, int pad, unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> exponent(-6, 4);
    std::uniform_int_distribution<int> black(0, 7);
    Image im(w, h, c, pad);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int k = 0; k < c; ++k)
                im.at(x, y)[k] = black(rng) == 0 ? 0.f : float(std::pow(10.0, exponent(rng)));
    return im;
}

/// OIDN's autoexposure, plainly, in double.
double reference(const Image& im)
{
    const int bins_h = (im.height + 15) / 16;
    const int bins_w = (im.width + 15) / 16;
    double log_sum   = 0;
    int kept         = 0;
    for (int i = 0; i < bins_h; ++i) {
        for (int j = 0; j < bins_w; ++j) {
            const int y0 = i * im.height / bins_h, y1 = (i + 1) * im.height / bins_h;
            const int x0 = j * im.width / bins_w, x1 = (j + 1) * im.width / bins_w;
            double sum = 0;
            for (int y = y0; y < y1; ++y) {
                for (int x = x0; x < x1; ++x) {
                    double c[3];
                    for (int k = 0; k < 3; ++k) {
                        double v = im.at(x, y)[k];
                        if (std::isnan(v))
                            v = 0;
                        c[k] = std::min(std::max(v, 0.0), double(FLT_MAX));
                    }
                    sum += 0.212671 * c[0] + 0.715160 * c[1] + 0.072169 * c[2];
                }
            }
            const double mean = sum / double((y1 - y0) * (x1 - x0));
            if (mean > 1e-8) {
                log_sum += std::log2(mean);
                ++kept;
            }
        }
    }
    return kept > 0 ? 0.18 / std::exp2(log_sum / kept) : 1.0;
}

float computed(const Image& im)
{
    float scale = -1.f;
    EXPECT_TRUE(autoexposure(im.view(), scale));
    return scale;
}

void expect_matches_reference(const Image& im)
{
    const double expected = reference(im);
    EXPECT_NEAR(computed(im), expected, 1e-5 * expected)
        << im.width << "x" << im.height << ", " << im.channels << " channels";
}

TEST(NetworkAutoexposure, BinsAsOidnCountsThem)
{
    EXPECT_EQ(autoexposure_bins(1), 1);
    EXPECT_EQ(autoexposure_bins(16), 1);
    EXPECT_EQ(autoexposure_bins(17), 2);
    EXPECT_EQ(autoexposure_bins(33), 3);
    EXPECT_EQ(autoexposure_bins(2147483647), 134217728);
    // 17 pixels in 2 bins: 0-7 and 8-16; 33 in 3: 0-10, 11-21, 22-32.
    EXPECT_EQ(autoexposure_bin_begin(1, 17, 2), 8);
    EXPECT_EQ(autoexposure_bin_begin(1, 33, 3), 11);
    EXPECT_EQ(autoexposure_bin_begin(2, 33, 3), 22);
    EXPECT_EQ(autoexposure_bin_begin(3, 33, 3), 33);
}

TEST(NetworkAutoexposure, MatchesTheReferenceOnRandomImages)
{
    const int sizes[][2] = { { 1, 1 },  { 17, 33 },  { 16, 16 },   { 32, 48 }, { 15, 1 },
                             { 1, 40 }, { 100, 37 }, { 255, 256 }, { 64, 17 }, { 333, 129 } };
    unsigned seed        = 1;
    for (const auto& s : sizes) {
        expect_matches_reference(random_image(s[0], s[1], 3, 0, seed++));
        expect_matches_reference(random_image(s[0], s[1], 4, 5, seed++));
    }
}

TEST(NetworkAutoexposure, BlackImageGivesOne)
{
    Image im(40, 23);
    EXPECT_EQ(computed(im), 1.f);
    Image single(1, 1);
    EXPECT_EQ(computed(single), 1.f);
}

TEST(NetworkAutoexposure, ConstantImageGivesKeyOverLuminance)
{
    const float colours[][3] = {
        { 1.f, 1.f, 1.f }, { 0.5f, 2.f, 8.f }, { 1000.f, 0.f, 0.f }, { 1e-3f, 1e-3f, 1e-3f }
    };
    for (const auto& c : colours) {
        Image im(37, 21);
        im.fill(c[0], c[1], c[2]);
        const double l = 0.212671 * c[0] + 0.715160 * c[1] + 0.072169 * c[2];
        EXPECT_NEAR(computed(im), 0.18 / l, 1e-6 * 0.18 / l) << c[0] << " " << c[1] << " " << c[2];
    }
}

TEST(NetworkAutoexposure, NanAndNegativePixelsCountAsBlack)
{
    Image im        = random_image(70, 45, 3, 0, 99);
    Image zeroed    = im;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (int i = 0; i < 200; ++i) {
        const int x = (i * 37) % im.width, y = (i * 11) % im.height, k = i % 3;
        im.at(x, y)[k]     = i % 2 ? nan : -float(i + 1);
        zeroed.at(x, y)[k] = 0.f;
    }
    expect_matches_reference(im);
    EXPECT_EQ(computed(im), computed(zeroed));
    // An all-NaN or all-negative image has no bin kept.
    Image nans(20, 20);
    nans.fill(nan, nan, nan);
    EXPECT_EQ(computed(nans), 1.f);
    Image negative(20, 20);
    negative.fill(-1.f, -2.f, -3.f);
    EXPECT_EQ(computed(negative), 1.f);
}

TEST(NetworkAutoexposure, InfinityIsClampedToTheLargestFloat)
{
    Image im            = random_image(33, 17, 3, 0, 7);
    Image clamped       = im;
    im.at(3, 4)[1]      = std::numeric_limits<float>::infinity();
    clamped.at(3, 4)[1] = FLT_MAX;
    const float scale   = computed(im);
    EXPECT_EQ(scale, computed(clamped));
    EXPECT_TRUE(std::isfinite(scale));
    EXPECT_GT(scale, 0.f);
    expect_matches_reference(im);
}

TEST(NetworkAutoexposure, BinsAtOrBelowEpsAreLeftOut)
{
    // Two bins: the left one averaging 1e-9 (left out), the right one 2.
    Image im(32, 16);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 32; ++x)
            for (int k = 0; k < 3; ++k)
                im.at(x, y)[k] = x < 16 ? 1e-9f : 2.f;
    EXPECT_NEAR(computed(im), 0.09, 1e-7);
    // Just above eps, the left bin counts: 0.18 / sqrt(2e-8 * 2).
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x)
            for (int k = 0; k < 3; ++k)
                im.at(x, y)[k] = 2e-8f;
    EXPECT_NEAR(computed(im), 0.18 / std::sqrt(2e-8 * 2.0), 1e-5 * 0.18 / std::sqrt(4e-8));
}

TEST(NetworkAutoexposure, RefusesAnInvalidImage)
{
    const std::vector<float> values(12, 1.f);
    float scale = 5.f;
    EXPECT_FALSE(autoexposure(RgbIn {}, scale));
    EXPECT_FALSE(autoexposure(RgbIn { values.data(), 2, 2, 2, 6 }, scale));  // pixel stride 2
    EXPECT_FALSE(autoexposure(RgbIn { values.data(), 2, 2, 3, 5 }, scale));  // rows overlap
    EXPECT_FALSE(autoexposure(RgbIn { values.data(), 0, 2, 3, 6 }, scale));
    EXPECT_EQ(scale, 5.f);
    EXPECT_TRUE(autoexposure(RgbIn { values.data(), 2, 2, 3, 6 }, scale));
    EXPECT_NEAR(scale, 0.18f, 1e-6f);
}

}  // namespace
