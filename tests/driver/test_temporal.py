"""mcdtool --temporal N and --compare over a sequence, on small testrender
shots: the cross-frame result differs from the per-frame one and is closer
to the references; --temporal 0 changes nothing; a sequence split across
runs gives the same files as one run (neighbours come from disk); a missing
neighbour is warned about and left out; a neighbour of another resolution
fails that frame clearly; bad uses are usage errors; another renderer's
motion pass is refused with a warning; the sequence figures printed are
those of their definitions (computed here with numpy)."""
import os
import re
import shutil
import subprocess

import numpy as np
import pytest

from conftest import read_image, run, write_image

TESTRENDER = os.environ["TESTRENDER"]
EPS = 0.01


def render(directory, scene="shot_truck", frames=range(1, 6), spp=8, seed=1, res="40x32", name="shot"):
    """Renders `frames` of `scene` as directory/name.####.exr; returns the pattern."""
    directory.mkdir(exist_ok=True)
    for frame in frames:
        subprocess.run([TESTRENDER, "--scene", scene, "--res", res, "--spp", str(spp), "--seed", str(seed),
                        "--frame", str(frame), "-q", "-o", str(directory / f"{name}.{frame:04d}.exr")],
                       check=True, timeout=120)
    return directory / f"{name}.####.exr"


def beauty(path):
    pixels, spec = read_image(path)
    names = list(spec.channelnames)
    return pixels[:, :, [names.index(c) for c in "RGB"]].astype(np.float64)


def rel_mse(x, r):
    return float((((x - r) ** 2) / (r ** 2 + EPS)).mean())


def test_cross_frame_result_is_closer_to_the_references_than_per_frame(tmp_path):
    shot = render(tmp_path / "in")
    refs = render(tmp_path / "ref", spp=128, seed=1000, name="ref")
    per_frame = run(shot, "--frames", "1-5", "--denoise", "-o", tmp_path / "pf.####.exr")
    cross = run(shot, "--frames", "1-5", "--denoise", "--temporal", 2, "-o", tmp_path / "tf.####.exr")
    assert per_frame.code == 0 and cross.code == 0, (per_frame, cross)
    pf = [rel_mse(beauty(tmp_path / f"pf.{f:04d}.exr"), beauty(tmp_path / f"ref/ref.{f:04d}.exr")) for f in range(1, 6)]
    tf = [rel_mse(beauty(tmp_path / f"tf.{f:04d}.exr"), beauty(tmp_path / f"ref/ref.{f:04d}.exr")) for f in range(1, 6)]
    assert not np.array_equal(beauty(tmp_path / "pf.0003.exr"), beauty(tmp_path / "tf.0003.exr"))
    assert np.mean(tf) < np.mean(pf), (tf, pf)
    assert refs.name == "ref.####.exr"


def test_temporal_zero_changes_nothing(tmp_path):
    shot = render(tmp_path / "in", frames=range(1, 3))
    assert run(shot, "--frames", "1-2", "--denoise", "-o", tmp_path / "a.####.exr").code == 0
    assert run(shot, "--frames", "1-2", "--denoise", "--temporal", 0, "-o", tmp_path / "b.####.exr").code == 0
    for f in (1, 2):
        assert (tmp_path / f"a.{f:04d}.exr").read_bytes() == (tmp_path / f"b.{f:04d}.exr").read_bytes()


def test_split_runs_write_the_same_files_as_one_run(tmp_path):
    shot = render(tmp_path / "in")
    one = run(shot, "--frames", "1-5", "--denoise", "--temporal", 2, "-o", tmp_path / "one/o.####.exr")
    assert one.code == 0, one
    for frames in ("1-2", "3", "4-5"):
        part = run(shot, "--frames", frames, "--denoise", "--temporal", 2, "-o", tmp_path / "split/o.####.exr")
        assert part.code == 0, part
    for f in range(1, 6):
        assert (tmp_path / f"one/o.{f:04d}.exr").read_bytes() == (tmp_path / f"split/o.{f:04d}.exr").read_bytes()


def test_each_file_is_read_once(tmp_path):
    """The window holds the frames: 5 frames with 2 neighbours each side read 5 files, not 5 x 5."""
    shot = render(tmp_path / "in")
    r = run(shot, "--frames", "1-5", "--denoise", "--temporal", 2, "-o", tmp_path / "o.####.exr", "--runstats")
    assert r.code == 0 and re.search(r"read time +[0-9.]+ s \(5 files\)", r.out), r


