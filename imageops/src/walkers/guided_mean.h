// guided_mean.h: the window sums of the weighted-mean walker
// (guided_strip.h) for the pixels off its fast paths. A filter is a rule:
// which neighbours are viable and with what guide weight. Such pixels are
// summed window column by window column, each column once for a run of
// pixels whose weights depend on one center key (object id), or, where
// every pixel has its own key, for all of a run's pixels at once.
#pragma once

#include "core/window.h"
#include "walkers/dot_weighted_mean.h"
#include "walkers/separable_mean.h"

#include <vector>

namespace mcdenoise {

/// Working memory of `guided_mean_run` for runs of
/// up to `span` columns of `block_channels` values each.
struct GuidedScratch {
    GuidedScratch(int span, int block_channels)
        : guide(size_t(span)), column_weights(size_t(span)),
          spread(size_t(span) * block_channels), sums(size_t(span) * block_channels)
    {
    }
    std::vector<float> guide;             ///< one window row's guide weights
    std::vector<double> column_weights;   ///< whole weights summed per column
    std::vector<double> spread;           ///< one row's whole weights, one per value
    std::vector<double> sums;             ///< weighted sums per column and value
};

/// Adds window row `qy` (columns `cols`, weighted by `wy` times the rule's
/// guide weights for center (px, py)) to the per-column sums of `scratch`:
/// each value weighted in double by loops the compiler vectorises (zero
/// weights add zeros), and the weights to `column_weights`.
template<class Rule>
void add_window_row(const SeparableSource& src, const Rule& rule, int px, int py, int qy,
                    Span cols, double wy, GuidedScratch& scratch)
{
    const PixelBlock& block = src.block();
    const int per = block.nchannels, n = cols.size(), values = n * per;
    float* guide = scratch.guide.data();
    double* spread = scratch.spread.data();
    double* sums   = scratch.sums.data();
    rule.row_weights(px, py, qy, cols, guide);
    if (qy == py && px >= cols.begin && px < cols.end)
        guide[px - cols.begin] = 1.0f;
    for (int i = 0; i < n; ++i) {
        const double w = wy * guide[i];
        scratch.column_weights[size_t(i)] += w;
        std::fill_n(spread + i * per, per, w);
    }
    const float* v = block.pixel(cols.begin, qy);
    for (int j = 0; j < values; ++j)
        sums[j] += spread[j] * v[j];
}

/// Zeroes the per-column sums of `n` columns.
inline void clear_columns(GuidedScratch& scratch, int n, int per)
{
    std::fill_n(scratch.sums.data(), size_t(n) * per, 0.0);
    std::fill_n(scratch.column_weights.data(), size_t(n), 0.0);
}

/// The weighted mean at x from the column sums of `scratch`, which start at
/// column `first`: each column in x's window weighted by the spatial kernel,
/// into `out`. Returns the count of channels with no contribution (set to 0).
inline int mean_from_columns(const SeparableSource& src, int x, int first,
                             const GuidedScratch& scratch, float* out)
{
    const Kernel1D& k = src.kernel;
    const int r = k.radius, nc = src.nchannels, per = src.block().nchannels;
    const OIIO::ROI& reg = src.block().region;
    const Span xs        = clip_window(x, r, reg.xbegin, reg.xend);
    const float* kx      = k.weights.data() + (xs.begin - x + r);
    const double* sums   = scratch.sums.data() + size_t(xs.begin - first) * per;
    const double* cw     = scratch.column_weights.data() + (xs.begin - first);
    double total = 0.0;
    for (int i = 0; i < xs.size(); ++i)
        total += kx[i] * cw[i];
    int empty = 0;
    for (int c = 0; c < nc; ++c) {
        double num = 0.0, den = src.masked ? 0.0 : total;
        for (int i = 0; i < xs.size(); ++i) {
            num += kx[i] * sums[i * per + c];
            if (src.masked)
                den += kx[i] * sums[i * per + nc + c];
        }
        out[c] = masked_mean(num, den, empty);
    }
    return empty;
}

/// The weighted means of the pixels [xb, xe) of row y (written `stride`
/// floats apart from `out`): each pixel's viable finite neighbours weighted
/// by the spatial kernel times the rule's guide weight (the center by its
/// spatial weight alone). `Rule` provides
/// `void row_weights(int px, int py, int qy, Span xs, float* w) const`:
/// the guide weight, 0 where not viable, of each neighbour (qx, qy), qx in
/// `xs`, of center (px, py), into w[qx - xs.begin]. Every pixel of the run
/// must share the center's `rule.key`, so the weights are the same function
/// of the neighbour for all of them (and a pixel of the center's key weighs
/// 1): each window column is then weighted and summed once for the whole
/// run. A pixel's result does not depend on the run it is part of.
/// Returns the count of channels with no contribution (set to 0).
template<class Rule>
int guided_mean_run(const SeparableSource& src, const Rule& rule, int xb, int xe, int y,
                    GuidedScratch& scratch, float* out, std::ptrdiff_t stride)
{
    const Kernel1D& k = src.kernel;
    const int r = k.radius;
    const OIIO::ROI& reg = src.block().region;
    const Span cols { std::max(reg.xbegin, xb - r), std::min(reg.xend, xe + r) };
    const Span ys = clip_window(y, r, reg.ybegin, reg.yend);
    clear_columns(scratch, cols.size(), src.block().nchannels);
    for (int qy = ys.begin; qy < ys.end; ++qy)
        add_window_row(src, rule, xb, y, qy, cols, k.weights[size_t(qy - y + r)], scratch);
    int empty = 0;
    for (int x = xb; x < xe; ++x, out += stride)
        empty += mean_from_columns(src, x, cols.begin, scratch, out);
    return empty;
}

/// Working memory of `guided_mean_lanes` for runs of up to `span` pixels of
/// `block_channels` values each; value arrays are value-major (`span` per
/// value).
struct LaneScratch {
    LaneScratch(int span, int block_channels)
        : guide(size_t(span)), weight(size_t(span)), column_weight(size_t(span)),
          column(size_t(span) * block_channels), total(size_t(span)),
          window(size_t(span) * block_channels)
    {
    }
    std::vector<float> guide;            ///< each pixel's guide weight at one offset
    std::vector<double> weight;          ///< the same times the row's spatial weight
    std::vector<double> column_weight;   ///< each pixel's current window column
    std::vector<double> column;          ///< its weighted values
    std::vector<double> total;           ///< each pixel's window weight
    std::vector<double> window;          ///< its weighted values
};

/// column[j * n + i] += weight[i] * v[i * Per + j] for the `n` pixels of `v`
/// (Per values each; 0: `per`), read in order: with Per known, the compiler
/// vectorises it as interleaved loads.
template<int Per>
void add_weighted_pixels_of(const double* weight, const float* v, int n, int per,
                            double* column)
{
    if constexpr (Per == 0) {
        for (int j = 0; j < per; ++j)
            for (int i = 0; i < n; ++i)
                column[j * n + i] += weight[i] * v[i * per + j];
    } else {
        double* values[Per];
        for (int j = 0; j < Per; ++j)
            values[j] = column + j * n;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < Per; ++j)
                values[j][i] += weight[i] * v[i * Per + j];
    }
}

