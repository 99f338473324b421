"""mcdtool on multi-part OpenEXR files, as Arnold, RenderMan and Nuke write
them (the beauty and each AOV in a part of its own): the guides and light
passes are found across parts, and the output has the same parts, part
names, channel names, compression and pixel types, with only the beauty and
the light passes changed. Each test_* function is one CTest test."""
import numpy as np
import OpenImageIO as oiio

from conftest import check_failure, noisy_scene, run

RGB = "RGB"


def write_parts(path, parts, origins=None):
    """Writes `parts`, a list of (part name, channel names, H x W x C
    pixels, compression, pixel type), as one multi-part EXR."""
    specs = []
    for i, (name, names, pixels, compression, fmt) in enumerate(parts):
        h, w, c = pixels.shape
        spec = oiio.ImageSpec(w, h, c, fmt)
        spec.channelnames = tuple(names)
        spec.attribute("name", name)
        spec.attribute("compression", compression)
        if origins:
            spec.x, spec.y = origins[i]
        specs.append(spec)
    out = oiio.ImageOutput.create(str(path))
    assert out.open(str(path), tuple(specs)), out.geterror()
    for i, (_, _, pixels, _, _) in enumerate(parts):
        if i:
            assert out.open(str(path), specs[i], "AppendSubimage"), out.geterror()
        assert out.write_image(np.ascontiguousarray(pixels, np.float32)), out.geterror()
    out.close()
    return path


def read_parts(path):
    """[(part name, channel names, pixels, compression, channel types)]."""
    inp = oiio.ImageInput.open(str(path))
    assert inp, oiio.geterror()
    parts = []
    index = 0
    while inp.seek_subimage(index, 0):
        spec = inp.spec()
        parts.append((spec.getattribute("name"), list(spec.channelnames), inp.read_image(index, 0, 0, spec.nchannels,
                                                                                           "float"),
                      spec.getattribute("compression"), [str(t) for t in spec.channelformats] or [str(spec.format)]))
        index += 1
    inp.close()
    return parts


def arnold_parts(seed=7):
    """Arnold-style parts: RGBA beauty, two light groups that sum to it, a
    diffuse albedo, N and Z, each part with bare channel names."""
    beauty, ids, normal, depth = noisy_scene(seed=seed)
    share = np.random.default_rng(seed).uniform(0, 1, beauty.shape).astype(np.float32)
    alpha = np.ones(ids.shape + (1,), np.float32)
    rgba = lambda img: np.concatenate([img, alpha], axis=2)
    return [("rgba", list("RGBA"), rgba(beauty), "zip", "float"),
            ("RGBA_key", list("RGBA"), rgba(beauty * share), "piz", "float"),
            ("RGBA_fill", list("RGBA"), rgba(beauty * (1 - share)), "piz", "float"),
            ("diffuse_albedo", list(RGB), np.full(beauty.shape, 0.5, np.float32), "dwaa", "half"),
            ("N", list("XYZ"), normal, "zip", "half"),
            ("Z", ["Z"], depth[..., None], "zip", "float")]


def test_arnold_style_parts_are_read_and_written_as_parts(tmp_path):
    src = write_parts(tmp_path / "arnold.exr", arnold_parts())
    out = tmp_path / "clean.exr"
    r = run(src, "--aovs", "auto", "--denoise", "-v", "-o", out)
    assert r.code == 0, r
    assert "N.X,N.Y,N.Z" in r.out and "RGBA_key,RGBA_fill" in r.out, r.out
    before, after = read_parts(src), read_parts(out)
    assert [(p[0], p[1], p[3], p[4]) for p in after] == [(p[0], p[1], p[3], p[4]) for p in before]
    for (name, _, old, _, _), (_, _, new, _, _) in zip(before, after):
        if name in ("rgba", "RGBA_key", "RGBA_fill"):
            assert not np.array_equal(new[..., :3], old[..., :3]), name
            np.testing.assert_array_equal(new[..., 3], old[..., 3])
        else:
            np.testing.assert_array_equal(new, old, name)
    total = after[1][2][..., :3] + after[2][2][..., :3]
    beauty = after[0][2][..., :3]
    assert np.mean((total - beauty) ** 2 / (beauty ** 2 + 0.01)) <= 1e-6


