// test_network_transfer.cpp: the PU and sRGB curves (network/transfer.h)
// against values computed by hand (in double, from the segment formulas)
// on both sides of every switch; their continuity at the switches; inverse
// after forward over a log-spaced sweep; the normalisation; the row forms
// against the scalar ones; and what NaN, negatives and infinities give.
#include "network/transfer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace {

using namespace mcdenoise;

/// The float after `x`.
float next_up(float x) { return std::nextafter(x, std::numeric_limits<float>::infinity()); }

/// Expects `actual` within `rel` of `expected`, relatively.
void expect_near_rel(double actual, double expected, double rel, const char* what, double at)
{
    EXPECT_LE(std::abs(actual - expected), rel * std::abs(expected))
        << what << "(" << at << ") = " << actual << ", expected " << expected;
}

/// log-spaced values from `lo` to `hi`, `per_decade` a decade.
std::vector<float> sweep(double lo, double hi, int per_decade)
{
    std::vector<float> out;
    for (double e = std::log10(lo); e <= std::log10(hi) + 1e-12; e += 1.0 / per_decade)
        out.push_back(float(std::pow(10.0, e)));
    out.push_back(float(hi));
    return out;
}

/// Where the curves switch segments.
constexpr float pu_y0   = 1.57945760e-6f;
constexpr float pu_y1   = 3.22087631e-2f;
constexpr float pu_x0   = 2.23151711e-3f;
constexpr float pu_x1   = 0.370974749f;
constexpr float srgb_y0 = 0.0031308f;
constexpr float srgb_x0 = 0.04045f;

TEST(NetworkTransfer, PuForwardAgainstHandComputedValues)
{
    // Each value from the segment's formula in double (Python, %.9g).
    const struct {
        float y;
        double pu;
    } cases[] = {
        { 0.f, 0.0 },
        { 1e-7f, 1.41283765e-4 },  // 1.41283765e3 y
        { pu_y0, 2.23151716e-3 },  // the last of the linear segment
        { 2e-6f, 2.78605973e-3 },  // 1.64593172 y^0.431384981 - 2.94139609e-3
        { 1e-4f, 2.80236614e-2 },
        { 0.01f, 0.22281593 },
        { pu_y1, 0.370974758 },  // the last of the power segment
        { 0.04f, 0.406505774 },  // 0.192653254 ln(y + 6.26026094e-3) + 0.998620152
        { 1.f, 0.999822452 },
        { 100.f, 1.88583323 },
        { 65504.f, 3.13511904 },
    };
    for (const auto& c : cases)
        expect_near_rel(pu_forward(c.y), c.pu, 2e-6, "pu_forward", c.y);
    // Just past each switch, the next segment's formula.
    const double past_y0 =
        1.64593172 * std::pow(double(next_up(pu_y0)), 0.431384981) - 2.94139609e-3;
    expect_near_rel(pu_forward(next_up(pu_y0)), past_y0, 2e-6, "pu_forward", next_up(pu_y0));
    const double past_y1 =
        0.192653254 * std::log(double(next_up(pu_y1)) + 6.26026094e-3) + 0.998620152;
    expect_near_rel(pu_forward(next_up(pu_y1)), past_y1, 2e-6, "pu_forward", next_up(pu_y1));
}

TEST(NetworkTransfer, PuInverseAgainstHandComputedValues)
{
    const double a = 1.41283765e3, b = 1.64593172, c = 0.431384981, d = -2.94139609e-3;
    const double e = 0.192653254, f = 6.26026094e-3, g = 0.998620152;
    for (float x : { 1e-4f, pu_x0, next_up(pu_x0), 0.1f, pu_x1, next_up(pu_x1), 1.f, 3.f }) {
        const double xd = x;
        const double y  = xd <= pu_x0   ? xd / a
                          : xd <= pu_x1 ? std::pow((xd - d) / b, 1.0 / c)
                                        : std::exp((xd - g) / e) - f;
        expect_near_rel(pu_inverse(x), y, 4e-6, "pu_inverse", x);
    }
}

TEST(NetworkTransfer, PuNormIsPuOfTheLargestHalf)
{
    EXPECT_EQ(pu_norm(), pu_forward(pu_max_input));
    EXPECT_NEAR(pu_norm(), 3.135119, 1e-6);
    EXPECT_NEAR(pu_encode(pu_max_input), 1.f, 1.2e-7f);
    expect_near_rel(pu_decode(1.f), 65504.0, 1e-5, "pu_decode", 1.0);
    for (float y : sweep(1e-8, 65504, 7))
        EXPECT_FLOAT_EQ(pu_encode(y), pu_forward(y) / pu_norm()) << y;
    for (float x : { 0.f, 1e-4f, 0.01f, 0.1f, 0.5f, 1.f })
        EXPECT_EQ(pu_decode(x), pu_inverse(x * pu_norm())) << x;
}

