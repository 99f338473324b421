"""mcdtool bad-input tests: each prints one line naming the culprit, exits 1
(2 for usage errors) and leaves no output behind. Each test_* function is
one CTest test (tests/driver/CMakeLists.txt)."""
import os

import numpy as np
import OpenImageIO as oiio
import pytest

from conftest import assert_no_outputs, check_failure, noisy_scene, run, write_image

BEAUTY = ["R", "G", "B"]


def test_bad_missing_file(tmp_path):
    r = run(tmp_path / "nope.exr", "--median", 3, "-o", tmp_path / "out.exr")
    check_failure(r, 1, "nope.exr", "no such file")
    assert_no_outputs(tmp_path, [])


def test_bad_truncated_exr(testrender_exr, tmp_path):
    data = testrender_exr.read_bytes()
    bad = tmp_path / "truncated.exr"
    bad.write_bytes(data[:len(data) // 2])
    existing = os.listdir(tmp_path)
    r = run(bad, "--median", 3, "-o", tmp_path / "out.exr")
    check_failure(r, 1, "truncated.exr")
    assert_no_outputs(tmp_path, existing)
    (tmp_path / "garbage.exr").write_bytes(b"not an exr at all")
    r = run(tmp_path / "garbage.exr", "--median", 3, "-o", tmp_path / "out.exr")
    check_failure(r, 1, "garbage.exr")
    assert not (tmp_path / "out.exr").exists()


def test_bad_missing_channel(testrender_exr, tmp_path):
    existing = os.listdir(tmp_path)
    r = run(testrender_exr, "--aov", f"normal={testrender_exr}:Nrm", "--median", 3, "-o", tmp_path / "out.exr")
    check_failure(r, 2, "'Nrm'", "channels: R,G,B,A")  # checked against the header, before reading
    assert_no_outputs(tmp_path, existing)
    r = run(testrender_exr, "--beauty", "diffuse", "--median", 3, "-o", tmp_path / "out.exr")
    check_failure(r, 2, "--beauty", "'diffuse'", "channels: ")
    assert_no_outputs(tmp_path, existing)


def test_bad_guide_channel_count(testrender_exr, tmp_path):
    existing = os.listdir(tmp_path)
    r = run(testrender_exr, "--aov", f"id={testrender_exr}:N", "--median", 3, "-o", tmp_path / "out.exr")
    check_failure(r, 1, "id guide needs 1 channel", "N.X,N.Y,N.Z")
    assert_no_outputs(tmp_path, existing)


def test_bad_data_window(tmp_path):
    beauty, ids, *_ = noisy_scene()
    write_image(tmp_path / "beauty.exr", beauty, BEAUTY)
    display = (ids.shape[1], ids.shape[0])
    write_image(tmp_path / "ids.exr", ids[4:, 4:, None], ["Y"], origin=(4, 4), display=display)
    existing = os.listdir(tmp_path)
    r = run(tmp_path / "beauty.exr", "--aov", "id=" + str(tmp_path / "ids.exr"), "--median", 3,
            "-o", tmp_path / "out.exr")
    check_failure(r, 1, "ids.exr", "does not cover the beauty's data window")
    assert_no_outputs(tmp_path, existing)
    # A guide whose data window is larger than the beauty's is fine.
    big = np.zeros((ids.shape[0] + 4, ids.shape[1] + 4, 1), np.float32)
    big[2:-2, 2:-2, 0] = ids
    write_image(tmp_path / "big_ids.exr", big, ["Y"], origin=(-2, -2), display=display)
    r = run(tmp_path / "beauty.exr", "--aov", "id=" + str(tmp_path / "big_ids.exr"), "--median", 3,
            "-o", tmp_path / "out.exr")
    assert r.code == 0, r


def test_bad_missing_guide(tmp_path):
    beauty, *_ = noisy_scene()
    write_image(tmp_path / "beauty.exr", beauty, BEAUTY)
    r = run(tmp_path / "beauty.exr", "--object-median", 3, "-o", tmp_path / "out.exr")
    check_failure(r, 1, "--object-median", "id guide", "--aov id=", "channels: R,G,B")
    assert not (tmp_path / "out.exr").exists()


@pytest.mark.parametrize("size", [6, 257, 0])
def test_bad_kernel_size(testrender_exr, tmp_path, size):
    existing = os.listdir(tmp_path)
    r = run(testrender_exr, "--median", size, "-o", tmp_path / "out.exr")
    check_failure(r, 2, "mcdtool ERROR: --median : SIZE")  # checked when parsing
    assert_no_outputs(tmp_path, existing)


def test_bad_unknown_command(testrender_exr, tmp_path):
    r = run(testrender_exr, "--medain", 7, "-o", tmp_path / "out.exr")
    check_failure(r, 2, "'--medain'", "did you mean '--median'")
    r = run(testrender_exr, "--aov", "normals=x.exr", "-o", tmp_path / "out.exr")
    check_failure(r, 2, "'normals'", "did you mean 'normal'")
    assert not (tmp_path / "out.exr").exists()


def test_bad_missing_argument(testrender_exr, tmp_path):
    r = run(testrender_exr, "--median")
    check_failure(r, 2, "--median", "missing argument", "--median SIZE")
    r = run(testrender_exr, "--median", "--gaussian", 3, "-o", tmp_path / "out.exr")
    check_failure(r, 2, "--median", "missing argument")
    r = run(testrender_exr, "--median", "seven", "-o", tmp_path / "out.exr")
    check_failure(r, 2, "--median", "SIZE must be an integer", "'seven'")
    r = run(testrender_exr, "--median", 3, "-o")
    check_failure(r, 2, "-o", "missing argument")
    r = run(testrender_exr, "--frames", "1-x", "--median", 3)
    check_failure(r, 2, "--frames", "1-x")
    assert not (tmp_path / "out.exr").exists()


def test_bad_unwritable_output(testrender_exr, tmp_path):
    (tmp_path / "a_file").write_text("x")
    existing = os.listdir(tmp_path)
    r = run(testrender_exr, "--median", 3, "-o", tmp_path / "a_file" / "out.exr")
    check_failure(r, 1, "a_file/out.exr")
    assert ".mcdtool-" not in r.err, r  # the temp file is never named
    assert_no_outputs(tmp_path, existing)


def test_bad_later_failure_leaves_no_earlier_output(testrender_exr, tmp_path):
    existing = os.listdir(tmp_path)
    r = run(testrender_exr, "--median", 3, "-o", tmp_path / "first.exr", "--dof", 2, 5,
            "-o", tmp_path / "second.exr")  # FOCUS beyond LEVELS: the library's rule, checked before reading
    check_failure(r, 2, "--dof : ", "focus_level < levels")
    assert_no_outputs(tmp_path, existing)


def test_bad_sequence_usage(tmp_path):
    r = run("beauty.####.exr", "--median", 3, "-o", "clean.####.exr", cwd=tmp_path)
    check_failure(r, 2, "frame pattern", "--frames")
    r = run("beauty.####.exr", "--frames", "1-3", "--median", 3, "-o", "clean.exr", cwd=tmp_path)
    check_failure(r, 2, "-o 'clean.exr'", "no frame pattern")
    r = run("beauty.exr", "--frames", "1-3", "--median", 3, "-o", "clean.####.exr", cwd=tmp_path)
    check_failure(r, 2, "--frames", "no frame pattern")
    r = run("beauty.####.exr", "--frames", "3-1x0", "-o", "clean.####.exr", cwd=tmp_path)
    check_failure(r, 2, "--frames", "step")
    assert os.listdir(tmp_path) == []


def test_bad_multipart_input(testrender_exr, tmp_path):
    """Two parts holding the same layered channel names cannot be merged
    into one channel list: refused, naming the file and the channel."""
    parts = tmp_path / "parts.exr"
    first = oiio.ImageBuf(str(testrender_exr))
    out = oiio.ImageOutput.create(str(parts))
    spec = first.spec()
    assert out.open(str(parts), (spec, spec))
    for i in range(2):
        if i:
            assert out.open(str(parts), spec, "AppendSubimage")
        assert out.write_image(first.get_pixels(oiio.FLOAT))
    out.close()
    existing = os.listdir(tmp_path)
    r = run(parts, "--median", 3, "-o", tmp_path / "out.exr")
    check_failure(r, 1, "parts.exr", "'N.X' twice")
    assert_no_outputs(tmp_path, existing)
