// temporal.cpp: the cross-frame denoise: each frame prepared as `denoise`
// prepares it, the neighbours carried into the centre's pixel grid, the
// temporal guide, then one NL-means average over the centre's window and
// the neighbours' windows.
#include <mcdenoise/temporal.h>

#include "denoise_frame.h"
#include "energy_outliers.h"
#include "feature_field.h"
#include "frame_warp.h"
#include "guides.h"
#include "nlmeans_frames.h"
#include "operation.h"
#include "temporal_guide.h"
#include "window.h"

#include <algorithm>
#include <memory>
#include <numeric>
#include <string>

namespace mcdenoise {

using OIIO::ImageBuf;
using OIIO::ROI;

namespace {

constexpr const char* op_name = "denoise";

// A neighbour frame carried into the centre's regions.
struct Neighbour {
    ColourField colour;
    VarianceField variance;
    FeatureField features;
    SumSource values;
    Plane<float> usable;
};

// Which guides a frame has that `denoise` reads, as flags in the order of
// `Guides`.
std::string guide_set(const Guides& g)
{
    std::string s;
    for (const ImageBuf* p : { g.normal, g.depth, g.albedo, g.variance, g.half_a, g.half_b })
        s += p ? '1' : '0';
    return s;
}

bool same_window(const ROI& a, const ROI& b)
{
    return a.xbegin == b.xbegin && a.xend == b.xend && a.ybegin == b.ybegin && a.yend == b.yend
           && a.zbegin == b.zbegin && a.zend == b.zend;
}

// The checks of one frame's inputs against `roi`, its errors prefixed with
// `what` (the frame).
bool check_frame(ImageBuf& dst, const FrameInput& frame, const std::string& what,
                 const ROI& roi)
{
    const std::string op = std::string(op_name) + ": " + what;
    if (!frame.beauty) {
        dst.errorfmt("{}: no beauty", op);
        return false;
    }
    return check_denoise_guides(op.c_str(), dst, *frame.beauty, frame.guides, roi)
           && (!frame.guides.motion
               || check_guide(op.c_str(), "motion", dst, *frame.guides.motion, 4, roi));
}

bool check_neighbours(ImageBuf& dst, const FrameInput& centre,
                      const std::vector<FrameInput>& neighbours, const std::vector<int>& offsets)
{
    if (neighbours.size() != offsets.size()) {
        dst.errorfmt("{}: {} neighbour frames but {} offsets", op_name, neighbours.size(),
                     offsets.size());
        return false;
    }
    for (size_t i = 0; i < neighbours.size(); ++i) {
        const std::string what = "neighbour frame at offset " + std::to_string(offsets[i]);
        if (offsets[i] == 0
            || std::count(offsets.begin(), offsets.end(), offsets[i]) > 1) {
            dst.errorfmt("{}: {}: offsets must be non-zero and distinct", op_name, what);
            return false;
        }
        const FrameInput& n = neighbours[i];
        if (!check_frame(dst, n, what, n.beauty ? n.beauty->roi() : ROI()))
            return false;
        if (!same_window(n.beauty->roi(), centre.beauty->roi())
            || n.beauty->nchannels() != centre.beauty->nchannels()) {
            dst.errorfmt("{}: {}: data window or channel count differs from the centre frame's",
                         op_name, what);
            return false;
        }
        if (guide_set(n.guides) != guide_set(centre.guides)) {
            dst.errorfmt("{}: {}: has not the centre frame's set of guides", op_name, what);
            return false;
        }
    }
    return true;
}

// Prepare neighbour `n` over its data window and carry it into `centre`'s
// regions through `map`.
bool load_neighbour(ImageBuf& dst, const FrameInput& n, const FeatureInputs& centre,
                    const WarpMap& map, int nthreads, Neighbour& out)
{
    ROI dw    = n.beauty->roi();
    dw.chbegin = 0;
    dw.chend   = n.beauty->nchannels();
    DenoiseFrame frame;
    FeatureInputs own;
    if (!prepare_denoise_frame(dst, *n.beauty, n.beauty->nchannels(), n.guides, dw, nthreads,
                               frame)
        || !load_feature_inputs(op_name, dst, frame.clamped, frame.guides,
                                temporal_feature_sigmas, dw, dw, nthreads, own))
        return false;
    const ROI search = centre.values.region;
    out.colour   = warp_colour(own.colour, map, centre.colour.region(), false, nthreads);
    out.variance = warp_colour(own.variance, map, centre.variance.region(), true, nthreads);
    out.features = warp_features(own.features, map, search, nthreads);
    out.values   = warp_planes(own.values, map, search, false, nthreads);
    out.usable   = source_mask(map, search, nthreads);
    return true;
}

// Give every frame's values a finite mask when any has one, so the sums
// treat them alike.
void align_masks(std::vector<SumSource*> values)
{
    const bool any = std::any_of(values.begin(), values.end(),
                                 [](const SumSource* v) { return v->masked(); });
    for (SumSource* v : values)
        if (any && !v->masked())
            v->finite = Planes<float>(v->region, v->nchannels(), 1.0f).values;
}

// Load every neighbour into the centre's regions (those of `fin`), in the
// order of their offsets, so the sums do not depend on the order they are
// listed in.
bool load_neighbours(ImageBuf& dst, const FrameInput& centre,
                     const std::vector<FrameInput>& neighbours, const std::vector<int>& offsets,
                     const FeatureInputs& fin, int nthreads,
                     std::vector<std::unique_ptr<Neighbour>>& loaded)
{
    std::vector<std::unique_ptr<GuideChannels>> motions;
    if (!load_motions(op_name, dst, centre, neighbours, nthreads, motions))
        return false;
    std::vector<size_t> order(neighbours.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::sort(order.begin(), order.end(),
              [&](size_t a, size_t b) { return offsets[a] < offsets[b]; });
    for (size_t i : order) {
        const WarpMap map = motion_warp_map(motion_steps(motions, offsets, offsets[i]),
                                            offsets[i], fin.colour.region(),
                                            neighbours[i].beauty->roi(), nthreads);
        loaded.push_back(std::make_unique<Neighbour>());
        if (!load_neighbour(dst, neighbours[i], fin, map, nthreads, *loaded.back()))
            return false;
    }
    return true;
}

// The temporal guide, then the NL-means average of `roi` over the centre's
// window (`fin`, prepared as `c`) and the neighbours' (`loaded`).
bool average_frames(ImageBuf& dst, const FrameInput& centre, const DenoiseFrame& c,
                    FeatureInputs& fin, const std::vector<std::unique_ptr<Neighbour>>& loaded,
                    const ROI& roi, int nthreads)
{
    std::vector<SumSource*> values { &fin.values };
    for (const auto& n : loaded)
        values.push_back(&n->values);
    align_masks(values);
    const int radius = centre.guides.motion ? temporal_search_radius
                                            : temporal_still_search_radius;
    std::vector<NlmFrame> frames { { &fin.colour, &fin.variance, &fin.features, &fin.features,
                                     &fin.values, nullptr, denoise_search_radius, true } };
    for (const auto& n : loaded)
        frames.push_back({ &n->colour, &n->variance, &n->features, &fin.features, &n->values,
                           &n->usable, radius, false });
    // The patches and features every candidate is compared with: the
    // centre's, averaged over the frames that match them.
    const ROI dw              = c.clamped.roi();
    const TemporalGuide guide = temporal_guide(frames, grow_and_clip(roi, denoise_patch_radius, dw),
                                               dw, denoise_patch_radius, c.strength, nthreads);
    for (NlmFrame& f : frames)
        f.centre_features = &guide.features;
    return nlmeans_frames(op_name, dst, c.clamped, { centre.beauty, &c.clamped }, frames,
                          guide.colour, guide.variance, denoise_patch_radius, c.strength, roi,
                          nthreads);
}

}  // namespace

bool denoise(ImageBuf& dst, const FrameInput& centre, const std::vector<FrameInput>& neighbours,
             const std::vector<int>& offsets, ROI roi, int nthreads)
{
    if (!centre.beauty) {
        dst.errorfmt("{}: the centre frame has no beauty", op_name);
        return false;
    }
    if (!check_neighbours(dst, centre, neighbours, offsets))
        return false;
    if (neighbours.empty())
        return denoise(dst, *centre.beauty, centre.guides, roi, nthreads);
    const ImageBuf& beauty = *centre.beauty;
    if (!resolve_roi(op_name, dst, beauty, roi) || !check_frame(dst, centre, "centre frame", roi))
        return false;
    DenoiseFrame c;
    FeatureInputs fin;
    if (!prepare_denoise_frame(dst, beauty, beauty.nchannels(), centre.guides,
                               denoise_region(beauty, roi), nthreads, c))
        return false;
    const ROI dw      = c.clamped.roi();
    const ROI search  = grow_and_clip(roi, denoise_search_radius, dw);
    const ROI patches = grow_and_clip(roi, denoise_search_radius + denoise_patch_radius, dw);
    if (!load_feature_inputs(op_name, dst, c.clamped, c.guides, temporal_feature_sigmas, search,
                             patches, nthreads, fin))
        return false;
    std::vector<std::unique_ptr<Neighbour>> loaded;
    if (!load_neighbours(dst, centre, neighbours, offsets, fin, nthreads, loaded))
        return false;
    if (!average_frames(dst, centre, c, fin, loaded, roi, nthreads)
        || !give_back_excess(op_name, dst, c.excess, roi, beauty.roi(),
                             premultiplied_alpha(beauty, beauty.nchannels()), nthreads))
        return false;
    dst.specmod().attribute("mcdenoise:denoise_frames", int(neighbours.size()) + 1);
    return true;
}

ImageBuf denoise(const FrameInput& centre, const std::vector<FrameInput>& neighbours,
                 const std::vector<int>& offsets, ROI roi, int nthreads)
{
    return value_form(
        [&](ImageBuf& dst) { return denoise(dst, centre, neighbours, offsets, roi, nthreads); });
}

}  // namespace mcdenoise
