// shapes.h: the analytic shapes (sphere, parallelogram "quad", box rotated
// about the vertical axis) and their ray intersection. Each returns the hit
// distance, the outward geometric normal and surface coordinates for textures.
#pragma once

#include "math.h"

namespace testrender {

/// What a ray hit: filled by `Shape::intersect` (t, normal, uv, position)
/// and by the scene (which object).
struct Hit {
    double t = 0;
    Vec3 position;
    Vec3 normal;     ///< outward geometric normal, unit length
    double u = 0, v = 0;  ///< surface coordinates (world units along the surface)
    int object = -1;  ///< index into Scene::objects
};

enum class ShapeKind { sphere, quad, box };

struct Shape {
    ShapeKind kind = ShapeKind::sphere;
    // sphere: center, radius
    Vec3 center;
    double radius = 1;
    // quad: corner + edge_u * a + edge_v * b for a, b in [0,1]; normal is
    // normalize(cross(edge_u, edge_v))
    Vec3 corner, edge_u, edge_v;
    Vec3 quad_normal;
    double quad_area = 0;
    Vec3 quad_w;                  ///< cross(edge_u, edge_v) / |cross(edge_u, edge_v)|^2
    double edge_u_len = 0, edge_v_len = 0;
    // box: center, half extents, rotation about +y (cos, sin)
    Vec3 half_size;
    double cos_y = 1, sin_y = 0;

    static Shape sphere(const Vec3& center, double radius);
    static Shape quad(const Vec3& corner, const Vec3& edge_u, const Vec3& edge_v);
    static Shape box(const Vec3& center, const Vec3& half_size, double rotate_y_degrees);

    /// Distance to the nearest hit with t in (t_min, t_max), or 0 for none.
    /// Cheap: the surface attributes are computed by `surface` for the one
    /// hit that turns out nearest.
    double hit_distance(const Ray& ray, double t_min, double t_max) const;

    /// Fill position, normal, u, v of the hit at distance `t` along `ray`.
    void surface(const Ray& ray, double t, Hit& hit) const;

    /// The point the shape is placed by (a sphere's or box's center, a
    /// quad's corner): a point's position relative to it is its object-space
    /// position, which a translation of the shape leaves unchanged.
    Vec3 anchor() const { return kind == ShapeKind::quad ? corner : center; }
};

}  // namespace testrender
