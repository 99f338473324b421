// shapes.cpp: ray intersection of spheres (geometric form of the quadratic),
// quads (plane, then coordinates along the edges) and y-rotated boxes (slab
// test in the box's own frame). The distance test is separate from the
// surface attributes, which are computed only for the nearest hit.
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
    s.quad_w = n / dot(n, n);
    s.edge_u_len = length(edge_u);
    s.edge_v_len = length(edge_v);
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

double sphere_distance(const Shape& s, const Ray& ray, double t_min, double t_max)
{
    const Vec3 oc = ray.origin - s.center;
    const double b = dot(oc, ray.dir);
    // discriminant from the closest approach, for precision on far spheres
    const Vec3 closest = oc - ray.dir * b;
    const double disc = s.radius * s.radius - dot(closest, closest);
    if (disc < 0)
        return 0;
    const double root = std::sqrt(disc);
    double t = -b - root;
    if (t <= t_min || t >= t_max) {
        t = -b + root;
        if (t <= t_min || t >= t_max)
            return 0;
    }
    return t;
}

/// Coordinates of `p` along the quad's edges, each in [0, 1] on the quad.
void quad_coordinates(const Shape& s, const Vec3& p, double& a, double& b)
{
    const Vec3 d = p - s.corner;
    a = dot(cross(d, s.edge_v), s.quad_w);
    b = dot(cross(s.edge_u, d), s.quad_w);
}

double quad_distance(const Shape& s, const Ray& ray, double t_min, double t_max)
{
    const double denom = dot(s.quad_normal, ray.dir);
    if (std::abs(denom) < 1e-12)
        return 0;
    const double t = dot(s.corner - ray.origin, s.quad_normal) / denom;
    if (t <= t_min || t >= t_max)
        return 0;
    double a, b;
    quad_coordinates(s, ray.at(t), a, b);
    if (a < 0 || a > 1 || b < 0 || b > 1)
        return 0;
    return t;
}

/// The ray in the box's frame (rotated by -angle about y, box at the origin).
Ray box_local_ray(const Shape& s, const Ray& ray)
{
    const Vec3 o = ray.origin - s.center;
    return { Vec3(s.cos_y * o.x - s.sin_y * o.z, o.y, s.sin_y * o.x + s.cos_y * o.z),
             Vec3(s.cos_y * ray.dir.x - s.sin_y * ray.dir.z, ray.dir.y,
                  s.sin_y * ray.dir.x + s.cos_y * ray.dir.z) };
}

double box_distance(const Shape& s, const Ray& ray, double t_min, double t_max)
{
    const Ray local = box_local_ray(s, ray);
    double t_near = -1e300, t_far = 1e300;
    for (int a = 0; a < 3; ++a) {
        const double inv = 1.0 / local.dir[a];  // +-inf for axis-parallel rays is fine
        double t0 = (-s.half_size[a] - local.origin[a]) * inv;
        double t1 = (s.half_size[a] - local.origin[a]) * inv;
        if (t0 > t1)
            std::swap(t0, t1);
        t_near = std::max(t_near, t0);
        t_far = std::min(t_far, t1);
        if (t_near > t_far)
            return 0;
    }
    if (t_near > t_min && t_near < t_max)
        return t_near;
    if (t_far > t_min && t_far < t_max)
        return t_far;
    return 0;
}

void box_surface(const Shape& s, const Ray& ray, double t, Hit& hit)
{
    const Ray local = box_local_ray(s, ray);
    const Vec3 lp = local.at(t);
    // the face is the axis where the point is relatively closest to the side
    int axis = 0;
    double best = 1e300;
    for (int a = 0; a < 3; ++a) {
        const double gap = std::abs(std::abs(lp[a]) - s.half_size[a]);
        if (gap < best) {
            best = gap;
            axis = a;
        }
    }
    Vec3 ln(0, 0, 0);
    if (axis == 0) {
        ln.x = lp.x > 0 ? 1 : -1;
        hit.u = lp.z + s.half_size.z;
        hit.v = lp.y + s.half_size.y;
    } else if (axis == 1) {
        ln.y = lp.y > 0 ? 1 : -1;
        hit.u = lp.x + s.half_size.x;
        hit.v = lp.z + s.half_size.z;
    } else {
        ln.z = lp.z > 0 ? 1 : -1;
        hit.u = lp.x + s.half_size.x;
        hit.v = lp.y + s.half_size.y;
    }
    // back to world: rotate by +angle about y
    hit.normal = Vec3(s.cos_y * ln.x + s.sin_y * ln.z, ln.y, -s.sin_y * ln.x + s.cos_y * ln.z);
}

}  // namespace

double Shape::hit_distance(const Ray& ray, double t_min, double t_max) const
{
    switch (kind) {
    case ShapeKind::sphere: return sphere_distance(*this, ray, t_min, t_max);
    case ShapeKind::quad: return quad_distance(*this, ray, t_min, t_max);
    case ShapeKind::box: return box_distance(*this, ray, t_min, t_max);
    }
    return 0;
}

void Shape::surface(const Ray& ray, double t, Hit& hit) const
{
    hit.t = t;
    hit.position = ray.at(t);
    switch (kind) {
    case ShapeKind::sphere:
        hit.normal = (hit.position - center) / radius;
        // longitude / latitude times the radius: texture features keep their
        // world size on spheres of any radius
        hit.u = (std::atan2(hit.normal.z, hit.normal.x) + pi) * radius;
        hit.v = std::acos(std::clamp(hit.normal.y, -1.0, 1.0)) * radius;
        break;
    case ShapeKind::quad: {
        double a, b;
        quad_coordinates(*this, hit.position, a, b);
        hit.normal = quad_normal;
        hit.u = a * edge_u_len;
        hit.v = b * edge_v_len;
        break;
    }
    case ShapeKind::box: box_surface(*this, ray, t, hit); break;
    }
}

}  // namespace testrender
