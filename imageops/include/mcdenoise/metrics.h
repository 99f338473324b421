// metrics.h: image quality metrics for judging a denoised render against a
// reference: relative MSE, MSE, PSNR and SSIM, with non-finite pixels
// counted rather than hidden.
#pragma once

#include <mcdenoise/export.h>

#include <OpenImageIO/imagebuf.h>

#include <cstdint>
#include <string>

MCDENOISE_API_BEGIN

using OIIO::ImageBuf;
using OIIO::ROI;

/// The epsilon in relMSE's denominator (x - r)^2 / (r^2 + epsilon), which
/// keeps black reference pixels from dominating (Rousselle et al. 2011).
constexpr double rel_mse_epsilon = 0.01;
/// The peak value PSNR is relative to: 1, the white of a linear render.
/// PSNR is computed on values clamped to [0, psnr_peak], so on HDR
/// renders (emitters, fireflies far above 1) it stays >= 0 dB and measures
/// the displayable range, as SSIM's clamped luminance does.
constexpr double psnr_peak = 1.0;
/// SSIM's gaussian window: 11 x 11 taps, sigma 1.5 (Wang et al. 2004).
constexpr int ssim_window_size = 11;
constexpr double ssim_sigma = 1.5;
/// SSIM's stabilising constants C1 = (K1 L)^2 and C2 = (K2 L)^2 with
/// dynamic range L = 1 (Wang et al. 2004, eq. 7 and 9).
constexpr double ssim_k1 = 0.01;
constexpr double ssim_k2 = 0.03;

/// Every metric of one comparison, computed in one pass over the pixels.
struct ImageComparison {
    double rel_mse = 0;     ///< mean over pixels and channels of (x-r)^2 / (r^2 + 0.01)
    double mse = 0;         ///< mean over pixels and channels of (x-r)^2
    double psnr = 0;        ///< 10 log10(1 / mse of values clamped to [0, 1]) in dB; +Inf when that is 0
    double ssim = 0;        ///< mean SSIM of the luminance (see `compare_images`)
    int64_t pixels = 0;     ///< pixels that entered the metrics
    int64_t nonfinite = 0;  ///< pixels left out: a NaN or Inf in either image
    bool ok = false;        ///< false if the comparison could not be made
    std::string error;      ///< why, when `ok` is false
};

/// Compare `result` with `reference` over `roi`.
///
/// The default ROI is `result`'s data window and its first 3 channels (all
/// of them if it has fewer); an explicit ROI's channel range is clamped to
/// the channels both images have. Both images must cover the ROI with their
/// data windows (pixels are matched by coordinates, not by position in the
/// buffer); otherwise, or if either image is empty or unreadable, `ok` is
/// false and `error` says why. Nothing throws and nothing prints.
///
/// A pixel with a NaN or Inf in any ROI channel of either image is counted
/// in `nonfinite` and left out of every metric (and of every SSIM window);
/// the means are over the remaining `pixels`. With no finite pixel at all the
/// metrics are NaN.
///
/// - relMSE and MSE average over pixels and channels.
/// - PSNR is relative to a peak of 1 (`psnr_peak`), over values clamped
///   to [0, 1]: 10 log10(1 / MSE'), MSE' the MSE of the clamped values (the
///   plain MSE when both images lie in [0, 1]); it is never negative.
/// - SSIM is computed on luminance Y = 0.2126 R + 0.7152 G + 0.0722 B of the
///   ROI's first three channels (the mean of the channels if the ROI has fewer
///   than three), clamped to [0, 1] so emitters and fireflies cannot dominate
///   it, with an 11 x 11 gaussian window of sigma 1.5 and L = 1. The window
///   is clipped to the ROI and its weights renormalised over the pixels that
///   contributed (no padding); the result is the mean of the per-pixel SSIM.
///
/// Results are bit-identical for any `nthreads` (0: all cores, 1: the
/// calling thread).
ImageComparison compare_images(const ImageBuf& result, const ImageBuf& reference,
                               ROI roi = {}, int nthreads = 0);

/// relMSE of `result` against `reference` as in `compare_images`; NaN if the
/// comparison cannot be made.
double rel_mse(const ImageBuf& result, const ImageBuf& reference, ROI roi = {},
               int nthreads = 0);

/// MSE as in `compare_images`; NaN if the comparison cannot be made.
double mse(const ImageBuf& result, const ImageBuf& reference, ROI roi = {},
           int nthreads = 0);

/// PSNR in dB as in `compare_images`; NaN if the comparison cannot be made.
double psnr(const ImageBuf& result, const ImageBuf& reference, ROI roi = {},
            int nthreads = 0);

/// Mean SSIM of the luminance as in `compare_images`; NaN if the comparison
/// cannot be made.
double ssim(const ImageBuf& result, const ImageBuf& reference, ROI roi = {},
            int nthreads = 0);

MCDENOISE_API_END
