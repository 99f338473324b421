"""render_figures.py: the quality figures of mcdtool's results on a render
set, testrender's (make_reference_set, make_shot_set) or the Cycles set
(tests/cycles/make_cycles_set), measured as a user runs it: mcdtool on the
files, metrics of libmcdenoise (mcdenoise.rel_mse, compare_sequence)
against the set's references. Shared by tests/cycles/test_cycles_quality.py
and bench/render_table.

File names in a set: <scene>_<spp>.exr, <scene>_ref.exr; shots
<shot>_16_f<F>.exr and <shot>_ref_f<F>.exr. A file's beauty is Cycles'
<ViewLayer>.Combined.R,G,B or testrender's R,G,B; its passes
<ViewLayer>.<Pass>.R,G,B or <Pass>.R,G,B."""
import os
import subprocess

import numpy as np
import OpenImageIO as oiio

import mcdenoise

# The NL-means operator: what --aovs and --temporal run until the network
# has those modes, so the per-frame baseline their figures are taken against.
NLM = "--denoise:method=nlm"
# The luminance of libmcdenoise's metrics and energy figures (features.h).
LUMA = np.array([0.2126, 0.7152, 0.0722], dtype=np.float32)
# The passes `--aovs auto` denoises (oiiotool-ext/light_passes.cpp), and
# light groups (Combined_<group>).
LIGHT_PASSES = ("DiffDir", "DiffInd", "GlossDir", "GlossInd", "TransDir", "TransInd",
                "VolumeDir", "VolumeInd", "Emit", "Env")
LOBES = ("Diff", "Gloss", "Trans")
# The shots: frames on disk, frames with a reference (a static shot has one
# reference for every frame), neighbours each side for --temporal.
SHOTS = {
    "shot_static": dict(frames=range(0, 8), evaluated=range(0, 8), n=3, static=True),
    "shot_truck": dict(frames=range(0, 7), evaluated=range(2, 5), n=2, static=False),
}


class Image:
    """One EXR's channels by name, and its beauty and passes as HxWx3."""

    def __init__(self, path):
        buf = oiio.ImageBuf(path)
        if not buf.read(force=True, convert=oiio.FLOAT):
            raise RuntimeError(f"{path}: {buf.geterror()}")
        self.path = path
        self.names = list(buf.spec().channelnames)
        self.pixels = buf.get_pixels(oiio.FLOAT)
        combined = [n for n in self.names if n.endswith(".Combined.R")]
        self.layer = combined[0][:-len("Combined.R")] if combined else ""

    def channel(self, name):
        return self.pixels[:, :, self.names.index(name)]

    def rgb(self, prefix):
        return np.stack([self.channel(prefix + c) for c in "RGB"], axis=2)

    def beauty(self):
        return self.rgb(self.layer + "Combined." if self.layer else "")

    def alpha(self):
        name = self.layer + "Combined.A" if self.layer else "A"
        return self.channel(name) if name in self.names else None

    def has_pass(self, name):
        return self.layer + name + ".R" in self.names

    def light_pass(self, name):
        return self.rgb(self.layer + name + ".")

    def light_passes(self):
        """The passes of this file `--aovs auto` takes, in file order."""
        found = []
        for n in self.names:
            if not n.startswith(self.layer) or not n.endswith(".R"):
                continue
            name = n[len(self.layer):-2]
            if name in LIGHT_PASSES or name.startswith("Combined_"):
                found.append(name)
        return found


def srgb(linear):
    """Display-referred values in [0, 1] of `linear` (clamped), for pictures."""
    x = np.clip(linear, 0.0, 1.0)
    return np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1 / 2.4) - 0.055)


def rel_mse(x, ref):
    return float(mcdenoise.rel_mse(np.ascontiguousarray(x), np.ascontiguousarray(ref)))


def luminance(x):
    return x @ LUMA


def frame_mean_ratio(x, ref):
    """The mean luminance of `x` over the reference's."""
    return float(luminance(x).mean() / luminance(ref).mean())


def highlight_energy(x, ref, fraction=0.005):
    """Over the reference's brightest `fraction` of pixels (luminance): the
    sum of `x`'s luminance over the reference's."""
    lx, lr = luminance(x).ravel(), luminance(ref).ravel()
    count = max(1, int(round(fraction * lr.size)))
    top = np.argsort(lr)[-count:]
    return float(lx[top].sum() / lr[top].sum())


