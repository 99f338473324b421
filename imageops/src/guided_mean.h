// guided_mean.h: the one window walker for weighted-mean filters. A filter
// is a rule: which neighbours are viable and with what guide weight. Pixels
// whose whole window is viable with weight 1 take the separable fast path;
// the others are summed neighbour by neighbour.
#pragma once

#include "separable_mean.h"
#include "window.h"

#include <cstring>
#include <vector>

namespace mcdenoise {

/// Per-pixel working memory of `guided_mean_pixel`.
struct GuidedScratch {
    explicit GuidedScratch(int nchannels)
        : sums(size_t(2 * nchannels)), guide(size_t(max_window_size)),
          weights(size_t(max_window_size))
    {
    }
    std::vector<double> sums;     ///< numerators, then denominators
    std::vector<float> guide;     ///< one window row's guide weights
    std::vector<double> weights;  ///< the same row's whole weights
};

/// Adds one window row of `n` pixels `stride` floats apart, weighted by
/// `w`, to `num` and `den` (per channel when `masked`: the mask values
/// follow the `nc` colour values; else den[0] for all). `NC` is `nc` when
/// known at compile time (0: read `nc`). Zero weights add zeros, which
/// keeps the loop free of branches.
template<int NC>
void add_window_row(const float* v, int stride, const double* w, int n, int nc, bool masked,
                    double* num, double* den)
{
    if constexpr (NC == 0) {
        for (int i = 0; i < n; ++i, v += stride) {
            for (int c = 0; c < nc; ++c) {
                num[c] += w[i] * v[c];
                if (masked)
                    den[c] += w[i] * v[nc + c];
            }
            if (!masked)
                den[0] += w[i];
        }
    } else {
        // Register accumulators: stores through `num` would chain every add.
        double sum[NC] = {}, weight[NC] = {};
        for (int i = 0; i < n; ++i, v += stride)
            for (int c = 0; c < NC; ++c) {
                sum[c] += w[i] * v[c];
                weight[c] += w[i] * (masked ? v[NC + c] : 1.0f);
            }
        for (int c = 0; c < NC; ++c) {
            num[c] += sum[c];
            den[masked ? c : 0] += masked ? weight[c] : (c == 0 ? weight[0] : 0.0);
        }
    }
}

/// The weighted mean of pixel (x, y)'s viable finite neighbours, each
/// weighted by the spatial kernel times the rule's guide weight (the center
/// by its spatial weight alone), into `out`. `Rule` provides
/// `void row_weights(int px, int py, int qy, Span xs, float* w) const`:
/// the guide weight, 0 where not viable, of each neighbour (qx, qy), qx in
/// `xs`, of center (px, py), into w[qx - xs.begin].
/// Returns the count of channels with no contribution (set to 0).
template<class Rule>
int guided_mean_pixel(const SeparableSource& src, const Rule& rule, int x, int y,
                      GuidedScratch& scratch, float* out)
{
    const Kernel1D& k = src.kernel;
    const int r = k.radius, nc = src.nchannels;
    const PixelBlock& block = src.block();
    const OIIO::ROI& reg    = block.region;
    const Span xs = clip_window(x, r, reg.xbegin, reg.xend);
    const Span ys = clip_window(y, r, reg.ybegin, reg.yend);
    double* num = scratch.sums.data();
    double* den = num + nc;
    float* guide = scratch.guide.data();
    double* w    = scratch.weights.data();
    const float* kx = k.weights.data() + (xs.begin - x + r);
    std::fill(num, num + 2 * nc, 0.0);
    for (int qy = ys.begin; qy < ys.end; ++qy) {
        rule.row_weights(x, y, qy, xs, guide);
        if (qy == y)
            guide[x - xs.begin] = 1.0f;
        const double wy = k.weights[size_t(qy - y + r)];
        for (int i = 0; i < xs.size(); ++i)
            w[i] = wy * kx[i] * guide[i];
        const float* v = block.pixel(xs.begin, qy);
        switch (nc) {
        case 3: add_window_row<3>(v, block.nchannels, w, xs.size(), nc, src.masked, num, den); break;
        case 4: add_window_row<4>(v, block.nchannels, w, xs.size(), nc, src.masked, num, den); break;
        default: add_window_row<0>(v, block.nchannels, w, xs.size(), nc, src.masked, num, den);
        }
    }
    int empty = 0;
    for (int c = 0; c < nc; ++c) {
        const double d = src.masked ? den[c] : den[0];
        const bool any = d > 0.0;
        out[c]         = any ? float(num[c] / d) : 0.0f;
        empty += !any;
    }
    return empty;
}

/// The guided weighted mean over the pixels of `strip` that `selected(x, y)`
/// picks: pixels whose windows `rule.uniform_row` marks wholly viable with
/// weight 1 from the separable fast path, the others neighbour by
/// neighbour. Rows with no selected pixel are skipped. With `AllSelected`,
/// fast rows are written straight into `result` and only the other pixels
/// are overwritten.
template<bool AllSelected = false, class Rule, class Selected>
void guided_mean_strip(const SeparableSource& src, const Rule& rule, Selected&& selected,
                       const OIIO::ROI& strip, ResultPixels& result)
{
    const int nc = src.nchannels, w = strip.width();
    SeparableMeanRows fast(src, strip);
    std::vector<float> fast_row(AllSelected ? 0 : size_t(w) * nc);
    std::vector<uint8_t> fast_empty(static_cast<size_t>(w));
    std::vector<uint8_t> uniform(static_cast<size_t>(w));
    std::vector<uint8_t> chosen(static_cast<size_t>(w), 1);
    GuidedScratch scratch(nc);
    const std::ptrdiff_t stride = result.pixel_stride();
    int64_t empty = 0;
    for (int y = strip.ybegin; y < strip.yend; ++y) {
        if constexpr (!AllSelected) {
            bool any_selected = false;
            for (int x = strip.xbegin; x < strip.xend; ++x)
                any_selected |= chosen[size_t(x - strip.xbegin)] = selected(x, y);
            if (!any_selected)
                continue;
        }
        rule.uniform_row(y, Span { strip.xbegin, strip.xend }, uniform.data());
        int any_uniform = 0;
        for (int i = 0; i < w; ++i)
            any_uniform |= uniform[size_t(i)] &= chosen[size_t(i)];
        float* out_row = result.pixel(strip.xbegin, y);
        if (any_uniform) {
            if (AllSelected)
                fast.row(y, out_row, stride, fast_empty.data());
            else
                fast.row(y, fast_row.data(), nc, fast_empty.data());
            for (int i = 0; i < w; ++i)
                empty += uniform[size_t(i)] ? fast_empty[size_t(i)] : 0;
        }
        if (!AllSelected && any_uniform)
            for (int i = 0; i < w; ++i)
                if (uniform[size_t(i)])
                    std::copy_n(fast_row.data() + size_t(i) * nc, nc,
                                out_row + std::ptrdiff_t(i) * stride);
        // The other pixels, found by memchr: few away from guide edges.
        const uint8_t* u = uniform.data();
        for (auto* p = static_cast<const uint8_t*>(std::memchr(u, 0, size_t(w))); p;
             p = static_cast<const uint8_t*>(std::memchr(p + 1, 0, size_t(u + w - p - 1)))) {
            const int i = int(p - u);
            if (chosen[size_t(i)])
                empty += guided_mean_pixel(src, rule, strip.xbegin + i, y, scratch,
                                           out_row + std::ptrdiff_t(i) * stride);
        }
    }
    result.empty_windows += empty;
}

}  // namespace mcdenoise
