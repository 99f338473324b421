#!/usr/bin/python3
"""Numpy reference of OIDN 2.x's whole RT filter on an HDR beauty, as
mcdtool's --denoise runs it: autoexposure, the input and output processes
around the UNet, the prefiltering of the guides and the choice of weights.
Written from OIDN 2.4.1's source (core/rt_filter.cpp, core/unet_filter.cpp,
core/color.h, devices/cpu/color.ispc, cpu_autoexposure.*,
cpu_input_process.isph, cpu_output_process.isph); the network and the .tza
reader are tests/network/unet_reference.py's.

- Autoexposure (colour only): NaN to 0, clamp [0, FLT_MAX], luminance
  0.212671 R + 0.715160 G + 0.072169 B, averaged over ceil(H/16) x ceil(W/16)
  bins whose edges are i*H/bins (integer division); the bins whose mean is
  above 1e-8 give scale = 0.18 / 2^(mean of log2 of their means), 1 if none.
- Colour in: x scale, NaN to 0, clamp [0, FLT_MAX], PU(x) / PU(65504).
  Albedo in: NaN to 0, clamp [0, 1]. Normal in: NaN to 0, clamp [-1, 1],
  x0.5+0.5. The tensor is [colour, albedo, normal], zero padded at the
  bottom and right to multiples of 16 (one tile: images under 2160x2160).
- Colour out: NaN to 0, clamp [0, FLT_MAX], PU^-1(x PU(65504)), x (1/scale).
- Prefilter (OIDN's cleanAux, Blender's "Accurate"): each guide through its
  own filter first. Albedo alone: rt_alb*, sRGB transfer (in: clamp [0, 1],
  sRGB; out: clamp >= 0, sRGB^-1, min 1). Normal alone: rt_nrm*, linear
  (in: clamp [-1, 1], x0.5+0.5; out: clamp >= 0, x2-1, clamp [-1, 1]).
- Weights, as UNetFilter::getWeights picks them: colour with both guides
  rt_hdr_calb_cnrm (prefiltered) or rt_hdr_alb_nrm, with albedo only
  rt_hdr_alb, alone rt_hdr (a normal without albedo has no network). High
  takes the _large file where there is one, balanced the base file, fast the
  _small file where there is one (rt_alb and rt_nrm have none).

Everything in float32, as OIDN computes it on the CPU, except the mean of
the bins' log2 (float64).

The image: bare R,G,B (the beauty) and the guides mcdtool finds in the same
(unnamed) layer: albedo as albedo, Denoising Albedo, denoise_albedo or
diffuse_albedo; normal as N, Normal or Denoising Normal (case ignored), each
with components R,G,B or X,Y,Z. The output holds R,G,B in float.

Usage: /usr/bin/python3 tests/network/rt_pipeline_reference.py --weights-dir DIR
           [--quality fast|balanced|high] [--no-prefilter] IN.exr OUT.exr
"""

import argparse
import functools
import os
import sys

import numpy as np
import OpenImageIO as oiio

import unet_reference as unet

Failure = unet.Failure

FLT_MAX = np.finfo(np.float32).max
QUALITIES = ("fast", "balanced", "high")

# The files of each network: base, small, large (None: there is none).
MODELS = {
    "hdr": ("rt_hdr", "rt_hdr_small", None),
    "hdr_alb": ("rt_hdr_alb", "rt_hdr_alb_small", None),
    "hdr_alb_nrm": ("rt_hdr_alb_nrm", "rt_hdr_alb_nrm_small", None),
    "hdr_calb_cnrm": ("rt_hdr_calb_cnrm", "rt_hdr_calb_cnrm_small", "rt_hdr_calb_cnrm_large"),
    "alb": ("rt_alb", None, "rt_alb_large"),
    "nrm": ("rt_nrm", None, "rt_nrm_large"),
}

# The guides' pass names, preferred first, as mcdtool's role table has them.
GUIDE_PASSES = {
    "albedo": ("albedo", "Denoising Albedo", "denoise_albedo", "diffuse_albedo"),
    "normal": ("N", "Normal", "Denoising Normal"),
}
COMPONENTS = (("R", "G", "B"), ("X", "Y", "Z"))

# PU: a fit of the PU2 curve normalised at 100 cd/m^2.
PU_A, PU_B, PU_C, PU_D = map(np.float32, (1.41283765e+03, 1.64593172e+00, 4.31384981e-01, -2.94139609e-03))
PU_E, PU_F, PU_G = map(np.float32, (1.92653254e-01, 6.26026094e-03, 9.98620152e-01))
PU_Y0, PU_Y1 = np.float32(1.57945760e-06), np.float32(3.22087631e-02)
PU_X0, PU_X1 = np.float32(2.23151711e-03), np.float32(3.70974749e-01)
# sRGB
SRGB_A, SRGB_B, SRGB_C, SRGB_D = map(np.float32, (12.92, 1.055, 1 / 2.4, -0.055))
SRGB_Y0, SRGB_X0 = np.float32(0.0031308), np.float32(0.04045)

