"""The sequence metrics from Python: lists of numpy arrays or ImageBufs give
the figures of the definitions (computed here with numpy), the frame-by-frame
form gives the same numbers, and a frame that cannot be compared raises
mcdenoise.Error naming it."""
import numpy as np
import OpenImageIO as oiio
import pytest

import mcdenoise

EPS = 0.01


def frames(count, seed, noise):
    rng = np.random.default_rng(seed)
    x = np.linspace(0, 3, 12)[None, :, None]
    return [(0.4 + 0.2 * np.sin(x + t) + noise * rng.standard_normal((8, 12, 3))).astype(np.float32)
            for t in range(count)]


def test_compare_sequence_matches_numpy_definitions():
    results, references = frames(4, 1, 0.05), frames(4, 2, 0.01)
    x, r = np.array(results, np.float64), np.array(references, np.float64)
    per_frame = (((x - r) ** 2) / (r ** 2 + EPS)).mean(axis=(1, 2, 3))
    dx, dr = np.diff(x, axis=0), np.diff(r, axis=0)
    temporal = (((dx - dr) ** 2) / (dr ** 2 + EPS)).mean()
    flicker = (x.var(axis=0) / (r.mean(axis=0) ** 2 + EPS)).mean()
    s = mcdenoise.compare_sequence(results, references)
    np.testing.assert_allclose(s.frame_rel_mse, per_frame, rtol=1e-6)
    assert s.temporal_error == pytest.approx(temporal, rel=1e-6)
    assert s.flicker == pytest.approx(flicker, rel=1e-6)
    assert mcdenoise.temporal_error(results, references) == s.temporal_error
    assert mcdenoise.flicker(results, references, nthreads=1) == s.flicker


def test_frame_by_frame_equals_all_at_once_with_imagebufs():
    results, references = frames(3, 3, 0.1), frames(3, 4, 0.02)
    sums = mcdenoise.start_sequence(nthreads=2)
    for x, r in zip(results, references):
        assert mcdenoise.add_sequence_frame(sums, oiio.ImageBuf(x), oiio.ImageBuf(r))
    fed = mcdenoise.sequence_comparison(sums)
    all_at_once = mcdenoise.compare_sequence(results, references)
    assert (fed.temporal_error, fed.flicker, fed.frame_rel_mse) == (
        all_at_once.temporal_error, all_at_once.flicker, all_at_once.frame_rel_mse)


def test_a_frame_that_cannot_be_compared_raises_naming_it():
    results = frames(3, 5, 0.1)
    references = frames(2, 6, 0.0) + [np.zeros((8, 12, 1), np.float32)]
    with pytest.raises(mcdenoise.Error, match="frame 2"):
        mcdenoise.compare_sequence(results, references)
