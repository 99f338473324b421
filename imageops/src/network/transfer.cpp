// transfer.cpp: the PU and sRGB curves (transfer.h). The constants are
// those of OIDN 2.x's core/color.h, whose PU curve fits the perceptually
// uniform encoding of Aydin et al. 2008 in three segments.
#include "network/transfer.h"

#include <cmath>

namespace mcdenoise {

namespace {

/// The PU curve's segments: a y below pu_y0; b y^c + d below pu_y1;
/// e ln(y + f) + g above.
constexpr float pu_a  = 1.41283765e+03f;
constexpr float pu_b  = 1.64593172e+00f;
constexpr float pu_c  = 4.31384981e-01f;
constexpr float pu_d  = -2.94139609e-03f;
constexpr float pu_e  = 1.92653254e-01f;
constexpr float pu_f  = 6.26026094e-03f;
constexpr float pu_g  = 9.98620152e-01f;
constexpr float pu_y0 = 1.57945760e-06f;
constexpr float pu_y1 = 3.22087631e-02f;
/// The PU curve's values at pu_y0 and pu_y1: where its inverse switches.
constexpr float pu_x0 = 2.23151711e-03f;
constexpr float pu_x1 = 3.70974749e-01f;

/// The sRGB curve's segments: a y up to srgb_y0; b y^c + d above.
constexpr float srgb_a  = 12.92f;
constexpr float srgb_b  = 1.055f;
constexpr float srgb_c  = 1.f / 2.4f;
constexpr float srgb_d  = -0.055f;
constexpr float srgb_y0 = 0.0031308f;
/// Where the sRGB curve's inverse switches (the curve's value at srgb_y0
/// rounded as the standard gives it).
constexpr float srgb_x0 = 0.04045f;

inline float pu_forward_value(float y)
{
    if (y <= pu_y0)
        return pu_a * y;
    if (y <= pu_y1)
        return pu_b * std::pow(y, pu_c) + pu_d;
    return pu_e * std::log(y + pu_f) + pu_g;
}

inline float pu_inverse_value(float x)
{
    if (x <= pu_x0)
        return x / pu_a;
    if (x <= pu_x1)
        return std::pow((x - pu_d) / pu_b, 1.f / pu_c);
    return std::exp((x - pu_g) / pu_e) - pu_f;
}

inline float srgb_forward_value(float y)
{
    if (y <= srgb_y0)
        return srgb_a * y;
    return srgb_b * std::pow(y, srgb_c) + srgb_d;
}

inline float srgb_inverse_value(float x)
{
    if (x <= srgb_x0)
        return x / srgb_a;
    return std::pow((x - srgb_d) / srgb_b, 1.f / srgb_c);
}

/// The factor `pu_encode` multiplies by: the reciprocal of `pu_norm()`,
/// divided in double and rounded to float.
float pu_norm_scale()
{
    static const float scale = float(1.0 / double(pu_norm()));
    return scale;
}

}  // namespace

float pu_forward(float y) { return pu_forward_value(y); }

float pu_inverse(float x) { return pu_inverse_value(x); }

float pu_norm()
{
    static const float norm = pu_forward_value(pu_max_input);
    return norm;
}

float pu_encode(float y) { return pu_forward_value(y) * pu_norm_scale(); }

float pu_decode(float x) { return pu_inverse_value(x * pu_norm()); }

float srgb_forward(float y) { return srgb_forward_value(y); }

float srgb_inverse(float x) { return srgb_inverse_value(x); }

void pu_encode_row(float* values, size_t count)
{
    const float scale = pu_norm_scale();
    for (size_t i = 0; i < count; ++i)
        values[i] = pu_forward_value(values[i]) * scale;
}

void pu_decode_row(float* values, size_t count)
{
    const float norm = pu_norm();
    for (size_t i = 0; i < count; ++i)
        values[i] = pu_inverse_value(values[i] * norm);
}

void srgb_forward_row(float* values, size_t count)
{
    for (size_t i = 0; i < count; ++i)
        values[i] = srgb_forward_value(values[i]);
}

void srgb_inverse_row(float* values, size_t count)
{
    for (size_t i = 0; i < count; ++i)
        values[i] = srgb_inverse_value(values[i]);
}

}  // namespace mcdenoise
