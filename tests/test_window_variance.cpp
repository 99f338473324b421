// test_window_variance.cpp: the noise estimate `denoise` and the light
// passes' back-off make without a variance guide (walkers/window_variance.h)
// against brute force: each 3x3 window's sample variance and mean square,
// clipped to the bounds; the smallest value among the 3x3 windows around a
// pixel; and the bias constant that turns the smallest window variance of
// white noise into the noise's variance, measured afresh.
#include "walkers/window_variance.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace {

using mcdenoise::Plane;
using OIIO::ROI;

/// Uniform values in [lo, hi) over `region`.
Plane<float> random_plane(const ROI& region, unsigned seed, float lo, float hi)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> dist(lo, hi);
    Plane<float> p(region);
    for (float& v : p.values)
        v = dist(rng);
    return p;
}

/// The 3x3 window around (x, y) clipped to `bounds`, as [x0, x1) x [y0, y1).
struct Window {
    int x0, x1, y0, y1;
};
Window window_at(int x, int y, const ROI& bounds)
{
    return { std::max(x - 1, bounds.xbegin), std::min(x + 2, bounds.xend),
             std::max(y - 1, bounds.ybegin), std::min(y + 2, bounds.yend) };
}

/// Brute force: the sample variance (n - 1) and the mean square of `in`
/// over the window around (x, y) clipped to `bounds`.
void window_figures(const Plane<float>& in, int x, int y, const ROI& bounds, double& variance,
                    double& mean_square)
{
    const Window w = window_at(x, y, bounds);
    double sum = 0.0, square = 0.0;
    int n = 0;
    for (int qy = w.y0; qy < w.y1; ++qy)
        for (int qx = w.x0; qx < w.x1; ++qx, ++n) {
            sum += in.at(qx, qy);
            square += double(in.at(qx, qy)) * in.at(qx, qy);
        }
    const double mean = sum / n;
    double deviation  = 0.0;
    for (int qy = w.y0; qy < w.y1; ++qy)
        for (int qx = w.x0; qx < w.x1; ++qx)
            deviation += (in.at(qx, qy) - mean) * (in.at(qx, qy) - mean);
    variance    = n > 1 ? deviation / (n - 1) : 0.0;
    mean_square = square / n;
}

/// Checks `window_variances` over `out` within `bounds`, reading a plane
/// over `in_region`.
void check_window_variances(const ROI& in_region, const ROI& out, const ROI& bounds, int nthreads)
{
    const Plane<float> in = random_plane(in_region, 7, -2.0f, 5.0f);
    Plane<float> variance(out), mean_square(out);
    mcdenoise::window_variances(in.values.data(), in_region, out, bounds, nthreads,
                                variance.values.data(), mean_square.values.data());
    for (int y = out.ybegin; y < out.yend; ++y)
        for (int x = out.xbegin; x < out.xend; ++x) {
            double v, m;
            window_figures(in, x, y, bounds, v, m);
            EXPECT_NEAR(variance.at(x, y), v, 1e-5 * (1.0 + v)) << x << "," << y;
            EXPECT_NEAR(mean_square.at(x, y), m, 1e-5 * (1.0 + m)) << x << "," << y;
        }
}

TEST(WindowVariance, EveryWindowAgainstBruteForceInsideTheBounds)
{
    // the output well inside the bounds: every window whole
    const ROI in(-3, 30, 5, 27), out(0, 25, 8, 22);
    check_window_variances(in, out, in, 1);
    check_window_variances(in, out, in, 3);
}

TEST(WindowVariance, WindowsClippedAtTheBoundsAgainstBruteForce)
{
    // the output on every edge of the bounds, and a one-pixel-wide strip
    const ROI bounds(-4, 13, -2, 9);
    check_window_variances(bounds, bounds, bounds, 2);
    check_window_variances(bounds, ROI(12, 13, -2, 9), bounds, 1);
    check_window_variances(bounds, ROI(-4, 13, 8, 9), bounds, 1);
    // a one-pixel image: n = 1, variance 0
    const ROI one(3, 4, 3, 4);
    check_window_variances(one, one, one, 1);
}

TEST(WindowVariance, SmallestInWindowsAgainstBruteForce)
{
    for (const ROI& region : { ROI(0, 17, 0, 11), ROI(-5, -4, 2, 9), ROI(4, 9, 6, 7) }) {
        const Plane<float> in = random_plane(region, 11, 0.0f, 1.0f);
        Plane<float> out(region);
        mcdenoise::smallest_in_windows(in.values.data(), region, 2, out.values.data());
        for (int y = region.ybegin; y < region.yend; ++y)
            for (int x = region.xbegin; x < region.xend; ++x) {
                const Window w = window_at(x, y, region);
                float least    = in.at(w.x0, w.y0);
                for (int qy = w.y0; qy < w.y1; ++qy)
                    for (int qx = w.x0; qx < w.x1; ++qx)
                        least = std::min(least, in.at(qx, qy));
                EXPECT_EQ(out.at(x, y), least) << x << "," << y;
            }
    }
}

TEST(WindowVariance, SmallestWindowBiasIsWhatWhiteNoiseGives)
{
    // The smallest 3x3 window variance among the 3x3 windows around a pixel
    // of Gaussian white noise averages smallest_window_bias times the
    // noise's variance: measured here over 4 x 90000 pixels (standard error
    // of the mean about 0.001) with a variance other than 1.
    const float sigma = 3.0f;
    const ROI region(0, 300, 0, 300);
    double total = 0.0;
    size_t count = 0;
    for (unsigned seed = 1; seed <= 4; ++seed) {
        std::mt19937 rng(seed);
        std::normal_distribution<float> noise(10.0f, sigma);
        Plane<float> in(region), variance(region), smallest(region);
        for (float& v : in.values)
            v = noise(rng);
        mcdenoise::window_variances(in.values.data(), region, region, region, 0,
                                    variance.values.data());
        mcdenoise::smallest_in_windows(variance.values.data(), region, 0, smallest.values.data());
        // away from the border, where clipped windows hold fewer pixels
        for (int y = 2; y < region.yend - 2; ++y)
            for (int x = 2; x < region.xend - 2; ++x, ++count)
                total += smallest.at(x, y);
    }
    const double bias = total / double(count) / double(sigma * sigma);
    EXPECT_NEAR(bias, mcdenoise::smallest_window_bias, 0.006);
}

}  // namespace
