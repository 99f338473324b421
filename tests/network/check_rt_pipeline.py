#!/usr/bin/python3
"""The pipeline check: mcdtool's --denoise (OIDN 2.x's RT filter around our
UNet) against tests/network/rt_pipeline_reference.py, on OIDN's published
weights.

It writes two seeded synthetic HDR renders as float32 EXR, sizes not
multiples of 16: a noisy beauty from 1e-3 to 50 with a few fireflies up to
1e3, one NaN pixel and one negative pixel; a textured albedo in [0, 1] with
noise; unit normals with noise.

  72x56  R,G,B,A, albedo.R/G/B, N.X/Y/Z
  40x88  R,G,B, Denoising Albedo.R/G/B, Denoising Normal.X/Y/Z (Blender's)

Each image goes through `MCDTOOL IN.exr --denoise:quality=Q -o OUT.exr` for
Q in fast, balanced and high, and the 72x56 one also through
`MCDTOOL IN.exr --denoise:prefilter=0 -o OUT.exr`; the output's R,G,B are
compared with the reference's with the same settings. A case passes when the
mean over R,G,B of |ours - ref| / (|ref| + 0.01) is at most 1e-4; it prints
that, the largest absolute difference, the networks and both run times.

Anything missing (mcdtool, a weight file, an output, its R,G,B) fails with a
message naming it; nothing is skipped. --mcdtool is a command line, split
like a shell's, that takes IN.exr [options] -o OUT.exr. The closing line is
`check_rt_pipeline: N passed, N failed`; exit status 0 only if none failed.

Usage: /usr/bin/python3 tests/network/check_rt_pipeline.py --mcdtool PATH --weights-dir DIR
"""

import argparse
import os
import shlex
import shutil
import subprocess
import sys
import tempfile
import time

try:
    import numpy as np
    import OpenImageIO as oiio

    import rt_pipeline_reference as reference
except ImportError as e:
    print(f"check_rt_pipeline: FAIL, missing: the Python module {e.name} "
          "(apt-get install python3-numpy python3-openimageio)")
    sys.exit(1)

TOLERANCE = 1e-4
EPSILON = 0.01  # the relative difference's floor

# name, width, height, the beauty's channels, the albedo's, the normal's
IMAGES = [
    ("72x56", 72, 56, ["R", "G", "B", "A"], ["albedo.R", "albedo.G", "albedo.B"], ["N.X", "N.Y", "N.Z"]),
    ("40x88", 40, 88, ["R", "G", "B"], ["Denoising Albedo.R", "Denoising Albedo.G", "Denoising Albedo.B"],
     ["Denoising Normal.X", "Denoising Normal.Y", "Denoising Normal.Z"]),
]
# image, mcdtool's options, the reference's quality and prefilter
CASES = ([(image[0], [f"--denoise:quality={q}"], q, True) for image in IMAGES for q in reference.QUALITIES]
         + [(IMAGES[0][0], ["--denoise:prefilter=0"], "high", False),
            (IMAGES[1][0], ["--denoise:quality=fast:prefilter=0"], "fast", False)])


class Failed(Exception):
    pass


