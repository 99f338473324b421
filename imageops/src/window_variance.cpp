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
            size_t o = pixel_offset(out_region, out_region.xbegin, y);
            for (int x = out_region.xbegin; x < out_region.xend; ++x, ++o) {
                const Span xs = clip_window(x, 1, bounds.xbegin, bounds.xend);
                double s = 0.0, q = 0.0;
                for (int qx = xs.begin; qx < xs.end; ++qx) {
                    s += sum[size_t(qx - cols.begin)];
                    q += square[size_t(qx - cols.begin)];
                }
                const int n = xs.size() * ys.size();
                variance[o] = n > 1 ? float(std::max(0.0, q - s * s / n) / (n - 1)) : 0.0f;
                if (mean_square)
                    mean_square[o] = float(q / n);
            }
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
            float* dst = out + pixel_offset(region, region.xbegin, y);
            for (int i = 0; i < region.width(); ++i) {
                const Span xs = clip_window(i, 1, 0, region.width());
                float smallest = column[size_t(xs.begin)];
                for (int q = xs.begin + 1; q < xs.end; ++q)
                    smallest = std::min(smallest, column[size_t(q)]);
                dst[i] = smallest;
            }
        }
    });
}

}  // namespace mcdenoise
