"""cycles_scenes.py: the Cycles development set's scenes, built procedurally
(no external assets) and rendered by Blender's Cycles on the CPU. Run inside
Blender by make_cycles_set:

    blender -b --factory-startup --python cycles_scenes.py -- \
        --scene NAME --out DIR --size WxH --ref-spp N [--spps 4,16,64]

Stills (dof, metal, interior, glossy, glass, volume, product) write
<scene>_<spp>.exr (seed 1) for each of --spps and <scene>_ref.exr (seed
1000, --ref-spp samples). Shots write 16-spp frames <shot>_16_f<F>.exr
(F = 0.., Blender frame F + 1, the noise seed animated per frame) and
references <shot>_ref_f<F>.exr: shot_static frames 0..7 and one reference
(frame 0: nothing moves); shot_truck frames 0..6 (a keyframed camera truck
and a moving sphere, Vector pass on, motion blur off) and references of
frames 2..4. A file that exists is not rendered again; each is written
under a temporary name and renamed, so an interrupted run leaves none half
written.

Every render keeps Cycles' factory sampling (adaptive sampling, filter,
light-path clamps) but for the sample count, the seed and the denoiser
(off: Debian's Blender has no OpenImageDenoise); references also turn
adaptive sampling off, so that no pixel stops short of --ref-spp. Every object and material
has its own pass_index; the files carry Denoising Data, every light pass,
Depth, Normal, object and material index and, on the shots, Vector; the
product shot renders with a transparent film and three light groups."""
import argparse
import math
import os
import sys

import bpy
from mathutils import Vector

RENDER_SEED, REF_SEED = 1, 1000
SHOT_SPP = 16


