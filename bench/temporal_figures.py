#!/usr/bin/python3
"""temporal_figures: the pictures of docs/temporal.md.

Usage: bench/temporal_figures.py [BUILD_DIR] [OUT_DIR]   (default: build/, docs/images/)

Runs BUILD_DIR/bin/temporal_table on BUILD_DIR/shotset (make it with
`cmake --build BUILD_DIR --target shotset`) with --figures, which writes
temporal_object.png (the moving-object crops) and temporal_pixel.csv (one
static-shot pixel over the frames); this script plots the CSV as
temporal_pixel.png and moves both pictures to OUT_DIR.
"""
import csv
import os
import shutil
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "..", "build")
    out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(HERE, "..", "docs", "images")
    with tempfile.TemporaryDirectory() as tmp:
        subprocess.run([os.path.join(build, "bin", "temporal_table"),
                        os.path.join(build, "shotset"), "--figures", tmp],
                       check=True, stdout=subprocess.DEVNULL)
        with open(os.path.join(tmp, "temporal_pixel.csv")) as f:
            rows = list(csv.DictReader(f))
        frames = [int(r["frame"]) for r in rows]
        fig, ax = plt.subplots(figsize=(6, 3.2), dpi=100)
        styles = [("raw", "raw 16 spp", ":", "o"), ("per_frame", "per-frame denoise", "--", "s"),
                  ("cross", "cross-frame denoise, N = 3", "-", "D"),
                  ("reference", "reference (2048 spp)", "-", None)]
        for key, label, line, marker in styles:
            ax.plot(frames, [float(r[key]) for r in rows], line, marker=marker, label=label,
                    color="black" if key == "reference" else None)
        ax.set_xlabel("frame")
        ax.set_ylabel("green, pixel (30, 60)")
        ax.set_title("shot_static: one floor pixel over the frames")
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(out, "temporal_pixel.png"))
        shutil.copy(os.path.join(tmp, "temporal_object.png"), out)


if __name__ == "__main__":
    main()
