// median_walker.h: the one window walker for median filters. A filter is a
// rule saying which neighbours are viable; the walker takes the median of
// the viable finite values of each window, through the SIMD median network
// wherever a whole unclipped window is viable and finite, and through
// in-place selection elsewhere.
#pragma once

#include "median_kernel.h"
#include "operation.h"
#include "pixel_block.h"
#include "plane.h"
#include "window.h"

#include <limits>
#include <memory>
#include <vector>

namespace mcdenoise {

/// The beauty as the median walker reads it: one contiguous plane per
/// channel over `region`, and, when any value is non-finite, the share of
/// non-finite values in each ROI pixel's window, per channel.
struct MedianSource {
    OIIO::ROI roi;
    int radius = 0;
    Planes<float> planes;
    std::unique_ptr<ResultPixels> nonfinite_share;

    /// The region the planes cover.
    const OIIO::ROI& region() const { return planes.region; }
    /// Channel c's row y, indexed by x (from `region().xbegin`).
    const float* plane_row(int c, int y) const { return planes.row(c, y) - planes.region.xbegin; }
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
/// `void uniform_row(int y, Span xs, uint8_t* out) const`: out[x - xs.begin]
/// is 1 where every pixel of (x, y)'s clipped window is viable; and
/// `void row_weights(int px, int py, int qy, Span xs, float* w) const`: for
/// each neighbour (qx, qy), qx in `xs`, of center (px, py), w[qx - xs.begin]
/// is 0 where it is not viable.
/// Computes the median filter of one strip into `result`.
template<class Rule>
void median_strip(const MedianSource& src, const Rule& rule, const OIIO::ROI& strip,
                  ResultPixels& result)
{
    const int r = src.radius, k = 2 * r + 1;
    const OIIO::ROI& reg     = src.region();
    const MedianKernel wide   = wide_median_kernel(k);
    const MedianKernel narrow = narrow_median_kernel(k);
    const SlotMedians by_slots = slot_median_kernel(k);
    const bool net            = wide.run != nullptr;
    constexpr int lanes8      = 8;
    std::vector<float> slots_low(net ? size_t(k) * k * lanes8 : 0);
    std::vector<float> slots_high(slots_low.size());
    std::vector<int> pending;  // whole windows waiting for a masked batch
    std::vector<const float*> rows(static_cast<size_t>(k), nullptr);
    std::vector<float> gathered(size_t(k) * k);
    std::vector<float> viable(static_cast<size_t>(k));  // one window row's rule weights
    std::vector<uint8_t> fast(size_t(strip.width()));
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
    // Medians of up to 8 whole windows of one row, each over its viable
    // finite values: the others' slots get -inf and +inf alternately, so
    // with an even count left out the middle slot holds the median; with an
    // odd count, starting with -inf gives the lower of the two middle values
    // and starting with +inf the upper one, whose mean is the median.
    auto masked_batch = [&](int c, int y, const int* xs, int n, float* out_row) {
        constexpr float inf = std::numeric_limits<float>::infinity();
        int left_out[lanes8];
        bool odd = false;
        for (int l = 0; l < lanes8; ++l) {
            const int x = xs[std::min(l, n - 1)];
            int count   = 0;
            for (int dy = -r, i = 0; dy <= r; ++dy) {
                const float* row = src.plane_row(c, y + dy);
                rule.row_weights(x, y, y + dy, Span { x - r, x + r + 1 }, viable.data());
                for (int dx = -r; dx <= r; ++dx, ++i) {
                    const float v = row[x + dx];
                    const bool ok = std::isfinite(v)
                                    && ((dx == 0 && dy == 0) || viable[size_t(dx + r)] != 0.0f);
                    const bool low_first = count % 2 == 0;
                    slots_low[size_t(i * lanes8 + l)]  = ok ? v : (low_first ? -inf : inf);
                    slots_high[size_t(i * lanes8 + l)] = ok ? v : (low_first ? inf : -inf);
                    count += !ok;
                }
            }
            left_out[l] = count;
            odd |= count % 2 == 1;
        }
        float low[lanes8], high[lanes8];
        by_slots(slots_low.data(), low);
        if (odd)
            by_slots(slots_high.data(), high);
        for (int l = 0; l < n; ++l) {
            float& out = out_row[(xs[l] - strip.xbegin) * result.pixel_stride() + c];
            if (left_out[l] == k * k) {
                out = 0.0f;
                ++empty;
            } else {
                out = left_out[l] % 2 == 0 ? low[l]
                                           : float(0.5 * (double(low[l]) + double(high[l])));
            }
        }
    };
    auto flush_pending = [&](int c, int y, float* out_row) {
        for (size_t b = 0; b < pending.size(); b += lanes8)
            masked_batch(c, y, pending.data() + b,
                         int(std::min<size_t>(lanes8, pending.size() - b)), out_row);
        pending.clear();
    };
    auto gather_one = [&](int c, int x, int y) {
        const Span xs = clip_window(x, r, reg.xbegin, reg.xend);
        const Span ys = clip_window(y, r, reg.ybegin, reg.yend);
        int n = 0;
        for (int qy = ys.begin; qy < ys.end; ++qy) {
            const float* row = src.plane_row(c, qy);
            rule.row_weights(x, y, qy, xs, viable.data());
            for (int qx = xs.begin; qx < xs.end; ++qx)
                if (std::isfinite(row[qx]) && viable[size_t(qx - xs.begin)] != 0.0f)
                    gathered[size_t(n++)] = row[qx];
        }
        empty += n == 0;
        result.pixel(x, y)[c] = n ? median_in_place(gathered.data(), n) : 0.0f;
    };

    for (int y = strip.ybegin; y < strip.yend; ++y) {
        // Windows of this row that are whole (not clipped) and fully viable.
        const bool whole_rows = net && y - r >= reg.ybegin && y + r < reg.yend;
        rule.uniform_row(y, Span { strip.xbegin, strip.xend }, fast.data());
        for (int x = strip.xbegin; x < strip.xend; ++x)
            fast[size_t(x - strip.xbegin)] &= whole_rows && x - r >= reg.xbegin
                                              && x + r < reg.xend;
        float* out_row = result.pixel(strip.xbegin, y);
        for (int c = 0; c < strip.nchannels(); ++c) {
            for (int dy = -r; dy <= r && whole_rows; ++dy)
                rows[size_t(dy + r)] = src.plane_row(c, y + dy);
            auto by_network = [&](int x) {
                return fast[size_t(x - strip.xbegin)] && src.finite_window(c, x, y);
            };
            // Whole windows not taken by a plain network run wait for a
            // masked batch; clipped ones are selected in place.
            auto masked_or_gathered = [&](int x) {
                if (whole_rows && x - r >= reg.xbegin && x + r < reg.xend)
                    pending.push_back(x);
                else
                    gather_one(c, x, y);
            };
            int x = strip.xbegin;
            while (x < strip.xend) {
                int run = x;  // [x, run): windows the plain network can take
                while (run < strip.xend && by_network(run))
                    ++run;
                if (run > x && run - x >= narrow.lanes) {
                    network_run(c, x, run, out_row);
                } else {
                    for (int g = x; g < run; ++g)
                        masked_or_gathered(g);
                }
                x = run;
                if (x < strip.xend)  // the window that ended the run
                    masked_or_gathered(x++);
            }
            flush_pending(c, y, out_row);
        }
    }
    result.empty_windows += empty;
}

}  // namespace mcdenoise