/// `add_weighted_pixels_of` for the usual value counts.
inline void add_weighted_pixels(const double* weight, const float* v, int n, int per,
                                double* column)
{
    switch (per) {
    case 3: return add_weighted_pixels_of<3>(weight, v, n, per, column);
    case 4: return add_weighted_pixels_of<4>(weight, v, n, per, column);
    case 6: return add_weighted_pixels_of<6>(weight, v, n, per, column);
    default: return add_weighted_pixels_of<0>(weight, v, n, per, column);
    }
}

/// `guided_mean_run`'s means for the pixels [xb, xe) of row y when each may
/// have its own center key (curved surfaces under the normal rule): every
/// pixel's window summed at once, window column by window column, from the
/// guide weights `rule.offset_weights(y, xs, dx, qy, w)` gives for all of
/// them (w[x - xs.begin]: the weight of neighbour (x + dx, qy) of center
/// (x, y)). Each pixel's arithmetic is guided_mean_run's term for term,
/// so its result is bit-identical. Every window must lie inside the block's
/// columns. Returns the count of channels with no contribution.
template<class Rule>
int guided_mean_lanes(const SeparableSource& src, const Rule& rule, int xb, int xe, int y,
                      LaneScratch& s, float* out, std::ptrdiff_t stride)
{
    const Kernel1D& k = src.kernel;
    const int r = k.radius, n = xe - xb, nc = src.nchannels, per = src.block().nchannels;
    const OIIO::ROI& reg = src.block().region;
    const Span ys = clip_window(y, r, reg.ybegin, reg.yend);
    float* guide = s.guide.data();
    double *weight = s.weight.data(), *column_weight = s.column_weight.data();
    double *column = s.column.data(), *total = s.total.data(), *window = s.window.data();
    std::fill_n(total, n, 0.0);
    std::fill_n(window, size_t(n) * per, 0.0);
    for (int dx = -r; dx <= r; ++dx) {
        std::fill_n(column_weight, n, 0.0);
        std::fill_n(column, size_t(n) * per, 0.0);
        for (int qy = ys.begin; qy < ys.end; ++qy) {
            rule.offset_weights(y, Span { xb, xe }, dx, qy, guide);
            if (qy == y && dx == 0)
                std::fill_n(guide, n, 1.0f);
            const double wy = k.weights[size_t(qy - y + r)];
            for (int i = 0; i < n; ++i) {
                weight[i] = wy * guide[i];
                column_weight[i] += weight[i];
            }
            add_weighted_pixels(weight, src.block().pixel(xb + dx, qy), n, per, column);
        }
        const float kx = k.weights[size_t(dx + r)];
        for (int i = 0; i < n; ++i)
            total[i] += kx * column_weight[i];
        for (int j = 0; j < n * per; ++j)
            window[j] += kx * column[j];
    }
    int empty = 0;
    for (int i = 0; i < n; ++i, out += stride)
        for (int c = 0; c < nc; ++c) {
            const double num = window[c * n + i];
            const double den = src.masked ? window[(nc + c) * n + i] : total[i];
            out[c]           = masked_mean(num, den, empty);
        }
    return empty;
}

}  // namespace mcdenoise
