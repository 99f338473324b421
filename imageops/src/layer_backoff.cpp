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

/// `planes` over `region`: allocated only when their region differs.
void cover(BackoffPlanes& planes, const ROI& region)
{
    if (planes.noise.region == region && !planes.noise.values.empty())
        return;
    for (Plane<float>* p : { &planes.noise, &planes.residual, &planes.mean_square, &planes.level,
                             &planes.diff, &planes.values, &planes.variance,
                             &planes.window_mean_square, &planes.smallest })
        *p = Plane<float>(region);
}

/// Channel `c` of the average (0 where not finite) into `planes.values`
/// and of e = average - layer x scale into `planes.diff`, over the
/// average's region; its square into `planes.level` (added unless `first`).
void load_channel(const PixelBlock& average, const PixelBlock& layer, const Plane<float>& scale,
                  int c, bool first, int nthreads, BackoffPlanes& planes)
{
    const ROI& region = average.region;
    parallel_rows(region, nthreads, [&](int y) {
        const float* a = average.row(y) + c;
        const float* r = layer.pixel(region.xbegin, y) + c;
        const float* s = scale.from(region.xbegin, y);
        const size_t i = pixel_offset(region, region.xbegin, y);
        float* values  = planes.values.values.data() + i;
        float* diff    = planes.diff.values.data() + i;
        float* level   = planes.level.values.data() + i;
        for (int k = 0; k < region.width(); ++k) {
            const float v = a[k * average.nchannels];
            values[k]     = finite_or_zero(v);
            diff[k]       = finite_or_zero(v - r[k * layer.nchannels] * s[k]);
            level[k]      = (first ? 0.0f : level[k]) + values[k] * values[k];
        }
    });
}

/// Into `noise` (and `mean_square` when given), added unless `first`, the
/// figures of `values` (one of `planes`' channel planes): the smallest 3x3
/// window variance among the 3x3 windows around each pixel over
/// `smallest_window_bias`, and the 3x3 mean of the values squared.
void add_window_figures(const Plane<float>& values, bool first, int nthreads,
                        BackoffPlanes& planes, Plane<float>& noise, Plane<float>* mean_square)
{
    const ROI& region = values.region;
    window_variances(values.values.data(), region, region, region, nthreads,
                     planes.variance.values.data(),
                     mean_square ? planes.window_mean_square.values.data() : nullptr);
    smallest_in_windows(planes.variance.values.data(), region, nthreads,
                        planes.smallest.values.data());
    for_each_pixel(region, nthreads, [&](int, int, size_t i) {
        const float n   = planes.smallest.values[i] / smallest_window_bias;
        noise.values[i] = first ? n : noise.values[i] + n;
        if (mean_square)
            mean_square->values[i] = (first ? 0.0f : mean_square->values[i])
                                     + planes.window_mean_square.values[i];
    });
}

/// The median over every `median_stride`-th pixel of `roi` in x and y (of
/// the data window's grid) of noise / level where the level is above 0 (0
/// where it is 0 everywhere): the layer's typical relative noise.
float median_relative_noise(const Plane<float>& noise, const Plane<float>& level, const ROI& roi)
{
    std::vector<float> ratios;
    for (int y = roi.ybegin; y < roi.yend; ++y) {
        if (y % median_stride != 0)
            continue;
        for (int x = roi.xbegin; x < roi.xend; ++x)
            if (x % median_stride == 0 && level.at(x, y) > 0.0f)
                ratios.push_back(noise.at(x, y) / level.at(x, y));
    }
    if (ratios.empty())
        return 0.0f;
    const auto middle = ratios.begin() + std::ptrdiff_t(ratios.size() / 2);
    std::nth_element(ratios.begin(), middle, ratios.end());
    return *middle;
}

/// The figures of an average beside the values it averaged (times the
/// split's scale) into `planes` (noise, residual, mean_square, level);
/// returns `relative_noise_spread` times the median relative noise.
float fit_average(const PixelBlock& average, const PixelBlock& layer, const Plane<float>& scale,
                  const ROI& roi, int nthreads, BackoffPlanes& planes)
{
    cover(planes, average.region);
    for (int c = 0; c < average.nchannels; ++c) {
        const bool first = c == 0;
        load_channel(average, layer, scale, c, first, nthreads, planes);
        add_window_figures(planes.diff, first, nthreads, planes, planes.noise, &planes.mean_square);
        add_window_figures(planes.values, first, nthreads, planes, planes.residual, nullptr);
    }
    return relative_noise_spread * median_relative_noise(planes.noise, planes.level, roi);
}

}  // namespace

void back_off_layer(ImageBuf& result, const PixelBlock& average, const PixelBlock& layer,
                    const Plane<float>& scale, int nthreads, BackoffPlanes& planes,
                    Plane<float>& error)
{
    const ROI roi                   = result.roi();
    const float most_relative_noise = fit_average(average, layer, scale, roi, nthreads, planes);
    const int nc = average.nchannels;
    error        = Plane<float>(roi);
    parallel_rows(roi, nthreads, [&](int y) {
        float* out = static_cast<float*>(result.pixeladdr(roi.xbegin, y));
        size_t i   = pixel_offset(roi, roi.xbegin, y);
        for (int x = roi.xbegin; x < roi.xend; ++x, ++i, out += nc) {
            const float s2 = std::min(planes.noise.at(x, y), most_relative_noise * planes.level.at(x, y));
            const float t2    = std::min(planes.residual.at(x, y), s2);
            const float m2    = planes.mean_square.at(x, y);
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
