"""mcdtool driver tests for --aovs: the light passes of Cycles-, Arnold- and
testrender-style files are denoised with the beauty's weights so that they
still add up to the written beauty; colour passes, guides, ids and every
other channel stay bit-identical; unknown, colour or guide passes in a LIST
fail before any work. Each test_* function is one CTest test."""
import os
import subprocess

import numpy as np
import pytest

from conftest import check_failure, channel, read_image, run, write_image, noisy_scene

RGB = "RGB"
LIGHT_PASSES = ["DiffDir", "DiffInd", "GlossDir", "GlossInd", "Emit", "Env"]


def rel_mse(x, ref):
    """relMSE as the library computes it: mean of (x - r)^2 / (r^2 + 0.01)."""
    return float(np.mean((x - ref) ** 2 / (ref ** 2 + 0.01)))


def cycles_planes(layer="ViewLayer", seed=3):
    """A Cycles-style view layer whose Combined is sum Col x (Dir + Ind) +
    Emit + Env, each light pass noisy, with normal, albedo and object ids."""
    beauty, ids, normal, depth = noisy_scene(seed=seed)
    rng = np.random.default_rng(seed)
    shape = beauty.shape
    col = {"Diff": np.where(ids[..., None] > 0, 0.7, 0.3) * np.ones(shape, np.float32),
           "Gloss": np.full(shape, 0.04, np.float32)}
    passes = {}
    for lobe, level in (("Diff", 0.6), ("Gloss", 2.0)):
        for kind, share in (("Dir", 0.7), ("Ind", 0.3)):
            passes[lobe + kind] = np.abs(level * share + rng.normal(0, 0.2 * level, shape))
    passes["Emit"] = np.zeros(shape, np.float32)
    passes["Emit"][:3, :3] = 5.0
    passes["Env"] = np.abs(0.1 + rng.normal(0, 0.05, shape))
    combined = passes["Emit"] + passes["Env"]
    for lobe in col:
        combined = combined + col[lobe] * (passes[lobe + "Dir"] + passes[lobe + "Ind"])
    planes = {}
    for name, img in [("Combined", combined), ("DiffCol", col["Diff"]), ("GlossCol", col["Gloss"])] \
            + list(passes.items()):
        for i, c in enumerate(RGB):
            planes[f"{name}.{c}"] = img[..., i]
    planes["Combined.A"] = np.ones(ids.shape, np.float32)
    for i, c in enumerate("XYZ"):
        planes[f"Normal.{c}"] = normal[..., i]
    for i, c in enumerate(RGB):
        planes[f"Denoising Albedo.{c}"] = col["Diff"][..., i]
    planes["IndexOB.X"] = ids + 1.0
    planes["Depth.Z"] = depth
    return {f"{layer}.{k}": v.astype(np.float32) for k, v in planes.items()}


def write_planes(path, planes):
    return write_image(path, np.stack(list(planes.values()), axis=2), list(planes), fmt="float",
                       compression="zip")


def plane_image(pixels, spec, prefix):
    return np.stack([channel(pixels, spec, f"{prefix}.{c}") for c in RGB], axis=2)


def rebuild(pixels, spec, layer):
    """The compositor's Cycles recombination of the written passes."""
    total = plane_image(pixels, spec, f"{layer}.Emit") + plane_image(pixels, spec, f"{layer}.Env")
    for lobe in ("Diff", "Gloss"):
        total = total + plane_image(pixels, spec, f"{layer}.{lobe}Col") * (
            plane_image(pixels, spec, f"{layer}.{lobe}Dir") + plane_image(pixels, spec, f"{layer}.{lobe}Ind"))
    return total


def test_cycles_passes_rebuild_the_written_beauty(tmp_path):
    """--aovs auto finds the Cycles light passes; the written Combined is the
    recombination of the written passes, each pass is less noisy, and the
    colour passes, guides, ids and alpha are bit-identical."""
    src_path = write_planes(tmp_path / "cycles.exr", cycles_planes())
    out_path = tmp_path / "clean.exr"
    r = run(src_path, "--aovs", "auto", "--denoise", "-o", out_path)
    assert r.code == 0, r
    src, src_spec = read_image(src_path)
    out, spec = read_image(out_path)
    assert list(spec.channelnames) == list(src_spec.channelnames)
    beauty = plane_image(out, spec, "ViewLayer.Combined")
    assert rel_mse(rebuild(out, spec, "ViewLayer"), beauty) <= 1e-6
    for name in LIGHT_PASSES[:4]:
        before = plane_image(src, src_spec, f"ViewLayer.{name}")
        after = plane_image(out, spec, f"ViewLayer.{name}")
        assert after.std() < 0.7 * before.std(), name
    changed = {f"ViewLayer.{p}.{c}" for p in LIGHT_PASSES + ["Combined"] for c in RGB}
    for name in src_spec.channelnames:
        if name not in changed:
            np.testing.assert_array_equal(channel(out, spec, name), channel(src, src_spec, name), name)


