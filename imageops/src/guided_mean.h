// guided_mean.h: the one window walker for weighted-mean filters. A filter
// is a rule: which neighbours are viable and with what guide weight. Pixels
// whose whole window is viable with weight 1 take the separable fast path;
// the others are summed neighbour by neighbour.
#pragma once

#include "separable_mean.h"
#include "window.h"

#include <vector>

namespace mcdenoise {

/// Per-pixel working memory of `guided_mean_pixel`.
struct GuidedScratch {
    explicit GuidedScratch(int nchannels)
        : sums(size_t(2 * nchannels)), weights(size_t(max_window_size))
    {
    }
    std::vector<double> sums;    ///< numerators, then denominators
    std::vector<float> weights;  ///< one window row's guide weights
};

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
    double* den = num + nc;  // per channel when masked, else den[0] for all
    float* guide = scratch.weights.data();
    const float* kx = k.weights.data() + (xs.begin - x + r);
    std::fill(num, num + 2 * nc, 0.0);
    for (int qy = ys.begin; qy < ys.end; ++qy) {
        rule.row_weights(x, y, qy, xs, guide);
        if (qy == y)
            guide[x - xs.begin] = 1.0f;
        const double wy = k.weights[size_t(qy - y + r)];
        const float* v  = block.pixel(xs.begin, qy);
        for (int i = 0; i < xs.size(); ++i, v += block.nchannels) {
            if (guide[i] == 0.0f)
                continue;
            const double w = wy * kx[i] * guide[i];
            if (src.masked) {
                for (int c = 0; c < nc; ++c) {
                    num[c] += w * v[c];
                    den[c] += w * v[nc + c];  // mask: 1 where finite, else 0 (value 0)
                }
            } else {
                for (int c = 0; c < nc; ++c)
                    num[c] += w * v[c];
                den[0] += w;
            }
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
/// picks: `rule.uniform(x, y)` pixels from the separable fast path, the
/// others neighbour by neighbour. Rows with no selected pixel are skipped.
/// With `AllSelected`, fast rows are written straight into `result` and only
/// the other pixels are overwritten.
template<bool AllSelected = false, class Rule, class Selected>
void guided_mean_strip(const SeparableSource& src, const Rule& rule, Selected&& selected,
                       const OIIO::ROI& strip, ResultPixels& result)
{
    const int nc = src.nchannels, w = strip.width();
    SeparableMeanRows fast(src, strip);
    std::vector<float> fast_row(AllSelected ? 0 : size_t(w) * nc);
    std::vector<uint8_t> fast_empty(static_cast<size_t>(w));
    std::vector<uint8_t> uniform(static_cast<size_t>(w));
    GuidedScratch scratch(nc);
    const std::ptrdiff_t stride = result.pixel_stride();
    int64_t empty = 0;
    for (int y = strip.ybegin; y < strip.yend; ++y) {
        bool any_selected = false, any_uniform = false;
        for (int x = strip.xbegin; x < strip.xend; ++x) {
            const bool s = selected(x, y);
            const bool u = s && rule.uniform(x, y);
            uniform[size_t(x - strip.xbegin)] = u;
            any_selected |= s;
            any_uniform |= u;
        }
        if (!any_selected)
            continue;
        float* out_row = result.pixel(strip.xbegin, y);
        if (any_uniform) {
            if (AllSelected)
                fast.row(y, out_row, stride, fast_empty.data());
            else
                fast.row(y, fast_row.data(), nc, fast_empty.data());
        }
        for (int x = strip.xbegin; x < strip.xend; ++x) {
            const size_t i = size_t(x - strip.xbegin);
            float* out     = out_row + std::ptrdiff_t(i) * stride;
            if (uniform[i]) {
                if (!AllSelected)
                    std::copy_n(fast_row.data() + i * nc, nc, out);
                empty += fast_empty[i];
            } else if (AllSelected || selected(x, y)) {
                empty += guided_mean_pixel(src, rule, x, y, scratch, out);
            }
        }
    }
    result.empty_windows += empty;
}

}  // namespace mcdenoise
