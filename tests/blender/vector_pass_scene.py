"""vector_pass_scene.py: run inside Blender by test_vector_pass.py
(`blender -b --factory-startup --python vector_pass_scene.py -- --output DIR/frame_#### -f 2`).

A scene whose screen-space motion is known exactly, to read the sign and
orientation of Cycles' Vector pass: an orthographic camera looking straight
down -Z (64 x 64 pixels over 16 units: 4 pixels per unit, image right is +X,
image up is +Y), a static background plane, and a small cube moving linearly
by (+1, +0.5) units per frame (keyframes at frames 1 and 3), i.e. 4 pixels
right and 2 pixels up on the image per frame. Written as an OpenEXR
MultiLayer with the Vector, Normal, Depth and object index passes (motion
blur off: Cycles writes the Vector pass only then)."""
import sys

import bpy

RESOLUTION = 64
ORTHO_SCALE = 16.0
STEP = (1.0, 0.5)  # units per frame along +X (right) and +Y (up)


def output_path():
    args = sys.argv[sys.argv.index("--") + 1:]
    return args[args.index("--output") + 1]


def build(scene):
    bpy.ops.object.select_all(action="SELECT")
    bpy.ops.object.delete()
    bpy.ops.mesh.primitive_plane_add(size=40, location=(0, 0, 0))
    bpy.ops.mesh.primitive_cube_add(size=2, location=(-STEP[0], -STEP[1], 2))
    cube = bpy.context.active_object
    cube.pass_index = 1
    cube.keyframe_insert("location", frame=1)
    cube.location = (STEP[0], STEP[1], 2)
    cube.keyframe_insert("location", frame=3)
    for curve in cube.animation_data.action.fcurves:
        for key in curve.keyframe_points:
            key.interpolation = "LINEAR"
    bpy.ops.object.light_add(type="SUN", location=(0, 0, 10))
    bpy.ops.object.camera_add(location=(0, 0, 10), rotation=(0, 0, 0))
    camera = bpy.context.active_object
    camera.data.type = "ORTHO"
    camera.data.ortho_scale = ORTHO_SCALE
    scene.camera = camera


def configure(scene):
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = 4
    scene.cycles.use_denoising = False
    scene.render.use_motion_blur = False
    scene.render.resolution_x = scene.render.resolution_y = RESOLUTION
    scene.render.resolution_percentage = 100
    scene.render.threads_mode = "FIXED"
    scene.render.threads = 2
    layer = scene.view_layers[0]
    layer.use_pass_vector = True
    layer.use_pass_normal = True
    layer.use_pass_z = True
    layer.use_pass_object_index = True
    scene.frame_start, scene.frame_end = 1, 3
    scene.render.filepath = output_path()
    scene.render.image_settings.file_format = "OPEN_EXR_MULTILAYER"
    scene.render.image_settings.color_depth = "32"


scene = bpy.context.scene
build(scene)
configure(scene)
