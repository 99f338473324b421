"""mcdtool driver tests: the examples of docs/mcdtool.md, channel discovery,
output, sequences, --compare and --preview. Each test_* function is one
CTest test (tests/driver/CMakeLists.txt)."""
import os

import numpy as np
import OpenImageIO as oiio
import pytest

from conftest import (channel, check_failure, gaussian_reference, median_reference, noisy_scene, read_image,
                      run, write_image)

BEAUTY = ["R", "G", "B"]


def beauty_of(pixels, spec, names=BEAUTY):
    return np.stack([channel(pixels, spec, n) for n in names], axis=2)


# --- examples -------------------------------------------------------------

def test_median_gaussian_chain(testrender_exr, tmp_path):
    """mcdtool render.exr --median 7 --gaussian 3 -o clean.exr"""
    r = run(testrender_exr, "--median", 7, "--gaussian", 3, "-o", tmp_path / "clean.exr")
    assert r.code == 0, r
    src, src_spec = read_image(testrender_exr)
    out, out_spec = read_image(tmp_path / "clean.exr")
    expected = gaussian_reference(median_reference(beauty_of(src, src_spec), 7), 3)
    np.testing.assert_allclose(beauty_of(out, out_spec), expected, rtol=2e-3, atol=2e-3)
    # Every other channel is kept bit for bit, with the metadata and formats.
    assert sorted(out_spec.channelnames) == sorted(src_spec.channelnames)
    for name in src_spec.channelnames:
        if name not in BEAUTY:
            np.testing.assert_array_equal(channel(out, out_spec, name), channel(src, src_spec, name))
    assert out_spec.format == oiio.HALF
    assert out_spec.get_string_attribute("compression") == "piz"
    assert out_spec.get_string_attribute("mcd:shot") == "sq010_sh020"


def object_median_reference(img, ids, size):
    """Median over the clipped window's pixels with the center's id (docs/filters.md)."""
    r = size // 2
    h, w, c = img.shape
    out = np.empty_like(img)
    for y in range(h):
        for x in range(w):
            sl = (slice(max(0, y - r), y + r + 1), slice(max(0, x - r), x + r + 1))
            mask = np.rint(ids[sl]) == np.rint(ids[y, x])
            out[y, x] = np.median(img[sl][mask], axis=0)
    return out


def test_object_median_chain(testrender_exr, tmp_path):
    """mcdtool render.exr --object-median 7 --gaussian 3 -o clean.exr"""
    r = run(testrender_exr, "--object-median", 7, "--gaussian", 3, "-o", tmp_path / "clean.exr")
    assert r.code == 0, r
    src, src_spec = read_image(testrender_exr)
    out, spec = read_image(tmp_path / "clean.exr")
    ids = channel(src, src_spec, "id")
    expected = gaussian_reference(object_median_reference(beauty_of(src, src_spec), ids, 7), 3)
    np.testing.assert_allclose(beauty_of(out, spec), expected, rtol=2e-3, atol=2e-3)


def test_guided_commands_run(testrender_exr, tmp_path):
    """Every guided command of the table runs on a file holding its guides."""
    cases = {"--object-mean": [5], "--object-gaussian": [5], "--brdf-mean": [5], "--brdf-median": [5],
             "--brdf-gaussian": [3], "--normal-mean": [5], "--normal-gaussian": [5], "--dof": [4, 1],
             "--dof-range": [4, 0, 1.0, 4.0]}
    for command, args in cases.items():
        out = tmp_path / (command.strip("-") + ".exr")
        r = run(testrender_exr, command, *args, "-o", out)
        assert r.code == 0, (command, r)
        assert out.exists()


