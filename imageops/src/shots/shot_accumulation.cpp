// shot_accumulation.cpp: a frame averaged with its carried neighbours, each
// weighed by the temporal guide's weight at each pixel.
#include "shots/shot_accumulation.h"

#include "core/pixel_block.h"
#include "core/window.h"
#include "shots/shot_variance.h"
#include "shots/temporal_match.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;

namespace {

// The least temporal guide weight (exp(-d), d the patch's distance beyond
// the noise in the units of `nlmeans`' strength) at which a neighbour whose
// box mean agrees counts fully: d = 4, about three standard deviations of
// the distance two noisy 3x3 patches of the same thing have.
constexpr float patch_agreement = 0.0183f;

// How far a neighbour's motion (its 4 channels, carried to the centre's
// pixel) may differ from the centre's for it to show the same surface:
// `motion_tolerance` pixels plus `motion_tolerance_share` of the centre's
// motion (a surface's vectors change little from frame to frame; another
// object's, uncovered or covered by the motion, differ).
constexpr float motion_tolerance       = 0.5f;
constexpr float motion_tolerance_share = 0.1f;

// Every channel of `image` over its data window as planes (masked where a
// value is not finite).
bool image_planes(ImageBuf& dst, const ImageBuf& image, int nthreads, Planes<float>& out)
{
    ROI all     = image.roi();
    all.chbegin = 0;
    all.chend   = image.nchannels();
    PixelBlock block;
    if (!load_block(image, all, block)) {
        dst.errorfmt("{}: cannot read a frame: {}", temporal_op, image.geterror());
        return false;
    }
    out = channel_planes(block, nthreads);
    return true;
}

// The value of channel `c` of `p` at (x, y), and whether it counts (finite).
float value_at(const Planes<float>& p, int c, int x, int y, bool& counts)
{
    counts = !p.masked() || *p.finite_from(c, x, y) > 0.0f;
    return counts ? *p.from(c, x, y) : 0.0f;
}

// `band` of `out` (a float image): the centre's planes averaged with the
// carried neighbours' (`carried`, in offset order) with the guide's
// weights.
void average_band(const Planes<float>& centre, const std::vector<Planes<float>>& carried,
                  const std::vector<Plane<float>>& weights, const ROI& band, int nthreads,
                  ImageBuf& out)
{
    parallel_rows(band, nthreads, [&](int y) {
        for (int x = band.xbegin; x < band.xend; ++x) {
            float* pixel = static_cast<float*>(out.pixeladdr(x, y));
            for (int c = 0; c < centre.nchannels(); ++c) {
                bool counts     = true;
                const float own = value_at(centre, c, x, y, counts);
                float sum = own, total = 1.0f;
                for (size_t k = 0; k < carried.size(); ++k) {
                    const float v = value_at(carried[k], c, x, y, counts);
                    const float w = counts ? weights[k].at(x, y) : 0.0f;
                    sum += w * v;
                    total += w;
                }
                pixel[c] = sum / total;
            }
        }
    });
}

// 1 where `map` takes the centre's pixel from the same pixel of the
// neighbour, unmoved (nothing resampled), else 0, over `band`.
Plane<float> in_place(const WarpMap& map, const ROI& band)
{
    Plane<float> out(band, 0.0f);
    for (int y = band.ybegin; y < band.yend; ++y)
        for (int x = band.xbegin; x < band.xend; ++x) {
            const size_t i = map.xs.offset(x, y);
            if (map.xs.values[i] == x && map.ys.values[i] == y && map.dx.values[i] == 0.0f
                && map.dy.values[i] == 0.0f)
                out.values[out.offset(x, y)] = 1.0f;
        }
    return out;
}

// Each neighbour's weight over `band`: 1 where it is in place (`unmoved`:
// a still shot, or still parts of one) and agrees with the centre
// (`shot_agreement`: its features, and its box mean within the noise) and
// its 3x3 patch is not far beyond the noise either (a guide weight of at
// least `patch_agreement`: a thin line leaves the box mean alone but not
// the patch); elsewhere the temporal guide's weight. A resampled neighbour
// keeps the guide's weight: resampling and the motion's own errors are
// more than a box mean sees.
std::vector<Plane<float>> accumulation_weights(const BandMatch& match,
                                               const std::vector<Plane<float>>& unmoved,
                                               const ROI& band, const ROI& dw, int nthreads)
{
    std::vector<const Plane<float>*> in_place;
    for (const Plane<float>& p : unmoved)
        in_place.push_back(&p);
    std::vector<Plane<float>> weights = shot_agreement(match.frames, in_place, band, dw, nthreads);
    for (size_t k = 0; k < weights.size(); ++k)
        for (int y = band.ybegin; y < band.yend; ++y)
            for (int x = band.xbegin; x < band.xend; ++x) {
                float& w      = weights[k].values[weights[k].offset(x, y)];
                const float g = match.guide.weights[k].at(x, y);
                w             = w > 0.0f && g >= patch_agreement ? 1.0f : g;
            }
    return weights;
}

// Zero `weight` (over `band`) where the neighbour's motion carried to the
// centre's pixel (`carried`) is not the centre's own (`centre`, over the
// data window): a pixel the motion uncovers or covers, where the
// neighbour shows another object.
void keep_consistent_motion(const Planes<float>& centre, const Planes<float>& carried,
                            const ROI& band, Plane<float>& weight)
{
    for (int y = band.ybegin; y < band.yend; ++y)
        for (int x = band.xbegin; x < band.xend; ++x) {
            float apart = 0.0f, length = 0.0f;
            for (int c = 0; c < centre.nchannels(); ++c) {
                const float v = *centre.from(c, x, y), d = v - *carried.from(c, x, y);
                apart += d * d;
                length += v * v;
            }
            const float allowed = motion_tolerance + motion_tolerance_share * std::sqrt(length);
            if (!(apart <= allowed * allowed))
                weight.values[weight.offset(x, y)] = 0.0f;
        }
}

}  // namespace

