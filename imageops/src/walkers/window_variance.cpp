// window_variance.cpp: 3x3 window variances and 3x3 minima of planes, with
// sums and minima shared between neighbouring pixels (column sums of three
// rows, then three columns), one scratch row per strip of rows.
#include "walkers/window_variance.h"

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
        ColumnSums sums(cols);
        for (int y = strip.ybegin; y < strip.yend; ++y) {
            const Span ys = clip_window(y, 1, bounds.ybegin, bounds.yend);
            sums.clear();
            for (int qy = ys.begin; qy < ys.end; ++qy)
                sums.add_row(in + pixel_offset(in_region, cols.begin, qy));
            const size_t row = pixel_offset(out_region, out_region.xbegin, y);
            window_row(sums, { out_region.xbegin, out_region.xend }, bounds.xbegin, bounds.xend,
                       [&](int x, double s, double q, int columns) {
                           const int n    = columns * ys.size();
                           const size_t o = row + size_t(x - out_region.xbegin);
                           variance[o]    = sample_variance(s, q, n);
                           if (mean_square)
                               mean_square[o] = float(q / n);
                       });
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
        const Span columns = { region.xbegin, region.xend };
        for (int y = strip.ybegin; y < strip.yend; ++y) {
            const Span ys = clip_window(y, 1, region.ybegin, region.yend);
            smallest_of_rows(
                ys.size(), region.width(),
                [&](int r) { return in + pixel_offset(region, region.xbegin, ys.begin + r); },
                column.data());
            float* dst = out + pixel_offset(region, region.xbegin, y);
            window_minima(column.data(), columns, columns, region.xbegin, region.xend,
                          [&](int x, float m) { dst[x - region.xbegin] = m; });
        }
    });
}

}  // namespace mcdenoise
