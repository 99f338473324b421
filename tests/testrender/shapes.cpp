// shapes.cpp: ray intersection of spheres (geometric form of the quadratic),
// quads (plane then barycentric-like coordinates) and y-rotated boxes (slab
// test in the box's own frame).
#include "shapes.h"

namespace testrender {

Shape Shape::sphere(const Vec3& center, double radius)
{
    Shape s;
    s.kind = ShapeKind::sphere;
    s.center = center;
    s.radius = radius;
    return s;
}

Shape Shape::quad(const Vec3& corner, const Vec3& edge_u, const Vec3& edge_v)
{
    Shape s;
    s.kind = ShapeKind::quad;
    s.corner = corner;
    s.edge_u = edge_u;
    s.edge_v = edge_v;
    const Vec3 n = cross(edge_u, edge_v);
    s.quad_area = length(n);
    s.quad_normal = n / s.quad_area;
    return s;
}

Shape Shape::box(const Vec3& center, const Vec3& half_size, double rotate_y_degrees)
{
    Shape s;
    s.kind = ShapeKind::box;
    s.center = center;
    s.half_size = half_size;
    s.cos_y = std::cos(rotate_y_degrees * pi / 180);
    s.sin_y = std::sin(rotate_y_degrees * pi / 180);
    return s;
}

namespace {

bool hit_sphere(const Shape& s, const Ray& ray, double t_min, double t_max, Hit& hit)
{
    const Vec3 oc = ray.origin - s.center;
    const double b = dot(oc, ray.dir);
    // c computed from the closest approach for precision on far spheres
    const Vec3 closest = oc - ray.dir * b;
    const double disc = s.radius * s.radius - dot(closest, closest);
    if (disc < 0)
        return false;
    const double root = std::sqrt(disc);
    double t = -b - root;
    if (t <= t_min || t >= t_max) {
        t = -b + root;
        if (t <= t_min || t >= t_max)
            return false;
    }
    hit.t = t;
    hit.position = ray.at(t);
    hit.normal = (hit.position - s.center) / s.radius;
    // longitude/latitude scaled by the radius: texture features keep their
    // world size on spheres of any radius
    hit.u = (std::atan2(hit.normal.z, hit.normal.x) + pi) * s.radius;
    hit.v = std::acos(std::clamp(hit.normal.y, -1.0, 1.0)) * s.radius;
    return true;
}

bool hit_quad(const Shape& s, const Ray& ray, double t_min, double t_max, Hit& hit)
{
    const double denom = dot(s.quad_normal, ray.dir);
    if (std::abs(denom) < 1e-12)
        return false;
    const double t = dot(s.corner - ray.origin, s.quad_normal) / denom;
    if (t <= t_min || t >= t_max)
        return false;
    const Vec3 p = ray.at(t);
    const Vec3 d = p - s.corner;
    // coordinates along the (not necessarily orthogonal) edges
    const Vec3 w = cross(s.edge_u, s.edge_v);
    const double inv = 1.0 / dot(w, w);
    const double a = dot(cross(d, s.edge_v), w) * inv;
    const double b = dot(cross(s.edge_u, d), w) * inv;
    if (a < 0 || a > 1 || b < 0 || b > 1)
        return false;
    hit.t = t;
    hit.position = p;
    hit.normal = s.quad_normal;
    hit.u = a * length(s.edge_u);
    hit.v = b * length(s.edge_v);
    return true;
}

bool hit_box(const Shape& s, const Ray& ray, double t_min, double t_max, Hit& hit)
{
    // into the box frame: rotate by -angle about y
    const Vec3 o = ray.origin - s.center;
    const Vec3 lo(s.cos_y * o.x - s.sin_y * o.z, o.y, s.sin_y * o.x + s.cos_y * o.z);
    const Vec3 ld(s.cos_y * ray.dir.x - s.sin_y * ray.dir.z, ray.dir.y,
                  s.sin_y * ray.dir.x + s.cos_y * ray.dir.z);
    double t_near = -1e300, t_far = 1e300;
    int axis_near = 0, axis_far = 0;
    for (int a = 0; a < 3; ++a) {
        const double inv = 1.0 / ld[a];  // +-inf for axis-parallel rays is fine
        double t0 = (-s.half_size[a] - lo[a]) * inv;
        double t1 = (s.half_size[a] - lo[a]) * inv;
        if (t0 > t1)
            std::swap(t0, t1);
        if (t0 > t_near) {
            t_near = t0;
            axis_near = a;
        }
        if (t1 < t_far) {
            t_far = t1;
            axis_far = a;
        }
        if (t_near > t_far)
            return false;
    }
    double t = t_near;
    int axis = axis_near;
    if (t <= t_min || t >= t_max) {
        t = t_far;
        axis = axis_far;
        if (t <= t_min || t >= t_max)
            return false;
    }
    const Vec3 lp = lo + ld * t;
    Vec3 ln(0, 0, 0);
    double u, v;
    if (axis == 0) {
        ln.x = lp.x > 0 ? 1 : -1;
        u = lp.z + s.half_size.z;
        v = lp.y + s.half_size.y;
    } else if (axis == 1) {
        ln.y = lp.y > 0 ? 1 : -1;
        u = lp.x + s.half_size.x;
        v = lp.z + s.half_size.z;
    } else {
        ln.z = lp.z > 0 ? 1 : -1;
        u = lp.x + s.half_size.x;
        v = lp.y + s.half_size.y;
    }
    hit.t = t;
    hit.position = ray.at(t);
    // back to world: rotate by +angle about y
    hit.normal = Vec3(s.cos_y * ln.x + s.sin_y * ln.z, ln.y, -s.sin_y * ln.x + s.cos_y * ln.z);
    hit.u = u;
    hit.v = v;
    return true;
}

}  // namespace

bool Shape::intersect(const Ray& ray, double t_min, double t_max, Hit& hit) const
{
    switch (kind) {
    case ShapeKind::sphere: return hit_sphere(*this, ray, t_min, t_max, hit);
    case ShapeKind::quad: return hit_quad(*this, ray, t_min, t_max, hit);
    case ShapeKind::box: return hit_box(*this, ray, t_min, t_max, hit);
    }
    return false;
}

}  // namespace testrender
