"""The cross-frame denoise from Python and in mcdenoise.batch, on a small
testrender camera move: mcdenoise.denoise(beauty, guides, neighbours=[(offset,
beauty, guides), ...]) gives bit for bit what `mcdtool --denoise:method=nlm
--temporal` writes (as float), also with neighbours prepared once
(prepare_frame), and mcdenoise.denoise_network(..., neighbours=...) what
`mcdtool --denoise --temporal` writes; an empty list
gives the single-frame result; malformed neighbours are
a TypeError; the batch with --temporal writes the same files as one mcdtool
run, whatever the chunks (each task reads the frames its chunk needs)."""
import numpy as np
import OpenImageIO as oiio
import pytest

import mcdenoise
from mcdenoise.batch import denoise_sequence
from conftest import assert_same_file_contents, frame_file, mcdtool, render_sequence, read_pixels

#: testrender channel names of each guide --denoise uses.
GUIDES = {"normal": ["N.X", "N.Y", "N.Z"], "depth": ["Z"], "albedo": ["albedo.R", "albedo.G", "albedo.B"],
          "variance": ["var.R", "var.G", "var.B"], "half_a": ["A.R", "A.G", "A.B"],
          "half_b": ["B.R", "B.G", "B.B"], "motion": ["motion.X", "motion.Y", "motion.Z", "motion.W"]}


@pytest.fixture
def truck(tmp_path):
    return render_sequence(tmp_path / "in", range(1, 6), res="48x40", spp=8, scene="shot_truck")


def frame_arrays(pattern, frame):
    """(beauty, guides) of one testrender frame as numpy arrays."""
    pixels, spec = read_pixels(frame_file(pattern, frame))
    names = list(spec.channelnames)
    pick = lambda channels: np.ascontiguousarray(pixels[:, :, [names.index(c) for c in channels]])
    return pick(["R", "G", "B"]), {role: pick(channels) for role, channels in GUIDES.items()}


def test_binding_equals_mcdtool_temporal(truck, tmp_path):
    r = mcdtool(truck, "--frames", "3", "--denoise:method=nlm", "--temporal", 2, "-d", "float", "-o",
                tmp_path / "o.####.exr")
    assert r.returncode == 0, r.stderr
    beauty, guides = frame_arrays(truck, 3)
    neighbours = [(offset, *frame_arrays(truck, 3 + offset)) for offset in (-2, -1, 1, 2)]
    result = mcdenoise.denoise(beauty, guides, neighbours=neighbours)
    written, _ = read_pixels(tmp_path / "o.0003.exr")
    assert result.tobytes() == np.ascontiguousarray(written[:, :, :3]).tobytes()
    single = mcdenoise.denoise(beauty, guides)
    assert not np.array_equal(result, single)
    assert np.array_equal(mcdenoise.denoise(oiio.ImageBuf(beauty), guides, neighbours=[]).get_pixels(oiio.FLOAT),
                          single)
    # frames prepared once (prepare_frame), alone or mixed with plain tuples
    prepared = [(n[0], mcdenoise.prepare_frame(n[1], n[2], nthreads=1)) for n in neighbours]
    assert mcdenoise.denoise(beauty, guides, neighbours=prepared).tobytes() == result.tobytes()
    assert mcdenoise.denoise(beauty, guides, neighbours=prepared[:2] + neighbours[2:]).tobytes() == result.tobytes()
    with pytest.raises(mcdenoise.Error, match="motion has 3 channels"):
        mcdenoise.prepare_frame(beauty, {"motion": beauty})


def test_malformed_neighbours_are_type_errors(truck):
    beauty, guides = frame_arrays(truck, 1)
    with pytest.raises(TypeError, match=r"neighbours\[0\]"):
        mcdenoise.denoise(beauty, guides, neighbours=[(1, beauty)])
    with pytest.raises(TypeError):
        mcdenoise.denoise(beauty, guides, neighbours=3)
    with pytest.raises(mcdenoise.Error):
        mcdenoise.denoise(beauty, guides, neighbours=[(0, beauty, guides)])


def test_network_binding_equals_mcdtool_temporal(truck, tmp_path):
    r = mcdtool(truck, "--frames", "3", "--denoise", "--temporal", 2, "-d", "float", "-o", tmp_path / "o.####.exr")
    assert r.returncode == 0, r.stderr
    beauty, guides = frame_arrays(truck, 3)
    neighbours = [(offset, *frame_arrays(truck, 3 + offset)) for offset in (-2, -1, 1, 2)]
    result = mcdenoise.denoise_network(beauty, guides, neighbours=neighbours)
    written, _ = read_pixels(tmp_path / "o.0003.exr")
    assert result.tobytes() == np.ascontiguousarray(written[:, :, :3]).tobytes()
    assert not np.array_equal(result, mcdenoise.denoise_network(beauty, guides))


@pytest.mark.parametrize("chunk_size", [1, 2])
def test_batch_temporal_equals_one_mcdtool_run(truck, tmp_path, chunk_size):
    r = mcdtool(truck, "--frames", "1-5", "--denoise", "--temporal", 2, "-o", tmp_path / "one/o.####.exr")
    assert r.returncode == 0, r.stderr
    out = tmp_path / "batch" / "o.####.exr"
    out.parent.mkdir()
    summary = denoise_sequence(truck, "1-5", "--denoise", out, temporal=2, workers=2, chunk_size=chunk_size,
                               progress=False)
    assert summary.ok and summary.written == [1, 2, 3, 4, 5], summary.report()
    for frame in range(1, 6):
        assert_same_file_contents(frame_file(tmp_path / "one/o.####.exr", frame), frame_file(out, frame))
