// layer_backoff.cpp: a light layer's back-off towards its own values
// where the beauty's weights blurred it, and the error that leaves.
#include "layer_backoff.h"

#include "window_variance.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;

namespace {

/// The difference e = average - kept, per channel, over the average's
/// region; 0 where not finite.
Planes<float> differences(const PixelBlock& average, const PixelBlock& layer,
                          const Plane<float>& scale, int nthreads)
{
    const ROI& grown = average.region;
    Planes<float> diff(grown, average.nchannels);
    for_each_pixel(grown, nthreads, [&](int x, int y, size_t i) {
        const float* a = average.pixel(x, y);
        const float* r = layer.pixel(x, y);
        const float s  = scale.at(x, y);
        for (int c = 0; c < average.nchannels; ++c) {
            const float e             = a[c] - r[c] * s;
            diff.values[size_t(c)][i] = std::isfinite(e) ? e : 0.0f;
        }
    });
    return diff;
}

/// The average's channels as planes over its region; 0 where not finite.
Planes<float> planes_of(const PixelBlock& average, int nthreads)
{
    Planes<float> out(average.region, average.nchannels);
    for_each_pixel(average.region, nthreads, [&](int x, int y, size_t i) {
        const float* a = average.pixel(x, y);
        for (int c = 0; c < average.nchannels; ++c)
            out.values[size_t(c)][i] = std::isfinite(a[c]) ? a[c] : 0.0f;
    });
    return out;
}

/// Per channel of `planes`, the sample variance of each 3x3 window.
Planes<float> window_variances(const Planes<float>& planes, int nthreads)
{
    Planes<float> out(planes.region, planes.nchannels());
    for (int c = 0; c < planes.nchannels(); ++c)
        estimate_variance([&](int x, int y) { return *planes.from(c, x, y); }, planes.region,
                          planes.region, nthreads, out.values[size_t(c)].data());
    return out;
}

/// The noise of (x, y) from the window variances: per channel the smallest
/// among the 3x3 windows around it, summed, corrected for the minimum's bias.
float noise_at(const Planes<float>& variances, int x, int y)
{
    float sum = 0.0f;
    for (int c = 0; c < variances.nchannels(); ++c)
        sum += smallest_in_window(variances.values[size_t(c)].data(), variances.region, x, y);
    return sum / smallest_window_bias;
}

/// The 3x3 mean of |e|^2 (summed over channels) around (x, y), the window
/// clipped to the differences' region.
float mean_square_at(const Planes<float>& diff, int x, int y)
{
    const ROI& grown = diff.region;
    const Span xs    = clip_window(x, 1, grown.xbegin, grown.xend);
    const Span ys    = clip_window(y, 1, grown.ybegin, grown.yend);
    double sum       = 0.0;
    for (int c = 0; c < diff.nchannels(); ++c)
        for (int qy = ys.begin; qy < ys.end; ++qy) {
            const float* row = diff.from(c, xs.begin, qy);
            for (int i = 0; i < xs.size(); ++i)
                sum += double(row[i]) * double(row[i]);
        }
    return float(sum / (xs.size() * ys.size()));
}

/// The noise left in an average, per pixel of `roi`: the smallest-window
/// estimate of its own channels (`noise_at`).
Plane<float> residual_noise(const PixelBlock& average, const ROI& roi, int nthreads)
{
    const Planes<float> variances = window_variances(planes_of(average, nthreads), nthreads);
    Plane<float> out(roi);
    for_each_pixel(roi, nthreads,
                   [&](int x, int y, size_t i) { out.values[i] = noise_at(variances, x, y); });
    return out;
}

/// One pixel's figures of an average beside the values it averaged.
struct Figures {
    float s2;  ///< the kept values' noise
    float t2;  ///< the noise left in the average, at most s2
    float m2;  ///< the 3x3 mean of |average - kept|^2: bias^2 + s2
    /// The average's squared bias, m2 - s2 (0 when below).
    float bias2() const { return std::max(0.0f, m2 - s2); }
};

/// Per pixel of `roi`, the squared level of the average, summed over
/// channels (0 where not finite).
Plane<float> levels(const PixelBlock& average, const ROI& roi, int nthreads)
{
    Plane<float> out(roi);
    for_each_pixel(roi, nthreads, [&](int x, int y, size_t i) {
        const float* a = average.pixel(x, y);
        float sum      = 0.0f;
        for (int c = 0; c < average.nchannels; ++c)
            sum += std::isfinite(a[c]) ? a[c] * a[c] : 0.0f;
        out.values[i] = sum;
    });
    return out;
}

/// The median over `roi` of noise / level where the level is above 0
/// (0 where it is 0 everywhere): the layer's typical relative noise.
float median_relative_noise(const Plane<float>& noise, const Plane<float>& level)
{
    std::vector<float> ratios;
    ratios.reserve(level.values.size());
    for (size_t i = 0; i < level.values.size(); ++i)
        if (level.values[i] > 0.0f)
            ratios.push_back(noise.values[i] / level.values[i]);
    if (ratios.empty())
        return 0.0f;
    const auto middle = ratios.begin() + std::ptrdiff_t(ratios.size() / 2);
    std::nth_element(ratios.begin(), middle, ratios.end());
    return *middle;
}

/// An average beside the values it averaged (times the split's scale),
/// ready for `Figures` per pixel of `roi`.
struct AverageFit {
    Planes<float> diff;
    Plane<float> window_noise;
    Plane<float> level;
    Plane<float> residual;
    float most_relative_noise;

    AverageFit(const PixelBlock& average, const PixelBlock& layer, const Plane<float>& scale,
               const ROI& roi, int nthreads)
        : diff(differences(average, layer, scale, nthreads))
        , window_noise(roi)
        , level(levels(average, roi, nthreads))
        , residual(residual_noise(average, roi, nthreads))
    {
        const Planes<float> diff_var = window_variances(diff, nthreads);
        for_each_pixel(roi, nthreads, [&](int x, int y, size_t i) {
            window_noise.values[i] = noise_at(diff_var, x, y);
        });
        most_relative_noise = relative_noise_spread
                              * median_relative_noise(window_noise, level);
    }

    Figures at(int x, int y, size_t i) const
    {
        const float s2 = std::min(window_noise.values[i], most_relative_noise * level.values[i]);
        return { s2, std::min(residual.values[i], s2), mean_square_at(diff, x, y) };
    }
};

}  // namespace

void back_off_layer(ImageBuf& result, const PixelBlock& average, const PixelBlock& layer,
                    const Plane<float>& scale, int nthreads, Plane<float>& error)
{
    const ROI roi = result.roi();
    const AverageFit fit(average, layer, scale, roi, nthreads);
    const int nc = average.nchannels;
    error        = Plane<float>(roi);
    for_each_pixel(roi, nthreads, [&](int x, int y, size_t i) {
        const Figures f = fit.at(x, y, i);
        const float a   = f.m2 > 0.0f ? std::clamp(1.0f - f.s2 / f.m2, 0.0f, 1.0f) : 0.0f;
        float* out      = static_cast<float*>(result.pixeladdr(x, y));
        for (int c = 0; c < nc; ++c)
            out[c] -= a * *fit.diff.from(c, x, y);
        error.values[i] = a * a * f.s2 + (1.0f - a) * (1.0f - a) * (f.bias2() + f.t2);
    });
}

}  // namespace mcdenoise
