"""mcdtool driver tests for the feature-guided commands (--cross-bilateral,
--atrous, --nlmeans, --demodulate, --remodulate): they take the guides
present in the input, keep object edges, and demodulation round-trips.
Each test_* function is one CTest test (tests/driver/CMakeLists.txt)."""
import numpy as np

from conftest import channel, check_failure, noisy_scene, read_image, run, write_image

COMBINED = ["My Layer.Combined." + c for c in "RGB"]


def test_feature_commands_keep_object_edges(cycles_exr, tmp_path):
    """The filters read IndexOB, normals, depth and albedo from a Cycles file:
    the two objects (0.2 left, 0.8 right) never mix across the id edge."""
    src, src_spec = read_image(cycles_exr)
    noisy = np.stack([channel(src, src_spec, n) for n in COMBINED], axis=2)
    width = noisy.shape[1]
    for command, arg in (("--cross-bilateral", 7), ("--atrous", 4), ("--nlmeans", 5)):
        out_path = tmp_path / (command.strip("-") + ".exr")
        r = run(cycles_exr, command, arg, "-o", out_path)
        assert r.code == 0, (command, r)
        out, spec = read_image(out_path)
        clean = np.stack([channel(out, spec, n) for n in COMBINED], axis=2)
        left, right = clean[:, width // 2 - 1], clean[:, width // 2]
        # Mixing across the edge would pull the edge columns toward 0.5.
        assert abs(left.mean() - 0.2) < 0.08, (command, left.mean())
        assert abs(right.mean() - 0.8) < 0.08, (command, right.mean())
        # And the noise (sigma 0.2) went down inside each object.
        assert clean[:, : width // 2 - 3].std() < 0.7 * noisy[:, : width // 2 - 3].std(), command


def test_demodulate_round_trip_and_chain(cycles_exr, tmp_path):
    """--demodulate then --remodulate gives the beauty back; the albedo 0.5
    of the Cycles file divides the beauty by 0.51."""
    src, src_spec = read_image(cycles_exr)
    noisy = np.stack([channel(src, src_spec, n) for n in COMBINED], axis=2)
    r = run(cycles_exr, "--demodulate", "-o", tmp_path / "demod.exr")
    assert r.code == 0, r
    out, spec = read_image(tmp_path / "demod.exr")
    demod = np.stack([channel(out, spec, n) for n in COMBINED], axis=2)
    np.testing.assert_allclose(demod, noisy / np.float32(0.51), rtol=1e-6)
    np.testing.assert_array_equal(channel(out, spec, "My Layer.Combined.A"),
                                  channel(src, src_spec, "My Layer.Combined.A"))
    r = run(cycles_exr, "--demodulate", "--remodulate", "-o", tmp_path / "back.exr")
    assert r.code == 0, r
    out, spec = read_image(tmp_path / "back.exr")
    back = np.stack([channel(out, spec, n) for n in COMBINED], axis=2)
    np.testing.assert_allclose(back, noisy, rtol=1e-6, atol=1e-7)
    r = run(cycles_exr, "--demodulate", "--atrous", 3, "--remodulate", "-o", tmp_path / "chain.exr")
    assert r.code == 0, r


def test_feature_commands_without_guides_and_missing_albedo(tmp_path):
    """With a bare beauty the feature filters still run (no feature weight);
    --demodulate needs an albedo guide and says so, writing nothing."""
    beauty, _, _, _ = noisy_scene()
    path = write_image(tmp_path / "beauty.exr", beauty, ["R", "G", "B"])
    for command, arg in (("--cross-bilateral", 5), ("--atrous", 2), ("--nlmeans", 3)):
        r = run(path, command, arg, "-o", tmp_path / "out.exr")
        assert r.code == 0, (command, r)
    r = run(path, "--demodulate", "-o", tmp_path / "bad.exr")
    check_failure(r, 1, "--demodulate", "albedo")
    assert not (tmp_path / "bad.exr").exists()
    r = run(path, "--nlmeans", 200, "-o", tmp_path / "bad.exr")
    check_failure(r, 2, "SEARCH_RADIUS out of range")
    assert not (tmp_path / "bad.exr").exists()
