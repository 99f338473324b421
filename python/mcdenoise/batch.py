"""mcdenoise.batch: denoise every frame of a sequence with an mcdtool chain,
on a local process pool (the default, no set-up) or a Dask distributed cluster.

A frame is run by mcdtool's own per-frame code (through the compiled module):
the same pattern syntax ('#' = 4 digits, '####' or '@@@@' = one digit each,
'%04d'), guide discovery (testrender and Blender multilayer names, --aov),
output (every input channel and the metadata kept, written to a temp file in
the output's directory and renamed into place) and refusal to replace an
input. The chain is mcdtool's command words: "--object-median 7 --gaussian 3".

    from mcdenoise.batch import denoise_sequence
    summary = denoise_sequence("shot/beauty.####.exr", "1-48",
                               "--object-median 7 --gaussian 3",
                               "clean/beauty.####.exr")

Command line (mcdtool's sequence options, plus where to run):

    python3 -m mcdenoise.batch INPUT [mcdtool commands/options] -o OUTPUT
        --frames LIST [--skip-existing] [--force]
        [--scheduler tcp://HOST:PORT] [--workers N] [--retries N] [--chunk-size N] [--quiet]
"""
import concurrent.futures
import contextlib
import os
import shlex
import sys
import time
import types
from dataclasses import dataclass, field

from . import _mcdenoise

#: How often a frame that raised is tried again before it is reported failed.
DEFAULT_RETRIES = 2


@dataclass
class FrameResult:
    """What happened to one frame."""
    frame: int
    status: str          #: "written", "skipped" or "failed"
    attempts: int = 1    #: runs of the frame (more than 1 after a retry)
    seconds: float = 0.0
    message: str = ""    #: mcdtool's message when the frame failed
    where: str = ""      #: host and process that ran it


@dataclass
class BatchSummary:
    """Every frame's result and the wall time of the whole batch."""
    results: list = field(default_factory=list)
    seconds: float = 0.0

    def frames(self, status):
        """The frames (sorted) whose status is `status`."""
        return sorted(r.frame for r in self.results if r.status == status)

    @property
    def written(self):
        return self.frames("written")

    @property
    def skipped(self):
        return self.frames("skipped")

    @property
    def failed(self):
        return self.frames("failed")

    @property
    def ok(self):
        """True if no frame failed."""
        return not self.failed

    @property
    def frames_per_second(self):
        """Frames done (written or skipped) per second of wall time."""
        done = len(self.written) + len(self.skipped)
        return done / self.seconds if self.seconds > 0 else 0.0

    def report(self):
        """The final summary: counts, rate, and one line per failed frame."""
        lines = [f"mcdenoise.batch: {len(self.results)} frames: {len(self.written)} written, "
                 f"{len(self.skipped)} skipped, {len(self.failed)} failed in {self.seconds:.2f} s "
                 f"({self.frames_per_second:.2f} frames/s)"]
        for r in sorted(self.results, key=lambda r: r.frame):
            if r.status == "failed":
                lines.append(f"mcdenoise.batch: frame {r.frame} failed after {r.attempts} "
                             f"attempt(s): {r.message}")
        return "\n".join(lines)


def run_frames(args, frames, retries=DEFAULT_RETRIES):
    """Runs mcdtool's command line `args` on each of `frames` in this process,
    trying a frame that raises up to `retries` more times. Returns a
    FrameResult per frame; never raises for a frame's failure. This is the
    task a pool process or a Dask worker runs."""
    where = f"{os.uname().nodename}:{os.getpid()}"
    runner = _mcdenoise._FrameRunner(args)  # with --temporal, holds the frames read for the next ones
    results = []
    for frame in frames:
        start = time.perf_counter()
        attempts = 0
        while True:
            attempts += 1
            try:
                status = runner.run(frame)
                results.append(FrameResult(frame, status, attempts, time.perf_counter() - start, "", where))
                break
            except (_mcdenoise.Error, OSError, MemoryError) as error:
                if attempts > retries:
                    results.append(FrameResult(frame, "failed", attempts, time.perf_counter() - start,
                                               str(error), where))
                    break
    return results


def sequence_args(pattern, frames, chain, output_pattern, options=(), skip_existing=False, force=False,
                  threads=0, temporal=0, aovs=None):
    """The mcdtool command line (without the program name) that
    `denoise_sequence` runs: `chain` and `options` are mcdtool words, as one
    string or a list of strings (each split like a shell would); `frames` is
    an mcdtool frame list ("1-48", "1-10x2", "1,3,5") or integers; `aovs`
    is mcdtool's --aovs ("auto" or a list of pass names, as a string or a
    list of strings)."""
    args = [str(pattern)] + _words(chain) + _words(options) + ["-o", str(output_pattern)]
    frames_text = frames if isinstance(frames, str) else ",".join(str(int(f)) for f in frames)
    args += ["--frames", frames_text]
    if skip_existing:
        args.append("--skip-existing")
    if force:
        args.append("--force")
    if threads:
        args += ["--threads", str(threads)]
    if temporal:
        args += ["--temporal", str(temporal)]
    if aovs:
        args += ["--aovs", aovs if isinstance(aovs, str) else ",".join(aovs)]
    return args


