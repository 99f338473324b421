// transfer.h: the transfer functions of Open Image Denoise's RT networks
// (OIDN 2.x, core/color.h): the perceptual-uniform curve (PU) that maps HDR
// values into the network's range, normalised so that the largest half
// float, 65504, maps to 1; and the sRGB curve that LDR values and the albedo
// prefilter's input take. Scalar forms and in-place row forms over
// contiguous floats; implemented in transfer.cpp. The functions are the
// bare curves: they do not sanitise (the tile I/O of tile_io.h clamps
// before and after them), so a negative value takes the linear segment, a
// NaN stays NaN and +inf stays +inf.
#pragma once

#include <cstddef>

namespace mcdenoise {

/// The largest HDR value the PU curve is normalised for: the largest
/// finite float16.
constexpr float pu_max_input = 65504.f;

/// The PU curve of a linear value y: 1.41283765e3 y up to 1.57945760e-6,
/// then 1.64593172 y^0.431384981 - 2.94139609e-3 up to 3.22087631e-2,
/// then 0.192653254 ln(y + 6.26026094e-3) + 0.998620152.
float pu_forward(float y);

/// The inverse of `pu_forward`: x / 1.41283765e3 up to 2.23151711e-3, then
/// ((x + 2.94139609e-3) / 1.64593172)^(1 / 0.431384981) up to 0.370974749,
/// then exp((x - 0.998620152) / 0.192653254) - 6.26026094e-3.
float pu_inverse(float x);

/// The normalisation of the PU curve: `pu_forward(pu_max_input)`, about
/// 3.135119, computed once in float as OIDN computes it.
float pu_norm();

/// The PU curve normalised, as the HDR network's input takes it:
/// `pu_forward(y)` times float(1 / double(pu_norm())) (OIDN multiplies by
/// the reciprocal rather than dividing; the two differ by at most an ulp).
float pu_encode(float y);

/// The inverse of `pu_encode`, as the HDR network's output is decoded:
/// `pu_inverse(x * pu_norm())`.
float pu_decode(float x);

/// The sRGB curve of a linear value y: 12.92 y up to 0.0031308, then
/// 1.055 y^(1/2.4) - 0.055.
float srgb_forward(float y);

/// The inverse of `srgb_forward`: x / 12.92 up to 0.04045, then
/// ((x + 0.055) / 1.055)^2.4 (the exponent taken as 1 / float(1 / 2.4), as
/// OIDN does).
float srgb_inverse(float x);

/// `pu_encode` of each of the `count` contiguous `values`, in place.
void pu_encode_row(float* values, size_t count);

/// `pu_decode` of each of the `count` contiguous `values`, in place.
void pu_decode_row(float* values, size_t count);

/// `srgb_forward` of each of the `count` contiguous `values`, in place.
void srgb_forward_row(float* values, size_t count);

/// `srgb_inverse` of each of the `count` contiguous `values`, in place.
void srgb_inverse_row(float* values, size_t count);

}  // namespace mcdenoise