def test_separate_aov_files(tmp_path):
    """mcdtool beauty.exr --aov id=ids.exr --aov normal=render.exr:N ..."""
    beauty, ids, normal, depth = noisy_scene()
    write_image(tmp_path / "beauty.exr", beauty, BEAUTY)
    write_image(tmp_path / "ids.exr", ids[..., None], ["Y"])
    write_image(tmp_path / "render.exr", np.concatenate([beauty, normal], axis=2),
                BEAUTY + ["N.X", "N.Y", "N.Z"])
    r = run(tmp_path / "beauty.exr", "--aov", "id=" + str(tmp_path / "ids.exr"),
            "--aov", "normal=" + str(tmp_path / "render.exr") + ":N", "-v", "--normal-mean", 5,
            "-o", tmp_path / "out.exr")
    assert r.code == 0, r
    assert f"id       <- {tmp_path / 'ids.exr'}: Y" in r.out
    assert f"normal   <- {tmp_path / 'render.exr'}: N.X,N.Y,N.Z" in r.out
    # The guides come from the files named, not from the beauty's file.
    out, spec = read_image(tmp_path / "out.exr")
    assert list(spec.channelnames) == BEAUTY


def test_dof(testrender_exr, tmp_path):
    """mcdtool render.exr --dof 10 0 -o out.exr"""
    r = run(testrender_exr, "--dof", 10, 0, "-o", tmp_path / "out.exr")
    assert r.code == 0, r
    src, src_spec = read_image(testrender_exr)
    out, spec = read_image(tmp_path / "out.exr")
    # Depth 1 (left object) is the nearest level, in focus with focus 0: unchanged.
    near = channel(src, src_spec, "Z") == 1.0
    np.testing.assert_array_equal(beauty_of(out, spec)[near], beauty_of(src, src_spec)[near])
    assert not np.array_equal(beauty_of(out, spec)[~near], beauty_of(src, src_spec)[~near])
    r = run(testrender_exr, "--dof", 10, 10, "-o", tmp_path / "bad.exr")
    check_failure(r, 2, "mcdtool ERROR: --dof : ")
    assert not (tmp_path / "bad.exr").exists()


def test_sequence(tmp_path):
    """mcdtool 'shot/beauty.####.exr' --frames 1-3 --median 7 -o 'clean/beauty.####.exr'"""
    (tmp_path / "shot").mkdir()
    (tmp_path / "clean").mkdir()
    for frame in (1, 2, 3):
        beauty, *_ = noisy_scene(seed=frame)
        write_image(tmp_path / "shot" / f"beauty.{frame:04d}.exr", beauty, BEAUTY)
    r = run("shot/beauty.####.exr", "--frames", "1-3", "--median", 7, "-o", "clean/beauty.####.exr",
            cwd=tmp_path)
    assert r.code == 0, r
    assert sorted(os.listdir(tmp_path / "clean")) == [f"beauty.{f:04d}.exr" for f in (1, 2, 3)]
    # Not a terminal: no progress line, only the summary.
    assert r.err == "mcdtool: 3 frames: 3 written, 0 skipped, 0 failed\n", r
    # printf style and a frame list with a step.
    r = run("shot/beauty.%04d.exr", "--frames", "1-3x2", "--median", 3, "-o", "clean/step.%04d.exr",
            cwd=tmp_path)
    assert r.code == 0, r
    assert (tmp_path / "clean/step.0001.exr").exists() and (tmp_path / "clean/step.0003.exr").exists()
    assert not (tmp_path / "clean/step.0002.exr").exists()
    r = run("shot/beauty.####.exr", "--frames", "1,3", "--median", 3, "-o", "clean/list.####.exr",
            cwd=tmp_path)
    assert r.code == 0, r
    assert sorted(p for p in os.listdir(tmp_path / "clean") if p.startswith("list")) == [
        "list.0001.exr", "list.0003.exr"]
    # Counting down, and '@' padding (one digit per '@').
    r = run("shot/beauty.####.exr", "--frames", "3-2", "--median", 3, "-o", "clean/at.@@@.exr", cwd=tmp_path)
    assert r.code == 0, r
    assert (tmp_path / "clean/at.003.exr").exists() and (tmp_path / "clean/at.002.exr").exists()


