// median_walker.h: the one window walker for median filters. A filter is a
// rule saying which neighbours are viable; the walker takes the median of
// the viable finite values of each window, through the SIMD median network
// wherever a whole unclipped window is viable and finite, and through
// in-place selection elsewhere.
#pragma once

#include "core/operation.h"
#include "core/pixel_block.h"
#include "core/plane.h"
#include "core/window.h"
#include "walkers/median_kernel.h"

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

/// The median walker over one strip. `Rule` provides
/// `void uniform_row(int y, Span xs, uint8_t* out) const`: out[x - xs.begin]
/// is 1 where every pixel of (x, y)'s clipped window is viable; and
/// `void row_weights(int px, int py, int qy, Span xs, float* w) const`: for
/// each neighbour (qx, qy), qx in `xs`, of center (px, py), w[qx - xs.begin]
/// is 0 where it is not viable.
///
/// Each row and channel takes three paths: runs of windows that are whole
/// (not clipped), wholly viable and finite go through the network
/// (`network_run`); other whole windows wait in `pending` and go through
/// the slot network eight at a time with their left-out values masked
/// (`masked_batch`); clipped windows are selected in place (`gather_one`).
template<class Rule>
class MedianStrip {
public:
    MedianStrip(const MedianSource& src, const Rule& rule, const OIIO::ROI& strip,
                ResultPixels& result)
        : m_src(src), m_rule(rule), m_strip(strip), m_result(result), m_r(src.radius),
          m_k(2 * src.radius + 1), m_wide(wide_median_kernel(m_k)),
          m_narrow(narrow_median_kernel(m_k)), m_by_slots(slot_median_kernel(m_k)),
          m_net(m_wide.run != nullptr),
          m_slots_low(m_net ? size_t(m_k) * m_k * lanes : 0),
          m_slots_high(m_slots_low.size()), m_rows(size_t(m_k), nullptr),
          m_gathered(size_t(m_k) * m_k), m_viable(size_t(m_k)),
          m_network(size_t(strip.width()))
    {
    }

    /// Filters every row and channel of the strip into the result.
    void run()
    {
        for (int y = m_strip.ybegin; y < m_strip.yend; ++y) {
            mark_network_windows(y);
            for (int c = 0; c < m_strip.nchannels(); ++c)
                filter_row(c, y);
        }
        m_result.empty_windows += m_empty;
    }

private:
    /// Windows of a masked batch: the slot network's lanes.
    static constexpr int lanes = 8;

    /// True when (x, y)'s window lies inside the source region (not
    /// clipped), on a row whose whole windows the networks serve.
    bool whole_window(int x) const
    {
        const OIIO::ROI& reg = m_src.region();
        return m_whole_rows && x - m_r >= reg.xbegin && x + m_r < reg.xend;
    }

    /// Marks in `m_network` the windows of row y that are whole and wholly
    /// viable (the network takes them when their values are finite).
    void mark_network_windows(int y)
    {
        const OIIO::ROI& reg = m_src.region();
        m_whole_rows = m_net && y - m_r >= reg.ybegin && y + m_r < reg.yend;
        // Local copies: byte stores may alias any member, which would
        // otherwise be read again on every pixel.
        uint8_t* network   = m_network.data();
        const int xbegin   = m_strip.xbegin, xend = m_strip.xend, r = m_r;
        const int first    = reg.xbegin + r, last = reg.xend - r;  // whole windows' centres
        const bool whole   = m_whole_rows;
        m_rule.uniform_row(y, Span { xbegin, xend }, network);
        for (int x = xbegin; x < xend; ++x)
            network[x - xbegin] &= whole && x >= first && x < last;
        m_out_row = m_result.pixel(m_strip.xbegin, y);
    }

    /// True when the plain network takes (x, y)'s window of channel c.
    bool by_network(int c, int x, int y) const
    {
        return m_network[size_t(x - m_strip.xbegin)] && m_src.finite_window(c, x, y);
    }

    /// Channel c of row y: runs of network windows long enough for a
    /// batch go through the network, the other windows wait for a masked
    /// batch or are gathered.
    void filter_row(int c, int y)
    {
        for (int dy = -m_r; dy <= m_r && m_whole_rows; ++dy)
            m_rows[size_t(dy + m_r)] = m_src.plane_row(c, y + dy);
        int x = m_strip.xbegin;
        while (x < m_strip.xend) {
            int run = x;  // [x, run): windows the plain network can take
            while (run < m_strip.xend && by_network(c, run, y))
                ++run;
            if (run > x && run - x >= m_narrow.lanes) {
                network_run(c, x, run);
            } else {
                for (int g = x; g < run; ++g)
                    masked_or_gathered(c, g, y);
            }
            x = run;
            if (x < m_strip.xend)  // the window that ended the run
                masked_or_gathered(c, x++, y);
        }
        flush_pending(c, y);
    }

    /// A whole window not taken by a plain network run waits for a masked
    /// batch; a clipped one is selected in place.
    void masked_or_gathered(int c, int x, int y)
    {
        if (whole_window(x))
            m_pending.push_back(x);
        else
            gather_one(c, x, y);
    }

    /// Output of channel c at column x of the current row.
    float& out(int c, int x) { return m_out_row[(x - m_strip.xbegin) * m_result.pixel_stride() + c]; }

