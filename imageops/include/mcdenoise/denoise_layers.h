// denoise_layers.h: `denoise` of a beauty together with its light passes
// (AOVs), one per-pixel operator for all, so passes that add up to the
// beauty still add up to the denoised beauty.
#pragma once

#include <mcdenoise/export.h>
#include <mcdenoise/features.h>

#include <vector>

MCDENOISE_API_BEGIN

/// Denoise `beauty` as `denoise` does and every image of `layers` with the
/// same per-pixel operator: the outlier split (which pixels keep only the
/// firefly bound for the average, and the factor their excess is given
/// back with), and the non-local means weights are decided once, on the
/// beauty's colour and the guides, and applied alike to every layer
/// channel (the split to the colour and the layers, not to the beauty's
/// alpha or other channels).
///
/// So the result is linear in the layers: layers that sum to the beauty's
/// colour sum to the denoised beauty's colour (up to float rounding), and
/// a layer equal to the beauty comes out equal to the denoised beauty.
/// The beauty's result is bit-identical to `denoise(beauty, guides)`.
/// Premultiplied colour and alpha share the weights, which are
/// non-negative and normalised, and the excess given back is cut where it
/// would lift colour above alpha, so C <= alpha holds in the result
/// wherever it held in every input pixel of the window.
///
/// Use it for passes that add up to the beauty: light groups, per-lobe
/// direct/indirect passes, emission. Colour (filter) passes such as
/// albedo or DiffCol are not light and should stay as they are.
///
/// @param dst         The denoised beauty (allocated if uninitialized).
/// @param dst_layers  Resized to `layers.size()`; `dst_layers[i]` is the
///                    denoised `*layers[i]`, with its channels and names.
/// @param beauty      The noisy render, any channel count (colour first).
/// @param layers      Images of any channel count; each must cover the
///                    ROI (pixels outside its data window read as 0).
/// @param guides      As for `denoise`.
/// @param roi         The pixels to denoise (all channels of each image).
bool denoise_layers(ImageBuf& dst, std::vector<ImageBuf>& dst_layers, const ImageBuf& beauty,
                    const std::vector<const ImageBuf*>& layers, const Guides& guides = {},
                    ROI roi = {}, int nthreads = 0);
/// The value form: the denoised beauty, then the denoised layers in order
/// (on failure a single image with the error set).
std::vector<ImageBuf> denoise_layers(const ImageBuf& beauty,
                                     const std::vector<const ImageBuf*>& layers,
                                     const Guides& guides = {}, ROI roi = {}, int nthreads = 0);

MCDENOISE_API_END
