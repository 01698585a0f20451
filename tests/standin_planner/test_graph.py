"""The whole node graph over DDS (oracle monitor, planner node, player node, generator as separate processes, as
`txt2sce_launch` starts them): the planner node drives a benign scenario to its goal with no violation, and a fault
switched on by node parameter shows up in the oracle's verdict of the scenario built for it.

One scenario per graph: with several, the monitor node can attribute a run's 'finished' status to the next run
when the two arrive interleaved (a harness race, reported; not the planner's)."""

from __future__ import annotations

import json

import pytest

pytest.importorskip("rclpy")

from txt2sce_ros.cli.cmd_planner_check import DEFAULT_DIR  # noqa: E402
from txt2sce_ros.launcher import GraphConfig, run_graph  # noqa: E402


def _verdict(tmp_path, name: str, faults: list[str]) -> dict:
    cfg = GraphConfig(scenarios=[str(DEFAULT_DIR / f"{name}.xosc")], bag_dir=str(tmp_path / "bags"),
                      faults=faults, log_dir=str(tmp_path / "log"))
    codes = run_graph(cfg, timeout=240.0, quiet=True)
    logs = "\n".join(p.read_text(errors="replace")[-2000:] for p in (tmp_path / "log").glob("*.log"))
    assert codes.get("planner") == 0, logs
    verdicts = [json.loads(line) for line in (tmp_path / "bags" / "verdicts.jsonl").read_text().splitlines()]
    mine = [v for v in verdicts if v.get("scenario_id") == name]
    assert len(mine) == 1, verdicts
    return mine[0]


def test_planner_node_drives_a_benign_scenario_in_the_graph(tmp_path):
    benign = _verdict(tmp_path, "benign_junction_straight", [])
    assert benign["end_reason"] == "goal_reached", benign
    # The monitor holds the player's 'finished' status until the run's last frames are in (and a frame the
    # transport dropped is sent again within the writers' 50 ms heartbeat), so it sees the ego reach the goal the
    # player saw it reach: no category at all, PlanFail 'goal_not_reached' included.
    assert benign["verdict"] == "pass" and not benign["categories"], benign


def test_fault_parameter_shows_in_the_oracle_verdict(tmp_path):
    faulty = _verdict(tmp_path, "fault_no_start_when_close", ["no_start_when_close"])
    assert faulty["verdict"] == "fail", faulty
    assert [c["category"] for c in faulty["categories"]] == ["StartFail"], faulty
