"""Shared fixtures for the mcdtool driver tests: the tool's path, a runner,
and builders for test images (testrender names, Blender Cycles multilayer
names, separate AOV files) written with OpenImageIO."""
import os
import subprocess

import numpy as np
import OpenImageIO as oiio
import pytest

MCDTOOL = os.environ.get("MCDTOOL", "mcdtool")


class Result:
    """What one mcdtool run printed and returned."""

    def __init__(self, proc):
        self.code = proc.returncode
        self.out = proc.stdout
        self.err = proc.stderr

    def __repr__(self):
        return f"exit {self.code}\nstdout:\n{self.out}\nstderr:\n{self.err}"


def run(*args, cwd=None, env=None):
    """Runs mcdtool with `args` (strings or paths)."""
    full_env = dict(os.environ)
    full_env.pop("OCIO", None)
    if env:
        full_env.update(env)
    proc = subprocess.run([MCDTOOL] + [str(a) for a in args], cwd=cwd, env=full_env,
                          capture_output=True, text=True, timeout=120)
    return Result(proc)


def check_failure(result, code, *needles):
    """`result` failed with exit `code` and one stderr line holding `needles`."""
    assert result.code == code, result
    lines = result.err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("mcdtool ERROR: "), result
    for needle in needles:
        assert needle in lines[0], result


def assert_no_outputs(directory, before):
    """No new file (output or temp) appeared in `directory`."""
    assert sorted(os.listdir(directory)) == sorted(before)


def write_image(path, pixels, names, fmt="half", compression=None, origin=(0, 0), attrs=None, display=None):
    """Writes `pixels` (H x W x C float) with channel `names` to `path`; the
    data window starts at `origin`, the display window is `display` (width,
    height from (0, 0)) or the data window's size."""
    h, w, c = pixels.shape
    spec = oiio.ImageSpec(w, h, c, fmt)
    spec.channelnames = tuple(names)
    spec.x, spec.y = origin
    if display:
        spec.full_x, spec.full_y = 0, 0
        spec.full_width, spec.full_height = display
    if compression:
        spec.attribute("compression", compression)
    for key, value in (attrs or {}).items():
        spec.attribute(key, value)
    buf = oiio.ImageBuf(spec)
    buf.set_pixels(oiio.ROI(), np.ascontiguousarray(pixels, dtype=np.float32))
    assert buf.write(str(path)), oiio.geterror()
    return path


def read_image(path):
    """(pixels as float H x W x C, spec) of `path`."""
    buf = oiio.ImageBuf(str(path))
    assert buf.read(force=True), buf.geterror()
    return buf.get_pixels(oiio.FLOAT), buf.nativespec()


def channel(pixels, spec, name):
    """One named channel of a read image."""
    return pixels[:, :, list(spec.channelnames).index(name)]


def noisy_scene(width=40, height=32, seed=7):
    """A noisy RGB beauty over two objects, with ids, normals and depth."""
    rng = np.random.default_rng(seed)
    ids = np.zeros((height, width), np.float32)
    ids[:, width // 2:] = 1.0
    base = np.where(ids[..., None] > 0, 0.8, 0.2) * np.ones((height, width, 3), np.float32)
    beauty = base + rng.normal(0.0, 0.2, (height, width, 3)).astype(np.float32)
    normal = np.zeros((height, width, 3), np.float32)
    normal[..., 2] = 1.0
    depth = (1.0 + ids * 3.0).astype(np.float32)
    return beauty.astype(np.float32), ids, normal, depth


@pytest.fixture
def testrender_exr(tmp_path):
    """render.exr with testrender's channel names (half, piz)."""
    beauty, ids, normal, depth = noisy_scene()
    alpha = np.ones(ids.shape + (1,), np.float32)
    pixels = np.concatenate([beauty, alpha, ids[..., None], np.full_like(alpha, -1.0), normal,
                             depth[..., None]], axis=2)
    names = ["R", "G", "B", "A", "id", "reflid", "N.X", "N.Y", "N.Z", "Z"]
    return write_image(tmp_path / "render.exr", pixels, names, fmt="half", compression="piz",
                       attrs={"mcd:shot": "sq010_sh020"})


@pytest.fixture
def cycles_exr(tmp_path):
    """A Blender Cycles style multilayer EXR (float, zip) with a view layer
    whose name has a space, pass names with spaces and 1e10 background depth."""
    beauty, ids, normal, depth = noisy_scene()
    layer = "My Layer"
    depth = depth.copy()
    depth[:4, :] = 1e10
    alpha = np.ones(ids.shape, np.float32)
    planes = {
        "Combined.R": beauty[..., 0], "Combined.G": beauty[..., 1], "Combined.B": beauty[..., 2],
        "Combined.A": alpha,
        "Denoising Albedo.R": alpha * 0.5, "Denoising Albedo.G": alpha * 0.5,
        "Denoising Albedo.B": alpha * 0.5,
        "Denoising Depth.Z": np.where(depth > 1e9, 0.0, depth),
        "Denoising Normal.X": normal[..., 0], "Denoising Normal.Y": normal[..., 1],
        "Denoising Normal.Z": normal[..., 2],
        "Depth.Z": depth,
        "IndexOB.X": ids + 1.0,
        "Normal.X": normal[..., 0], "Normal.Y": normal[..., 1], "Normal.Z": normal[..., 2],
    }
    names = [f"{layer}.{k}" for k in planes]
    pixels = np.stack(list(planes.values()), axis=2)
    return write_image(tmp_path / "cycles.exr", pixels, names, fmt="float", compression="zip")


def median_reference(img, size):
    """Per-channel median over windows clipped to the image (docs/filters.md)."""
    r = size // 2
    h, w, _ = img.shape
    out = np.empty_like(img)
    for y in range(h):
        for x in range(w):
            win = img[max(0, y - r):y + r + 1, max(0, x - r):x + r + 1]
            out[y, x] = np.median(win.reshape(-1, img.shape[2]), axis=0)
    return out


def gaussian_reference(img, size):
    """Binomial weighted mean over clipped windows, normalised by the
    weights that contributed (docs/filters.md)."""
    from math import comb
    r = size // 2
    taps = np.array([comb(size - 1, i) for i in range(size)], np.float64)
    h, w, c = img.shape
    out = np.empty_like(img)
    for y in range(h):
        for x in range(w):
            y0, y1 = max(0, y - r), min(h, y + r + 1)
            x0, x1 = max(0, x - r), min(w, x + r + 1)
            wy = taps[y0 - (y - r):y1 - (y - r)]
            wx = taps[x0 - (x - r):x1 - (x - r)]
            weight = np.outer(wy, wx)
            win = img[y0:y1, x0:x1].astype(np.float64)
            out[y, x] = (win * weight[..., None]).sum(axis=(0, 1)) / weight.sum()
    return out
