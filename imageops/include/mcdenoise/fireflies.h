// fireflies.h: clamping fireflies, the rare very bright samples that
// dominate the error of a Monte Carlo render, before any averaging.
#pragma once

#include <mcdenoise/defaults.h>
#include <mcdenoise/export.h>
#include <mcdenoise/features.h>

MCDENOISE_API_BEGIN

/// Firefly clamp, the outlier pass of the feature-guided denoisers (as in
/// Cycles' NLM denoiser after Rousselle, Manzi & Zwicker 2013): a pixel far
/// brighter than almost all of its neighbours is scaled down to a bound set
/// by them, so a single lucky sample cannot spread into its window.
///
/// For each pixel p, the luminances (features.h) of its neighbours q != p in
/// the (2 radius + 1)^2 window clipped to the beauty's data window, and with
/// p's object id when `guides.object_id` is given, are sorted ascending as
/// s_0 .. s_{n-1}; the bound is `factor * s_k`, k = floor(0.75 (n - 1)).
/// If p's luminance L exceeds the bound, its colour channels (the first
/// three) are multiplied by `bound / L` (0 when the bound is <= 0). Pixels
/// with no such neighbour, further channels (alpha) and non-finite values
/// are copied unchanged. This trades a little energy (bias) for much less
/// error; every other guide in `guides` is ignored.
///
/// @param beauty  The noisy image, any channel count.
/// @param guides  Only `object_id` is read, when present.
/// @param factor  How many times the 75th-percentile neighbour a pixel may
///                be before it is clamped; must be >= 1.
/// @param radius  Window radius, 1..max_firefly_radius.
ImageBuf clamp_fireflies(const ImageBuf& beauty, const Guides& guides, float factor = default_firefly_factor,
                         int radius = default_firefly_radius, ROI roi = {}, int nthreads = 0);
/// Write to an existing image `dst` (allocating if it is uninitialized).
bool clamp_fireflies(ImageBuf& dst, const ImageBuf& beauty, const Guides& guides,
                     float factor = default_firefly_factor, int radius = default_firefly_radius, ROI roi = {},
                     int nthreads = 0);

/// The largest `radius` `clamp_fireflies` accepts.
constexpr int max_firefly_radius = 7;

MCDENOISE_API_END
