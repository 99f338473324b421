#!/usr/bin/python3
"""cycles_pictures.py: docs/quality.md's pictures of what goes wrong on real
Cycles renders, raw | result | reference, from the results bench/render_table
left in BUILD_DIR/render_table/cycles_bench_set/cycles/ (with --small, of
the small set cycles_set/, as `bench/render_table --small` leaves them):

- glint.png: the dof still at 16 spp, `--denoise`, a crop around the sun
  glint on the chrome sphere (the reference's brightest GlossDir pixel);
- direct_pass.png: a direct-light pass of `--aovs auto --denoise` at 16 spp.

Usage: PYTHONPATH=build/python /usr/bin/python3 bench/cycles_pictures.py BUILD_DIR OUT_DIR [--small] [SCENE PASS]
(default SCENE PASS: glossy GlossDir)."""
import argparse
import os
import sys

import numpy as np
import OpenImageIO as oiio

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "support"))
import render_figures as rf  # noqa: E402


def write_row(path, panels, scale):
    """The panels side by side, 4 px apart, each enlarged `scale` times."""
    gap = np.ones((panels[0].shape[0] * scale, 4, 3), np.float32)
    row = []
    for p in panels:
        row += [np.kron(rf.srgb(p), np.ones((scale, scale, 1))).astype(np.float32), gap]
    pixels = np.concatenate(row[:-1], axis=1)
    h, w, _ = pixels.shape
    buf = oiio.ImageBuf(oiio.ImageSpec(w, h, 3, oiio.UINT8))
    buf.set_pixels(oiio.ROI(), pixels)
    if not buf.write(path):
        sys.exit(f"cycles_pictures: {path}: {buf.geterror()}")
    print(f"cycles_pictures: wrote {path}")


def crop_around(images, centre, size):
    (y, x), (h, w) = centre, size
    top = int(np.clip(y - h // 2, 0, images[0].shape[0] - h))
    left = int(np.clip(x - w // 2, 0, images[0].shape[1] - w))
    return [img[top:top + h, left:left + w] for img in images]


def main():
    parser = argparse.ArgumentParser(prog="cycles_pictures")
    parser.add_argument("build")
    parser.add_argument("out")
    parser.add_argument("--small", action="store_true")
    parser.add_argument("scene", nargs="?", default="glossy")
    parser.add_argument("light", nargs="?", default="GlossDir")
    args = parser.parse_args()
    build, out, scene, light = args.build, args.out, args.scene, args.light
    set_name = "cycles_set" if args.small else "cycles_bench_set"
    data = os.path.join(build, set_name)
    results = os.path.join(build, "render_table", set_name, "cycles")
    os.makedirs(out, exist_ok=True)

    raw, ref = rf.Image(f"{data}/dof_16.exr"), rf.Image(f"{data}/dof_ref.exr")
    denoised = rf.Image(f"{results}/dof_16_denoise.exr")
    glint = np.unravel_index(np.argmax(rf.luminance(ref.light_pass("GlossDir"))), ref.pixels.shape[:2])
    panels = crop_around([raw.beauty(), denoised.beauty(), ref.beauty()], glint, (72, 96))
    write_row(os.path.join(out, "glint.png"), panels, 2)

    raw, ref = rf.Image(f"{data}/{scene}_16.exr"), rf.Image(f"{data}/{scene}_ref.exr")
    layered = rf.Image(f"{results}/{scene}_16_aovs.exr")
    write_row(os.path.join(out, "direct_pass.png"),
              [img.light_pass(light) for img in (raw, layered, ref)], 1)


if __name__ == "__main__":
    main()