def test_arnold_light_groups_add_up_to_the_denoised_beauty(tmp_path):
    """RGBA_<group> light groups that sum to RGBA sum to the denoised RGBA;
    their alpha and diffuse_albedo are untouched."""
    beauty, ids, normal, depth = noisy_scene(seed=5)
    rng = np.random.default_rng(5)
    share = rng.uniform(0.0, 1.0, beauty.shape).astype(np.float32)
    key, fill = beauty * share, beauty * (1 - share)
    alpha = np.ones(ids.shape + (1,), np.float32)
    albedo = np.full(beauty.shape, 0.5, np.float32)
    pixels = np.concatenate([beauty, alpha, key, alpha, fill, alpha, albedo, normal, depth[..., None]],
                            axis=2)
    names = (["R", "G", "B", "A"] + [f"RGBA_key.{c}" for c in "RGBA"] + [f"RGBA_fill.{c}" for c in "RGBA"]
             + [f"diffuse_albedo.{c}" for c in RGB] + ["N.X", "N.Y", "N.Z", "Z"])
    src_path = write_image(tmp_path / "arnold.exr", pixels, names, fmt="float")
    out_path = tmp_path / "clean.exr"
    r = run(src_path, "--aovs", "auto", "--denoise", "-o", out_path)
    assert r.code == 0, r
    out, spec = read_image(out_path)
    total = plane_image(out, spec, "RGBA_key") + plane_image(out, spec, "RGBA_fill")
    written = np.stack([channel(out, spec, c) for c in RGB], axis=2)
    assert rel_mse(total, written) <= 1e-6
    assert written.std() < beauty.std()
    src, src_spec = read_image(src_path)
    for name in ["A", "RGBA_key.A", "RGBA_fill.A", "diffuse_albedo.R", "N.X", "Z"]:
        np.testing.assert_array_equal(channel(out, spec, name), channel(src, src_spec, name), name)
    # the beauty is what --denoise alone writes on the NL-means operator,
    # which --aovs runs until the network has a light-pass mode
    alone_path = tmp_path / "alone.exr"
    assert run(src_path, "--denoise:method=nlm", "-o", alone_path).code == 0
    alone, alone_spec = read_image(alone_path)
    for c in RGB:
        np.testing.assert_array_equal(channel(out, spec, c), channel(alone, alone_spec, c))


def test_a_list_denoises_only_the_passes_named(tmp_path):
    src_path = write_planes(tmp_path / "cycles.exr", cycles_planes())
    out_path = tmp_path / "clean.exr"
    r = run(src_path, "--aovs", "DiffInd,Env", "--denoise", "-o", out_path)
    assert r.code == 0, r
    src, src_spec = read_image(src_path)
    out, spec = read_image(out_path)
    for name in src_spec.channelnames:
        same = np.array_equal(channel(out, spec, name), channel(src, src_spec, name))
        expect_changed = name.split(".")[1] in ("DiffInd", "Env", "Combined") and not name.endswith(".A")
        assert same != expect_changed, name


@pytest.mark.parametrize("listed, needle", [("DiffDir,Nope", "'Nope'"), ("DiffCol", "colour pass"),
                                            ("Normal", "guide")])
def test_a_list_with_a_pass_that_is_not_light_fails_before_any_work(tmp_path, listed, needle):
    src_path = write_planes(tmp_path / "cycles.exr", cycles_planes())
    before = os.listdir(tmp_path)
    r = run(src_path, "--aovs", listed, "--denoise", "-o", tmp_path / "clean.exr")
    check_failure(r, 2, "--aovs", needle)
    assert sorted(os.listdir(tmp_path)) == sorted(before)


def test_aovs_without_denoise_is_a_usage_error(tmp_path):
    src_path = write_planes(tmp_path / "cycles.exr", cycles_planes())
    r = run(src_path, "--aovs", "auto", "--median", "3", "-o", tmp_path / "clean.exr")
    check_failure(r, 2, "--aovs", "--denoise")


def test_testrender_passes_rebuild_the_written_beauty(tmp_path):
    """On a testrender file (Cycles' names, a transmission lobe too) the
    written beauty is the recombination of the written passes."""
    testrender = os.environ["TESTRENDER"]
    src_path = tmp_path / "render.exr"
    subprocess.run([testrender, "--scene", "textured", "--res", "48x36", "--spp", "4", "--passes", "-q",
                    "-o", str(src_path)], check=True)
    out_path = tmp_path / "clean.exr"
    r = run(src_path, "--aovs", "auto", "--denoise", "-o", out_path)
    assert r.code == 0, r
    out, spec = read_image(out_path)
    written = np.stack([channel(out, spec, c) for c in RGB], axis=2)
    total = plane_image(out, spec, "Emit") + plane_image(out, spec, "Env")
    for lobe in ("Diff", "Gloss", "Trans"):
        total = total + plane_image(out, spec, f"{lobe}Col") * (
            plane_image(out, spec, f"{lobe}Dir") + plane_image(out, spec, f"{lobe}Ind"))
    assert rel_mse(total, written) <= 1e-6
