// materials.cpp: evaluation, density and sampling of each surface model.
// Glossy uses the GGX (Trowbridge-Reitz) distribution with the separable
// Smith shadowing term and Schlick's Fresnel (Walter et al. 2007).
#include "materials.h"

namespace testrender {

Material Material::diffuse(const Texture& t)
{
    Material m;
    m.kind = MaterialKind::diffuse;
    m.albedo = t;
    return m;
}

Material Material::mirror(const Vec3& tint)
{
    Material m;
    m.kind = MaterialKind::mirror;
    m.specular = tint;
    m.albedo = Texture::constant(Vec3(0.0));
    return m;
}

Material Material::glossy(const Texture& base, const Vec3& f0, double roughness)
{
    Material m;
    m.kind = MaterialKind::glossy;
    m.albedo = base;
    m.specular = f0;
    m.roughness = roughness;
    return m;
}

Material Material::glass(double ior)
{
    Material m;
    m.kind = MaterialKind::glass;
    m.ior = ior;
    m.albedo = Texture::constant(Vec3(0.0));
    return m;
}

Material Material::emitter(const Vec3& radiance)
{
    Material m;
    m.kind = MaterialKind::emitter;
    m.emission = radiance;
    m.albedo = Texture::constant(Vec3(0.0));
    return m;
}

Material bumped(Material m, double amplitude, double scale)
{
    m.bump = amplitude;
    m.bump_scale = scale;
    return m;
}

Vec3 shading_normal(const Material& m, const Vec3& n, const Vec3& p)
{
    if (m.bump == 0)
        return n;
    const Vec3 q = p * (2 * pi * m.bump_scale);
    const Vec3 ripple(std::sin(q.y + 1.7 * std::sin(q.z)), std::sin(q.z + 1.3 * std::sin(q.x)),
                      std::sin(q.x + 1.1 * std::sin(q.y)));
    const Vec3 tangent = ripple - n * dot(ripple, n);
    return normalize(n + tangent * m.bump);
}

namespace {

/// Probability of sampling the glossy lobe rather than the diffuse base.
double specular_probability(const Material& m, const Vec3& base)
{
    const double s = luminance(m.specular), d = luminance(base);
    if (d <= 0)
        return 1;
    return std::clamp(s / (s + d), 0.25, 0.9);
}

double ggx_d(double alpha, double cos_h)
{
    const double a2 = alpha * alpha;
    const double k = cos_h * cos_h * (a2 - 1) + 1;
    return a2 / (pi * k * k);
}

double smith_g1(double alpha, double cos_v)
{
    const double a2 = alpha * alpha;
    return 2 * cos_v / (cos_v + std::sqrt(a2 + (1 - a2) * cos_v * cos_v));
}

Vec3 schlick(const Vec3& f0, double cos_theta)
{
    const double m = std::pow(1 - std::clamp(cos_theta, 0.0, 1.0), 5);
    return f0 + (Vec3(1.0) - f0) * m;
}

Vec3 glossy_lobe(const Material& m, const Vec3& wo, const Vec3& wi)
{
    const Vec3 h = normalize(wo + wi);
    const double d = ggx_d(m.roughness, h.z);
    const double g = smith_g1(m.roughness, wo.z) * smith_g1(m.roughness, wi.z);
    return schlick(m.specular, dot(wi, h)) * (d * g / (4 * wo.z));  // times cos(wi)
}

double glossy_pdf(const Material& m, const Vec3& wo, const Vec3& wi)
{
    const Vec3 h = normalize(wo + wi);
    return ggx_d(m.roughness, h.z) * h.z / (4 * dot(wo, h));
}

/// Unpolarised Fresnel reflectance of a smooth dielectric; `cos_i` > 0,
/// `eta` = n_incident / n_transmitted.
double fresnel_dielectric(double cos_i, double eta, double& cos_t)
{
    const double sin2_t = eta * eta * (1 - cos_i * cos_i);
    if (sin2_t >= 1) {
        cos_t = 0;
        return 1;  // total internal reflection
    }
    cos_t = std::sqrt(1 - sin2_t);
    const double rs = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    const double rp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    return 0.5 * (rs * rs + rp * rp);
}

}  // namespace

Vec3 bsdf_eval(const Material& m, const Vec3& base, const Vec3& wo, const Vec3& wi)
{
    if (wi.z <= 0 || wo.z <= 0)
        return Vec3(0.0);
    switch (m.kind) {
    case MaterialKind::diffuse: return base * (inv_pi * wi.z);
    case MaterialKind::glossy: return base * (inv_pi * wi.z) + glossy_lobe(m, wo, wi);
    default: return Vec3(0.0);
    }
}

double bsdf_pdf(const Material& m, const Vec3& base, const Vec3& wo, const Vec3& wi)
{
    if (wi.z <= 0 || wo.z <= 0)
        return 0;
    switch (m.kind) {
    case MaterialKind::diffuse: return wi.z * inv_pi;
    case MaterialKind::glossy: {
        const double ps = specular_probability(m, base);
        return ps * glossy_pdf(m, wo, wi) + (1 - ps) * wi.z * inv_pi;
    }
    default: return 0;
    }
}

bool bsdf_sample(const Material& m, const Vec3& base, const Vec3& wo, bool entering,
                 double u0, double u1, double u2, BsdfSample& out)
{
    switch (m.kind) {
    case MaterialKind::mirror:
        out.wi = Vec3(-wo.x, -wo.y, wo.z);
        out.weight = m.specular;
        out.pdf = 0;
        out.specular = true;
        return true;
    case MaterialKind::glass: {
        const double eta = entering ? 1.0 / m.ior : m.ior;
        double cos_t;
        const double f = fresnel_dielectric(wo.z, eta, cos_t);
        out.specular = true;
        out.pdf = 0;
        out.weight = Vec3(1.0);
        if (u0 < f) {
            out.wi = Vec3(-wo.x, -wo.y, wo.z);
        } else {
            // refracted direction, on the other side (-z); radiance scaling
            // by eta^2 is left out (paths start at the camera, importance)
            out.wi = normalize(Vec3(-wo.x * eta, -wo.y * eta, -cos_t));
        }
        return true;
    }
    case MaterialKind::diffuse:
    case MaterialKind::glossy: {
        if (wo.z <= 0)
            return false;
        const double ps = m.kind == MaterialKind::glossy ? specular_probability(m, base) : 0;
        if (u0 < ps) {
            const double a2 = m.roughness * m.roughness;
            const double cos_h = std::sqrt((1 - u1) / (1 + (a2 - 1) * u1));
            const double sin_h = std::sqrt(std::max(0.0, 1 - cos_h * cos_h));
            const double phi = 2 * pi * u2;
            const Vec3 h(sin_h * std::cos(phi), sin_h * std::sin(phi), cos_h);
            out.wi = reflect(-wo, h);
        } else {
            // cosine-weighted hemisphere
            const double r = std::sqrt(u1), phi = 2 * pi * u2;
            out.wi = Vec3(r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1 - u1)));
        }
        if (out.wi.z <= 0)
            return false;
        out.pdf = bsdf_pdf(m, base, wo, out.wi);
        if (out.pdf <= 0)
            return false;
        out.weight = bsdf_eval(m, base, wo, out.wi) / out.pdf;
        out.specular = false;
        return true;
    }
    case MaterialKind::emitter: return false;
    }
    return false;
}

