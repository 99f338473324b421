#!/usr/bin/python3
"""Brute-force numpy reference of OIDN 2.x's UNets (base, small and large),
straight from a .tza weights file: the second independent reference of
tests/network/check_unet.py, and the only one for the large network.

Its own .tza 2.0 reader; every convolution 3x3, padding 1, plus bias, then
ReLU (the last one too, as OIDN 2.x's C++ graph does); 2x2 max pooling with
stride 2; 2x nearest upsampling; each decoder level convolves
[upsampled, skip] concatenated along the channels. The architecture is told
by the tensor names (enc_conv0: base or small, which differ only in their
widths, taken from the file; enc_conv1a: large) and every shape is checked.
Float32 throughout; a convolution is one matmul of the 9 shifted copies of
its padded input (im2col) against the weights.

No transfer function, exposure, clamping or padding: the input file is the
network's input tensor, the output the last convolution's, after its ReLU.
Tensor files: little-endian int32 height, width, channels, then
height*width*channels float32 in HWC order (channel fastest, then x, y).

Usage: /usr/bin/python3 tests/network/unet_reference.py WEIGHTS.tza INPUT.bin OUTPUT.bin
"""

import struct
import sys

import numpy as np

# The layers in the order they run. ("conv", name), ("pool", skip or None):
# pool and, with a name, keep the result as that skip; ("up", skip): upsample
# and concatenate [upsampled, skip] ("input" is the network's input).
BASE = [
    ("conv", "enc_conv0"), ("conv", "enc_conv1"), ("pool", "pool1"),
    ("conv", "enc_conv2"), ("pool", "pool2"),
    ("conv", "enc_conv3"), ("pool", "pool3"),
    ("conv", "enc_conv4"), ("pool", None),
    ("conv", "enc_conv5a"), ("conv", "enc_conv5b"),
    ("up", "pool3"), ("conv", "dec_conv4a"), ("conv", "dec_conv4b"),
    ("up", "pool2"), ("conv", "dec_conv3a"), ("conv", "dec_conv3b"),
    ("up", "pool1"), ("conv", "dec_conv2a"), ("conv", "dec_conv2b"),
    ("up", "input"), ("conv", "dec_conv1a"), ("conv", "dec_conv1b"),
    ("conv", "dec_conv0"),
]
LARGE = [
    ("conv", "enc_conv1a"), ("conv", "enc_conv1b"), ("pool", "pool1"),
    ("conv", "enc_conv2a"), ("conv", "enc_conv2b"), ("pool", "pool2"),
    ("conv", "enc_conv3a"), ("conv", "enc_conv3b"), ("pool", "pool3"),
    ("conv", "enc_conv4a"), ("conv", "enc_conv4b"), ("pool", None),
    ("conv", "enc_conv5a"), ("conv", "enc_conv5b"),
    ("up", "pool3"), ("conv", "dec_conv4a"), ("conv", "dec_conv4b"),
    ("up", "pool2"), ("conv", "dec_conv3a"), ("conv", "dec_conv3b"),
    ("up", "pool1"), ("conv", "dec_conv2a"), ("conv", "dec_conv2b"),
    ("up", "input"), ("conv", "dec_conv1a"), ("conv", "dec_conv1b"),
    ("conv", "dec_conv1c"),
]


class Failure(Exception):
    pass


def read_tza(path):
    """{name: float32 array} of a .tza 2.0 file (weights OIHW, biases X)."""
    with open(path, "rb") as f:
        blob = f.read()

    def unpack(fmt, offset):
        size = struct.calcsize(fmt)
        if offset + size > len(blob):
            raise Failure(f"{path}: truncated at byte {offset}")
        return struct.unpack_from(fmt, blob, offset), offset + size

    (magic, major, minor, table), _ = unpack("<HBBQ", 0)
    if magic != 0x41D7:
        raise Failure(f"{path}: magic {magic:#06x}, not a .tza file (0x41d7)")
    if (major, minor) != (2, 0):
        raise Failure(f"{path}: .tza version {major}.{minor}, expected 2.0")
    (count,), offset = unpack("<I", table)
    tensors = {}
    for _ in range(count):
        (name_len,), offset = unpack("<H", offset)
        name = blob[offset:offset + name_len].decode()
        offset += name_len
        (ndims,), offset = unpack("<B", offset)
        dims, offset = unpack(f"<{ndims}I", offset)
        layout = blob[offset:offset + ndims].decode()
        offset += ndims
        (dtype, data), offset = unpack("<cQ", offset)
        expected = {4: "oihw", 1: "x"}.get(ndims)
        if layout != expected:
            raise Failure(f"{path}: tensor {name!r} has layout {layout!r}, expected {expected!r}")
        types = {b"f": "<f4", b"h": "<f2"}
        if dtype not in types:
            raise Failure(f"{path}: tensor {name!r} has data type {dtype!r}, expected 'f' or 'h'")
        n = int(np.prod(dims))
        end = data + n * np.dtype(types[dtype]).itemsize
        if end > len(blob):
            raise Failure(f"{path}: tensor {name!r}: data runs past the end of the file")
        values = np.frombuffer(blob, types[dtype], n, data).astype(np.float32)
        tensors[name] = values.reshape(dims)
    return tensors


