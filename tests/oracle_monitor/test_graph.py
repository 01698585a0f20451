"""End to end over DDS: generator -> player <-> stand-in planner, the monitor node recording; then every recording
re-judged offline must give the verdict the live monitor gave (and wrote to verdicts.jsonl and into the bag)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

pytest.importorskip("rclpy")

from oracle_monitor.judge import judge_bag  # noqa: E402
from txt2sce_ros.contract import Verdict  # noqa: E402
from txt2sce_ros.launcher import GraphConfig, run_graph  # noqa: E402

from .oracle_runs import ESMINI  # noqa: E402

SCENARIOS = ["pedestrian_collision.xosc", "slow-lead-vehicle.xosc"]


def test_graph_runs_rejudged_offline_match_live(tmp_path: Path) -> None:
    bags = tmp_path / "bags"
    cfg = GraphConfig(scenarios=[str(ESMINI / "xosc" / s) for s in SCENARIOS], bag_dir=str(bags),
                      log_dir=str(tmp_path / "log"), planner_timeout=5.0, run_timeout=60.0)
    codes = run_graph(cfg, timeout=150.0, quiet=True)
    assert codes.get("oracle") == 0, (tmp_path / "log" / "oracle.log").read_text()
    live = [json.loads(line) for line in (bags / "verdicts.jsonl").read_text().splitlines()]
    assert [v["scenario_id"] for v in live] == [Path(s).stem for s in SCENARIOS]
    for entry in live:
        bag = Path(entry.pop("bag"))
        result = judge_bag(bag)
        assert result.complete, result.issues
        (offline,) = result.verdicts
        assert offline.to_dict() == entry                      # offline == live, field for field
        assert result.agrees_with_live() is True               # and == the verdict recorded in the bag
        assert offline.frames >= 1
        # A run the player ended because the planner did not answer is an error, never a failure of the stack.
        assert (offline.verdict is Verdict.ERROR) == (offline.end_reason == "planner_not_responding"), offline
