// atrous.cpp: the edge-avoiding a-trous wavelet filter (Dammertz et al.
// 2010) with SVGF's variance-guided luminance weight (Schied et al. 2017).
#include <mcdenoise/atrous.h>

#include "core/operation.h"
#include "core/window.h"
#include "features/feature_field.h"
#include "features/weighted_sums.h"
#include "walkers/offset_walk.h"

#include <cmath>

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;

namespace {

// The B3-spline taps of Dammertz et al. (2010), offsets -2..2.
constexpr int tap_radius        = 2;
constexpr float b3_spline[5]    = { 1.0f / 16, 1.0f / 4, 3.0f / 8, 1.0f / 4, 1.0f / 16 };
// SVGF's guard against a zero variance (Schied et al. 2017, eq. 3).
constexpr float luminance_guard = 1e-10f;

// One iterate over `region`: every channel (finite after the first), its
// luminance and the luminance variance, as planes of the region's width.
struct Iterate {
    SumSource values;
    Plane<float> luminance;
    Plane<float> variance;
};

// Remaining reach of the taps before iteration i of n: sum of 2 * 2^j, j >= i.
int reach_before(int i, int n)
{
    return (2 << n) - (2 << i);
}

// 1 / (sigma_luminance sqrt(g) + guard) over `out_region`, g the 3x3
// binomial blur of `cur.variance` clipped to `dw` and renormalised; 0
// everywhere when the luminance weight is off.
Plane<float> luminance_scale(const Iterate& cur, float sigma_luminance, const ROI& out_region,
                             const ROI& dw, int nthreads)
{
    static constexpr float binomial3[3] = { 1.0f, 2.0f, 1.0f };
    Plane<float> inv(out_region, 0.0f);
    if (!(sigma_luminance > 0.0f))
        return inv;
    parallel_rows(out_region, nthreads, [&](int y) {
        const Span ys = clip_window(y, 1, dw.ybegin, dw.yend);
        float* out    = inv.row(y);
        for (int x = out_region.xbegin; x < out_region.xend; ++x) {
            const Span xs = clip_window(x, 1, dw.xbegin, dw.xend);
            float sum = 0.0f, weight = 0.0f;
            for (int qy = ys.begin; qy < ys.end; ++qy)
                for (int qx = xs.begin; qx < xs.end; ++qx) {
                    const float k = binomial3[qy - y + 1] * binomial3[qx - x + 1];
                    sum += k * cur.variance.at(qx, qy);
                    weight += k;
                }
            out[x - out_region.xbegin]
                = 1.0f / (sigma_luminance * std::sqrt(sum / weight) + luminance_guard);
        }
    });
    return inv;
}

// The luminance of the colour channels of `values` at each pixel of its region.
Plane<float> luminance_of(const SumSource& values, int ncolour, int nthreads)
{
    const auto lw = luminance_weights(ncolour);
    const ROI& reg = values.region;
    Plane<float> lum(reg);
    parallel_rows(reg, nthreads, [&](int y) {
        float* out = lum.row(y);
        for (int i = 0; i < reg.width(); ++i) {
            float l = 0.0f;
            for (int c = 0; c < ncolour; ++c)
                l += lw[size_t(c)] * values.row(c, y)[i];
            out[i] = l;
        }
    });
    return lum;
}

// One a-trous pass with step `step` from `cur` over `out_region`. On the
// last pass, writes channels [roi.chbegin, roi.chend) into `result`
// instead of making the next iterate.
Iterate atrous_pass(const Iterate& cur, const FeatureField& features, int step,
                    float sigma_luminance, int ncolour, const ROI& out_region, const ROI& dw,
                    ResultPixels* result, int nthreads)
{
    const Plane<float> inv = luminance_scale(cur, sigma_luminance, out_region, dw, nthreads);
    const SumSource& src   = cur.values;
    Iterate next;
    const int nch = src.nchannels();
    if (!result) {
        next.values   = SumSource(out_region, nch);
        next.variance = Plane<float>(out_region);
    }
    parallel_rows(out_region, nthreads, [&](int y) {
        const FlushDenormals flush;
        for_each_segment(out_region.xbegin, out_region.xend, [&](int x0, int n) {
            const int c0 = result ? result->roi.chbegin : 0;
            const int c1 = result ? result->roi.chend : nch;
            WeightedSums sums(c0, c1, n, src.masked());
            const size_t len = static_cast<size_t>(n);
            std::vector<float> e(len), w(len), wsum(len, 0.0f), w2var(len, 0.0f);
            const float* lum_p = cur.luminance.from(x0, y);
            const float* inv_p = inv.from(x0, y);
            for_each_offset(y, x0, n, tap_radius, step, dw, [&](const Offset& o) {
                const int i0 = o.i0, i1 = o.i1;
                const float h = b3_spline[o.ky + tap_radius] * b3_spline[o.kx + tap_radius];
                // Neighbour pointers start at i0 (those of i < i0 lie outside).
                const float* lum_q = cur.luminance.from(o.first_neighbour(x0), y + o.dy);
                const float* var_q = cur.variance.from(o.first_neighbour(x0), y + o.dy);
                if (o.centre()) {
                    std::fill(w.begin() + i0, w.begin() + i1, h);
                } else {
                    for (int i = i0; i < i1; ++i)
                        e[i] = std::fabs(lum_p[i] - lum_q[i - i0]) * inv_p[i];
                    features.weights_row(y, x0 + i0, o.count(), o.dx, o.dy, e.data() + i0, h,
                                         w.data() + i0);
                }
                for (int i = i0; i < i1; ++i) {
                    wsum[i] += w[i];
                    w2var[i] += w[i] * w[i] * var_q[i - i0];
                }
                sums.add(w.data(), src, x0 + o.dx, y + o.dy, i0, i1);
            });
            if (result) {
                result->empty_windows += sums.write(result->pixel(x0, y), result->pixel_stride());
                return;
            }
            std::vector<float*> planes(static_cast<size_t>(nch));
            for (int c = 0; c < nch; ++c)
                planes[size_t(c)] = next.values.from(c, x0, y);
            sums.write_planes(planes.data());
            float* variance = next.variance.from(x0, y);
            for (int i = 0; i < n; ++i)
                variance[i] = w2var[i] / (wsum[i] * wsum[i]);
        });
    });
    if (!result)
        next.luminance = luminance_of(next.values, ncolour, nthreads);
    return next;
}

}  // namespace

