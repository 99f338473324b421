// test_layer_backoff.cpp: a light layer's back-off towards its own values
// (passes/layer_backoff.h) against a brute-force reading of its rule, in
// double, window by window: m2, s2 (the smallest window variance over the
// bias constant, capped by the median relative noise), t2, the blend a, the
// result and its error variance. Also two hand-worked cases: an average
// equal to the kept values is left as it is, and a constant shift with no
// noise is taken back whole.
#include "passes/layer_backoff.h"
#include "walkers/window_variance.h"

#include <OpenImageIO/imagebuf.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace {

using mcdenoise::PixelBlock;
using mcdenoise::Plane;
using OIIO::ImageBuf;
using OIIO::ROI;

/// A block of `nc` channels over `region` holding `values(x, y, c)`.
template<class Values>
PixelBlock block_of(const ROI& region, int nc, Values&& values)
{
    PixelBlock b;
    b.region         = region;
    b.region.chbegin = 0;
    b.region.chend   = nc;
    b.nchannels      = nc;
    b.row_stride     = std::ptrdiff_t(region.width()) * nc;
    b.owned.resize(size_t(region.width()) * size_t(region.height()) * size_t(nc));
    for (int y = region.ybegin; y < region.yend; ++y)
        for (int x = region.xbegin; x < region.xend; ++x)
            for (int c = 0; c < nc; ++c)
                b.owned[size_t((y - region.ybegin) * region.width() + (x - region.xbegin)) * nc
                        + c] = values(x, y, c);
    b.data = b.owned.data();
    return b;
}

/// The brute-force figures and result of one pixel.
struct Expected {
    std::vector<double> out;
    double error;
};

/// The back-off's rule (layer_backoff.h), computed directly. `g` is the
/// region of the blocks (the ROI grown by backoff_reach, clipped).
class BruteForce {
public:
    BruteForce(const PixelBlock& average, const PixelBlock& layer, const Plane<float>& scale,
               const ROI& roi)
        : m_average(average)
        , m_layer(layer)
        , m_scale(scale)
        , m_g(average.region)
        , m_roi(roi)
    {
        // the cap: relative_noise_spread times the median over every
        // median_stride-th pixel of noise / level where the level is > 0
        std::vector<double> ratios;
        for (int y = roi.ybegin; y < roi.yend; ++y)
            for (int x = roi.xbegin; x < roi.xend; ++x)
                if (y % mcdenoise::median_stride == 0 && x % mcdenoise::median_stride == 0
                    && level(x, y) > 0.0)
                    ratios.push_back(noise(x, y, false) / level(x, y));
        std::sort(ratios.begin(), ratios.end());
        m_cap = ratios.empty() ? 0.0 : mcdenoise::relative_noise_spread * ratios[ratios.size() / 2];
    }

