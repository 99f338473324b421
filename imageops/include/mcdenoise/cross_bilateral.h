// cross_bilateral.h: the joint (cross) bilateral filter guided by the
// features of features.h and, optionally, the beauty's own colour.
#pragma once

#include <mcdenoise/defaults.h>
#include <mcdenoise/export.h>
#include <mcdenoise/features.h>

MCDENOISE_API_BEGIN

/// Joint / cross bilateral filter (Eisemann & Durand 2004, "Flash
/// Photography Enhancement via Intrinsic Relighting"; Petschnigg et al.
/// 2004, "Digital Photography with Flash and No-Flash Image Pairs"). Each
/// pixel p becomes, per channel, `sum w v_q / sum w` over the finite values
/// of the `size` x `size` window (clipped to the data window), with
///
///     w(p,q) = exp(-|q - p|^2 / (2 sigma_spatial^2)) * wf(p,q) * C(p,q)
///
/// where `wf` is the feature weight of `FeatureSigmas`, and
/// `C = exp(-|c_p - c_q|^2 / (2 sigma_color^2))` of the colours (see
/// features.h) when `sigma_color > 0`, else 1. The center weighs 1.
///
/// @param beauty        The noisy image, any channel count.
/// @param guides        Object id, normal, depth and albedo are used when
///                      present; variance (still checked when given) and the
///                      halves are not read.
/// @param size          Window side: odd, 1..255.
/// @param sigma_spatial Spatial fall-off in pixels; must be > 0.
/// @param sigma_color   Colour fall-off; <= 0 leaves colour out (a pure
///                      feature-guided filter).
/// @param sigmas        Feature fall-offs.
ImageBuf cross_bilateral(const ImageBuf& beauty, const Guides& guides,
                         int size = default_cross_bilateral_size,
                         float sigma_spatial = default_cross_bilateral_sigma_spatial,
                         float sigma_color = default_cross_bilateral_sigma_color,
                         const FeatureSigmas& sigmas = {}, ROI roi = {}, int nthreads = 0);
/// Write to an existing image `dst` (allocating if it is uninitialized).
bool cross_bilateral(ImageBuf& dst, const ImageBuf& beauty, const Guides& guides,
                     int size = default_cross_bilateral_size,
                     float sigma_spatial = default_cross_bilateral_sigma_spatial,
                     float sigma_color = default_cross_bilateral_sigma_color,
                     const FeatureSigmas& sigmas = {}, ROI roi = {}, int nthreads = 0);

MCDENOISE_API_END
