// guided_strip.h: the guided weighted-mean walker over one strip, row by
// row in named steps: which pixels the row filters, the fast pixels from
// the separable sums, the smooth ones from dot-weighted sums, and the rest
// window by window (guided_mean.h).
#pragma once

#include "core/operation.h"
#include "walkers/guided_mean.h"

#include <cstring>
#include <type_traits>
#include <vector>

namespace mcdenoise {

/// The index of the first byte equal to `value` in [from, n) of `bytes`,
/// or n (a SIMD scan: memchr).
inline int next_byte(const uint8_t* bytes, int from, int n, uint8_t value)
{
    const void* p = from < n ? std::memchr(bytes + from, value, size_t(n - from)) : nullptr;
    return p ? int(static_cast<const uint8_t*>(p) - bytes) : n;
}

/// The end of the fast segment that starts at the uniform pixel `first` of
/// a row's `uniform` flags (n of them): one past its last uniform pixel,
/// where the next uniform pixel lies more than `gap` pixels beyond it.
inline int fast_segment_end(const uint8_t* uniform, int first, int n, int gap)
{
    int end = first + 1;
    while (end < n) {
        const int hole = next_byte(uniform, end, n, 0);
        const int next = next_byte(uniform, hole, n, 1);
        if (next == n || next - (hole - 1) > gap)
            return hole;
        end = next + 1;
    }
    return end;
}

/// True for a rule whose guide weight is, on some windows, the dot product
/// of the center's and the neighbour's vectors: it provides
/// `smooth_row(y, xs, out)` (1 where (x, y)'s window is one of them) and
/// `dot_vectors()` (the plane of those vectors).
template<class Rule, class = void>
struct has_dot_weights : std::false_type {};
template<class Rule>
struct has_dot_weights<Rule, std::void_t<decltype(&Rule::smooth_row)>> : std::true_type {};

/// Fast pixels closer together than this are summed in one segment of the
/// separable path: each new segment sums the window's reach (2 r columns)
/// again, so a gap up to that reach (and `segment_slack` pixels more) costs
/// less to sum through than to restart after.
inline int fast_segment_gap(int radius)
{
    constexpr int segment_slack = 16;
    return 2 * radius + segment_slack;
}

/// The guided weighted mean over the rows of one strip. Pixels whose
/// windows `rule.uniform_row` marks wholly viable with weight 1 come from
/// the separable fast path; the others, where the rule has dot weights and
/// the window is smooth, from `dot_weighted_means`; the rest from
/// `guided_mean_run`, in runs of equal `rule.key(x, y)` (a value whose
/// equality implies equal guide weights), or from `guided_mean_lanes` where
/// consecutive pixels each have their own key (the results are the same
/// either way).
template<class Rule>
class GuidedMeanStrip {
public:
    GuidedMeanStrip(const SeparableSource& src, const Rule& rule, const OIIO::ROI& strip,
                    ResultPixels& result)
        : m_src(src), m_rule(rule), m_strip(strip), m_result(result), m_width(strip.width()),
          m_gap(fast_segment_gap(src.kernel.radius)), m_fast(src, strip),
          m_fast_empty(size_t(m_width)), m_uniform(size_t(m_width)),
          m_chosen(size_t(m_width), 1), m_done(size_t(m_width)),
          m_scratch(m_width + 2 * src.kernel.radius, src.block().nchannels),
          m_lanes(m_width, src.block().nchannels),
          m_smooth(has_dot_weights<Rule>::value ? size_t(m_width) : 0)
    {
    }

    /// Adds the strip's empty windows to the result's count.
    ~GuidedMeanStrip() { m_result.empty_windows += m_empty; }

    /// Filters every pixel of row y; the fast pixels' segments are written
    /// straight into the result (the other pixels in them are overwritten
    /// after).
    void every_pixel(int y)
    {
        mark_fast_pixels(y);
        float* out = out_row(y);
        const std::ptrdiff_t stride = m_result.pixel_stride();
        for_each_fast_segment([&](Span segment, int) {
            return m_fast.row(y, segment, out, stride, m_fast_empty.data());
        });
        filter_slow_pixels(y);
    }

