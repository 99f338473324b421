"""The bindings: every library function is there with the header's names and
docs; numpy and ImageBuf calls give exactly what mcdtool (the C++ library
through the driver) writes; errors raise with the library's message; the GIL
is released while filtering."""
import re
import threading
import time
from pathlib import Path

import numpy as np
import OpenImageIO as oiio
import pytest

import mcdenoise
from conftest import frame_file, mcdtool, random_image, read_pixels

HEADERS = Path(__file__).resolve().parents[2] / "imageops" / "include" / "mcdenoise"

#: The channels of a testrender frame that hold each Guides field it has.
FEATURES = {"object_id": ["id"], "normal": ["N.X", "N.Y", "N.Z"], "depth": ["Z"],
            "albedo": ["albedo.R", "albedo.G", "albedo.B"], "variance": ["var.R", "var.G", "var.B"],
            "half_a": ["A.R", "A.G", "A.B"], "half_b": ["B.R", "B.G", "B.B"]}


def used_guides(function):
    """The (field, channels) of the guides `function` uses (the library's
    guides_used, which mcdtool passes), in the order of the Guides struct."""
    return [(field, FEATURES[field]) for field in mcdenoise.guides_used[function] if field in FEATURES]

#: mcdtool command -> (library function, guide channels by argument (for
#: `guides`, a list of (field, channels)), keyword parameters).
CASES = {
    "--mean 5": ("mean", {}, {"size": 5}),
    "--median 5": ("median", {}, {"size": 5}),
    "--gaussian 5": ("gaussian", {}, {"size": 5}),
    "--object-mean 5": ("object_mean", {"object_id": ["id"]}, {"size": 5}),
    "--object-median 7": ("object_median", {"object_id": ["id"]}, {"size": 7}),
    "--object-gaussian 5": ("object_gaussian", {"object_id": ["id"]}, {"size": 5}),
    "--brdf-mean 5": ("brdf_mean", {"object_id": ["id"], "reflect_id": ["reflid"]}, {"size": 5}),
    "--brdf-median 5": ("brdf_median", {"object_id": ["id"], "reflect_id": ["reflid"]}, {"size": 5}),
    "--brdf-gaussian 5": ("brdf_gaussian", {"object_id": ["id"], "reflect_id": ["reflid"]}, {"size": 5}),
    "--normal-mean 5": ("normal_mean", {"object_id": ["id"], "normal": ["N.X", "N.Y", "N.Z"]}, {"size": 5}),
    "--normal-gaussian 5": ("normal_gaussian", {"object_id": ["id"], "normal": ["N.X", "N.Y", "N.Z"]},
                            {"size": 5}),
    "--dof 4 1": ("dof", {"object_id": ["id"], "depth": ["Z"]}, {"levels": 4, "focus_level": 1}),
    "--dof-range 4 1 1.5 6": ("dof", {"object_id": ["id"], "depth": ["Z"]},
                              {"levels": 4, "focus_level": 1, "depth_near": 1.5, "depth_far": 6.0}),
    "--cross-bilateral 7": ("cross_bilateral", {"guides": used_guides("cross_bilateral")}, {"size": 7}),
    "--atrous 3": ("atrous", {"guides": used_guides("atrous")}, {"iterations": 3}),
    "--nlmeans 3": ("nlmeans", {"guides": used_guides("nlmeans")}, {"search_radius": 3}),
    "--denoise:method=nlm": ("denoise", {"guides": used_guides("denoise")}, {}),
    "--denoise": ("denoise_network", {"guides": used_guides("denoise_network")}, {}),
    "--clamp-fireflies 2": ("clamp_fireflies", {"guides": used_guides("clamp_fireflies")}, {"factor": 2.0}),
    "--demodulate": ("demodulate", {"albedo": ["albedo.R", "albedo.G", "albedo.B"]}, {}),
    "--remodulate": ("remodulate", {"albedo": ["albedo.R", "albedo.G", "albedo.B"]}, {}),
}


def header_functions():
    """{name: first doc line} of every documented function in the headers."""
    found = {}
    for header in sorted(HEADERS.glob("*.h")):
        doc = []
        for line in header.read_text().splitlines():
            line = line.strip()
            if line.startswith("///"):
                doc.append(line[3:].strip())
                continue
            match = re.match(r"^(?:const\s+)?[A-Za-z_][\w:<>]*\*?\s+([a-z_][a-z0-9_]*)\(", line)
            if match and doc and match.group(1) not in found:
                found[match.group(1)] = doc[0]
            doc = []
    return found