bool accumulate_shot(ImageBuf& dst, const PreparedFrameData& centre,
                     const std::vector<const PreparedFrameData*>& neighbours,
                     const std::vector<int>& offsets, const std::vector<const ImageBuf*>& images,
                     const ROI& roi, int nthreads)
{
    const ROI dw = centre.input.beauty->roi();
    std::vector<Planes<float>> planes(images.size());
    for (size_t i = 0; i < images.size(); ++i)
        if (!image_planes(dst, *images[i], nthreads, planes[i]))
            return false;
    ROI all     = roi;
    all.chbegin = 0;
    all.chend   = planes[0].nchannels();
    dst.reset(OIIO::ImageSpec(all, OIIO::TypeDesc::FLOAT));
    std::vector<const GuideChannels*> motions { centre.has_motion() ? &centre.motion : nullptr };
    for (const PreparedFrameData* f : neighbours)
        motions.push_back(f->has_motion() ? &f->motion : nullptr);
    const std::vector<size_t> order = offset_order(offsets);
    std::vector<CarriedFrame> carried;
    std::vector<Planes<float>> warped;
    for (int y = roi.ybegin; y < roi.yend; y += accumulation_band_rows) {
        ROI band    = roi;
        band.ybegin = y;
        band.yend   = std::min(roi.yend, y + accumulation_band_rows);
        carried.clear();
        warped.clear();
        carry_neighbours(centre, neighbours, offsets, temporal_regions(band, dw), nthreads,
                         carried);
        BandMatch match;
        match_band(centre, carried, centre.planes.values, band, nthreads, match);
        std::vector<WarpMap> maps;
        std::vector<Plane<float>> unmoved;
        for (size_t i : order) {
            maps.push_back(motion_warp_map(motion_steps(motions, offsets, offsets[i]), offsets[i],
                                           band, dw, nthreads));
            unmoved.push_back(in_place(maps.back(), band));
            warped.push_back(warp_planes(planes[i + 1], maps.back(), band, nthreads));
        }
        std::vector<Plane<float>> weights = accumulation_weights(match, unmoved, band, dw, nthreads);
        for (size_t k = 0; k < order.size(); ++k)
            if (centre.has_motion() && neighbours[order[k]]->has_motion())
                keep_consistent_motion(centre.motion,
                                       warp_planes(neighbours[order[k]]->motion, maps[k], band,
                                                   nthreads),
                                       band, weights[k]);
        average_band(planes[0], warped, weights, band, nthreads, dst);
    }
    return true;
}

}  // namespace mcdenoise
