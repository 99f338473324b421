"""The Blender add-on in Debian's real Blender, headless: a small Cycles
animation rendered with `-a` and the add-on enabled from the built zip is
denoised frame by frame exactly as `mcdtool --denoise` denoises the raw
frames, leaves every other channel alone and comes closer to a 64-spp render;
a still (`-f`) with the report's chain goes to a sibling path; a still with
"Denoise light passes" equals `mcdtool --aovs auto --denoise`; a non-EXR
output, or frames that cannot be written, are reported and Blender still
exits 0; the Image editor's sequence operator writes sibling files equal to
mcdtool's."""
import os
import shutil
import subprocess
import time

import numpy as np
import OpenImageIO as oiio

import mcdenoise

BLENDER = shutil.which(os.environ.get("BLENDER", "blender"))
ADDON_ZIP = os.environ.get("MCD_BLENDER_ADDON_ZIP", "")
MCDTOOL = os.environ.get("MCDTOOL", "mcdtool")
SCENE_SCRIPT = os.path.join(os.path.dirname(__file__), "blender_scene.py")
COMBINED = "ViewLayer.Combined."

if BLENDER is None:
    raise RuntimeError("blender is not on PATH: scripts/setup installs it")


def run_blender(tmp_path, *options, render=("-a",)):
    """Runs blender_scene.py in a headless Blender with its own user folders;
    returns the completed process (stdout and stderr together)."""
    env = dict(os.environ, BLENDER_USER_CONFIG=str(tmp_path / "config"),
               BLENDER_USER_SCRIPTS=str(tmp_path / "scripts"))
    command = [BLENDER, "-b", "--factory-startup", "--python-exit-code", "1", "--python", SCENE_SCRIPT,
               *render, "--", "--zip", ADDON_ZIP, *[str(o) for o in options]]
    start = time.perf_counter()
    process = subprocess.run(command, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                             timeout=300)
    print(f"blender {' '.join(str(o) for o in options)}: {time.perf_counter() - start:.1f} s")
    return process


def read(path):
    """(channel names, float pixels H x W x C) of an EXR."""
    buf = oiio.ImageBuf(str(path))
    assert buf.read(force=True), buf.geterror()
    return list(buf.spec().channelnames), buf.get_pixels(oiio.FLOAT)


def channels(path, wanted):
    """The named channels' pixels (H x W x len(wanted))."""
    names, pixels = read(path)
    return pixels[:, :, [names.index(n) for n in wanted]]


def mcdtool_denoise(raw, target, chain=("--denoise",)):
    process = subprocess.run([MCDTOOL, str(raw), *chain, "-o", str(target)], capture_output=True,
                             text=True, timeout=120)
    assert process.returncode == 0, process.stderr
    return target


def test_animation_is_denoised_like_mcdtool(tmp_path):
    frames = 3
    rendered = run_blender(tmp_path, "--output", tmp_path / "out" / "frame_####", "--frames", frames,
                           "--spp", 8, "--denoise", "--raw-dir", tmp_path / "raw")
    assert rendered.returncode == 0, rendered.stdout
    assert "turned Cycles' own denoiser off" in rendered.stdout
    assert f"{frames} frame(s) denoised, 0 failed" in rendered.stdout, rendered.stdout
    for frame in range(1, frames + 1):
        name = f"frame_{frame:04d}.exr"
        out, raw = tmp_path / "out" / name, tmp_path / "raw" / name
        expected = mcdtool_denoise(raw, tmp_path / f"expected_{name}")
        out_names, out_pixels = read(out)
        raw_names, raw_pixels = read(raw)
        expected_names, expected_pixels = read(expected)
        assert out_names == raw_names == expected_names
        assert "ViewLayer.Denoising Albedo.R" in out_names
        assert out_pixels.tobytes() == expected_pixels.tobytes(), f"{name} differs from mcdtool --denoise"
        beauty = [i for i, n in enumerate(out_names) if n.startswith(COMBINED) and n[-1] in "RGB"]
        others = [i for i in range(len(out_names)) if i not in beauty]
        assert not np.array_equal(out_pixels[:, :, beauty], raw_pixels[:, :, beauty])
        assert out_pixels[:, :, others].tobytes() == raw_pixels[:, :, others].tobytes()

    reference = run_blender(tmp_path / "ref", "--output", tmp_path / "ref" / "frame_####", "--frames", 1,
                            "--spp", 64, render=("-f", "1"))
    assert reference.returncode == 0, reference.stdout
    rgb = [COMBINED + c for c in "RGB"]
    ref = channels(tmp_path / "ref" / "frame_0001.exr", rgb)
    raw_error = mcdenoise.rel_mse(channels(tmp_path / "raw" / "frame_0001.exr", rgb), ref)
    denoised_error = mcdenoise.rel_mse(channels(tmp_path / "out" / "frame_0001.exr", rgb), ref)
    print(f"relMSE against 64 spp: raw 8 spp {raw_error:.5f}, denoised {denoised_error:.5f}")
    assert denoised_error < raw_error


