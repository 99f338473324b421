// nlmeans.h: non-local means with variance-normalised patch distances and
// feature weights.
#pragma once

#include <mcdenoise/defaults.h>
#include <mcdenoise/export.h>
#include <mcdenoise/features.h>

MCDENOISE_API_BEGIN

/// Non-local means with variance-normalised patch distances (Rousselle,
/// Knaus & Zwicker 2012, "Adaptive Rendering with Non-Local Means
/// Filtering") and feature weights (Rousselle, Manzi & Zwicker 2013,
/// "Robust Denoising using Feature and Color Information").
///
/// For each q in the (2 search_radius + 1)^2 window around p (clipped to
/// the data window), with u the colour and v the per-channel variance of
/// features.h and k = `strength`, the distance of pixels x and y in colour
/// channel c is
///
///     d_c(x,y) = ((u_x - u_y)^2 - (v_x + min(v_x, v_y))) / (1e-10 + k^2 (v_x + v_y))
///
/// and the patch distance D(p,q) is the mean of d_c(p+n, q+n) over the
/// colour channels and the offsets n in [-f, f]^2 (f = `patch_radius`)
/// for which p+n and q+n both lie in the data window. q weighs
/// `exp(-max(0, D)) * wf(p,q)` (`wf`: the feature weight of
/// `FeatureSigmas`); the center weighs 1. Each channel of the result is the
/// weighted mean of the finite values.
///
/// @param beauty        The noisy image, any channel count.
/// @param guides        Object id, normal, depth, albedo and variance are
///                      used when present; the halves are not read.
/// @param search_radius 0..127; the search window side is 2 r + 1.
/// @param patch_radius  0..7; the patch side is 2 f + 1.
/// @param strength      k above, > 0: larger values filter more.
/// @param sigmas        Feature fall-offs.
ImageBuf nlmeans(const ImageBuf& beauty, const Guides& guides,
                 int search_radius = default_nlmeans_search_radius,
                 int patch_radius = default_nlmeans_patch_radius, float strength = default_nlmeans_strength,
                 const FeatureSigmas& sigmas = {}, ROI roi = {}, int nthreads = 0);
/// Write to an existing image `dst` (allocating if it is uninitialized).
bool nlmeans(ImageBuf& dst, const ImageBuf& beauty, const Guides& guides,
             int search_radius = default_nlmeans_search_radius,
             int patch_radius = default_nlmeans_patch_radius, float strength = default_nlmeans_strength,
             const FeatureSigmas& sigmas = {}, ROI roi = {}, int nthreads = 0);

/// The largest `search_radius` `nlmeans` accepts.
constexpr int max_nlmeans_search_radius = 127;
/// The largest `patch_radius` `nlmeans` accepts.
constexpr int max_nlmeans_patch_radius = 7;

MCDENOISE_API_END
