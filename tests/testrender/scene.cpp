// scene.cpp: object storage, brute-force nearest-hit and shadow queries
// (the scenes have tens of objects), area-proportional light sampling, and
// the object motion between neighbouring frames.
#include "scene.h"

#include <algorithm>

namespace testrender {

int Scene::add_material(const Material& m)
{
    materials.push_back(m);
    return int(materials.size()) - 1;
}

int Scene::add(const Shape& shape, int material, int id)
{
    objects.push_back({ shape, material, id });
    const int index = int(objects.size()) - 1;
    if (materials[size_t(material)].kind == MaterialKind::emitter && shape.kind == ShapeKind::quad) {
        lights_.push_back(index);
        total_light_area_ += shape.quad_area;
        light_cdf_.push_back(total_light_area_);
    }
    return index;
}

void Scene::set_neighbours(const Scene& previous, const Scene& next)
{
    neighbours.clear();
    for (const Scene* other : { &previous, &next }) {
        NeighbourFrame f;
        f.camera = other->camera;
        for (size_t i = 0; i < objects.size(); ++i)
            f.shift.push_back(other->objects[i].shape.anchor() - objects[i].shape.anchor());
        neighbours.push_back(f);
    }
}

const CameraParams& Scene::neighbour_camera(int which) const
{
    return neighbours.empty() ? camera : neighbours[size_t(which)].camera;
}

Vec3 Scene::neighbour_shift(int which, int object) const
{
    return neighbours.empty() ? Vec3(0.0) : neighbours[size_t(which)].shift[size_t(object)];
}

bool Scene::intersect(const Ray& ray, Hit& hit, double t_max) const
{
    int nearest = -1;
    double closest = t_max;
    for (size_t i = 0; i < objects.size(); ++i) {
        const double t = objects[i].shape.hit_distance(ray, ray_epsilon, closest);
        if (t > 0) {
            closest = t;
            nearest = int(i);
        }
    }
    if (nearest < 0)
        return false;
    objects[size_t(nearest)].shape.surface(ray, closest, hit);
    hit.object = nearest;
    return true;
}

bool Scene::occluded(const Ray& ray, double t_max) const
{
    for (const Object& o : objects)
        if (o.shape.hit_distance(ray, ray_epsilon, t_max) > 0)
            return true;
    return false;
}

LightSample Scene::sample_light(double u0, double u1, double u2) const
{
    LightSample s;
    if (lights_.empty())
        return s;
    const double target = u0 * total_light_area_;
    const size_t k = std::min(size_t(std::upper_bound(light_cdf_.begin(), light_cdf_.end(), target)
                                     - light_cdf_.begin()),
                              lights_.size() - 1);
    const Object& light = objects[size_t(lights_[k])];
    const Shape& q = light.shape;
    s.position = q.corner + q.edge_u * u1 + q.edge_v * u2;
    s.normal = q.quad_normal;
    s.radiance = materials[size_t(light.material)].emission;
    s.pdf_area = 1.0 / total_light_area_;
    return s;
}

}  // namespace testrender
