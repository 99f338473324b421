// integrator.cpp: the path tracer. At each non-specular vertex the light is
// sampled by area (next-event estimation) and the BSDF is sampled for the
// next bounce; both estimates of light hit by a BSDF-sampled ray are
// combined with the power heuristic (Veach 1997, section 9.2). Specular
// vertices (mirror, glass) continue the path without light sampling. Every
// contribution to the radiance is also filed in the light passes, by the
// first hit's lobe and the number of scatterings before it reaches the camera.
#include "integrator.h"

#include <limits>

namespace testrender {

namespace {

/// Secondary rays start this far off the surface, on the side they leave.
constexpr double surface_offset = 1e-5;
/// Shadow rays stop this fraction short of the light point.
constexpr double shadow_margin = 1e-7;
/// Russian roulette keeps a path with at most this probability.
constexpr double max_survival = 0.95;

double power_heuristic(double pdf_a, double pdf_b)
{
    const double a2 = pdf_a * pdf_a, b2 = pdf_b * pdf_b;
    return a2 / (a2 + b2);
}

Vec3 offset_origin(const Hit& hit, const Vec3& dir)
{
    return hit.position + hit.normal * (dot(dir, hit.normal) > 0 ? surface_offset : -surface_offset);
}

/// Direct light at a non-specular vertex by sampling a point on the lights;
/// `shares` receives how the material's lobes divide it (lobe_shares).
Vec3 sample_direct(const Scene& scene, const Material& m, const Vec3& base, const Hit& hit,
                   const Frame& frame, const Vec3& wo, SampleRng& rng, Vec3 shares[3])
{
    const double u0 = rng.next(), u1 = rng.next(), u2 = rng.next();
    const LightSample ls = scene.sample_light(u0, u1, u2);
    const Vec3 to_light = ls.position - hit.position;
    const double dist2 = dot(to_light, to_light);
    const double dist = std::sqrt(dist2);
    const Vec3 wi = to_light / dist;
    const double cos_light = -dot(wi, ls.normal);
    if (cos_light <= 0)
        return Vec3(0.0);
    const Vec3 wi_local = frame.to_local(wi);
    const Vec3 f = bsdf_eval(m, base, wo, wi_local);
    if (is_black(f))
        return Vec3(0.0);
    // The shadow ray leaves from the offset origin, so its length to the
    // light point is measured from there: the light itself must not count as
    // an occluder.
    const Vec3 origin = offset_origin(hit, wi);
    const Vec3 to_light_from_origin = ls.position - origin;
    const double shadow_length = length(to_light_from_origin);
    const Ray shadow { origin, to_light_from_origin / shadow_length };
    if (scene.occluded(shadow, shadow_length * (1 - shadow_margin)))
        return Vec3(0.0);
    const double pdf_light = ls.pdf_area * dist2 / cos_light;
    const double weight = power_heuristic(pdf_light, bsdf_pdf(m, base, wo, wi_local));
    lobe_shares(m, base, wo, wi_local, shares);
    return f * ls.radiance * (weight / pdf_light);
}

/// File `light`, which reaches the camera after `scatterings` >= 1
/// scatterings (1: direct), in the passes of the first hit's lobes by `shares`.
void file_light(SamplePasses& p, const Vec3& light, int scatterings, const Vec3 shares[3])
{
    Vec3* passes = scatterings == 1 ? p.direct : p.indirect;
    for (int lobe = 0; lobe < lobe_count; ++lobe)
        passes[lobe] += light * shares[lobe];
}

}  // namespace

PathResult trace_path(const Scene& scene, const Ray& camera_ray, SampleRng& rng)
{
    PathResult result;
    SamplePasses& passes = result.passes;
    Vec3 throughput(1.0);
    Vec3 albedo_throughput(1.0);  // mirror tints along the specular prefix
    Vec3 first_shares[lobe_count];  // how the first hit's lobes divide the path's light
    bool albedo_done = false;
    bool previous_specular = true;  // the camera counts as specular: no MIS
    double previous_pdf = 0;
    Ray ray = camera_ray;
    for (int depth = 0;; ++depth) {
        Hit hit;
        if (!scene.intersect(ray, hit)) {
            if (depth == 0 && scene.transparent_film) {
                result.alpha = 0;
                break;
            }
            const Vec3 light = throughput * scene.background;
            result.radiance += light;
            if (depth == 0)
                passes.env = light;
            else
                file_light(passes, light, depth, first_shares);
            if (!albedo_done)
                result.albedo = albedo_throughput * scene.background;
            break;
        }
        const Object& object = scene.objects[size_t(hit.object)];
        const Material& m = scene.materials[size_t(object.material)];
        const bool front = dot(ray.dir, hit.normal) < 0;
        const Vec3 n = shading_normal(m, front ? hit.normal : -hit.normal, hit.position);
        if (depth == 0)
            result.normal = n;

        if (m.kind == MaterialKind::emitter) {
            if (front) {
                double weight = 1;
                if (!previous_specular) {
                    const double cos_light = -dot(ray.dir, hit.normal);
                    const double pdf_light = scene.light_pdf_area() * hit.t * hit.t / cos_light;
                    weight = power_heuristic(previous_pdf, pdf_light);
                }
                const Vec3 light = throughput * m.emission * weight;
                result.radiance += light;
                if (depth == 0)
                    passes.emit = light;
                else
                    file_light(passes, light, depth, first_shares);
            }
            if (!albedo_done)
                result.albedo = albedo_throughput * (front ? m.emission : Vec3(0.0));
            break;  // lights do not reflect
        }

        const Vec3 base = m.albedo.eval(hit.u, hit.v, hit.position);
        if (depth == 0)
            lobe_colours(m, base, passes.colour);
        if (!albedo_done && !m.is_specular()) {
            result.albedo = albedo_throughput * surface_albedo(m, base);
            albedo_done = true;
        }
        if (depth >= scene.max_depth)
            break;

        const Frame frame(n);
        const Vec3 wo = frame.to_local(-ray.dir);
        if (!m.is_specular() && scene.has_lights()) {
            Vec3 light_shares[lobe_count];
            const Vec3 light
                = throughput * sample_direct(scene, m, base, hit, frame, wo, rng, light_shares);
            result.radiance += light;
            file_light(passes, light, depth + 1, depth == 0 ? light_shares : first_shares);
        }

        BsdfSample bs;
        const double u0 = rng.next(), u1 = rng.next(), u2 = rng.next();
        if (!bsdf_sample(m, base, wo, front, u0, u1, u2, bs))
            break;
        if (depth == 0)
            lobe_shares(m, base, wo, bs.wi, first_shares);
        throughput *= bs.weight;
        if (!albedo_done)
            albedo_throughput *= bs.weight;
        previous_specular = bs.specular;
        previous_pdf = bs.pdf;
        const Vec3 wi = normalize(frame.to_world(bs.wi));
        ray = { offset_origin(hit, wi), wi };

        if (depth + 1 >= scene.roulette_depth) {
            const double survive = std::min(max_survival, max_component(throughput));
            if (survive <= 0 || rng.next() >= survive)
                break;
            throughput *= 1.0 / survive;
        }
    }
    return result;
}

GeometryAovs trace_geometry(const Scene& scene, const Ray& center_ray)
{
    GeometryAovs g { std::numeric_limits<float>::infinity(), -1, -1, -1, Vec3(0.0) };
    Hit hit;
    if (!scene.intersect(center_ray, hit))
        return g;
    const Object& object = scene.objects[size_t(hit.object)];
    g.depth = float(hit.t);
    g.id = object.id;
    g.object = hit.object;
    g.position = hit.position;
    if (scene.materials[size_t(object.material)].kind == MaterialKind::mirror) {
        const Vec3 n = dot(center_ray.dir, hit.normal) < 0 ? hit.normal : -hit.normal;
        const Vec3 r = reflect(center_ray.dir, n);
        Hit seen;
        if (scene.intersect({ offset_origin(hit, r), r }, seen))
            g.reflid = scene.objects[size_t(seen.object)].id;
    }
    return g;
}

}  // namespace testrender
