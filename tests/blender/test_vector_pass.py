"""The convention of Blender Cycles' Vector pass, which the motion guide
takes as it is (docs/mcdtool.md, "The motion guide"), checked on a real
render: vector_pass_scene.py moves a cube 4 pixels right and 2 pixels up the
image per frame under an orthographic camera; at frame 2 the cube's pixels
must hold X,Y = previous - current = (-4, -2) and Z,W = current - next =
(-4, -2) in pixels with y up, the static background 0, and mcdtool must
find the pass as the motion guide."""
import os
import shutil
import subprocess

import numpy as np
import OpenImageIO as oiio

BLENDER = shutil.which(os.environ.get("BLENDER", "blender"))
MCDTOOL = os.environ.get("MCDTOOL", "mcdtool")
SCENE_SCRIPT = os.path.join(os.path.dirname(__file__), "vector_pass_scene.py")
STEP_PIXELS = (4.0, 2.0)  # the cube's motion per frame: right, up (vector_pass_scene.py)

if BLENDER is None:
    raise RuntimeError("blender is not on PATH: scripts/setup installs it")


def render_frame_2(tmp_path):
    """Renders frame 2 of vector_pass_scene.py; returns the EXR's path."""
    env = dict(os.environ, BLENDER_USER_CONFIG=str(tmp_path / "config"),
               BLENDER_USER_SCRIPTS=str(tmp_path / "scripts"))
    command = [BLENDER, "-b", "--factory-startup", "--python-exit-code", "1", "--python", SCENE_SCRIPT,
               "-f", "2", "--", "--output", str(tmp_path / "frame_####")]
    process = subprocess.run(command, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                             timeout=300)
    assert process.returncode == 0, process.stdout
    return tmp_path / "frame_0002.exr"


def passes(path):
    """(Vector X,Y,Z,W pixels H x W x 4, object index H x W) of a Cycles multilayer EXR."""
    buf = oiio.ImageBuf(str(path))
    assert buf.read(force=True), buf.geterror()
    names = list(buf.spec().channelnames)
    pixels = buf.get_pixels(oiio.FLOAT)
    vector = pixels[:, :, [names.index(f"ViewLayer.Vector.{c}") for c in "XYZW"]]
    return vector, pixels[:, :, names.index("ViewLayer.IndexOB.X")]


def test_cycles_vector_pass_points_to_previous_and_from_next_frame_y_up(tmp_path):
    vector, index = passes(render_frame_2(tmp_path))
    cube = index > 0.5
    inside = cube & np.roll(cube, 1, 0) & np.roll(cube, -1, 0) & np.roll(cube, 1, 1) & np.roll(cube, -1, 1)
    assert inside.sum() >= 16, "the cube should cover at least 4 x 4 inner pixels"
    right, up = STEP_PIXELS
    expected = np.array([-right, -up, -right, -up])
    np.testing.assert_allclose(vector[inside], np.broadcast_to(expected, vector[inside].shape), atol=0.05)
    background = ~(cube | np.roll(cube, 1, 0) | np.roll(cube, -1, 0) | np.roll(cube, 1, 1) | np.roll(cube, -1, 1))
    assert np.abs(vector[background]).max() == 0.0


def test_mcdtool_finds_the_vector_pass_as_the_motion_guide(tmp_path):
    render_frame_2(tmp_path)
    process = subprocess.run([MCDTOOL, str(tmp_path / "frame_####.exr"), "-v", "--denoise", "--temporal", "1", "--frames", "2"],
                             capture_output=True, text=True, timeout=120)
    assert "motion   <- " in process.stdout, process.stdout + process.stderr
    assert "ViewLayer.Vector.X,ViewLayer.Vector.Y,ViewLayer.Vector.Z,ViewLayer.Vector.W" in process.stdout