Vec3 surface_albedo(const Material& m, const Vec3& base)
{
    switch (m.kind) {
    case MaterialKind::glossy: return base + m.specular;
    case MaterialKind::emitter: return m.emission;
    default: return base;
    }
}

void lobe_colours(const Material& m, const Vec3& base, Vec3 colours[3])
{
    colours[0] = colours[1] = colours[2] = Vec3(0.0);
    switch (m.kind) {
    case MaterialKind::diffuse: colours[0] = base; break;
    case MaterialKind::glossy:
        colours[0] = base;
        colours[1] = m.specular;
        break;
    case MaterialKind::mirror: colours[1] = m.specular; break;
    case MaterialKind::glass: colours[1] = colours[2] = Vec3(1.0); break;
    case MaterialKind::emitter: break;
    }
}

void lobe_shares(const Material& m, const Vec3& base, const Vec3& wo, const Vec3& wi,
                 Vec3 shares[3])
{
    shares[0] = shares[1] = shares[2] = Vec3(0.0);
    switch (m.kind) {
    case MaterialKind::diffuse: shares[0] = Vec3(1.0); break;
    case MaterialKind::glossy: {
        const Vec3 f = bsdf_eval(m, base, wo, wi);
        const Vec3 fd = base * (inv_pi * std::max(wi.z, 0.0));
        auto share = [](double part, double whole) { return whole > 0 ? part / whole : 1.0; };
        shares[0] = Vec3(share(fd.x, f.x), share(fd.y, f.y), share(fd.z, f.z));
        shares[1] = Vec3(1.0) - shares[0];
        break;
    }
    case MaterialKind::mirror: shares[1] = Vec3(1.0); break;
    case MaterialKind::glass: shares[wi.z * wo.z > 0 ? 1 : 2] = Vec3(1.0); break;
    case MaterialKind::emitter: break;
    }
}

}  // namespace testrender
