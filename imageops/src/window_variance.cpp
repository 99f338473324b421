// window_variance.cpp: 3x3 window variances and 3x3 minima of planes, with
// sums and minima shared between neighbouring pixels (column sums of three
// rows, then three columns), one scratch row per strip of rows.
#include "window_variance.h"

#include <OpenImageIO/imagebufalgo_util.h>

#include <vector>

namespace mcdenoise {

using OIIO::ROI;

void window_variances(const float* in, const ROI& in_region, const ROI& out_region,
                      const ROI& bounds, int nthreads, float* variance, float* mean_square)
{
    // the columns the windows of out_region's pixels read
    const Span cols = { std::max(bounds.xbegin, out_region.xbegin - 1),
                        std::min(bounds.xend, out_region.xend + 1) };
    ROI rows    = out_region;
    rows.chbegin = 0;
    rows.chend   = 1;
    OIIO::ImageBufAlgo::parallel_image(rows, nthreads, [&](ROI strip) {
        std::vector<double> sum(size_t(cols.size())), square(size_t(cols.size()));
        for (int y = strip.ybegin; y < strip.yend; ++y) {
            const Span ys = clip_window(y, 1, bounds.ybegin, bounds.yend);
            std::fill(sum.begin(), sum.end(), 0.0);
            std::fill(square.begin(), square.end(), 0.0);
            for (int qy = ys.begin; qy < ys.end; ++qy) {
                const float* row = in + pixel_offset(in_region, cols.begin, qy);
                for (int i = 0; i < cols.size(); ++i) {
                    const double v = row[i];
                    sum[size_t(i)] += v;
                    square[size_t(i)] += v * v;
                }
            }
            // pixels whose window is not clipped in x: three columns each
            const int inner_begin = std::max(out_region.xbegin, bounds.xbegin + 1);
            const int inner_end   = std::max(inner_begin, std::min(out_region.xend, bounds.xend - 1));
            const size_t row      = pixel_offset(out_region, out_region.xbegin, y);
            const auto put = [&](int x, double s, double q, int n) {
                const size_t o = row + size_t(x - out_region.xbegin);
                variance[o]    = n > 1 ? float(std::max(0.0, q - s * s / n) / (n - 1)) : 0.0f;
                if (mean_square)
                    mean_square[o] = float(q / n);
            };
            const auto clipped = [&](int x) {
                const Span xs = clip_window(x, 1, bounds.xbegin, bounds.xend);
                double s = 0.0, q = 0.0;
                for (int qx = xs.begin; qx < xs.end; ++qx) {
                    s += sum[size_t(qx - cols.begin)];
                    q += square[size_t(qx - cols.begin)];
                }
                put(x, s, q, xs.size() * ys.size());
            };
            for (int x = out_region.xbegin; x < inner_begin; ++x)
                clipped(x);
            const int n            = 3 * ys.size();
            const double* s_at     = sum.data() + (inner_begin - cols.begin);
            const double* q_at     = square.data() + (inner_begin - cols.begin);
            float* var_out         = variance + row + size_t(inner_begin - out_region.xbegin);
            float* square_out      = mean_square ? mean_square + row + size_t(inner_begin - out_region.xbegin)
                                                 : nullptr;
            for (int i = 0; i < inner_end - inner_begin; ++i) {
                const double s = s_at[i - 1] + s_at[i] + s_at[i + 1];
                const double q = q_at[i - 1] + q_at[i] + q_at[i + 1];
                var_out[i]     = float(std::max(0.0, q - s * s / n) / (n - 1));
                if (square_out)
                    square_out[i] = float(q / n);
            }
            for (int x = inner_end; x < out_region.xend; ++x)
                clipped(x);
        }
    });
}

void smallest_in_windows(const float* in, const ROI& region, int nthreads, float* out)
{
    ROI rows    = region;
    rows.chbegin = 0;
    rows.chend   = 1;
    OIIO::ImageBufAlgo::parallel_image(rows, nthreads, [&](ROI strip) {
        std::vector<float> column(size_t(region.width()));
        for (int y = strip.ybegin; y < strip.yend; ++y) {
            const Span ys = clip_window(y, 1, region.ybegin, region.yend);
            const float* first = in + pixel_offset(region, region.xbegin, ys.begin);
            std::copy(first, first + region.width(), column.begin());
            for (int qy = ys.begin + 1; qy < ys.end; ++qy) {
                const float* row = in + pixel_offset(region, region.xbegin, qy);
                for (int i = 0; i < region.width(); ++i)
                    column[size_t(i)] = std::min(column[size_t(i)], row[i]);
            }
            float* dst  = out + pixel_offset(region, region.xbegin, y);
            const int w = region.width();
            if (w == 1) {
                dst[0] = column[0];
                continue;
            }
            dst[0] = std::min(column[0], column[1]);
            for (int i = 1; i < w - 1; ++i)
                dst[i] = std::min(std::min(column[size_t(i - 1)], column[size_t(i)]),
                                  column[size_t(i + 1)]);
            dst[w - 1] = std::min(column[size_t(w - 2)], column[size_t(w - 1)]);
        }
    });
}

}  // namespace mcdenoise
