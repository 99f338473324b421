// nlmeans_layers.h: the form of nlmeans that takes extra light layers
// (AOVs) along, as value planes the NL-means weights of the beauty average
// too (defined in nlmeans.cpp; used by denoise and denoise_layers).
#pragma once

#include <mcdenoise/features.h>

#include "core/operation.h"
#include "core/plane.h"
#include "features/nlmeans_frames.h"

#include <OpenImageIO/imagebuf.h>

#include <vector>

namespace mcdenoise {

/// Where the NL-means average of some value channels goes: the channels
/// [value_begin, value_begin + result->roi.nchannels()) of the values, into
/// `result` (over its ROI's pixels).
struct NlmTarget {
    ResultPixels* result;
    int value_begin;
};

/// `nlmeans_frames` into several targets over the same pixels (the first
/// target's ROI), every one averaged with the same weights; with `tap`,
/// the own frame's weights of the pixels it names go there too.
void nlmeans_frames(const std::vector<NlmFrame>& frames, const ColourField& colour,
                    const VarianceField& variance, const OIIO::ROI& dw, int patch_radius,
                    float strength, int nthreads, const std::vector<NlmTarget>& targets,
                    const WeightTap* tap = nullptr);

/// `nlmeans` of `beauty` into `dst`, averaging with the same weights the
/// values of each layer, `values[i]` (every channel of `*layers[i]`, over
/// the ROI grown by `search_radius` and clipped to the beauty's data
/// window, as `sum_source` gives them), into `dst_layers[i]` (resized to
/// the layer count; allocated over the ROI like `*layers[i]` if
/// uninitialized). The beauty's result is `nlmeans`'. With `tap`, the
/// weights of the pixels it names go there too (`nlmeans_frames`).
bool nlmeans_layers(OIIO::ImageBuf& dst, std::vector<OIIO::ImageBuf>& dst_layers,
                    const OIIO::ImageBuf& beauty, const std::vector<const OIIO::ImageBuf*>& layers,
                    std::vector<SumSource>&& values, const Guides& guides, int search_radius,
                    int patch_radius, float strength, const FeatureSigmas& sigmas, OIIO::ROI roi,
                    int nthreads, const WeightTap* tap = nullptr);

}  // namespace mcdenoise
