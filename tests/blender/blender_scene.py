"""blender_scene.py: run inside Blender by test_blender_addon.py
(`blender -b --factory-startup --python blender_scene.py -- OPTIONS [-a]`).

Builds a small procedural scene (floor, cube, sphere moving across the
frames, cylinder, an area light) rendered by Cycles on the CPU at 96x64,
installs and enables the mcdenoise add-on from the built zip, and sets it up
from the options. --raw-dir keeps a copy of each raw frame, taken by a
render_write handler that runs before the add-on's. --operator runs the
add-on's sequence operator on existing frames instead of rendering."""
import argparse
import os
import shutil
import sys

import addon_utils
import bpy


def parse_options():
    parser = argparse.ArgumentParser(prog="blender_scene.py")
    parser.add_argument("--zip", required=True, help="the add-on zip to install and enable")
    parser.add_argument("--output", required=True, help="render output path (Blender's, with ####)")
    parser.add_argument("--spp", type=int, default=8)
    parser.add_argument("--frames", type=int, default=3, help="frames 1..N")
    parser.add_argument("--format", default="OPEN_EXR_MULTILAYER")
    parser.add_argument("--denoise", action="store_true", help="enable mcdenoise for the render")
    parser.add_argument("--mode", default="DENOISE", help="the add-on's mode (DENOISE, REPORT_CHAIN)")
    parser.add_argument("--light-passes", action="store_true", help="the add-on also denoises the light passes")
    parser.add_argument("--pattern", help="the add-on writes to this sibling path pattern, not in place")
    parser.add_argument("--raw-dir", help="copy each written frame here before the add-on denoises it")
    parser.add_argument("--operator", nargs="+", metavar="FILE",
                        help="run the sequence operator on these files (output to denoised/{name}.exr)")
    return parser.parse_args(sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else [])


def material(name, colour):
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    mat.node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value = (*colour, 1.0)
    return mat


def add(operator, colour, **placement):
    operator(**placement)
    obj = bpy.context.active_object
    obj.data.materials.append(material(obj.name, colour))
    return obj


def build_scene(scene, options):
    bpy.ops.object.select_all(action="SELECT")
    bpy.ops.object.delete()
    add(bpy.ops.mesh.primitive_plane_add, (0.8, 0.8, 0.8), size=12)
    add(bpy.ops.mesh.primitive_cube_add, (0.8, 0.2, 0.1), size=1.5, location=(-1.6, 0.5, 0.75))
    add(bpy.ops.mesh.primitive_cylinder_add, (0.1, 0.3, 0.8), radius=0.5, depth=2, location=(1.8, 1.0, 1))
    sphere = add(bpy.ops.mesh.primitive_uv_sphere_add, (0.2, 0.7, 0.2), radius=0.7, location=(0, -0.5, 0.7))
    for frame in range(1, options.frames + 1):
        sphere.location.x = -0.6 + 0.6 * (frame - 1)
        sphere.keyframe_insert("location", frame=frame)
    bpy.ops.object.light_add(type="AREA", location=(0, -1, 5))
    bpy.context.active_object.data.energy = 800
    bpy.context.active_object.data.size = 3
    bpy.ops.object.camera_add(location=(0, -7, 4), rotation=(1.1, 0, 0))
    scene.camera = bpy.context.active_object
    scene.world.color = (0.05, 0.05, 0.05)

    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = options.spp
    scene.cycles.use_adaptive_sampling = False
    scene.render.resolution_x, scene.render.resolution_y = 96, 64
    scene.render.resolution_percentage = 100
    scene.render.threads_mode = "FIXED"
    scene.render.threads = 2
    scene.frame_start, scene.frame_end = 1, options.frames
    scene.render.filepath = options.output
    scene.render.image_settings.file_format = options.format
    if options.format.startswith("OPEN_EXR"):
        scene.render.image_settings.color_depth = "32"


def enable_addon(zip_path):
    bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True)
    if addon_utils.enable("mcdenoise_blender", default_set=True) is None:
        raise SystemExit("blender_scene.py: the mcdenoise add-on did not enable")


def keep_raw_frames(raw_dir):
    """A render_write handler ahead of the add-on's that copies each frame."""
    os.makedirs(raw_dir, exist_ok=True)

    def copy_frame(scene, *_):
        path = bpy.path.abspath(scene.render.frame_path(frame=scene.frame_current))
        shutil.copy(path, os.path.join(raw_dir, os.path.basename(path)))

    bpy.app.handlers.render_write.insert(0, copy_frame)


def main():
    options = parse_options()
    enable_addon(options.zip)
    scene = bpy.context.scene
    if options.operator:
        bpy.ops.mcdenoise.denoise_sequence(
            directory=os.path.dirname(options.operator[0]), output="PATTERN", pattern="denoised/{name}.exr",
            files=[{"name": os.path.basename(f)} for f in options.operator])
        return
    build_scene(scene, options)
    if options.raw_dir:
        keep_raw_frames(options.raw_dir)
    if options.denoise:
        scene.mcdenoise.mode = options.mode
        scene.mcdenoise.light_passes = options.light_passes
        if options.pattern:
            scene.mcdenoise.output, scene.mcdenoise.pattern = "PATTERN", options.pattern
        scene.mcdenoise.enabled = True   # also turns Cycles' own denoiser off and the passes on
    else:
        scene.cycles.use_denoising = False  # Debian's Blender has no OpenImageDenoise


main()
