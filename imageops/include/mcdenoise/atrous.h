// atrous.h: the edge-avoiding a-trous wavelet filter with SVGF's
// variance-guided luminance weight.
#pragma once

#include <mcdenoise/defaults.h>
#include <mcdenoise/export.h>
#include <mcdenoise/features.h>

MCDENOISE_API_BEGIN

/// Edge-avoiding a-trous wavelet filter (Dammertz et al. 2010,
/// "Edge-Avoiding A-Trous Wavelet Transform for fast Global Illumination
/// Filtering") with the variance-guided luminance weight of SVGF (Schied et
/// al. 2017, "Spatiotemporal Variance-Guided Filtering").
///
/// Iteration i = 0 .. iterations-1 has step s = 2^i and 25 taps at
/// (px + kx s, py + ky s), kx, ky in -2..2, with B3-spline weights
/// h = (1/16, 1/4, 3/8, 1/4, 1/16); taps outside the data window are left
/// out. A tap weighs
///
///     w = h[kx] h[ky] wf(p,q) exp(-|L_p - L_q| / (sigma_luminance sqrt(g_p) + 1e-10))
///
/// with `wf` the feature weight of `FeatureSigmas`, L the luminance of the
/// current iterate (features.h) and g_p the 3x3 binomial blur (clipped,
/// renormalised) of the current luminance variance, which starts as the
/// variance of features.h and propagates as `sum w^2 varL_q / (sum w)^2`
/// (sums over every tap, finite or not). Each channel of the next iterate
/// is `sum w v_q / sum w` over the finite values. Every channel of the
/// beauty is iterated (the colour drives the weights), the ROI's channels
/// are written. Intermediate iterates cover the ROI grown by the remaining
/// reach, so the result does not depend on the ROI split. Empty windows
/// (no finite value) are counted in the last iteration.
///
/// @param beauty          The noisy image, any channel count.
/// @param guides          Object id, normal, depth, albedo and variance are
///                        used when present; the halves are not read.
/// @param iterations      1..10 (reach 2^(iterations+1) - 2 pixels).
/// @param sigma_luminance Luminance edge-stopping scale, in standard
///                        deviations; <= 0 makes the luminance weight 1.
/// @param sigmas          Feature fall-offs.
ImageBuf atrous(const ImageBuf& beauty, const Guides& guides, int iterations = default_atrous_iterations,
                float sigma_luminance = default_atrous_sigma_luminance, const FeatureSigmas& sigmas = {},
                ROI roi = {}, int nthreads = 0);
/// Write to an existing image `dst` (allocating if it is uninitialized).
bool atrous(ImageBuf& dst, const ImageBuf& beauty, const Guides& guides,
            int iterations = default_atrous_iterations,
            float sigma_luminance = default_atrous_sigma_luminance, const FeatureSigmas& sigmas = {},
            ROI roi = {}, int nthreads = 0);

/// The largest `iterations` `atrous` accepts.
constexpr int max_atrous_iterations = 10;

MCDENOISE_API_END
