// weighted_sums.cpp: masked weighted sums over pixel runs.
#include "features/weighted_sums.h"

#include "core/window.h"


#include <algorithm>

namespace mcdenoise {

SumSource sum_source(const PixelBlock& block, int chbegin, int chend, const OIIO::ROI& region,
                     int nthreads)
{
    const int nc = chend - chbegin;
    SumSource src(region, nc);
    // Row y's masked values, with their weights into the finite mask when
    // `with_mask`; true if some value of the row is not finite.
    const auto masked_row = [&](int y, bool with_mask) {
        const float* in = block.pixel(region.xbegin, y) + chbegin;
        bool any        = false;
        for (int c = 0; c < nc; ++c)
            any |= masked_values(in + c, block.nchannels, region.width(), src.row(c, y),
                                 with_mask ? src.finite_row(c, y) : nullptr, 1);
        return any;
    };
    std::vector<uint8_t> row_has_nonfinite(size_t(region.height()));
    parallel_rows(region, nthreads, [&](int y) {
        row_has_nonfinite[size_t(y - region.ybegin)] = masked_row(y, false);
    });
    if (std::find(row_has_nonfinite.begin(), row_has_nonfinite.end(), uint8_t(1))
        == row_has_nonfinite.end())
        return src;
    // The finite mask only when some value is not finite: an image of
    // finite values (the usual case) allocates and writes no mask planes.
    src.finite = Planes<float>(region, nc).values;
    parallel_rows(region, nthreads, [&](int y) { masked_row(y, true); });
    return src;
}

WeightedSums::WeightedSums(int chbegin, int chend, int n, bool masked)
    : m_c0(chbegin)
    , m_nc(chend - chbegin)
    , m_n(n)
    , m_stride((n + 7) / 8 * 8)
    , m_masked(masked)
    , m_num(size_t(m_nc) * size_t(m_stride), 0.0f)
    , m_den(size_t(masked ? m_nc : 1) * size_t(m_stride), 0.0f)
{
}

void WeightedSums::add(const float* w, const SumSource& src, int qx0, int qy, int i0, int i1)
{
    if (i0 >= i1)
        return;
    // Pointers start at i0: the neighbours of i < i0 may lie left of the
    // source region.
    const int qx    = qx0 + i0;
    const int n     = i1 - i0;
    const float* wi = w + i0;
    for (int c = 0; c < m_nc; ++c) {
        const float* v = src.from(m_c0 + c, qx, qy);
        float* num     = m_num.data() + size_t(c) * m_stride + i0;
        for (int i = 0; i < n; ++i)
            num[i] += wi[i] * v[i];
        if (m_masked) {
            const float* m = src.finite_from(m_c0 + c, qx, qy);
            float* den     = m_den.data() + size_t(c) * m_stride + i0;
            for (int i = 0; i < n; ++i)
                den[i] += wi[i] * m[i];
        }
    }
    if (!m_masked)
        for (int i = i0; i < i1; ++i)
            m_den[size_t(i)] += w[i];
}

// The loops over a group's sums run unrolled, so the sums stay in registers.
#if defined(__GNUC__) && !defined(__clang__)
#    define MCD_UNROLL_GROUP _Pragma("GCC unroll 16")
#else
#    define MCD_UNROLL_GROUP
#endif

namespace {

/// The most sums `add_rows` holds in registers at once (with the weight
/// sum, the weights and a value: within AVX2's sixteen).
constexpr size_t max_group = 11;

/// Eight lanes holding `count` values from `p` from lane `first` on, 0 in
/// the others.
OIIO::simd::vfloat8 lanes_from(const float* p, int first, int count)
{
    float padded[OIIO::simd::vfloat8::elements] = {};
    std::copy_n(p, count, padded + first);
    return OIIO::simd::vfloat8(padded);
}

}  // namespace

template<int G, bool Weights>
void WeightedSums::add_rows_group(const WeightRow* rows, int count, const SumSource& src,
                                  const Target* targets, float* weight_sum) const
{
    using OIIO::simd::vfloat8;
    constexpr int lanes = vfloat8::elements;
    // Every row reads source row qy: target g's value for row k at pixel i
    // is row[g][rows[k].qx0 - xbegin + i].
    const int qy = rows[0].qy, xbegin = src.region.xbegin;
    const float* row[G];
    MCD_UNROLL_GROUP
    for (int g = 0; g < G; ++g) {
        const int c = m_c0 + targets[g].channel;
        row[g]      = targets[g].mask ? src.finite_from(c, xbegin, qy) : src.from(c, xbegin, qy);
    }
    // The pixels every row covers.
    int lo = 0, hi = m_n;
    for (int k = 0; k < count; ++k) {
        lo = std::max(lo, rows[k].i0);
        hi = std::min(hi, rows[k].i1);
    }
    for (int i = 0; i < m_n; i += lanes) {
        if (i < lo || i + lanes > hi) {
            add_rows_block<G, Weights>(rows, count, row, xbegin, i, targets, weight_sum);
            continue;
        }
        vfloat8 acc[G];
        MCD_UNROLL_GROUP
        for (int g = 0; g < G; ++g)
            acc[g] = vfloat8(targets[g].sum + i);
        vfloat8 weights = Weights ? vfloat8(weight_sum + i) : vfloat8(0.0f);
        for (int k = 0; k < count; ++k) {
            const vfloat8 w(rows[k].w + i);
            const int x = rows[k].qx0 - xbegin + i;
            MCD_UNROLL_GROUP
            for (int g = 0; g < G; ++g)
                acc[g] = acc[g] + w * vfloat8(row[g] + x);
            if (Weights)
                weights = weights + w;
        }
        MCD_UNROLL_GROUP
        for (int g = 0; g < G; ++g)
            acc[g].store(targets[g].sum + i);
        if (Weights)
            weights.store(weight_sum + i);
    }
}

template<int G, bool Weights>
void WeightedSums::add_rows_block(const WeightRow* rows, int count, const float* const* row,
                                  int xbegin, int i, const Target* targets,
                                  float* weight_sum) const
{
    using OIIO::simd::vfloat8;
    constexpr int lanes = vfloat8::elements;
    for (int k = 0; k < count; ++k) {
        // Lanes [a, b) alone: the others take 0 * 0, which leaves a sum as
        // it is.
        const WeightRow& r = rows[k];
        const int a = std::max(i, r.i0), b = std::min(i + lanes, r.i1);
        if (a >= b)
            continue;
        const int x     = r.qx0 - xbegin;
        const vfloat8 w = lanes_from(r.w + a, a - i, b - a);
        for (int g = 0; g < G; ++g)
            (vfloat8(targets[g].sum + i) + w * lanes_from(row[g] + x + a, a - i, b - a))
                .store(targets[g].sum + i);
        if (Weights)
            (vfloat8(weight_sum + i) + w).store(weight_sum + i);
    }
}

void WeightedSums::add_rows(const WeightRow* rows, int count, const SumSource& src)
{
    // Runs of rows on one source row at a time.
    int run = 1;
    while (run < count && rows[run].qy == rows[0].qy)
        ++run;
    if (run < count) {
        add_rows(rows, run, src);
        add_rows(rows + run, count - run, src);
        return;
    }
    if (count <= 0)
        return;
    std::vector<Target> targets;
    for (int c = 0; c < m_nc; ++c)
        targets.push_back({ m_num.data() + size_t(c) * m_stride, c, false });
    if (m_masked)
        for (int c = 0; c < m_nc; ++c)
            targets.push_back({ m_den.data() + size_t(c) * m_stride, c, true });
    // The sums in as few groups as fit the registers, of sizes as even as
    // can be (each group pass has its own overhead per row); the first also
    // sums the weights alone (the denominator without a finite mask).
    const size_t ngroups = (targets.size() + max_group - 1) / max_group;
    size_t t             = 0;
    for (size_t k = 0; k < ngroups; ++k) {
        const size_t size = (targets.size() - t) / (ngroups - k);
        const Target* g   = targets.data() + t;
        float* den        = t == 0 && !m_masked ? m_den.data() : nullptr;
        t += size;
        switch (size) {
        case 1: add_group<1>(rows, count, src, g, den); break;
        case 2: add_group<2>(rows, count, src, g, den); break;
        case 3: add_group<3>(rows, count, src, g, den); break;
        case 4: add_group<4>(rows, count, src, g, den); break;
        case 5: add_group<5>(rows, count, src, g, den); break;
        case 6: add_group<6>(rows, count, src, g, den); break;
        case 7: add_group<7>(rows, count, src, g, den); break;
        case 8: add_group<8>(rows, count, src, g, den); break;
        case 9: add_group<9>(rows, count, src, g, den); break;
        case 10: add_group<10>(rows, count, src, g, den); break;
        default: add_group<max_group>(rows, count, src, g, den); break;
        }
    }
}

template<int G>
void WeightedSums::add_group(const WeightRow* rows, int count, const SumSource& src,
                             const Target* targets, float* weight_sum) const
{
    if (weight_sum)
        add_rows_group<G, true>(rows, count, src, targets, weight_sum);
    else
        add_rows_group<G, false>(rows, count, src, targets, nullptr);
}

template<class Store>
int64_t WeightedSums::write_each(int c0, int c1, Store&& store) const
{
    int64_t empty = 0;
    for (int c = c0; c < c1; ++c) {
        const float* num = m_num.data() + size_t(c) * m_stride;
        const float* den = m_den.data() + (m_masked ? size_t(c) * m_stride : 0);
        for (int i = 0; i < m_n; ++i)
            store(c, i, masked_mean(num[i], den[i], empty));
    }
    return empty;
}

int64_t WeightedSums::write(float* out, std::ptrdiff_t stride) const
{
    return write(out, stride, m_c0, m_c0 + m_nc);
}

int64_t WeightedSums::write(float* out, std::ptrdiff_t stride, int chbegin, int chend) const
{
    const int c0 = chbegin - m_c0;
    return write_each(c0, chend - m_c0,
                      [=](int c, int i, float v) { out[i * stride + c - c0] = v; });
}

int64_t WeightedSums::write_planes(float* const* out) const
{
    return write_each(0, m_nc, [=](int c, int i, float v) { out[c][i] = v; });
}

}  // namespace mcdenoise