def synthetic_render(name, width, height):
    """(beauty, albedo, normal), H x W x 3 float32 each, seeded by NAME."""
    rng = np.random.default_rng(list(name.encode()))
    v, u = np.meshgrid((np.arange(height) + 0.5) / height, (np.arange(width) + 0.5) / width, indexing="ij")
    # albedo: four flat materials, one of them a checker, plus noise
    materials = np.array([[0.8, 0.2, 0.1], [0.1, 0.5, 0.9], [0.9, 0.9, 0.85], [0.3, 0.6, 0.2]], np.float32)
    region = (u > 0.45).astype(int) + 2 * (v > 0.6)
    checker = ((np.floor(u * 8) + np.floor(v * 8)) % 2)[..., None]
    albedo = materials[region] * np.where(region[..., None] == 3, 0.4 + 0.6 * checker, 1.0)
    albedo = np.clip(albedo + rng.normal(0, 0.03, albedo.shape), 0, 1)
    # normal: a sphere in the middle of a tilted plane, plus noise
    dx, dy = (u - 0.5) * 2.2, (v - 0.5) * 2.2
    inside = dx * dx + dy * dy < 0.8
    normal = np.where(inside[..., None],
                      np.stack([dx, -dy, np.sqrt(np.maximum(1.0 - dx * dx - dy * dy, 0.04))], axis=2),
                      np.array([0.2, 0.3, 1.0]))
    normal = normal + rng.normal(0, 0.05, normal.shape)
    normal /= np.linalg.norm(normal, axis=2, keepdims=True)
    # beauty: the albedo lit from one side, brightness from 1e-3 (left) to
    # 50 (right), with Monte Carlo-like noise and fireflies
    light = np.array([0.5, 0.5, 0.7]) / np.linalg.norm([0.5, 0.5, 0.7])
    shading = np.maximum(normal @ light, 0.05) * np.exp(np.log(1e-3) + u * np.log(5e4))
    beauty = albedo * shading[..., None] * rng.gamma(4.0, 0.25, albedo.shape)
    beauty = np.clip(beauty, 1e-3, 50)
    for _ in range(5):
        beauty[rng.integers(height), rng.integers(width)] = rng.uniform(200, 1000, 3)
    beauty[height // 3, width // 4] = np.nan
    beauty[height // 2, width // 3] = [-0.5, -0.02, -3.0]
    return beauty.astype(np.float32), albedo.astype(np.float32), normal.astype(np.float32)


def write_exr(path, width, height, channels):
    """CHANNELS: [(names, H x W x n array)] into one float32 EXR."""
    names = [name for group, _ in channels for name in group]
    pixels = np.concatenate([values for _, values in channels], axis=2).astype(np.float32)
    spec = oiio.ImageSpec(width, height, len(names), oiio.FLOAT)
    spec.channelnames = names
    buf = oiio.ImageBuf(spec)
    if not buf.set_pixels(oiio.ROI(0, width, 0, height, 0, 1, 0, len(names)), pixels) or not buf.write(path):
        raise Failed(f"cannot write {path}: {buf.geterror()}")


def make_images(tmp):
    """{name: (path, beauty, albedo, normal)} of the test images."""
    images = {}
    for name, width, height, beauty_names, albedo_names, normal_names in IMAGES:
        beauty, albedo, normal = synthetic_render(name, width, height)
        channels = [(beauty_names[:3], beauty), (albedo_names, albedo), (normal_names, normal)]
        if len(beauty_names) == 4:
            channels.insert(1, (beauty_names[3:], np.ones((height, width, 1), np.float32)))
        path = os.path.join(tmp, f"render_{name}.exr")
        write_exr(path, width, height, channels)
        finite = beauty[np.isfinite(beauty)]
        print(f"     image {name}: {', '.join(n for group, _ in channels for n in group)}; beauty in "
              f"[{finite.min():.3g}, {finite.max():.3g}], {np.isnan(beauty).any(axis=2).sum()} NaN pixel(s), "
              f"{(beauty < 0).any(axis=2).sum()} negative")
        images[name] = (path, beauty, albedo, normal)
    return images


def mcdtool_command(mcdtool):
    if not mcdtool:
        raise Failed("--mcdtool is not given: build mcdtool and pass its path")
    command = shlex.split(mcdtool)
    if not command or not shutil.which(command[0]):
        raise Failed(f"--mcdtool {mcdtool!r}: {command[0] if command else 'nothing'} is not an executable: "
                     "build mcdtool and pass its path")
    return command


def check_weights(weights_dir):
    """Fails naming every weight file the cases need that is missing."""
    if not weights_dir:
        raise Failed("--weights-dir is not given: install the weights with scripts/fetch-weights --dest DIR")
    names = {name for _, _, quality, prefilter in CASES
             for name in reference.networks(quality, prefilter, True, True).values()}
    missing = sorted(os.path.join(weights_dir, n + ".tza") for n in names
                     if not os.path.isfile(os.path.join(weights_dir, n + ".tza")))
    if missing:
        raise Failed(f"{', '.join(missing)} missing: install the weights with "
                     f"scripts/fetch-weights --dest {weights_dir}")


def run_mcdtool(command, input_path, options, output_path):
    """mcdtool's denoised R,G,B and the seconds taken."""
    if os.path.exists(output_path):
        os.remove(output_path)  # no stale output of the case before
    argv = command + [input_path] + options + ["-o", output_path]
    start = time.monotonic()
    result = subprocess.run(argv, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    seconds = time.monotonic() - start
    if result.returncode != 0:
        raise Failed(f"exited with {result.returncode}: {shlex.join(argv)}\n{result.stdout.strip()}")
    if not os.path.isfile(output_path):
        raise Failed(f"wrote no {output_path}: {shlex.join(argv)}")
    try:
        return reference.read_image(output_path)["beauty"], seconds
    except reference.Failure as e:
        raise Failed(f"its output: {e}")


def compare(ours, ref):
    """(mean of |ours - ref| / (|ref| + EPSILON), max |ours - ref|)."""
    if ours.shape != ref.shape:
        raise Failed(f"output sizes differ: {ours.shape[1]}x{ours.shape[0]} and {ref.shape[1]}x{ref.shape[0]}")
    if not (np.isfinite(ours).all() and np.isfinite(ref).all()):
        raise Failed(f"an output holds NaN or infinity (mcdtool {np.isfinite(ours).all()}, "
                     f"reference {np.isfinite(ref).all()} all finite)")
    diff = np.abs(ours.astype(np.float64) - ref.astype(np.float64))
    return float(np.mean(diff / (np.abs(ref) + EPSILON))), float(diff.max())


def check(command, weights_dir, tmp):
    images = make_images(tmp)
    passed = failed = 0
    for image, options, quality, prefilter in CASES:
        path, beauty, albedo, normal = images[image]
        case = f"{image} {' '.join(options)}"
        try:
            chosen = reference.networks(quality, prefilter, True, True)
            start = time.monotonic()
            ref = reference.denoise(weights_dir, quality, prefilter, beauty, albedo, normal)
            seconds_ref = time.monotonic() - start
            # A file name of its own per case: OpenImageIO's image cache
            # would serve a reused name's earlier pixels.
            out = os.path.join(tmp, f"out_{passed + failed}.exr")
            ours, seconds_ours = run_mcdtool(command, path, options, out)
            relative, largest = compare(ours, ref)
        except (Failed, reference.Failure) as e:
            print(f"FAIL {case}: {e}")
            failed += 1
            continue
        ok = relative <= TOLERANCE
        print(f"{'ok  ' if ok else 'FAIL'} {case}: mean relative difference {relative:.2e} (limit {TOLERANCE:.0e}), "
              f"max abs difference {largest:.2e}, output in [{ref.min():.3g}, {ref.max():.3g}]; "
              f"{' + '.join(chosen.values())}; mcdtool {seconds_ours:.2f} s, reference {seconds_ref:.2f} s")
        passed += ok
        failed += not ok
    return passed, failed


def main(argv):
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__.split("\n\n", 1)[1])
    parser.add_argument("--mcdtool", metavar="COMMAND",
                        help="mcdtool, or any command line (split like a shell's) taking IN.exr [options] -o OUT.exr")
    parser.add_argument("--weights-dir", metavar="DIR", help="the folder of OIDN 2.x's rt_*.tza files")
    args = parser.parse_args(argv)
    try:
        command = mcdtool_command(args.mcdtool)
        check_weights(args.weights_dir)
        print(f"check_rt_pipeline: {shlex.join(command)} against rt_pipeline_reference.py, {len(CASES)} cases")
        with tempfile.TemporaryDirectory(prefix="check_rt_pipeline.") as tmp:
            passed, failed = check(command, args.weights_dir, tmp)
    except Failed as e:
        print(f"check_rt_pipeline: FAIL: {e}")
        return 1
    print(f"check_rt_pipeline: {passed} passed, {failed} failed")
    return 0 if failed == 0 and passed > 0 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
