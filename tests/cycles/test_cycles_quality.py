"""test_cycles_quality.py: regressions of mcdtool's quality on the small
Cycles set (make_cycles_set: 128x96, 1024-spp references; Blender 3.4,
factory sampling, no variance pass). Each limit comes from the figure
measured when it was set (MEASURED, on 2026-12-04 with the code of that
day) with a 25 % margin, and is never above raw (1.0) except where today's
code is known to be worse than raw: those cases are listed in KNOWN_WORSE
with the issue that brings them below raw, and only guard against getting
worse still (docs/quality.md, "Real Cycles renders", shows them)."""
import os
import sys

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
import render_figures as rf  # noqa: E402

SET = os.environ.get("MCD_CYCLES_SET_DIR", "")
STILLS = ("dof", "metal", "interior", "glossy", "glass", "volume", "product")
SPPS = (4, 16, 64)
MARGIN = 1.25

# The NL-means operator's (--denoise:method=nlm) relMSE over raw, per
# still and spp, as measured (after issue 31: the excess given back over
# each pixel's own NL-means window).
DENOISE = {
    "dof": (0.759, 0.787, 0.943), "metal": (0.452, 0.525, 1.360),
    "interior": (0.099, 0.095, 0.149), "glossy": (0.202, 0.276, 0.380),
    "glass": (0.314, 0.330, 0.364), "volume": (0.190, 0.244, 0.285),
    "product": (0.442, 0.833, 0.772),
}
# The network's (--denoise, OIDN's large networks) relMSE over raw, per
# still and spp, as measured on 2026-12-07 (issue 46), and the frame means
# it keeps where it is known to lose energy: dof's small bright emitters,
# a few pixels each at 128x96, lose their peaks as OIDN's networks take
# them (docs/network.md, "What limits it").
NETWORK = {
    "dof": (0.800, 1.128, 0.725), "metal": (0.420, 0.318, 0.659),
    "interior": (0.018, 0.035, 0.085), "glossy": (0.078, 0.117, 0.271),
    "glass": (0.044, 0.102, 0.193), "volume": (0.046, 0.063, 0.127),
    "product": (0.138, 0.278, 0.607),
}
NETWORK_MEAN_KNOWN = {("dof", 4): 0.702, ("dof", 16): 0.822}
# The worst ratio of a written light pass's relMSE to its raw relMSE
# under --aovs auto --denoise, per still and spp, as measured (after issue
# 33: each pass backed off towards its own values, then corrected to add
# up; docs/aovs.md).
AOV_WORST = {
    "dof": (1.004, 1.001, 1.002), "metal": (0.974, 1.312, 1.634),
    "interior": (0.815, 0.975, 2.115), "glossy": (0.989, 0.987, 1.021),
    "glass": (0.987, 0.996, 1.008), "volume": (0.825, 1.229, 1.744),
    "product": (1.001, 1.007, 1.409),
}
# Shots: --temporal over per-frame --denoise, as measured.
TEMPORAL = {
    "shot_static": {"rel_mse": 0.33, "temporal": 0.027, "flicker": 0.077},
    "shot_truck": {"rel_mse": 0.83, "temporal": 0.77},
}
# Where today's code is worse than raw, and the issue that fixes it.
KNOWN_WORSE = {
    "denoise": "#31 (not met there): metal at 64 spp",
    "network": "#46 (OIDN's own bias): dof at 16 spp, its emitters' peaks",
    "aovs": "#33 (not met there: a few passes with little noise, or glossy ones, at 16-64 spp)",
}


def limit(measured):
    """The measured figure with the margin, capped at raw unless known worse."""
    return measured * MARGIN if measured > 1.0 else min(1.0, measured * MARGIN)


@pytest.fixture(scope="module")
def tool(tmp_path_factory):
    if not os.path.isdir(SET):
        pytest.fail(f"no Cycles set at '{SET}' (CTest's make_cycles_set renders it)")
    return rf.Mcdtool(os.environ["MCDTOOL"], str(tmp_path_factory.mktemp("cycles")))


