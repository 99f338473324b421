// frame_warp.cpp: the motion-chained nearest-pixel map from the centre
// frame to a neighbour frame, and the planes it carries.
#include "frame_warp.h"

#include "guides.h"
#include "window.h"

#include <cmath>

namespace mcdenoise {

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
    WarpMap map { Plane<int32_t>(region), Plane<int32_t>(region) };
    const bool forward = offset > 0;
    const bool still   = steps.empty() || !steps.front();
    parallel_rows(region, nthreads, [&](int y) {
        for (int x = region.xbegin; x < region.xend; ++x) {
            float px = float(x), py = float(y), vx = 0.0f, vy = 0.0f;
            int qx = x, qy = y;
            for (size_t k = 0; !still && k < steps.size() && inside(source_dw, qx, qy); ++k) {
                if (steps[k])
                    step_vector(*steps[k], qx, qy, forward, vx, vy);
                px += vx;
                py += vy;
                qx = nearest(px);
                qy = nearest(py);
            }
            const bool ok = inside(source_dw, qx, qy);
            map.xs.at(x, y) = ok ? qx : WarpMap::no_source;
            map.ys.at(x, y) = ok ? qy : WarpMap::no_source;
        }
    });
    return map;
}

template<class T>
Plane<T> warp_plane(const Plane<T>& src, const WarpMap& map, const ROI& region, T fill)
{
    Plane<T> out(region);
    for (int y = region.ybegin; y < region.yend; ++y)
        for (int x = region.xbegin; x < region.xend; ++x) {
            const size_t i = map.xs.offset(x, y);
            const int sx = map.xs.values[i], sy = map.ys.values[i];
            out.at(x, y) = map.has_source(i) && inside(src.region, sx, sy) ? src.at(sx, sy)
                                                                          : fill;
        }
    return out;
}

template Plane<float> warp_plane(const Plane<float>&, const WarpMap&, const ROI&, float);
template Plane<Id> warp_plane(const Plane<Id>&, const WarpMap&, const ROI&, Id);

namespace {

// Channel `values[c]` of planes over `from` as a plane of its own.
Plane<float> channel(const std::vector<LargeVector<float>>& values, size_t c, const ROI& from)
{
    Plane<float> p;
    p.region = from;
    p.values = values[c];
    return p;
}

std::vector<LargeVector<float>> warp_channels(const std::vector<LargeVector<float>>& values,
                                              const ROI& from, const WarpMap& map,
                                              const ROI& region)
{
    std::vector<LargeVector<float>> out;
    for (size_t c = 0; c < values.size(); ++c)
        out.push_back(warp_plane(channel(values, c, from), map, region, 0.0f).values);
    return out;
}

}  // namespace

Planes<float> warp_planes(const Planes<float>& src, const WarpMap& map, const ROI& region)
{
    Planes<float> out;
    out.region = region;
    out.values = warp_channels(src.values, src.region, map, region);
    out.finite = warp_channels(src.finite, src.region, map, region);
    return out;
}

ColourPlanes warp_colour(const ColourPlanes& src, const WarpMap& map, const ROI& region)
{
    return { warp_planes(src.colour, map, region),
             warp_plane(src.luminance, map, region, 0.0f) };
}

FeatureField warp_features(const FeatureField& src, const WarpMap& map, const ROI& region)
{
    FeatureField out;
    out.dims = warp_planes(src.dims, map, region);
    if (!src.ids.values.empty())
        out.ids = warp_plane(src.ids, map, region, no_guide_id);
    return out;
}

Plane<float> source_mask(const WarpMap& map, const ROI& region)
{
    Plane<float> out(region);
    for (int y = region.ybegin; y < region.yend; ++y)
        for (int x = region.xbegin; x < region.xend; ++x)
            out.at(x, y) = map.has_source(map.xs.offset(x, y)) ? 1.0f : 0.0f;
    return out;
}

}  // namespace mcdenoise
