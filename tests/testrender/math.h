// math.h: the small vector algebra the path tracer needs: a 3-vector of
// doubles, rays, an orthonormal basis, and a few constants.
#pragma once

#include <algorithm>
#include <cmath>

namespace testrender {

constexpr double pi = 3.14159265358979323846;
constexpr double inv_pi = 1.0 / pi;
/// Offset of secondary ray origins from the surface they leave, and the
/// smallest hit distance accepted (against self-intersection).
constexpr double ray_epsilon = 1e-6;

struct Vec3 {
    double x = 0, y = 0, z = 0;
    constexpr Vec3() = default;
    constexpr Vec3(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}
    constexpr explicit Vec3(double v) : x(v), y(v), z(v) {}
    constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
    Vec3& operator+=(const Vec3& b) { x += b.x; y += b.y; z += b.z; return *this; }
    Vec3& operator*=(const Vec3& b) { x *= b.x; y *= b.y; z *= b.z; return *this; }
    Vec3& operator*=(double s) { x *= s; y *= s; z *= s; return *this; }
};

constexpr Vec3 operator+(const Vec3& a, const Vec3& b) { return { a.x + b.x, a.y + b.y, a.z + b.z }; }
constexpr Vec3 operator-(const Vec3& a, const Vec3& b) { return { a.x - b.x, a.y - b.y, a.z - b.z }; }
constexpr Vec3 operator-(const Vec3& a) { return { -a.x, -a.y, -a.z }; }
constexpr Vec3 operator*(const Vec3& a, const Vec3& b) { return { a.x * b.x, a.y * b.y, a.z * b.z }; }
constexpr Vec3 operator*(const Vec3& a, double s) { return { a.x * s, a.y * s, a.z * s }; }
constexpr Vec3 operator*(double s, const Vec3& a) { return a * s; }
constexpr Vec3 operator/(const Vec3& a, double s) { return a * (1.0 / s); }
constexpr double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr Vec3 cross(const Vec3& a, const Vec3& b)
{
    return { a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x };
}
inline double length(const Vec3& a) { return std::sqrt(dot(a, a)); }
inline Vec3 normalize(const Vec3& a) { return a / length(a); }
constexpr double max_component(const Vec3& a) { return std::max(a.x, std::max(a.y, a.z)); }
/// Rec.709 luminance.
constexpr double luminance(const Vec3& c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }
constexpr bool is_black(const Vec3& c) { return c.x == 0 && c.y == 0 && c.z == 0; }
/// Mirror `d` (pointing at the surface) about the normal `n`.
constexpr Vec3 reflect(const Vec3& d, const Vec3& n) { return d - n * (2 * dot(d, n)); }

struct Ray {
    Vec3 origin;
    Vec3 dir;  ///< unit length, so hit distances are distances
    Vec3 at(double t) const { return origin + dir * t; }
};

/// An orthonormal basis around the unit vector `w` (Duff et al. 2017,
/// "Building an Orthonormal Basis, Revisited").
struct Frame {
    Vec3 u, v, w;
    explicit Frame(const Vec3& n) : w(n)
    {
        const double sign = std::copysign(1.0, n.z);
        const double a = -1.0 / (sign + n.z);
        const double b = n.x * n.y * a;
        u = Vec3(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
        v = Vec3(b, sign + n.y * n.y * a, -n.y);
    }
    Vec3 to_world(const Vec3& l) const { return u * l.x + v * l.y + w * l.z; }
    Vec3 to_local(const Vec3& d) const { return { dot(d, u), dot(d, v), dot(d, w) }; }
};

}  // namespace testrender