TEST(NetworkTransfer, SrgbAgainstHandComputedValues)
{
    const struct {
        float y;
        double x;
    } cases[] = {
        { 0.f, 0.0 },
        { 0.001f, 0.01292 },
        { srgb_y0, 0.040449936 },
        { 0.01f, 0.0998528227 },
        { 0.18f, 0.46135613 },
        { 0.5f, 0.735356983 },
        { 1.f, 1.0 },
        { 2.f, 1.35325605 },
    };
    for (const auto& c : cases) {
        expect_near_rel(srgb_forward(c.y), c.x, 2e-6, "srgb_forward", c.y);
        if (c.y > 0.f)
            expect_near_rel(srgb_inverse(float(c.x)), c.y, 4e-6, "srgb_inverse", c.x);
    }
    const double past_y0 = 1.055 * std::pow(double(next_up(srgb_y0)), 1 / 2.4) - 0.055;
    expect_near_rel(srgb_forward(next_up(srgb_y0)), past_y0, 2e-6, "srgb_forward",
                    next_up(srgb_y0));
    expect_near_rel(srgb_inverse(srgb_x0), 0.04045 / 12.92, 2e-6, "srgb_inverse", srgb_x0);
    const double past_x0 = std::pow((double(next_up(srgb_x0)) + 0.055) / 1.055, 2.4);
    expect_near_rel(srgb_inverse(next_up(srgb_x0)), past_x0, 4e-6, "srgb_inverse",
                    next_up(srgb_x0));
}

TEST(NetworkTransfer, ContinuousAtEverySwitch)
{
    const struct {
        float (*f)(float);
        float at;
        const char* name;
    } switches[] = {
        { pu_forward, pu_y0, "pu_forward" },       { pu_forward, pu_y1, "pu_forward" },
        { pu_inverse, pu_x0, "pu_inverse" },       { pu_inverse, pu_x1, "pu_inverse" },
        { srgb_forward, srgb_y0, "srgb_forward" }, { srgb_inverse, srgb_x0, "srgb_inverse" },
    };
    for (const auto& s : switches)
        expect_near_rel(s.f(next_up(s.at)), s.f(s.at), 1e-5, s.name, s.at);
}

TEST(NetworkTransfer, InverseUndoesForwardOverTheRange)
{
    for (float y : sweep(1e-8, 65504, 50)) {
        expect_near_rel(pu_inverse(pu_forward(y)), y, 1e-5, "pu_inverse(pu_forward)", y);
        expect_near_rel(pu_decode(pu_encode(y)), y, 1e-5, "pu_decode(pu_encode)", y);
        expect_near_rel(srgb_inverse(srgb_forward(y)), y, 1e-5, "srgb_inverse(srgb_forward)", y);
    }
    for (float y : { pu_y0, next_up(pu_y0), pu_y1, next_up(pu_y1), srgb_y0, next_up(srgb_y0) }) {
        expect_near_rel(pu_decode(pu_encode(y)), y, 1e-5, "pu_decode(pu_encode)", y);
        expect_near_rel(srgb_inverse(srgb_forward(y)), y, 1e-5, "srgb_inverse(srgb_forward)", y);
    }
}

TEST(NetworkTransfer, MonotonicOverTheRange)
{
    const std::vector<float> ys = sweep(1e-8, 65504, 50);
    for (size_t i = 1; i < ys.size(); ++i) {
        EXPECT_LT(pu_forward(ys[i - 1]), pu_forward(ys[i])) << ys[i];
        EXPECT_LT(srgb_forward(ys[i - 1]), srgb_forward(ys[i])) << ys[i];
    }
}

TEST(NetworkTransfer, RowFormsEqualTheScalarForms)
{
    std::vector<float> values = sweep(1e-8, 65504, 20);
    values.push_back(0.f);
    const struct {
        void (*row)(float*, size_t);
        float (*scalar)(float);
    } forms[] = { { pu_encode_row, pu_encode },
                  { pu_decode_row, pu_decode },
                  { srgb_forward_row, srgb_forward },
                  { srgb_inverse_row, srgb_inverse } };
    for (const auto& form : forms) {
        std::vector<float> row = values;
        form.row(row.data(), row.size());
        for (size_t i = 0; i < values.size(); ++i)
            EXPECT_EQ(row[i], form.scalar(values[i])) << values[i];
    }
}

TEST(NetworkTransfer, NanNegativeAndInfinity)
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    for (float (*f)(float) :
         { pu_forward, pu_inverse, pu_encode, pu_decode, srgb_forward, srgb_inverse }) {
        EXPECT_TRUE(std::isnan(f(nan)));
        EXPECT_EQ(f(inf), inf);
        EXPECT_EQ(f(0.f), 0.f);
    }
    // Negative values take the linear segment: the curves are odd there.
    EXPECT_FLOAT_EQ(pu_forward(-1.f), -1.41283765e3f);
    EXPECT_FLOAT_EQ(pu_inverse(-1.f), -1.f / 1.41283765e3f);
    EXPECT_FLOAT_EQ(srgb_forward(-0.5f), -0.5f * 12.92f);
    EXPECT_FLOAT_EQ(srgb_inverse(-0.5f), -0.5f / 12.92f);
    // The largest float decodes past the float range.
    EXPECT_EQ(pu_decode(std::numeric_limits<float>::max()), inf);
}

}  // namespace
