// weighted_sums.cpp: masked weighted sums over pixel runs.
#include "weighted_sums.h"

#include "window.h"


#include <algorithm>
#include <cmath>

namespace mcdenoise {

SumSource sum_source(const PixelBlock& block, int chbegin, int chend, const OIIO::ROI& region,
                     int nthreads)
{
    const int nc = chend - chbegin;
    SumSource src(region, nc);
    std::vector<uint8_t> row_has_nonfinite(size_t(region.height()));
    parallel_rows(region, nthreads, [&](int y) {
        const float* in = block.pixel(region.xbegin, y);
        const size_t at = src.offset(region.xbegin, y);
        bool any        = false;
        for (int i = 0; i < region.width(); ++i, in += block.nchannels)
            for (int c = 0; c < nc; ++c) {
                const float v = in[chbegin + c];
                src.values[size_t(c)][at + i] = summable(v);
                any |= !std::isfinite(v);
            }
        row_has_nonfinite[size_t(y - region.ybegin)] = any;
    });
    if (std::find(row_has_nonfinite.begin(), row_has_nonfinite.end(), uint8_t(1))
        == row_has_nonfinite.end())
        return src;
    // The finite mask only when some value is not finite: an image of
    // finite values (the usual case) allocates and writes no mask planes.
    src.finite = Planes<float>(region, nc).values;
    parallel_rows(region, nthreads, [&](int y) {
        const float* in = block.pixel(region.xbegin, y);
        const size_t at = src.offset(region.xbegin, y);
        for (int i = 0; i < region.width(); ++i, in += block.nchannels)
            for (int c = 0; c < nc; ++c)
                src.finite[size_t(c)][at + i] = std::isfinite(in[chbegin + c]) ? 1.0f : 0.0f;
    });
    return src;
}

WeightedSums::WeightedSums(int chbegin, int chend, int n, bool masked)
    : m_c0(chbegin)
    , m_nc(chend - chbegin)
    , m_n(n)
    , m_masked(masked)
    , m_num(size_t(m_nc) * n, 0.0f)
    , m_den(size_t(masked ? m_nc : 1) * n, 0.0f)
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
        float* num     = m_num.data() + size_t(c) * m_n + i0;
        for (int i = 0; i < n; ++i)
            num[i] += wi[i] * v[i];
        if (m_masked) {
            const float* m = src.finite_from(m_c0 + c, qx, qy);
            float* den     = m_den.data() + size_t(c) * m_n + i0;
            for (int i = 0; i < n; ++i)
                den[i] += wi[i] * m[i];
        }
    }
    if (!m_masked)
        for (int i = i0; i < i1; ++i)
            m_den[size_t(i)] += w[i];
}

template<class Store>
int64_t WeightedSums::write_each(int c0, int c1, Store&& store) const
{
    int64_t empty = 0;
    for (int c = c0; c < c1; ++c) {
        const float* num = m_num.data() + size_t(c) * m_n;
        const float* den = m_den.data() + (m_masked ? size_t(c) * m_n : 0);
        for (int i = 0; i < m_n; ++i) {
            const bool any = den[i] > 0.0f;
            store(c, i, any ? num[i] / den[i] : 0.0f);
            empty += !any;
        }
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
