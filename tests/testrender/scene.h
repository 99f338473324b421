// scene.h: a scene is a list of objects (shape + material + object id), the
// area lights among them, a background colour and a camera, at one frame of
// its animation, with where its camera and objects are one frame before and
// after; plus the registry of built-in scenes.
#pragma once

#include "camera.h"
#include "materials.h"
#include "shapes.h"

#include <string>
#include <vector>

namespace testrender {

struct Object {
    Shape shape;
    int material = 0;
    int id = 0;  ///< the object id written to the `id` and `reflid` AOVs
};

/// A point chosen on the area lights, with density over total light area.
struct LightSample {
    Vec3 position;
    Vec3 normal;
    Vec3 radiance;
    double pdf_area = 0;
};

/// The camera and the objects at a neighbouring frame (the previous or the
/// next), relative to the scene's own frame. Objects move by translation only.
struct NeighbourFrame {
    CameraParams camera;
    std::vector<Vec3> shift;  ///< per object: its translation from this frame to that one
};

struct Scene {
    std::string name;
    std::string description;
    std::vector<Object> objects;
    std::vector<Material> materials;
    Vec3 background { 0, 0, 0 };  ///< radiance of rays that escape
    /// Camera rays that escape are transparent (alpha 0, no colour) instead
    /// of seeing the background, which still lights the scene.
    bool transparent_film = false;
    CameraParams camera;
    int max_depth = 8;       ///< longest path, in bounces
    int roulette_depth = 3;  ///< bounces before Russian roulette starts
    /// The scene one frame earlier and one frame later. Empty (no motion:
    /// the camera and every object stay put) unless set by `set_neighbours`.
    std::vector<NeighbourFrame> neighbours;

    /// Record where the camera and every object are in `previous` and `next`,
    /// the same scene built one frame before and one frame after (same
    /// objects in the same order; each may only be translated).
    void set_neighbours(const Scene& previous, const Scene& next);
    /// The camera of the previous (`which` = 0) or next (1) frame; this
    /// frame's camera if the scene has no neighbours.
    const CameraParams& neighbour_camera(int which) const;
    /// The translation of object `object` from this frame to the previous
    /// (`which` = 0) or next (1) frame; 0 if the scene has no neighbours.
    Vec3 neighbour_shift(int which, int object) const;

    int add_material(const Material& m);
    /// Add an object; returns its index. Emitters must be quads (they are
    /// sampled by area) and emit on the side of the quad's normal.
    int add(const Shape& shape, int material, int id);

    /// Nearest hit along `ray` closer than `t_max`.
    bool intersect(const Ray& ray, Hit& hit, double t_max = 1e300) const;
    /// True if anything blocks `ray` before `t_max`.
    bool occluded(const Ray& ray, double t_max) const;

    bool has_lights() const { return !lights_.empty(); }
    /// A point on the lights, uniform over their total area.
    LightSample sample_light(double u0, double u1, double u2) const;
    /// Area density of `sample_light` (the same everywhere on every light).
    double light_pdf_area() const { return lights_.empty() ? 0 : 1.0 / total_light_area_; }

private:
    std::vector<int> lights_;          ///< object indices of emitters
    std::vector<double> light_cdf_;    ///< cumulative area
    double total_light_area_ = 0;
};

/// The names of the built-in scenes, in the order `--list` shows them.
std::vector<std::string> scene_names();
/// Build the built-in scene `name` at frame `frame` of its animation, with
/// its neighbour frames; false if there is none by that name.
bool make_scene(const std::string& name, Scene& scene, int frame = 0);

}  // namespace testrender
