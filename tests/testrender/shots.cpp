// shots.cpp: the animated scenes. They share one stage: a checker floor, a
// textured back wall lower than the view (sky above it), a panel light and
// three objects at different depths; what moves differs per shot. Every
// motion is periodic in the frame number, period `shot_period`.
#include "shots.h"

#include "scene_parts.h"

namespace testrender {

namespace {

/// Sideways travel (world units) of the trucking camera and of the moving
/// sphere; the camera also rises by `truck_rise` per unit sideways and the
/// sphere hops `object_hop` high, so the motion has vertical components too.
constexpr double truck_amplitude = 1.2;
constexpr double truck_rise = 0.3;
constexpr double object_amplitude = 1.4;
constexpr double object_hop = 0.3;

/// The phase of `frame` in the shots' cycle, in radians.
double phase(int frame) { return 2 * pi * double(frame % shot_period) / shot_period; }

/// The stage and its camera, the camera translated by `camera_offset`.
/// Ids: floor 1, back wall 2, light 3, near red sphere 10, glossy box 11,
/// far checker sphere 12.
void add_stage(Scene& s, const Vec3& camera_offset)
{
    const int floor = s.add_material(
        Material::diffuse(Texture::checker({ 0.8, 0.8, 0.75 }, { 0.2, 0.2, 0.25 }, 2)));
    const int wall = s.add_material(
        Material::diffuse(Texture::noise({ 0.7, 0.55, 0.4 }, { 0.35, 0.3, 0.3 }, 3)));
    const int light = s.add_material(Material::emitter({ 14, 13, 11 }));
    const int red = s.add_material(Material::diffuse(Texture::constant({ 0.75, 0.12, 0.1 })));
    const int glossy = s.add_material(
        Material::glossy(Texture::constant({ 0.1, 0.2, 0.5 }), { 0.3, 0.3, 0.3 }, 0.15));
    const int green = s.add_material(
        Material::diffuse(Texture::checker({ 0.2, 0.6, 0.2 }, { 0.85, 0.85, 0.8 }, 4)));
    s.add(facing_quad({ -8, 0, -4 }, { 16, 0, 0 }, { 0, 0, 12 }, { 0, 1, 0 }), floor, 1);
    s.add(facing_quad({ -8, 0, -3 }, { 16, 0, 0 }, { 0, 2.5, 0 }, { 0, 0, 1 }), wall, 2);
    add_panel_light(s, { 0.8, 3.2, 0.5 }, 0.6, 0.6, light, 3);
    s.add(Shape::sphere({ -1.0, 0.4, 1.2 }, 0.4), red, 10);
    s.add(Shape::box({ 0.6, 0.6, -0.6 }, { 0.35, 0.6, 0.35 }, 25), glossy, 11);
    s.add(Shape::sphere({ -0.3, 0.5, -2.2 }, 0.5), green, 12);
    s.background = { 0.3, 0.4, 0.55 };
    s.camera.eye = Vec3(0, 1.3, 4.5) + camera_offset;
    s.camera.look_at = Vec3(0, 0.7, 0) + camera_offset;
    s.camera.vfov_degrees = 45;
    s.max_depth = 6;
}

}  // namespace

void shot_static(Scene& s, int /*frame: nothing moves*/)
{
    s.description = "shot: a still stage, only the noise changes per frame";
    add_stage(s, Vec3(0.0));
}

void shot_truck(Scene& s, int frame)
{
    s.description = "shot: the camera trucks sideways past objects at several depths";
    const double x = truck_amplitude * std::sin(phase(frame));
    add_stage(s, Vec3(x, truck_rise * x, 0));
}

void shot_object(Scene& s, int frame)
{
    s.description = "shot: a sphere hops across the stage, casting a moving shadow";
    add_stage(s, Vec3(0.0));
    // uv checker texture: it moves with the sphere (a position-based noise would slide)
    const int orange = s.add_material(
        Material::diffuse(Texture::checker({ 0.9, 0.5, 0.1 }, { 0.9, 0.9, 0.85 }, 5)));
    const double hop = std::sin(phase(frame));
    s.add(Shape::sphere({ object_amplitude * hop, 0.35 + object_hop * hop * hop, 0.3 }, 0.35),
          orange, 20);
}

}  // namespace testrender
