// layer_backoff.cpp: a light layer's back-off towards its own values
// where the beauty's weights blurred it, and the error that leaves. The
// window figures are planes over the average's region, one channel at a
// time through the same scratch planes.
#include "layer_backoff.h"

#include "window_variance.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;

namespace {

/// `v`, or 0 where not finite.
float finite_or_zero(float v) { return std::isfinite(v) ? v : 0.0f; }

/// Planes reused for every channel of one layer.
struct Scratch {
    Plane<float> values, variance, mean_square, smallest;
    explicit Scratch(const ROI& region)
        : values(region), variance(region), mean_square(region), smallest(region)
    {
    }
};

/// Add to `noise` (and to `mean_square` when given) the figures of the
/// plane in `scratch.values`: the smallest 3x3 window variance among the
/// 3x3 windows around each pixel over `smallest_window_bias`, and the 3x3
/// mean of the values squared.
void add_window_figures(Scratch& scratch, int nthreads, Plane<float>& noise,
                        Plane<float>* mean_square)
{
    const ROI& region = scratch.values.region;
    window_variances(scratch.values.values.data(), region, region, region, nthreads,
                     scratch.variance.values.data(),
                     mean_square ? scratch.mean_square.values.data() : nullptr);
    smallest_in_windows(scratch.variance.values.data(), region, nthreads,
                        scratch.smallest.values.data());
    for_each_pixel(region, nthreads, [&](int, int, size_t i) {
        noise.values[i] += scratch.smallest.values[i] / smallest_window_bias;
        if (mean_square)
            mean_square->values[i] += scratch.mean_square.values[i];
    });
}

/// The median over `roi` of noise / |average|^2 where |average|^2 is above
/// 0 (0 where it is 0 everywhere): the layer's typical relative noise.
float median_relative_noise(const Plane<float>& noise, const PixelBlock& average, const ROI& roi);

/// An average beside the values it averaged (times the split's scale):
/// per pixel of the average's region, summed over channels, the figures
/// `back_off_layer` documents.
struct AverageFit {
    Plane<float> noise;        ///< s2 from the windows alone
    Plane<float> residual;     ///< the same estimate of the average's own values
    Plane<float> mean_square;  ///< m2
    float most_relative_noise = 0.0f;

    AverageFit(const PixelBlock& average, const PixelBlock& layer, const Plane<float>& scale,
               const ROI& roi, int nthreads)
        : noise(average.region, 0.0f)
        , residual(average.region, 0.0f)
        , mean_square(average.region, 0.0f)
    {
        Scratch scratch(average.region);
        for (int c = 0; c < average.nchannels; ++c) {
            for_each_pixel(average.region, nthreads, [&](int x, int y, size_t i) {
                scratch.values.values[i] = finite_or_zero(average.pixel(x, y)[c]
                                                          - layer.pixel(x, y)[c] * scale.at(x, y));
            });
            add_window_figures(scratch, nthreads, noise, &mean_square);
            for_each_pixel(average.region, nthreads, [&](int x, int y, size_t i) {
                scratch.values.values[i] = finite_or_zero(average.pixel(x, y)[c]);
            });
            add_window_figures(scratch, nthreads, residual, nullptr);
        }
        most_relative_noise = relative_noise_spread * median_relative_noise(noise, average, roi);
    }
};

/// |average|^2 at (x, y), summed over channels (non-finite values as 0).
float level(const PixelBlock& average, int x, int y)
{
    const float* a = average.pixel(x, y);
    float sum      = 0.0f;
    for (int c = 0; c < average.nchannels; ++c)
        sum += finite_or_zero(a[c]) * finite_or_zero(a[c]);
    return sum;
}

float median_relative_noise(const Plane<float>& noise, const PixelBlock& average, const ROI& roi)
{
    std::vector<float> ratios;
    ratios.reserve(plane_size(roi));
    for (int y = roi.ybegin; y < roi.yend; ++y)
        for (int x = roi.xbegin; x < roi.xend; ++x) {
            const float l = level(average, x, y);
            if (l > 0.0f)
                ratios.push_back(noise.at(x, y) / l);
        }
    if (ratios.empty())
        return 0.0f;
    const auto middle = ratios.begin() + std::ptrdiff_t(ratios.size() / 2);
    std::nth_element(ratios.begin(), middle, ratios.end());
    return *middle;
}

}  // namespace

void back_off_layer(ImageBuf& result, const PixelBlock& average, const PixelBlock& layer,
                    const Plane<float>& scale, int nthreads, Plane<float>& error)
{
    const ROI roi = result.roi();
    const AverageFit fit(average, layer, scale, roi, nthreads);
    const int nc = average.nchannels;
    error        = Plane<float>(roi);
    parallel_rows(roi, nthreads, [&](int y) {
        float* out = static_cast<float*>(result.pixeladdr(roi.xbegin, y));
        size_t i   = pixel_offset(roi, roi.xbegin, y);
        for (int x = roi.xbegin; x < roi.xend; ++x, ++i, out += nc) {
            const float s2 = std::min(fit.noise.at(x, y),
                                      fit.most_relative_noise * level(average, x, y));
            const float t2    = std::min(fit.residual.at(x, y), s2);
            const float m2    = fit.mean_square.at(x, y);
            const float bias2 = std::max(0.0f, m2 - s2);
            const float a     = m2 > 0.0f ? std::clamp(1.0f - s2 / m2, 0.0f, 1.0f) : 0.0f;
            const float* avg  = average.pixel(x, y);
            const float* kept = layer.pixel(x, y);
            const float s     = scale.at(x, y);
            for (int c = 0; c < nc; ++c)
                out[c] -= a * finite_or_zero(avg[c] - kept[c] * s);
            error.values[i] = a * a * s2 + (1.0f - a) * (1.0f - a) * (bias2 + t2);
        }
    });
}

}  // namespace mcdenoise
