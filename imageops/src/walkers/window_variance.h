// window_variance.h: the noise of a plane as `denoise` estimates it when no
// variance is given: the sample variance of each 3x3 window, and per pixel
// the smallest of those among the 3x3 windows around it (the window on one
// side of an edge, not the one across it); implemented in
// window_variance.cpp.
#pragma once

#include "core/plane.h"
#include "core/window.h"

#include <OpenImageIO/imagebuf.h>

#include <algorithm>
#include <vector>

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

/// The sample variance (divided by n - 1, 0 for n <= 1) of n values
/// whose sum and sum of squares are given.
inline float sample_variance(double sum, double square, int n)
{
    return n > 1 ? float(std::max(0.0, square - sum * sum / n) / (n - 1)) : 0.0f;
}

/// Per column of `reads`, the sum and the sum of squares of the rows added
/// since `clear`: one row of windows' column sums, in double.
struct ColumnSums {
    Span reads;
    std::vector<double> sum, square;

    explicit ColumnSums(Span reads_)
        : reads(reads_), sum(size_t(reads_.size())), square(size_t(reads_.size()))
    {
    }
    void clear()
    {
        std::fill(sum.begin(), sum.end(), 0.0);
        std::fill(square.begin(), square.end(), 0.0);
    }
    /// Add a row of values, one per column of `reads`.
    void add_row(const float* row)
    {
        for (size_t i = 0; i < sum.size(); ++i) {
            const double v = row[i];
            sum[i] += v;
            square[i] += v * v;
        }
    }
};

/// For every x of `out`, `put(x, s, q, columns)` with the sums over the 3
/// columns around x clipped to [lo, hi) (all within `sums.reads`); the
/// columns whose window is not clipped take a loop without clipping.
template<class Put>
void window_row(const ColumnSums& sums, Span out, int lo, int hi, Put&& put)
{
    const auto clipped = [&](int x) {
        const Span xs = clip_window(x, 1, lo, hi);
        double s = 0.0, q = 0.0;
        for (int qx = xs.begin; qx < xs.end; ++qx) {
            s += sums.sum[size_t(qx - sums.reads.begin)];
            q += sums.square[size_t(qx - sums.reads.begin)];
        }
        put(x, s, q, xs.size());
    };
    const int inner_begin = std::max(out.begin, lo + 1);
    const int inner_end   = std::max(inner_begin, std::min(out.end, hi - 1));
    for (int x = out.begin; x < std::min(inner_begin, out.end); ++x)
        clipped(x);
    const double* s = sums.sum.data() + (inner_begin - sums.reads.begin);
    const double* q = sums.square.data() + (inner_begin - sums.reads.begin);
    for (int i = 0; i < inner_end - inner_begin; ++i)
        put(inner_begin + i, s[i - 1] + s[i] + s[i + 1], q[i - 1] + q[i] + q[i + 1], 3);
    for (int x = std::max(out.begin, inner_end); x < out.end; ++x)
        clipped(x);
}

/// Into `smallest`, per column, the smallest of `rows` rows of `width`
/// values each, the row r starting at `row(r)` (r from 0).
template<class Row>
void smallest_of_rows(int rows, int width, Row&& row, float* smallest)
{
    const float* first = row(0);
    std::copy(first, first + width, smallest);
    for (int r = 1; r < rows; ++r) {
        const float* values = row(r);
        for (int i = 0; i < width; ++i)
            smallest[i] = std::min(smallest[i], values[i]);
    }
}

/// For every x of `out`, `put(x, m)` with m the smallest of `column` (one
/// value per column of `columns`) over the 3 columns around x clipped to
/// [lo, hi) (all within `columns`).
template<class Put>
void window_minima(const float* column, Span columns, Span out, int lo, int hi, Put&& put)
{
    for (int x = out.begin; x < out.end; ++x) {
        const Span xs  = clip_window(x, 1, lo, hi);
        const float* c = column + (xs.begin - columns.begin);
        float m        = c[0];
        for (int i = 1; i < xs.size(); ++i)
            m = std::min(m, c[i]);
        put(x, m);
    }
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
