// textures.cpp: checker by integer cell parity, and three octaves of 3D
// value noise (hashed lattice values, smoothstep-interpolated).
#include "textures.h"

#include "rng.h"

#include <cstdint>

namespace testrender {

namespace {

/// A lattice value in [0, 1) for the integer cell (i, j, k).
double lattice(int64_t i, int64_t j, int64_t k)
{
    const uint64_t h = mix64(uint64_t(i) * 0x8da6b343ULL ^ mix64(uint64_t(j) * 0xd8163841ULL
                                                                 ^ mix64(uint64_t(k))));
    return double(h >> 11) * 0x1.0p-53;
}

double smooth(double t) { return t * t * (3 - 2 * t); }

double value_noise(const Vec3& p)
{
    const double fx = std::floor(p.x), fy = std::floor(p.y), fz = std::floor(p.z);
    const int64_t i = int64_t(fx), j = int64_t(fy), k = int64_t(fz);
    const double tx = smooth(p.x - fx), ty = smooth(p.y - fy), tz = smooth(p.z - fz);
    double c[2][2];
    for (int dj = 0; dj < 2; ++dj)
        for (int dk = 0; dk < 2; ++dk) {
            const double v0 = lattice(i, j + dj, k + dk);
            const double v1 = lattice(i + 1, j + dj, k + dk);
            c[dj][dk] = v0 + (v1 - v0) * tx;
        }
    const double y0 = c[0][0] + (c[1][0] - c[0][0]) * ty;
    const double y1 = c[0][1] + (c[1][1] - c[0][1]) * ty;
    return y0 + (y1 - y0) * tz;
}

/// Octaves of value noise, each twice the frequency at half the amplitude.
constexpr int noise_octaves = 3;

}  // namespace

Vec3 Texture::eval(double u, double v, const Vec3& p) const
{
    switch (kind) {
    case TextureKind::constant: return a;
    case TextureKind::checker: {
        const int64_t cu = int64_t(std::floor(u * scale));
        const int64_t cv = int64_t(std::floor(v * scale));
        return ((cu + cv) & 1) ? b : a;
    }
    case TextureKind::noise: {
        double sum = 0, amplitude = 0.5, total = 0, frequency = scale;
        for (int o = 0; o < noise_octaves; ++o) {
            sum += amplitude * value_noise(p * frequency);
            total += amplitude;
            amplitude *= 0.5;
            frequency *= 2;
        }
        const double t = sum / total;
        return a + (b - a) * t;
    }
    }
    return a;
}

}  // namespace testrender