def read_tensor(path):
    with open(path, "rb") as f:
        blob = f.read()
    if len(blob) < 12:
        raise Failure(f"{path}: shorter than its 12-byte header")
    h, w, c = struct.unpack_from("<3i", blob)
    if min(h, w, c) <= 0 or len(blob) != 12 + 4 * h * w * c:
        raise Failure(f"{path}: {len(blob)} bytes do not hold a {h}x{w}x{c} float32 tensor")
    return np.frombuffer(blob, "<f4", h * w * c, 12).reshape(h, w, c).astype(np.float32)


def write_tensor(path, x):
    h, w, c = x.shape
    with open(path, "wb") as f:
        f.write(struct.pack("<3i", h, w, c))
        f.write(np.ascontiguousarray(x, "<f4").tobytes())


def conv_relu(x, weight, bias):
    """3x3 convolution, zero padding 1, plus bias, then ReLU; x is HWC."""
    h, w, c = x.shape
    o = weight.shape[0]
    padded = np.pad(x, ((1, 1), (1, 1), (0, 0)))
    # columns[y, x, (ky, kx, c)] = padded[y + ky, x + kx, c]
    columns = np.concatenate(
        [padded[ky:ky + h, kx:kx + w, :] for ky in range(3) for kx in range(3)], axis=2)
    kernel = weight.transpose(2, 3, 1, 0).reshape(9 * c, o)  # (ky, kx, i) x o
    y = columns.reshape(h * w, 9 * c) @ kernel + bias
    return np.maximum(y, 0, dtype=np.float32).reshape(h, w, o)


def pool(x):
    h, w, c = x.shape
    return x.reshape(h // 2, 2, w // 2, 2, c).max(axis=(1, 3))


def upsample(x):
    return x.repeat(2, axis=0).repeat(2, axis=1)


def run(tensors, x):
    """The network's output for the HWC input x."""
    if "enc_conv0.weight" in tensors:
        layers = BASE
    elif "enc_conv1a.weight" in tensors:
        layers = LARGE
    else:
        raise Failure("neither enc_conv0.weight (base, small) nor enc_conv1a.weight (large): not an OIDN UNet")
    used = {f"{name}.{part}" for kind, name in layers if kind == "conv" for part in ("weight", "bias")}
    missing = sorted(used - tensors.keys())
    extra = sorted(tensors.keys() - used)
    if missing or extra:
        raise Failure(f"tensors missing: {missing}, not used: {extra}")
    h, w, _ = x.shape
    if h % 16 or w % 16:
        raise Failure(f"input {h}x{w} is not a multiple of 16 (the network pools 4 times)")
    skips = {"input": x}
    for kind, name in layers:
        if kind == "conv":
            weight, bias = tensors[f"{name}.weight"], tensors[f"{name}.bias"]
            if weight.shape[1:] != (x.shape[2], 3, 3) or bias.shape != (weight.shape[0],):
                raise Failure(f"{name}: weight {weight.shape} and bias {bias.shape} "
                              f"do not fit an input of {x.shape[2]} channels")
            x = conv_relu(x, weight, bias)
        elif kind == "pool":
            x = pool(x)
            if name:
                skips[name] = x
        else:
            x = np.concatenate([upsample(x), skips[name]], axis=2)
    return x


def main(argv):
    if len(argv) != 3 or argv[0] in ("-h", "--help"):
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 0 if argv[:1] in (["-h"], ["--help"]) else 2
    weights, input_path, output_path = argv
    try:
        write_tensor(output_path, run(read_tza(weights), read_tensor(input_path)))
    except (Failure, OSError) as e:
        print(f"unet_reference: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
