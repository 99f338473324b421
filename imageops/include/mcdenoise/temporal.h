// temporal.h: the cross-frame denoiser: one frame of a shot denoised with
// its neighbouring frames, so the shot does not flicker.
#pragma once

#include <mcdenoise/denoise.h>
#include <mcdenoise/export.h>
#include <mcdenoise/features.h>

#include <memory>
#include <string>
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
/// 1. Every frame goes through `denoise`'s first steps on its own: the
///    firefly clamp, and the variance from its guide, halves or estimate.
/// 2. Each neighbour is carried into the centre's pixel grid through the
///    motion guides: the colour its patches are compared by sampled
///    bilinearly where the motion leads (its variance as that of the
///    sample), every channel averaged with Keys' cubic (Catmull-Rom, kept
///    within the 2x2 pixels around the point: sharper, with no overshoot),
///    the features at the nearest pixel. For |offset| > 1 the vectors of the
///    frames in between are chained; a frame on the way that is left out
///    or has no motion guide repeats the previous step's vector. Without a
///    motion guide on the centre the neighbours are taken as they are, and
///    the search window in them is wider.
/// 3. The shot's own measure of its noise: at each pixel, every frame's
///    variance is raised to the sample variance of the colours of the
///    frames that agree there, when three or more do (the centre, and each
///    neighbour carried without resampling, its features matching and its
///    7x7 mean colour within the noise of such a mean of the centre's). On
///    a still shot it sees the noise a single frame's estimate misses (the
///    clusters of rare bright samples a pixel filter spreads); a moving
///    shadow or object disagrees over the box and is left out.
/// 4. The temporal guide: at each pixel, the centre's colour and features
///    averaged with each neighbour's at that pixel, the centre weighing 1
///    and a neighbour its NL-means weight against the centre (its patch's
///    variance-normalised distance and its features, as below). It is the
///    centre where no neighbour matches (disocclusions, moving shadows),
///    and a cleaner, steadier centre where they do.
/// 5. `denoise`'s NL-means average extends across frames: the centre's own
///    window (radius 5) and each neighbour's window of radius
///    `temporal_search_radius` (`temporal_still_search_radius` without
///    motion), every candidate weighed by the variance-normalised distance
///    of its patch to the guide's patch and by the feature weight of
///    features.h (fall-offs `temporal_feature_sigmas`) between the guide's
///    features and its own. So a neighbour pixel on another surface (another
///    normal, depth or albedo) or in another colour (a moving shadow) gets
///    no weight, nor does one carried from outside the neighbour's data
///    window. Every channel is averaged with the same weights. The object
///    id is not read, as in `denoise`.
/// 6. The excess the firefly clamp took out is given back as the shot's:
///    each frame's excess given out over its own frame as its `denoise`
///    does it (carried as the values are), averaged at each pixel with the
///    temporal guide's weights (the centre 1). A firefly is shared among
///    the frames that show the same surface, as its noise is; where no
///    neighbour matches, the centre keeps its own excess.
///
/// Every neighbour must have the centre's data window, channel count and
/// set of the guides `denoise` reads (normal, depth, albedo, variance,
/// halves); every frame's guides must cover its data window (each frame is
/// prepared whole, as `prepare_frame` does, whatever the ROI); a motion
/// guide has 4 channels; `offsets` must be distinct and non-zero. The
/// order of the neighbours does not change the result. The `dst`
/// attribute `mcdenoise:denoise_frames` is the count of frames used.
ImageBuf denoise(const FrameInput& centre, const std::vector<FrameInput>& neighbours,
                 const std::vector<int>& offsets, ROI roi = {}, int nthreads = 0);
/// Write to an existing image `dst` (allocating if it is uninitialized).
bool denoise(ImageBuf& dst, const FrameInput& centre, const std::vector<FrameInput>& neighbours,
             const std::vector<int>& offsets, ROI roi = {}, int nthreads = 0);

/// What `prepare_frame` keeps of a frame (the library's own type).
struct PreparedFrameData;

/// One frame of a shot ready for the cross-frame `denoise`: step 1 below
/// (`denoise`'s firefly clamp and variance) done over its whole data
/// window, and the planes the average reads (colour, variance, features,
/// every channel, the motion) converted once. A sequence prepares each
/// frame once and passes it to every window it is in, as the centre and
/// as a neighbour, instead of preparing it again for each. Copies share
/// the prepared planes, which never change. The frame's beauty and guide
/// images must stay alive and unchanged while it is used.
struct PreparedFrame {
    /// The prepared planes (the library's own type); null unless prepared
    /// successfully.
    std::shared_ptr<const PreparedFrameData> data;
    /// Why preparing failed; empty if it succeeded or was not attempted.
    std::string error;
};

/// Prepare `frame` for the cross-frame `denoise` (`PreparedFrame`), over
/// its data window, with the checks `denoise` makes of one frame (a
/// beauty; its guides readable and covering its data window; a motion
/// guide of 4 channels). On failure the result has no `data` and an
/// `error`. The prepared planes are bit-identical for any `nthreads`.
PreparedFrame prepare_frame(const FrameInput& frame, int nthreads = 0);

/// The cross-frame `denoise` of already prepared frames: the same result,
/// bit for bit, as the form above given the frames they were prepared
/// from, with the same checks (an unprepared frame or one that failed to
/// prepare is an error naming it).
ImageBuf denoise(const PreparedFrame& centre, const std::vector<PreparedFrame>& neighbours,
                 const std::vector<int>& offsets, ROI roi = {}, int nthreads = 0);
/// Write to an existing image `dst` (allocating if it is uninitialized).
bool denoise(ImageBuf& dst, const PreparedFrame& centre,
             const std::vector<PreparedFrame>& neighbours, const std::vector<int>& offsets,
             ROI roi = {}, int nthreads = 0);

/// Search radius in each neighbour frame carried by the motion guide.
constexpr int temporal_search_radius = 2;
/// Search radius in each neighbour frame when the centre has no motion
/// guide: the patch search alone finds the moved content.
constexpr int temporal_still_search_radius = 5;
/// Feature fall-offs of the cross-frame denoise, for every frame: albedo
/// and normal as `denoise_feature_sigmas` (their guides are noisy at low
/// sample counts too), depth as tight as `FeatureSigmas`' default: across
/// frames a depth change is the surest sign of a disocclusion.
constexpr FeatureSigmas temporal_feature_sigmas { 0.3f, 0.6f, 0.1f };

MCDENOISE_API_END
