// denoise_frame.h: the steps `denoise` takes on a frame before its
// NL-means average (the firefly clamp and the variance), shared with the
// cross-frame denoise of temporal.h.
#pragma once

#include <mcdenoise/features.h>

#include "core/plane.h"
#include "denoise/energy_outliers.h"

#include <OpenImageIO/imagebuf.h>

#include <string>

namespace mcdenoise {

/// A frame ready for `denoise`'s NL-means average. Not movable: `guides`
/// may point at `variance`.
struct DenoiseFrame {
    DenoiseFrame()                    = default;
    DenoiseFrame(const DenoiseFrame&) = delete;
    DenoiseFrame& operator=(const DenoiseFrame&) = delete;

    OIIO::ImageBuf clamped;   ///< the beauty, fireflies clamped
    Planes<float> excess;     ///< what the clamp took, per channel, to give back
    OIIO::ImageBuf variance;  ///< when not given as a guide
    Guides guides;            ///< the guides the average reads (variance set)
    float strength = 0.0f;    ///< the NL-means strength the variance calls for
    /// The outliers were judged by a measured noise (a variance guide or
    /// the halves): those that give excess are known fireflies.
    bool outliers_measured = false;
};

/// `denoise`'s steps before the average on `beauty` over `region` (all its
/// channels): split the fireflies off (`split_outliers`), then take the
/// variance from the guide, the halves or an estimate. Object ids are
/// dropped from the guides. The guides must have been checked; on failure
/// sets `dst`'s error. With `scales`, what the clamp did to each pixel goes
/// there too (`split_outliers`).
bool prepare_denoise_frame(OIIO::ImageBuf& dst, const OIIO::ImageBuf& beauty, const Guides& guides,
                           const OIIO::ROI& region, int nthreads,
                           DenoiseFrame& frame, SplitScales* scales = nullptr);

/// Where `frame`'s excess goes when `roi` is filtered (`dw`: the data
/// window): spread wide when its outliers were measured (known fireflies),
/// else the sources that reach `roi` (`excess_sources` over `roi` grown by
/// `denoise_search_radius`), whose weights the average of `roi` fills
/// through `weight_tap` and `finish_firefly_weights` completes.
ExcessWeights firefly_sources(const DenoiseFrame& frame, const OIIO::ROI& roi,
                              const OIIO::ROI& dw);

/// The frame of `planes` as `denoise` searches it: its own window of
/// radius `denoise_search_radius`, its features compared with its own.
NlmFrame own_window(const FeatureInputs& planes);

/// Complete `weights` after the average of `roi` filled those inside it:
/// the sources outside `roi` from `frame`'s own window (`fill_outside`, its
/// planes read over their windows), then every window normalised. On
/// failure sets `dst`'s error.
bool finish_firefly_weights(OIIO::ImageBuf& dst, const DenoiseFrame& frame, const OIIO::ROI& roi,
                            const OIIO::ROI& dw, int nthreads, ExcessWeights& weights);

/// The names of the guides `denoise` reads, comma separated (its `dst`
/// attribute `mcdenoise:denoise_guides`).
std::string denoise_guide_names(const Guides& guides);

/// Check the guides `denoise` reads (the feature guides and the halves)
/// against `roi`; on failure sets `dst`'s error prefixed with `op`.
bool check_denoise_guides(const char* op, OIIO::ImageBuf& dst, const OIIO::ImageBuf& beauty,
                          const Guides& guides, const OIIO::ROI& roi);

/// The region `denoise`'s steps read to filter `roi` of `beauty`: the
/// sources whose excess reaches `roi` (the Gaussian's radius, or the
/// windows of the sources within the search radius: twice it), their
/// patches and the two 3x3 windows of an estimated variance, clipped to the
/// data window, with all channels.
OIIO::ROI denoise_region(const OIIO::ImageBuf& beauty, const OIIO::ROI& roi);

/// `denoise`'s NL-means search and patch radii.
constexpr int denoise_search_radius = 5;
constexpr int denoise_patch_radius  = 1;

}  // namespace mcdenoise