    /// Filters the pixels (x, y) of row y that `select(y, xs, out)` marks
    /// (out[x - xs.begin] = 1); the others are left alone. Rows with no such
    /// pixel are skipped.
    template<class Select>
    void chosen_pixels(int y, Select&& select)
    {
        select(y, Span { m_strip.xbegin, m_strip.xend }, m_chosen.data());
        if (next_byte(m_chosen.data(), 0, m_width, 1) == m_width)
            return;
        mark_fast_pixels(y);
        const int nc = m_src.nchannels;
        m_fast_row.resize(size_t(m_width) * nc);
        float* out = out_row(y);
        const std::ptrdiff_t stride = m_result.pixel_stride();
        for_each_fast_segment([&](Span segment, int first) {
            const int64_t empty
                = m_fast.row(y, segment, m_fast_row.data(), nc, m_fast_empty.data());
            for (int i = first; i < first + segment.size(); ++i)
                if (m_uniform[size_t(i)])
                    std::copy_n(m_fast_row.data() + size_t(i) * nc, nc,
                                out + std::ptrdiff_t(i) * stride);
            return empty;
        });
        filter_slow_pixels(y);
    }

private:
    float* out_row(int y) const { return m_result.pixel(m_strip.xbegin, y); }

    /// Marks the chosen pixels of row y whose windows are uniform (fast) and
    /// those done once they are written: fast or not chosen.
    void mark_fast_pixels(int y)
    {
        // Local pointers: byte stores may alias any member, which would
        // otherwise be read again on every pixel.
        uint8_t* uniform      = m_uniform.data();
        const uint8_t* chosen = m_chosen.data();
        uint8_t* done         = m_done.data();
        const int n           = m_width;
        m_rule.uniform_row(y, Span { m_strip.xbegin, m_strip.xend }, uniform);
        for (int i = 0; i < n; ++i) {
            uniform[i] &= chosen[i];
            done[i] = uniform[i] | !chosen[i];
        }
    }

    /// Calls `write(segment, first)` for the segments of the row's fast
    /// pixels (`first`: the segment's first column from the strip's start):
    /// a gap wider than `m_gap` starts a new segment. `write` returns the
    /// segment's empty windows and leaves each pixel's count in
    /// `m_fast_empty`: those of the fast pixels count.
    template<class Write>
    void for_each_fast_segment(Write&& write)
    {
        const uint8_t* fast  = m_uniform.data();
        const uint8_t* empty = m_fast_empty.data();
        const int n          = m_width;
        for (int first = next_byte(fast, 0, n, 1); first < n;) {
            const int end = fast_segment_end(fast, first, n, m_gap);
            const Span segment { m_strip.xbegin + first, m_strip.xbegin + end };
            if (write(segment, first))
                for (int i = first; i < end; ++i)
                    m_empty += fast[i] ? empty[i] : 0;
            first = next_byte(fast, end, n, 1);
        }
    }

    /// The pixels of row y not done by the fast path: smooth windows by dot
    /// weights (for rules that have them), then the rest.
    void filter_slow_pixels(int y)
    {
        if constexpr (has_dot_weights<Rule>::value)
            filter_smooth_pixels(y);
        filter_remaining_pixels(y);
    }

    /// The pixels of row y not yet done whose windows the rule marks smooth,
    /// in segments (as the fast ones) by `dot_weighted_means`.
    void filter_smooth_pixels(int y)
    {
        uint8_t* smooth = m_smooth.data();  // local pointers, as in mark_fast_pixels
        uint8_t* done   = m_done.data();
        const int n     = m_width;
        m_rule.smooth_row(y, Span { m_strip.xbegin, m_strip.xend }, smooth);
        for (int i = 0; i < n; ++i)
            smooth[i] &= !done[i];
        const std::ptrdiff_t stride = m_result.pixel_stride();
        float* out = out_row(y);
        for (int first = next_byte(smooth, 0, n, 1); first < n;) {
            const int end = fast_segment_end(smooth, first, n, m_gap);
            m_empty += dot_weighted_means(m_src, m_rule.dot_vectors(), m_strip.xbegin + first,
                                          m_strip.xbegin + end, y, smooth + first, m_dot_scratch,
                                          out + std::ptrdiff_t(first) * stride, stride);
            first = next_byte(smooth, end, n, 1);
        }
        for (int i = 0; i < n; ++i)
            done[i] |= smooth[i];
    }

