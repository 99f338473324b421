"""What a new user trips on: argument values checked before any input is
read (exit 2, once per run), output folders made, diagnostics' paths checked
before the work, file modes kept and write-protected files refused,
progress on a terminal and a summary for sequences, and suspect input
(guides of another resolution, constant ids, 8-bit display-referred
pictures, formats without channel names, HDR PSNR) refused or warned about;
--version names the tool's, the library's and OpenImageIO's versions."""
import os
import pty
import re
import stat
import subprocess
import time

import numpy as np
import OpenImageIO as oiio

from conftest import MCDTOOL, noisy_scene, read_image, run, write_image

BEAUTY = ["R", "G", "B"]


def error_lines(result):
    """The 'mcdtool ERROR:' lines of a run's stderr."""
    return [line for line in result.err.splitlines() if line.startswith("mcdtool ERROR:")]


def test_version_names_the_tool_the_library_and_openimageio():
    header = os.path.join(os.path.dirname(__file__), "..", "..", "imageops", "include", "mcdenoise", "version.h")
    with open(header, encoding="utf-8") as f:
        version = re.search(r'#define MCDENOISE_VERSION_STRING "([0-9.]+)"', f.read()).group(1)
    r = run("--version")
    assert r.code == 0 and r.err == "", r
    assert r.out == f"mcdtool {version} (libmcdenoise {version}, OpenImageIO {oiio.VERSION_STRING})\n", r


def write_sequence(directory, frames, names=BEAUTY):
    """beauty.NNNN.exr frames of noisy_scene in `directory`."""
    for frame in frames:
        beauty, *_ = noisy_scene(seed=frame)
        write_image(directory / f"beauty.{frame:04d}.exr", beauty, names)
    return "beauty.####.exr"


def test_bad_values_fail_before_reading(tmp_path):
    """Sizes, ranges and factors are checked when parsing, the rules between
    a command's values (FOCUS below LEVELS) by the library before reading:
    the input (which does not exist) is never read; exit 2."""
    for args, needle in (
        (["--median", 4], "SIZE must be odd"),
        (["--gaussian", 257], "SIZE out of range (odd window side, 1..255), got 257"),
        (["--atrous", 11], "ITERATIONS"),
        (["--nlmeans", 200], "SEARCH_RADIUS"),
        (["--clamp-fireflies", 0.5], "FACTOR"),
        (["--dof", 0, 0], "LEVELS"),
        (["--dof", 10, 12], "0 <= focus_level < levels"),
        (["--dof-range", 200, 0, 1, 9], "window side of 399"),
    ):
        r = run(tmp_path / "missing.exr", *args, "-o", tmp_path / "out.exr")
        assert r.code == 2 and len(error_lines(r)) == 1 and needle in r.err, r
        assert "cannot read" not in r.err, r


def test_bad_value_fails_once_for_a_sequence(tmp_path):
    pattern = write_sequence(tmp_path, (1, 2, 3))
    r = run(pattern, "--frames", "1-3", "--median", 4, "-o", "clean.####.exr", cwd=tmp_path)
    assert r.code == 2 and len(error_lines(r)) == 1 and "odd" in r.err, r
    assert not any(name.startswith("clean") for name in os.listdir(tmp_path))


def test_unknown_beauty_channels_fail_once_before_filtering(tmp_path):
    """--beauty is checked against the first frame's header: one error,
    exit 2, no frame filtered."""
    pattern = write_sequence(tmp_path, (1, 2, 3))
    r = run(pattern, "--frames", "1-3", "--beauty", "X,Y,Z", "--median", 3, "-o", "clean.####.exr", "-v",
            cwd=tmp_path)
    assert r.code == 2 and len(error_lines(r)) == 1 and "'X'" in r.err and "R,G,B" in r.err, r
    assert "--median" not in r.out, r


def test_display_is_checked_before_reading(tmp_path):
    r = run(tmp_path / "missing.exr", "--median", 3, "--preview", tmp_path / "p.png", "--display", "sRGB")
    assert r.code == 2 and "--display" in r.err and "OCIO config" in r.err, r
    (tmp_path / "bad.ocio").write_text("not a config")
    r = run(tmp_path / "missing.exr", "--median", 3, "--preview", tmp_path / "p.png", "--ocio-config",
            tmp_path / "bad.ocio")
    assert r.code == 2 and "--ocio-config" in r.err, r


def test_missing_output_folder_is_made(tmp_path):
    """As renderers do; the error for a folder that cannot be made names
    the output, never the temp file."""
    pattern = write_sequence(tmp_path, (1, 2))
    r = run(pattern, "--frames", "1-2", "--median", 3, "-o", "new/deeper/clean.####.exr", cwd=tmp_path)
    assert r.code == 0, r
    assert sorted(os.listdir(tmp_path / "new" / "deeper")) == ["clean.0001.exr", "clean.0002.exr"]
    (tmp_path / "afile").write_text("a file, not a folder")
    r = run(pattern, "--frames", "1-2", "--median", 3, "-o", "afile/clean.####.exr", cwd=tmp_path)
    assert r.code == 1 and "afile" in r.err and ".mcdtool-" not in r.err, r


