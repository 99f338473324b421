// median_kernel.h: the one median kernel every median filter shares: a
// pruned selection network run on eight windows at once (SIMD lanes) for
// full windows of finite values, and in-place selection for everything else.
#pragma once

#include <OpenImageIO/simd.h>

#include <vector>

namespace mcdenoise {

/// The median of `values[0 .. n)` (n >= 1): the middle value for odd n, the
/// mean of the two middle values for even n. Reorders `values`.
float median_in_place(float* values, int n);

/// A comparator network that leaves the median of `count` inputs in one slot:
/// Batcher's odd-even merge sort padded to a power of two, the padding
/// resolved symbolically (it holds +inf), then pruned back from the median
/// so only the comparators (or their min or max half) that reach it remain.
class MedianNetwork {
public:
    /// The network for an odd `count` of inputs, built once and cached.
    /// Returns nullptr for an even count or one above `max_count`.
    static const MedianNetwork* for_count(int count);

    /// The largest input count served by a network (a 9 x 9 window).
    static constexpr int max_count = 81;

    /// Slots `run` uses: the inputs in 0 .. count-1, plus scratch.
    int slots() const { return m_count + 1; }
    /// The slot that holds the median after `run`.
    int result_slot() const { return m_result; }
    /// Comparators in the pruned network.
    size_t size() const { return m_ops.size(); }

    /// Run the network over `v[0 .. slots())`, one window per SIMD lane.
    void run(OIIO::simd::vfloat8* v) const
    {
        for (const Op& op : m_ops) {
            const OIIO::simd::vfloat8 a = v[op.in_lo], b = v[op.in_hi];
            v[op.out_min] = OIIO::simd::min(a, b);
            v[op.out_max] = OIIO::simd::max(a, b);
        }
    }

private:
    explicit MedianNetwork(int count);

    struct Op {
        int in_lo, in_hi;    // slots compared
        int out_min, out_max;  // where min and max go (scratch if unused)
    };
    int m_count  = 0;
    int m_result = 0;
    std::vector<Op> m_ops;
};

}  // namespace mcdenoise