def denoise_sequence(pattern, frames, chain, output_pattern, options=(), *, skip_existing=False, force=False,
                     threads=0, temporal=0, aovs=None, client=None, scheduler=None, workers=None,
                     retries=DEFAULT_RETRIES, chunk_size=1, progress=True):
    """Denoises every frame of `pattern` with `chain` into `output_pattern`.

    `chain` and `options` are mcdtool words ("--object-median 7 --gaussian 3";
    options such as "--aov normal=n.####.exr -d half"); `frames` is an mcdtool
    frame list or a sequence of integers. `skip_existing` and `force` are
    mcdtool's --skip-existing and --force; `threads` the library threads per
    frame (0: all cores); `temporal` is mcdtool's --temporal N (--denoise
    with the N frames before and after each frame, read from disk, so every
    task reads the frames its chunk needs and the files equal mcdtool's).
    `aovs` ("auto" or pass names) is mcdtool's --aovs: with a --denoise in
    `chain`, the light passes are denoised with the beauty so they still add
    up to it.

    Runs on `client` (a dask.distributed.Client), else on the Dask scheduler
    at `scheduler` ("tcp://HOST:PORT"), else on a local process pool of
    `workers` processes (default: one per core). One task per `chunk_size`
    frames; a frame that fails is tried `retries` more times, then reported;
    it never stops the others and never leaves a partial file. With
    `progress`, a line per frame goes to stderr. Returns a BatchSummary;
    raises UsageError (before any work) for a malformed chain or pattern.
    """
    args = sequence_args(pattern, frames, chain, output_pattern, options, skip_existing, force, threads,
                         temporal, aovs)
    return run_batch(args, client=client, scheduler=scheduler, workers=workers, retries=retries,
                     chunk_size=chunk_size, progress=progress)


def run_batch(args, *, client=None, scheduler=None, workers=None, retries=DEFAULT_RETRIES, chunk_size=1,
              progress=True):
    """Runs mcdtool's sequence command line `args` (which must hold a frame
    pattern and --frames) frame by frame on a pool or Dask; see
    `denoise_sequence` for the rest. Returns a BatchSummary."""
    described = _mcdenoise._describe_command_line(args)
    if not described["frames"]:
        raise _mcdenoise.UsageError(f"'{described['input']}' is not a frame sequence: give a frame pattern "
                                    "(#, @ or %04d) and --frames")
    if chunk_size < 1:
        raise _mcdenoise.UsageError(f"chunk_size must be >= 1, got {chunk_size}")
    if retries < 0:
        raise _mcdenoise.UsageError(f"retries must be >= 0, got {retries}")
    frames = _mcdenoise.frame_list(described["frames"])
    chunks = [frames[i:i + chunk_size] for i in range(0, len(frames), chunk_size)]
    summary = BatchSummary()
    start = time.perf_counter()
    report = _Progress(len(frames), progress)
    if client is None and scheduler:
        from distributed import Client
        with Client(scheduler) as own_client:
            _run_on_dask(own_client, args, chunks, retries, summary, report)
    elif client is not None:
        _run_on_dask(client, args, chunks, retries, summary, report)
    else:
        _run_on_pool(workers or os.cpu_count() or 1, args, chunks, retries, summary, report)
    summary.seconds = time.perf_counter() - start
    if progress:
        print(summary.report(), file=sys.stderr, flush=True)
    return summary


class _Progress:
    """One stderr line per finished frame: 'frame 7 written (3/48)'."""

    def __init__(self, total, enabled):
        self.total = total
        self.done = 0
        self.enabled = enabled

    def add(self, result):
        self.done += 1
        if self.enabled:
            detail = f": {result.message}" if result.status == "failed" else ""
            print(f"mcdenoise.batch: frame {result.frame} {result.status} ({self.done}/{self.total}, "
                  f"{result.seconds:.2f} s, {result.where}){detail}", file=sys.stderr, flush=True)


def _collect(summary, report, results):
    for result in results:
        summary.results.append(result)
        report.add(result)


def _failed_chunk(chunk, error):
    """Results for a chunk whose task itself was lost (e.g. its workers died)."""
    message = f"{type(error).__name__}: {error}"
    return [FrameResult(frame, "failed", 1, 0.0, message, "") for frame in chunk]


@contextlib.contextmanager
def _without_main_script():
    """Hides the caller's __main__ module while pool processes start.

    A 'forkserver' (or 'spawn') process re-runs the parent's main script
    (as __mp_main__) before it takes a task, so a script that calls
    denoise_sequence at top level without `if __name__ == "__main__":`
    would call it again in every pool process, which multiprocessing
    refuses: every frame failed with BrokenProcessPool. The tasks are
    mcdenoise.batch.run_frames with plain arguments and never need the
    caller's script, so the processes are started as if there were none
    (an empty __main__): nothing is re-run, and the guard is unnecessary.
    """
    saved = sys.modules["__main__"]
    sys.modules["__main__"] = types.ModuleType("__main__")
    try:
        yield
    finally:
        sys.modules["__main__"] = saved


