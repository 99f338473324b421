"""mcdenoise.denoise(..., layers=[...]) and the batch's aovs=: the layers get
the beauty's own per-pixel operator (layers that sum to the beauty sum to
the result, the beauty unchanged by them), the same pixels as
`mcdtool --aovs`, and the batch writes what `mcdtool --aovs` writes."""
import re

import numpy as np
import OpenImageIO as oiio
import pytest

import mcdenoise
from mcdenoise.batch import denoise_sequence, sequence_args
from conftest import assert_same_file_contents, frame_file, mcdtool, random_image, read_pixels, render_sequence

GUIDES = {"normal": ["N.X", "N.Y", "N.Z"], "depth": ["Z"], "albedo": ["albedo.R", "albedo.G", "albedo.B"],
          "variance": ["var.R", "var.G", "var.B"], "half_a": ["A.R", "A.G", "A.B"],
          "half_b": ["B.R", "B.G", "B.B"]}


@pytest.fixture(scope="module")
def frames_with_passes(tmp_path_factory):
    return render_sequence(tmp_path_factory.mktemp("passes"), range(1, 3), res="40x32", passes=True)


def planes(pixels, spec, names):
    index = [list(spec.channelnames).index(n) for n in names]
    return np.ascontiguousarray(pixels[:, :, index])


def test_the_docstring_documents_pythons_arguments():
    """Python takes the C++ terms as sums= and colours=, before roi and
    nthreads, and its docstring says so."""
    signature, _, body = mcdenoise.denoise_layers.__doc__.partition("\n")
    names = re.findall(r"(?:\(|, )(\w+): ", signature)
    assert names[:7] == ["beauty", "layers", "guides", "sums", "colours", "roi", "nthreads"], signature
    assert "@param sums" in body and "@param colours" in body and "@param terms" not in body


def test_layers_that_sum_to_the_beauty_sum_to_the_result():
    beauty = np.abs(random_image((24, 30, 3), 4))
    share = np.random.default_rng(2).uniform(0, 1, beauty.shape).astype(np.float32)
    key, fill = beauty * share, beauty * (1 - share)
    result, layers = mcdenoise.denoise(beauty, layers=[key, fill])
    assert len(layers) == 2 and layers[0].shape == beauty.shape
    assert mcdenoise.rel_mse(layers[0] + layers[1], result) <= 1e-6
    assert np.array_equal(result, mcdenoise.denoise(beauty))
    # ImageBufs in, ImageBufs out, same pixels
    as_buf = [oiio.ImageBuf(oiio.ImageSpec(30, 24, 3, oiio.FLOAT)) for _ in range(3)]
    for buf, array in zip(as_buf, (beauty, key, fill)):
        buf.set_pixels(oiio.ROI(), array)
    buf_result, buf_layers = mcdenoise.denoise_layers(as_buf[0], as_buf[1:])
    assert isinstance(buf_layers[0], oiio.ImageBuf)
    assert np.array_equal(buf_layers[0].get_pixels(oiio.FLOAT), layers[0])


def test_layers_match_mcdtool_aovs(frames_with_passes, tmp_path):
    path = frame_file(frames_with_passes, 1)
    out = tmp_path / "clean.exr"
    r = mcdtool(path, "--aovs", "GlossInd,Emit", "--denoise", "-o", out)
    assert r.returncode == 0, r.stderr
    pixels, spec = read_pixels(path)
    guides = {name: planes(pixels, spec, chans) for name, chans in GUIDES.items()}
    passes = [planes(pixels, spec, [f"{p}.{c}" for c in "RGB"]) for p in ("GlossInd", "Emit")]
    gloss_colour = planes(pixels, spec, [f"GlossCol.{c}" for c in "RGB"])
    result, layers = mcdenoise.denoise(planes(pixels, spec, list("RGB")), guides=guides, layers=passes,
                                       colours=[gloss_colour, None])
    written, wspec = read_pixels(out)
    assert np.array_equal(planes(written, wspec, list("RGB")), result)
    for name, layer in zip(("GlossInd", "Emit"), layers):
        assert np.array_equal(planes(written, wspec, [f"{name}.{c}" for c in "RGB"]), layer), name


def test_batch_passes_aovs(frames_with_passes, tmp_path):
    assert sequence_args("a.####.exr", "1-2", "--denoise", "b.####.exr", aovs=["DiffDir", "Env"])[-2:] == \
        ["--aovs", "DiffDir,Env"]
    expected = tmp_path / "mcdtool" / "clean.####.exr"
    expected.parent.mkdir()
    r = mcdtool(frames_with_passes, "--frames", "1-2", "--aovs", "auto", "--denoise", "-o", expected)
    assert r.returncode == 0, r.stderr
    out = tmp_path / "batch" / "clean.####.exr"
    out.parent.mkdir()
    summary = denoise_sequence(frames_with_passes, "1-2", "--denoise", out, aovs="auto", workers=1,
                               progress=False)
    assert summary.ok and summary.written == [1, 2]
    for frame in (1, 2):
        assert_same_file_contents(frame_file(out, frame), frame_file(expected, frame))
    noisy, spec = read_pixels(frame_file(frames_with_passes, 1))
    clean, _ = read_pixels(frame_file(out, 1))
    index = list(spec.channelnames).index("DiffInd.R")
    assert not np.array_equal(noisy[:, :, index], clean[:, :, index])
