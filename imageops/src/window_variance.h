// window_variance.h: the noise of a plane as `denoise` estimates it when no
// variance is given: the sample variance of each 3x3 window, and per pixel
// the smallest of those among the 3x3 windows around it (the window on one
// side of an edge, not the one across it).
#pragma once

#include "plane.h"
#include "window.h"

#include <OpenImageIO/imagebuf.h>

#include <algorithm>

namespace mcdenoise {

/// The region's pixels, row by row, with offsets into a plane of its width.
template<class Fn>
void for_each_pixel(const OIIO::ROI& region, int nthreads, Fn&& fn)
{
    parallel_rows(region, nthreads, [&](int y) {
        size_t i = pixel_offset(region, region.xbegin, y);
        for (int x = region.xbegin; x < region.xend; ++x, ++i)
            fn(x, y, i);
    });
}

/// Sample variance (divided by n - 1, 0 for n == 1) of `at(x, y)` over the
/// 3x3 window around each pixel of `region`, clipped to `bounds` (`at` reads
/// every such window), into `out`, a plane over `region`.
template<class At>
void estimate_variance(At&& at, const OIIO::ROI& region, const OIIO::ROI& bounds, int nthreads,
                       float* out)
{
    for_each_pixel(region, nthreads, [&](int x, int y, size_t i) {
        const Span xs = clip_window(x, 1, bounds.xbegin, bounds.xend);
        const Span ys = clip_window(y, 1, bounds.ybegin, bounds.yend);
        const int n   = xs.size() * ys.size();
        double sum    = 0.0;
        for (int qy = ys.begin; qy < ys.end; ++qy)
            for (int qx = xs.begin; qx < xs.end; ++qx)
                sum += at(qx, qy);
        const double mean = sum / n;
        double sq         = 0.0;
        for (int qy = ys.begin; qy < ys.end; ++qy)
            for (int qx = xs.begin; qx < xs.end; ++qx) {
                const double d = at(qx, qy) - mean;
                sq += d * d;
            }
        out[i] = n > 1 ? float(sq / (n - 1)) : 0.0f;
    });
}

/// The smallest value of `in` (a plane over its region) among the 3x3
/// window around (x, y), clipped to `in`'s region.
inline float smallest_in_window(const float* in, const OIIO::ROI& in_region, int x, int y)
{
    const Span xs  = clip_window(x, 1, in_region.xbegin, in_region.xend);
    const Span ys  = clip_window(y, 1, in_region.ybegin, in_region.yend);
    float smallest = in[pixel_offset(in_region, xs.begin, ys.begin)];
    for (int qy = ys.begin; qy < ys.end; ++qy)
        for (int qx = xs.begin; qx < xs.end; ++qx)
            smallest = std::min(smallest, in[pixel_offset(in_region, qx, qy)]);
    return smallest;
}

/// What the smallest window variance of white noise averages to, as a
/// share of the noise's variance (0.524, measured over 360000 pixels of
/// Gaussian noise): the minimum picks the windows whose noise happened to
/// be low. Divide by it for an estimate of the variance itself.
constexpr float smallest_window_bias = 0.524f;

}  // namespace mcdenoise
