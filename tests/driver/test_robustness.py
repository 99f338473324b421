"""mcdtool robustness tests (docs/robustness.md): interrupted and killed
writes leave the old file or the complete new one, a full disk or a file
size limit is reported, inputs are never modified, memory and channel
limits are clear errors, overscan and odd data windows are filtered and
kept, and --threads 1/2/16 give bit-identical files. Each test_* function
is one CTest test (tests/driver/CMakeLists.txt)."""
import hashlib
import os
import resource
import signal
import subprocess
import time

import numpy as np
import OpenImageIO as oiio
import pytest

from conftest import (MCDTOOL, check_failure, median_reference, noisy_scene, read_image,
                      run, write_image)

BEAUTY = ["R", "G", "B"]
RENDER = ["R", "G", "B", "A", "id", "reflid", "N.X", "N.Y", "N.Z", "Z"]


def digest(path):
    return hashlib.sha256(path.read_bytes()).hexdigest()


def temp_files(directory):
    return [name for name in os.listdir(directory) if ".mcdtool-" in name]


def big_render(path, width, height, seed=3):
    """A render with testrender's channels, large enough that writing it takes a while."""
    rng = np.random.default_rng(seed)
    pixels = rng.uniform(0.0, 1.0, (height, width, len(RENDER))).astype(np.float32)
    return write_image(path, pixels, RENDER, fmt="float", compression="piz")


# --- interrupted writes ------------------------------------------------------

def interrupt_mid_write(tmp_path, sig, attempts=6):
    """Starts mcdtool writing over an existing out.exr and sends `sig` as soon
    as its temp file appears. Returns (caught mid-write, old digest, the
    input's digest before)."""
    src = big_render(tmp_path / "render.exr", 1024, 768)
    old = write_image(tmp_path / "out.exr", np.full((4, 4, 3), 0.25, np.float32), BEAUTY)
    old_digest, src_digest = digest(old), digest(src)
    for _ in range(attempts):
        proc = subprocess.Popen([MCDTOOL, str(src), "--median", "3", "-o", str(old), "-d", "float",
                                 "--compression", "piz"], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        caught = False
        while proc.poll() is None:
            if temp_files(tmp_path):
                proc.send_signal(sig)
                caught = True
                break
            time.sleep(0.0005)
        proc.wait(timeout=120)
        if caught and proc.returncode == -sig:
            return True, old_digest, src_digest
        # It finished before the temp file was seen: put the old file back and try again.
        write_image(old, np.full((4, 4, 3), 0.25, np.float32), BEAUTY)
    return False, old_digest, src_digest


def assert_old_or_complete_new(path, old_digest):
    if digest(path) == old_digest:
        return
    pixels, spec = read_image(path)
    assert (spec.width, spec.height) == (1024, 768) and pixels.shape[2] == len(RENDER)


@pytest.mark.parametrize("sig", [signal.SIGINT, signal.SIGTERM])
def test_robust_interrupt_removes_temp_files(tmp_path, sig):
    caught, old_digest, src_digest = interrupt_mid_write(tmp_path, sig)
    assert caught, "mcdtool always finished before its temp file could be seen"
    assert_old_or_complete_new(tmp_path / "out.exr", old_digest)
    assert temp_files(tmp_path) == []
    assert digest(tmp_path / "render.exr") == src_digest


def test_robust_killed_write_never_truncates(tmp_path):
    caught, old_digest, src_digest = interrupt_mid_write(tmp_path, signal.SIGKILL)
    assert caught, "mcdtool always finished before its temp file could be seen"
    assert_old_or_complete_new(tmp_path / "out.exr", old_digest)
    # A kill cannot clean up: what is left has the hidden temp name only.
    for name in temp_files(tmp_path):
        assert name.startswith(".out.exr.mcdtool-") and name != "out.exr"
    assert digest(tmp_path / "render.exr") == src_digest


# --- full disk ------------------------------------------------------------------

def limit_file_size(limit):
    return lambda: resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))


def test_robust_file_size_limit_is_reported(tmp_path):
    src = big_render(tmp_path / "render.exr", 256, 256)
    existing = sorted(os.listdir(tmp_path))
    proc = subprocess.run([MCDTOOL, str(src), "--median", "3", "-o", str(tmp_path / "out.exr")],
                          capture_output=True, text=True, timeout=120, preexec_fn=limit_file_size(64 * 1024))
    assert proc.returncode == 1, proc
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("mcdtool ERROR: -o : cannot write"), proc.stderr
    assert "out.exr" in lines[0]
    assert sorted(os.listdir(tmp_path)) == existing


def test_robust_full_disk_is_reported(tmp_path):
    disk = tmp_path / "small_disk"
    disk.mkdir()
    mounted = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=128k", "tmpfs", str(disk)],
                             capture_output=True).returncode == 0
    if not mounted:
        pytest.skip("cannot mount a small tmpfs here (needs root)")
    try:
        src = big_render(tmp_path / "render.exr", 256, 256)
        r = run(src, "--median", 3, "-o", disk / "out.exr")
        check_failure(r, 1, "-o : cannot write", "small_disk/out.exr")
        assert os.listdir(disk) == []
    finally:
        subprocess.run(["umount", str(disk)], check=True)