def test_still_with_report_chain_to_sibling_path(tmp_path):
    rendered = run_blender(tmp_path, "--output", tmp_path / "out" / "still_####", "--frames", 1, "--spp", 4,
                           "--denoise", "--mode", "REPORT_CHAIN", "--pattern", "clean/{name}.exr",
                           render=("-f", "1"))
    assert rendered.returncode == 0, rendered.stdout
    assert "turned on the Object Index pass" in rendered.stdout
    raw, out = tmp_path / "out" / "still_0001.exr", tmp_path / "out" / "clean" / "still_0001.exr"
    assert "ViewLayer.IndexOB.X" in read(raw)[0]
    expected = mcdtool_denoise(raw, tmp_path / "expected.exr", ("--object-median", "7", "--gaussian", "3"))
    assert read(out)[1].tobytes() == read(expected)[1].tobytes()
    assert read(out)[1].tobytes() != read(raw)[1].tobytes()


def test_light_passes_are_denoised_like_mcdtool_aovs(tmp_path):
    """With "Denoise light passes" the add-on turns the light passes on and
    writes what `mcdtool --aovs auto --denoise` writes: the light passes
    denoised, and a Combined equal to their compositor rebuild."""
    rendered = run_blender(tmp_path, "--output", tmp_path / "out" / "still_####", "--frames", 1, "--spp", 4,
                           "--denoise", "--light-passes", "--raw-dir", tmp_path / "raw", render=("-f", "1"))
    assert rendered.returncode == 0, rendered.stdout
    assert "turned on the light passes" in rendered.stdout, rendered.stdout
    raw, out = tmp_path / "raw" / "still_0001.exr", tmp_path / "out" / "still_0001.exr"
    expected = mcdtool_denoise(raw, tmp_path / "expected.exr", ("--aovs", "auto", "--denoise"))
    assert read(out)[1].tobytes() == read(expected)[1].tobytes()
    layer = "ViewLayer."
    rgb = lambda name: channels(out, [f"{layer}{name}.{c}" for c in "RGB"])
    rebuilt = rgb("Emit") + rgb("Env")
    for lobe in ("Diff", "Gloss", "Trans"):
        rebuilt = rebuilt + rgb(lobe + "Col") * (rgb(lobe + "Dir") + rgb(lobe + "Ind"))
    assert mcdenoise.rel_mse(rebuilt, rgb("Combined")) <= 1e-6
    assert not np.array_equal(rgb("DiffInd"), channels(raw, [f"{layer}DiffInd.{c}" for c in "RGB"]))


def test_non_exr_output_is_reported(tmp_path):
    rendered = run_blender(tmp_path, "--output", tmp_path / "out" / "frame_####", "--frames", 1,
                           "--format", "PNG", "--denoise")
    assert rendered.returncode == 0, rendered.stdout
    assert "Warning: mcdenoise: the output format PNG cannot carry the passes" in rendered.stdout, rendered.stdout
    assert (tmp_path / "out" / "frame_0001.png").exists()


def test_failed_frames_are_reported_and_the_render_goes_on(tmp_path):
    rendered = run_blender(tmp_path, "--output", tmp_path / "out" / "frame_####", "--frames", 2, "--spp", 2,
                           "--denoise", "--pattern", "/proc/no-such-folder/{name}.exr")
    assert rendered.returncode == 0, rendered.stdout
    assert "Error: mcdenoise: frame 1 (1 done)" in rendered.stdout, rendered.stdout
    assert "0 frame(s) denoised, 2 failed" in rendered.stdout, rendered.stdout
    assert (tmp_path / "out" / "frame_0002.exr").exists()


def test_sequence_operator_writes_sibling_files(tmp_path):
    rendered = run_blender(tmp_path, "--output", tmp_path / "seq" / "frame_####", "--frames", 2, "--spp", 4)
    assert rendered.returncode == 0, rendered.stdout
    files = [tmp_path / "seq" / f"frame_{f:04d}.exr" for f in (1, 2)]
    raw = [read(f)[1].tobytes() for f in files]
    operated = run_blender(tmp_path, "--output", "unused", "--operator", *files, render=())
    assert operated.returncode == 0, operated.stdout
    assert "2 of 2 frame(s) denoised" in operated.stdout, operated.stdout
    for path, raw_bytes in zip(files, raw):
        expected = mcdtool_denoise(path, tmp_path / f"expected_{path.name}")
        assert read(tmp_path / "seq" / "denoised" / path.name)[1].tobytes() == read(expected)[1].tobytes()
        assert read(path)[1].tobytes() == raw_bytes  # the raw frame is kept
