// scenes.cpp: the built-in scenes. Each exercises something a denoiser must
// handle: cornell (diffuse, mirror and glossy objects, direct light),
// mirrors (reflections of distinct objects), textured (high-frequency
// albedo), dof (defocus over depth), interior (mostly indirect light),
// transparent (a transparent film: alpha), metal (bump-mapped metal with a
// sun glint), bokeh (defocused highlights), dim (the interior, ten times
// darker); the
// animated shots are in shots.cpp. These stills ignore the frame.
#include "scene.h"
#include "scene_parts.h"
#include "shots.h"

namespace testrender {

namespace {

void cornell(Scene& s, int /*frame: still*/)
{
    s.description = "Cornell box: diffuse walls, a diffuse sphere, a mirror sphere, a glossy box";
    const int white = s.add_material(Material::diffuse(Texture::constant({ 0.73, 0.73, 0.73 })));
    const int red = s.add_material(Material::diffuse(Texture::constant({ 0.65, 0.05, 0.05 })));
    const int green = s.add_material(Material::diffuse(Texture::constant({ 0.12, 0.45, 0.15 })));
    const int light = s.add_material(Material::emitter({ 17, 12, 4 }));
    const int matte = s.add_material(Material::diffuse(Texture::constant({ 0.8, 0.75, 0.6 })));
    const int mirror = s.add_material(Material::mirror({ 0.95, 0.95, 0.95 }));
    const int glossy = s.add_material(
        Material::glossy(Texture::constant({ 0.15, 0.2, 0.45 }), { 0.35, 0.35, 0.35 }, 0.12));
    // ids: floor 1, ceiling 2, back 3, left 4, right 5
    add_room(s, { -1, 0, -1 }, { 1, 2, 1 }, white, white, white, red, green, white, 1, false);
    add_panel_light(s, { 0, 1.999, 0 }, 0.3, 0.3, light, 6);
    s.add(Shape::sphere({ -0.45, 0.3, 0.45 }, 0.3), matte, 7);
    s.add(Shape::sphere({ 0.45, 0.35, 0.25 }, 0.35), mirror, 8);
    s.add(Shape::box({ -0.45, 0.6, -0.35 }, { 0.28, 0.6, 0.28 }, 18), glossy, 9);
    s.camera.eye = { 0, 1, 3.9 };
    s.camera.look_at = { 0, 1, 0 };
    s.camera.vfov_degrees = 40;
    s.max_depth = 8;
}

void mirrors(Scene& s, int /*frame: still*/)
{
    s.description = "closed room with a mirror sphere and three flat mirrors, each reflecting "
                    "different objects";
    const int grey = s.add_material(Material::diffuse(Texture::constant({ 0.6, 0.6, 0.6 })));
    const int warm = s.add_material(Material::diffuse(Texture::constant({ 0.75, 0.6, 0.3 })));
    const int cool = s.add_material(Material::diffuse(Texture::constant({ 0.35, 0.5, 0.7 })));
    const int light = s.add_material(Material::emitter({ 9, 9, 8 }));
    const int mirror = s.add_material(Material::mirror({ 0.95, 0.95, 0.95 }));
    const int red = s.add_material(Material::diffuse(Texture::constant({ 0.8, 0.1, 0.08 })));
    const int blue = s.add_material(Material::diffuse(Texture::constant({ 0.1, 0.15, 0.8 })));
    const int checker = s.add_material(
        Material::diffuse(Texture::checker({ 0.9, 0.9, 0.9 }, { 0.1, 0.5, 0.1 }, 6)));
    const int noise = s.add_material(
        Material::diffuse(Texture::noise({ 0.9, 0.8, 0.1 }, { 0.4, 0.1, 0.4 }, 6)));
    // ids: floor 1, ceiling 2, back 3, left 4, right 5, front (behind the camera) 6
    add_room(s, { -2, 0, -2 }, { 2, 2.5, 2.2 }, grey, grey, grey, cool, cool, warm, 1, true);
    add_panel_light(s, { 0, 2.499, 0 }, 0.6, 0.6, light, 7);
    s.add(Shape::sphere({ 0, 0.5, -0.6 }, 0.5), mirror, 10);
    // flat mirrors: across the two back corners, turned towards the room's
    // middle (each shows the objects on the other side), and one on the back wall
    s.add(facing_quad({ -1.95, 0.05, -0.8 }, { 0.8, 0, -1.15 }, { 0, 1.5, 0 }, { 1, 0, 1 }), mirror,
          11);
    s.add(facing_quad({ 1.95, 0.05, -0.8 }, { -0.8, 0, -1.15 }, { 0, 1.5, 0 }, { -1, 0, 1 }), mirror,
          12);
    s.add(facing_quad({ -0.9, 1.15, -1.98 }, { 1.8, 0, 0 }, { 0, 1.0, 0 }, { 0, 0, 1 }), mirror, 13);
    s.add(Shape::sphere({ -1.1, 0.35, 0.4 }, 0.35), red, 20);
    s.add(Shape::box({ 1.15, 0.35, 0.3 }, { 0.3, 0.35, 0.3 }, 30), blue, 21);
    s.add(Shape::sphere({ 1.0, 0.3, -1.3 }, 0.3), checker, 22);
    s.add(Shape::sphere({ -1.0, 0.3, -1.3 }, 0.3), noise, 23);
    s.camera.eye = { 0, 1.2, 1.8 };
    s.camera.look_at = { 0, 0.7, -1 };
    s.camera.vfov_degrees = 60;
    s.max_depth = 8;
}

void textured(Scene& s, int /*frame: still*/)
{
    s.description = "high-frequency checker floor, noise- and checker-textured objects and a "
                    "glass sphere under a sky";
    const int floor = s.add_material(
        Material::diffuse(Texture::checker({ 0.85, 0.85, 0.8 }, { 0.08, 0.08, 0.1 }, 8)));
    const int noise = s.add_material(
        Material::diffuse(Texture::noise({ 0.05, 0.2, 0.6 }, { 0.95, 0.85, 0.3 }, 14)));
    const int fine = s.add_material(
        Material::diffuse(Texture::checker({ 0.9, 0.1, 0.1 }, { 0.95, 0.95, 0.95 }, 20)));
    const int boxtex = s.add_material(
        Material::diffuse(Texture::noise({ 0.2, 0.5, 0.1 }, { 0.9, 0.9, 0.7 }, 25)));
    const int glossy = s.add_material(Material::glossy(
        Texture::checker({ 0.5, 0.3, 0.1 }, { 0.1, 0.05, 0.02 }, 16), { 0.2, 0.2, 0.2 }, 0.2));
    const int light = s.add_material(Material::emitter({ 12, 11, 10 }));
    const int glass = s.add_material(Material::glass(1.5));
    s.add(facing_quad({ -10, 0, -10 }, { 20, 0, 0 }, { 0, 0, 20 }, { 0, 1, 0 }), floor, 1);
    add_panel_light(s, { 1.5, 4, 1.5 }, 1.0, 1.0, light, 2);
    s.add(Shape::sphere({ -0.9, 0.5, 0 }, 0.5), noise, 3);
    s.add(Shape::sphere({ 0.5, 0.35, 0.8 }, 0.35), fine, 4);
    s.add(Shape::box({ 0.7, 0.45, -0.6 }, { 0.45, 0.45, 0.45 }, 35), boxtex, 5);
    s.add(Shape::sphere({ -0.2, 0.25, 1.3 }, 0.25), glossy, 6);
    s.add(Shape::sphere({ 0.55, 0.22, 1.9 }, 0.22), glass, 7);  // refracts the checker floor
    s.background = { 0.35, 0.45, 0.6 };
    s.camera.eye = { 0, 1.3, 3.8 };
    s.camera.look_at = { 0, 0.3, 0 };
    s.camera.vfov_degrees = 40;
    s.max_depth = 6;
}

void dof(Scene& s, int /*frame: still*/)
{
    s.description = "spheres spread from near to far on a checker floor, thin lens focused on "
                    "the middle one";
    const int floor = s.add_material(
        Material::diffuse(Texture::checker({ 0.8, 0.8, 0.8 }, { 0.15, 0.15, 0.2 }, 2)));
    const int light = s.add_material(Material::emitter({ 10, 10, 9 }));
    const Vec3 colours[] = { { 0.8, 0.1, 0.1 }, { 0.9, 0.6, 0.1 }, { 0.2, 0.7, 0.2 },
                             { 0.1, 0.5, 0.8 }, { 0.5, 0.2, 0.8 }, { 0.8, 0.8, 0.8 } };
    s.add(facing_quad({ -20, 0, -30 }, { 40, 0, 0 }, { 0, 0, 40 }, { 0, 1, 0 }), floor, 1);
    add_panel_light(s, { -2, 6, 0 }, 2, 4, light, 2);
    for (int i = 0; i < 6; ++i) {
        const Texture t = i % 2 ? Texture::checker(colours[i], colours[i] * 0.3, 5)
                                : Texture::constant(colours[i]);
        const int m = s.add_material(Material::diffuse(t));
        const double z = 2.0 - 2.2 * i;
        const double x = (i % 2 ? 0.7 : -0.7) + 0.1 * i;
        s.add(Shape::sphere({ x, 0.5, z }, 0.5), m, 10 + i);
    }
    s.background = { 0.3, 0.35, 0.45 };
    s.camera.eye = { 0, 1.0, 5.5 };
    s.camera.look_at = { 0, 0.5, -2 };
    s.camera.vfov_degrees = 35;
    s.camera.aperture_radius = 0.3;
    // focus on the third sphere (z = -2.4)
    s.camera.focus_distance = dot(Vec3(-0.5, 0.5, -2.4) - s.camera.eye,
                                  normalize(s.camera.look_at - s.camera.eye));
    s.max_depth = 6;
}

/// The interior room with an uplight of radiance `light`.
void interior_room(Scene& s, const Vec3& light_radiance)
{
    const int wall = s.add_material(Material::diffuse(Texture::constant({ 0.75, 0.72, 0.65 })));
    const int floor = s.add_material(
        Material::diffuse(Texture::noise({ 0.35, 0.2, 0.1 }, { 0.6, 0.4, 0.2 }, 3)));
    const int ceiling = s.add_material(Material::diffuse(Texture::constant({ 0.85, 0.85, 0.85 })));
    const int accent = s.add_material(Material::diffuse(Texture::constant({ 0.2, 0.35, 0.6 })));
    const int light = s.add_material(Material::emitter(light_radiance));
    const int dark = s.add_material(Material::diffuse(Texture::constant({ 0.1, 0.1, 0.1 })));
    const int wood = s.add_material(Material::glossy(
        Texture::noise({ 0.3, 0.15, 0.05 }, { 0.5, 0.3, 0.12 }, 8), { 0.05, 0.05, 0.05 }, 0.25));
    const int red = s.add_material(Material::diffuse(Texture::constant({ 0.7, 0.15, 0.1 })));
    const int mirror = s.add_material(Material::mirror({ 0.9, 0.9, 0.9 }));
    // ids: floor 1, ceiling 2, back 3, left 4, right 5, front 6
    add_room(s, { -2.5, 0, -2.5 }, { 2.5, 2.6, 2.5 }, floor, ceiling, wall, accent, wall, wall, 1,
             true);
    // uplight: a shade (box) with the emitter on top, facing the ceiling
    s.add(Shape::box({ -1.8, 0.9, -1.8 }, { 0.25, 0.9, 0.25 }, 0), dark, 7);
    add_panel_light(s, { -1.8, 1.801, -1.8 }, 0.22, 0.22, light, 8, true);
    // table and objects on it
    s.add(Shape::box({ 0.3, 0.7, -0.6 }, { 0.8, 0.04, 0.5 }, 10), wood, 9);
    s.add(Shape::box({ 0.3, 0.33, -0.6 }, { 0.06, 0.33, 0.06 }, 10), wood, 10);
    s.add(Shape::sphere({ 0.0, 0.94, -0.6 }, 0.2), red, 11);
    s.add(Shape::sphere({ 0.7, 0.89, -0.4 }, 0.15), mirror, 12);
    s.add(Shape::box({ 1.6, 0.45, 0.6 }, { 0.4, 0.45, 0.4 }, -25), accent, 13);
    s.camera.eye = { 1.2, 1.5, 2.3 };
    s.camera.look_at = { -0.4, 0.8, -1.2 };
    s.camera.vfov_degrees = 55;
    s.max_depth = 10;
    s.roulette_depth = 4;
}

void interior(Scene& s, int /*frame: still*/)
{
    s.description = "room lit by an uplight against the ceiling: almost all light is indirect";
    interior_room(s, { 120, 100, 70 });
}

void dim(Scene& s, int /*frame: still*/)
{
    s.description = "the interior with a ten times dimmer uplight: dark, almost all indirect";
    interior_room(s, { 12, 10, 7 });
}

void metal(Scene& s, int /*frame: still*/)
{
    s.description = "bump-mapped gold sphere and steel plate under a small, intense sun: glints";
    const Vec3 gold_f0(1.0, 0.71, 0.29), steel_f0(0.56, 0.57, 0.58);
    const int gold = s.add_material(bumped(
        Material::glossy(Texture::constant({ 0.02, 0.015, 0.01 }), gold_f0, 0.08), 0.25, 6));
    const int steel = s.add_material(bumped(
        Material::glossy(Texture::constant({ 0.05, 0.05, 0.05 }), steel_f0, 0.15), 0.15, 3));
    const int matte = s.add_material(Material::diffuse(Texture::constant({ 0.6, 0.25, 0.2 })));
    const int sun = s.add_material(Material::emitter({ 4000, 3800, 3400 }));
    s.add(facing_quad({ -3, 0, -3 }, { 6, 0, 0 }, { 0, 0, 6 }, { 0, 1, 0 }), steel, 1);
    add_panel_light(s, { 2.5, 6, -3 }, 0.08, 0.08, sun, 2);
    s.add(Shape::sphere({ -0.3, 0.6, 0 }, 0.6), gold, 3);
    s.add(Shape::box({ 0.9, 0.3, 0.6 }, { 0.3, 0.3, 0.3 }, 20), matte, 4);
    s.background = { 0.25, 0.3, 0.4 };
    s.camera.eye = { 0, 1.4, 3.2 };
    s.camera.look_at = { 0, 0.4, 0 };
    s.camera.vfov_degrees = 45;
    s.max_depth = 6;
}

void bokeh(Scene& s, int /*frame: still*/)
{
    s.description = "a sphere in focus before small mirror balls far behind it: the light's "
                    "glints in the balls defocus into bright discs";
    const int floor = s.add_material(
        Material::diffuse(Texture::checker({ 0.5, 0.5, 0.5 }, { 0.1, 0.1, 0.12 }, 1)));
    const int red = s.add_material(Material::diffuse(Texture::constant({ 0.7, 0.15, 0.1 })));
    const int mirror = s.add_material(Material::mirror({ 0.9, 0.9, 0.9 }));
    const int light = s.add_material(Material::emitter({ 40, 36, 30 }));
    s.add(facing_quad({ -20, 0, -30 }, { 40, 0, 0 }, { 0, 0, 40 }, { 0, 1, 0 }), floor, 1);
    add_panel_light(s, { 0, 4, 3 }, 1, 1, light, 2);
    s.add(Shape::sphere({ 0, 0.5, 1.5 }, 0.5), red, 3);
    for (int i = 0; i < 7; ++i) {
        const double x = -2.1 + 0.7 * i, y = 0.5 + 0.4 * (i % 3), z = -4.0 - 0.8 * (i % 2);
        s.add(Shape::sphere({ x, y, z }, 0.2), mirror, 10 + i);
    }
    s.background = { 0.02, 0.02, 0.03 };
    s.camera.eye = { 0, 0.9, 4.5 };
    s.camera.look_at = { 0, 0.6, 0 };
    s.camera.vfov_degrees = 40;
    s.camera.aperture_radius = 0.25;
    s.camera.focus_distance = 3.0;
    s.max_depth = 6;
}

void transparent(Scene& s, int /*frame: still*/)
{
    s.description = "objects on a floor tile lit only by the sky, transparent film: alpha 0 "
                    "where the camera sees no geometry";
    const int tile = s.add_material(
        Material::diffuse(Texture::checker({ 0.7, 0.7, 0.65 }, { 0.25, 0.25, 0.3 }, 3)));
    const int red = s.add_material(Material::diffuse(Texture::constant({ 0.75, 0.15, 0.1 })));
    const int blue = s.add_material(Material::diffuse(Texture::constant({ 0.15, 0.3, 0.7 })));
    const int mirror = s.add_material(Material::mirror({ 0.9, 0.9, 0.9 }));
    // ids: tile 1, red sphere 2, blue box 3, mirror sphere 4
    s.add(facing_quad({ -1.2, 0, -1.2 }, { 2.4, 0, 0 }, { 0, 0, 2.4 }, { 0, 1, 0 }), tile, 1);
    s.add(Shape::sphere({ -0.5, 0.4, 0.1 }, 0.4), red, 2);
    s.add(Shape::box({ 0.55, 0.35, -0.35 }, { 0.3, 0.35, 0.3 }, 30), blue, 3);
    s.add(Shape::sphere({ 0.45, 0.25, 0.6 }, 0.25), mirror, 4);
    // no light and only diffuse and mirror surfaces (weights <= 1): every
    // sample's radiance is at most the sky's, below 1, so colour <= alpha
    s.background = { 0.8, 0.85, 0.9 };
    s.transparent_film = true;
    s.camera.eye = { 0, 1.8, 3.4 };
    s.camera.look_at = { 0, 0.2, 0 };
    s.camera.vfov_degrees = 45;
    s.max_depth = 6;
}

struct Entry {
    const char* name;
    void (*build)(Scene&, int frame);
};

const Entry scenes[] = { { "cornell", cornell },         { "mirrors", mirrors },
                         { "textured", textured },       { "dof", dof },
                         { "interior", interior },       { "transparent", transparent },
                         { "metal", metal },             { "bokeh", bokeh },
                         { "dim", dim },
                         { "shot_static", shot_static },
                         { "shot_truck", shot_truck },   { "shot_object", shot_object } };

void build(const Entry& e, int frame, Scene& scene)
{
    scene = Scene();
    scene.name = e.name;
    e.build(scene, frame);
}

}  // namespace

std::vector<std::string> scene_names()
{
    std::vector<std::string> names;
    for (const Entry& e : scenes)
        names.emplace_back(e.name);
    return names;
}

bool make_scene(const std::string& name, Scene& scene, int frame)
{
    for (const Entry& e : scenes) {
        if (name == e.name) {
            Scene previous, next;
            build(e, frame - 1, previous);
            build(e, frame + 1, next);
            build(e, frame, scene);
            scene.set_neighbours(previous, next);
            return true;
        }
    }
    return false;
}

}  // namespace testrender
