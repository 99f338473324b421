# EXPERIMENT of issue 20 (reverted next commit): per-pixel choice among
# denoise strengths (MCD_FR_K of imageops/src/feature_regression.cpp) by the
# true error, box-smoothed over (2r+1)^2: the bound of any selection.
# Usage: PYTHONPATH=build/python python3 bench/denoise_strength_oracle.py 0.5,1.0,2.0
import os, sys, math
import numpy as np
import OpenImageIO as oiio
import mcdenoise
D = "build/refset"
def chans(buf, names):
    idx = [buf.spec().channelindex(n) for n in names]
    return oiio.ImageBufAlgo.channels(buf, tuple(idx))
def load(path):
    b = oiio.ImageBuf(path)
    g = {"normal": chans(b, ["N.X","N.Y","N.Z"]) , "depth": chans(b, ["Z"]),
         "albedo": chans(b, ["albedo.R","albedo.G","albedo.B"]),
         "variance": chans(b, ["var.R","var.G","var.B"]),
         "half_a": chans(b, ["A.R","A.G","A.B"]), "half_b": chans(b, ["B.R","B.G","B.B"])}
    return chans(b, ["R","G","B"]), g
print(oiio.ImageBuf(D+"/cornell_16.exr").spec().channelnames)
EPS = 0.01
def arr(b): return b.get_pixels(oiio.FLOAT)
def box(a, r):
    # a: HxW, mean over (2r+1)^2 clipped
    p = np.pad(a, r, mode="edge")
    c = np.cumsum(np.cumsum(p, 0), 1)
    c = np.pad(c, ((1,0),(1,0)))
    n = 2*r+1
    return (c[n:, n:] - c[:-n, n:] - c[n:, :-n] + c[:-n, :-n]) / (n*n)
def den(beauty, g, k):
    os.environ["MCD_FR_OFF"] = "1"; os.environ["MCD_FR_K"] = str(k)
    return arr(mcdenoise.denoise(beauty, guides=g))
scenes = ["cornell","mirrors","textured","dof","interior","metal","bokeh","dim"]
ks = [float(x) for x in sys.argv[1].split(",")]
radii = [0, 3, 7]
logs = {r: 0.0 for r in radii}; n = 0
for s in scenes:
    ref = arr(chans(oiio.ImageBuf(f"{D}/{s}_ref.exr"), ["R","G","B"]))
    for spp in (4, 16, 64):
        beauty, g = load(f"{D}/{s}_{spp}.exr")
        cands = [den(beauty, g, k) for k in ks]
        errs = [(((c - ref) ** 2) / (ref ** 2 + EPS)).sum(2) for c in cands]
        base = errs[ks.index(1.0)].mean() / 3
        line = f"{s} {spp} base {base:.5f}"
        for r in radii:
            sm = np.stack([box(e, r) if r else e for e in errs])
            pick = sm.argmin(0)
            sel = np.take_along_axis(np.stack(errs), pick[None], 0)[0].mean() / 3
            logs[r] += math.log(base / sel)
            line += f" r{r} {sel:.5f} ({base/sel:.2f})"
        n += 1
        print(line, flush=True)
for r in radii:
    print("oracle radius", r, "geo gain over current", math.exp(logs[r] / n))
