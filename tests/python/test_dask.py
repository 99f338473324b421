"""mcdenoise.batch on a real Dask cluster (a dask-scheduler and two
dask-worker processes on 127.0.0.1, started and torn down by the
dask_cluster fixture): the same files as the local pool, through a Client and
through --scheduler, and no frame lost when a worker is killed mid-run."""
import os
import signal
import subprocess
import sys
import threading
import time

from mcdenoise.batch import denoise_sequence
from conftest import CHAIN, assert_same_file_contents, frame_file, mcdtool, render_sequence

#: A chain slow enough (about half a second a frame on one thread at
#: 160x160) that a worker can be killed while it holds a frame.
SLOW_CHAIN = "--median 11 --gaussian 5 --threads 1"


def test_dask_cluster_equals_local_pool(sequence, dask_cluster, tmp_path):
    local = tmp_path / "local" / "clean.####.exr"
    local.parent.mkdir()
    assert denoise_sequence(sequence, "1-4", CHAIN, local, workers=2, progress=False).ok

    on_client = tmp_path / "client" / "clean.####.exr"
    on_client.parent.mkdir()
    summary = denoise_sequence(sequence, "1-4", CHAIN, on_client, client=dask_cluster.client, progress=False)
    assert summary.ok and summary.written == [1, 2, 3, 4]

    on_scheduler = tmp_path / "scheduler" / "clean.####.exr"
    on_scheduler.parent.mkdir()
    r = subprocess.run([sys.executable, "-m", "mcdenoise.batch", str(sequence), "--frames", "1-4", *CHAIN.split(),
                        "-o", str(on_scheduler), "--scheduler", dask_cluster.address, "--chunk-size", "2"],
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    assert "4 frames: 4 written, 0 skipped, 0 failed" in r.stderr

    worker_pids = set(dask_cluster.worker_pids().values())
    assert {int(result.where.rsplit(":", 1)[1]) for result in summary.results} <= worker_pids
    for frame in range(1, 5):
        assert_same_file_contents(frame_file(on_client, frame), frame_file(local, frame))
        assert_same_file_contents(frame_file(on_scheduler, frame), frame_file(local, frame))
    for directory in (on_client.parent, on_scheduler.parent):
        assert sorted(os.listdir(directory)) == [f"clean.{f:04d}.exr" for f in range(1, 5)]


def test_dask_worker_killed_mid_run_loses_no_frame(dask_cluster, tmp_path):
    """Kill one of the two workers once the first frame is written: the
    scheduler hands its frames to the other, and every frame is written,
    whole and correct (the dead worker can leave only a hidden temp file)."""
    frames = range(1, 9)
    shot = render_sequence(tmp_path / "shot", frames, res="160x160", spp=2)
    out_dir = tmp_path / "clean"
    out_dir.mkdir()
    out = out_dir / "clean.####.exr"
    outcome = {}

    def run():
        outcome["summary"] = denoise_sequence(shot, "1-8", SLOW_CHAIN, out, client=dask_cluster.client,
                                              progress=False)

    batch = threading.Thread(target=run)
    batch.start()
    deadline = time.monotonic() + 300
    while not any(name.startswith("clean.") for name in os.listdir(out_dir)):
        assert batch.is_alive() and time.monotonic() < deadline, "no frame was written"
        time.sleep(0.02)
    victim = dask_cluster.processes["worker0"]
    os.kill(victim.pid, signal.SIGKILL)
    written_at_kill = [name for name in os.listdir(out_dir) if name.startswith("clean.")]
    assert len(written_at_kill) < len(frames) - 2, "the run was nearly over when the worker was killed"
    victim.wait(timeout=30)
    batch.join(timeout=600)
    assert not batch.is_alive()

    summary = outcome["summary"]
    assert summary.ok and summary.written == list(frames), summary.report()
    assert len(summary.results) == len(frames)
    assert len(dask_cluster.client.scheduler_info()["workers"]) == 1

    expected = tmp_path / "mcdtool" / "clean.####.exr"
    expected.parent.mkdir()
    r = mcdtool(shot, "--frames", "1-8", *SLOW_CHAIN.split(), "-o", expected)
    assert r.returncode == 0, r.stderr
    for frame in frames:
        assert_same_file_contents(frame_file(out, frame), frame_file(expected, frame))
    finals = sorted(name for name in os.listdir(out_dir) if not name.startswith("."))
    assert finals == [f"clean.{f:04d}.exr" for f in frames]


def test_dask_temporal_equals_mcdtool(dask_cluster, tmp_path):
    """--temporal on Dask: each task reads its chunk's neighbours from disk;
    the files equal one mcdtool run's."""
    truck = render_sequence(tmp_path / "in", range(1, 5), res="48x40", spp=8, scene="shot_truck")
    r = mcdtool(truck, "--frames", "1-4", "--denoise", "--temporal", 1, "-o", tmp_path / "one/o.####.exr")
    assert r.returncode == 0, r.stderr
    out = tmp_path / "dask" / "o.####.exr"
    out.parent.mkdir()
    summary = denoise_sequence(truck, "1-4", "--denoise", out, temporal=1, client=dask_cluster.client,
                               chunk_size=2, progress=False)
    assert summary.ok and summary.written == [1, 2, 3, 4], summary.report()
    for frame in range(1, 5):
        assert_same_file_contents(frame_file(tmp_path / "one/o.####.exr", frame), frame_file(out, frame))
