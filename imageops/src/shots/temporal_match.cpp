// temporal_match.cpp: the neighbours carried into a band of the centre
// frame and matched with it: the shot's noise and the temporal guide.
#include "shots/temporal_match.h"

#include "core/window.h"
#include "denoise/denoise_frame.h"
#include "shots/shot_variance.h"

#include <algorithm>
#include <numeric>

namespace mcdenoise {

using OIIO::ROI;

CarryRegions temporal_regions(const ROI& roi, const ROI& dw)
{
    const ROI patches = grow_and_clip(roi, denoise_search_radius + denoise_patch_radius, dw);
    return { grow_and_clip(patches, 1 + agreement_radius, dw), patches,
             grow_and_clip(roi, denoise_search_radius, dw) };
}

std::vector<size_t> offset_order(const std::vector<int>& offsets)
{
    std::vector<size_t> order(offsets.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::sort(order.begin(), order.end(),
              [&](size_t a, size_t b) { return offsets[a] < offsets[b]; });
    return order;
}

void carry_neighbours(const PreparedFrameData& centre,
                      const std::vector<const PreparedFrameData*>& neighbours,
                      const std::vector<int>& offsets, const CarryRegions& r, int nthreads,
                      std::vector<CarriedFrame>& carried)
{
    std::vector<const GuideChannels*> motions;
    for (const PreparedFrameData* f : neighbours)
        motions.push_back(f->has_motion() ? &f->motion : nullptr);
    motions.insert(motions.begin(), centre.has_motion() ? &centre.motion : nullptr);
    for (size_t i : offset_order(offsets))
        carried.push_back(carry_frame(neighbours[i]->planes, neighbours[i]->given_excess,
                                      neighbours[i]->input.beauty->roi(),
                                      motion_steps(motions, offsets, offsets[i]), offsets[i], r,
                                      nthreads));
}

void match_band(const PreparedFrameData& centre, const std::vector<CarriedFrame>& carried,
                const SumSource& values, const ROI& band, int nthreads, BandMatch& out)
{
    const FeatureInputs& c = centre.planes;
    const ROI dw           = centre.frame.clamped.roi();
    const int radius = centre.has_motion() ? temporal_search_radius
                                           : temporal_still_search_radius;
    out.frames = { { &c.colour, &c.variance, &c.features, &c.features, &values, nullptr,
                     denoise_search_radius, true } };
    for (const CarriedFrame& n : carried)
        out.frames.push_back({ &n.colour, &n.variance, &n.features, &c.features, &n.values,
                               &n.usable, radius, false });
    std::vector<const Plane<float>*> faithful;
    for (const CarriedFrame& n : carried)
        faithful.push_back(&n.faithful);
    out.variances = shot_variance(out.frames, faithful, temporal_regions(band, dw).variance, dw,
                                  nthreads);
    for (size_t k = 0; k < out.variances.size(); ++k)
        out.frames[k].variance = &out.variances[k];
    // The patches and features every candidate is compared with: the
    // centre's, averaged over the frames that match them.
    out.guide = temporal_guide(out.frames, grow_and_clip(band, denoise_patch_radius, dw), dw,
                               denoise_patch_radius, centre.frame.strength, nthreads);
    for (NlmFrame& f : out.frames)
        f.centre_features = &out.guide.features;
}

}  // namespace mcdenoise