def cycles_rebuild(get, has):
    """The compositor's rebuild of Cycles-style passes, from `get(name)`
    (the volume passes where `has(name)`)."""
    total = get("Emit") + get("Env")
    for name in ("VolumeDir", "VolumeInd"):
        if has(name):
            total = total + get(name)
    for lobe in LOBES:
        total = total + get(lobe + "Col") * (get(lobe + "Dir") + get(lobe + "Ind"))
    return total


class Mcdtool:
    """Runs mcdtool, writing results under `work` (kept between calls, so a
    result already there is reused)."""

    def __init__(self, binary, work):
        self.binary = binary
        self.work = work
        os.makedirs(work, exist_ok=True)
        # A result older than the build is made again.
        lib = os.path.join(os.path.dirname(binary), "..", "lib")
        built = [binary] + [os.path.join(lib, n) for n in os.listdir(lib)] if os.path.isdir(lib) else [binary]
        self.built = max(os.path.getmtime(f) for f in built)

    def run(self, *args):
        done = subprocess.run([self.binary, *args], capture_output=True, text=True)
        if done.returncode != 0:
            raise RuntimeError(f"mcdtool {' '.join(args)} failed:\n{done.stderr}")
        return done.stderr

    def fresh(self, out, source):
        """Whether `out` exists and is newer than `source` and the build."""
        return os.path.exists(out) and os.path.getmtime(out) >= max(os.path.getmtime(source), self.built)

    def result(self, name, source, *commands):
        """`mcdtool SOURCE COMMANDS -o WORK/NAME.exr` (once); the output."""
        out = os.path.join(self.work, name + ".exr")
        if not self.fresh(out, source):
            self.run(source, *commands, "-o", out)
        return Image(out)


def still_figures(tool, folder, scene, spp):
    """raw, the NL-means operator ("denoise"), the network ("network", the
    default --denoise) and the report's chain (--object-median 7 --gaussian
    3): relMSE, frame mean and highlight energy against the reference."""
    source = os.path.join(folder, f"{scene}_{spp}.exr")
    ref = Image(os.path.join(folder, f"{scene}_ref.exr")).beauty()
    results = {
        "raw": Image(source).beauty(),
        "denoise": tool.result(f"{scene}_{spp}_nlm", source, NLM).beauty(),
        "network": tool.result(f"{scene}_{spp}_network", source, "--denoise").beauty(),
        "chain": tool.result(f"{scene}_{spp}_chain", source, "--object-median", "7",
                             "--gaussian", "3").beauty(),
    }
    figures = {}
    for method, x in results.items():
        figures[method] = rel_mse(x, ref)
        figures[method + " mean"] = frame_mean_ratio(x, ref)
        figures[method + " highlight"] = highlight_energy(x, ref)
    return figures


def rebuilt_where_raw_rebuilds(raw, out, names=None):
    """The written passes' rebuild of the written beauty, as relMSE over the
    pixels where the raw passes rebuild the raw beauty (within 1e-3 of its
    size in every channel): the light groups' plain sum when `names` are
    given, else the Cycles-style rebuild. None where no pixel rebuilds."""
    def rebuild(img):
        if names:
            return sum(img.light_pass(n) for n in names)
        return cycles_rebuild(img.light_pass, img.has_pass)
    raw_sum, beauty = rebuild(raw), raw.beauty()
    size = np.abs(beauty) + np.abs(raw_sum)
    mask = np.all(np.abs(raw_sum - beauty) <= 1e-3 * size + 1e-7, axis=2)
    if not mask.any():
        return None
    return rel_mse(rebuild(out)[mask], out.beauty()[mask])