def _run_on_pool(workers, args, chunks, retries, summary, report):
    # Imported here: the Blender add-on imports this module for run_frames,
    # and importing multiprocessing inside Debian's Blender 3.4 makes Blender
    # crash when it exits.
    import multiprocessing
    # forkserver rather than fork: the pool's processes start from a clean
    # single-threaded server instead of a copy of a parent that may hold
    # threads (OpenImageIO's pool, the caller's), whose locks a fork could
    # copy held. The pool starts its processes in submit(), inside the
    # block that hides the main script.
    context = multiprocessing.get_context("forkserver")
    with concurrent.futures.ProcessPoolExecutor(max_workers=workers, mp_context=context) as pool:
        with _without_main_script():
            futures = {pool.submit(run_frames, args, chunk, retries): chunk for chunk in chunks}
        for future in concurrent.futures.as_completed(futures):
            try:
                results = future.result()
            except Exception as error:  # the pool process died: report, go on
                results = _failed_chunk(futures[future], error)
            _collect(summary, report, results)


def _run_on_dask(client, args, chunks, retries, summary, report):
    from distributed import as_completed
    futures = {client.submit(run_frames, args, chunk, retries, pure=False): tuple(chunk) for chunk in chunks}
    for future in as_completed(list(futures)):
        try:
            results = future.result()
        except Exception as error:  # e.g. KilledWorker: the task's workers kept dying
            results = _failed_chunk(futures[future], error)
        _collect(summary, report, results)


def _words(words):
    """mcdtool words from one string or a list of strings."""
    if isinstance(words, str):
        return shlex.split(words)
    return [word for item in words for word in shlex.split(str(item))]


#: The batch's own options: name -> (attribute, converter); the rest of the
#: command line goes to mcdtool's parser unchanged.
_BATCH_OPTIONS = {
    "--scheduler": ("scheduler", str),
    "--workers": ("workers", int),
    "--retries": ("retries", int),
    "--chunk-size": ("chunk_size", int),
}

_USAGE = """usage: python3 -m mcdenoise.batch INPUT [mcdtool commands/options] -o OUTPUT --frames LIST
       [--skip-existing] [--force] [--scheduler tcp://HOST:PORT] [--workers N]
       [--retries N] [--chunk-size N] [--quiet]

Runs mcdtool's command line frame by frame, in parallel: on a local process
pool (--workers N processes, default one per core) or on the Dask cluster
whose scheduler is at --scheduler. A frame that fails is tried --retries more
times (default 2), then reported; the others go on. --chunk-size frames per
task (default 1). Commands, patterns, --frames, --skip-existing, --force and
every other option are mcdtool's (see `mcdtool --help`). Exit status: 0 when
every frame was written or skipped, 1 when any failed, 2 for a bad command line.
"""


def main(argv=None):
    """The command line; returns the exit status."""
    argv = list(sys.argv[1:] if argv is None else argv)
    if not argv or argv[0] in ("-h", "--help"):
        print(_USAGE, end="", file=sys.stdout if argv else sys.stderr)
        return 0 if argv else 2
    settings = {"scheduler": None, "workers": None, "retries": DEFAULT_RETRIES, "chunk_size": 1}
    progress = True
    args = []
    i = 0
    try:
        while i < len(argv):
            word = argv[i]
            if word == "--quiet":
                progress = False
            elif word in _BATCH_OPTIONS:
                name, convert = _BATCH_OPTIONS[word]
                if i + 1 >= len(argv):
                    raise _mcdenoise.UsageError(f"{word} : missing argument")
                try:
                    settings[name] = convert(argv[i + 1])
                except ValueError:
                    raise _mcdenoise.UsageError(f"{word} : expected a number, got '{argv[i + 1]}'") from None
                i += 1
            else:
                args.append(word)
            i += 1
        if settings["workers"] is not None and settings["workers"] < 1:
            raise _mcdenoise.UsageError(f"--workers : expected a count >= 1, got {settings['workers']}")
        summary = run_batch(args, progress=progress, **settings)
    except _mcdenoise.UsageError as error:
        print(f"mcdenoise.batch ERROR: {error}", file=sys.stderr)
        return 2
    except OSError as error:  # e.g. no scheduler at --scheduler
        print(f"mcdenoise.batch ERROR: {error}", file=sys.stderr)
        return 1
    if not progress and not summary.ok:
        print(summary.report(), file=sys.stderr)
    return 0 if summary.ok else 1


if __name__ == "__main__":
    # Run the package's copy of this module, so the tasks sent to pool
    # processes and Dask workers name mcdenoise.batch.run_frames, which
    # they can import, rather than __main__.run_frames.
    from mcdenoise.batch import main as package_main
    sys.exit(package_main())
