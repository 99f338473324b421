// layer_channels.h: the forms of clamp_fireflies, denoise and nlmeans that
// take extra light layers (AOVs) along: as further channels of a stacked
// image, which the outlier scale multiplies like the colour, or as value
// planes the NL-means weights of the beauty average too.
#pragma once

#include <mcdenoise/features.h>

#include "nlmeans_frames.h"
#include "operation.h"
#include "plane.h"

#include <OpenImageIO/imagebuf.h>

#include <vector>

namespace mcdenoise {

/// `clamp_fireflies`, where channels from `layer_begin` on are scaled by
/// each pixel's factor like the colour channels; channels between the
/// colour and `layer_begin` (alpha) are copied. The factor is decided on
/// the colour alone. When `scales` is given it receives that factor of
/// every pixel of the ROI.
bool clamp_fireflies_layers(OIIO::ImageBuf& dst, const OIIO::ImageBuf& beauty, int layer_begin,
                            const Guides& guides, float factor, int radius, OIIO::ROI roi,
                            int nthreads, Plane<float>* scales = nullptr);

/// `denoise` of a stacked image: every weight and outlier scale is decided
/// on the colour and the guides and applied alike to every channel, the
/// outlier scale to the colour and the channels from `layer_begin` on.
bool denoise_stacked(OIIO::ImageBuf& dst, const OIIO::ImageBuf& beauty, int layer_begin,
                     const Guides& guides, OIIO::ROI roi, int nthreads);

/// Where the NL-means average of some value channels goes: the channels
/// [value_begin, value_begin + result->roi.nchannels()) of the values, into
/// `result` (over its ROI's pixels).
struct NlmTarget {
    ResultPixels* result;
    int value_begin;
};

/// `nlmeans_frames` into several targets over the same pixels (the first
/// target's ROI), every one averaged with the same weights.
void nlmeans_frames(const std::vector<NlmFrame>& frames, const ColourField& colour,
                    const VarianceField& variance, const OIIO::ROI& dw, int patch_radius,
                    float strength, int nthreads, const std::vector<NlmTarget>& targets);

/// `nlmeans` of `beauty` into `dst`, averaging with the same weights the
/// values of each layer, `values[i]` (every channel of `*layers[i]`, over
/// the ROI grown by `search_radius` and clipped to the beauty's data
/// window, as `sum_source` gives them), into `dst_layers[i]` (resized to
/// the layer count; allocated over the ROI like `*layers[i]` if
/// uninitialized). The beauty's result is `nlmeans`'.
bool nlmeans_layers(OIIO::ImageBuf& dst, std::vector<OIIO::ImageBuf>& dst_layers,
                    const OIIO::ImageBuf& beauty, const std::vector<const OIIO::ImageBuf*>& layers,
                    std::vector<SumSource>&& values, const Guides& guides, int search_radius,
                    int patch_radius, float strength, const FeatureSigmas& sigmas, OIIO::ROI roi,
                    int nthreads);

}  // namespace mcdenoise
