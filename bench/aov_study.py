#!/usr/bin/env python3
"""aov_study.py: what `mcdtool --aovs auto --denoise` does to testrender's
light passes, printed as the tables of docs/aovs.md.

For each scene, from a noisy render and a reference render (both written by
`testrender --passes`): each light pass's relMSE against the reference pass,
raw and denoised with the beauty's weights; the beauty of `--denoise` alone
and the beauty rebuilt from the denoised passes; how exactly the written
beauty equals the compositor's rebuild of the written passes; and two
per-component alternatives and the floor of any rebuild (the
reference light passes times the render's own, noisy, colour passes): each irradiance pass denoised with its own
weights (`denoise` on the pass, guides normal, depth, albedo, its variance
estimated) and then rebuilt, and each light product Col x (Dir + Ind)
denoised on its own.

Usage: PYTHONPATH=build/python /usr/bin/python3 bench/aov_study.py MCDTOOL DIR SCENE... [--figure FILE.png]
where DIR holds SCENE_16.exr and SCENE_ref.exr for every SCENE. --figure
writes the first scene's beauty and indirect passes, raw | denoised |
reference, as one sRGB PNG.
"""
import os
import subprocess
import sys

import numpy as np
import OpenImageIO as oiio

import mcdenoise

LOBES = ("Diff", "Gloss", "Trans")
PLAIN = ("Emit", "Env")


def read(path):
    buf = oiio.ImageBuf(str(path))
    assert buf.read(force=True), buf.geterror()
    names = list(buf.spec().channelnames)
    pixels = buf.get_pixels(oiio.FLOAT)
    return {name: pixels[:, :, i] for i, name in enumerate(names)}


def rgb(img, prefix=""):
    return np.stack([img[prefix + c] for c in "RGB"], axis=2)


def pass_of(img, name):
    return rgb(img, name + ".")


def rel_mse(x, ref):
    return float(np.mean((x - ref) ** 2 / (ref ** 2 + 0.01)))


def rebuild(get):
    """sum Col x (Dir + Ind) + Emit + Env, from `get(pass name)`."""
    total = get("Emit") + get("Env")
    for lobe in LOBES:
        total = total + get(lobe + "Col") * (get(lobe + "Dir") + get(lobe + "Ind"))
    return total


def study(mcdtool, folder, scene):
    noisy_path = os.path.join(folder, f"{scene}_16.exr")
    layered_path = os.path.join(folder, f"{scene}_aovs.exr")
    alone_path = os.path.join(folder, f"{scene}_alone.exr")
    subprocess.run([mcdtool, noisy_path, "--aovs", "auto", "--denoise", "-o", layered_path], check=True)
    subprocess.run([mcdtool, noisy_path, "--denoise", "-o", alone_path], check=True)
    noisy, ref = read(noisy_path), read(os.path.join(folder, f"{scene}_ref.exr"))
    layered, alone = read(layered_path), read(alone_path)
    guides = {"normal": np.stack([noisy["N." + c] for c in "XYZ"], axis=2),
              "depth": noisy["Z"][..., None], "albedo": rgb(noisy, "albedo.")}

    def own(name):
        return np.asarray(mcdenoise.denoise(pass_of(noisy, name), guides))

    rows = []
    for lobe in LOBES:
        for kind in ("Dir", "Ind"):
            rows.append(lobe + kind)
    rows += list(PLAIN)
    print(f"\n### {scene}\n")
    print("| pass | raw relMSE | denoised (beauty's weights) | ratio | own weights | ratio |")
    print("|---|---|---|---|---|---|")
    own_passes = {}
    for name in rows:
        raw = rel_mse(pass_of(noisy, name), pass_of(ref, name))
        den = rel_mse(pass_of(layered, name), pass_of(ref, name))
        own_passes[name] = own(name)
        mine = rel_mse(own_passes[name], pass_of(ref, name))
        print(f"| {name} | {raw:.5f} | {den:.5f} | {den / raw if raw else 0:.2f} | {mine:.5f} | "
              f"{mine / raw if raw else 0:.2f} |")
    reference = rgb(ref)
    raw_beauty = rel_mse(rgb(noisy), reference)
    beauty_alone = rel_mse(rgb(alone), reference)
    rebuilt = rel_mse(rgb(layered), reference)
    consistency = rel_mse(rebuild(lambda n: pass_of(layered, n)), rgb(layered))
    per_pass = rel_mse(rebuild(lambda n: own_passes.get(n, pass_of(noisy, n))), reference)
    products = pass_of(noisy, "Emit") * 0
    for lobe in LOBES:
        light = pass_of(noisy, lobe + "Col") * (pass_of(noisy, lobe + "Dir") + pass_of(noisy, lobe + "Ind"))
        products = products + np.asarray(mcdenoise.denoise(light, guides))
    products = products + own_passes["Emit"] + own_passes["Env"]
    per_light = rel_mse(products, reference)
    floor = rel_mse(rebuild(lambda n: pass_of(noisy if n.endswith("Col") else ref, n)), reference)
    print()
    print("| beauty | relMSE |")
    print("|---|---|")
    print(f"| raw 16 spp | {raw_beauty:.5f} |")
    print(f"| `--denoise` alone | {beauty_alone:.5f} |")
    print(f"| rebuilt from the passes denoised with the beauty's weights (`--aovs auto`) | {rebuilt:.5f} |")
    print(f"| rebuilt from irradiance passes each denoised with its own weights | {per_pass:.5f} |")
    print(f"| sum of light products Col x (Dir + Ind) each denoised with its own weights | {per_light:.5f} |")
    print(f"| floor of any rebuild: the reference passes times the noisy colour passes | {floor:.5f} |")
    print(f"\nWritten beauty against the rebuild of the written passes: relMSE {consistency:.2e}")


def srgb(linear):
    """Display-referred 8-bit values of `linear` (clamped to [0, 1])."""
    x = np.clip(linear, 0.0, 1.0)
    return np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1 / 2.4) - 0.055)


def figure(folder, scene, path):
    """Rows: beauty, DiffDir, DiffInd, GlossInd; columns: raw, denoised, reference."""
    noisy, ref = read(os.path.join(folder, f"{scene}_16.exr")), read(os.path.join(folder, f"{scene}_ref.exr"))
    layered = read(os.path.join(folder, f"{scene}_aovs.exr"))
    rows = []
    for name in ("", "DiffDir", "DiffInd", "GlossInd"):
        get = (lambda img: rgb(img)) if not name else (lambda img, n=name: pass_of(img, n))
        rows.append(np.concatenate([srgb(get(img)) for img in (noisy, layered, ref)], axis=1))
    pixels = np.concatenate(rows, axis=0).astype(np.float32)
    h, w, _ = pixels.shape
    buf = oiio.ImageBuf(oiio.ImageSpec(w, h, 3, oiio.UINT8))
    buf.set_pixels(oiio.ROI(), pixels)
    assert buf.write(path), buf.geterror()


def main():
    args = sys.argv[1:]
    figure_path = None
    if "--figure" in args:
        at = args.index("--figure")
        figure_path = args[at + 1]
        del args[at:at + 2]
    mcdtool, folder, scenes = args[0], args[1], args[2:]
    for scene in scenes:
        study(mcdtool, folder, scene)
    if figure_path:
        figure(folder, scenes[0], figure_path)


if __name__ == "__main__":
    main()