    Expected at(int x, int y) const
    {
        const double s2    = std::min(noise(x, y, false), m_cap * level(x, y));
        const double t2    = std::min(noise(x, y, true), s2);
        const double m2    = mean_square(x, y);
        const double a     = m2 > 0.0 ? std::clamp(1.0 - s2 / m2, 0.0, 1.0) : 0.0;
        const double bias2 = std::max(0.0, m2 - s2);
        Expected e;
        for (int c = 0; c < m_average.nchannels; ++c)
            e.out.push_back(m_average.pixel(x, y)[c] - a * diff(x, y, c));
        e.error = a * a * s2 + (1.0 - a) * (1.0 - a) * (bias2 + t2);
        return e;
    }

private:
    /// e = average - kept x scale, channel c.
    double diff(int x, int y, int c) const
    {
        return double(m_average.pixel(x, y)[c]) - double(m_layer.pixel(x, y)[c]) * m_scale.at(x, y);
    }
    double value(int x, int y, int c, bool of_average) const
    {
        return of_average ? double(m_average.pixel(x, y)[c]) : diff(x, y, c);
    }
    /// The 3x3 window around (x, y) clipped to g, as [x0, x1) x [y0, y1).
    void window(int x, int y, int& x0, int& x1, int& y0, int& y1) const
    {
        x0 = std::max(x - 1, m_g.xbegin), x1 = std::min(x + 2, m_g.xend);
        y0 = std::max(y - 1, m_g.ybegin), y1 = std::min(y + 2, m_g.yend);
    }
    double window_variance(int x, int y, int c, bool of_average) const
    {
        int x0, x1, y0, y1;
        window(x, y, x0, x1, y0, y1);
        double sum = 0.0;
        int n      = 0;
        for (int qy = y0; qy < y1; ++qy)
            for (int qx = x0; qx < x1; ++qx, ++n)
                sum += value(qx, qy, c, of_average);
        double deviation = 0.0;
        for (int qy = y0; qy < y1; ++qy)
            for (int qx = x0; qx < x1; ++qx)
                deviation += std::pow(value(qx, qy, c, of_average) - sum / n, 2);
        return n > 1 ? deviation / (n - 1) : 0.0;
    }
    /// Per channel the smallest window variance among the windows around
    /// (x, y), summed, over the bias constant: s2 (of e) or t2's estimate
    /// (of the average).
    double noise(int x, int y, bool of_average) const
    {
        int x0, x1, y0, y1;
        window(x, y, x0, x1, y0, y1);
        double total = 0.0;
        for (int c = 0; c < m_average.nchannels; ++c) {
            double least = INFINITY;
            for (int qy = y0; qy < y1; ++qy)
                for (int qx = x0; qx < x1; ++qx)
                    least = std::min(least, window_variance(qx, qy, c, of_average));
            total += least / double(mcdenoise::smallest_window_bias);
        }
        return total;
    }
    double mean_square(int x, int y) const
    {
        int x0, x1, y0, y1;
        window(x, y, x0, x1, y0, y1);
        double total = 0.0;
        for (int c = 0; c < m_average.nchannels; ++c) {
            double square = 0.0;
            for (int qy = y0; qy < y1; ++qy)
                for (int qx = x0; qx < x1; ++qx)
                    square += std::pow(diff(qx, qy, c), 2);
            total += square / ((x1 - x0) * (y1 - y0));
        }
        return total;
    }
    double level(int x, int y) const
    {
        double total = 0.0;
        for (int c = 0; c < m_average.nchannels; ++c)
            total += std::pow(double(m_average.pixel(x, y)[c]), 2);
        return total;
    }

    const PixelBlock& m_average;
    const PixelBlock& m_layer;
    const Plane<float>& m_scale;
    ROI m_g, m_roi;
    double m_cap = 0.0;
};

/// A float image over `roi` holding the average's pixels there.
ImageBuf result_over(const ROI& roi, const PixelBlock& average)
{
    ImageBuf result(
        OIIO::ImageSpec(roi.width(), roi.height(), average.nchannels, OIIO::TypeDesc::FLOAT));
    result.set_origin(roi.xbegin, roi.ybegin);
    for (int y = roi.ybegin; y < roi.yend; ++y)
        for (int x = roi.xbegin; x < roi.xend; ++x)
            result.setpixel(x, y, average.pixel(x, y), average.nchannels);
    return result;
}

/// Runs the back-off over `roi` of a data window `data`, a layer of `nc`
/// channels: a noisy ramp with an edge, its average a blur of it that
/// misses the edge and has a dark column, and an outlier split's scale
/// below 1 in places.
void check_against_brute_force(const ROI& data, const ROI& roi, int nc, int nthreads)
{
    ROI g    = roi;
    g.xbegin = std::max(data.xbegin, roi.xbegin - mcdenoise::backoff_reach);
    g.xend   = std::min(data.xend, roi.xend + mcdenoise::backoff_reach);
    g.ybegin = std::max(data.ybegin, roi.ybegin - mcdenoise::backoff_reach);
    g.yend   = std::min(data.yend, roi.yend + mcdenoise::backoff_reach);
    std::mt19937 rng(5);
    std::normal_distribution<float> noise(0.0f, 0.2f);
    std::vector<float> layer_values, average_values;
    const auto edge = [&](int x, int c) {
        return (x > (data.xbegin + data.xend) / 2 ? 2.0f : 0.5f) + 0.1f * c;
    };
    const PixelBlock layer =
        block_of(g, nc, [&](int x, int, int c) { return edge(x, c) + noise(rng); });
    // a dark column in the average: every window around it crosses it, so
    // its noise is capped by the median relative noise
    const int dark           = (roi.xbegin + roi.xend) / 2;
    const PixelBlock average = block_of(g, nc, [&](int x, int, int c) {
        const float v = 0.5f * (edge(x - 2, c) + edge(x + 2, c)) + 0.3f * noise(rng);
        return x == dark ? 0.05f : v;
    });
    Plane<float> scale(g, 1.0f);
    for (int y = g.ybegin; y < g.yend; y += 5)
        scale.values[scale.offset(g.xbegin + (y - g.ybegin) % g.width(), y)] = 0.25f;

    ImageBuf result = result_over(roi, average);
    mcdenoise::BackoffPlanes planes;
    Plane<float> error;
    mcdenoise::back_off_layer(result, average, layer, scale, nthreads, planes, error);
    ASSERT_EQ(error.region.xbegin, roi.xbegin);
    ASSERT_EQ(error.region.yend, roi.yend);
    ASSERT_EQ(error.values.size(), size_t(roi.width()) * size_t(roi.height()));

    const BruteForce brute(average, layer, scale, roi);
    for (int y = roi.ybegin; y < roi.yend; ++y)
        for (int x = roi.xbegin; x < roi.xend; ++x) {
            const Expected e = brute.at(x, y);
            for (int c = 0; c < nc; ++c)
                EXPECT_NEAR(result.getchannel(x, y, 0, c), e.out[size_t(c)],
                            2e-5 * (1.0 + std::fabs(e.out[size_t(c)])))
                    << x << "," << y << " channel " << c;
            EXPECT_NEAR(error.at(x, y), e.error, 2e-5 * (1.0 + e.error)) << x << "," << y;
        }
}

