"""End to end over DDS: generator -> player <-> stand-in planner, the monitor node recording; then every recording
re-judged offline must give the verdict the live monitor gave (and wrote to verdicts.jsonl and into the bag), and the
bag holds each run's road once, as the player node published it."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

pytest.importorskip("rclpy")

from oracle_monitor.bagread import read_bag  # noqa: E402
from oracle_monitor.judge import judge_bag  # noqa: E402
from scenario_player import Simulation, SimulationConfig, load_scenario  # noqa: E402
from txt2sce_ros.contract import TOPIC_MAP_MARKERS, TOPIC_SCENARIO_MARKERS, VIEW_TOPICS, Verdict  # noqa: E402
from txt2sce_ros.ros_io import road_markers_bytes  # noqa: E402
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
    assert [v["scenario_id"] for v in live] == [Path(s).stem for s in SCENARIOS], \
        [(v["scenario_id"], v["verdict"], v["frames"], v["end_reason"], v["error"], v["notes"]) for v in live]
    bags_seen = {entry.pop("bag") for entry in live}
    assert len(bags_seen) == 1
    result = judge_bag(Path(bags_seen.pop()))
    assert result.complete, result.issues
    for entry in live:
        entry.pop("run")
    assert [v.to_dict() for v in result.verdicts] == live            # offline == live, field for field
    assert result.agrees_with_live() is True                         # and == the verdicts recorded in the bag
    for offline in result.verdicts:
        assert offline.frames >= 1, [(v.scenario_id, v.frames, v.end_reason, v.t_end, v.summary())
                                     for v in result.verdicts]
        # A run the player ended because the planner did not answer is an error, never a failure of the stack.
        assert (offline.verdict is Verdict.ERROR) == (offline.end_reason == "planner_not_responding"), offline

    # The road of each run, recorded once per run from the live player node: the very bytes the in-process
    # recorder writes for that map (one road model, one message), and the goal/light markers with each run.
    bag = Path(json.loads((bags / "verdicts.jsonl").read_text().splitlines()[0])["bag"])
    views = {t: [bytes(m.data) for m in read_bag(bag).messages(frozenset({t}))] for t in VIEW_TOPICS}
    expected = [road_markers_bytes(Simulation(load_scenario(str(ESMINI / "xosc" / s)), SimulationConfig()).network)
                for s in SCENARIOS]
    # The player node publishes the encoded bytes; DDS may pad a payload to a multiple of 4 bytes on the wire.
    assert [v[:len(e)] for v, e in zip(views[TOPIC_MAP_MARKERS], expected)] == expected
    assert [len(v) - len(e) for v, e in zip(views[TOPIC_MAP_MARKERS], expected)] == [(-len(e)) % 4 for e in expected]
    assert len(views[TOPIC_SCENARIO_MARKERS]) >= len(SCENARIOS)