# --- inputs never modified -------------------------------------------------------

def test_robust_inputs_never_modified(testrender_exr, tmp_path):
    beauty, ids, normal, _ = noisy_scene()
    ids_file = write_image(tmp_path / "ids.exr", ids[..., None], ["Y"])
    normal_file = write_image(tmp_path / "normal.exr", normal, ["R", "G", "B"])
    inputs = [testrender_exr, ids_file, normal_file]
    before = [digest(p) for p in inputs]
    good = run(testrender_exr, "--aov", f"id={ids_file}", "--aov", f"normal={normal_file}", "--normal-mean", 5,
               "--median", 3, "-o", tmp_path / "out.exr", "--compare", testrender_exr)
    assert good.code == 0, good
    bad = run(testrender_exr, "--aov", f"id={ids_file}", "--median", 3, "-o", testrender_exr)
    check_failure(bad, 1, "is an input of this run")
    bad = run(testrender_exr, "--median", 3, "-o", tmp_path / "x.exr", "--dof", 2, 5, "-o", ids_file)
    check_failure(bad, 2, "--dof : ")
    assert [digest(p) for p in inputs] == before


# --- limits ------------------------------------------------------------------

def test_robust_image_too_large_for_the_memory_limit(tmp_path):
    # 2000 x 2000 x 3 floats are 46 MiB in memory (the file is tiny: constant, zip).
    big = write_image(tmp_path / "big.exr", np.full((2000, 2000, 3), 0.5, np.float32), BEAUTY,
                      compression="zip")
    existing = os.listdir(tmp_path)
    r = run(big, "--median", 3, "-o", tmp_path / "out.exr", "--memory-limit", 10)
    check_failure(r, 1, "input : ", "big.exr", "2000 x 2000, 3 channels",
                  "needs 46 MiB", "memory limit of 10 MiB")
    assert_no_new(tmp_path, existing)
    # The file fits (46 MiB) but the frame's working set (15 float planes) does not.
    r = run(big, "--median", 3, "-o", tmp_path / "out.exr", "--memory-limit", 100)
    check_failure(r, 1, "big.exr", "this frame", "memory limit of 100 MiB")
    assert_no_new(tmp_path, existing)
    r = run(big, "--median", 3, "-o", tmp_path / "out.exr", "--memory-limit", 400)
    assert r.code == 0, r
    r = run(big, "--median", 3, "-o", tmp_path / "out.exr", "--memory-limit", "0")
    check_failure(r, 2, "--memory-limit", "'0'")


def assert_no_new(directory, existing):
    assert sorted(os.listdir(directory)) == sorted(existing)


@pytest.mark.parametrize("size", [257, 1001, 999999999])
def test_robust_kernel_size_over_the_limit(testrender_exr, tmp_path, size):
    existing = os.listdir(tmp_path)
    r = run(testrender_exr, "--median", size, "-o", tmp_path / "out.exr")
    check_failure(r, 2, "--median : SIZE out of range (odd window side, 1..255)", str(size))
    assert_no_new(tmp_path, existing)


def test_robust_channel_counts_that_do_not_fit(tmp_path):
    beauty, ids, *_ = noisy_scene()
    five = np.concatenate([beauty, beauty[..., :2]], axis=2)
    src = write_image(tmp_path / "five.exr", five, ["R", "G", "B", "X", "Y"])
    existing = os.listdir(tmp_path)
    # Five beauty channels cannot go into a PNG.
    r = run(src, "--beauty", "R,G,B,X,Y", "--median", 3, "-o", tmp_path / "out.png")
    check_failure(r, 1, "out.png")
    assert_no_new(tmp_path, existing)
    # Half buffers must have the beauty's channel count.
    r = run(src, "--beauty", "R,G,B", "--aov", f"half_a={src}:R,G", "--median", 3, "-o", tmp_path / "out.exr")
    check_failure(r, 1, "half_a guide needs 3 (like the beauty)", "got 2")
    assert_no_new(tmp_path, existing)
    # An id guide of three channels is refused, naming them.
    r = run(src, "--aov", f"id={src}:R,G,B", "--median", 3, "-o", tmp_path / "out.exr")
    check_failure(r, 1, "id guide needs 1 channel", "R,G,B")
    assert_no_new(tmp_path, existing)


# --- data windows ---------------------------------------------------------------