TEST(LayerBackoff, AgainstBruteForceInsideTheDataWindow)
{
    check_against_brute_force(ROI(-6, 34, 3, 31), ROI(2, 26, 8, 25), 3, 1);
}

TEST(LayerBackoff, AgainstBruteForceAtTheDataWindowsEdges)
{
    // the ROI on the data window's edges (the windows clipped), two
    // channels, split across threads
    check_against_brute_force(ROI(0, 23, 0, 17), ROI(0, 23, 0, 17), 2, 3);
    check_against_brute_force(ROI(0, 23, 0, 17), ROI(21, 23, 1, 16), 1, 1);
}

/// The region the hand-worked cases' blocks cover, and their ROI.
const ROI small_g(0, 12, 0, 10), small_roi(2, 10, 2, 8);

/// The back-off over `small_roi` of `average` towards `layer` (3 channels
/// over `small_g`, scale 1): the result, and the error into `error`.
ImageBuf backed_off(const PixelBlock& average, const PixelBlock& layer, Plane<float>& error)
{
    ImageBuf result = result_over(small_roi, average);
    mcdenoise::BackoffPlanes planes;
    mcdenoise::back_off_layer(result, average, layer, Plane<float>(small_g, 1.0f), 1, planes,
                              error);
    return result;
}

TEST(LayerBackoff, AnAverageEqualToTheLayerIsKept)
{
    // e = 0 everywhere: m2 = 0, so a = 0 and the average stays
    const auto values = [](int x, int y, int c) { return 0.1f * float(x * 7 % 5 + y + c); };
    Plane<float> error;
    const ImageBuf result =
        backed_off(block_of(small_g, 3, values), block_of(small_g, 3, values), error);
    for (int y = small_roi.ybegin; y < small_roi.yend; ++y)
        for (int x = small_roi.xbegin; x < small_roi.xend; ++x)
            for (int c = 0; c < 3; ++c)
                EXPECT_EQ(result.getchannel(x, y, 0, c), values(x, y, c));
}

TEST(LayerBackoff, ABiasWithoutNoiseIsTakenBackWhole)
{
    // e = 0.5 everywhere, with no spread: s2 = 0 and m2 = 0.25 x 3, so
    // a = 1, the result is the layer's own values and the error 0
    const auto values = [](int x, int y, int c) { return 1.0f + 0.1f * float(x + 2 * y + c); };
    const PixelBlock average =
        block_of(small_g, 3, [&](int x, int y, int c) { return values(x, y, c) + 0.5f; });
    Plane<float> error;
    const ImageBuf result = backed_off(average, block_of(small_g, 3, values), error);
    for (int y = small_roi.ybegin; y < small_roi.yend; ++y)
        for (int x = small_roi.xbegin; x < small_roi.xend; ++x) {
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(result.getchannel(x, y, 0, c), values(x, y, c), 1e-5);
            EXPECT_NEAR(error.at(x, y), 0.0f, 1e-6);
        }
}

}  // namespace
