// frame_warp.cpp: the motion-chained path from a pixel of the centre frame
// to a neighbour frame, the map of those paths, and the planes carried
// along them, with where the carried colour is faithful to the source's.
#include "shots/frame_warp.h"

#include "core/guides.h"
#include "core/window.h"

#include <algorithm>
#include <cmath>

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;

namespace {

bool inside(const ROI& r, int x, int y)
{
    return x >= r.xbegin && x < r.xend && y >= r.ybegin && y < r.yend;
}

int nearest(float v) { return int(std::floor(v + 0.5f)); }

// The pixel step of `motion` at (x, y) towards the next frame (`forward`)
// or the previous one: (x + X, y - Y) back, (x - Z, y + W) on.
void step_vector(const GuideChannels& motion, int x, int y, bool forward, float& vx, float& vy)
{
    const size_t i = motion.offset(x, y);
    vx = forward ? -motion.values[2][i] : motion.values[0][i];
    vy = forward ? motion.values[3][i] : -motion.values[1][i];
}

// Where pixel (x, y) of the centre lies in the frame `offset` frames away
// (data window `source_dw`): its nearest source pixel (qx, qy), whether
// that lies inside `source_dw`, and the motion's distance from that
// pixel's centre (dx, dy).
struct Source {
    int qx, qy;
    float dx, dy;
    bool ok;
};

Source trace(const std::vector<const GuideChannels*>& steps, int offset, const ROI& source_dw,
             int x, int y)
{
    const bool forward = offset > 0;
    const bool still   = steps.empty() || !steps.front();
    // The path from the pixel, as a displacement: the same at any data
    // window origin.
    float px = 0.0f, py = 0.0f, vx = 0.0f, vy = 0.0f;
    int qx = x, qy = y;
    for (size_t k = 0; !still && k < steps.size() && inside(source_dw, qx, qy); ++k) {
        if (steps[k])
            step_vector(*steps[k], qx, qy, forward, vx, vy);
        px += vx;
        py += vy;
        qx = x + nearest(px);
        qy = y + nearest(py);
    }
    return { qx, qy, px - float(qx - x), py - float(qy - y), inside(source_dw, qx, qy) };
}

// The resampling taps of a source point over the 4x4 pixels around it,
// weighted by a kernel and normalised over the taps inside `from`; a
// bounded sample (Keys' cubic) lies within the values of its `inner` taps,
// the 2x2 pixels around the point.
struct Taps {
    int n = 0, ninner = 0;
    size_t at[16];
    float w[16], w2[16];  // the weights and their squares
    size_t inner[4];
};

// A kernel's four weights at fraction t in [0, 1) of the way from pixel 1
// to pixel 2.
using Kernel = void (*)(float t, float* k);

// Bilinear: the 2x2 pixels around the point.
void linear_weights(float t, float* k)
{
    k[0] = 0.0f;
    k[1] = 1.0f - t;
    k[2] = t;
    k[3] = 0.0f;
}

// Keys' cubic (Catmull-Rom, a = -0.5): sharper than bilinear, but its
// negative lobes overshoot at edges unless bounded.
void cubic_weights(float t, float* k)
{
    const float t2 = t * t, t3 = t2 * t;
    k[0] = 0.5f * (-t3 + 2.0f * t2 - t);
    k[1] = 1.5f * t3 - 2.5f * t2 + 1.0f;
    k[2] = -1.5f * t3 + 2.0f * t2 + 0.5f * t;
    k[3] = 0.5f * (t3 - t2);
}

// The pixel cell a source's point lies in: its top-left pixel (bx, by)
// and the point's fractions (tx, ty) across it, from the nearest pixel, so
// the same at any data window origin.
struct Cell {
    int bx, by;
    float tx, ty;
};

Cell cell_of(const Source& s)
{
    return { s.qx + (s.dx < 0.0f ? -1 : 0), s.qy + (s.dy < 0.0f ? -1 : 0),
             s.dx < 0.0f ? 1.0f + s.dx : s.dx, s.dy < 0.0f ? 1.0f + s.dy : s.dy };
}

Taps resampling_taps(const Source& s, const ROI& from, Kernel kernel, bool bounded)
{
    const Cell cell = cell_of(s);
    const int bx = cell.bx, by = cell.by;
    float kx[4], ky[4];
    kernel(cell.tx, kx);
    kernel(cell.ty, ky);
    Taps t;
    float total = 0.0f;
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
            const int x = bx - 1 + i, y = by - 1 + j;
            const float wt = kx[i] * ky[j];
            if (wt == 0.0f || !inside(from, x, y))
                continue;
            t.at[t.n]  = pixel_offset(from, x, y);
            t.w[t.n++] = wt;
            total += wt;
            if (bounded && (i == 1 || i == 2) && (j == 1 || j == 2))
                t.inner[t.ninner++] = t.at[t.n - 1];
        }
    for (int k = 0; k < t.n; ++k) {
        t.w[k] /= total;
        t.w2[k] = t.w[k] * t.w[k];
    }
    return t;
}

