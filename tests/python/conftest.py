"""Shared fixtures for the Python tests: the tools' paths, a testrender frame
sequence, a runner for mcdtool, and a Dask cluster (a scheduler and two
workers on 127.0.0.1) started for the tests that ask for one."""
import json
import os
import signal
import subprocess
import sys
import time

import numpy as np
import OpenImageIO as oiio
import pytest

MCDTOOL = os.environ.get("MCDTOOL", "mcdtool")
TESTRENDER = os.environ.get("TESTRENDER", "testrender")
#: The report's best chain, as mcdtool words.
CHAIN = "--object-median 7 --gaussian 3"
#: Seconds a cluster gets to come up before the test fails.
CLUSTER_START_TIMEOUT = 60


def mcdtool(*args, cwd=None):
    """Runs mcdtool with `args`; returns the completed process."""
    return subprocess.run([MCDTOOL] + [str(a) for a in args], cwd=cwd, capture_output=True, text=True,
                          timeout=300)


def render_sequence(directory, frames, res="64x64", spp=4, scene="cornell", passes=False):
    """testrender frames 'shot.####.exr' in `directory`, seed = frame; with
    `passes`, the light passes too."""
    directory.mkdir(parents=True, exist_ok=True)
    for frame in frames:
        subprocess.run([TESTRENDER, "--scene", scene, "--res", res, "--spp", str(spp), "--seed", str(frame),
                        "--threads", "1", "-q", "-o", str(directory / f"shot.{frame:04d}.exr")]
                       + (["--passes"] if passes else []), check=True, timeout=300)
    return directory / "shot.####.exr"


def frame_file(pattern, frame):
    """The file of `frame` in a 'NAME.####.EXT' pattern."""
    return str(pattern).replace("####", f"{frame:04d}")


def read_pixels(path):
    """(float pixels H x W x C, native spec) of `path`."""
    buf = oiio.ImageBuf(str(path))
    assert buf.read(force=True), buf.geterror()
    return buf.get_pixels(oiio.FLOAT), buf.nativespec()


def assert_same_file_contents(a, b):
    """`a` and `b` hold bit-identical pixels, the same channels and types."""
    pa, sa = read_pixels(a)
    pb, sb = read_pixels(b)
    assert sa.channelnames == sb.channelnames
    assert [str(t) for t in sa.channelformats] == [str(t) for t in sb.channelformats]
    assert pa.tobytes() == pb.tobytes(), f"{a} and {b} differ"


@pytest.fixture(scope="session")
def sequence(tmp_path_factory):
    """Four small testrender frames (1-4) with different seeds."""
    return render_sequence(tmp_path_factory.mktemp("shot"), range(1, 5))


class Cluster:
    """A dask-scheduler and dask-worker processes on 127.0.0.1."""

    def __init__(self, directory):
        directory.mkdir(parents=True, exist_ok=True)
        self.directory = directory
        self.scheduler_file = directory / "scheduler.json"
        self.processes = {}
        self.client = None
        self.address = None

    def launch(self, workers=2):
        """Starts the scheduler and `workers` workers, and connects."""
        self.start("scheduler", [sys.executable, "-m", "distributed.cli.dask_scheduler", "--host", "127.0.0.1",
                                 "--port", "0", "--no-dashboard", "--scheduler-file", str(self.scheduler_file)])
        self.address = self.wait_for_scheduler()
        for i in range(workers):
            # No nanny: a killed worker stays dead, as when a machine is lost.
            self.start(f"worker{i}", [sys.executable, "-m", "distributed.cli.dask_worker", self.address,
                                      "--host", "127.0.0.1", "--nthreads", "1", "--no-nanny", "--no-dashboard",
                                      "--name", f"worker{i}", "--local-directory", str(self.directory / f"w{i}")])
        self.client = self.connect(workers)

    def start(self, name, command):
        log = open(self.directory / f"{name}.log", "w")
        self.processes[name] = subprocess.Popen(command, stdout=log, stderr=subprocess.STDOUT,
                                                start_new_session=True)

    def wait_for_scheduler(self):
        deadline = time.monotonic() + CLUSTER_START_TIMEOUT
        while time.monotonic() < deadline:
            if self.scheduler_file.exists():
                try:
                    return json.loads(self.scheduler_file.read_text())["address"]
                except (ValueError, KeyError):
                    pass
            time.sleep(0.1)
        raise RuntimeError(f"dask scheduler did not start: {self.log('scheduler')}")

    def connect(self, workers):
        from distributed import Client
        client = Client(self.address, timeout=CLUSTER_START_TIMEOUT)
        client.wait_for_workers(workers, timeout=CLUSTER_START_TIMEOUT)
        return client

    def worker_pids(self):
        """{worker address: pid} as the scheduler knows them."""
        info = self.client.scheduler_info()["workers"]
        pids = self.client.run(os.getpid)
        return {address: pids[address] for address in info}

    def log(self, name):
        return (self.directory / f"{name}.log").read_text()

    def close(self):
        try:
            if self.client is not None:
                self.client.close()
        finally:
            for process in self.processes.values():
                if process.poll() is None:
                    os.killpg(process.pid, signal.SIGTERM)
            for process in self.processes.values():
                try:
                    process.wait(timeout=20)
                except subprocess.TimeoutExpired:
                    os.killpg(process.pid, signal.SIGKILL)
                    process.wait()


@pytest.fixture
def dask_cluster(tmp_path):
    """A running cluster of two single-thread workers, torn down after."""
    cluster = Cluster(tmp_path / "cluster")
    try:
        cluster.launch()
        yield cluster
    finally:
        cluster.close()


def random_image(shape, seed):
    """A float32 image with a few non-finite and negative values."""
    rng = np.random.default_rng(seed)
    return rng.normal(0.5, 0.3, shape).astype(np.float32)
