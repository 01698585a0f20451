"""ROS 2 node putting CommonRoad's reactive planner under test: the shared lock-step topic side
(`txt2sce_ros.nodes.lockstep_planner`) around `core.CommonRoadPlanner`. Runs in the planner's own environment
(`make sut-commonroad`: .venv-commonroad), started by `txt2sce_launch --planner commonroad` or by hand:

    .venv-commonroad/bin/python -m sut_adapters.commonroad.node --ros-args -p settings:=my.yaml -p stats_file:=s.json

Parameters:
- `settings` (string): adapter settings YAML (keys of `settings.AdapterSettings`), default the built-in ones.
- `stats_file` (string): where to write, after every planning cycle, a JSON object with the planner's name,
  version, settings and per-run cycle counts (planned / no feasible trajectory / exception), planning times and
  braking steps. The campaign stores it with each run's verdict. Empty: not written.
"""

from __future__ import annotations

import json
import os
import sys
from pathlib import Path

import rclpy

# The planner stack is imported before the node exists: its publisher then appears only once the adapter can answer.
from . import PLANNER_NAME
from .core import CommonRoadPlanner, planner_version
from .settings import AdapterSettings
from txt2sce_ros.contract import Goal, ScenarioEnvelope
from txt2sce_ros.nodes.lifetime import node_lifetime
from txt2sce_ros.nodes.lockstep_planner import LockStepPlannerNode
from txt2sce_ros.road import RoadNetwork


class CommonRoadAdapterNode(LockStepPlannerNode):
    def __init__(self) -> None:
        super().__init__("commonroad_adapter")
        self.declare_parameter("settings", "")
        self.declare_parameter("stats_file", "")
        self.settings = AdapterSettings.from_yaml(self.get_parameter("settings").value or None)
        self.stats_file = str(self.get_parameter("stats_file").value)
        self.runs: dict[str, dict] = {}
        self.core: CommonRoadPlanner | None = None
        self.run_id = ""
        self.get_logger().info(f"{PLANNER_NAME} {planner_version()} settings {self.settings.to_dict()}")

    def make_planner(self, network: RoadNetwork, goal: Goal, envelope: ScenarioEnvelope | None) -> CommonRoadPlanner:
        self.run_id = envelope.id if envelope is not None else f"run{len(self.runs)}"
        self.core = CommonRoadPlanner(network, goal, self.settings,
                                      xodr_text=envelope.map_xodr if envelope is not None else None)
        return self

    # the node itself is the stepping planner: it forwards to the core and keeps the statistics on disk
    def step(self, frame):
        cmd = self.core.step(frame)
        if self.core.stats.plan_times and len(self.core.stats.plan_times) != self._written:
            self._write_stats()
        return cmd

    _written = -1

    def _write_stats(self) -> None:
        if self.core is None:
            return
        self.runs[self.run_id] = self.core.stats.to_dict()
        self._written = len(self.core.stats.plan_times)
        if not self.stats_file:
            return
        doc = {"planner": PLANNER_NAME, "version": planner_version(), "settings": self.settings.to_dict(),
               "runs": self.runs}
        path = Path(self.stats_file)
        path.parent.mkdir(parents=True, exist_ok=True)
        tmp = path.with_name(path.name + f".{os.getpid()}.tmp")
        tmp.write_text(json.dumps(doc, sort_keys=True), encoding="utf-8")
        tmp.replace(path)

    def on_run_end(self) -> None:
        self._write_stats()
        self.core = None
        self._written = -1


def main(args: list[str] | None = None) -> int:
    rclpy.init(args=args)
    node = CommonRoadAdapterNode()
    with node_lifetime(node, on_exit=node._write_stats) as n:
        rclpy.spin(n)
    return 0


if __name__ == "__main__":
    sys.exit(main())
