// weighted_sums.h: the accumulation every feature-guided filter ends with:
// per channel, the sum of weight times finite value and of the weights that
// contributed, over runs of pixels in contiguous float rows, and the
// weights themselves from exponent rows.
#pragma once

#include "core/pixel_block.h"
#include "core/plane.h"

#include <OpenImageIO/fmath.h>
#include <OpenImageIO/simd.h>

#include <algorithm>
#include <type_traits>

#if defined(__SSE__)
#    include <xmmintrin.h>
#endif

#include <cstdint>
#include <vector>

namespace mcdenoise {

/// The values the sums read, as channel planes: the masked values
/// (`masked_values`): each value as a sum takes it (non-finite ones as 0,
/// huge ones clamped) and, when any is non-finite, their weights as the
/// finite mask.
using SumSource = Planes<float>;

/// Channels [chbegin, chend) of `block` (whose channels start at 0) over
/// `region` (inside the block) as a `SumSource`.
SumSource sum_source(const PixelBlock& block, int chbegin, int chend, const OIIO::ROI& region,
                     int nthreads);

/// One row of weights for `WeightedSums::add_rows`: `w[i]`, i in [i0, i1),
/// the weight of the value at (qx0 + i, qy) for pixel i of the run.
struct WeightRow {
    const float* w;
    int qx0, qy, i0, i1;
};

/// Per-channel weighted sums for a run of `n` pixels, over channels
/// [chbegin, chend) of the `SumSource`s they are given.
class WeightedSums {
public:
    WeightedSums(int chbegin, int chend, int n, bool masked);

    /// For each i in [i0, i1): add `w[i]` times the value of `src` at
    /// (qx0 + i, qy) to pixel i's sums (finite values only).
    void add(const float* w, const SumSource& src, int qx0, int qy, int i0, int i1);

    /// `add` of each of `rows[0, count)` in turn, in one pass over the sums
    /// (eight pixels and up to eight channels held in registers while every
    /// row goes by): each sum takes the same terms in the same order as
    /// from `add`, so the result is the same, with far less memory traffic
    /// when there are many channels.
    void add_rows(const WeightRow* rows, int count, const SumSource& src);

    /// Pixel i's channel chbegin + c: the weighted mean, or 0 when no weight
    /// contributed. Returns the count of such empty channels over the run,
    /// writing `out[i * stride + c]`.
    int64_t write(float* out, std::ptrdiff_t stride) const;

    /// `write` of channels [chbegin, chend) alone (absolute channel
    /// numbers, inside this object's), `out[i * stride + c - chbegin]`.
    int64_t write(float* out, std::ptrdiff_t stride, int chbegin, int chend) const;

    /// The weighted means of channel c into `out[c][i]`; returns the count
    /// of empty channels, as `write`.
    int64_t write_planes(float* const* out) const;

private:
    // Calls store(c, i, mean) for every channel c in [c0, c1) (counted
    // from chbegin) and pixel i.
    template<class Store>
    int64_t write_each(int c0, int c1, Store&& store) const;

    // One sum plane of `add_rows`: where it goes, and the plane it takes
    // `w * value` from (`channel` of the values, or of the finite mask).
    struct Target {
        float* sum;
        int channel;
        bool mask;
    };
    // `add_rows` for G targets at once and, when `weight_sum` is given, the
    // weights alone into it.
    template<int G>
    void add_group(const WeightRow* rows, int count, const SumSource& src,
                   const Target* targets, float* weight_sum) const;
    template<int G, bool Weights>
    void add_rows_group(const WeightRow* rows, int count, const SumSource& src,
                        const Target* targets, float* weight_sum) const;
    // The eight pixels from i of `add_rows_group`, where some row does not
    // cover them all; `row[g]` is target g's source row from xbegin.
    template<int G, bool Weights>
    void add_rows_block(const WeightRow* rows, int count, const float* const* row, int xbegin,
                        int i, const Target* targets, float* weight_sum) const;

