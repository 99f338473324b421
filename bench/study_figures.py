"""study_figures: the pictures of docs/quality.md for bench/quality_study: a
plot per scene of relMSE against total time, and the crop galleries (one per
filter family of bench/filter_table.py, plus its COMPARISONS).
"""
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402 (after the backend)
import numpy as np  # noqa: E402
import OpenImageIO as oiio  # noqa: E402
from PIL import Image  # noqa: E402

import filter_table  # noqa: E402

# Top-left corner of each scene's crop, as a fraction of the frame (chosen on
# docs/testrender.md's pictures: edges, reflections, texture, defocus).
CROPS = {
    "cornell": (0.39, 0.43),   # box edge, mirror sphere, shadows
    "mirrors": (0.31, 0.37),   # the central mirror sphere
    "textured": (0.25, 0.43),  # checker sphere and floor
    "dof": (0.23, 0.31),       # defocused and sharp spheres
    "interior": (0.31, 0.39),  # table and spheres
}
CROP_FRACTION = 0.375  # side of a crop over the frame's side (96 of 256 pixels)
PALETTE_COLORS = 256   # the galleries are stored as palette PNGs (small files)
IMAGES = os.path.join("images", "quality")


def rgb(path, prefix=""):
    """The R, G, B channels (or prefix.R, ...) of an EXR as an HxWx3 array."""
    buf = oiio.ImageBuf(path)
    names = list(buf.spec().channelnames)
    pixels = buf.get_pixels(oiio.FLOAT)
    return np.stack([pixels[:, :, names.index(prefix + c)] for c in "RGB"], axis=-1)


def srgb(path):
    """An EXR's beauty, display-referred through OCIO (linear to sRGB), clipped."""
    linear = rgb(path)
    buf = oiio.ImageBuf(oiio.ImageSpec(linear.shape[1], linear.shape[0], 3, oiio.FLOAT))
    buf.set_pixels(oiio.ROI(), linear)
    return np.clip(oiio.ImageBufAlgo.colorconvert(buf, "linear", "sRGB").get_pixels(oiio.FLOAT),
                   0.0, 1.0)


def crop(image, scene):
    h, w = image.shape[:2]
    fx, fy = CROPS.get(scene, (0.3, 0.3))
    side = int(round(CROP_FRACTION * w))
    x, y = int(fx * w), int(fy * h)
    return image[y:y + side, x:x + side]


def save_small(fig, path):
    """Saves a figure as a palette PNG (a quarter of an RGBA PNG's size)."""
    fig.savefig(path, dpi=100)
    plt.close(fig)
    Image.open(path).convert("RGB").quantize(PALETTE_COLORS).save(path, optimize=True)


def plot_scene(study, cfg, scene, results, cost, headline_spp, headline_raw_spp, path):
    spps = cfg["spps"]
    rows = results[scene]
    chain = filter_table.BEST_CHAIN.name
    names = [n for n in rows[spps[0]] if n != "raw"]
    best = min(names, key=lambda n: rows[headline_spp][n]["relmse"])
    fig, ax = plt.subplots(figsize=(6, 4))

    def line(name, **style):
        t = [spp * cost[scene] + rows[spp][name]["seconds"] for spp in spps]
        ax.plot(t, [rows[spp][name]["relmse"] for spp in spps], marker="o", markersize=3,
                **style)

    for name in names:
        if name not in (chain, best, "denoise"):
            line(name, color="0.8", linewidth=0.7)
    line("raw", color="black", label="raw")
    line(chain, color="red", label=chain)
    if best not in (chain, "denoise"):
        line(best, color="green", label=best)
    if "denoise" in names:
        line("denoise", color="blue", label="denoise")
    ax.axhline(rows[headline_raw_spp]["raw"]["relmse"], color="black", linestyle="--",
               linewidth=0.8)
    for spp in spps:
        ax.annotate(f"{spp}", (spp * cost[scene], rows[spp]["raw"]["relmse"]),
                    textcoords="offset points", xytext=(3, 3), fontsize=7)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("render + filter time (s)")
    ax.set_ylabel("relMSE")
    ax.set_title(f"{scene} ({cfg['res']}x{cfg['res']}; raw points labelled with spp)")
    ax.legend(fontsize=7)
    fig.tight_layout()
    save_small(fig, path)


def gallery(study, cfg, results, entries, columns, path):
    """A grid of crops: a row per scene, columns of (title, spp, entry name;
    None: the raw render; "ref": the reference), relMSE under each; `entries`
    maps the names to their entries."""
    scenes = cfg["scenes"]
    side = int(round(CROP_FRACTION * cfg["res"]))
    width = len(columns) * (side + 20) / 100 + 0.3  # inches; 0.3 for the scene names
    fig, axes = plt.subplots(len(scenes), len(columns), squeeze=False,
                             figsize=(width, len(scenes) * (side + 28) / 100 + 0.6))
    for r, scene in enumerate(scenes):
        for c, (title, spp, name) in enumerate(columns):
            ax = axes[r][c]
            if name == "ref":
                image, label = srgb(study.render_path(scene, "ref")), "reference"
            elif name is None:
                image = srgb(study.render_path(scene, spp))
                label = f"relMSE {results[scene][spp]['raw']['relmse']:.3g}"
            else:
                image = srgb(study.output_path(scene, spp, entries[name]))
                label = f"relMSE {results[scene][spp][name]['relmse']:.3g}"
            ax.imshow(crop(image, scene), interpolation="nearest")
            ax.set_xticks([])
            ax.set_yticks([])
            ax.set_xlabel(label, fontsize=6, labelpad=1)
            if r == 0:
                ax.set_title(title.replace(" + ", "\n+ "), fontsize=6)
            if c == 0:
                ax.set_ylabel(scene, fontsize=7)
    fig.subplots_adjust(left=0.3 / width, right=0.99, top=0.95, bottom=0.05, wspace=0.05,
                        hspace=0.25)
    save_small(fig, path)


def draw(study, cfg, entries, results, cost, out, gallery_spp, headline_spp, headline_raw_spp):
    """Draws every picture under out/images/quality/; returns their paths
    relative to out: {"plots": {scene: path}, "galleries": [(title, path)]}."""
    os.makedirs(os.path.join(out, IMAGES), exist_ok=True)
    figures = {"plots": {}, "galleries": []}
    for scene in cfg["scenes"]:
        rel = os.path.join(IMAGES, f"{scene}_relmse_time.png")
        plot_scene(study, cfg, scene, results, cost, headline_spp, headline_raw_spp,
                   os.path.join(out, rel))
        figures["plots"][scene] = rel
    families = []
    for e in entries:
        if e.family not in families:
            families.append(e.family)
    sections = [(family, f"{family} filters",
                 [(f"{gallery_spp} spp raw", gallery_spp, None)]
                 + [(e.name, gallery_spp, e.name) for e in entries if e.family == family])
                for family in families]
    by_name = {e.name: e for e in entries}
    for slug, title, members in filter_table.COMPARISONS:
        sections.append((slug, title, [(f"{headline_raw_spp} spp raw", headline_raw_spp, None)]
                         + [(f"{headline_spp} spp, {n}", headline_spp, n)
                            for n in members if n in by_name]))
    for slug, title, columns in sections:
        rel = os.path.join(IMAGES, f"gallery_{slug}.png")
        gallery(study, cfg, results, by_name, columns + [("reference", None, "ref")],
                os.path.join(out, rel))
        figures["galleries"].append((title, rel))
    return figures
