"""Trajectories against the reference player's recordings (esmini, same 0.05 s step), for one example per
action family. The full table of all 18 files is printed by `txt2sce conformance` (see the report)."""

from __future__ import annotations

from pathlib import Path

import pytest

from scenario_player.conformance import run_file

from .conftest import ESMINI

CASES = {
    "straight_500m": 0.01,                 # step speed, teleport
    "cut-in": 0.5,                         # continuous relative speed, lane change on a curve, headway
    "cut-in_simple": 0.5,                  # wrong-way placement, relative road position, freespace headway
    "speed-profile": 0.01,                 # SpeedProfileAction follow + position modes
    "synch_with_steady_state": 0.1,        # SynchronizeAction with steady state, TTC condition
    "highway_merge": 0.2,                  # LongitudinalDistanceAction with dynamics, lane change
    "drop-bike": 0.01,                     # LongitudinalDistanceAction without dynamics, relative object position
    "traffic_lights": 0.5,                 # signals, signal conditions with delay, routes through a junction
    "lane_change_simple": 0.5,             # end of road, teleports, maximumExecutionCount
    "keep_lateral_distance": 0.5,          # LateralDistanceAction (speed-limited and damped), relative lanes
    "trajectory-test": 0.5,                # FollowTrajectory: timed Polyline, Clothoid, Nurbs; relative lanes
}


@pytest.mark.parametrize("name", sorted(CASES))
def test_matches_reference(esmini, name: str) -> None:
    result, _ = run_file(esmini / "xosc" / f"{name}.xosc", esmini / "reference" / f"{name}.csv")
    assert result.ran, result.error
    assert result.entities and all(e.rows > 100 for e in result.entities)
    worst = max(result.entities, key=lambda e: e.rms)
    assert worst.rms < CASES[name], (worst.name, worst.rms, worst.max)


#: The 18 shared examples (issue 18's acceptance): every entity within 0.5 m of esmini at every recorded step. The
#: last ones to pass: routing-test (a step's road-s carry-over through junction clothoids, was 0.75 m) and
#: trajectory-test (which NURBS sample times a control point, was 0.71 m).
SHARED = sorted(p.stem for p in (ESMINI / "xosc").glob("*.xosc"))


@pytest.mark.parametrize("name", SHARED)
def test_shared_example_within_half_a_metre_at_every_step(esmini, name: str) -> None:
    result, _ = run_file(esmini / "xosc" / f"{name}.xosc", esmini / "reference" / f"{name}.csv")
    assert result.ran, result.error
    assert result.entities and all(e.rows > 50 for e in result.entities)
    worst = max(result.entities, key=lambda e: e.max)
    assert worst.max < 0.5, worst


def test_all_shared_examples_are_checked(esmini) -> None:
    assert len(SHARED) == 18


#: Cases made for this repository (tests/scenario_player/conformance_cases, references recorded with the shared
#: esmini): the worst position error of any entity at any step must stay under 0.5 m.
CASES_DIR = Path(__file__).with_name("conformance_cases")
OWN_CASES = {
    "lane_change_rate": "LaneChangeAction with dynamicsDimension rate: the rate is each shape's peak lateral speed",
    "offset_curve": "a lateral offset through a curve advances at the radius of the offset path",
    "trajectory_end": "after FollowTrajectoryAction the entity goes on along the road, its heading picks the way",
}


@pytest.mark.parametrize("name", sorted(OWN_CASES))
def test_own_cases_match_the_reference_at_every_step(name: str) -> None:
    result, _ = run_file(CASES_DIR / "xosc" / f"{name}.xosc", CASES_DIR / "reference" / f"{name}.csv")
    assert result.ran, result.error
    assert result.entities and all(e.rows > 200 for e in result.entities)
    worst = max(result.entities, key=lambda e: e.max)
    assert worst.max < 0.5, (OWN_CASES[name], worst)


def test_a_wrong_reference_is_detected(esmini) -> None:
    # Comparing against another scenario's recording must fail: the metric is not vacuous.
    result, _ = run_file(esmini / "xosc" / "cut-in.xosc", esmini / "reference" / "keep_lateral_distance.csv")
    assert result.rms > 1.0
