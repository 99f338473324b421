// denoise_layers.h: `denoise` of a beauty together with its light passes
// (AOVs): each pass denoised as far as its own noise allows, and the
// passes that add up to the beauty made to add up to the denoised beauty.
#pragma once

#include <mcdenoise/export.h>
#include <mcdenoise/features.h>

#include <vector>

MCDENOISE_API_BEGIN

/// How a layer takes part in rebuilding the beauty's colour.
struct LayerTerm {
    /// The rebuild it is a term of: the layers with the same `sum` add up
    /// to the beauty, each times its colour. -1: it rebuilds nothing.
    int sum = 0;
    /// The colour (filter) pass it is multiplied by in that rebuild
    /// (Cycles' <Lobe>Col for <Lobe>Dir and <Lobe>Ind), or nullptr for 1.
    const ImageBuf* colour = nullptr;
};

/// Denoise `beauty` as `denoise` does, and every image of `layers` as far
/// as its own noise allows, so that layers that add up to the beauty add
/// up to the denoised beauty.
///
/// The steps:
/// 1. The beauty's operator for every layer: the outlier split (which
///    pixels keep only the firefly bound for the average, and the factor
///    their excess is given back with) and the non-local means weights are
///    decided once, on the beauty's colour and the guides, and applied
///    alike to every layer channel (the split to the colour and the
///    layers, not to the beauty's alpha or other channels).
/// 2. Each layer backs off towards its own kept values where the average
///    moved it further than its own noise explains: with e the average
///    minus the kept values, m2 the 3x3 mean of |e|^2 and s2 the layer's
///    noise, the layer becomes average + a (kept - average),
///    a = clamp(1 - s2 / m2, 0, 1). s2 is the smallest 3x3 variance of e
///    among the 3x3 windows around the pixel (corrected for the minimum's
///    bias), at most 9 times the layer's median of s2 / |average|^2 over
///    the ROI, times the pixel's |average|^2: where every window crosses an
///    edge, the windows measure the edge, not the noise. A direct pass
///    keeps its shadow edges when the weights, set by the indirect light's
///    noise, would blur them.
/// 3. The excess is given back to each layer as to the beauty.
/// 4. The layers add up again: per rebuild (`terms`), wherever the raw
///    layers rebuild the raw beauty (within 1e-3 of its size), the
///    difference between the denoised beauty and the rebuild of the
///    denoised layers is shared among them in proportion to colour^2 x
///    their estimated error, a^2 s2 + (1 - a)^2 (max(0, m2 - s2) + t2)
///    (t2 the same noise estimate of the average), each share divided by
///    the layer's colour, moving no layer by more than 2 standard
///    deviations of that error; the rest (the beauty's own error more than
///    the layers' noise) in proportion to each layer's part of the rebuild,
///    |colour x value|. No layer is pushed below min(0, its value).
///
/// The beauty's result is bit-identical to `denoise(beauty, guides)`.
/// Premultiplied colour and alpha share the weights, which are
/// non-negative and normalised, and the excess given back is cut where it
/// would lift colour above alpha, so C <= alpha holds in the beauty's
/// result wherever it held in every input pixel of the window.
///
/// Use it for passes that add up to the beauty: light groups, per-lobe
/// direct/indirect passes, emission. Colour (filter) passes such as
/// albedo or DiffCol are not light and should stay as they are.
///
/// Returns the denoised beauty, then the denoised layers in order, each
/// with its channels and names (on failure a single image with the error
/// set).
///
/// @param beauty      The noisy render, any channel count (colour first).
/// @param layers      Images of any channel count; each must cover the
///                    ROI (pixels outside its data window read as 0).
/// @param guides      As for `denoise`.
/// @param terms       Empty (every layer a term of one plain sum), or one
///                    per layer; a colour must cover the ROI with the
///                    layer's colour channels.
/// @param roi         The pixels to denoise (all channels of each image).
std::vector<ImageBuf> denoise_layers(const ImageBuf& beauty,
                                     const std::vector<const ImageBuf*>& layers,
                                     const Guides& guides = {},
                                     const std::vector<LayerTerm>& terms = {}, ROI roi = {},
                                     int nthreads = 0);
/// Write to an existing image `dst` (allocating if it is uninitialized), and
/// the layers to `dst_layers`, resized to `layers.size()`.
bool denoise_layers(ImageBuf& dst, std::vector<ImageBuf>& dst_layers, const ImageBuf& beauty,
                    const std::vector<const ImageBuf*>& layers, const Guides& guides = {},
                    const std::vector<LayerTerm>& terms = {}, ROI roi = {}, int nthreads = 0);

MCDENOISE_API_END