bool atrous(ImageBuf& dst, const ImageBuf& beauty, const Guides& guides, int iterations,
            float sigma_luminance, const FeatureSigmas& sigmas, ROI roi, int nthreads)
{
    const char* op = "atrous";
    if (iterations < 1 || iterations > max_atrous_iterations) {
        dst.errorfmt("{}: iterations must be between 1 and {}, got {}", op,
                     max_atrous_iterations, iterations);
        return false;
    }
    if (!resolve_roi(op, dst, beauty, roi) || !check_feature_guides(op, dst, guides, roi))
        return false;
    const ROI dw    = beauty.roi();
    const ROI first = grow_and_clip(roi, reach_before(0, iterations), dw);
    FeatureInputs in;
    if (!load_feature_inputs(op, dst, beauty, guides, sigmas, first, first, nthreads, in))
        return false;
    Iterate cur;
    cur.values    = std::move(in.values);
    cur.luminance = cropped(in.colour.luminance, first);
    cur.variance  = std::move(in.variance.luminance);
    ResultPixels result;
    if (!begin_result(op, dst, beauty,
                      { &beauty, guides.object_id, guides.normal, guides.depth, guides.albedo,
                        guides.variance },
                      roi, result))
        return false;
    const int ncolour = in.colour.nchannels();
    for (int i = 0; i < iterations; ++i) {
        const bool last = i == iterations - 1;
        const ROI out   = last ? roi : grow_and_clip(roi, reach_before(i + 1, iterations), dw);
        cur = atrous_pass(cur, in.features, 1 << i, sigma_luminance, ncolour, out, dw,
                          last ? &result : nullptr, nthreads);
    }
    return finish_result(op, dst, result);
}

ImageBuf atrous(const ImageBuf& beauty, const Guides& guides, int iterations,
                float sigma_luminance, const FeatureSigmas& sigmas, ROI roi, int nthreads)
{
    return value_form([&](ImageBuf& dst) {
        return atrous(dst, beauty, guides, iterations, sigma_luminance, sigmas, roi, nthreads);
    });
}

}  // namespace mcdenoise