def aov_figures(tool, folder, scene, spp):
    """`--aovs auto --denoise` on a render with light passes: each written
    pass's relMSE raw and denoised; the beauty of the NL-means operator
    alone (which --aovs runs) and of --aovs; how exactly the written passes rebuild the written beauty
    where the raw ones rebuild the raw beauty (the Cycles-style rebuild,
    and the light groups' sum when there are groups); alpha raw and
    written."""
    source = os.path.join(folder, f"{scene}_{spp}.exr")
    raw, ref = Image(source), Image(os.path.join(folder, f"{scene}_ref.exr"))
    out = tool.result(f"{scene}_{spp}_aovs", source, "--aovs", "auto", "--denoise")
    alone = tool.result(f"{scene}_{spp}_nlm", source, NLM)
    passes = {}
    for name in raw.light_passes():
        truth = ref.light_pass(name)
        passes[name] = (rel_mse(raw.light_pass(name), truth), rel_mse(out.light_pass(name), truth))
    groups = [n for n in passes if n.startswith("Combined_")]
    figures = dict(passes=passes, beauty_raw=rel_mse(raw.beauty(), ref.beauty()),
                   beauty_denoise=rel_mse(alone.beauty(), ref.beauty()),
                   beauty_aovs=rel_mse(out.beauty(), ref.beauty()),
                   rebuild=rebuilt_where_raw_rebuilds(raw, out))
    if groups:
        figures["groups_rebuild"] = rebuilt_where_raw_rebuilds(raw, out, groups)
    if ref.alpha() is not None:
        a_ref = ref.alpha()[..., None]
        figures["alpha_raw"] = rel_mse(raw.alpha()[..., None], a_ref)
        figures["alpha_aovs"] = rel_mse(out.alpha()[..., None], a_ref)
    return figures


def shot_sequence_figures(results, references):
    """relMSE (mean over frames), temporal error and flicker of a result."""
    c = mcdenoise.compare_sequence([np.ascontiguousarray(x) for x in results],
                                   [np.ascontiguousarray(r) for r in references])
    return dict(rel_mse=c.mean_rel_mse, temporal=c.temporal_error, flicker=c.flicker,
                worst=max(c.frame_rel_mse))


def shot_figures(tool, folder, shot, baseline_binary=None, denoise=NLM):
    """The shot's raw frames, per-frame `denoise` (NLM: the NL-means
    operator; "--denoise": the network), `denoise --temporal N` and (with
    the warped_baseline binary) the naive baseline, over its evaluated
    frames: relMSE, temporal error, flicker and worst frame."""
    cfg = SHOTS[shot]
    tag = "nlm" if denoise == NLM else "network"
    frame_path = lambda f: os.path.join(folder, f"{shot}_16_f{f}.exr")  # noqa: E731
    refs = [Image(os.path.join(folder, f"{shot}_ref_f{0 if cfg['static'] else f}.exr")).beauty()
            for f in cfg["evaluated"]]
    first, last = cfg["frames"][0], cfg["frames"][-1]
    per_frame = {f: tool.result(f"{shot}_f{f}_{tag}", frame_path(f), denoise)
                 for f in cfg["frames"]}
    pattern = os.path.join(tool.work, f"{shot}_temporal_{tag}_f@.exr")
    temporal_path = lambda f: pattern.replace("@", str(f))  # noqa: E731
    if not all(tool.fresh(temporal_path(f), frame_path(f)) for f in cfg["evaluated"]):
        frames = f"{cfg['evaluated'][0]}-{cfg['evaluated'][-1]}"
        tool.run(os.path.join(folder, f"{shot}_16_f@.exr"), "--frames", frames, denoise,
                 "--temporal", str(cfg["n"]), "-o", pattern)
    methods = {
        "raw": [Image(frame_path(f)).beauty() for f in cfg["evaluated"]],
        "per-frame": [per_frame[f].beauty() for f in cfg["evaluated"]],
        "temporal": [Image(temporal_path(f)).beauty() for f in cfg["evaluated"]],
    }
    if baseline_binary:
        methods["baseline"] = []
        for f in cfg["evaluated"]:
            out = os.path.join(tool.work, f"{shot}_baseline_f{f}.exr")
            args = [out, frame_path(f), per_frame[f].path]
            for g in range(max(first, f - cfg["n"]), min(last, f + cfg["n"]) + 1):
                if g != f:
                    args += [frame_path(g), per_frame[g].path, str(g - f)]
            done = subprocess.run([baseline_binary, *args], capture_output=True, text=True)
            if done.returncode != 0:
                raise RuntimeError(f"warped_baseline failed:\n{done.stderr}")
            methods["baseline"].append(Image(out).pixels[:, :, :3])
    return {m: shot_sequence_figures(x, refs) for m, x in methods.items()}
