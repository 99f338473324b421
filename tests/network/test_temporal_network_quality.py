"""test_temporal_network_quality.py: `mcdtool --denoise --temporal N` on the
network against the network frame by frame, on both shot sets as a user
runs them (testrender's shot set, with a variance pass; the Cycles set's
shots, without): the still shot's relMSE and flicker within the targets of
docs/temporal.md ("On the network"), the moving shot better than per-frame
on every frame and its relMSE held where it was measured (2026-12-08)."""
import os
import sys

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
import render_figures as rf  # noqa: E402

SETS = {"testrender": os.environ.get("MCD_SHOTSET_DIR", ""), "cycles": os.environ.get("MCD_CYCLES_SET_DIR", "")}
# The still shot's targets (ratios to the per-frame network, N = 3).
STILL_TARGETS = {"rel_mse": 0.5, "flicker": 0.15}
# The moving shot's relMSE ratio as measured (N = 2), held within 10 %.
MOVING_MEASURED = {"testrender": 0.74, "cycles": 0.90}


@pytest.fixture(scope="module", params=sorted(SETS))
def shot_set(request, tmp_path_factory):
    folder = SETS[request.param]
    if not os.path.isdir(folder):
        pytest.fail(f"no {request.param} shot set at '{folder}' (CTest's fixtures render them)")
    tool = rf.Mcdtool(os.environ["MCDTOOL"], str(tmp_path_factory.mktemp(request.param)))
    return request.param, tool, folder


def test_still_shot_on_the_network(shot_set):
    name, tool, folder = shot_set
    f = rf.shot_figures(tool, folder, "shot_static", denoise="--denoise")
    for figure, target in STILL_TARGETS.items():
        ratio = f["temporal"][figure] / f["per-frame"][figure]
        assert ratio <= target, f"{name} still shot {figure}: {ratio:.3f}x the per-frame network"


def test_moving_shot_on_the_network(shot_set):
    name, tool, folder = shot_set
    f = rf.shot_figures(tool, folder, "shot_truck", denoise="--denoise")
    ratio = f["temporal"]["rel_mse"] / f["per-frame"]["rel_mse"]
    assert ratio <= min(1.0, 1.1 * MOVING_MEASURED[name]), f"{name} moving shot relMSE: {ratio:.3f}x"
    worst = f["temporal"]["worst"] / f["per-frame"]["worst"]
    assert worst < 1.0, f"{name} moving shot: its worst frame {worst:.3f}x the per-frame network's"
    temporal = f["temporal"]["temporal"] / f["per-frame"]["temporal"]
    assert temporal < 1.0, f"{name} moving shot temporal error: {temporal:.3f}x"