def test_renderman_style_parts_find_guides_and_lobes_across_parts(tmp_path):
    """RenderMan-style parts (Ci, its mse and zfiltered denoise AOVs, the
    four lighting lobes that sum to Ci): the variance and depth guides and
    the lobes are found in their parts, and the denoised lobes sum to the
    denoised Ci."""
    beauty, ids, normal, depth = noisy_scene(seed=11)
    shares = np.random.default_rng(11).dirichlet(np.ones(4), size=beauty.shape).astype(np.float32)
    lobes = ["directDiffuse", "indirectDiffuse", "directSpecular", "indirectSpecular"]
    alpha = np.ones(ids.shape + (1,), np.float32)
    parts = [("Ci", list("RGBA"), np.concatenate([beauty, alpha], axis=2), "zip", "half")]
    parts += [(lobe, list(RGB), beauty * shares[..., i], "zip", "float") for i, lobe in enumerate(lobes)]
    parts += [("mse", list(RGB), np.full(beauty.shape, 0.04, np.float32), "zip", "half"),
              ("zfiltered", ["Z"], depth[..., None], "zip", "float"),
              ("N", list("XYZ"), normal, "zip", "half")]
    src = write_parts(tmp_path / "renderman.exr", parts)
    out = tmp_path / "clean.exr"
    r = run(src, "--aovs", "auto", "--denoise", "-v", "-o", out)
    assert r.code == 0, r
    assert "mse.R,mse.G,mse.B" in r.out and "zfiltered.Z" in r.out and ",".join(lobes) in r.out, r.out
    after = read_parts(out)
    assert [p[0] for p in after] == [p[0] for p in parts]
    total = sum(after[1 + i][2] for i in range(len(lobes)))
    written = after[0][2][..., :3]
    assert np.mean((total - written) ** 2 / (written ** 2 + 0.01)) <= 1e-6
    assert written.std() < beauty.std()


def test_nuke_style_parts_keep_their_layer_names(tmp_path):
    """Parts whose channels already carry the layer (diffuse.R) keep it."""
    beauty, ids, normal, depth = noisy_scene(seed=3)
    parts = [("rgba", list(RGB), beauty, "zip", "half"),
             ("diffuse", [f"diffuse.{c}" for c in RGB], beauty * 0.5, "zip", "half"),
             ("other", ["N.X", "N.Y", "N.Z", "id"], np.concatenate([normal, ids[..., None]], axis=2), "none",
              "float")]
    src = write_parts(tmp_path / "nuke.exr", parts)
    out = tmp_path / "clean.exr"
    r = run(src, "--median", "3", "-v", "-o", out)
    assert r.code == 0, r
    assert "normal   <- " in r.out and "N.X,N.Y,N.Z" in r.out, r.out
    before, after = read_parts(src), read_parts(out)
    assert [p[0] for p in after] == ["rgba", "diffuse", "other"]
    assert [p[1] for p in after] == [p[1] for p in before]
    assert [p[3] for p in after] == ["zip", "zip", "none"]
    np.testing.assert_array_equal(after[1][2], before[1][2])
    np.testing.assert_array_equal(after[2][2], before[2][2])
    assert not np.array_equal(after[0][2], before[0][2])


def test_parts_with_different_data_windows_are_refused_by_name(tmp_path):
    beauty, _, normal, _ = noisy_scene()
    src = write_parts(tmp_path / "bad.exr", [("rgba", list(RGB), beauty, "zip", "half"),
                                             ("N", list("XYZ"), normal, "zip", "half")],
                      origins=[(0, 0), (2, 0)])
    r = run(src, "--denoise", "-o", tmp_path / "clean.exr")
    check_failure(r, 1, "part 'N'", "window")
    assert not (tmp_path / "clean.exr").exists()
