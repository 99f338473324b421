// scene_parts.cpp: pieces the built-in scenes are assembled from: oriented
// quads, rooms and panel lights.
#include "scene_parts.h"

namespace testrender {

Shape facing_quad(const Vec3& c, const Vec3& u, const Vec3& v, const Vec3& facing)
{
    if (dot(cross(u, v), facing) < 0)
        return Shape::quad(c, v, u);
    return Shape::quad(c, u, v);
}

void add_room(Scene& s, const Vec3& lo, const Vec3& hi, int floor_m, int ceiling_m, int back_m,
              int left_m, int right_m, int front_m, int first_id, bool closed)
{
    const Vec3 dx(hi.x - lo.x, 0, 0), dy(0, hi.y - lo.y, 0), dz(0, 0, hi.z - lo.z);
    s.add(facing_quad(lo, dx, dz, { 0, 1, 0 }), floor_m, first_id + 0);
    s.add(facing_quad(Vec3(lo.x, hi.y, lo.z), dx, dz, { 0, -1, 0 }), ceiling_m, first_id + 1);
    s.add(facing_quad(lo, dx, dy, { 0, 0, 1 }), back_m, first_id + 2);
    s.add(facing_quad(lo, dy, dz, { 1, 0, 0 }), left_m, first_id + 3);
    s.add(facing_quad(Vec3(hi.x, lo.y, lo.z), dy, dz, { -1, 0, 0 }), right_m, first_id + 4);
    if (closed)
        s.add(facing_quad(Vec3(lo.x, lo.y, hi.z), dx, dy, { 0, 0, -1 }), front_m, first_id + 5);
}

void add_panel_light(Scene& s, const Vec3& c, double half_x, double half_z, int material,
                     int id, bool facing_up)
{
    s.add(facing_quad(Vec3(c.x - half_x, c.y, c.z - half_z), Vec3(2 * half_x, 0, 0),
                      Vec3(0, 0, 2 * half_z), Vec3(0, facing_up ? 1 : -1, 0)),
          material, id);
}

}  // namespace testrender
