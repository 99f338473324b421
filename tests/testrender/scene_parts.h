// scene_parts.h: pieces the built-in scenes are assembled from: oriented
// quads, rooms and panel lights.
#pragma once

#include "scene.h"

namespace testrender {

/// A quad with corner `c` and edges `u`, `v`, oriented so that its normal
/// points along `facing` (the edges are swapped if needed).
Shape facing_quad(const Vec3& c, const Vec3& u, const Vec3& v, const Vec3& facing);

/// The inside of the axis-aligned box [lo, hi] as five or six walls facing
/// inwards, ids first_id, first_id+1, ... in the order floor, ceiling,
/// back (-z), left (-x), right (+x) and, if `closed`, front (+z).
void add_room(Scene& s, const Vec3& lo, const Vec3& hi, int floor_m, int ceiling_m, int back_m,
              int left_m, int right_m, int front_m, int first_id, bool closed);

/// A horizontal area light facing down (or up) centered at `c`.
void add_panel_light(Scene& s, const Vec3& c, double half_x, double half_z, int material,
                     int id, bool facing_up = false);

}  // namespace testrender
