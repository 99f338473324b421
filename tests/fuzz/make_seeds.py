"""Writes the committed seed corpora of the fuzz targets (tests/fuzz/corpus/):
command lines for `driver` (one argument per line, naming the files its
scratch directory holds), small EXR files of every kind for `exr`, and byte
strings for `filter`, and small hand-made .tza files (valid and broken, never
the real weights) for `tza`. Run once with /usr/bin/python3 when a target's input
format changes; the fuzzer grows its own corpus from these in build-fuzz/."""
import os
import random
import struct

import numpy as np
import OpenImageIO as oiio

HERE = os.path.dirname(os.path.abspath(__file__))

DRIVER_SEEDS = {
    "median": ["render.exr", "--median", "3", "-o", "out.exr"],
    "chain": ["render.exr", "--object-median", "7", "--gaussian", "3", "-o", "out.exr"],
    "brdf": ["render.exr", "--brdf-median", "5", "--brdf-gaussian", "3", "-o", "a.exr", "-o", "b.png"],
    "normal": ["render.exr", "--aov", "id=ids.exr", "--aov", "normal=normal.exr", "--normal-mean", "5",
               "-o", "out.exr", "-d", "float", "--compression", "zip"],
    "dof": ["cycles.exr", "--dof-range", "4", "1", "1.5", "20", "-o", "out.exr", "--threads", "2"],
    "dof_levels": ["cycles.exr", "--dof", "10", "0", "--compare", "ref.exr", "-o", "out.exr"],
    "cycles_beauty": ["cycles.exr", "--beauty", "View Layer.Combined", "--mean", "9", "-o", "out.exr", "-v"],
    "sequence": ["shot.####.exr", "--frames", "1-2", "--median", "3", "-o", "clean.####.exr", "--runstats"],
    "skip": ["shot.%04d.exr", "--frames", "2,1", "--skip-existing", "--gaussian", "5", "-o", "c.%04d.exr"],
    "preview": ["render.exr", "--median", "3", "--preview", "p.png", "--compare", "ref.exr"],
    "force": ["render.exr", "--median", "3", "-o", "render.exr", "--force"],
    "bad_guide": ["render.exr", "--aov", "id=small_ids.exr", "--object-mean", "3", "-o", "out.exr"],
    "png": ["small.png", "--median", "5", "-o", "out.png"],
    "limit": ["render.exr", "--memory-limit", "1", "--median", "3", "-o", "out.exr"],
    "help": ["--help"],
    "bad_size": ["render.exr", "--median", "257", "-o", "out.exr"],
}


def write_driver_seeds():
    for name, args in DRIVER_SEEDS.items():
        with open(os.path.join(HERE, "corpus", "driver", name), "w") as f:
            f.write("\n".join(args))


def write_exr(path, width, height, names, fmt, compression, origin=(0, 0), tile=None, seed=0):
    rng = np.random.default_rng(seed)
    spec = oiio.ImageSpec(width, height, len(names), fmt)
    spec.channelnames = tuple(names)
    spec.x, spec.y = origin
    spec.attribute("compression", compression)
    if tile:
        spec.tile_width, spec.tile_height = tile
    buf = oiio.ImageBuf(spec)
    pixels = rng.uniform(0.0, 2.0, (height, width, len(names))).astype(np.float32)
    pixels[0, 0, 0] = np.nan
    buf.set_pixels(oiio.ROI(), pixels)
    assert buf.write(path), oiio.geterror()


def write_exr_seeds():
    out = os.path.join(HERE, "corpus", "exr")
    testrender = ["R", "G", "B", "A", "id", "reflid", "N.X", "N.Y", "N.Z", "Z"]
    cycles = ["L.Combined.R", "L.Combined.G", "L.Combined.B", "L.IndexOB.X", "L.Depth.Z"]
    write_exr(os.path.join(out, "rgb_half_none.exr"), 6, 5, ["R", "G", "B"], "half", "none")
    write_exr(os.path.join(out, "rgba_float_zip.exr"), 7, 4, ["R", "G", "B", "A"], "float", "zip",
              origin=(-2, 3))
    write_exr(os.path.join(out, "testrender_piz.exr"), 8, 6, testrender, "half", "piz")
    write_exr(os.path.join(out, "cycles_zips.exr"), 5, 5, cycles, "float", "zips")
    write_exr(os.path.join(out, "rgb_rle_tiled.exr"), 9, 7, ["R", "G", "B"], "half", "rle", tile=(4, 4))
    write_exr(os.path.join(out, "y_pxr24.exr"), 6, 6, ["Y"], "float", "pxr24", origin=(10, -4))
    write_exr(os.path.join(out, "rgb_b44.exr"), 8, 8, ["R", "G", "B"], "half", "b44")
    write_exr(os.path.join(out, "rgb_dwaa.exr"), 8, 8, ["R", "G", "B"], "half", "dwaa")


