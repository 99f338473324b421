// temporal_guide.h: the patches the cross-frame denoise compares every
// candidate with: the centre frame averaged over the frames that show the
// same thing at each pixel, so the weights depend little on the centre's
// own noise and the frames of a shot weigh their pixels alike.
#pragma once

#include "features/nlmeans_frames.h"

#include <vector>

namespace mcdenoise {

/// Colour, variance and feature planes over one region.
struct TemporalGuide {
    ColourField colour;
    VarianceField variance;
    FeatureField features;  ///< dimensions only
    /// Each neighbour's weight (frames[1] on) at offset 0, over the region.
    std::vector<Plane<float>> weights;
};

/// At each pixel of `region` (inside `dw`, the centre's data window): the
/// colour of `frames[0]` (the centre, `own`) and of every other frame at
/// that pixel (offset 0, whatever their search radius), weighed as
/// `nlmeans_frames` weighs them (patch radius `patch_radius`, `strength`):
/// the centre 1, a neighbour by how well its patch and features match the
/// centre's (`match_weights`). The variance is that of the weighted mean,
/// sum(w^2 v) / (sum w)^2; the features the same weighted mean of the
/// frames' feature dimensions (`features`, as the frames scale them); the
/// neighbours' weights are kept (`weights`).
/// Every frame's colour, variance and features must cover `region`.
TemporalGuide temporal_guide(const std::vector<NlmFrame>& frames, const OIIO::ROI& region,
                             const OIIO::ROI& dw, int patch_radius, float strength,
                             int nthreads);

}  // namespace mcdenoise
