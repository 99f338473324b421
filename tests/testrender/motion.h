// motion.h: the motion AOV: where the surface a pixel sees was one frame
// earlier and will be one frame later, on the film, in Blender Cycles'
// Vector-pass convention.
#pragma once

#include "camera.h"
#include "integrator.h"
#include "scene.h"

namespace testrender {

/// The motion pass of one pixel, in pixels, rows counted from the top:
/// the pixel at film position (fx, fy) was at (fx + x, fy - y) in the
/// previous frame and is at (fx - z, fy + w) in the next frame.
struct MotionVector {
    float x = 0, y = 0, z = 0, w = 0;
};

/// The cameras of a frame and of its two neighbours, at one resolution.
struct ShotCameras {
    ShotCameras(const Scene& scene, int width, int height);
    Camera current, previous, next;
    /// Whether the previous / next frame's camera is this frame's.
    bool previous_still, next_still;
};

/// The motion of the center-ray hit `g` seen through film position (fx, fy):
/// its object-space point carried by the object's translation to the
/// previous and next frame and projected through that frame's camera. A miss
/// moves as the direction at infinity does (only a camera rotation moves
/// it). A half whose point is behind that frame's camera is 0, and so is
/// one where neither the camera nor the object moves (exactly, not to
/// rounding).
MotionVector pixel_motion(const Scene& scene, const ShotCameras& cameras, double fx, double fy,
                          const Ray& center_ray, const GeometryAovs& g);

}  // namespace testrender
