#!/usr/bin/env python3
"""aov_backoff_study.py: a numpy study of two steps after `--aovs auto
--denoise` (docs/aovs.md, "Studied (2026-12-05): back-off towards the raw pass, then
reconciliation"):

- back-off: each written pass D blended per pixel towards its raw pass R,
  by a = clip(1 - KAPPA s2 / m2, 0, 1), where m2 is the 3x3 mean of |D - R|^2
  (bias^2 + noise) and s2 the noise of R, the smallest 3x3 variance of D - R
  among the 3x3 windows around the pixel (denoise's own estimate);
- reconciliation: the difference between `--denoise`'s beauty and the
  Cycles-style rebuild of the backed-off passes shared among the passes in
  proportion to Col^2 s2 (each pass's noise in the beauty's units), only
  where the raw passes rebuild the raw beauty, never below zero.

Prints each pass's relMSE over raw (today, back-off, reconciled) and the
rebuilt beauty over `--denoise` alone's. Needs Debian's python3-scipy.

Usage: KAPPA=1 PYTHONPATH=build/python /usr/bin/python3 bench/aov_backoff_study.py \
           build/bin/mcdtool NOISY REF TAG [NOISY REF TAG ...]
Outputs go to /tmp/aov_backoff_study.
"""
import os
import subprocess
import sys

import numpy as np
from scipy.ndimage import minimum_filter, uniform_filter

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from aov_study import read, rel_mse  # noqa: E402

MCD = sys.argv[1]
KAPPA = float(os.environ.get("KAPPA", "1"))
OUT = "/tmp/aov_backoff_study"
os.makedirs(OUT, exist_ok=True)
LOBES = ("Diff", "Gloss", "Trans", "Volume")

def strip(img):
    out = {}
    for k, v in img.items():
        out[k[len("ViewLayer."):] if k.startswith("ViewLayer.") else k] = v
    return out

def rgb(img, p):
    keys = [p + "." + c for c in "RGB"] if p else ["Combined.R", "Combined.G", "Combined.B"] if "Combined.R" in img else ["R", "G", "B"]
    return np.stack([img[k] for k in keys], axis=2) if all(k in img for k in keys) else None

def local_var(e):
    m = uniform_filter(e, size=(3, 3, 1)); q = uniform_filter(e * e, size=(3, 3, 1))
    v = np.maximum(q - m * m, 0) * 9 / 8
    return minimum_filter(v, size=(3, 3, 1)).sum(axis=2)

def backoff(D, R):
    e = D - R
    m2 = uniform_filter((e * e).sum(axis=2), size=3)
    s2 = local_var(e)
    a = np.clip(1 - KAPPA * s2 / np.maximum(m2, 1e-20), 0, 1)
    return D + a[:, :, None] * (R - D), s2

def run(noisy, ref, tag):
    a = os.path.join(OUT, tag + "_aovs.exr"); d = os.path.join(OUT, tag + "_den.exr")
    subprocess.run([MCD, noisy, "--aovs", "auto", "--denoise", "-o", a], check=True, capture_output=True)
    subprocess.run([MCD, noisy, "--denoise", "-o", d], check=True, capture_output=True)
    N, T, A, Dn = (strip(read(p)) for p in (noisy, ref, a, d))
    passes = [p for p in ["DiffDir", "DiffInd", "GlossDir", "GlossInd", "TransDir", "TransInd", "VolumeDir", "VolumeInd", "Emit", "Env"]
              + sorted({k.split(".")[0] for k in N if k.startswith("Combined_")}) if p + ".R" in N]
    Bt, Bd = rgb(T, ""), rgb(Dn, "")
    out = {}; s2s = {}
    for p in passes:
        R, Tp, D = rgb(N, p), rgb(T, p), rgb(A, p)
        if np.abs(Tp).max() == 0: continue
        O, s2 = backoff(D, R); out[p] = (R, Tp, D, O); s2s[p] = s2
    cyc = [p for p in out if not p.startswith("Combined_")]
    ones = np.ones_like(Bd)
    colours = {p: rgb(N, p[:-3] + "Col") if p[:-3] in LOBES else None for p in cyc}
    col = lambda p: colours[p] if colours[p] is not None else ones
    # reconcile the Cycles-style passes with --denoise's beauty
    reb = lambda get: sum(col(p) * get(p) for p in cyc)
    rawreb = reb(lambda p: out[p][0])
    ok = (np.abs(rawreb - rgb(N, "")) <= 1e-3 * (np.abs(rgb(N, "")) + 1e-3)).all(axis=2)
    E = {p: col(p) ** 2 * s2s[p][:, :, None] for p in cyc}
    tot = sum(E.values()) + 1e-30
    delta = Bd - reb(lambda p: out[p][3])
    rec = {}
    for p in cyc:
        c = col(p)
        share = np.where(c > 1e-4, delta * E[p] / tot / np.maximum(c, 1e-4), 0)
        rec[p] = np.maximum(out[p][3] + np.where(ok[:, :, None], share, 0), 0)
    for p in out:
        R, Tp, D, O = out[p]; r = rel_mse(R, Tp)
        recs = f"{rel_mse(rec[p], Tp) / r:5.2f}" if p in rec else "   - "
        print(f"{tag:12s} {p:14s} raw {r:.5f} today {rel_mse(D, Tp) / r:5.2f} backoff {rel_mse(O, Tp) / r:5.2f} reconciled {recs}")
    bd = rel_mse(Bd, Bt)
    print(f"{tag:12s} beauty --denoise {bd:.5f} rebuilt today {rel_mse(reb(lambda p: out[p][2]), Bt) / bd:5.3f} "
          f"backoff {rel_mse(reb(lambda p: out[p][3]), Bt) / bd:5.3f} reconciled {rel_mse(reb(lambda p: rec[p]), Bt) / bd:5.3f} "
          f"(rebuild-ok pixels {ok.mean():.3f})")

for noisy, ref, tag in zip(sys.argv[2::3], sys.argv[3::3], sys.argv[4::3]):
    run(noisy, ref, tag)