def test_missing_compare_reference_fails_before_the_work(tmp_path):
    beauty, *_ = noisy_scene()
    write_image(tmp_path / "in.exr", beauty, BEAUTY)
    r = run(tmp_path / "in.exr", "--median", 3, "-o", tmp_path / "out.exr", "--compare",
            tmp_path / "missing.exr", "-v")
    assert r.code == 1 and "missing.exr" in r.err, r
    assert "--median 3" not in r.out, r  # the filter never ran


def test_preview_into_a_missing_folder_keeps_the_result(tmp_path):
    beauty, *_ = noisy_scene()
    write_image(tmp_path / "in.exr", beauty, BEAUTY)
    r = run(tmp_path / "in.exr", "--median", 3, "-o", tmp_path / "out.exr", "--preview",
            tmp_path / "nodir" / "p.png")
    assert r.code == 0, r
    assert (tmp_path / "out.exr").exists() and (tmp_path / "nodir" / "p.png").exists()


def test_write_protected_output_needs_force(tmp_path):
    beauty, *_ = noisy_scene()
    write_image(tmp_path / "in.exr", beauty, BEAUTY)
    out = tmp_path / "out.exr"
    out.write_bytes(b"protected")
    out.chmod(0o444)
    r = run(tmp_path / "in.exr", "--median", 3, "-o", out)
    assert r.code == 1 and "write-protected" in r.err and "--force" in r.err, r
    assert out.read_bytes() == b"protected"
    r = run(tmp_path / "in.exr", "--median", 3, "-o", out, "--force")
    assert r.code == 0, r
    assert out.read_bytes() != b"protected" and stat.S_IMODE(out.stat().st_mode) == 0o444


def test_replaced_file_keeps_its_mode(tmp_path):
    beauty, *_ = noisy_scene()
    write_image(tmp_path / "in.exr", beauty, BEAUTY)
    out = tmp_path / "out.exr"
    out.write_bytes(b"old")
    out.chmod(0o664)
    r = run(tmp_path / "in.exr", "--median", 3, "-o", out)
    assert r.code == 0, r
    assert out.read_bytes() != b"old" and stat.S_IMODE(out.stat().st_mode) == 0o664


def run_on_terminal(args, cwd):
    """Runs mcdtool with stderr on a pseudo-terminal; (exit code, what the
    terminal showed)."""
    master, slave = pty.openpty()
    proc = subprocess.Popen([MCDTOOL] + [str(a) for a in args], cwd=cwd, stdout=subprocess.DEVNULL,
                            stderr=slave)
    os.close(slave)
    shown = b""
    while True:
        try:
            chunk = os.read(master, 65536)
        except OSError:  # the terminal closed: the process ended
            break
        if not chunk:
            break
        shown += chunk
    os.close(master)
    return proc.wait(timeout=300), shown.decode(errors="replace")


def slow_frame(tmp_path, seconds=4.0):
    """A frame whose --nlmeans 24 takes about `seconds`: a 256 x 128 trial
    run is timed and the frame scaled from it (at most 1024 x 512, about 4 s
    on 2 cores), so a sanitizer build is not given a frame 20x too slow."""
    rng = np.random.default_rng(3)
    write_image(tmp_path / "big.exr", rng.random((128, 256, 3), np.float32), BEAUTY)
    args = ["big.exr", "--nlmeans", 24, "-o", "clean.exr"]
    start = time.monotonic()
    assert run(*args, cwd=tmp_path).code == 0
    scale = min(4, max(1, round((seconds / (time.monotonic() - start)) ** 0.5)))
    write_image(tmp_path / "big.exr", rng.random((128 * scale, 256 * scale, 3), np.float32), BEAUTY)
    return args


def test_progress_of_a_slow_command_on_a_terminal_only(tmp_path):
    args = slow_frame(tmp_path)
    start = time.monotonic()
    code, shown = run_on_terminal(args, tmp_path)
    assert code == 0, shown
    if time.monotonic() - start > 3.0:  # slow enough to be shown (a much faster machine skips the check)
        assert "mcdtool: --nlmeans 24" in shown and " s" in shown and "\r" in shown, shown
    r = run(*args, cwd=tmp_path)
    assert r.code == 0 and r.err == "", r  # not a terminal: nothing


