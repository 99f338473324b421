// dot_weighted_mean.cpp: the dot-weighted means of runs of pixels, from
// window columns of vectors times values.
#include "walkers/dot_weighted_mean.h"

#include <algorithm>

namespace mcdenoise {

namespace {

/// Values per column: each block value times each vector component, then
/// (unless masked: the mask channels give the weights) the vector alone.
int products_per_column(const SeparableSource& src)
{
    return 3 * src.block().nchannels + (src.masked ? 0 : 3);
}

/// Adds window row `qy` of columns `cols`, weighted by `wy`, to the column
/// sums `sum` (planes `wide` apart, one per product): wy * (n_k * v_c) to
/// plane 3c + k, and (unless masked) wy * n_k to plane 3 per + k. `Per` is
/// the block's value count (0: read from the block).
template<int Per>
void add_row_products_of(const SeparableSource& src, const NormalPlanes& vectors,
                         int qy, Span cols, double wy, double* sum, size_t wide)
{
    const int per = Per ? Per : src.block().nchannels, m = cols.size();
    const float* v      = src.block().pixel(cols.begin, qy);
    const NormalRow n   = vectors.from(cols.begin, qy);
    for (int c = 0; c < per; ++c, sum += 3 * wide) {
        double *x = sum, *y = sum + wide, *z = sum + 2 * wide;
        for (int i = 0; i < m; ++i) {
            const double value = v[i * per + c];
            x[i] += wy * (n.x[i] * value);
            y[i] += wy * (n.y[i] * value);
            z[i] += wy * (n.z[i] * value);
        }
    }
    if (!src.masked) {
        double *x = sum, *y = sum + wide, *z = sum + 2 * wide;
        for (int i = 0; i < m; ++i) {
            x[i] += wy * n.x[i];
            y[i] += wy * n.y[i];
            z[i] += wy * n.z[i];
        }
    }
}

/// `add_row_products_of` for the usual value counts.
void add_row_products(const SeparableSource& src, const NormalPlanes& vectors, int qy,
                      Span cols, double wy, double* sum, size_t wide)
{
    switch (src.block().nchannels) {
    case 3: return add_row_products_of<3>(src, vectors, qy, cols, wy, sum, wide);
    case 4: return add_row_products_of<4>(src, vectors, qy, cols, wy, sum, wide);
    default: return add_row_products_of<0>(src, vectors, qy, cols, wy, sum, wide);
    }
}

/// sum[i] = sum of k[d] * column[i + d] over the taps d in order, for the
/// `n` values of one plane (two taps per pass: the same sums, fewer stores).
void add_row_taps(const std::vector<float>& k, const double* column, int n, double* sum)
{
    const int taps = int(k.size());
    int d          = 0;
    for (; d + 1 < taps; d += 2) {
        const double wa = k[size_t(d)], wb = k[size_t(d + 1)];
        const double *a = column + d, *b = column + d + 1;
        for (int i = 0; i < n; ++i)
            sum[i] = (sum[i] + wa * a[i]) + wb * b[i];
    }
    if (d < taps) {
        const double w = k[size_t(d)];
        const double* a = column + d;
        for (int i = 0; i < n; ++i)
            sum[i] += w * a[i];
    }
}

/// n . (the three values at m, `step` apart).
double dot(const UnitNormal& n, const double* m, size_t step)
{
    return double(n.x) * m[0] + double(n.y) * m[step] + double(n.z) * m[2 * step];
}

/// The most pixels summed at once: their window columns stay in the L1
/// cache.
constexpr int pixels_per_pass = 64;

/// `dot_weighted_means` for at most `pixels_per_pass` pixels.
int dot_weighted_pass(const SeparableSource& src, const NormalPlanes& vectors, int xb,
                      int xe, int y, const uint8_t* chosen, DotScratch& scratch, float* out,
                      std::ptrdiff_t stride)
{
    const Kernel1D& k = src.kernel;
    const int r = k.radius, nc = src.nchannels, per = src.block().nchannels;
    const int P = products_per_column(src), n = xe - xb;
    const OIIO::ROI& reg = src.block().region;
    // Planes of columns xb - r .. xe + r; those outside the block stay 0,
    // which adds exact zeros where a window is clipped.
    const Span inside { std::max(reg.xbegin, xb - r), std::min(reg.xend, xe + r) };
    const size_t wide = size_t(n + 2 * r);
    scratch.columns.assign(wide * P, 0.0);
    scratch.window.assign(size_t(n) * P, 0.0);
    double* columns = scratch.columns.data();
    double* window  = scratch.window.data();
    const Span ys   = clip_window(y, r, reg.ybegin, reg.yend);
    for (int qy = ys.begin; qy < ys.end; ++qy)
        add_row_products(src, vectors, qy, inside, k.weights[size_t(qy - y + r)],
                         columns + (inside.begin - (xb - r)), wide);
    for (int j = 0; j < P; ++j)
        add_row_taps(k.weights, columns + j * wide, n, window + size_t(j) * n);
    int empty = 0;
    for (int i = 0; i < n; ++i) {
        if (!chosen[i])
            continue;
        const UnitNormal v  = vectors.at(xb + i, y);
        const double* sums  = window + i;
        float* o            = out + std::ptrdiff_t(i) * stride;
        for (int c = 0; c < nc; ++c) {
            const double num = dot(v, sums + size_t(3 * c) * n, size_t(n));
            const double den = dot(v, sums + size_t(3 * (src.masked ? nc + c : per)) * n, size_t(n));
            o[c]             = masked_mean(num, den, empty);
        }
    }
    return empty;
}

}  // namespace

int dot_weighted_means(const SeparableSource& src, const NormalPlanes& vectors,
                       int xb, int xe, int y, const uint8_t* chosen, DotScratch& scratch,
                       float* out, std::ptrdiff_t stride)
{
    int empty = 0;
    for (int x = xb; x < xe; x += pixels_per_pass)
        empty += dot_weighted_pass(src, vectors, x, std::min(xe, x + pixels_per_pass), y,
                                   chosen + (x - xb), scratch,
                                   out + std::ptrdiff_t(x - xb) * stride, stride);
    return empty;
}

}  // namespace mcdenoise
