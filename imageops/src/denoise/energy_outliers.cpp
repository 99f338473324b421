// energy_outliers.cpp: `denoise`'s energy-keeping outlier step: highlights
// told from fireflies, the firefly excess taken out of the beauty, and
// given back over each firefly's own NL-means window.
#include "denoise/energy_outliers.h"

#include "core/window.h"
#include "features/feature_field.h"
#include "features/weighted_sums.h"

#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;

namespace {

/// The luminance variance over `region` of `variance` (a variance guide),
/// or an empty plane without one.
bool luminance_variance(const char* op, ImageBuf& dst, const ImageBuf* variance, int nc,
                        const ROI& region, int nthreads, Plane<float>& out)
{
    out = Plane<float>();
    GuideChannels given;
    if (!variance)
        return true;
    if (!load_guide_channels(op, dst, *variance, region, nthreads, given))
        return false;
    const auto lw = luminance_weights(nc);
    out           = Plane<float>(region);
    parallel_rows(region, nthreads, [&](int y) {
        for (int x = region.xbegin; x < region.xend; ++x) {
            const size_t i = out.offset(x, y);
            float v        = 0.0f;
            for (int c = 0; c < nc; ++c) {
                const size_t k = size_t(std::min(c, given.nchannels() - 1));
                v += lw[size_t(c)] * lw[size_t(c)] * std::max(0.0f, given.values[k][i]);
            }
            out.values[i] = v;
        }
    });
    return true;
}

/// Rec. 709 (or mean) luminance of the first `nc` channels of `v`,
/// non-finite values as 0.
float luminance(const float* v, int nc)
{
    const auto lw = luminance_weights(nc);
    float lum     = 0.0f;
    for (int c = 0; c < nc; ++c)
        lum += std::isfinite(v[c]) ? lw[size_t(c)] * v[c] : 0.0f;
    return lum;
}

/// The Gaussian of `excess_spread_sigma` at offsets -radius..radius.
std::vector<float> spread_kernel()
{
    std::vector<float> g(size_t(2 * excess_spread_radius + 1));
    const double s2 = 2.0 * double(excess_spread_sigma) * double(excess_spread_sigma);
    for (int t = -excess_spread_radius; t <= excess_spread_radius; ++t)
        g[size_t(t + excess_spread_radius)] = float(std::exp(-double(t) * t / s2));
    return g;
}

/// 1 / (the sum of g over the pixels of [lo, hi) around each q in [a, b)).
std::vector<float> inverse_coverage(const std::vector<float>& g, int a, int b, int lo, int hi)
{
    std::vector<float> inv(size_t(b - a));
    for (int q = a; q < b; ++q) {
        const Span s = clip_window(q, excess_spread_radius, lo, hi);
        double sum   = 0.0;
        for (int p = s.begin; p < s.end; ++p)
            sum += g[size_t(p - q + excess_spread_radius)];
        inv[size_t(q - a)] = float(1.0 / sum);
    }
    return inv;
}

}  // namespace

bool split_outliers(const char* op, ImageBuf& dst, const ImageBuf& beauty,
                    const ImageBuf* variance, float factor, int radius, const ROI& region,
                    int nthreads, ImageBuf& kept, Planes<float>& excess, SplitScales* scales)
{
    const int nch = beauty.nchannels();
    const int nc  = colour_channels(nch);
    Plane<float> noise;
    if (!luminance_variance(op, dst, variance, nc, region, nthreads, noise))
        return false;
    if (scales)
        scales->gives_back = Plane<uint8_t>(region, uint8_t(0));
    if (!clamp_fireflies_scales(kept, beauty, {}, factor, radius, region, nthreads,
                                scales ? &scales->scale : nullptr)) {
        dst.errorfmt("{}: {}", op, kept.geterror());
        return false;
    }
    PixelBlock block;
    if (!read_beauty(op, dst, beauty, region, block))
        return false;
    excess = Planes<float>(region, nch, 0.0f);
    parallel_rows(region, nthreads, [&](int y) {
        for (int x = region.xbegin; x < region.xend; ++x) {
            const float* in = block.pixel(x, y);
            float* out      = static_cast<float*>(kept.pixeladdr(x, y));
            const float lum = luminance(in, nc);
            const float cut = lum - luminance(out, nc);
            if (!(cut > 0.0f))
                continue;
            const size_t i = excess.offset(x, y);
            const bool highlight = !noise.values.empty()
                                   && cut > consistent_excess_sigmas * std::sqrt(noise.values[i]);
            if (scales) {
                scales->scale.at(x, y)      = highlight ? 1.0f : scales->scale.at(x, y);
                scales->gives_back.at(x, y) = !highlight;
            }
            for (int c = 0; c < nc; ++c) {
                if (highlight)
                    out[c] = in[c];
                else if (std::isfinite(in[c]))
                    excess.values[size_t(c)][i] = in[c] - out[c];
            }
        }
    });
    return true;
}

