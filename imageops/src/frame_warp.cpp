// frame_warp.cpp: the motion-chained path from a pixel of the centre frame
// to a neighbour frame, the map of those paths, and the planes carried
// along them.
#include "frame_warp.h"

#include "guides.h"
#include "window.h"

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

// The bilinear taps around `s`'s point in `from`: up to four (index,
// weight), the weights normalised over the taps inside.
int bilinear_taps(const Source& s, const ROI& from, size_t* at, float* w)
{
    const float fx = s.dx, fy = s.dy;
    const int x0 = s.qx + (fx < 0.0f ? -1 : 0);
    const int y0 = s.qy + (fy < 0.0f ? -1 : 0);
    const float ax = fx < 0.0f ? 1.0f + fx : fx, ay = fy < 0.0f ? 1.0f + fy : fy;
    int n       = 0;
    float total = 0.0f;
    for (int ty = 0; ty < 2; ++ty)
        for (int tx = 0; tx < 2; ++tx) {
            const float wt = (tx ? ax : 1.0f - ax) * (ty ? ay : 1.0f - ay);
            if (wt <= 0.0f || !inside(from, x0 + tx, y0 + ty))
                continue;
            at[n] = pixel_offset(from, x0 + tx, y0 + ty);
            w[n++] = wt;
            total += wt;
        }
    for (int k = 0; k < n; ++k)
        w[k] = w[k] / total;
    return n;
}

// The source's pixel at `o` of each plane of `planes` as the taps sample
// it, each tap's weight squared with `squared`.
void sample(const std::vector<LargeVector<float>>& src, std::vector<LargeVector<float>>& out,
            size_t o, int n, const size_t* at, const float* w, bool squared)
{
    for (size_t c = 0; c < src.size(); ++c) {
        float v = 0.0f;
        for (int k = 0; k < n; ++k)
            v += (squared ? w[k] * w[k] : w[k]) * src[c][at[k]];
        out[c][o] = v;
    }
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
            size_t at[4];
            float w[4];
            const int n = s.ok ? bilinear_taps(s, src.region, at, w) : 0;
            sample(src.values, out.values, o, n, at, w, false);
            sample(src.finite, out.finite, o, n, at, w, false);
        }
    });
    return out;
}

CarriedFrame carry_frame(const FeatureInputs& src, const ROI& source_dw,
                         const std::vector<const GuideChannels*>& steps, int offset,
                         const CarryRegions& regions, int nthreads)
{
    const ROI& all = regions.colour;
    CarriedFrame out { { planes_like(src.colour.colour, regions.colour), Plane<float>() },
                       { planes_like(src.variance.colour, regions.variance), Plane<float>() },
                       { Planes<float>(regions.window, src.features.dims.nchannels()), IdPlane() },
                       planes_like(src.values, regions.window),
                       Plane<float>(regions.window) };
    const bool ids = !src.features.ids.values.empty();
    if (ids)
        out.features.ids = IdPlane(regions.window);
    parallel_rows(all, nthreads, [&](int y) {
        for (int x = all.xbegin; x < all.xend; ++x) {
            const Source s = trace(steps, offset, source_dw, x, y);
            size_t at[4];
            float w[4];
            const int n = s.ok ? bilinear_taps(s, source_dw, at, w) : 0;
            const size_t oc = out.colour.colour.offset(x, y);
            sample(src.colour.colour.values, out.colour.colour.values, oc, n, at, w, false);
            sample(src.colour.colour.finite, out.colour.colour.finite, oc, n, at, w, false);
            if (inside(regions.variance, x, y)) {
                const size_t ov = out.variance.colour.offset(x, y);
                sample(src.variance.colour.values, out.variance.colour.values, ov, n, at, w, true);
                sample(src.variance.colour.finite, out.variance.colour.finite, ov, n, at, w,
                       false);
            }
            if (!inside(regions.window, x, y))
                continue;
            const size_t o = out.values.offset(x, y);
            sample(src.values.values, out.values.values, o, n, at, w, false);
            sample(src.values.finite, out.values.finite, o, n, at, w, false);
            const size_t q = s.ok ? pixel_offset(source_dw, s.qx, s.qy) : 0;
            for (size_t d = 0; d < out.features.dims.values.size(); ++d)
                out.features.dims.values[d][o] = s.ok ? src.features.dims.values[d][q] : 0.0f;
            if (ids)
                out.features.ids.values[o] = s.ok ? src.features.ids.values[q] : no_guide_id;
            out.usable.values[o] = s.ok ? 1.0f : 0.0f;
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
