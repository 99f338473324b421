// window_variance.h: the noise of a plane as `denoise` estimates it when no
// variance is given: the sample variance of each 3x3 window, and per pixel
// the smallest of those among the 3x3 windows around it (the window on one
// side of an edge, not the one across it); implemented in
// window_variance.cpp.
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

/// Per pixel of `out_region`, the sample variance (divided by n - 1, 0
/// for n == 1) of `in` over the 3x3 window around it, clipped to `bounds`,
/// into `variance` (a plane over `out_region`); with `mean_square`, the
/// window's mean of in^2 into it too (same layout). `in` is a plane over
/// `in_region`, which holds every such window. Box sums in double: column
/// sums of three rows, then three of those, per row.
void window_variances(const float* in, const OIIO::ROI& in_region, const OIIO::ROI& out_region,
                      const OIIO::ROI& bounds, int nthreads, float* variance,
                      float* mean_square = nullptr);

/// Per pixel of `region`, the smallest value of `in` (a plane over
/// `region`) among the 3x3 window around it, clipped to `region`, into
/// `out` (a plane over `region`): a row minimum, then a column minimum.
void smallest_in_windows(const float* in, const OIIO::ROI& region, int nthreads, float* out);

/// What the smallest window variance of white noise averages to, as a
/// share of the noise's variance (0.524, measured over 360000 pixels of
/// Gaussian noise): the minimum picks the windows whose noise happened to
/// be low. Divide by it for an estimate of the variance itself.
constexpr float smallest_window_bias = 0.524f;

}  // namespace mcdenoise
