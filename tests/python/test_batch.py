"""mcdenoise.batch on the local process pool: the files equal mcdtool's
sequence output; --skip-existing, failed frames, bad command lines and
argument values (raised once, before any frame), inputs that must never be
replaced; an unreachable --scheduler; the docs' example run verbatim as a
plain script and from stdin."""
import os
import shutil
import socket
import subprocess
import sys

import numpy as np
import OpenImageIO as oiio
import pytest

import mcdenoise
from mcdenoise.batch import denoise_sequence
from conftest import CHAIN, assert_same_file_contents, frame_file, mcdtool, read_pixels



def batch_cli(*args, cwd=None):
    """Runs `python3 -m mcdenoise.batch ARGS`."""
    return subprocess.run([sys.executable, "-m", "mcdenoise.batch"] + [str(a) for a in args], cwd=cwd,
                          capture_output=True, text=True, timeout=300)


def test_local_pool_equals_mcdtool(sequence, tmp_path):
    """Every frame written by the pool is bit-identical (pixels, channels,
    types, metadata) to what `mcdtool --frames` writes."""
    expected = tmp_path / "mcdtool" / "clean.####.exr"
    expected.parent.mkdir()
    r = mcdtool(sequence, "--frames", "1-4", *CHAIN.split(), "-o", expected)
    assert r.returncode == 0, r.stderr

    out = tmp_path / "batch" / "clean.####.exr"
    out.parent.mkdir()
    summary = denoise_sequence(sequence, "1-4", CHAIN, out, workers=2, progress=False)
    assert summary.ok and summary.written == [1, 2, 3, 4] and summary.skipped == []
    assert summary.frames_per_second > 0
    assert sorted(os.listdir(out.parent)) == [f"clean.{f:04d}.exr" for f in range(1, 5)]
    for frame in range(1, 5):
        assert_same_file_contents(frame_file(out, frame), frame_file(expected, frame))
        _, spec = read_pixels(frame_file(out, frame))
        _, input_spec = read_pixels(frame_file(sequence, frame))
        assert spec.channelnames == input_spec.channelnames
    frame1, _ = read_pixels(frame_file(out, 1))
    frame2, _ = read_pixels(frame_file(out, 2))
    assert frame1.tobytes() != frame2.tobytes(), "frames of different seeds came out the same"


def test_chain_as_list_and_frames_as_integers(sequence, tmp_path):
    out = tmp_path / "c.%04d.exr"
    summary = denoise_sequence(sequence, [3, 1], ["--object-median 7", "--gaussian", "3"], out, workers=1,
                               chunk_size=2, progress=False)
    assert summary.written == [1, 3]
    assert_same_file_contents(tmp_path / "c.0001.exr",
                              _mcdtool_frame(sequence, 1, tmp_path / "ref.####.exr"))


def _mcdtool_frame(sequence, frame, out):
    r = mcdtool(sequence, "--frames", str(frame), *CHAIN.split(), "-o", out)
    assert r.returncode == 0, r.stderr
    return frame_file(out, frame)


def test_cli_progress_summary_and_skip_existing(sequence, tmp_path):
    out = tmp_path / "clean.####.exr"
    r = batch_cli(sequence, "--frames", "1-3", *CHAIN.split(), "-o", out, "--workers", "2")
    assert r.returncode == 0, r.stderr
    assert r.stderr.count(" written (") == 3
    assert "3 frames: 3 written, 0 skipped, 0 failed" in r.stderr
    before = {f: os.stat(frame_file(out, f)).st_mtime_ns for f in (1, 2, 3)}
    r = batch_cli(sequence, "--frames", "1-4", *CHAIN.split(), "-o", out, "--skip-existing", "--workers", "2")
    assert r.returncode == 0, r.stderr
    assert "4 frames: 1 written, 3 skipped, 0 failed" in r.stderr
    assert {f: os.stat(frame_file(out, f)).st_mtime_ns for f in (1, 2, 3)} == before


def test_failed_frame_is_retried_reported_and_others_written(sequence, tmp_path):
    """Frame 9 does not exist: it fails after 1 + retries attempts with
    mcdtool's message; the others are written; no file for frame 9."""
    out = tmp_path / "clean.####.exr"
    r = batch_cli(sequence, "--frames", "1,9,2", *CHAIN.split(), "-o", out, "--retries", "1", "--workers", "2")
    assert r.returncode == 1, r.stderr
    assert "3 frames: 2 written, 0 skipped, 1 failed" in r.stderr
    assert f"frame 9 failed after 2 attempt(s): input : cannot read '{frame_file(sequence, 9)}'" in r.stderr
    assert sorted(os.listdir(tmp_path)) == ["clean.0001.exr", "clean.0002.exr"]


def test_bad_command_lines_fail_before_any_work(sequence, tmp_path):
    out = tmp_path / "clean.####.exr"
    with pytest.raises(mcdenoise.UsageError, match="unknown command '--medain'"):
        denoise_sequence(sequence, "1-2", "--medain 3", out, progress=False)
    with pytest.raises(mcdenoise.UsageError, match="bad"):
        denoise_sequence(sequence, "1-bad", CHAIN, out, progress=False)
    with pytest.raises(mcdenoise.UsageError, match="no frame pattern"):
        denoise_sequence(sequence, "1-2", CHAIN, tmp_path / "clean.exr", progress=False)
    r = batch_cli(sequence, "--frames", "1-2", "--median", "-o", out)
    assert r.returncode == 2 and "mcdenoise.batch ERROR: --median : missing argument" in r.stderr, r.stderr
    r = batch_cli(frame_file(sequence, 1), "--median", "3", "-o", tmp_path / "one.exr")
    assert r.returncode == 2 and "not a frame sequence" in r.stderr, r.stderr
    r = batch_cli(sequence, "--frames", "1-2", "--median", "3", "-o", out, "--workers", "zero")
    assert r.returncode == 2 and "--workers : expected a number" in r.stderr, r.stderr
    assert os.listdir(tmp_path) == []


