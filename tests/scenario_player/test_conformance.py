"""Trajectories against the reference player's recordings (esmini, same 0.05 s step), for one example per
action family. The full table of all 18 files is printed by `txt2sce conformance` (see the report)."""

from __future__ import annotations

import pytest

from scenario_player.conformance import run_file

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


def test_a_wrong_reference_is_detected(esmini) -> None:
    # Comparing against another scenario's recording must fail: the metric is not vacuous.
    result, _ = run_file(esmini / "xosc" / "cut-in.xosc", esmini / "reference" / "keep_lateral_distance.csv")
    assert result.rms > 1.0