def test_missing_neighbour_is_warned_about_and_left_out(tmp_path):
    shot = render(tmp_path / "in", frames=range(1, 4))
    full = run(shot, "--frames", "2", "--denoise", "--temporal", 1, "-o", tmp_path / "full.####.exr")
    assert full.code == 0 and "WARNING" not in full.err, full
    os.remove(tmp_path / "in/shot.0003.exr")
    gap = run(shot, "--frames", "2", "--denoise", "--temporal", 1, "-v", "-o", tmp_path / "gap.####.exr")
    assert gap.code == 0 and "--temporal : frame 2 with frames 1\n" in gap.out, gap
    assert "frame 2: --temporal : neighbour frame 3" in gap.err and "does not exist: left out" in gap.err, gap
    assert not np.array_equal(beauty(tmp_path / "full.0002.exr"), beauty(tmp_path / "gap.0002.exr"))
    # frame 2 with only frame 1 is what it would be if frame 3 were never rendered
    shutil.rmtree(tmp_path / "in")
    render(tmp_path / "in", frames=range(1, 3))
    alone = run(shot, "--frames", "2", "--denoise", "--temporal", 1, "-o", tmp_path / "alone.####.exr")
    assert alone.code == 0, alone
    # pixels, not bytes: the re-rendered inputs carry another render time in their metadata
    assert np.array_equal(beauty(tmp_path / "alone.0002.exr"), beauty(tmp_path / "gap.0002.exr"))


def test_neighbour_of_another_resolution_fails_that_frame(tmp_path):
    shot = render(tmp_path / "in", frames=range(1, 3))
    render(tmp_path / "in", frames=[3], res="32x32")
    r = run(shot, "--frames", "1-3", "--denoise", "--temporal", 1, "-o", tmp_path / "o.####.exr")
    assert r.code == 1, r
    assert "frame 2: --temporal : neighbour frame 3" in r.err and "display window" in r.err, r
    assert os.path.exists(tmp_path / "o.0001.exr") and not os.path.exists(tmp_path / "o.0002.exr")


@pytest.mark.parametrize("args, needle", [
    (("--temporal", "2", "--denoise"), "needs a frame sequence"),
    (("--frames", "1", "--temporal", "2", "--median", "3"), "only --denoise works across frames"),
    (("--frames", "1", "--temporal", "2", "--median", "3", "--denoise"), "must be the first command"),
    (("--frames", "1", "--temporal", "-1", "--denoise"), "expected a frame count 0..8"),
    (("--frames", "1", "--temporal", "9", "--denoise"), "expected a frame count 0..8"),
    (("--frames", "1", "--temporal", "1", "--denoise", "--aovs", "auto"), "cannot be combined with --aovs"),
])
def test_bad_temporal_use_is_a_usage_error(tmp_path, args, needle):
    shot = render(tmp_path / "in", frames=[1])
    if "--frames" not in args:
        shot = tmp_path / "in/shot.0001.exr"
    r = run(shot, *args, "-o", tmp_path / ("o.####.exr" if "--frames" in args else "o.exr"))
    assert r.code == 2 and needle in r.err, r
    assert not list(tmp_path.glob("o.*"))


def test_arnold_motionvector_is_refused_with_a_warning(tmp_path):
    rng = np.random.default_rng(3)
    for frame in (1, 2):
        write_image(tmp_path / f"arnold.{frame:04d}.exr", rng.random((8, 10, 5)).astype(np.float32),
                    ["R", "G", "B", "motionvector.R", "motionvector.G"], fmt="float")
    r = run(tmp_path / "arnold.####.exr", "--frames", "1-2", "--denoise", "--temporal", 1, "-v",
            "-o", tmp_path / "o.####.exr")
    assert r.code == 0, r
    assert r.err.count("Arnold's motionvector AOV") == 1 and "is not used as the motion guide" in r.err, r
    assert "motion   <-" not in r.out


def test_compare_over_a_sequence_prints_the_sequence_figures(tmp_path):
    shot = render(tmp_path / "in", scene="shot_static", frames=range(1, 4))
    render(tmp_path / "ref", scene="shot_static", frames=range(1, 4), spp=64, seed=1000, name="ref")
    r = run(shot, "--frames", "1-3", "--denoise", "-o", tmp_path / "o.####.exr", "--compare",
            tmp_path / "ref/ref.####.exr")
    assert r.code == 0, r
    x = np.array([beauty(tmp_path / f"o.{f:04d}.exr") for f in (1, 2, 3)])
    ref = np.array([beauty(tmp_path / f"ref/ref.{f:04d}.exr") for f in (1, 2, 3)])
    dx, dr = np.diff(x, axis=0), np.diff(ref, axis=0)
    expected = (np.mean([rel_mse(a, b) for a, b in zip(x, ref)]),
                (((dx - dr) ** 2) / (dr ** 2 + EPS)).mean(),
                (x.var(axis=0) / (ref.mean(axis=0) ** 2 + EPS)).mean())
    match = re.search(r"compare sequence, 3 frames.*\n  input .*\n  result  mean relMSE (\S+)  temporal error (\S+)"
                      r"  flicker (\S+)", r.out)
    assert match, r
    # the outputs are half floats: the figures of the written files agree to their precision
    np.testing.assert_allclose([float(v) for v in match.groups()], expected, rtol=2e-3)
