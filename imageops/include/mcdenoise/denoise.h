// denoise.h: the one-call denoiser: takes whatever guides are present and
// chooses its parameters from the data.
#pragma once

#include <mcdenoise/export.h>
#include <mcdenoise/features.h>

MCDENOISE_API_BEGIN

/// Denoise a Monte Carlo render with every guide it is given: the
/// project's best non-learned result in one call.
///
/// The steps:
/// 1. Outliers, keeping energy: a pixel `clamp_fireflies` (factor 2,
///    radius 2) would scale down is split into the clamped value, which is
///    averaged, and the excess over it, which is not. A pixel whose
///    luminance excess exceeds twice the standard deviation of its measured
///    noise (the `variance` guide, else `(half_a - half_b)^2 / 4`) is a
///    highlight the samples agree on, not a firefly, and is kept whole.
/// 2. `nlmeans` (search radius 5, patch radius 1) on the split beauty, with
///    variance-normalised patch distances (Rousselle, Knaus & Zwicker 2012)
///    and feature weights (Rousselle, Manzi & Zwicker 2013) with fall-offs
///    `denoise_feature_sigmas`.
/// 3. The excess is given back, so the frame keeps its energy. With a
///    measured noise the pixels that gave excess are known fireflies: their
///    excess is spread over the neighbourhood with a Gaussian of standard
///    deviation 10 pixels (radius 30), normalised per source pixel over the
///    data window, a faint wide glow rather than a blotch. Without one
///    (Cycles writes neither a variance nor halves), each pixel's excess is
///    shared out over its own search window in proportion to the weights
///    `nlmeans` gave that window when it filtered the pixel, normalised to
///    sum 1: an outlier on a surface gives its excess to the pixels alike
///    to it, never further than 5 pixels; one unlike its surroundings (a
///    glint, a small emitter) gets its own excess back, so the result backs
///    off towards the input there instead of inventing a glow. The
///    per-pixel split applies to the colour channels; further channels
///    (alpha) are filtered as they are. With an alpha channel
///    (`spec().alpha_channel`, else a fourth channel), the excess a pixel
///    receives is scaled down where it would lift a colour channel above
///    alpha, so premultiplied colour stays <= alpha where it was.
///
/// What each guide buys (relMSE per guide set: docs/quality.md):
/// - `variance`: the noise level of every pixel, so the colour distance
///   tells noise from detail. Without it the variance comes from the halves
///   (the 3x3 mean of `(half_a - half_b)^2 / 4`) or, with neither, is
///   estimated: per channel, the smallest 3x3 sample variance among the 3x3
///   windows around the pixel (the window on one side of an edge, not the
///   one across it). The strength follows: `denoise_measured_strength` for
///   a measured variance, `denoise_estimated_strength` for an estimate.
/// - `normal`, `depth`, `albedo`: neighbours on other surfaces, at other
///   distances or with another texture weigh less, so edges and texture
///   stay where the colour alone cannot tell them from noise.
/// - `half_a`, `half_b`: only used for the variance when it is absent.
/// - `object_id` is not read: on every test scene the hard object edge made
///   the result worse (fewer neighbours where the features already separate
///   the objects), and defocus or motion blur make ids disagree with the
///   beauty.
/// Albedo is not divided out: the albedo buffer carries its own sampling
/// noise (sub-pixel texture, defocus), which remodulation would put back;
/// `demodulate` / `remodulate` are there for chains with a clean albedo.
///
/// The `dst` attribute `mcdenoise:denoise_guides` lists the guides read.
///
/// @param beauty  The noisy render, any channel count (colour first).
/// @param guides  Any subset; each present one must cover the ROI.
ImageBuf denoise(const ImageBuf& beauty, const Guides& guides = {}, ROI roi = {},
                 int nthreads = 0);
/// Write to an existing image `dst` (allocating if it is uninitialized).
bool denoise(ImageBuf& dst, const ImageBuf& beauty, const Guides& guides = {}, ROI roi = {},
             int nthreads = 0);

/// The feature fall-offs `denoise` uses: wider than `FeatureSigmas`'
/// defaults, because after the colour distance has judged the noise the
/// features only need to keep distinct surfaces apart.
constexpr FeatureSigmas denoise_feature_sigmas { 0.3f, 0.6f, 1.0f };
/// `nlmeans` strength when the variance is measured (guide or halves).
constexpr float denoise_measured_strength = 1.0f;
/// `nlmeans` strength when the variance is estimated from the neighbourhood.
constexpr float denoise_estimated_strength = 0.8f;

MCDENOISE_API_END
