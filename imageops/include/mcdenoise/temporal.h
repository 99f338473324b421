// temporal.h: the cross-frame denoiser: one frame of a shot denoised with
// its neighbouring frames, so the shot does not flicker.
#pragma once

#include <mcdenoise/denoise.h>
#include <mcdenoise/export.h>
#include <mcdenoise/features.h>

#include <vector>

MCDENOISE_API_BEGIN

/// One frame of a shot: its noisy render and its own guides (its own
/// `motion` among them).
struct FrameInput {
    const ImageBuf* beauty = nullptr;
    Guides guides;
};

/// Denoise `centre` with its neighbouring frames: `neighbours[i]` is the
/// frame at offset `offsets[i]` from the centre (..., -2, -1, +1, +2, ...;
/// frames that do not exist, as at the ends of a shot, are simply left
/// out). With no neighbours the result is bit-identical to
/// `denoise(*centre.beauty, centre.guides, roi, nthreads)`.
///
/// Every frame goes through `denoise`'s first steps on its own (the
/// firefly clamp, the variance from its guide, halves or estimate). Each
/// neighbour is then carried into the centre's pixel grid through the
/// motion guides (nearest pixel; the vectors of the frames in between are
/// chained for |offset| > 1, the last one known standing in for a frame
/// that is left out, or without motion on it), or taken as it is when the
/// centre has no motion guide. The NL-means average of `denoise` then
/// extends across frames: besides the centre's own search window
/// (radius 5), each neighbour pixel within `temporal_search_radius` (with
/// motion; `temporal_still_search_radius` without) is weighed by the
/// variance-normalised distance of its patch to the centre's patch and by
/// the feature weight of features.h with the fall-offs
/// `temporal_feature_sigmas` between the centre's features and its own, so
/// a pixel the neighbour shows on another surface (disoccluded, another
/// normal, depth, albedo or object id) or in another colour (a moving
/// shadow) gets no weight. A pixel carried from outside the neighbour's
/// data window gets none either. Every channel is averaged with the same
/// weights.
///
/// Every neighbour must have the centre's data window, channel count and
/// set of guides (each covering its data window); `offsets` must be
/// distinct and non-zero. The result covers `roi` of the centre frame.
ImageBuf denoise(const FrameInput& centre, const std::vector<FrameInput>& neighbours,
                 const std::vector<int>& offsets, ROI roi = {}, int nthreads = 0);
/// Write to an existing image `dst` (allocating if it is uninitialized).
bool denoise(ImageBuf& dst, const FrameInput& centre, const std::vector<FrameInput>& neighbours,
             const std::vector<int>& offsets, ROI roi = {}, int nthreads = 0);

/// Search radius in each neighbour frame carried by the motion guide.
constexpr int temporal_search_radius = 2;
/// Search radius in each neighbour frame when the centre has no motion
/// guide: the patch search alone finds the moved content.
constexpr int temporal_still_search_radius = 5;
/// Feature fall-offs between the centre and a neighbour frame: the
/// defaults of `FeatureSigmas`, tighter than `denoise_feature_sigmas`,
/// since the same surface seen in two frames has the same features.
constexpr FeatureSigmas temporal_feature_sigmas {};

MCDENOISE_API_END
