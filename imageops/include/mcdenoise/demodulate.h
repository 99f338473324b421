// demodulate.h: albedo demodulation: divide the texture out of the beauty
// before filtering and multiply it back after, so a filter never blurs it.
#pragma once

#include <mcdenoise/defaults.h>
#include <mcdenoise/export.h>
#include <mcdenoise/simple.h>

MCDENOISE_API_BEGIN

/// Albedo demodulation (Zimmer et al. 2015; Bako et al. 2017's "diffuse
/// irradiance"; SVGF, Schied et al. 2017): every colour channel becomes
/// `v_c / (a_k + epsilon)` with `a_k = max(0, albedo_k)` (non-finite albedo
/// taken as 0), `k = c` for a three-channel albedo and 0 for a one-channel
/// one. Only the beauty's first three channels are divided; further ones
/// (alpha) are copied unchanged, and so are non-finite beauty values (the
/// filters leave them out).
///
/// @param beauty   The image to demodulate, any channel count.
/// @param albedo   Three or one channels; must cover the ROI.
/// @param epsilon  Added to the albedo so black texels do not divide by
///                 zero; must be > 0.
ImageBuf demodulate(const ImageBuf& beauty, const ImageBuf& albedo,
                    float epsilon = default_demodulate_epsilon, ROI roi = {}, int nthreads = 0);
/// Write to an existing image `dst` (allocating if it is uninitialized).
bool demodulate(ImageBuf& dst, const ImageBuf& beauty, const ImageBuf& albedo,
                float epsilon = default_demodulate_epsilon, ROI roi = {}, int nthreads = 0);

/// Albedo remodulation, the inverse of `demodulate`: every colour channel
/// of `filtered` becomes `v_c * (a_k + epsilon)`, with the same albedo,
/// channel and non-finite rules. Use the same `epsilon` as `demodulate`.
///
/// @param filtered The demodulated (and usually filtered) image.
/// @param albedo   Three or one channels; must cover the ROI.
/// @param epsilon  As given to `demodulate`; must be > 0.
ImageBuf remodulate(const ImageBuf& filtered, const ImageBuf& albedo,
                    float epsilon = default_demodulate_epsilon, ROI roi = {}, int nthreads = 0);
/// Write to an existing image `dst` (allocating if it is uninitialized).
bool remodulate(ImageBuf& dst, const ImageBuf& filtered, const ImageBuf& albedo,
                float epsilon = default_demodulate_epsilon, ROI roi = {}, int nthreads = 0);

MCDENOISE_API_END
