"""CommonRoad's reactive planner under test, for real: the adapter node in its own environment (.venv-commonroad),
the player and the oracle monitor as separate processes over DDS, on short real scenarios. Skipped, saying why,
only when the planner's environment is absent (`make test` creates it)."""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest

from sut_adapters.commonroad.venv import available
from txt2sce_ros.campaign.ros_runs import PlannerSpec, run_over_ros
from txt2sce_ros.paths import REPO_ROOT

SCENARIOS = REPO_ROOT / "examples" / "scenarios"
WHY = available()
pytestmark = pytest.mark.skipif(bool(WHY), reason=WHY)


def _run(name: str, tmp_path: Path, time_limit: float | None = None):
    traj = tmp_path / f"{name}.npz"
    # Two attempts, as a campaign gives a run that broke on timing: twice in five full CI runs (sessions 16, 17)
    # the adapter left the first frame unanswered for 60 s at t = 0 while passing 16 of 16 times in loops. The
    # likely cause, DDS losing the first frame sent right after discovery, is handled since session 18 (the player
    # sends an unanswered first frame again, tests/scenario_player/test_node.py); a second attempt is reported as
    # a warning, so CI's log says whether it still happens. What these tests check is the planner's driving; the
    # graph's own robustness has its tests in tests/integration.
    rec = run_over_ros(SCENARIOS / f"{name}.xosc", planner=PlannerSpec("commonroad"), keep_trajectory=traj,
                       run_timeout=800.0, attempts=2, time_limit=time_limit)
    if rec.details.get("ros_attempts", 1) > 1:
        warnings.warn(f"{name}: the CommonRoad run took {rec.details['ros_attempts']} attempts", stacklevel=2)
    if rec.verdict.value == "error":
        # The logs' last lines in full (an assertion message would be cut short), to say where the run stood.
        tails = rec.details.get("last_log_lines") or {}
        pytest.fail(f"{rec.error}\n" + "\n".join(f"--- {who}:\n{lines}" for who, lines in tails.items()),
                    pytrace=False)
    with np.load(traj) as data:
        paths = {k: data[k] for k in data.files}
    return rec, paths


@pytest.mark.timeout(1000)
def test_parked_car_ahead_is_passed_clear_and_the_goal_reached(tmp_path: Path) -> None:
    rec, paths = _run("benign_parked_car", tmp_path)
    assert "Collision" not in rec.categories
    assert rec.end_reason == "goal_reached"
    ego = paths["ego"]
    parked = next(v for k, v in paths.items() if k != "ego")
    # the ego ends beyond the parked car along the road, having moved sideways round it (columns t, x, y, h, v)
    along = np.array([np.cos(ego[0, 3]), np.sin(ego[0, 3])])
    side = np.array([-along[1], along[0]])
    rel_end = (ego[-1, 1:3] - parked[0, 1:3]) @ along
    assert rel_end > 5.0
    lateral = (ego[:, 1:3] - ego[0, 1:3]) @ side
    assert np.abs(lateral).max() > 1.0
    stats = rec.details["planner_stats"]
    assert stats["cycles"]["planned"] > 10


@pytest.mark.timeout(1000)
def test_red_light_is_never_entered_on_red(tmp_path: Path) -> None:
    # red for the first 12 s, then green: 16 s simulated show the wait and the start
    rec, paths = _run("benign_red_then_green", tmp_path, time_limit=16.0)
    # the oracle's red-light rule is a Misinterp violation; the ego must have held at the line, then gone on green
    assert "Misinterp" not in rec.categories and "Collision" not in rec.categories
    ego = paths["ego"]
    red = ego[:, 0] < 11.5
    assert ego[red, 4].max() < 0.5, "the ego moved on red"
    assert rec.details["planner_stats"]["stop_line_cycles"] > 0       # it was the planner's stopping mode
    assert ego[-1, 4] > 2.0, "the ego did not start on green"
