// temporal_match.h: how the frames of a shot match the centre frame over
// one band of rows: the neighbours carried into the centre's pixel grid,
// the shot's own noise and the temporal guide with each neighbour's weight
// at each pixel. The cross-frame NL-means average (temporal.cpp) and the
// network's accumulated input (shot_accumulation.h) both start from it.
#pragma once

#include "shots/frame_warp.h"
#include "shots/temporal_frame.h"
#include "shots/temporal_guide.h"

#include <vector>

namespace mcdenoise {

/// The regions of the centre frame (data window `dw`) the cross-frame
/// average reads to filter `roi`, as `nlmeans` reads them: the colour (the
/// patches grown by one, and by the box `shot_variance` compares frames
/// over), the variance (the patches) and the features and values (the
/// search windows).
CarryRegions temporal_regions(const OIIO::ROI& roi, const OIIO::ROI& dw);

/// The indices of `offsets` in increasing order of offset: the order
/// `carry_neighbours` carries the neighbours in.
std::vector<size_t> offset_order(const std::vector<int>& offsets);

/// Carry every neighbour (the frames at `offsets`) into the centre's
/// regions `r`, appended to `carried` in the order of their offsets, so
/// that sums over them do not depend on the order they are listed in.
void carry_neighbours(const PreparedFrameData& centre,
                      const std::vector<const PreparedFrameData*>& neighbours,
                      const std::vector<int>& offsets, const CarryRegions& r, int nthreads,
                      std::vector<CarriedFrame>& carried);

/// The frames of one band as the cross-frame average compares them.
/// Not movable: `frames` points into `variances`.
struct BandMatch {
    /// The centre first (its own search window), then each carried
    /// neighbour; each variance the shot's own where it measured one.
    std::vector<NlmFrame> frames;
    std::vector<VarianceField> variances;  ///< the shot's noise, or empty
    /// The centre averaged with the neighbours that match it, and each
    /// neighbour's weight at offset 0 (over `band` grown by the patch
    /// radius).
    TemporalGuide guide;
};

/// Match the carried neighbours `carried` (carried into
/// `temporal_regions(band, dw)`) with `centre` over `band`: the shot's
/// noise (`shot_variance`), then the temporal guide, into `out`. `values`
/// are the centre's values the frames average (the centre's own, or a
/// copy masked alike with the neighbours'). Every frame's features are
/// then compared with the guide's.
void match_band(const PreparedFrameData& centre, const std::vector<CarriedFrame>& carried,
                const SumSource& values, const OIIO::ROI& band, int nthreads, BandMatch& out);

}  // namespace mcdenoise