def parse_options():
    parser = argparse.ArgumentParser(prog="cycles_scenes.py")
    parser.add_argument("--scene", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--size", default="96x72")
    parser.add_argument("--ref-spp", type=int, default=512)
    parser.add_argument("--spps", default="4,16,64")
    return parser.parse_args(sys.argv[sys.argv.index("--") + 1:])


# --- building blocks ---------------------------------------------------------

class Indices:
    """Hands out pass_index values, one per object and one per material."""

    def __init__(self):
        self.object = 0
        self.material = 0

    def next_object(self):
        self.object += 1
        return self.object

    def next_material(self):
        self.material += 1
        return self.material


INDICES = Indices()


def principled(name, colour=(0.8, 0.8, 0.8), metallic=0.0, roughness=0.5, transmission=0.0,
               emission=None, strength=0.0):
    """A Principled BSDF material with its own pass_index."""
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    mat.pass_index = INDICES.next_material()
    bsdf = mat.node_tree.nodes["Principled BSDF"]
    bsdf.inputs["Base Color"].default_value = (*colour, 1.0)
    bsdf.inputs["Metallic"].default_value = metallic
    bsdf.inputs["Roughness"].default_value = roughness
    bsdf.inputs["Transmission"].default_value = transmission
    if emission is not None:
        bsdf.inputs["Emission"].default_value = (*emission, 1.0)
        bsdf.inputs["Emission Strength"].default_value = strength
    return mat


def node(mat, kind, **inputs):
    """A new shader node of `kind` in `mat` with input default values set."""
    n = mat.node_tree.nodes.new(kind)
    for key, value in inputs.items():
        n.inputs[key].default_value = value
    return n


def link(mat, output, input_socket):
    mat.node_tree.links.new(output, input_socket)


def checker(mat, colour_a, colour_b, scale):
    """Drives the material's base colour by a checker texture."""
    tex = node(mat, "ShaderNodeTexChecker", Color1=(*colour_a, 1), Color2=(*colour_b, 1), Scale=scale)
    link(mat, tex.outputs["Color"], mat.node_tree.nodes["Principled BSDF"].inputs["Base Color"])
    return mat


def bump(mat, scale, strength):
    """Bumps the material's normal by a noise texture."""
    noise = node(mat, "ShaderNodeTexNoise", Scale=scale, Detail=8.0)
    b = node(mat, "ShaderNodeBump", Strength=strength)
    link(mat, noise.outputs["Fac"], b.inputs["Height"])
    link(mat, b.outputs["Normal"], mat.node_tree.nodes["Principled BSDF"].inputs["Normal"])
    return mat


def glass(name, colour=(1, 1, 1), roughness=0.0):
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    mat.pass_index = INDICES.next_material()
    nodes = mat.node_tree.nodes
    nodes.remove(nodes["Principled BSDF"])
    g = node(mat, "ShaderNodeBsdfGlass", Color=(*colour, 1), Roughness=roughness, IOR=1.45)
    link(mat, g.outputs["BSDF"], nodes["Material Output"].inputs["Surface"])
    return mat


def fog(name, density):
    """A volume-only material (no surface)."""
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    mat.pass_index = INDICES.next_material()
    nodes = mat.node_tree.nodes
    nodes.remove(nodes["Principled BSDF"])
    v = node(mat, "ShaderNodeVolumePrincipled", Density=density)
    link(mat, v.outputs["Volume"], nodes["Material Output"].inputs["Volume"])
    return mat


def place(obj, mat, smooth=False):
    obj.pass_index = INDICES.next_object()
    obj.data.materials.append(mat)
    if smooth:
        for poly in obj.data.polygons:
            poly.use_smooth = True
    return obj


def sphere(location, radius, mat):
    bpy.ops.mesh.primitive_uv_sphere_add(radius=radius, location=location, segments=64, ring_count=32)
    return place(bpy.context.active_object, mat, smooth=True)


def box(location, size, mat):
    """An axis-aligned box of `size` (x, y, z) centred at `location`."""
    bpy.ops.mesh.primitive_cube_add(size=1, location=location)
    obj = bpy.context.active_object
    obj.scale = size
    return place(obj, mat)


def cylinder(location, radius, depth, mat):
    bpy.ops.mesh.primitive_cylinder_add(radius=radius, depth=depth, location=location, vertices=64)
    return place(bpy.context.active_object, mat, smooth=True)


def floor(mat, size=40):
    bpy.ops.mesh.primitive_plane_add(size=size)
    return place(bpy.context.active_object, mat)


def light(kind, location, energy, rotation=(0, 0, 0), size=None, colour=(1, 1, 1), group=None):
    bpy.ops.object.light_add(type=kind, location=location, rotation=rotation)
    obj = bpy.context.active_object
    obj.data.energy = energy
    obj.data.color = colour
    if size is not None:
        if kind == "SUN":
            obj.data.angle = size
        elif kind == "SPOT":
            obj.data.spot_size = size
        else:
            obj.data.size = size
    if group:
        obj.lightgroup = group
    return obj


def aim(obj, target):
    direction = Vector(target) - obj.location
    obj.rotation_euler = direction.to_track_quat("-Z", "Y").to_euler()


def camera(scene, location, target, lens=35.0):
    bpy.ops.object.camera_add(location=location)
    cam = bpy.context.active_object
    cam.data.lens = lens
    aim(cam, target)
    scene.camera = cam
    return cam


def world(scene, colour, strength):
    scene.world.use_nodes = True
    background = scene.world.node_tree.nodes["Background"]
    background.inputs["Color"].default_value = (*colour, 1)
    background.inputs["Strength"].default_value = strength


# --- the scenes --------------------------------------------------------------

def build_dof(scene):
    """Depth of field: a chrome sphere with a sun glint in focus, small
    emitters far behind it seen as bokeh discs (85 mm at f/0.6), a gold
    sphere near the lens out of focus."""
    floor(checker(principled("floor"), (0.35, 0.35, 0.35), (0.08, 0.08, 0.08), 12))
    centre = Vector((0, 0, 0.8))
    sphere(centre, 0.8, principled("chrome", (0.9, 0.9, 0.9), metallic=1.0, roughness=0.04))
    sphere((-0.45, -5.6, 0.6), 0.22, principled("gold", (1.0, 0.7, 0.3), metallic=1.0, roughness=0.12))
    sphere((1.4, 0.8, 0.5), 0.5, principled("red", (0.7, 0.08, 0.05), roughness=0.4))
    for i in range(7):
        glow = principled(f"emitter{i}", emission=(1.0, 0.6 + 0.05 * i, 0.3), strength=80.0)
        sphere((-3.0 + i, 14.0 + 0.5 * i, 1.8 + 0.5 * (i % 3)), 0.06, glow)
    eye = Vector((0.3, -8.0, 0.95))
    # the sun's mirror image on the chrome sphere sits at its upper left
    to_eye = (eye - centre).normalized()
    normal = Vector((-0.35, -0.8, 0.5)).normalized()
    to_sun = 2 * normal.dot(to_eye) * normal - to_eye
    sun = light("SUN", (0, 0, 10), 3.0, size=math.radians(2.0))
    aim(sun, sun.location - to_sun)
    world(scene, (0.05, 0.07, 0.12), 1.0)
    cam = camera(scene, eye, centre, lens=85)
    cam.data.dof.use_dof = True
    cam.data.dof.focus_distance = (centre - eye).length
    cam.data.dof.aperture_fstop = 0.6


def build_metal(scene):
    """Textures with bump-mapped metal: brushed-looking copper and steel with
    noise bumps, on a textured floor under an area light."""
    floor(checker(principled("tiles", roughness=0.6), (0.55, 0.45, 0.35), (0.2, 0.18, 0.15), 20))
    sphere((-0.9, 0, 0.7), 0.7, bump(principled("copper", (0.95, 0.55, 0.4), metallic=1.0,
                                                  roughness=0.25), 6.0, 0.25))
    box((0.9, 0.2, 0.6), (1.1, 1.1, 1.2), bump(principled("steel", (0.8, 0.8, 0.82), metallic=1.0,
                                                           roughness=0.18), 4.0, 0.3))
    sphere((0.1, -1.2, 0.3), 0.3, bump(checker(principled("painted", roughness=0.35),
                                               (0.1, 0.3, 0.7), (0.9, 0.9, 0.8), 8), 10.0, 0.2))
    area = light("AREA", (-2.0, -2.5, 4.0), 300.0, size=1.5)
    aim(area, (0, 0, 0.5))
    world(scene, (0.2, 0.22, 0.25), 0.5)
    camera(scene, (0.6, -4.8, 2.2), (0, 0, 0.55), lens=40)


def build_interior(scene):
    """A dim interior lit through a window: a closed room, the sun and sky
    entering through one opening, everything else indirect."""
    wall = principled("plaster", (0.75, 0.72, 0.68), roughness=0.8)
    w, d, h = 5.0, 5.0, 2.8
    box((0, 0, -0.05), (w, d, 0.1), checker(principled("boards", roughness=0.5),
                                            (0.45, 0.3, 0.18), (0.35, 0.22, 0.12), 6))
    box((0, 0, h + 0.05), (w, d, 0.1), wall)
    box((0, d / 2 + 0.05, h / 2), (w, 0.1, h), wall)
    box((0, -d / 2 - 0.05, h / 2), (w, 0.1, h), wall)
    box((-w / 2 - 0.05, 0, h / 2), (0.1, d, h), wall)
    # the window wall at +x: four pieces around an opening 1.2 wide, 1.1 high
    x = w / 2 + 0.05
    box((x, -1.55, h / 2), (0.1, 1.9, h), wall)
    box((x, 1.55, h / 2), (0.1, 1.9, h), wall)
    box((x, 0, 0.45), (0.1, 1.2, 0.9), wall)
    box((x, 0, 2.4), (0.1, 1.2, 0.8), wall)
    box((0.6, 0.8, 0.4), (1.4, 0.8, 0.8), principled("sofa", (0.2, 0.35, 0.5), roughness=0.7))
    sphere((-0.8, -0.6, 0.35), 0.35, principled("vase", (0.8, 0.8, 0.8), metallic=1.0, roughness=0.1))
    cylinder((-1.2, 1.2, 0.5), 0.3, 1.0, principled("lamp", (0.9, 0.5, 0.2), roughness=0.4))
    light("SUN", (6, 0, 6), 5.0, rotation=(0, math.radians(55), 0), size=math.radians(1.0))
    world(scene, (0.4, 0.55, 0.9), 1.0)
    camera(scene, (-2.1, -2.1, 1.5), (1.0, 0.6, 0.7), lens=22)


def build_glossy(scene):
    """Glossy and mirror reflections: a mirror wall, a glossy floor and a
    rough metal sphere reflecting coloured diffuse objects."""
    floor(principled("glossy floor", (0.1, 0.1, 0.12), roughness=0.15))
    box((0, 2.0, 1.2), (4.0, 0.1, 2.4), principled("mirror", (0.95, 0.95, 0.95), metallic=1.0,
                                                    roughness=0.0))
    sphere((-0.8, 0, 0.6), 0.6, principled("satin", (0.9, 0.9, 0.9), metallic=1.0, roughness=0.3))
    box((0.9, -0.2, 0.45), (0.9, 0.9, 0.9), principled("green", (0.1, 0.6, 0.15), roughness=0.6))
    cylinder((0.2, 0.9, 0.7), 0.25, 1.4, principled("orange", (0.9, 0.35, 0.05), roughness=0.5))
    area = light("AREA", (1.5, -2.0, 3.5), 400.0, size=1.0)
    aim(area, (0, 0.5, 0.5))
    world(scene, (0.1, 0.1, 0.1), 1.0)
    camera(scene, (1.2, -5.0, 1.8), (0, 0.5, 0.7), lens=35)


def build_glass(scene):
    """Glass: a clear sphere and a tinted glass block over a checker floor,
    casting caustics under a small light."""
    floor(checker(principled("floor", roughness=0.6), (0.8, 0.8, 0.8), (0.2, 0.2, 0.2), 16))
    sphere((-0.6, 0, 0.6), 0.6, glass("clear"))
    box((0.8, 0.3, 0.5), (0.7, 0.7, 1.0), glass("tinted", (0.6, 0.85, 1.0), roughness=0.05))
    sphere((0.2, 1.5, 0.4), 0.4, principled("clay", (0.8, 0.4, 0.3), roughness=0.7))
    spot = light("SPOT", (-1.5, -1.0, 4.0), 800.0, size=math.radians(45))
    aim(spot, (0, 0, 0.3))
    world(scene, (0.05, 0.05, 0.06), 1.0)
    camera(scene, (0.5, -4.5, 2.0), (0, 0.2, 0.5), lens=38)


def build_volume(scene):
    """A volume: a fog-filled box with a spot light's beam through it, and
    a sphere inside casting a shadow in the fog."""
    floor(principled("floor", (0.5, 0.5, 0.5), roughness=0.7))
    bpy.ops.mesh.primitive_cube_add(size=1, location=(0, 0, 1.5))
    haze = bpy.context.active_object
    haze.scale = (6, 6, 3)
    place(haze, fog("fog", 0.08))
    sphere((0.3, 0.2, 1.0), 0.5, principled("ball", (0.8, 0.3, 0.2), roughness=0.4))
    spot = light("SPOT", (-1.0, 0.5, 2.9), 1500.0, size=math.radians(30))
    aim(spot, (0.3, 0.2, 0.0))
    world(scene, (0.02, 0.02, 0.03), 1.0)
    camera(scene, (0.0, -5.5, 1.5), (0, 0, 1.0), lens=32)


def build_product(scene):
    """A transparent-film product shot: a bottle and a cap floating on a
    transparent background (premultiplied alpha), lit by three light groups
    (key, fill, rim); the world lights the "env" group."""
    layer = scene.view_layers[0]
    for group in ("key", "fill", "rim", "env"):
        layer.lightgroups.add(name=group)
    scene.render.film_transparent = True
    cylinder((0, 0, 0.9), 0.4, 1.6, principled("bottle", (0.6, 0.05, 0.08), roughness=0.2))
    cylinder((0, 0, 1.85), 0.18, 0.3, principled("cap", (0.85, 0.85, 0.85), metallic=1.0,
                                                 roughness=0.15))
    sphere((0.75, -0.4, 0.3), 0.3, principled("berry", (0.25, 0.05, 0.4), roughness=0.3))
    key = light("AREA", (-2.0, -2.0, 2.5), 300.0, size=1.0, colour=(1.0, 0.95, 0.9), group="key")
    aim(key, (0, 0, 1))
    fill = light("AREA", (2.5, -1.5, 1.2), 80.0, size=2.0, colour=(0.8, 0.9, 1.0), group="fill")
    aim(fill, (0, 0, 1))
    rim = light("SPOT", (0.5, 2.5, 2.5), 400.0, size=math.radians(40), group="rim")
    aim(rim, (0, 0, 1))
    world(scene, (0.3, 0.3, 0.32), 0.4)
    scene.world.lightgroup = "env"
    camera(scene, (0.0, -4.5, 1.3), (0.1, 0, 1.0), lens=50)


def build_shot_static(scene):
    """The static shot: the glossy scene, nothing moving, 8 frames."""
    build_glossy(scene)
    scene.frame_start, scene.frame_end = 1, 8


def keyframe_linear(obj, path, frames_values):
    for frame, value in frames_values:
        setattr(obj, path, value)
        obj.keyframe_insert(path, frame=frame)
    for curve in obj.animation_data.action.fcurves:
        for key in curve.keyframe_points:
            key.interpolation = "LINEAR"


def build_shot_truck(scene):
    """The moving shot: a camera trucking sideways past pillars (one close
    to the lens, moving fast on screen) and a sphere rolling across, 7
    frames, keyframed, for the Vector pass."""
    floor(checker(principled("floor", roughness=0.5), (0.7, 0.7, 0.7), (0.25, 0.25, 0.25), 16))
    for i, (x, y) in enumerate([(-2.0, 2.0), (0.0, 3.0), (2.0, 1.5), (-0.6, -1.6)]):
        cylinder((x, y, 0.9), 0.25, 1.8, principled(f"pillar{i}", (0.3 + 0.15 * i, 0.5, 0.7 - 0.12 * i),
                                                     roughness=0.45))
    box((1.0, 0.5, 0.4), (0.8, 0.8, 0.8), principled("crate", (0.7, 0.5, 0.25), roughness=0.6))
    ball = sphere((-1.5, 0.0, 0.35), 0.35, principled("ball", (0.9, 0.9, 0.9), metallic=1.0,
                                                      roughness=0.2))
    keyframe_linear(ball, "location", [(1, (-1.2, 0.3, 0.35)), (7, (1.2, -0.3, 0.35))])
    area = light("AREA", (-1.0, -2.0, 4.0), 500.0, size=2.0)
    aim(area, (0, 0.5, 0))
    world(scene, (0.15, 0.18, 0.22), 0.6)
    cam = camera(scene, (-1.5, -4.5, 1.4), (0, 0.5, 0.6), lens=30)
    keyframe_linear(cam, "location", [(1, (-1.5, -4.5, 1.4)), (7, (1.5, -4.5, 1.4))])
    scene.frame_start, scene.frame_end = 1, 7


STILLS = {
    "dof": build_dof, "metal": build_metal, "interior": build_interior, "glossy": build_glossy,
    "glass": build_glass, "volume": build_volume, "product": build_product,
}
# shot: (builder, frames, frames with a reference)
SHOTS = {
    "shot_static": (build_shot_static, range(0, 8), [0]),
    "shot_truck": (build_shot_truck, range(0, 7), [2, 3, 4]),
}


# --- rendering ---------------------------------------------------------------

def configure(scene, size, motion):
    """Cycles on the CPU with factory sampling, every pass the set needs."""
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.use_denoising = False
    scene.render.use_motion_blur = False
    scene.render.resolution_x, scene.render.resolution_y = size
    scene.render.resolution_percentage = 100
    scene.render.image_settings.file_format = "OPEN_EXR_MULTILAYER"
    scene.render.image_settings.color_depth = "32"
    layer = scene.view_layers[0]
    for name in ("z", "normal", "object_index", "material_index", "diffuse_direct",
                 "diffuse_indirect", "diffuse_color", "glossy_direct", "glossy_indirect",
                 "glossy_color", "transmission_direct", "transmission_indirect",
                 "transmission_color", "emit", "environment"):
        setattr(layer, "use_pass_" + name, True)
    layer.use_pass_vector = motion
    layer.cycles.denoising_store_passes = True
    layer.cycles.use_pass_volume_direct = True
    layer.cycles.use_pass_volume_indirect = True


def render(scene, path, spp, seed, frame=None, animated_seed=False, reference=False):
    """Renders the current scene to `path` unless it exists. A reference
    turns adaptive sampling off, so that every pixel gets all its samples."""
    if os.path.exists(path):
        return
    if frame is not None:
        scene.frame_set(frame)
    scene.cycles.use_adaptive_sampling = not reference
    scene.cycles.samples = spp
    scene.cycles.seed = seed
    scene.cycles.use_animated_seed = animated_seed
    partial = path[:-len(".exr")] + ".partial.exr"
    scene.render.filepath = partial
    bpy.ops.render.render(write_still=True)
    os.replace(partial, path)
    print(f"cycles_scenes: wrote {path}", flush=True)


def main():
    options = parse_options()
    size = tuple(int(v) for v in options.size.split("x"))
    scene = bpy.context.scene
    bpy.ops.object.select_all(action="SELECT")
    bpy.ops.object.delete()
    name = options.scene
    out = lambda file: os.path.join(options.out, file)  # noqa: E731
    if name in STILLS:
        STILLS[name](scene)
        configure(scene, size, motion=False)
        for spp in (int(s) for s in options.spps.split(",")):
            render(scene, out(f"{name}_{spp}.exr"), spp, RENDER_SEED)
        render(scene, out(f"{name}_ref.exr"), options.ref_spp, REF_SEED, reference=True)
    elif name in SHOTS:
        build, frames, references = SHOTS[name]
        build(scene)
        configure(scene, size, motion=name != "shot_static")
        for f in frames:
            render(scene, out(f"{name}_{SHOT_SPP}_f{f}.exr"), SHOT_SPP, RENDER_SEED, f + 1, True)
        for f in references:
            render(scene, out(f"{name}_ref_f{f}.exr"), options.ref_spp, REF_SEED, f + 1, True,
                   reference=True)
    else:
        raise SystemExit(f"cycles_scenes.py: unknown scene '{name}'; scenes: "
                         + ", ".join([*STILLS, *SHOTS]))


main()