LUMINANCE = np.array([0.212671, 0.715160, 0.072169], np.float32)
AUTOEXPOSURE_BIN = 16
AUTOEXPOSURE_KEY = 0.18
AUTOEXPOSURE_EPS = np.float32(1e-8)
ALIGNMENT = 16  # the tensor's spatial alignment (the network pools 4 times)


def pu_forward(y):
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(y <= PU_Y0, PU_A * y,
                        np.where(y <= PU_Y1, PU_B * np.power(y, PU_C) + PU_D,
                                 PU_E * np.log(y + PU_F) + PU_G)).astype(np.float32)


def pu_inverse(x):
    with np.errstate(invalid="ignore", over="ignore"):
        return np.where(x <= PU_X0, x / PU_A,
                        np.where(x <= PU_X1, np.power((x - PU_D) / PU_B, np.float32(1) / PU_C),
                                 np.exp((x - PU_G) / PU_E) - PU_F)).astype(np.float32)


def srgb_forward(y):
    with np.errstate(invalid="ignore"):
        return np.where(y <= SRGB_Y0, SRGB_A * y, SRGB_B * np.power(y, SRGB_C) + SRGB_D).astype(np.float32)


def srgb_inverse(x):
    with np.errstate(invalid="ignore", over="ignore"):
        return np.where(x <= SRGB_X0, x / SRGB_A,
                        np.power((x - SRGB_D) / SRGB_B, np.float32(1) / SRGB_C)).astype(np.float32)


# PU(65504), the largest half value: the colour tensor's 1.
PU_MAX = np.float32(pu_forward(np.float32(65504)))
PU_NORM = np.float32(1.0 / float(PU_MAX))


def sanitise(x, low, high):
    """NaN to 0, then clamped to [low, high]."""
    return np.clip(np.where(np.isnan(x), np.float32(0), x), low, high).astype(np.float32)