def channels(pixels, spec, names):
    """The named channels of a read image, as a contiguous H x W x C array."""
    index = [list(spec.channelnames).index(n) for n in names]
    return np.ascontiguousarray(pixels[:, :, index])


def image_argument(pixels, spec, names, convert):
    """An image argument from its channel `names` (a list), or a guides dict
    from a list of (field, channel names); images made with `convert`."""
    if isinstance(names[0], tuple):
        return {field: convert(channels(pixels, spec, chans)) for field, chans in names}
    return convert(channels(pixels, spec, names))


def as_imagebuf(array):
    """A float ImageBuf holding `array` (H x W x C)."""
    h, w, c = array.shape
    buf = oiio.ImageBuf(oiio.ImageSpec(w, h, c, oiio.FLOAT))
    assert buf.set_pixels(oiio.ROI(), array)
    return buf


def test_every_header_function_is_bound_with_its_doc():
    functions = header_functions()
    assert {"mean", "object_median", "dof", "compare_images", "ssim"} <= set(functions)
    for name, first_line in functions.items():
        bound = getattr(mcdenoise, name, None)
        assert bound is not None, f"{name} is declared in the headers but not bound"
        assert first_line in bound.__doc__, name


def test_version_is_the_headers():
    """mcdenoise.__version__ and version() are the loaded library's version,
    the one mcdenoise/version.h writes."""
    text = (HEADERS / "version.h").read_text()
    header = re.search(r'#define MCDENOISE_VERSION_STRING "([0-9.]+)"', text).group(1)
    assert mcdenoise.__version__ == header == mcdenoise.version()
    major, minor, patch = (int(p) for p in header.split("."))
    assert mcdenoise.version_number() == major * 10000 + minor * 100 + patch


def test_guide_vocabulary_is_the_guides_struct():
    """guide_fields names the fields of features.h's Guides struct, in order,
    and every name guides_used gives is one of them."""
    struct = re.search(r"struct Guides \{(.*?)\n\};", (HEADERS / "features.h").read_text(), re.S).group(1)
    fields = tuple(re.findall(r"const ImageBuf\* (\w+)\s*=", struct))
    assert fields == mcdenoise.guide_fields
    assert set(mcdenoise.guides_used) == {"cross_bilateral", "atrous", "nlmeans", "clamp_fireflies", "denoise",
                                          "denoise_network"}
    for function, used in mcdenoise.guides_used.items():
        assert used and set(used) <= set(fields), function
    assert mcdenoise.guides_used["clamp_fireflies"] == ("object_id",)
    assert mcdenoise.guides_used["denoise_network"] == ("normal", "albedo")


def test_argument_names_and_defaults_are_the_librarys():
    signature = mcdenoise.dof.__doc__.splitlines()[0]
    assert signature.startswith("dof(beauty: ")
    for part in ("object_id: ", "depth: ", "levels: int", "focus_level: int", "depth_near: float = 0.0",
                 "depth_far: float = 0.0", "roi: OpenImageIO.ROI = ROI.All", "nthreads: int = 0"):
        assert part in signature, (part, signature)
    assert f"size: int = {mcdenoise.default_window_size}" in mcdenoise.object_median.__doc__.splitlines()[0]
    image = random_image((9, 11, 3), 1)
    assert np.array_equal(mcdenoise.median(image),
                          mcdenoise.median(beauty=image, size=mcdenoise.default_window_size, nthreads=1))
    with pytest.raises(TypeError):
        mcdenoise.median(image, width=3)