void split_layer(const PixelBlock& in, const SplitScales& scales, const ROI& values_region,
                 int nthreads, SumSource& kept, Planes<float>& excess)
{
    const ROI& region = scales.scale.region;
    const int nc      = in.nchannels;
    kept              = SumSource(values_region, nc);
    excess            = Planes<float>(region, nc, 0.0f);
    std::vector<uint8_t> row_has_nonfinite(size_t(values_region.height()), 0);
    parallel_rows(region, nthreads, [&](int y) {
        const bool values_row = y >= values_region.ybegin && y < values_region.yend;
        bool any              = false;
        for (int x = region.xbegin; x < region.xend; ++x) {
            const float* v    = in.pixel(x, y);
            const float s     = scales.scale.at(x, y);
            const bool gives  = scales.gives_back.at(x, y);
            const size_t i    = excess.offset(x, y);
            const bool stored = values_row && x >= values_region.xbegin
                                && x < values_region.xend;
            for (int c = 0; c < nc; ++c) {
                const bool finite = std::isfinite(v[c]);
                const float k     = finite ? v[c] * s : v[c];
                if (gives && finite)
                    excess.values[size_t(c)][i] = v[c] - k;
                if (stored)
                    *kept.from(c, x, y) = summable(k);
                any |= stored && !finite;
            }
        }
        if (values_row)
            row_has_nonfinite[size_t(y - values_region.ybegin)] = any;
    });
    if (std::find(row_has_nonfinite.begin(), row_has_nonfinite.end(), uint8_t(1))
        == row_has_nonfinite.end())
        return;
    kept.finite = Planes<float>(values_region, nc).values;
    parallel_rows(values_region, nthreads, [&](int y) {
        for (int x = values_region.xbegin; x < values_region.xend; ++x)
            for (int c = 0; c < nc; ++c)
                kept.finite[size_t(c)][kept.offset(x, y)] = finite_weight(in.pixel(x, y)[c]);
    });
}

ExcessWeights excess_sources(const Planes<float>& excess, const ROI& sources, int radius)
{
    ExcessWeights out;
    out.radius = radius;
    for (int y = sources.ybegin; y < sources.yend; ++y)
        for (int x = sources.xbegin; x < sources.xend; ++x) {
            const size_t i = excess.offset(x, y);
            for (const auto& plane : excess.values)
                if (plane[i] != 0.0f) {
                    out.sources.push_back({ x, y });
                    break;
                }
        }
    out.weights.assign(out.sources.size() * window_size(out), 0.0f);
    return out;
}

WeightTap weight_tap(ExcessWeights& weights, const ROI& roi)
{
    WeightTap tap { Plane<int32_t>(roi, -1), weights.weights.data() };
    for (size_t k = 0; k < weights.sources.size(); ++k) {
        const PixelXY p = weights.sources[k];
        if (roi.contains(p.x, p.y))
            tap.index.at(p.x, p.y) = int32_t(k);
    }
    return tap;
}

void fill_outside(ExcessWeights& weights, const ROI& roi, const NlmFrame& frame,
                  const ColourField& colour, const VarianceField& variance, const ROI& dw,
                  int patch_radius, float strength, int nthreads)
{
    std::vector<PixelXY> outside;
    std::vector<size_t> slots;
    for (size_t k = 0; k < weights.sources.size(); ++k)
        if (!roi.contains(weights.sources[k].x, weights.sources[k].y)) {
            outside.push_back(weights.sources[k]);
            slots.push_back(k);
        }
    if (outside.empty())
        return;
    std::vector<float> w;
    window_weights(frame, colour, variance, dw, patch_radius, strength, outside, nthreads, w);
    const size_t count = window_size(weights);
    for (size_t j = 0; j < slots.size(); ++j)
        std::copy(w.begin() + std::ptrdiff_t(j * count), w.begin() + std::ptrdiff_t((j + 1) * count),
                  weights.weights.begin() + std::ptrdiff_t(slots[j] * count));
}