    int m_c0, m_nc, m_n;
    int m_stride;  // floats per channel in m_num and m_den: m_n padded to 8
    bool m_masked;
    std::vector<float> m_num;  // channel-major, m_stride per channel
    std::vector<float> m_den;  // per channel when masked, else one run
};

/// While alive, the calling thread flushes denormal floats to zero (FTZ and
/// DAZ): far neighbours' weights, and their squares, fall below float's
/// normal range, and arithmetic on denormals is ~100 times slower. Every
/// worker of a filter sets it, so results stay the same on any thread.
class FlushDenormals {
public:
#if defined(__SSE__)
    FlushDenormals()
        : m_saved(_mm_getcsr())
    {
        _mm_setcsr(m_saved | flush_bits);
    }
    ~FlushDenormals() { _mm_setcsr(m_saved); }

private:
    static constexpr unsigned flush_bits = 0x8040;  // FTZ | DAZ
    unsigned m_saved;
#endif
};

/// Columns filtered together: a run short enough that the rows every tap
/// reads stay in cache while all the taps go by.
constexpr int segment_width = 256;

/// Call `fn(x0, n)` for consecutive runs [x0, x0 + n) of at most
/// `segment_width` columns covering [xbegin, xend).
template<class Fn>
void for_each_segment(int xbegin, int xend, Fn&& fn)
{
    for (int x0 = xbegin; x0 < xend; x0 += segment_width)
        fn(x0, xend - x0 < segment_width ? xend - x0 : segment_width);
}

/// Past this exponent a float exp underflows to denormals: the weight is 0.
constexpr float max_weight_exponent = 87.0f;

/// Eight floats (or 32-bit ints) from `p`, the first `count` of them read
/// and the rest 0. A partial block goes through a local copy (OIIO's own
/// partial loads read whole doubles at float alignment).
template<class T>
inline auto load_lanes(const T* p, int count)
{
    using Lanes = std::conditional_t<std::is_same_v<T, float>, OIIO::simd::vfloat8,
                                     OIIO::simd::vint8>;
    if (count == Lanes::elements)
        return Lanes(p);
    T padded[Lanes::elements] = {};
    std::copy_n(p, count, padded);
    return Lanes(padded);
}

/// The first `count` lanes of `v` into `p`.
inline void store_lanes(const OIIO::simd::vfloat8& v, float* p, int count)
{
    if (count == OIIO::simd::vfloat8::elements) {
        v.store(p);
        return;
    }
    float all[OIIO::simd::vfloat8::elements];
    v.store(all);
    std::copy_n(all, count, p);
}

/// `scale * exp(-e)` lane by lane, 0 past `max_weight_exponent` (OIIO's
/// fast_exp: at most 230 ulp from exp).
inline OIIO::simd::vfloat8 weight_lanes(const OIIO::simd::vfloat8& e,
                                        const OIIO::simd::vfloat8& scale)
{
    using OIIO::simd::vfloat8;
    return OIIO::simd::select(e < vfloat8(max_weight_exponent), scale * OIIO::fast_exp(-e),
                              vfloat8(0.0f));
}

/// Run `lanes(i, load)` for i = 0, 8, 16 ... < n, where `load(ptr)` reads
/// the eight values ptr[i ..] (only those below n on the last block,
/// padding with 0), and store each result at out + i (in part on the last
/// block). Every pixel goes through the same lane-wise arithmetic, so a
/// result never depends on where its run starts.
template<class Lanes>
void for_each_lane_block(int n, float* out, Lanes&& lanes)
{
    using OIIO::simd::vfloat8;
    constexpr int width = vfloat8::elements;
    int i = 0;
    for (; i + width <= n; i += width)
        lanes(i, [i](const auto* p) { return load_lanes(p + i, width); }).store(out + i);
    if (i < n) {
        const int rest = n - i;
        store_lanes(lanes(i, [i, rest](const auto* p) { return load_lanes(p + i, rest); }),
                    out + i, rest);
    }
}


}  // namespace mcdenoise