@pytest.mark.parametrize("command", list(CASES))
def test_numpy_and_imagebuf_equal_mcdtool(sequence, tmp_path, command):
    """Each filter through numpy and through ImageBuf gives bit for bit the
    beauty mcdtool writes for the same command on a testrender frame."""
    name, guide_channels, params = CASES[command]
    frame = frame_file(sequence, 1)
    out = tmp_path / "out.exr"
    r = mcdtool(frame, *command.split(), "-d", "float", "-o", out)
    assert r.returncode == 0, r.stderr
    expected_pixels, expected_spec = read_pixels(out)
    expected = channels(expected_pixels, expected_spec, ["R", "G", "B"])

    pixels, spec = read_pixels(frame)
    beauty = channels(pixels, spec, ["R", "G", "B"])
    guides = {arg: image_argument(pixels, spec, names, lambda array: array)
              for arg, names in guide_channels.items()}
    function = getattr(mcdenoise, name)

    from_numpy = function(beauty, **guides, **params)
    assert isinstance(from_numpy, np.ndarray) and from_numpy.dtype == np.float32
    assert from_numpy.tobytes() == expected.tobytes()

    guide_bufs = {arg: image_argument(pixels, spec, names, as_imagebuf) for arg, names in guide_channels.items()}
    from_imagebuf = function(as_imagebuf(beauty), **guide_bufs, **params)
    assert type(from_imagebuf) is oiio.ImageBuf
    assert from_imagebuf.get_pixels(oiio.FLOAT).tobytes() == expected.tobytes()


def test_feature_guided_filters_take_a_guides_dict(sequence):
    """cross_bilateral, atrous, nlmeans, clamp_fireflies and denoise take
    the library's Guides fields as a dict; numpy and ImageBuf agree, the
    guides change the result, and FeatureSigmas is the library's struct."""
    pixels, spec = read_pixels(frame_file(sequence, 2))
    beauty = channels(pixels, spec, ["R", "G", "B"])
    guides = {"object_id": channels(pixels, spec, ["id"]),
              "normal": channels(pixels, spec, ["N.X", "N.Y", "N.Z"]),
              "depth": channels(pixels, spec, ["Z"]),
              "albedo": channels(pixels, spec, ["albedo.R", "albedo.G", "albedo.B"]),
              "variance": channels(pixels, spec, ["var.R", "var.G", "var.B"])}
    calls = {
        "cross_bilateral": dict(size=5, sigma_spatial=1.5, sigmas=mcdenoise.FeatureSigmas(albedo=0.2, depth=0.5)),
        "atrous": dict(iterations=2),
        "nlmeans": dict(search_radius=3, patch_radius=1),
        "clamp_fireflies": dict(factor=2.0, radius=2),
        "denoise": {},
    }
    for name, params in calls.items():
        function = getattr(mcdenoise, name)
        from_numpy = function(beauty, guides, **params)
        from_imagebuf = function(as_imagebuf(beauty), {k: as_imagebuf(v) for k, v in guides.items()},
                                 **params)
        assert from_numpy.tobytes() == from_imagebuf.get_pixels(oiio.FLOAT).tobytes(), name
        assert from_numpy.shape == beauty.shape
        if name != "clamp_fireflies":
            assert not np.array_equal(from_numpy, function(beauty, {}, **params)), name
    assert np.array_equal(mcdenoise.denoise(beauty), mcdenoise.denoise(beauty, guides=None))
    assert np.array_equal(mcdenoise.atrous(beauty, {"normal": None}), mcdenoise.atrous(beauty, {}))
    assert repr(mcdenoise.FeatureSigmas()) == "FeatureSigmas(albedo=0.1, normal=0.3, depth=0.1)"
    with pytest.raises(ValueError, match="unknown guide 'normals'"):
        mcdenoise.atrous(beauty, {"normals": guides["normal"]})
    with pytest.raises(TypeError, match="'depth' must be"):
        mcdenoise.atrous(beauty, {"depth": "Z"})
    epsilon = mcdenoise.default_demodulate_epsilon
    demodulated = mcdenoise.demodulate(beauty, guides["albedo"], epsilon=epsilon)
    remodulated = mcdenoise.remodulate(demodulated, guides["albedo"], epsilon=epsilon)
    assert np.allclose(remodulated, beauty, rtol=1e-5, atol=1e-6)


def test_imagebuf_is_openimageio_type_and_keeps_data_window():
    """The result is a real OpenImageIO.ImageBuf (shared pybind11 type), and
    an ImageBuf with an offset data window is filtered where it is."""
    image = random_image((6, 8, 3), 2)
    spec = oiio.ImageSpec(8, 6, 3, oiio.FLOAT)
    spec.x, spec.y = 10, 20
    buf = oiio.ImageBuf(spec)
    buf.set_pixels(oiio.ROI(), image)
    result = mcdenoise.gaussian(buf, size=3)
    assert isinstance(result, oiio.ImageBuf)
    assert (result.roi.xbegin, result.roi.ybegin, result.roi.xend, result.roi.yend) == (10, 20, 18, 26)
    assert oiio.ImageBufAlgo.compare(result, as_imagebuf_at(mcdenoise.gaussian(image, size=3), 10, 20),
                                     0.0, 0.0).nfail == 0