def autoexposure(color):
    """OIDN's input scale for an HDR colour image (H x W x 3)."""
    h, w, _ = color.shape
    luminance = sanitise(color, 0, FLT_MAX) @ LUMINANCE
    bins_h, bins_w = -(-h // AUTOEXPOSURE_BIN), -(-w // AUTOEXPOSURE_BIN)
    edges_h = np.array([i * h // bins_h for i in range(bins_h + 1)])
    edges_w = np.array([j * w // bins_w for j in range(bins_w + 1)])
    with np.errstate(over="ignore"):  # a bin of several FLT_MAX pixels sums to inf, as in OIDN
        sums = np.add.reduceat(np.add.reduceat(luminance, edges_h[:-1], axis=0), edges_w[:-1], axis=1)
    means = (sums / np.outer(np.diff(edges_h), np.diff(edges_w)).astype(np.float32)).astype(np.float32)
    kept = means[means > AUTOEXPOSURE_EPS]
    if kept.size == 0:
        return np.float32(1)
    return np.float32(AUTOEXPOSURE_KEY / np.exp2(np.mean(np.log2(kept.astype(np.float64)))))


def select_weights(model, quality):
    """The file name (no .tza) OIDN takes for MODEL at QUALITY."""
    base, small, large = MODELS[model]
    return {"high": large or base, "balanced": base, "fast": small or base}[quality]


def networks(quality, prefilter, albedo, normal):
    """{"albedo", "normal", "beauty": weight file name} of the filters that
    run, for a beauty with or without each guide."""
    if quality not in QUALITIES:
        raise Failure(f"quality {quality!r}: not one of {', '.join(QUALITIES)}")
    if normal and not albedo:
        raise Failure("a normal without an albedo: OIDN has no network for colour and normal alone")
    chosen = {}
    if prefilter and albedo:
        chosen["albedo"] = select_weights("alb", quality)
    if prefilter and normal:
        chosen["normal"] = select_weights("nrm", quality)
    if albedo and normal:
        beauty = "hdr_calb_cnrm" if prefilter else "hdr_alb_nrm"
    else:
        beauty = "hdr_alb" if albedo else "hdr"
    chosen["beauty"] = select_weights(beauty, quality)
    return chosen


@functools.lru_cache(maxsize=None)
def load_weights(weights_dir, name):
    path = os.path.join(weights_dir, name + ".tza")
    if not os.path.isfile(path):
        raise Failure(f"{path} is missing: install the weights with scripts/fetch-weights --dest {weights_dir}")
    return unet.read_tza(path)


def run_network(tensors, x):
    """The network on the H x W x C tensor x, padded with zeros at the bottom
    and right to multiples of 16; its first 3 output channels, H x W."""
    h, w, c = x.shape
    padded = np.zeros((-(-h // ALIGNMENT) * ALIGNMENT, -(-w // ALIGNMENT) * ALIGNMENT, c), np.float32)
    padded[:h, :w] = x
    y = unet.run(tensors, padded)
    if y.shape[2] != 3:
        raise Failure(f"the network gives {y.shape[2]} channels, expected 3")
    return y[:h, :w]


def filter_albedo(tensors, albedo):
    """The albedo alone through its network (sRGB transfer, scale 1)."""
    y = run_network(tensors, srgb_forward(sanitise(albedo, 0, 1)))
    return np.minimum(srgb_inverse(sanitise(y, 0, FLT_MAX)), np.float32(1))


def filter_normal(tensors, normal):
    """The normal alone through its network (linear transfer, signed)."""
    y = run_network(tensors, sanitise(normal, -1, 1) * np.float32(0.5) + np.float32(0.5))
    return np.clip(sanitise(y, 0, FLT_MAX) * np.float32(2) - np.float32(1), -1, 1).astype(np.float32)


def filter_beauty(tensors, color, albedo, normal):
    """The HDR colour, with the guides given, through its network."""
    scale = autoexposure(color)
    with np.errstate(invalid="ignore"):  # inf x 0 is NaN, then 0
        planes = [pu_forward(sanitise(color * scale, 0, FLT_MAX)) * PU_NORM]
    if albedo is not None:
        planes.append(sanitise(albedo, 0, 1))
    if normal is not None:
        planes.append(sanitise(normal, -1, 1) * np.float32(0.5) + np.float32(0.5))
    y = run_network(tensors, np.concatenate(planes, axis=2))
    output_scale = np.float32(1) / scale if scale != 0 else np.float32(0)
    return pu_inverse(sanitise(y, 0, FLT_MAX) * PU_MAX) * output_scale


def denoise(weights_dir, quality, prefilter, color, albedo=None, normal=None):
    """The denoised colour (H x W x 3 float32) of COLOR with the guides given
    (H x W x 3 each, or None), as OIDN's RT filter in HDR mode gives it."""
    chosen = networks(quality, prefilter, albedo is not None, normal is not None)
    if "albedo" in chosen:
        albedo = filter_albedo(load_weights(weights_dir, chosen["albedo"]), albedo)
    if "normal" in chosen:
        normal = filter_normal(load_weights(weights_dir, chosen["normal"]), normal)
    return filter_beauty(load_weights(weights_dir, chosen["beauty"]), color, albedo, normal)


def find_channels(names):
    """{"beauty": [R, G, B], "albedo": [...], "normal": [...]} channel
    indices; a guide not in NAMES is left out."""
    index = {name: i for i, name in enumerate(names)}
    missing = [c for c in ("R", "G", "B") if c not in index]
    if missing:
        raise Failure(f"no beauty channel {', '.join(missing)} (channels: {', '.join(names)})")
    found = {"beauty": [index[c] for c in ("R", "G", "B")]}
    for role, passes in GUIDE_PASSES.items():
        for pass_name in passes:
            components = {}
            for i, name in enumerate(names):
                head, dot, component = name.rpartition(".")
                if dot and "." not in head and head.lower() == pass_name.lower():
                    components[component] = i
            order = next((o for o in COMPONENTS if set(o) == set(components)), None)
            if order:
                found[role] = [components[c] for c in order]
                break
    return found


def read_image(path):
    """{"beauty", "albedo", "normal": H x W x 3 float32} of an image (a guide
    it lacks is left out)."""
    buf = oiio.ImageBuf(path)
    pixels = buf.get_pixels(oiio.FLOAT)
    if buf.has_error or pixels is None or pixels.size == 0:
        raise Failure(f"cannot read {path}: {buf.geterror() or 'no pixels'}")
    spec = buf.spec()
    pixels = pixels.reshape(spec.height, spec.width, spec.nchannels)
    return {role: np.ascontiguousarray(pixels[:, :, idx])
            for role, idx in find_channels(list(spec.channelnames)).items()}


def write_image(path, rgb):
    h, w, _ = rgb.shape
    spec = oiio.ImageSpec(w, h, 3, oiio.FLOAT)
    spec.channelnames = ("R", "G", "B")
    buf = oiio.ImageBuf(spec)
    if not buf.set_pixels(oiio.ROI(0, w, 0, h, 0, 1, 0, 3), np.ascontiguousarray(rgb, np.float32)) \
            or not buf.write(path):
        raise Failure(f"cannot write {path}: {buf.geterror()}")


def main(argv):
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__.split("\n\n", 1)[1])
    parser.add_argument("--weights-dir", metavar="DIR", required=True,
                        help="the folder of OIDN 2.x's rt_*.tza files (scripts/fetch-weights)")
    parser.add_argument("--quality", choices=QUALITIES, default="high")
    parser.add_argument("--no-prefilter", action="store_true",
                        help="the guides go to the network as they are (no cleanAux)")
    parser.add_argument("input", metavar="IN.exr")
    parser.add_argument("output", metavar="OUT.exr")
    args = parser.parse_args(argv)
    try:
        planes = read_image(args.input)
        denoised = denoise(args.weights_dir, args.quality, not args.no_prefilter, planes["beauty"],
                           planes.get("albedo"), planes.get("normal"))
        write_image(args.output, denoised)
    except (Failure, OSError) as e:
        print(f"rt_pipeline_reference: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
