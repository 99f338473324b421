// frame_warp.cpp: the motion-chained nearest-pixel map from the centre
// frame to a neighbour frame, and the planes it carries.
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

}  // namespace

WarpMap motion_warp_map(const std::vector<const GuideChannels*>& steps, int offset,
                        const ROI& region, const ROI& source_dw, int nthreads)
{
    WarpMap map { Plane<int32_t>(region), Plane<int32_t>(region), Plane<float>(region),
                  Plane<float>(region) };
    const bool forward = offset > 0;
    const bool still   = steps.empty() || !steps.front();
    parallel_rows(region, nthreads, [&](int y) {
        for (int x = region.xbegin; x < region.xend; ++x) {
            // The path from the pixel, as a displacement: the same at any
            // data window origin.
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
            const bool ok = inside(source_dw, qx, qy);
            map.xs.at(x, y) = ok ? qx : WarpMap::no_source;
            map.ys.at(x, y) = ok ? qy : WarpMap::no_source;
            map.dx.at(x, y) = px - float(qx - x);
            map.dy.at(x, y) = py - float(qy - y);
        }
    });
    return map;
}

namespace {

// Each of `values` (planes over `from`) at each pixel's nearest source,
// over `region`; `fill` where there is none or it lies outside `from`.
template<class T>
std::vector<LargeVector<T>> nearest_channels(const std::vector<const LargeVector<T>*>& values,
                                             const ROI& from, const WarpMap& map,
                                             const ROI& region, T fill, int nthreads)
{
    std::vector<LargeVector<T>> out;
    for (size_t c = 0; c < values.size(); ++c)
        out.emplace_back(plane_size(region));
    parallel_rows(region, nthreads, [&](int y) {
        for (int x = region.xbegin; x < region.xend; ++x) {
            const size_t i = map.xs.offset(x, y), o = pixel_offset(region, x, y);
            const int sx = map.xs.values[i], sy = map.ys.values[i];
            const bool ok = map.has_source(i) && inside(from, sx, sy);
            const size_t at = ok ? pixel_offset(from, sx, sy) : 0;
            for (size_t c = 0; c < values.size(); ++c)
                out[c][o] = ok ? (*values[c])[at] : fill;
        }
    });
    return out;
}

}  // namespace

namespace {

// The bilinear taps around pixel i's source in `from`: up to four
// (index, weight), the weights normalised over the taps inside; with
// `squared`, each normalised weight squared.
int bilinear_taps(const WarpMap& map, size_t i, const ROI& from, bool squared, size_t* at,
                  float* w)
{
    const float fx = map.dx.values[i], fy = map.dy.values[i];
    const int x0 = map.xs.values[i] + (fx < 0.0f ? -1 : 0);
    const int y0 = map.ys.values[i] + (fy < 0.0f ? -1 : 0);
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
        w[k] = squared ? (w[k] / total) * (w[k] / total) : w[k] / total;
    return n;
}

std::vector<LargeVector<float>> warp_channels(const std::vector<LargeVector<float>>& values,
                                              const ROI& from, const WarpMap& map,
                                              const ROI& region, bool squared, int nthreads)
{
    std::vector<LargeVector<float>> out;
    for (size_t c = 0; c < values.size(); ++c)
        out.emplace_back(plane_size(region));
    parallel_rows(region, nthreads, [&](int y) {
        for (int x = region.xbegin; x < region.xend; ++x) {
            const size_t i = map.xs.offset(x, y), o = pixel_offset(region, x, y);
            size_t at[4];
            float w[4];
            const int n = map.has_source(i) ? bilinear_taps(map, i, from, squared, at, w) : 0;
            for (size_t c = 0; c < values.size(); ++c) {
                float v = 0.0f;
                for (int k = 0; k < n; ++k)
                    v += w[k] * values[c][at[k]];
                out[c][o] = v;
            }
        }
    });
    return out;
}

}  // namespace

Planes<float> warp_planes(const Planes<float>& src, const WarpMap& map, const ROI& region,
                          bool variance, int nthreads)
{
    Planes<float> out;
    out.region = region;
    out.values = warp_channels(src.values, src.region, map, region, variance, nthreads);
    out.finite = warp_channels(src.finite, src.region, map, region, false, nthreads);
    return out;
}

ColourPlanes warp_colour(const ColourPlanes& src, const WarpMap& map, const ROI& region,
                         bool variance, int nthreads)
{
    return { warp_planes(src.colour, map, region, variance, nthreads), Plane<float>() };
}

FeatureField warp_features(const FeatureField& src, const WarpMap& map, const ROI& region,
                           int nthreads)
{
    FeatureField out;
    std::vector<const LargeVector<float>*> dims;
    for (const LargeVector<float>& dim : src.dims.values)
        dims.push_back(&dim);
    out.dims.region = region;
    out.dims.values = nearest_channels(dims, src.dims.region, map, region, 0.0f, nthreads);
    if (!src.ids.values.empty()) {
        out.ids.region = region;
        out.ids.values = std::move(nearest_channels<Id>({ &src.ids.values }, src.ids.region, map,
                                                        region, no_guide_id, nthreads)
                                       .front());
    }
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

Plane<float> source_mask(const WarpMap& map, const ROI& region, int nthreads)
{
    Plane<float> out(region);
    parallel_rows(region, nthreads, [&](int y) {
        for (int x = region.xbegin; x < region.xend; ++x)
            out.at(x, y) = map.has_source(map.xs.offset(x, y)) ? 1.0f : 0.0f;
    });
    return out;
}

}  // namespace mcdenoise
