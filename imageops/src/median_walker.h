// median_walker.h: the one window walker for median filters. A filter is a
// rule saying which neighbours are viable; the walker takes the median of
// the viable finite values of each window, through the SIMD median network
// wherever a whole unclipped window is viable and finite, and through
// in-place selection elsewhere.
#pragma once

#include "median_kernel.h"
#include "operation.h"
#include "pixel_block.h"
#include "window.h"

#include <memory>
#include <vector>

namespace mcdenoise {

/// The beauty as the median walker reads it: one contiguous plane per
/// channel over `region`, and, when any value is non-finite, the share of
/// non-finite values in each ROI pixel's window, per channel.
struct MedianSource {
    OIIO::ROI region;
    OIIO::ROI roi;
    int radius = 0;
    std::vector<std::unique_ptr<float[]>> planes;
    std::unique_ptr<ResultPixels> nonfinite_share;

    const float* plane_row(int c, int y) const
    {
        return planes[size_t(c)].get() + size_t(y - region.ybegin) * region.width()
               - region.xbegin;
    }
    bool finite_window(int c, int x, int y) const
    {
        return !nonfinite_share || nonfinite_share->pixel(x, y)[c] == 0.0f;
    }
};

/// Read the beauty for a median of window side `size` over `roi`.
/// Returns false with `dst`'s error set if the pixels cannot be read.
bool load_median_source(const char* op, OIIO::ImageBuf& dst,
                        const OIIO::ImageBuf& beauty, const OIIO::ROI& roi,
                        int size, int nthreads, MedianSource& source);

/// A viability rule for the median walker. `Rule` provides
/// `bool uniform(int x, int y) const`: every pixel of (x, y)'s clipped window
/// is viable; and `bool viable(int px, int py, int qx, int qy) const`.
/// Computes the median filter of one strip into `result`.
template<class Rule>
void median_strip(const MedianSource& src, const Rule& rule, const OIIO::ROI& strip,
                  ResultPixels& result)
{
    const int r = src.radius, k = 2 * r + 1;
    const OIIO::ROI& reg     = src.region;
    const MedianKernel wide   = wide_median_kernel(k);
    const MedianKernel narrow = narrow_median_kernel(k);
    const bool net            = wide.run != nullptr;
    std::vector<const float*> rows(static_cast<size_t>(k), nullptr);
    std::vector<float> gathered(size_t(k) * k);
    std::vector<char> fast(size_t(strip.width()));
    int64_t empty = 0;

    // Medians of the windows at x .. x + kernel.lanes - 1 by the network.
    auto network_batch = [&](const MedianKernel& kernel, int c, int x, float* out_row) {
        float medians[16];
        kernel.run(rows.data(), x, medians);
        float* out = out_row + (x - strip.xbegin) * result.pixel_stride() + c;
        for (int l = 0; l < kernel.lanes; ++l)
            out[l * result.pixel_stride()] = medians[l];
    };
    // Medians of the windows [x, end), all taken by the network, at least
    // 8 of them: wide batches, then narrow ones, the last overlapping.
    auto network_run = [&](int c, int x, int end, float* out_row) {
        for (; end - x >= wide.lanes; x += wide.lanes)
            network_batch(wide, c, x, out_row);
        for (; x < end; x += narrow.lanes)
            network_batch(narrow, c, std::min(x, end - narrow.lanes), out_row);
    };
    auto gather_one = [&](int c, int x, int y) {
        const Span xs = clip_window(x, r, reg.xbegin, reg.xend);
        const Span ys = clip_window(y, r, reg.ybegin, reg.yend);
        int n = 0;
        for (int qy = ys.begin; qy < ys.end; ++qy) {
            const float* row = src.plane_row(c, qy);
            for (int qx = xs.begin; qx < xs.end; ++qx)
                if (std::isfinite(row[qx]) && rule.viable(x, y, qx, qy))
                    gathered[size_t(n++)] = row[qx];
        }
        empty += n == 0;
        result.pixel(x, y)[c] = n ? median_in_place(gathered.data(), n) : 0.0f;
    };

    for (int y = strip.ybegin; y < strip.yend; ++y) {
        // Windows of this row that are whole (not clipped) and fully viable.
        const bool whole_rows = net && y - r >= reg.ybegin && y + r < reg.yend;
        for (int x = strip.xbegin; x < strip.xend; ++x)
            fast[size_t(x - strip.xbegin)] = whole_rows && x - r >= reg.xbegin
                                             && x + r < reg.xend && rule.uniform(x, y);
        float* out_row = result.pixel(strip.xbegin, y);
        for (int c = 0; c < strip.nchannels(); ++c) {
            for (int dy = -r; dy <= r && whole_rows; ++dy)
                rows[size_t(dy + r)] = src.plane_row(c, y + dy);
            auto by_network = [&](int x) {
                return fast[size_t(x - strip.xbegin)] && src.finite_window(c, x, y);
            };
            int x = strip.xbegin;
            while (x < strip.xend) {
                int run = x;  // [x, run): windows the network can take
                while (run < strip.xend && by_network(run))
                    ++run;
                if (run > x && run - x >= narrow.lanes) {
                    network_run(c, x, run, out_row);
                } else {
                    for (int g = x; g < run; ++g)
                        gather_one(c, g, y);
                }
                x = run;
                if (x < strip.xend)  // the window that ended the run
                    gather_one(c, x++, y);
            }
        }
    }
    result.empty_windows += empty;
}

}  // namespace mcdenoise