def test_sequence_summary_and_runstats_count_outcomes(tmp_path):
    """Frame 1 skipped (its output exists), 2 failed (no input), 3 and 4
    written: the summary line (not a terminal) and --runstats say so."""
    pattern = write_sequence(tmp_path, (1, 3, 4))
    (tmp_path / "clean.0001.exr").write_bytes(b"done before")
    r = run(pattern, "--frames", "1-4", "--skip-existing", "--median", 3, "-o", "clean.####.exr", "--runstats",
            cwd=tmp_path)
    assert r.code == 1, r
    assert "mcdtool: 4 frames: 2 written, 1 skipped, 1 failed" in r.err, r
    assert "4 (2 written, 1 skipped, 1 failed)" in r.out, r
    assert "\r" not in r.err, r


def test_guide_of_another_resolution_is_refused(tmp_path):
    beauty, *_ = noisy_scene(width=40, height=32)
    write_image(tmp_path / "in.exr", beauty, BEAUTY)
    write_image(tmp_path / "albedo.exr", np.full((64, 80, 3), 0.5, np.float32), BEAUTY)
    r = run(tmp_path / "in.exr", "--aov", f"albedo={tmp_path / 'albedo.exr'}", "--demodulate", "--median", 3,
            "--remodulate", "-o", tmp_path / "out.exr")
    assert r.code == 1 and "display window 80 x 64" in r.err and "40 x 32" in r.err, r
    assert not (tmp_path / "out.exr").exists()


def test_constant_id_guide_warns(tmp_path):
    beauty, ids, *_ = noisy_scene()
    pixels = np.concatenate([beauty, np.zeros_like(ids)[..., None]], axis=2)
    write_image(tmp_path / "in.exr", pixels, BEAUTY + ["id"])
    r = run(tmp_path / "in.exr", "--object-median", 3, "-o", tmp_path / "out.exr")
    assert r.code == 0 and "WARNING" in r.err and "id guide" in r.err and "0 everywhere" in r.err, r
    write_image(tmp_path / "two.exr", np.concatenate([beauty, ids[..., None]], axis=2), BEAUTY + ["id"])
    r = run(tmp_path / "two.exr", "--object-median", 3, "-o", tmp_path / "out2.exr")
    assert r.code == 0 and r.err == "", r


def test_8bit_display_referred_input_warns(tmp_path):
    pixels = (np.random.default_rng(1).random((16, 16, 3)) * 255).astype(np.uint8)
    spec = oiio.ImageSpec(16, 16, 3, oiio.UINT8)
    buf = oiio.ImageBuf(spec)
    buf.set_pixels(oiio.ROI(), pixels)
    assert buf.write(str(tmp_path / "photo.png"))
    r = run(tmp_path / "photo.png", "--median", 3, "-o", tmp_path / "out.exr")
    assert r.code == 0 and "WARNING" in r.err and "display-referred" in r.err, r


def test_tiff_output_never_renames_channels(testrender_exr, tmp_path):
    """TIFF stores no channel names: the output holds the beauty under its
    names (with a warning), never AOVs renamed 'channel4', ..."""
    r = run(testrender_exr, "--median", 3, "-o", tmp_path / "clean.tif")
    assert r.code == 0 and "WARNING" in r.err and "EXR" in r.err, r
    names = list(read_image(tmp_path / "clean.tif")[1].channelnames)
    assert names == BEAUTY and not any(n.startswith("channel") for n in names)
    r = run(testrender_exr, "--median", 3, "-o", tmp_path / "clean.exr")
    assert r.code == 0 and r.err == "", r
    assert "N.X" in read_image(tmp_path / "clean.exr")[1].channelnames


def test_compare_psnr_is_positive_on_hdr(tmp_path):
    """PSNR is on values clamped to [0, 1] (peak 1): an emitter at 40 that
    the result misses by 10 does not make it negative."""
    reference = np.full((16, 16, 3), 0.5, np.float32)
    reference[:8] = 40.0
    result = reference.copy()
    result[:8] = 30.0
    result[8:] = 0.6
    write_image(tmp_path / "ref.exr", reference, BEAUTY, fmt="float")
    write_image(tmp_path / "in.exr", result, BEAUTY, fmt="float")
    r = run(tmp_path / "in.exr", "--mean", 1, "--compare", tmp_path / "ref.exr")
    assert r.code == 0, r
    psnr = float(r.out.split("PSNR ")[1].split(" dB")[0])
    # clamped MSE: half the pixels 0 (both 1 after the clamp), half 0.1^2
    assert abs(psnr - 10 * np.log10(1 / 0.005)) < 0.01, r


def test_readme_leads_with_denoise():
    """The README's first command is the one-call denoiser; the report's
    chain is shown as the report's method, with its measured limits."""
    readme = open(os.path.join(os.path.dirname(__file__), "..", "..", "README.md")).read()
    commands = [line for line in readme.splitlines() if line.startswith("build/bin/mcdtool ")]
    assert "--denoise" in commands[0], commands
    chain_at = readme.find("--object-median 7 --gaussian 3")
    assert chain_at > readme.find("--denoise")
    assert "0.0073" in readme and "0.179" in readme
