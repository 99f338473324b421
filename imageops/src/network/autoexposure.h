// autoexposure.h: the exposure OIDN 2.x gives an HDR image before its
// network sees it (devices/cpu/cpu_autoexposure.*): the geometric mean of
// the average luminances of 16 x 16 bins, turned into the scale that brings
// it to middle grey; implemented in autoexposure.cpp.
#pragma once

#include "network/rgb_pixels.h"

namespace mcdenoise {

/// The largest side of an autoexposure bin, in pixels.
constexpr int autoexposure_bin_size = 16;
/// The luminance the image's geometric mean is scaled to (middle grey).
constexpr float autoexposure_key = 0.18f;
/// Bins of this average luminance or less are left out.
constexpr float autoexposure_eps = 1e-8f;

/// The number of bins along a side of `size` pixels: ceil(size / 16).
int autoexposure_bins(int size);

/// The first pixel of bin `i` of `bins` along a side of `size` pixels:
/// i * size / bins in integer division (bin i spans [begin(i), begin(i+1))).
int autoexposure_bin_begin(int i, int size, int bins);

/// The luminance of linear RGB: 0.212671 R + 0.715160 G + 0.072169 B.
double autoexposure_luminance(double r, double g, double b);

/// Sets `scale` to the input scale OIDN's autoexposure gives `image`: each
/// pixel sanitised (NaN to 0, then clamped to [0, FLT_MAX]), its luminance
/// averaged over each bin of `autoexposure_bins` rows by columns; the bins
/// averaging more than `autoexposure_eps` kept; `scale` = 0.18 /
/// 2^(mean of log2 of the kept averages), or 1 when none is kept. One pass
/// over the rows, summed in double (OIDN sums in float, which can overflow
/// to infinity where pixels near FLT_MAX share a bin; here it cannot).
/// Returns false, `scale` unchanged, when `image` is not `valid()`.
bool autoexposure(const RgbIn& image, float& scale);

}  // namespace mcdenoise
