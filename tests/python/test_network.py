"""mcdenoise.denoise_network: its keyword arguments reach the library (each
quality runs its own weight files, the prefilter can be turned off), bad
arguments raise ValueError, a missing weights folder or weight file raises
mcdenoise.Error naming it, and the colour comes out denoised while alpha is
kept."""
import os
import shutil

import numpy as np
import pytest

import mcdenoise


def noisy(seed=1, h=48, w=64, c=4):
    rng = np.random.default_rng(seed)
    base = np.linspace(0.2, 2.0, w, dtype=np.float32)[None, :, None]
    image = (base * (0.5 + rng.random((h, w, c), dtype=np.float32))).astype(np.float32)
    image[..., 3] = rng.random((h, w), dtype=np.float32)
    return image


def guides(h=48, w=64):
    albedo = np.full((h, w, 3), 0.5, np.float32)
    normal = np.zeros((h, w, 3), np.float32)
    normal[..., 2] = 1.0
    return {"albedo": albedo, "normal": normal}


def test_the_network_denoises_the_colour_and_keeps_alpha():
    beauty = noisy()
    out = mcdenoise.denoise_network(beauty, guides())
    assert out.shape == beauty.shape and out.dtype == np.float32
    np.testing.assert_array_equal(out[..., 3], beauty[..., 3])
    # Along each column the truth is constant: the noise across rows drops.
    assert out[..., :3].std(axis=0).mean() < 0.3 * beauty[..., :3].std(axis=0).mean()


def test_each_quality_and_the_prefilter_change_the_result():
    beauty, g = noisy(2), guides()
    results = {q: mcdenoise.denoise_network(beauty, g, quality=q) for q in ("fast", "balanced", "high")}
    assert not np.array_equal(results["fast"], results["balanced"])
    assert not np.array_equal(results["balanced"], results["high"])
    raw_guides = mcdenoise.denoise_network(beauty, g, prefilter_guides=False)
    assert not np.array_equal(raw_guides, results["high"])
    np.testing.assert_array_equal(mcdenoise.denoise_network(beauty, g), results["high"])


def test_bad_arguments_are_named():
    with pytest.raises(ValueError, match="quality"):
        mcdenoise.denoise_network(noisy(), quality="ultra")
    with pytest.raises(mcdenoise.Error, match="/nonexistent/weights"):
        mcdenoise.denoise_network(noisy(), weights_dir="/nonexistent/weights")


def test_a_missing_weight_file_is_named(tmp_path):
    source = os.environ["MCD_WEIGHTS_DIR"]
    for name in os.listdir(source):
        if name.endswith(".tza") and name != "rt_hdr_small.tza":
            shutil.copy(os.path.join(source, name), tmp_path / name)
    with pytest.raises(mcdenoise.Error, match="rt_hdr_small.tza.*fetch-weights"):
        mcdenoise.denoise_network(noisy()[..., :3], quality="fast", weights_dir=str(tmp_path))