def test_sequence_frame_error_keeps_other_frames(tmp_path):
    """A missing frame is reported with its number; the others are written; exit 1."""
    for frame in (1, 3):
        beauty, *_ = noisy_scene(seed=frame)
        write_image(tmp_path / f"beauty.{frame:04d}.exr", beauty, BEAUTY)
    r = run("beauty.####.exr", "--frames", "1-3", "--median", 3, "-o", "clean.####.exr", cwd=tmp_path)
    assert r.code == 1, r
    assert "frame 2:" in r.err and "beauty.0002.exr" in r.err
    assert (tmp_path / "clean.0001.exr").exists() and (tmp_path / "clean.0003.exr").exists()
    assert not (tmp_path / "clean.0002.exr").exists()


def test_progress_line_on_terminal(tmp_path):
    """On a terminal, stderr shows frame count, rate and ETA."""
    import pty
    import subprocess
    from conftest import MCDTOOL
    for frame in (1, 2, 3):
        beauty, *_ = noisy_scene(seed=frame)
        write_image(tmp_path / f"b.{frame:04d}.exr", beauty, BEAUTY)
    master, slave = pty.openpty()
    proc = subprocess.run([MCDTOOL, "b.####.exr", "--frames", "1-3", "--median", "3", "-o", "c.####.exr"],
                          cwd=tmp_path, stdout=subprocess.PIPE, stderr=slave, timeout=120)
    os.close(slave)
    shown = b""
    try:
        while True:
            chunk = os.read(master, 65536)
            if not chunk:
                break
            shown += chunk
    except OSError:
        pass
    os.close(master)
    assert proc.returncode == 0
    text = shown.decode()
    assert "3/3" in text and "frames/s" in text and "ETA" in text, text


def test_skip_existing(tmp_path):
    for frame in (1, 2):
        beauty, *_ = noisy_scene(seed=frame)
        write_image(tmp_path / f"beauty.{frame:04d}.exr", beauty, BEAUTY)
    (tmp_path / "clean.0001.exr").write_bytes(b"placeholder")
    r = run("beauty.####.exr", "--frames", "1-2", "--skip-existing", "--median", 3, "-o", "clean.####.exr",
            cwd=tmp_path)
    assert r.code == 0, r
    assert (tmp_path / "clean.0001.exr").read_bytes() == b"placeholder"
    assert (tmp_path / "clean.0002.exr").exists()


def test_compare(testrender_exr, tmp_path):
    """mcdtool render.exr --median 7 --compare reference.exr"""
    beauty, ids, normal, depth = noisy_scene()
    clean = np.where(ids[..., None] > 0, 0.8, 0.2) * np.ones_like(beauty)
    write_image(tmp_path / "reference.exr", clean, BEAUTY, fmt="float")
    r = run(testrender_exr, "--median", 7, "--compare", tmp_path / "reference.exr")
    assert r.code == 0, r
    lines = [line for line in r.out.splitlines() if "relMSE" in line]
    assert len(lines) == 2 and all("PSNR" in l and "SSIM" in l for l in lines), r
    before, after = (float(l.split("relMSE")[1].split()[0]) for l in lines)
    assert after < before


def test_preview(testrender_exr, tmp_path):
    """mcdtool render.exr --median 7 -o clean.exr --preview before_after.png"""
    r = run(testrender_exr, "--median", 7, "-o", tmp_path / "clean.exr", "--preview",
            tmp_path / "before_after.png")
    assert r.code == 0, r
    pixels, spec = read_image(tmp_path / "before_after.png")
    assert (spec.width, spec.height, spec.nchannels) == (80, 32, 3)
    assert spec.format == oiio.UINT8
    # With --compare, the reference is the third panel.
    write_image(tmp_path / "reference.exr", np.full((32, 40, 3), 0.5, np.float32), BEAUTY)
    r = run(testrender_exr, "--median", 7, "--compare", tmp_path / "reference.exr", "--preview",
            tmp_path / "three.png")
    assert r.code == 0, r
    pixels, spec = read_image(tmp_path / "three.png")
    assert spec.width == 120
    # Plain sRGB without a config: linear 0.5 displays as ~0.735.
    assert abs(pixels[10, 100, 0] - 0.735) < 0.01


