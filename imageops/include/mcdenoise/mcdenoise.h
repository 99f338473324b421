// mcdenoise.h: the umbrella header of libmcdenoise, and the rules every
// operation shares. Include this one header to get every filter and metric.
#pragma once

/// @defgroup mcdenoise_intro mcdenoise: common rules
///
/// Every operation follows `OIIO::ImageBufAlgo`'s conventions; the exact rule
/// of every filter is in `docs/filters.md`, and the rules they share are:
///
/// - **Two forms.** `bool op(ImageBuf& dst, const ImageBuf& beauty, <guides>,
///   <params>, ROI roi = {}, int nthreads = 0)` writes into `dst`, allocating
///   it (float pixels, covering `roi`) if it is uninitialized;
///   `ImageBuf op(const ImageBuf& beauty, <guides>, <params>, ROI roi = {},
///   int nthreads = 0)` returns a new image. Guides come in the order
///   `object_id, reflect_id, normal, depth, albedo, variance`; the
///   feature-guided filters take them together as `Guides` (features.h).
/// - **Errors.** The bool form returns false and sets `dst.errorfmt(...)`,
///   leaving `dst` untouched; the value form returns an image whose
///   `has_error()` is true. Nothing throws and nothing prints.
/// - **ROI.** The default is the beauty's data window and all its channels.
///   Guides must cover the ROI (their data windows, not just their sizes).
/// - **Windows.** `size` is the odd side of a square window, 1..255; the
///   window is clipped to the beauty's data window (no padding) and every
///   mean divides by the weights that actually contributed.
/// - **Non-finite values** in the beauty are left out of every window, per
///   channel. A window with no finite value yields 0 and is counted in the
///   `dst` attribute `mcdenoise:empty_windows`.
/// - **Threads.** `nthreads = 0` uses all cores, 1 the calling thread only.
///   Results are bit-identical for any thread count and any ROI split.
/// - **In place.** `dst` may be the same image as `beauty`.

#include <mcdenoise/atrous.h>
#include <mcdenoise/brdf.h>
#include <mcdenoise/cross_bilateral.h>
#include <mcdenoise/defaults.h>
#include <mcdenoise/demodulate.h>
#include <mcdenoise/denoise.h>
#include <mcdenoise/denoise_layers.h>
#include <mcdenoise/denoise_network.h>
#include <mcdenoise/dof.h>
#include <mcdenoise/features.h>
#include <mcdenoise/fireflies.h>
#include <mcdenoise/nlmeans.h>
#include <mcdenoise/normal.h>
#include <mcdenoise/object.h>
#include <mcdenoise/simple.h>
#include <mcdenoise/temporal.h>
#include <mcdenoise/version.h>
#include <mcdenoise/metrics.h>
#include <mcdenoise/sequence_metrics.h>