def as_imagebuf_at(array, x, y):
    """`array` as an ImageBuf whose data window starts at (x, y)."""
    h, w, c = array.shape
    spec = oiio.ImageSpec(w, h, c, oiio.FLOAT)
    spec.x, spec.y = x, y
    buf = oiio.ImageBuf(spec)
    buf.set_pixels(oiio.ROI(), array)
    return buf


def test_numpy_shapes_and_types():
    gray = random_image((7, 9), 3)
    result = mcdenoise.median(gray, size=3)
    assert result.shape == (7, 9)
    assert np.array_equal(result, mcdenoise.median(gray[..., None], size=3)[..., 0])
    as_float64 = mcdenoise.mean(gray.astype(np.float64), size=3)
    assert as_float64.dtype == np.float32 and np.array_equal(as_float64, mcdenoise.mean(gray, size=3))
    strided = random_image((7, 18, 3), 4)[:, ::2]
    assert np.array_equal(mcdenoise.gaussian(strided), mcdenoise.gaussian(np.ascontiguousarray(strided)))


def test_metrics():
    reference = np.clip(random_image((16, 16, 3), 5), 0.0, 0.8)  # within [0, 1] with the error: PSNR's clamp keeps it
    noisy = reference + np.float32(0.1)
    comparison = mcdenoise.compare_images(noisy, reference)
    assert isinstance(comparison, mcdenoise.ImageComparison) and comparison.ok
    assert comparison.pixels == 256 and comparison.nonfinite == 0
    assert comparison.mse == pytest.approx(0.01, rel=1e-5)
    assert mcdenoise.mse(noisy, reference) == comparison.mse
    assert mcdenoise.psnr(noisy, reference) == pytest.approx(20.0, rel=1e-5)
    assert mcdenoise.rel_mse(noisy, reference) == comparison.rel_mse
    assert mcdenoise.ssim(reference, reference) == 1.0


def test_library_errors_raise_with_the_librarys_message():
    image = random_image((8, 8, 3), 6)
    with pytest.raises(mcdenoise.Error, match="median: size must be odd, got 4"):
        mcdenoise.median(image, size=4)
    with pytest.raises(mcdenoise.Error, match="object_mean"):
        mcdenoise.object_mean(image, np.zeros((4, 4), np.float32), size=3)
    with pytest.raises(mcdenoise.Error, match="dof"):
        mcdenoise.dof(image, np.zeros((8, 8), np.float32), np.ones((8, 8), np.float32), levels=0, focus_level=0)
    with pytest.raises(mcdenoise.Error):
        mcdenoise.compare_images(image, random_image((4, 4, 3), 7))
    assert issubclass(mcdenoise.Error, RuntimeError)


def test_bad_arguments_raise():
    image = random_image((8, 8, 3), 8)
    with pytest.raises(ValueError, match="shape"):
        mcdenoise.median(np.zeros((2, 2, 2, 2), np.float32))
    with pytest.raises(ValueError, match="non-empty"):
        mcdenoise.median(np.zeros((0, 4, 3), np.float32))
    with pytest.raises(TypeError):
        mcdenoise.median("render.exr")
    with pytest.raises(TypeError):
        mcdenoise.median(image, size="three")
    with pytest.raises(TypeError):
        mcdenoise.object_median(image)


def test_gil_is_released_while_filtering():
    """Another Python thread keeps running while a long filter runs."""
    image = random_image((768, 768, 3), 9)
    span = {}
    ticks = []

    def filter_image():
        span["start"] = time.perf_counter()
        mcdenoise.median(image, size=9, nthreads=1)
        span["end"] = time.perf_counter()

    worker = threading.Thread(target=filter_image)
    worker.start()
    while worker.is_alive():
        ticks.append(time.perf_counter())
        time.sleep(0.001)
    worker.join()
    assert span["end"] - span["start"] > 0.05, "the filter was too quick to tell"
    during = [t for t in ticks if span["start"] + 0.01 < t < span["end"] - 0.01]
    assert len(during) >= 5, f"{len(during)} ticks in {span['end'] - span['start']:.3f} s of filtering"