    /// One past the last pixel of the run of not-done pixels from strip
    /// column i that share pixel i's center key.
    int key_run_end(int i, int y) const
    {
        const int x = m_strip.xbegin, n = m_width;
        const uint8_t* done = m_done.data();
        int end = i + 1;
        while (end < n && !done[end] && m_rule.key(x + end, y) == m_rule.key(x + i, y))
            ++end;
        return end;
    }

    /// True when the run [i, end) is one pixel whose window lies inside the
    /// block's columns (such pixels are summed together by lanes).
    bool lone(int i, int end) const
    {
        const int x = m_strip.xbegin + i, r = m_src.kernel.radius;
        const OIIO::ROI& reg = m_src.block().region;
        return end == i + 1 && x - r >= reg.xbegin && x + r < reg.xend;
    }

    /// The pixels of row y still not done (few away from guide edges): in
    /// runs of one center key by `guided_mean_run`; consecutive lone pixels
    /// together by `guided_mean_lanes`.
    void filter_remaining_pixels(int y)
    {
        const std::ptrdiff_t stride = m_result.pixel_stride();
        const uint8_t* done = m_done.data();
        float* row = out_row(y);
        for (int i = next_byte(done, 0, m_width, 0); i < m_width;) {
            int end    = key_run_end(i, y);
            float* out = row + std::ptrdiff_t(i) * stride;
            const int xb = m_strip.xbegin + i;
            if (lone(i, end)) {
                while (end < m_width && !done[end] && lone(end, key_run_end(end, y)))
                    ++end;
                m_empty += guided_mean_lanes(m_src, m_rule, xb, m_strip.xbegin + end, y, m_lanes,
                                             out, stride);
            } else {
                m_empty += guided_mean_run(m_src, m_rule, xb, m_strip.xbegin + end, y, m_scratch,
                                           out, stride);
            }
            i = next_byte(done, end, m_width, 0);
        }
    }

    const SeparableSource& m_src;
    const Rule& m_rule;
    const OIIO::ROI& m_strip;
    ResultPixels& m_result;
    const int m_width;  // the strip's columns
    const int m_gap;    // see fast_segment_gap
    SeparableMeanRows m_fast;
    std::vector<float> m_fast_row;       // a row of fast means, for chosen pixels
    std::vector<uint8_t> m_fast_empty;   // per pixel, its fast window's empty channels
    std::vector<uint8_t> m_uniform;      // 1: chosen and fast
    std::vector<uint8_t> m_chosen;       // 1: filtered in this row
    std::vector<uint8_t> m_done;         // 1: written, or not chosen
    GuidedScratch m_scratch;
    LaneScratch m_lanes;
    std::vector<uint8_t> m_smooth;       // 1: by dot weights
    DotScratch m_dot_scratch;
    int64_t m_empty = 0;
};

/// The guided weighted mean of every pixel of `strip` into `result` (see
/// `GuidedMeanStrip`).
template<class Rule>
void guided_mean_strip(const SeparableSource& src, const Rule& rule, const OIIO::ROI& strip,
                       ResultPixels& result)
{
    GuidedMeanStrip<Rule> walker(src, rule, strip, result);
    for (int y = strip.ybegin; y < strip.yend; ++y)
        walker.every_pixel(y);
}

/// The guided weighted mean of the pixels of `strip` that `select` picks
/// (`select(y, xs, out)` sets out[x - xs.begin] to 1 for the pixels (x, y)
/// to filter, 0 for the others) into `result`; the others are left alone.
template<class Rule, class Select>
void guided_mean_chosen(const SeparableSource& src, const Rule& rule, Select&& select,
                        const OIIO::ROI& strip, ResultPixels& result)
{
    GuidedMeanStrip<Rule> walker(src, rule, strip, result);
    for (int y = strip.ybegin; y < strip.yend; ++y)
        walker.chosen_pixels(y, select);
}

}  // namespace mcdenoise
