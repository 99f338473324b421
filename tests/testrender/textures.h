// textures.h: procedural reflectance textures: constant, checker and value
// noise, evaluated at a hit's surface coordinates (u, v) and position.
#pragma once

#include "math.h"

namespace testrender {

enum class TextureKind { constant, checker, noise };

struct Texture {
    TextureKind kind = TextureKind::constant;
    Vec3 a { 0.8, 0.8, 0.8 };  ///< constant colour; checker's first / noise's low colour
    Vec3 b { 0.2, 0.2, 0.2 };  ///< checker's second / noise's high colour
    double scale = 1;          ///< checks or noise cells per world unit

    static Texture constant(const Vec3& c) { return { TextureKind::constant, c, c, 1 }; }
    static Texture checker(const Vec3& a, const Vec3& b, double scale)
    {
        return { TextureKind::checker, a, b, scale };
    }
    static Texture noise(const Vec3& a, const Vec3& b, double scale)
    {
        return { TextureKind::noise, a, b, scale };
    }

    /// The reflectance at surface coordinates (u, v) and world position p.
    /// Checkers use (u, v); noise uses the 3D position (no seams).
    Vec3 eval(double u, double v, const Vec3& p) const;
};

}  // namespace testrender
