// motion.cpp: the motion AOV, by projecting the first hit (or, for a miss,
// the view direction) through the neighbouring frames' cameras.
#include "motion.h"

namespace testrender {

namespace {

bool same_point(const Vec3& a, const Vec3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

bool same_camera(const CameraParams& a, const CameraParams& b)
{
    return same_point(a.eye, b.eye) && same_point(a.look_at, b.look_at) && same_point(a.up, b.up)
           && a.vfov_degrees == b.vfov_degrees;
}

}  // namespace

ShotCameras::ShotCameras(const Scene& scene, int width, int height)
    : current(scene.camera, width, height),
      previous(scene.neighbour_camera(0), width, height),
      next(scene.neighbour_camera(1), width, height),
      previous_still(same_camera(scene.camera, scene.neighbour_camera(0))),
      next_still(same_camera(scene.camera, scene.neighbour_camera(1)))
{
}

namespace {

/// Where the hit (or, for a miss, the direction) appears through `camera`
/// in the neighbour frame `which`; false if behind that camera or if
/// nothing moves (camera `still` and the object not shifted).
bool neighbour_position(const Scene& scene, int which, const Camera& camera, bool still,
                        const Ray& ray, const GeometryAovs& g, double& fx, double& fy)
{
    if (g.object < 0)
        return !still && camera.project_direction(ray.dir, fx, fy);
    const Vec3 shift = scene.neighbour_shift(which, g.object);
    if (still && is_black(shift))
        return false;
    return camera.project(g.position + shift, fx, fy);
}

}  // namespace

MotionVector pixel_motion(const Scene& scene, const ShotCameras& cameras, double fx, double fy,
                          const Ray& center_ray, const GeometryAovs& g)
{
    MotionVector m;
    double px, py;
    if (neighbour_position(scene, 0, cameras.previous, cameras.previous_still, center_ray, g, px, py)) {
        m.x = float(px - fx);
        m.y = float(fy - py);
    }
    if (neighbour_position(scene, 1, cameras.next, cameras.next_still, center_ray, g, px, py)) {
        m.z = float(fx - px);
        m.w = float(py - fy);
    }
    return m;
}

}  // namespace testrender
