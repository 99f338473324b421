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
    explicit GuidedScratch(int block_channels)
        : guide(size_t(max_window_size)),
          spread(size_t(max_window_size) * block_channels),
          sums(size_t(max_window_size) * block_channels)
    {
    }
    std::vector<float> guide;    ///< one window row's guide weights
    std::vector<double> spread;  ///< its whole weights, one per value
    std::vector<double> sums;    ///< weighted sums per window column and value
};

/// The weighted mean of pixel (x, y)'s viable finite neighbours, each
/// weighted by the spatial kernel times the rule's guide weight (the center
/// by its spatial weight alone), into `out`. `Rule` provides
/// `void row_weights(int px, int py, int qy, Span xs, float* w) const`:
/// the guide weight, 0 where not viable, of each neighbour (qx, qy), qx in
/// `xs`, of center (px, py), into w[qx - xs.begin]. Each window row is one
/// contiguous run of values, summed per value (colour and finite mask) in
/// double by loops the compiler vectorises; zero weights add zeros.
/// Returns the count of channels with no contribution (set to 0).
template<class Rule>
int guided_mean_pixel(const SeparableSource& src, const Rule& rule, int x, int y,
                      GuidedScratch& scratch, float* out)
{
    const Kernel1D& k = src.kernel;
    const int r = k.radius, nc = src.nchannels;
    const PixelBlock& block = src.block();
    const int per = block.nchannels;  // nc values, then nc masks when masked
    const OIIO::ROI& reg = block.region;
    const Span xs = clip_window(x, r, reg.xbegin, reg.xend);
    const Span ys = clip_window(y, r, reg.ybegin, reg.yend);
    const int n = xs.size(), values = n * per;
    float* guide   = scratch.guide.data();
    double* spread = scratch.spread.data();
    double* sums   = scratch.sums.data();
    const float* kx = k.weights.data() + (xs.begin - x + r);
    std::fill(sums, sums + values, 0.0);
    double total = 0.0;  // the weights' sum: the denominator when unmasked
    for (int qy = ys.begin; qy < ys.end; ++qy) {
        rule.row_weights(x, y, qy, xs, guide);
        if (qy == y)
            guide[x - xs.begin] = 1.0f;
        const double wy = k.weights[size_t(qy - y + r)];
        for (int i = 0; i < n; ++i) {
            const double w = wy * kx[i] * guide[i];
            total += w;
            std::fill_n(spread + i * per, per, w);
        }
        const float* v = block.pixel(xs.begin, qy);
        for (int j = 0; j < values; ++j)
            sums[j] += spread[j] * v[j];
    }
    int empty = 0;
    for (int c = 0; c < nc; ++c) {
        double num = 0.0, den = src.masked ? 0.0 : total;
        for (int i = 0; i < n; ++i) {
            num += sums[i * per + c];
            if (src.masked)
                den += sums[i * per + nc + c];
        }
        const bool any = den > 0.0;
        out[c]         = any ? float(num / den) : 0.0f;
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
    GuidedScratch scratch(src.block().nchannels);
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