OCIO_CONFIG = """ocio_profile_version: 2
roles:
  default: linear
  scene_linear: linear
displays:
  TestDisplay:
    - !<View> {name: Gamma, colorspace: gamma_display}
    - !<View> {name: Raw, colorspace: linear}
active_displays: []
active_views: []
colorspaces:
  - !<ColorSpace>
    name: linear
    isdata: false
  - !<ColorSpace>
    name: gamma_display
    isdata: false
    from_scene_reference: !<ExponentTransform> {value: 2.0, direction: inverse}
"""


def test_preview_ocio(tmp_path):
    write_image(tmp_path / "flat.exr", np.full((8, 8, 3), 0.25, np.float32), BEAUTY)
    (tmp_path / "test.ocio").write_text(OCIO_CONFIG)
    r = run(tmp_path / "flat.exr", "--median", 3, "--preview", tmp_path / "gamma.png", "--ocio-config",
            tmp_path / "test.ocio")
    assert r.code == 0, r
    assert abs(read_image(tmp_path / "gamma.png")[0][4, 4, 0] - 0.5) < 0.01  # 0.25 ** (1/2)
    r = run(tmp_path / "flat.exr", "--median", 3, "--preview", tmp_path / "raw.png", "--view", "Raw",
            env={"OCIO": str(tmp_path / "test.ocio")})
    assert r.code == 0, r
    assert abs(read_image(tmp_path / "raw.png")[0][4, 4, 0] - 0.25) < 0.01
    r = run(tmp_path / "flat.exr", "--median", 3, "--preview", tmp_path / "bad.png", "--view", "Filmic",
            "--ocio-config", tmp_path / "test.ocio")
    assert r.code == 2 and "--view : 'Filmic'" in r.err and "Gamma, Raw" in r.err, r
    assert not (tmp_path / "bad.png").exists()


def test_cycles_multilayer_discovery(cycles_exr, tmp_path):
    r = run(cycles_exr, "-v", "--median", 5, "-o", tmp_path / "out.exr")
    assert r.code == 0, r
    assert "beauty   <- " in r.out and "My Layer.Combined.R,My Layer.Combined.G,My Layer.Combined.B" in r.out
    assert "id       <- " in r.out and ": My Layer.IndexOB.X" in r.out
    assert ("normal   <- " in r.out
            and ": My Layer.Denoising Normal.X,My Layer.Denoising Normal.Y,My Layer.Denoising Normal.Z" in r.out)
    assert "depth    <- " in r.out and ": My Layer.Depth.Z" in r.out
    assert "albedo   <- " in r.out and "My Layer.Denoising Albedo.R" in r.out
    src, src_spec = read_image(cycles_exr)
    out, out_spec = read_image(tmp_path / "out.exr")
    assert out_spec.format == oiio.FLOAT and out_spec.get_string_attribute("compression") == "zip"
    names = [f"My Layer.Combined.{c}" for c in "RGB"]
    expected = median_reference(beauty_of(src, src_spec, names), 5)
    np.testing.assert_allclose(beauty_of(out, out_spec, names), expected, rtol=1e-6, atol=1e-6)
    for name in src_spec.channelnames:
        if name not in names:  # alpha, depth 1e10 and every other pass pass through
            np.testing.assert_array_equal(channel(out, out_spec, name), channel(src, src_spec, name))


