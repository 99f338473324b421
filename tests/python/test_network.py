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


def test_neighbours_average_the_frames_results_and_prepared_frames_give_the_same():
    """With `neighbours` on a still shot (the same picture, new noise per
    frame) the result lies between the frames' own network results and is
    closer to the truth; a neighbour made once with prepare_network_frame
    gives the same result as one given as (offset, beauty, guides)."""
    h, w = 48, 64
    truth = np.broadcast_to(np.linspace(0.2, 2.0, w, dtype=np.float32)[None, :, None], (h, w, 3))
    frames = []
    for seed in (1, 2, 3):
        rng = np.random.default_rng(seed)
        frames.append(np.ascontiguousarray(truth * rng.gamma(4.0, 0.25, (h, w, 3)).astype(np.float32)))
    g = guides(h, w)
    own = [mcdenoise.denoise_network(f, g, quality="fast") for f in frames]
    out = mcdenoise.denoise_network(frames[1], g, neighbours=[(-1, frames[0], g), (1, frames[2], g)],
                                    quality="fast")
    lo, hi = np.minimum.reduce(own), np.maximum.reduce(own)
    assert np.all(out >= lo - 1e-6 * np.abs(lo)) and np.all(out <= hi + 1e-6 * np.abs(hi))
    error = lambda x: float(np.mean((x - truth) ** 2 / (truth ** 2 + 0.01)))  # noqa: E731
    assert error(out) < 0.8 * error(own[1])
    made = mcdenoise.prepare_network_frame(frames[2], g, quality="fast")
    again = mcdenoise.denoise_network(frames[1], g, neighbours=[(-1, frames[0], g), (1, made)], quality="fast")
    np.testing.assert_array_equal(again, out)
    with pytest.raises(TypeError, match="neighbours\\[0\\]"):
        mcdenoise.denoise_network(frames[1], g, neighbours=[(1, frames[0])])