bool sources_outside(const ExcessWeights& weights, const ROI& roi)
{
    return std::any_of(weights.sources.begin(), weights.sources.end(),
                       [&](const PixelXY& p) { return !roi.contains(p.x, p.y); });
}

void normalise_weights(ExcessWeights& weights)
{
    const size_t count = window_size(weights);
    for (size_t k = 0; k < weights.sources.size(); ++k) {
        float* w   = weights.weights.data() + k * count;
        double sum = 0.0;
        for (size_t j = 0; j < count; ++j)
            sum += w[j];
        for (size_t j = 0; j < count; ++j)
            w[j] = float(w[j] / sum);
    }
}

namespace {

/// The excess spread over `roi` by the Gaussian of `excess_spread_sigma`
/// normalised per source pixel over `data_window` (see `ExcessWeights::
/// wide`), handed out row by row: `sink(y, c, sum)` takes row y of channel
/// c (the ROI's width of values) for each plane c that holds any excess.
template<class Sink>
void gaussian_rows(const Planes<float>& excess, const ROI& roi, const ROI& data_window,
                 int nthreads, Sink&& sink)
{
    const std::vector<float> g = spread_kernel();
    const ROI& reg             = excess.region;
    const int nc               = excess.nchannels();
    const std::vector<float> inv_x = inverse_coverage(g, reg.xbegin, reg.xend,
                                                      data_window.xbegin, data_window.xend);
    const std::vector<float> inv_y = inverse_coverage(g, reg.ybegin, reg.yend,
                                                      data_window.ybegin, data_window.yend);
    // Along the rows: h(x, y) = sum_t g(t) e(x + t, y) / nx(x + t), for the
    // ROI's columns and every row of the region.
    ROI rows    = reg;
    rows.xbegin = roi.xbegin;
    rows.xend   = roi.xend;
    Planes<float> h(rows, nc, 0.0f);
    parallel_rows(rows, nthreads, [&](int y) {
        for (int c = 0; c < nc; ++c) {
            const float* e = excess.row(c, y);
            float* out     = h.row(c, y);
            for (int qx = reg.xbegin; qx < reg.xend; ++qx) {
                const float v = e[qx - reg.xbegin];
                if (v == 0.0f)
                    continue;
                const float w   = v * inv_x[size_t(qx - reg.xbegin)];
                const Span span = clip_window(qx, excess_spread_radius, roi.xbegin, roi.xend);
                for (int x = span.begin; x < span.end; ++x)
                    out[x - roi.xbegin] += w * g[size_t(x - qx + excess_spread_radius)];
            }
        }
    });
    // Down the columns, into the channels of the result, for the planes
    // that hold any excess.
    std::vector<char> given(static_cast<size_t>(nc));
    for (int c = 0; c < nc; ++c)
        given[size_t(c)] = std::any_of(excess.values[size_t(c)].begin(),
                                       excess.values[size_t(c)].end(),
                                       [](float v) { return v != 0.0f; });
    // Blocks of rows at a time, eight columns in registers: each row of h
    // is read once for every row of the block that reaches it; for a row
    // the terms come in the same order as one row at a time (a row out of
    // reach takes 0 * h, which leaves its sum as it is).
    using OIIO::simd::vfloat8;
    constexpr int block = 8;
    const int nblocks   = (roi.height() + block - 1) / block;
    const int width     = roi.width();
    parallel_rows(ROI(0, 1, 0, nblocks), nthreads, [&](int b) {
        const int y0   = roi.ybegin + b * block;
        const int rows = std::min(block, roi.yend - y0);
        const int qlo  = clip_window(y0, excess_spread_radius, reg.ybegin, reg.yend).begin;
        const int qhi  = clip_window(y0 + rows - 1, excess_spread_radius, reg.ybegin, reg.yend).end;
        // w[(qy - qlo) * block + j]: the weight of h's row qy for row y0 + j.
        std::vector<float> w(size_t(qhi - qlo) * block, 0.0f);
        for (int j = 0; j < rows; ++j) {
            const Span span = clip_window(y0 + j, excess_spread_radius, reg.ybegin, reg.yend);
            for (int qy = span.begin; qy < span.end; ++qy)
                w[size_t(qy - qlo) * block + size_t(j)] = g[size_t(y0 + j - qy + excess_spread_radius)]
                                                          * inv_y[size_t(qy - reg.ybegin)];
        }
        std::vector<float> sums(size_t(block) * size_t(width));
        for (int c = 0; c < nc; ++c) {
            if (!given[size_t(c)])
                continue;
            for (int i = 0; i < width; i += vfloat8::elements) {
                const int count = std::min(int(vfloat8::elements), width - i);
                vfloat8 acc[block];
                for (int j = 0; j < block; ++j)
                    acc[j] = vfloat8(0.0f);
                for (int qy = qlo; qy < qhi; ++qy) {
                    const vfloat8 hv  = load_lanes(h.row(c, qy) + i, count);
                    const float* wq   = w.data() + size_t(qy - qlo) * block;
                    for (int j = 0; j < block; ++j)
                        acc[j] = acc[j] + vfloat8(wq[j]) * hv;
                }
                for (int j = 0; j < block; ++j)
                    store_lanes(acc[j], sums.data() + size_t(j) * size_t(width) + size_t(i), count);
            }
            for (int j = 0; j < rows; ++j)
                sink(y0 + j, c, sums.data() + size_t(j) * size_t(width));
        }
    });
}

/// The excess given out over `roi` over each source's window (see
/// `spread_excess`), row by row: `sink(y, c, sum)` takes row y of channel c
/// (the ROI's width of values) for each plane c of `excess`, each source's
/// terms added in the order of the sources.
template<class Sink>
void window_rows(const ExcessWeights& weights, const Planes<float>& excess, const ROI& roi,
                 int nthreads, Sink&& sink)
{
    const int r        = weights.radius;
    const int side     = 2 * r + 1;
    const size_t count = size_t(side) * size_t(side);
    const int nc       = excess.nchannels();
    const std::vector<PixelXY>& sources = weights.sources;
    parallel_rows(roi, nthreads, [&](int y) {
        // The sources of rows y - r .. y + r, found by binary search.
        const auto below = [](const PixelXY& s, int row) { return s.y < row; };
        const auto first = std::lower_bound(sources.begin(), sources.end(), y - r, below);
        const auto last  = std::lower_bound(first, sources.end(), y + r + 1, below);
        std::vector<float> sum(size_t(roi.width()));
        for (int c = 0; c < nc; ++c) {
            std::fill(sum.begin(), sum.end(), 0.0f);
            for (auto s = first; s != last; ++s) {
                const float e = excess.values[size_t(c)][excess.offset(s->x, s->y)];
                if (e == 0.0f)
                    continue;
                const float* w = weights.weights.data() + size_t(s - sources.begin()) * count
                                 + size_t(y - s->y + r) * size_t(side);
                const Span span = clip_window(s->x, r, roi.xbegin, roi.xend);
                for (int x = span.begin; x < span.end; ++x)
                    sum[size_t(x - roi.xbegin)] += e * w[x - s->x + r];
            }
            sink(y, c, sum.data());
        }
    });
}

/// The excess given out over `roi` as `weights` says, row by row (see
/// `gaussian_rows` and `window_rows`).
template<class Sink>
void spread_rows(const ExcessWeights& weights, const Planes<float>& excess, const ROI& roi,
                 int nthreads, Sink&& sink)
{
    if (weights.wide)
        gaussian_rows(excess, roi, weights.data_window, nthreads, sink);
    else
        window_rows(weights, excess, roi, nthreads, sink);
}

}  // namespace