def test_testrender_file_discovery(tmp_path):
    """Every role is found in a real testrender file."""
    testrender = os.environ["TESTRENDER"]
    import subprocess
    subprocess.run([testrender, "--scene", "cornell", "--res", "32x24", "--spp", "2", "-q", "-o",
                    str(tmp_path / "tr.exr")], check=True, timeout=120)
    r = run(tmp_path / "tr.exr", "-v", "--median", 3, "-o", tmp_path / "clean.exr")
    assert r.code == 0, r
    for role, channels in [("beauty", "R,G,B"), ("id", "id"), ("reflid", "reflid"), ("normal", "N.X,N.Y,N.Z"),
                           ("depth", "Z"), ("albedo", "albedo.R,albedo.G,albedo.B"),
                           ("variance", "var.R,var.G,var.B"), ("half_a", "A.R,A.G,A.B"),
                           ("half_b", "B.R,B.G,B.B"), ("motion", "motion.X,motion.Y,motion.Z,motion.W")]:
        assert f"{role:<8} <- {tmp_path / 'tr.exr'}: {channels}\n" in r.out, r


def test_cycles_guided_filters(cycles_exr, tmp_path):
    """IndexOB ids and Depth.Z with 1e10 background drive the guided filters."""
    for args in (["--object-median", 7, "--gaussian", 3], ["--dof", 4, 0], ["--normal-gaussian", 5]):
        r = run(cycles_exr, *args, "-o", tmp_path / "out.exr")
        assert r.code == 0, (args, r)
        out, spec = read_image(tmp_path / "out.exr")
        assert np.isfinite(out).all()


# The channel names of each renderer's denoise AOVs, in the order beauty (3),
# alpha, variance (3), albedo (3), normal (3), depth.
RENDERER_NAMES = {
    "renderman": ["Ci.r", "Ci.g", "Ci.b", "a", "mse.r", "mse.g", "mse.b", "albedo.r", "albedo.g",
                  "albedo.b", "normal.x", "normal.y", "normal.z", "zfiltered"],
    "arnold": ["R", "G", "B", "A", "variance.R", "variance.G", "variance.B", "denoise_albedo.R",
               "denoise_albedo.G", "denoise_albedo.B", "N.R", "N.G", "N.B", "Z"],
}


@pytest.mark.parametrize("renderer", sorted(RENDERER_NAMES))
def test_renderer_denoise_aovs(renderer, tmp_path):
    """A renderer's denoise AOVs take the roles of testrender's names: the
    same data under either set of names gives the same file."""
    beauty, ids, normal, depth = noisy_scene()
    rng = np.random.default_rng(3)
    variance = rng.uniform(0.01, 0.05, beauty.shape).astype(np.float32)
    albedo = np.full_like(beauty, 0.5)
    alpha = np.ones(ids.shape + (1,), np.float32)
    pixels = np.concatenate([beauty, alpha, variance, albedo, normal, depth[..., None]], axis=2)
    names = RENDERER_NAMES[renderer]
    render = write_image(tmp_path / f"{renderer}.exr", pixels, names, fmt="float")
    testrender = write_image(tmp_path / "tr.exr", pixels,
                             ["R", "G", "B", "A", "var.R", "var.G", "var.B", "albedo.R", "albedo.G",
                              "albedo.B", "N.X", "N.Y", "N.Z", "Z"], fmt="float")
    r = run(render, "-v", "--denoise", "-o", tmp_path / "out.exr")
    assert r.code == 0, r
    for role, channels in [("beauty", names[0:3]), ("variance", names[4:7]), ("albedo", names[7:10]),
                           ("normal", names[10:13]), ("depth", names[13:])]:
        assert f"{role:<8} <- {render}: {','.join(channels)}\n" in r.out, r
    assert run(testrender, "--denoise", "-o", tmp_path / "tr_out.exr").code == 0
    out, spec = read_image(tmp_path / "out.exr")
    expected, expected_spec = read_image(tmp_path / "tr_out.exr")
    np.testing.assert_array_equal(beauty_of(out, spec, names[0:3]), beauty_of(expected, expected_spec))
    np.testing.assert_array_equal(channel(out, spec, names[3]), alpha[..., 0])