def test_denoise_no_worse_than_raw_and_keeps_the_frame_mean_on_every_still(tool):
    """One test for both figures: they come from the same 21 runs."""
    failures = []
    for scene in STILLS:
        for spp, measured in zip(SPPS, DENOISE[scene]):
            f = rf.still_figures(tool, SET, scene, spp)
            ratio = f["denoise"] / f["raw"]
            print(f"{scene} {spp} spp: --denoise {f['denoise']:.5f}, raw {f['raw']:.5f}, ratio {ratio:.3f}")
            if ratio > limit(measured):
                failures.append(f"{scene} {spp} spp: ratio {ratio:.3f} > {limit(measured):.3f}")
            if not 0.93 <= f["denoise mean"] <= 1.05:
                failures.append(f"{scene} {spp} spp: frame mean {f['denoise mean']:.3f} of the reference's")
    assert not failures, failures


def test_network_no_worse_than_raw_and_keeps_the_frame_mean_on_every_still(tool):
    """The default --denoise (the network at high quality) on every still:
    relMSE no worse than measured (and than raw, but for KNOWN_WORSE), the
    frame mean within 0.93-1.05 of the reference's but where
    NETWORK_MEAN_KNOWN says less, and never below that."""
    failures = []
    for scene in STILLS:
        for spp, measured in zip(SPPS, NETWORK[scene]):
            f = rf.still_figures(tool, SET, scene, spp)
            ratio = f["network"] / f["raw"]
            print(f"{scene} {spp} spp: network {f['network']:.5f}, raw {f['raw']:.5f}, ratio {ratio:.3f}, "
                  f"mean {f['network mean']:.3f}")
            if ratio > limit(measured):
                failures.append(f"{scene} {spp} spp: ratio {ratio:.3f} > {limit(measured):.3f}")
            known = NETWORK_MEAN_KNOWN.get((scene, spp))
            low = 0.95 * known if known else 0.93
            if not low <= f["network mean"] <= 1.05:
                failures.append(f"{scene} {spp} spp: frame mean {f['network mean']:.3f} of the reference's")
    assert not failures, failures


def test_light_passes_no_worse_than_raw_and_rebuild_the_written_beauty(tool):
    """One test for both figures: they come from the same 21 runs. The
    rebuilds (Cycles-style, and the product shot's light groups) are
    checked where the raw passes rebuild the raw beauty."""
    failures = []
    for scene in STILLS:
        for spp, measured in zip(SPPS, AOV_WORST[scene]):
            f = rf.aov_figures(tool, SET, scene, spp)
            for name, (raw, out) in f["passes"].items():
                if raw < 1e-6:  # a pass with no light in it
                    continue
                if out / raw > limit(measured):
                    failures.append(f"{scene} {spp} spp {name}: {out / raw:.2f}x raw > {limit(measured):.2f}")
            for figure in ("rebuild", "groups_rebuild"):
                if f.get(figure) is not None and f[figure] > 1e-6:
                    failures.append(f"{scene} {spp} spp: written passes ({figure}) against the "
                                    f"written beauty, relMSE {f[figure]:.2e}")
            if f["beauty_aovs"] > 1.02 * f["beauty_denoise"]:
                failures.append(f"{scene} {spp} spp: --aovs beauty {f['beauty_aovs']:.5f} > 1.02x "
                                f"--denoise's {f['beauty_denoise']:.5f}")
            if "alpha_raw" in f and f["alpha_aovs"] > max(f["alpha_raw"], 1e-9):
                failures.append(f"{scene} {spp} spp: alpha {f['alpha_aovs']:.2e} > raw {f['alpha_raw']:.2e}")
    assert not failures, failures


def test_temporal_no_worse_than_per_frame_on_the_static_shot(tool):
    f = rf.shot_figures(tool, SET, "shot_static")
    for figure, measured in TEMPORAL["shot_static"].items():
        ratio = f["temporal"][figure] / f["per-frame"][figure]
        assert ratio <= limit(measured), f"static shot {figure}: {ratio:.3f}x per-frame"


def test_temporal_no_worse_than_per_frame_on_the_moving_shot(tool):
    f = rf.shot_figures(tool, SET, "shot_truck")
    for figure, measured in TEMPORAL["shot_truck"].items():
        ratio = f["temporal"][figure] / f["per-frame"][figure]
        assert ratio <= limit(measured), f"moving shot {figure}: {ratio:.3f}x per-frame"