ImageBuf spread_excess(const ExcessWeights& weights, const Planes<float>& excess, const ROI& roi,
                       int nchannels, int nthreads)
{
    ROI full     = roi;
    full.chbegin = 0;
    full.chend   = nchannels;
    ImageBuf spread(OIIO::ImageSpec(full, OIIO::TypeDesc::FLOAT));
    OIIO::ImageBufAlgo::zero(spread);
    spread_rows(weights, excess, roi, nthreads, [&](int y, int c, const float* sum) {
        for (int x = roi.xbegin; x < roi.xend; ++x)
            static_cast<float*>(spread.pixeladdr(x, y))[c] = sum[x - roi.xbegin];
    });
    return spread;
}

Planes<float> spread_excess_planes(const ExcessWeights& weights, const Planes<float>& excess,
                                   const ROI& roi, int nthreads)
{
    Planes<float> spread(roi, excess.nchannels(), 0.0f);
    spread_rows(weights, excess, roi, nthreads, [&](int y, int c, const float* sum) {
        std::copy_n(sum, roi.width(), spread.row(c, y));
    });
    return spread;
}

int premultiplied_alpha(const ImageBuf& beauty)
{
    const int given = beauty.spec().alpha_channel;
    if (given >= 0)
        return given;
    return beauty.nchannels() > feature_colour_channels ? feature_colour_channels : -1;
}

