// fireflies.cpp: the firefly clamp: each pixel's luminance against a
// percentile of its (same-object) neighbours'.
#include <mcdenoise/fireflies.h>

#include "core/operation.h"
#include "core/window.h"
#include "features/feature_field.h"
#include "features/firefly_scales.h"
#include "walkers/offset_walk.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;

namespace {

constexpr const char* op_name = "clamp_fireflies";

/// Rank of the percentile among n sorted neighbours.
inline size_t percentile_rank(size_t n) { return (3 * (n - 1)) / 4; }

/// The factor pixel (x, y)'s colour is multiplied by: 1 unless its luminance
/// exceeds `factor` times the 75th-percentile luminance of its viable
/// neighbours. `scratch` holds at least (2 radius + 1)^2 floats.
float clamp_scale(const ColourField& colour, const IdPlane* ids, float factor, int radius,
                  int x, int y, std::vector<float>& scratch)
{
    const ROI& reg   = colour.region();
    const Span xs    = clip_window(x, radius, reg.xbegin, reg.xend);
    const Span ys    = clip_window(y, radius, reg.ybegin, reg.yend);
    const Id id = ids ? ids->at(x, y) : 0;
    size_t n         = 0;
    for (int qy = ys.begin; qy < ys.end; ++qy)
        for (int qx = xs.begin; qx < xs.end; ++qx)
            if ((qx != x || qy != y) && (!ids || ids->at(qx, qy) == id))
                scratch[n++] = colour.luminance.at(qx, qy);
    if (n == 0)
        return 1.0f;
    const size_t k = percentile_rank(n);
    std::nth_element(scratch.begin(), scratch.begin() + std::ptrdiff_t(k),
                     scratch.begin() + std::ptrdiff_t(n));
    const float bound = factor * scratch[k];
    const float lum   = colour.luminance.at(x, y);
    if (!(lum > bound))
        return 1.0f;
    return bound > 0.0f ? bound / lum : 0.0f;
}

/// For row y of `roi`, mark in `suspect` the pixels `clamp_scale` may
/// change. A pixel is kept exactly when at least n - k of its n viable
/// neighbours q have factor * L_q >= L_p (k the percentile rank): scaling by
/// `factor` keeps the order, so then factor * s_k >= L_p. Counting needs no
/// sort and runs along the row.
void find_suspects(const ColourField& colour, const IdPlane* ids, float factor, int radius,
                   const ROI& roi, int y, std::vector<uint16_t>& count,
                   std::vector<uint16_t>& viable, std::vector<uint8_t>& suspect)
{
    const int w = roi.width();
    std::fill(count.begin(), count.end(), uint16_t(0));
    std::fill(viable.begin(), viable.end(), uint16_t(0));
    const float* lp = colour.luminance.from(roi.xbegin, y);
    for_each_offset(y, roi.xbegin, w, radius, 1, colour.region(), [&](const Offset& o) {
        if (o.centre())
            return;
        // Pointers start at i0: the neighbour of i < i0 lies outside.
        const int n = o.count(), xq = o.first_neighbour(roi.xbegin);
        const float* p  = lp + o.i0;
        const float* q  = colour.luminance.from(xq, y + o.dy);
        uint16_t* c     = count.data() + o.i0;
        uint16_t* v     = viable.data() + o.i0;
        if (!ids) {
            for (int i = 0; i < n; ++i) {
                v[i] += 1;
                c[i] += uint16_t(factor * q[i] >= p[i]);
            }
            return;
        }
        const Id* ip = ids->from(roi.xbegin + o.i0, y);
        const Id* iq = ids->from(xq, y + o.dy);
        for (int i = 0; i < n; ++i) {
            const uint16_t same = uint16_t(ip[i] == iq[i]);
            v[i] += same;
            c[i] += uint16_t(same & uint16_t(factor * q[i] >= p[i]));
        }
    });
    for (int i = 0; i < w; ++i) {
        const size_t n = viable[size_t(i)];
        suspect[size_t(i)] = n > 0 && count[size_t(i)] < n - percentile_rank(n);
    }
}

}  // namespace

bool clamp_fireflies(ImageBuf& dst, const ImageBuf& beauty, const Guides& guides, float factor,
                     int radius, ROI roi, int nthreads)
{
    return clamp_fireflies_scales(dst, beauty, guides, factor, radius, roi, nthreads, nullptr);
}

bool clamp_fireflies_scales(ImageBuf& dst, const ImageBuf& beauty, const Guides& guides,
                            float factor, int radius, ROI roi, int nthreads,
                            Plane<float>* scales)
{
    if (!(factor >= 1.0f) || !std::isfinite(factor)) {
        dst.errorfmt("{}: factor must be a finite number >= 1, got {}", op_name, factor);
        return false;
    }
    if (radius < 1 || radius > max_firefly_radius) {
        dst.errorfmt("{}: radius must be 1..{}, got {}", op_name, max_firefly_radius, radius);
        return false;
    }
    if (!resolve_roi(op_name, dst, beauty, roi)
        || (guides.object_id
            && !check_guide(op_name, "object_id", dst, *guides.object_id, 1, roi)))
        return false;
    ROI region    = grow_and_clip(roi, radius, beauty.roi());
    region.chbegin = 0;
    region.chend   = beauty.nchannels();
    PixelBlock block;
    IdPlane ids;
    if (!read_beauty(op_name, dst, beauty, region, block)
        || (guides.object_id
            && !load_object_ids(op_name, dst, *guides.object_id, region, nthreads, ids)))
        return false;
    const ColourField colour = colour_field(block, region, nthreads);
    ResultPixels result;
    if (!begin_result(op_name, dst, beauty, { &beauty, guides.object_id }, roi, result))
        return false;
    const int ncolour  = colour.nchannels();
    const IdPlane* idp = guides.object_id ? &ids : nullptr;
    if (scales)
        *scales = Plane<float>(roi);
    parallel_rows(roi, nthreads, [&](int y) {
        const size_t w = size_t(roi.width());
        std::vector<float> scratch(size_t((2 * radius + 1) * (2 * radius + 1)));
        std::vector<uint16_t> count(w), viable(w);
        std::vector<uint8_t> suspect(w);
        find_suspects(colour, idp, factor, radius, roi, y, count, viable, suspect);
        float* out = result.pixel(roi.xbegin, y);
        for (int x = roi.xbegin; x < roi.xend; ++x, out += result.pixel_stride()) {
            const float scale = suspect[size_t(x - roi.xbegin)]
                                    ? clamp_scale(colour, idp, factor, radius, x, y, scratch)
                                    : 1.0f;
            if (scales)
                scales->at(x, y) = scale;
            const float* in   = block.pixel(x, y);
            for (int ch = roi.chbegin; ch < roi.chend; ++ch) {
                const float v = in[ch];
                const bool scaled = ch < ncolour && std::isfinite(v);
                out[ch - roi.chbegin] = scaled ? v * scale : v;
            }
        }
    });
    return finish_result(op_name, dst, result);
}

ImageBuf clamp_fireflies(const ImageBuf& beauty, const Guides& guides, float factor, int radius,
                         ROI roi, int nthreads)
{
    return value_form([&](ImageBuf& dst) {
        return clamp_fireflies(dst, beauty, guides, factor, radius, roi, nthreads);
    });
}

}  // namespace mcdenoise