def window_case(tmp_path, name, data_origin, data_size, display_size):
    """A beauty whose data window is `data_size` at `data_origin`, with a
    display window of `display_size` at 0,0; returns (path, pixels)."""
    rng = np.random.default_rng(5)
    w, h = data_size
    pixels = rng.uniform(0.0, 1.0, (h, w, 3)).astype(np.float32)
    spec = oiio.ImageSpec(w, h, 3, "float")
    spec.channelnames = tuple(BEAUTY)
    spec.x, spec.y = data_origin
    spec.full_x = spec.full_y = 0
    spec.full_width, spec.full_height = display_size
    buf = oiio.ImageBuf(spec)
    buf.set_pixels(oiio.ROI(), pixels)
    path = tmp_path / f"{name}.exr"
    assert buf.write(str(path)), buf.geterror()
    return path, pixels


@pytest.mark.parametrize("name,origin,size", [
    ("overscan", (-6, -4), (52, 40)),      # data window larger than the 40 x 32 display window
    ("crop", (5, 3), (20, 14)),            # smaller, inside it
    ("shifted", (17, -9), (30, 30)),       # non-zero origin, partly outside
])
def test_robust_data_windows_are_filtered_and_kept(tmp_path, name, origin, size):
    path, pixels = window_case(tmp_path, name, origin, size, (40, 32))
    r = run(path, "--median", 5, "-o", tmp_path / "out.exr")
    assert r.code == 0, r
    out, spec = read_image(tmp_path / "out.exr")
    assert (spec.x, spec.y, spec.width, spec.height) == (origin[0], origin[1], size[0], size[1])
    assert (spec.full_x, spec.full_y, spec.full_width, spec.full_height) == (0, 0, 40, 32)
    np.testing.assert_array_equal(out, median_reference(pixels, 5))


def filtered(src, out, *args):
    """The pixels and spec mcdtool writes to `out` from `src` with `args`."""
    r = run(src, *args, "-o", out)
    assert r.code == 0, r
    return read_image(out)


def test_robust_guides_with_other_covering_data_windows(tmp_path):
    beauty, ids, *_ = noisy_scene()
    h, w, _ = beauty.shape
    src = write_image(tmp_path / "beauty.exr", beauty, BEAUTY, fmt="float", origin=(3, -2))
    # The id guide covers the beauty with 5 extra pixels on every side,
    # holding another object there (which must not leak in).
    big = np.full((h + 10, w + 10, 1), 9.0, np.float32)
    big[5:-5, 5:-5, 0] = ids
    big_ids = write_image(tmp_path / "big_ids.exr", big, ["Y"], fmt="float", origin=(-2, -7), display=(w, h))
    exact_ids = write_image(tmp_path / "ids.exr", ids[..., None], ["Y"], fmt="float", origin=(3, -2))
    a, a_spec = filtered(src, tmp_path / "a.exr", "--aov", f"id={big_ids}", "--object-median", 5)
    b, _ = filtered(src, tmp_path / "b.exr", "--aov", f"id={exact_ids}", "--object-median", 5)
    assert (a_spec.x, a_spec.y, a_spec.width, a_spec.height) == (3, -2, w, h)
    np.testing.assert_array_equal(a, b)


def test_robust_guide_channels_come_in_the_selector_order(tmp_path):
    """A guide picked from scattered channels in another order holds them in
    the order typed: the same result as a file that stores them that way."""
    beauty, ids, _, _ = noisy_scene()
    rng = np.random.default_rng(11)
    normal = rng.normal(0.0, 1.0, ids.shape + (3,)).astype(np.float32)
    scattered = np.concatenate([normal[..., 2:3], beauty, normal[..., 0:1], ids[..., None],
                                normal[..., 1:2]], axis=2)
    src = write_image(tmp_path / "scattered.exr", scattered, ["nz", "R", "G", "B", "nx", "id", "ny"],
                      fmt="float", origin=(2, 5))
    ordered = write_image(tmp_path / "normal.exr", normal, ["X", "Y", "Z"], fmt="float", origin=(2, 5))
    a, _ = filtered(src, tmp_path / "a.exr", "--aov", f"normal={src}:nx,ny,nz", "--normal-gaussian", 5)
    b, _ = filtered(src, tmp_path / "b.exr", "--aov", f"normal={ordered}", "--normal-gaussian", 5)
    np.testing.assert_array_equal(a, b)
    c, _ = filtered(src, tmp_path / "c.exr", "--aov", f"normal={src}:nz,ny,nx", "--normal-gaussian", 5)
    assert not np.array_equal(a, c)


# --- determinism ------------------------------------------------------------------

def test_robust_threads_give_bit_identical_files(testrender_exr, tmp_path):
    chain = ["--median", 5, "--gaussian", 3, "--mean", 3, "--object-median", 5, "--brdf-gaussian", 5,
             "--normal-gaussian", 5, "--dof", 4, 1]
    digests = set()
    for threads in (1, 2, 16):
        out = tmp_path / f"out{threads}.exr"
        r = run(testrender_exr, *chain, "--threads", threads, "-o", out, "-d", "float")
        assert r.code == 0, r
        digests.add(digest(out))
    assert len(digests) == 1
