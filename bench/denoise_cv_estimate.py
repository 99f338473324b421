# EXPERIMENT of issue 20 (reverted next commit): the half-buffer
# cross-validation estimate of nlmeans at strengths 0.5, 1, 2 (halves filtered
# with the full image's weights) against the true relMSE.
# Usage: PYTHONPATH=build/python python3 bench/denoise_cv_estimate.py
import sys, numpy as np, OpenImageIO as oiio, mcdenoise
D="build/refset"
def ch(b, names): return oiio.ImageBufAlgo.channels(b, tuple(b.spec().channelindex(n) for n in names))
for scene, spp in [("cornell",4),("cornell",16),("dof",16),("textured",16)]:
    b = oiio.ImageBuf(f"{D}/{scene}_{spp}.exr")
    ref = ch(oiio.ImageBuf(f"{D}/{scene}_ref.exr"), ["R","G","B"]).get_pixels(oiio.FLOAT)
    g = {"normal": ch(b,["N.X","N.Y","N.Z"]), "depth": ch(b,["Z"]), "albedo": ch(b,["albedo.R","albedo.G","albedo.B"]), "variance": ch(b,["var.R","var.G","var.B"])}
    src = ch(b, ["R","G","B","A.R","A.G","A.B","B.R","B.G","B.B"])
    s = src.get_pixels(oiio.FLOAT)
    A, B = s[..., 3:6], s[..., 6:9]
    full = s[..., :3]
    print(scene, spp, "full - (A+B)/2 max", np.abs(full - (A + B) / 2).max(), "var(A-B)/4 mean", ((A-B)**2/4).mean(), "var guide mean", g["variance"].get_pixels(oiio.FLOAT).mean())
    for k in (0.5, 1.0, 2.0):
        f = mcdenoise.nlmeans(src, guides=g, search_radius=5, patch_radius=1, strength=k).get_pixels(oiio.FLOAT)
        F, FA, FB = f[..., :3], f[..., 3:6], f[..., 6:9]
        norm = ref**2 + 0.01
        true = ((F - ref)**2 / norm).mean()
        trueA = ((FA - ref)**2 / norm).mean()
        est = ((0.5*((FA-B)**2 + (FB-A)**2) - 0.25*(FA-FB)**2) / norm).mean()
        varB = (((B - ref)**2) / norm).mean()
        print(f"  k {k}: true {true:.5f} trueA {trueA:.5f} est {est:.5f} est-var(B) {est - varB:.5f}  Fhalves-F {np.abs((FA+FB)/2-F).max():.2g}")
