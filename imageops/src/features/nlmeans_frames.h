// nlmeans_frames.h: NL-means over several frames in one pixel grid: the
// filtered frame's own search window and, for the cross-frame denoise,
// windows in neighbour frames already carried into that grid.
#pragma once

#include "core/operation.h"
#include "core/plane.h"
#include "features/feature_field.h"

#include <vector>

namespace mcdenoise {

/// One frame the search windows reach into, over the filtered frame's
/// regions (colour over the patches grown by one, variance over the
/// patches, features and values over the search windows).
struct NlmFrame {
    const ColourField* colour;
    const VarianceField* variance;
    /// This frame's features and the filtered frame's, compared as
    /// `FeatureField::weights_row` does (the same dimensions, same scales).
    const FeatureField* features;
    const FeatureField* centre_features;
    /// Every channel; all frames' `masked()` must agree.
    const SumSource* values;
    /// A factor on every weight of a pixel of this frame, over the search
    /// region; nullptr for 1.
    const Plane<float>* usable;
    int search_radius;
    /// True for the filtered frame itself: its pixel weighs 1 for itself.
    bool own;
};

/// The NL-means average over the windows of every frame in order, with
/// patch radius `patch_radius` and `strength`, into `result` (over
/// `result.roi`, whose channels select the values'): the patches of the
/// filtered pixels are read from `colour` (over the ROI grown by the patch
/// radius) with the variance `variance` and compared with each frame's own
/// patches and variance; `dw` is the filtered frame's data window.
void nlmeans_frames(const std::vector<NlmFrame>& frames, const ColourField& colour,
                    const VarianceField& variance, const OIIO::ROI& dw, int patch_radius,
                    float strength, int nthreads, ResultPixels& result);

/// `nlmeans_frames` over `roi` into `dst`, as `nlmeans` writes it: `like`
/// is the image the result is shaped after (its data window `dw`),
/// `inputs` every image read (for in-place detection).
bool nlmeans_frames(const char* op, OIIO::ImageBuf& dst, const OIIO::ImageBuf& like,
                    std::initializer_list<const OIIO::ImageBuf*> inputs,
                    const std::vector<NlmFrame>& frames, const ColourField& colour,
                    const VarianceField& variance, int patch_radius, float strength,
                    const OIIO::ROI& roi, int nthreads);

/// The weight `nlmeans_frames` gives frame `q`'s pixel at offset 0 from
/// each pixel of `w.region` (inside `dw`): 1 for the filtered frame
/// itself, else its patch against `colour`, `variance` and its features
/// against `q.centre_features`, times `q.usable`; into `w`.
void match_weights(const NlmFrame& q, const ColourField& colour, const VarianceField& variance,
                   const OIIO::ROI& dw, int patch_radius, float strength, int nthreads,
                   Plane<float>& w);

/// A pixel's coordinates.
struct PixelXY {
    int x, y;
};

/// Where `nlmeans_frames` also copies the weights the filtered frame's own
/// window gives some of the pixels it filters: `index` over a region
/// holding the ROI (k >= 0 for the k-th such pixel, -1 for the others),
/// and for pixel k and offset (dx, dy) the weight goes to `weights[k *
/// side^2 + (dy + r) * side + dx + r]` (r: the own frame's search radius,
/// side = 2 r + 1), as `window_weights` lays them out.
struct WeightTap {
    Plane<int32_t> index;
    float* weights = nullptr;
};

/// The weights `nlmeans_frames` gives the pixels of `frame`'s window when
/// it filters each pixel of `pixels` (inside `dw`) with that one window:
/// for pixel k and offset (dx, dy), `weights[k * side^2 + (dy + r) * side
/// + dx + r]` (r: the frame's search radius, side = 2 r + 1), 0 for
/// offsets outside `dw`. `colour`, `variance` and the frame's planes must
/// cover the pixels' windows and patches.
void window_weights(const NlmFrame& frame, const ColourField& colour,
                    const VarianceField& variance, const OIIO::ROI& dw, int patch_radius,
                    float strength, const std::vector<PixelXY>& pixels, int nthreads,
                    std::vector<float>& weights);

}  // namespace mcdenoise