    /// Medians of the windows at x .. x + kernel.lanes - 1 by the network.
    void network_batch(const MedianKernel& kernel, int c, int x)
    {
        float medians[16];
        kernel.run(m_rows.data(), x, medians);
        for (int l = 0; l < kernel.lanes; ++l)
            out(c, x + l) = medians[l];
    }

    /// Medians of the windows [x, end), all taken by the network, at least
    /// 8 of them: wide batches, then narrow ones, the last overlapping.
    void network_run(int c, int x, int end)
    {
        for (; end - x >= m_wide.lanes; x += m_wide.lanes)
            network_batch(m_wide, c, x);
        for (; x < end; x += m_narrow.lanes)
            network_batch(m_narrow, c, std::min(x, end - m_narrow.lanes));
    }

    /// Fills lane l of the slots with (x, y)'s window of channel c: its
    /// viable finite values, and for each value left out -inf and +inf
    /// alternately (the other order in the high slots). Returns how many
    /// were left out.
    int fill_slots(int l, int c, int x, int y)
    {
        constexpr float inf = std::numeric_limits<float>::infinity();
        int count = 0;
        for (int dy = -m_r, i = 0; dy <= m_r; ++dy) {
            const float* row = m_src.plane_row(c, y + dy);
            m_rule.row_weights(x, y, y + dy, Span { x - m_r, x + m_r + 1 }, m_viable.data());
            for (int dx = -m_r; dx <= m_r; ++dx, ++i) {
                const float v = row[x + dx];
                const bool ok = std::isfinite(v)
                                && ((dx == 0 && dy == 0) || m_viable[size_t(dx + m_r)] != 0.0f);
                const bool low_first = count % 2 == 0;
                m_slots_low[size_t(i * lanes + l)]  = ok ? v : (low_first ? -inf : inf);
                m_slots_high[size_t(i * lanes + l)] = ok ? v : (low_first ? inf : -inf);
                count += !ok;
            }
        }
        return count;
    }

    /// Medians of up to 8 whole windows of one row, each over its viable
    /// finite values: with an even count left out the middle slot holds the
    /// median; with an odd count, starting with -inf gives the lower of the
    /// two middle values and starting with +inf the upper one, whose mean is
    /// the median.
    void masked_batch(int c, int y, const int* xs, int n)
    {
        int left_out[lanes];
        bool odd = false;
        for (int l = 0; l < lanes; ++l) {
            left_out[l] = fill_slots(l, c, xs[std::min(l, n - 1)], y);
            odd |= left_out[l] % 2 == 1;
        }
        float low[lanes], high[lanes];
        m_by_slots(m_slots_low.data(), low);
        if (odd)
            m_by_slots(m_slots_high.data(), high);
        for (int l = 0; l < n; ++l) {
            float& o = out(c, xs[l]);
            if (left_out[l] == m_k * m_k) {
                o = 0.0f;
                ++m_empty;
            } else {
                o = left_out[l] % 2 == 0 ? low[l]
                                         : float(0.5 * (double(low[l]) + double(high[l])));
            }
        }
    }

    /// The pending windows of channel c of row y, in masked batches.
    void flush_pending(int c, int y)
    {
        for (size_t b = 0; b < m_pending.size(); b += lanes)
            masked_batch(c, y, m_pending.data() + b,
                         int(std::min<size_t>(lanes, m_pending.size() - b)));
        m_pending.clear();
    }

    /// The median of (x, y)'s clipped window of channel c by in-place
    /// selection over its viable finite values.
    void gather_one(int c, int x, int y)
    {
        const OIIO::ROI& reg = m_src.region();
        const Span xs = clip_window(x, m_r, reg.xbegin, reg.xend);
        const Span ys = clip_window(y, m_r, reg.ybegin, reg.yend);
        int n = 0;
        for (int qy = ys.begin; qy < ys.end; ++qy) {
            const float* row = m_src.plane_row(c, qy);
            m_rule.row_weights(x, y, qy, xs, m_viable.data());
            for (int qx = xs.begin; qx < xs.end; ++qx)
                if (std::isfinite(row[qx]) && m_viable[size_t(qx - xs.begin)] != 0.0f)
                    m_gathered[size_t(n++)] = row[qx];
        }
        m_empty += n == 0;
        m_result.pixel(x, y)[c] = n ? median_in_place(m_gathered.data(), n) : 0.0f;
    }

    const MedianSource& m_src;
    const Rule& m_rule;
    const OIIO::ROI& m_strip;
    ResultPixels& m_result;
    const int m_r, m_k;  // window radius and side
    const MedianKernel m_wide, m_narrow;
    const SlotMedians m_by_slots;
    const bool m_net;  // a network serves this window side
    std::vector<float> m_slots_low, m_slots_high;  // the masked batch's slots
    std::vector<int> m_pending;          // whole windows waiting for a masked batch
    std::vector<const float*> m_rows;    // the network's window rows
    std::vector<float> m_gathered;       // a clipped window's values
    std::vector<float> m_viable;         // one window row's rule weights
    std::vector<uint8_t> m_network;      // the row's windows the network may take
    bool m_whole_rows = false;           // the row's windows can be whole
    float* m_out_row  = nullptr;         // the row's output
    int64_t m_empty   = 0;
};

/// Computes the median filter of one strip into `result` (see `MedianStrip`).
template<class Rule>
void median_strip(const MedianSource& src, const Rule& rule, const OIIO::ROI& strip,
                  ResultPixels& result)
{
    MedianStrip<Rule>(src, rule, strip, result).run();
}

}  // namespace mcdenoise