// The bilinear taps of a source (a point with no source: none).
Taps linear_taps(const Source& s, const ROI& from)
{
    return s.ok ? resampling_taps(s, from, linear_weights, false) : Taps();
}

// The bounded cubic taps of a source (a point with no source: none).
Taps cubic_taps(const Source& s, const ROI& from)
{
    return s.ok ? resampling_taps(s, from, cubic_weights, true) : Taps();
}

// The source's pixel at `o` of each plane of `planes` as the taps sample
// it, within the inner taps' values if the taps are bounded; with
// `squared` (a variance), the taps' values times their squared weights.
void sample(const std::vector<LargeVector<float>>& src, std::vector<LargeVector<float>>& out,
            size_t o, const Taps& t, bool squared)
{
    const float* w = squared ? t.w2 : t.w;
    for (size_t c = 0; c < src.size(); ++c) {
        const float* v = src[c].data();
        float sum      = 0.0f;
        for (int k = 0; k < t.n; ++k)
            sum += w[k] * v[t.at[k]];
        if (!squared && t.ninner > 0) {
            float lo = v[t.inner[0]], hi = lo;
            for (int k = 1; k < t.ninner; ++k) {
                lo = std::min(lo, v[t.inner[k]]);
                hi = std::max(hi, v[t.inner[k]]);
            }
            sum = std::min(hi, std::max(lo, sum));
        }
        out[c][o] = sum;
    }
}

// How many standard deviations of the source's noise the estimated
// resampling error of a carried pixel may reach for it to count as
// faithful (`CarriedFrame::faithful`): a neighbour that errs by that much
// raises the spread it joins by at most a quarter of its variance.
constexpr float faithful_error_sigmas = 0.5f;

// Whether the bilinear sample at `s` of every plane of `colour` (over
// `from`) is within `faithful_error_sigmas` of the noise of the cell's
// pixels (the mean of their `variance`): in each plane the interpolation
// error tx (1 - tx) / 2 |f_xx| + ty (1 - ty) / 2 |f_yy|, exact for a
// quadratic, f_xx the larger of the cell's two columns' second
// differences along x (each the mean over the cell's two rows), f_yy
// alike; false where the 4x4 pixels around the point leave `from`.
bool resampled_within_noise(const Source& s, const ROI& from,
                            const std::vector<LargeVector<float>>& colour,
                            const std::vector<LargeVector<float>>& variance)
{
    const Cell cell = cell_of(s);
    const int bx = cell.bx, by = cell.by;
    if (!inside(from, bx - 1, by - 1) || !inside(from, bx + 2, by + 2))
        return false;
    const float cx = 0.5f * cell.tx * (1.0f - cell.tx), cy = 0.5f * cell.ty * (1.0f - cell.ty);
    const float allowed = faithful_error_sigmas * faithful_error_sigmas;
    // The 4x4 pixels from (bx - 1, by - 1), row by row.
    const size_t corner = pixel_offset(from, bx - 1, by - 1), row = size_t(from.width());
    size_t at[4][4];
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i)
            at[j][i] = corner + size_t(j) * row + size_t(i);
    for (size_t c = 0; c < colour.size(); ++c) {
        const float* v  = colour[c].data();
        const float* vv = variance[c].data();
        float fxx = 0.0f, fyy = 0.0f, mean_variance = 0.0f;
        for (int i = 1; i <= 2; ++i) {
            // Column i along x and row i along y, each over the cell's two
            // rows (columns).
            float sx = 0.0f, sy = 0.0f;
            for (int j = 1; j <= 2; ++j) {
                sx += v[at[j][i - 1]] - 2.0f * v[at[j][i]] + v[at[j][i + 1]];
                sy += v[at[i - 1][j]] - 2.0f * v[at[i][j]] + v[at[i + 1][j]];
                mean_variance += 0.25f * vv[at[j][i]];
            }
            fxx = std::max(fxx, std::abs(0.5f * sx));
            fyy = std::max(fyy, std::abs(0.5f * sy));
        }
        const float error = cx * fxx + cy * fyy;
        if (!(error * error <= allowed * mean_variance))
            return false;
    }
    return true;
}

// Planes shaped as `src`'s (with its finite mask if any) over `region`.
Planes<float> planes_like(const Planes<float>& src, const ROI& region)
{
    Planes<float> out(region, src.nchannels());
    if (src.masked())
        out.finite = Planes<float>(region, src.nchannels()).values;
    return out;
}

}  // namespace

WarpMap motion_warp_map(const std::vector<const GuideChannels*>& steps, int offset,
                        const ROI& region, const ROI& source_dw, int nthreads)
{
    WarpMap map { Plane<int32_t>(region), Plane<int32_t>(region), Plane<float>(region),
                  Plane<float>(region) };
    parallel_rows(region, nthreads, [&](int y) {
        for (int x = region.xbegin; x < region.xend; ++x) {
            const Source s  = trace(steps, offset, source_dw, x, y);
            map.xs.at(x, y) = s.ok ? s.qx : WarpMap::no_source;
            map.ys.at(x, y) = s.ok ? s.qy : WarpMap::no_source;
            map.dx.at(x, y) = s.dx;
            map.dy.at(x, y) = s.dy;
        }
    });
    return map;
}