namespace {

/// Add `spread` to the float image `sum` over `roi` as `give_back_excess`
/// says.
void add_spread(ImageBuf& sum, const ImageBuf& spread, const ROI& roi, int alpha_channel,
                int nthreads, Plane<float>* factors)
{
    const int nch    = sum.nchannels();
    const int nc     = colour_channels(nch);
    const bool alpha = alpha_channel >= nc && alpha_channel < nch;
    parallel_rows(roi, nthreads, [&](int y) {
        for (int x = roi.xbegin; x < roi.xend; ++x) {
            float* out     = static_cast<float*>(sum.pixeladdr(x, y));
            const float* e = static_cast<const float*>(spread.pixeladdr(x, y));
            float factor   = 1.0f;
            for (int c = 0; alpha && c < nc; ++c)
                if (e[c] > 0.0f && out[c] <= out[alpha_channel]
                    && out[c] + e[c] > out[alpha_channel])
                    factor = std::min(factor, (out[alpha_channel] - out[c]) / e[c]);
            if (factors)
                factors->at(x, y) = factor;
            const float a = alpha ? out[alpha_channel] : 0.0f;
            for (int c = 0; c < nch; ++c) {
                const bool held = alpha && c < nc && out[c] <= a;
                out[c] += factor * e[c];
                if (held)  // the factor's rounding must not lift it above
                    out[c] = std::min(out[c], a);
            }
        }
    });
}

}  // namespace

bool give_back_spread(const char* op, ImageBuf& dst, const ImageBuf& spread, const ROI& roi,
                      int alpha_channel, int nthreads, Plane<float>* factors)
{
    if (factors)
        *factors = Plane<float>(roi);
    if (dst.spec().format == OIIO::TypeDesc::FLOAT && dst.localpixels()) {
        add_spread(dst, spread, roi, alpha_channel, nthreads, factors);
        return true;
    }
    ImageBuf sum;
    if (!OIIO::ImageBufAlgo::copy(sum, dst, OIIO::TypeDesc::FLOAT, roi, nthreads)) {
        dst.errorfmt("{}: could not add the spread excess: {}", op, sum.geterror());
        return false;
    }
    add_spread(sum, spread, roi, alpha_channel, nthreads, factors);
    if (!OIIO::ImageBufAlgo::paste(dst, roi.xbegin, roi.ybegin, 0, 0, sum, roi, nthreads)) {
        dst.errorfmt("{}: could not add the spread excess: {}", op, dst.geterror());
        return false;
    }
    return true;
}

bool give_back_excess(const char* op, ImageBuf& dst, const ExcessWeights& weights,
                      const Planes<float>& excess, const ROI& roi, int alpha_channel,
                      int nthreads, Plane<float>* factors)
{
    return give_back_spread(op, dst, spread_excess(weights, excess, roi, dst.nchannels(), nthreads),
                            roi, alpha_channel, nthreads, factors);
}

void give_back_layer_excess(ImageBuf& dst, const ExcessWeights& weights,
                            const Planes<float>& excess, const ROI& roi,
                            const Plane<float>& factors, int nthreads)
{
    const std::ptrdiff_t stride = dst.pixel_stride() / std::ptrdiff_t(sizeof(float));
    spread_rows(weights, excess, roi, nthreads, [&](int y, int c, const float* sum) {
        float* out      = static_cast<float*>(dst.pixeladdr(roi.xbegin, y, 0, c));
        const float* f  = factors.from(roi.xbegin, y);
        for (int i = 0; i < roi.width(); ++i)
            out[i * stride] += f[i] * sum[i];
    });
}

}  // namespace mcdenoise