def write_filter_seeds():
    rng = random.Random(9)
    out = os.path.join(HERE, "corpus", "filter")
    for i, length in enumerate([16, 64, 256, 1024, 4096]):
        with open(os.path.join(out, f"random_{i}"), "wb") as f:
            f.write(bytes(rng.randrange(256) for _ in range(length)))


def tza_bytes(tensors, magic=0x41D7, version=(2, 0), table_offset=None):
    """A .tza file (OIDN 2.x, docs/network.md): the header, every tensor's
    data, then the table; each tensor is (name, dims, layout, dtype, data)."""
    out = bytearray(struct.pack("<HBBQ", magic, version[0], version[1], 0))
    offsets = []
    for _, _, _, _, data in tensors:
        offsets.append(len(out))
        out += data
    table = len(out) if table_offset is None else table_offset
    out[4:12] = struct.pack("<Q", table)
    out += struct.pack("<I", len(tensors))
    for (name, dims, layout, dtype, _), offset in zip(tensors, offsets):
        encoded = name.encode()
        out += struct.pack("<H", len(encoded)) + encoded + struct.pack("<B", len(dims))
        out += struct.pack("<%dI" % len(dims), *dims) + layout.encode() + dtype.encode()
        out += struct.pack("<Q", offset)
    return bytes(out)


def write_tza_seeds():
    out = os.path.join(HERE, "corpus", "tza")
    os.makedirs(out, exist_ok=True)
    rng = random.Random(3)
    weight = struct.pack("<18f", *[rng.uniform(-1, 1) for _ in range(18)])
    halves = struct.pack("<18e", *[rng.uniform(-1, 1) for _ in range(18)])
    valid = [("enc_conv0.weight", (2, 1, 3, 3), "oihw", "f", weight),
             ("enc_conv0.bias", (2,), "x", "h", struct.pack("<2e", 0.5, -0.25))]
    special = struct.pack("<6H", 0x0001, 0x03FF, 0x7C00, 0xFC00, 0x7E01, 0x8000)  # subnormals, infinities, NaN, -0
    seeds = {
        "valid_float32.tza": tza_bytes(valid),
        "valid_float16.tza": tza_bytes([("dec_conv0.weight", (1, 2, 3, 3), "oihw", "h", halves),
                                        ("dec_conv0.bias", (6,), "x", "h", special)]),
        "empty_table.tza": tza_bytes([]),
        "bad_magic.tza": tza_bytes(valid, magic=0x1234),
        "bad_version.tza": tza_bytes(valid, version=(1, 0)),
        "table_past_end.tza": tza_bytes(valid, table_offset=4096),
        "truncated.tza": tza_bytes(valid)[:-5],
        "duplicate.tza": tza_bytes([valid[0], valid[0]]),
        "bad_dtype.tza": tza_bytes([("w", (2,), "x", "d", weight)]),
        "bad_layout.tza": tza_bytes([("w", (2, 9), "oi", "f", weight)]),
        "zero_dim.tza": tza_bytes([("w", (0,), "x", "f", b"")]),
        "data_past_end.tza": tza_bytes([("w", (1000,), "x", "f", weight)]),
    }
    for name, data in seeds.items():
        with open(os.path.join(out, name), "wb") as f:
            f.write(data)


if __name__ == "__main__":
    for target in ("driver", "exr", "filter", "tza"):
        os.makedirs(os.path.join(HERE, "corpus", target), exist_ok=True)
    write_driver_seeds()
    write_exr_seeds()
    write_filter_seeds()
    write_tza_seeds()