def test_input_is_never_replaced(sequence, tmp_path):
    """An output pattern naming the inputs fails every frame (mcdtool's
    check) and leaves the inputs as they were."""
    before = {f: open(frame_file(sequence, f), "rb").read() for f in (1, 2)}
    summary = denoise_sequence(sequence, "1-2", CHAIN, sequence, retries=0, workers=1, progress=False)
    assert summary.failed == [1, 2]
    assert all("input" in r.message for r in summary.results)
    assert {f: open(frame_file(sequence, f), "rb").read() for f in (1, 2)} == before


def test_unreachable_scheduler_is_an_error(sequence, tmp_path):
    """--scheduler with nothing listening: one error line naming the
    address, exit 1, nothing written."""
    with socket.socket() as probe:  # a port that was free a moment ago
        probe.bind(("127.0.0.1", 0))
        port = probe.getsockname()[1]
    env = dict(os.environ, DASK_DISTRIBUTED__COMM__TIMEOUTS__CONNECT="2s")
    r = subprocess.run([sys.executable, "-m", "mcdenoise.batch", str(sequence), "--frames", "1-2", *CHAIN.split(),
                        "-o", str(tmp_path / "clean.####.exr"), "--scheduler", f"tcp://127.0.0.1:{port}"],
                       capture_output=True, text=True, timeout=120, env=env)
    assert r.returncode == 1, r.stderr
    assert r.stderr.startswith("mcdenoise.batch ERROR: ") and f"tcp://127.0.0.1:{port}" in r.stderr, r.stderr
    assert os.listdir(tmp_path) == []


def test_usage_errors_raise_once_before_any_frame(sequence, tmp_path):
    """Argument values (a size, --beauty channels the first frame lacks) are
    checked before any frame runs: UsageError, no retries, nothing written."""
    out = tmp_path / "clean.####.exr"
    with pytest.raises(mcdenoise.UsageError, match="SIZE must be odd"):
        denoise_sequence(sequence, "1-4", "--median 4", out, progress=False)
    with pytest.raises(mcdenoise.UsageError, match="no channel or layer 'X'"):
        denoise_sequence(sequence, "1-4", CHAIN, out, options="--beauty X,Y,Z", progress=False)
    r = batch_cli(sequence, "--frames", "1-4", "--median", "4", "-o", out)
    assert r.returncode == 2 and r.stderr.count("ERROR") == 1 and "odd" in r.stderr, r.stderr
    assert os.listdir(tmp_path) == []


def docs_batch_example():
    """The denoise_sequence example of docs/python.md, verbatim."""
    docs = open(os.path.join(os.path.dirname(__file__), "..", "..", "docs", "python.md")).read()
    blocks = [block.split("```")[0] for block in docs.split("```python\n")[1:]]
    return next(block for block in blocks if "denoise_sequence(" in block)


def write_docs_example_frames(directory):
    """shot/beauty.0001-0048.exr (beauty and object ids) and
    shot/normal.####.exr (N.X, N.Y, N.Z): the files the docs example names."""
    shot = directory / "shot"
    shot.mkdir()
    rng = np.random.default_rng(18)
    for frame in range(1, 49):
        ids = np.zeros((16, 16, 1), np.float32)
        ids[:, 8:] = 1.0
        beauty = np.concatenate([0.5 + 0.1 * rng.standard_normal((16, 16, 3)).astype(np.float32), ids], axis=2)
        normal = np.zeros((16, 16, 3), np.float32)
        normal[..., 2] = 1.0
        for name, pixels, channels in (("beauty", beauty, ("R", "G", "B", "id")),
                                       ("normal", normal, ("N.X", "N.Y", "N.Z"))):
            spec = oiio.ImageSpec(16, 16, len(channels), "half")
            spec.channelnames = channels
            buf = oiio.ImageBuf(spec)
            buf.set_pixels(oiio.ROI(), pixels)
            assert buf.write(str(shot / f"{name}.{frame:04d}.exr")), oiio.geterror()


def test_docs_example_runs_as_a_plain_script_and_from_stdin(tmp_path):
    """No `if __name__ == "__main__":` guard: the pool does not re-run the
    caller's script. The example's output folder 'clean' does not exist."""
    write_docs_example_frames(tmp_path)
    script = tmp_path / "denoise_shot.py"
    script.write_text(docs_batch_example())
    for how in ("script", "stdin"):
        command = [sys.executable, str(script)] if how == "script" else [sys.executable, "-"]
        r = subprocess.run(command, cwd=tmp_path, input=script.read_text() if how == "stdin" else None,
                           capture_output=True, text=True, timeout=600)
        assert r.returncode == 0, (how, r.stderr)
        assert "BrokenProcessPool" not in r.stderr and "48 written, 0 skipped, 0 failed" in r.stderr, (how, r.stderr)
        assert sorted(os.listdir(tmp_path / "clean")) == [f"beauty.{f:04d}.exr" for f in range(1, 49)]
        shutil.rmtree(tmp_path / "clean")