Planes<float> warp_planes(const Planes<float>& src, const WarpMap& map, const ROI& region,
                          int nthreads)
{
    Planes<float> out = planes_like(src, region);
    parallel_rows(region, nthreads, [&](int y) {
        for (int x = region.xbegin; x < region.xend; ++x) {
            const size_t i = map.xs.offset(x, y), o = out.offset(x, y);
            const Source s { map.xs.values[i], map.ys.values[i], map.dx.values[i],
                             map.dy.values[i], map.has_source(i) };
            const Taps t = cubic_taps(s, src.region);
            sample(src.values, out.values, o, t, false);
            sample(src.finite, out.finite, o, t, false);
        }
    });
    return out;
}

CarriedFrame carry_frame(const FeatureInputs& src, const Planes<float>& excess,
                         const ROI& source_dw,
                         const std::vector<const GuideChannels*>& steps, int offset,
                         const CarryRegions& regions, int nthreads)
{
    const ROI& all = regions.colour;
    CarriedFrame out { { planes_like(src.colour.colour, regions.colour), Plane<float>() },
                       { planes_like(src.variance.colour, regions.variance), Plane<float>() },
                       { Planes<float>(regions.colour, src.features.dims.nchannels()), IdPlane() },
                       planes_like(src.values, regions.window),
                       Plane<float>(regions.colour), Plane<float>(regions.colour),
                       planes_like(excess, regions.window) };
    const bool ids = !src.features.ids.values.empty();
    if (ids)
        out.features.ids = IdPlane(regions.colour);
    parallel_rows(all, nthreads, [&](int y) {
        for (int x = all.xbegin; x < all.xend; ++x) {
            const Source s = trace(steps, offset, source_dw, x, y);
            const Taps t = linear_taps(s, source_dw);
            const size_t oc = out.colour.colour.offset(x, y);
            const size_t q  = s.ok ? pixel_offset(source_dw, s.qx, s.qy) : 0;
            for (size_t d = 0; d < out.features.dims.values.size(); ++d)
                out.features.dims.values[d][oc] = s.ok ? src.features.dims.values[d][q] : 0.0f;
            if (ids)
                out.features.ids.values[oc] = s.ok ? src.features.ids.values[q] : no_guide_id;
            out.usable.values[oc]   = s.ok ? 1.0f : 0.0f;
            const bool in_place = s.qx == x && s.qy == y && s.dx == 0.0f && s.dy == 0.0f;
            const bool faithful = s.ok
                                  && (in_place
                                      || resampled_within_noise(s, source_dw,
                                                                src.colour.colour.values,
                                                                src.variance.colour.values));
            out.faithful.values[oc] = faithful ? 1.0f : 0.0f;
            sample(src.colour.colour.values, out.colour.colour.values, oc, t, false);
            sample(src.colour.colour.finite, out.colour.colour.finite, oc, t, false);
            if (inside(regions.variance, x, y)) {
                const size_t ov = out.variance.colour.offset(x, y);
                sample(src.variance.colour.values, out.variance.colour.values, ov, t, true);
                sample(src.variance.colour.finite, out.variance.colour.finite, ov, t, false);
            }
            if (!inside(regions.window, x, y))
                continue;
            const size_t o = out.values.offset(x, y);
            const Taps sharp = cubic_taps(s, source_dw);
            sample(src.values.values, out.values.values, o, sharp, false);
            sample(src.values.finite, out.values.finite, o, sharp, false);
            sample(excess.values, out.excess.values, o, t, false);
        }
    });
    return out;
}

bool load_motions(const char* op, ImageBuf& dst, const FrameInput& centre,
                  const std::vector<FrameInput>& neighbours, int nthreads,
                  std::vector<std::unique_ptr<GuideChannels>>& motions)
{
    motions.clear();
    for (size_t i = 0; i <= neighbours.size(); ++i) {
        const FrameInput& f = i == 0 ? centre : neighbours[i - 1];
        motions.emplace_back();
        if (!f.guides.motion)
            continue;
        motions.back() = std::make_unique<GuideChannels>();
        if (!load_guide_channels(op, dst, *f.guides.motion, f.beauty->roi(), nthreads,
                                 *motions.back()))
            return false;
    }
    return true;
}

std::vector<const GuideChannels*> motion_steps(const std::vector<const GuideChannels*>& motions,
                                               const std::vector<int>& offsets, int offset)
{
    std::vector<const GuideChannels*> steps;
    const int sign = offset > 0 ? 1 : -1;
    // The frame k steps away: the centre (motions[0]), or the neighbour at
    // offset sign * k (motions[1 + its index]) when there is one.
    for (int k = 0; k < sign * offset; ++k) {
        const auto at = std::find(offsets.begin(), offsets.end(), sign * k);
        const size_t i = k == 0 ? 0 : at == offsets.end() ? motions.size()
                                                          : 1 + size_t(at - offsets.begin());
        steps.push_back(i < motions.size() ? motions[i] : nullptr);
    }
    return steps;
}

}  // namespace mcdenoise
