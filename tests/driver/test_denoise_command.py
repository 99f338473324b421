"""mcdtool driver tests for --denoise and --clamp-fireflies: the guides are
found in the file, object edges stay, noise and fireflies go, every other
channel is kept. Each test_* function is one CTest test."""
import numpy as np

from conftest import channel, read_image, run, write_image, noisy_scene

COMBINED = ["My Layer.Combined." + c for c in "RGB"]


def test_denoise_keeps_edges_and_channels_of_a_cycles_file(cycles_exr, tmp_path):
    """On a Cycles multilayer file (no variance: it is estimated) the two
    objects stay apart, the noise drops, and every channel is written; on
    the NL-means operator, whose colour distance keeps this edge the flat
    albedo and the shared normals do not show."""
    src, src_spec = read_image(cycles_exr)
    noisy = np.stack([channel(src, src_spec, n) for n in COMBINED], axis=2)
    out_path = tmp_path / "clean.exr"
    r = run(cycles_exr, "--denoise:method=nlm", "-o", out_path)
    assert r.code == 0, r
    out, spec = read_image(out_path)
    assert list(spec.channelnames) == list(src_spec.channelnames)
    clean = np.stack([channel(out, spec, n) for n in COMBINED], axis=2)
    width = clean.shape[1]
    assert abs(clean[:, width // 2 - 1].mean() - 0.2) < 0.05
    assert abs(clean[:, width // 2].mean() - 0.8) < 0.05
    inside = slice(0, width // 2 - 3)
    assert clean[:, inside].std() < 0.5 * noisy[:, inside].std()
    np.testing.assert_array_equal(channel(out, spec, "My Layer.IndexOB.X"),
                                  channel(src, src_spec, "My Layer.IndexOB.X"))


def test_network_denoise_of_a_cycles_file(cycles_exr, tmp_path):
    """The network (the default --denoise) on the same file: it reads the
    Denoising Albedo and Denoising Normal passes as Blender feeds OIDN, the
    noise drops on either side of the edge, the halves keep their levels a
    few pixels from it, and every other channel is written unchanged."""
    src, src_spec = read_image(cycles_exr)
    noisy = np.stack([channel(src, src_spec, n) for n in COMBINED], axis=2)
    out_path = tmp_path / "clean.exr"
    r = run(cycles_exr, "-v", "--denoise", "-o", out_path)
    assert r.code == 0, r
    assert "My Layer.Denoising Albedo.R" in r.out and "My Layer.Denoising Normal.X" in r.out, r
    assert "prefilter albedo" in r.out and "network" in r.out, r
    out, spec = read_image(out_path)
    assert list(spec.channelnames) == list(src_spec.channelnames)
    clean = np.stack([channel(out, spec, n) for n in COMBINED], axis=2)
    width = clean.shape[1]
    left, right = slice(0, width // 2 - 3), slice(width // 2 + 3, width)
    assert abs(clean[:, left].mean() - 0.2) < 0.03 and abs(clean[:, right].mean() - 0.8) < 0.05
    assert clean[:, left].std() < 0.5 * noisy[:, left].std()
    for name in ("My Layer.IndexOB.X", "My Layer.Combined.A", "My Layer.Denoising Normal.X"):
        np.testing.assert_array_equal(channel(out, spec, name), channel(src, src_spec, name))


def test_clamp_fireflies_removes_a_lone_bright_pixel(tmp_path):
    """A pixel 100x brighter than its object is scaled down to twice its
    neighbours' 75th percentile; the rest is left as it was."""
    beauty, _, _, _ = noisy_scene()
    beauty = np.abs(beauty) + 0.1
    beauty[10, 5] = 100.0
    path = write_image(tmp_path / "beauty.exr", beauty, ["R", "G", "B"], fmt="float")
    r = run(path, "--clamp-fireflies", 2, "-o", tmp_path / "clean.exr")
    assert r.code == 0, r
    out, spec = read_image(tmp_path / "clean.exr")
    lum = beauty @ np.array([0.2126, 0.7152, 0.0722], np.float32)
    neighbours = np.delete(lum[8:13, 3:8].ravel(), 12)
    bound = 2 * np.sort(neighbours)[(3 * (len(neighbours) - 1)) // 4]
    clean_lum = out[10, 5, :3] @ np.array([0.2126, 0.7152, 0.0722], np.float32)
    assert abs(clean_lum - bound) < 1e-4 * bound
    assert clean_lum < 10
    changed = np.argwhere(np.any(out[..., :3] != beauty, axis=2))
    assert len(changed) < 0.05 * lum.size, changed
