# EXPERIMENT of issue 20 (reverted next commit): the time of nlmeans (radius
# 5, patch 1, every guide, 2 threads) on 4, 14, 21 and 48 channels, the
# cost of carrying the regression moments through the weights.
# Usage: PYTHONPATH=build/python python3 bench/denoise_channel_cost.py cornell_1080p.exr
#   (build/bin/testrender --scene cornell --res 1920x1080 --spp 2 --seed 7 -o cornell_1080p.exr)
import sys, time, resource, numpy as np, OpenImageIO as oiio, mcdenoise
b = oiio.ImageBuf(sys.argv[1])
def ch(names): return oiio.ImageBufAlgo.channels(b, tuple(b.spec().channelindex(n) for n in names))
g = {"normal": ch(["N.X","N.Y","N.Z"]), "depth": ch(["Z"]), "albedo": ch(["albedo.R","albedo.G","albedo.B"]), "variance": ch(["var.R","var.G","var.B"])}
rgb = ch(["R","G","B"]).get_pixels(oiio.FLOAT)
def img(nch):
    a = np.concatenate([rgb] + [rgb[..., :1]] * (nch - 3), axis=2).copy()
    buf = oiio.ImageBuf(oiio.ImageSpec(a.shape[1], a.shape[0], nch, oiio.FLOAT)); buf.set_pixels(oiio.ROI(), a); return buf
for rep in range(2):
    for nch in (4, 14, 21, 48):
        src = img(nch)
        t0 = time.time(); c0 = resource.getrusage(resource.RUSAGE_SELF).ru_utime
        mcdenoise.nlmeans(src, guides=g, search_radius=5, patch_radius=1, strength=1.0, nthreads=2)
        print(nch, "channels: wall %.2f s cpu %.2f s" % (time.time() - t0, resource.getrusage(resource.RUSAGE_SELF).ru_utime - c0), flush=True)
