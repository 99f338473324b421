// integrator.h: unidirectional path tracing with next-event estimation and
// multiple importance sampling (power heuristic), and the geometric AOVs of
// a pixel's center ray.
#pragma once

#include "passes.h"
#include "rng.h"
#include "scene.h"

namespace testrender {

/// What one camera sample returns.
struct PathResult {
    Vec3 radiance;
    Vec3 albedo;  ///< reflectance of the first non-specular hit, times mirror tints
    Vec3 normal;  ///< first-hit normal facing the camera; 0 for a miss
    double alpha = 1;  ///< 0 if the camera ray escapes through a transparent film
    SamplePasses passes;  ///< `radiance` split into the light passes
};

/// Trace one path from `camera_ray`, drawing random numbers from `rng`.
PathResult trace_path(const Scene& scene, const Ray& camera_ray, SampleRng& rng);

/// The AOVs taken from one ray per pixel (through the pixel center and the
/// lens center), because averaging them over samples has no meaning.
struct GeometryAovs {
    float depth;  ///< first-hit distance, +Inf for a miss
    int id;       ///< object id of the first hit, -1 for a miss
    int reflid;   ///< at a mirror first hit, object id its reflection ray hits; else -1
    int object;   ///< index of the first-hit object in Scene::objects, -1 for a miss
    Vec3 position;  ///< the first-hit point (world space); unset for a miss
};

GeometryAovs trace_geometry(const Scene& scene, const Ray& center_ray);

}  // namespace testrender