def test_ids_stored_as_integers(tmp_path):
    """An id channel stored as uint (Arnold's ID pass) gives the whole
    numbers it holds, not OIIO's float reading scaled to [0, 1] (where every
    id would round to 0), and passes through to the output unchanged, ids
    beyond float's 24 bits too."""
    beauty, _, _, _ = noisy_scene()
    h, w, _ = beauty.shape
    objects = np.minimum(np.arange(w) * 4 // w, 3)[None, :].repeat(h, axis=0)
    beauty = beauty + (objects[..., None] * 0.3).astype(np.float32)
    stored = np.array([7, 123456789, 4000000001, 70000], np.float64)[objects]  # beyond float's 24 bits
    spec = oiio.ImageSpec(w, h, 4, oiio.UINT32)
    spec.channelnames = ("R", "G", "B", "ID")
    spec.channelformats = (oiio.TypeDesc("float"),) * 3 + (oiio.TypeDesc("uint"),)
    render = str(tmp_path / "arnold.exr")
    out = oiio.ImageOutput.create(render)
    assert out.open(render, spec)
    # uint32 data: the ID channel stores it as it is, the float channels as
    # its value / (2^32 - 1), so the beauty is given in [0, 1] that way.
    scaled_beauty = np.round(np.clip(beauty / 2, 0, 1) * 4294967295.0)
    assert out.write_image(np.concatenate([scaled_beauty, stored[..., None]], axis=2).astype(np.uint32))
    out.close()
    whole = write_image(tmp_path / "whole.exr", objects[..., None].astype(np.float32), ["Y"], fmt="float")

    r = run(render, "-v", "--object-median", 5, "-o", tmp_path / "out.exr")
    assert r.code == 0, r
    assert f"id       <- {render}: ID\n" in r.out, r
    assert run(render, "--aov", f"id={whole}", "--object-median", 5, "-o", tmp_path / "expected.exr").code == 0
    got, got_spec = read_image(tmp_path / "out.exr")
    expected, _ = read_image(tmp_path / "expected.exr")
    np.testing.assert_array_equal(beauty_of(got, got_spec), beauty_of(expected, got_spec))
    written = oiio.ImageInput.open(str(tmp_path / "out.exr"))
    ids = written.read_image(0, 0, 3, 4, oiio.UINT32)[..., 0]
    written.close()
    np.testing.assert_array_equal(ids, stored.astype(np.uint32))


# Cryptomatte hashes (float bits): two of them round to the same whole
# number as float ids (and as the background's 0), so only ids taken from
# the bits keep the four objects apart.
CRYPTO_HASHES = np.array([0, 0x0A3F1234, 0x0A3F1235, 0xC2F0AAAA], np.uint32)
CRYPTO_LAYOUTS = {
    "arnold": ("", "crypto_object", {"cryptomatte/d593dd7/name": "crypto_object",
                                     "cryptomatte/d593dd7/hash": "MurmurHash3_32",
                                     "cryptomatte/d593dd7/conversion": "uint32_to_float32"}),
    "cycles without metadata": ("ViewLayer.", "ViewLayer.CryptoObject", {}),
}


@pytest.mark.parametrize("layout", sorted(CRYPTO_LAYOUTS))
def test_cryptomatte_object_ids(layout, tmp_path):
    """With no id pass, a Cryptomatte object layer's rank-0 ids (its hashes'
    bits) drive the object filters exactly as whole-number ids would."""
    prefix, layer, attrs = CRYPTO_LAYOUTS[layout]
    beauty, _, _, _ = noisy_scene()
    h, w, _ = beauty.shape
    objects = np.minimum(np.arange(w) * 4 // w, 3)[None, :].repeat(h, axis=0)
    beauty = beauty + (objects[..., None] * 0.3).astype(np.float32)
    hashes = CRYPTO_HASHES[objects].view(np.float32)
    coverage = np.ones_like(hashes)
    zero = np.zeros_like(hashes)
    pixels = np.concatenate([beauty, np.stack([hashes, coverage, zero, zero], axis=2)], axis=2)
    beauty_names = [f"{prefix}Combined.{c}" if prefix else c for c in "RGB"]
    names = beauty_names + [f"{layer}00.{c}" for c in "RGBA"]
    render = write_image(tmp_path / "render.exr", pixels, names, fmt="float", attrs=attrs)
    whole = write_image(tmp_path / "whole.exr", objects[..., None].astype(np.float32), ["Y"], fmt="float")
    raw = write_image(tmp_path / "raw.exr", hashes[..., None], ["Y"], fmt="float")

    r = run(render, "-v", "--object-median", 5, "-o", tmp_path / "crypto.exr")
    assert r.code == 0, r
    assert f"id       <- {render}: {layer}00.R (Cryptomatte ids)\n" in r.out, r
    for ids, out in ((whole, "whole.out.exr"), (raw, "raw.out.exr")):
        assert run(render, "--aov", f"id={ids}", "--object-median", 5, "-o", tmp_path / out).code == 0
    crypto, spec = read_image(tmp_path / "crypto.exr")
    expected, _ = read_image(tmp_path / "whole.out.exr")
    rounded, _ = read_image(tmp_path / "raw.out.exr")
    np.testing.assert_array_equal(beauty_of(crypto, spec, beauty_names), beauty_of(expected, spec, beauty_names))
    assert not np.array_equal(beauty_of(rounded, spec, beauty_names), beauty_of(expected, spec, beauty_names))
    r = run(render, "-v", "--aov", f"id={render}:{layer}00.R", "--object-median", 5, "-o", tmp_path / "aov.exr")
    assert r.code == 0 and "(Cryptomatte ids)" in r.out, r
    np.testing.assert_array_equal(read_image(tmp_path / "aov.exr")[0], crypto)


def test_beauty_override_and_layer_prefix(cycles_exr, tmp_path):
    r = run(cycles_exr, "--beauty", "My Layer.Combined", "--aov", f"normal={cycles_exr}:My Layer.Denoising Normal",
            "-v", "--median", 3, "-o", tmp_path / "out.exr")
    assert r.code == 0, r
    assert "My Layer.Combined.R,My Layer.Combined.G,My Layer.Combined.B,My Layer.Combined.A" in r.out
    assert "My Layer.Denoising Normal.X,My Layer.Denoising Normal.Y,My Layer.Denoising Normal.Z" in r.out


def test_data_format_and_compression(testrender_exr, tmp_path):
    r = run(testrender_exr, "--median", 3, "-d", "float", "--compression", "zip", "-o", tmp_path / "f.exr")
    assert r.code == 0, r
    spec = read_image(tmp_path / "f.exr")[1]
    assert spec.format == oiio.FLOAT and spec.get_string_attribute("compression") == "zip"


def test_runstats_and_threads(testrender_exr, tmp_path):
    r = run(testrender_exr, "--threads", 1, "--median", 3, "--gaussian", 3, "-o", tmp_path / "o.exr",
            "--runstats")
    assert r.code == 0, r
    for key in ("read time", "write time", "--median", "--gaussian", "peak memory"):
        assert key in r.out, r


def test_png_output_gets_the_beauty(testrender_exr, tmp_path):
    """A format that holds at most four channels gets the beauty only."""
    r = run(testrender_exr, "--median", 3, "-o", tmp_path / "clean.png")
    assert r.code == 0, r
    spec = read_image(tmp_path / "clean.png")[1]
    assert list(spec.channelnames) == BEAUTY


def test_force_overwrites_input(testrender_exr, tmp_path):
    r = run(testrender_exr, "--median", 3, "-o", testrender_exr)
    assert r.code == 1 and "--force" in r.err, r
    before = testrender_exr.read_bytes()
    r = run(testrender_exr, "--median", 3, "-o", testrender_exr, "--force")
    assert r.code == 0, r
    assert testrender_exr.read_bytes() != before


def test_help_lists_every_command():
    r = run("--help")
    assert r.code == 0
    for name in ("--mean SIZE", "--median SIZE", "--gaussian SIZE", "--aov ROLE=FILE[:CHANNELS]"):
        assert name in r.out


