// materials.h: the surface models: Lambertian (textured), perfect mirror,
// glossy (Lambertian base + GGX microfacet lobe), smooth glass, and area-light
// emitters. Directions are in the local shading frame: the normal is +z and
// faces the outgoing direction wo.
#pragma once

#include "math.h"
#include "textures.h"

namespace testrender {

enum class MaterialKind { diffuse, mirror, glossy, glass, emitter };

struct Material {
    MaterialKind kind = MaterialKind::diffuse;
    Texture albedo;                  ///< diffuse reflectance (diffuse; glossy's base)
    Vec3 specular { 1, 1, 1 };       ///< mirror tint; glossy's normal-incidence Fresnel F0
    double roughness = 0.2;          ///< glossy: GGX alpha
    double ior = 1.5;                ///< glass: index of refraction
    Vec3 emission { 0, 0, 0 };       ///< emitter: radiance leaving the front side
    double bump = 0;                 ///< bump map: the shading normal's largest tilt (0: none)
    double bump_scale = 1;           ///< bump map: bumps per world unit

    static Material diffuse(const Texture& t);
    static Material mirror(const Vec3& tint);
    static Material glossy(const Texture& base, const Vec3& f0, double roughness);
    static Material glass(double ior);
    static Material emitter(const Vec3& radiance);

    /// Mirror and glass: a single direction, no next-event estimation.
    bool is_specular() const { return kind == MaterialKind::mirror || kind == MaterialKind::glass; }
};

/// A direction chosen by a material. `weight` is f * cos / pdf (or the
/// specular throughput); `pdf` is the solid-angle density (0 for specular).
struct BsdfSample {
    Vec3 wi;
    Vec3 weight;
    double pdf = 0;
    bool specular = false;
};

/// `m` with a bump map: its shading normal tilts by up to `amplitude`
/// (a tangent offset of that length), in ripples `scale` per world unit.
Material bumped(Material m, double amplitude, double scale);

/// The shading normal at world position p of a surface with (front-facing)
/// geometric normal n: n itself without a bump map, else n tilted by the
/// tangent part of a smooth procedural ripple field.
Vec3 shading_normal(const Material& m, const Vec3& n, const Vec3& p);

/// f(wo, wi) * cos(wi) for the non-specular materials; `base` is the
/// albedo texture's value at the hit.
Vec3 bsdf_eval(const Material& m, const Vec3& base, const Vec3& wo, const Vec3& wi);

/// The solid-angle density `bsdf_sample` picks wi with.
double bsdf_pdf(const Material& m, const Vec3& base, const Vec3& wo, const Vec3& wi);

/// Sample an incoming direction from three uniform numbers. `entering` says
/// whether wo is on the outside of a glass surface. False if the path ends.
bool bsdf_sample(const Material& m, const Vec3& base, const Vec3& wo, bool entering,
                 double u0, double u1, double u2, BsdfSample& out);

/// The reflectance the albedo AOV reports at a non-specular hit.
Vec3 surface_albedo(const Material& m, const Vec3& base);

/// The light passes' colours of a first hit (lobe weights, indexed by
/// `Lobe` in passes.h): diffuse: base; glossy: base and F0; mirror: its
/// tint as glossy; glass: 1 as glossy (reflection) and as transmission.
void lobe_colours(const Material& m, const Vec3& base, Vec3 colours[3]);

/// How light scattered from direction wi into wo divides among the lobes
/// (per channel, summing to 1): diffuse and glossy in proportion to their
/// share of bsdf_eval; a mirror is glossy; glass is glossy when wi is on
/// wo's side (reflection), else transmission.
void lobe_shares(const Material& m, const Vec3& base, const Vec3& wo, const Vec3& wi,
                 Vec3 shares[3]);

}  // namespace testrender
