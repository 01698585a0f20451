"""ROS 2 node of the stand-in planner: a thin adapter moving messages to and from the `Planner` core.

Subscribes: /txt2sce/scenario (the map and road condition), /planning/goal, /sim/ego/odom, /sim/objects/odom,
/sim/objects/markers, /sim/traffic_lights. Publishes: /control/command (geometry_msgs/TwistStamped, stamped with
the time of the frame it answers). Lock-step: one command per complete frame (see txt2sce_ros.contract).

Parameters:
- `faults` (string[]): fault modes to switch on (see standin_planner.faults), default none.
- `config` (string): planner YAML, default the package's config/planner.yaml.
- `road_friction` (double): friction the stack assumes; < 0 (default) reads it from the scenario's environment.
- `map` (string): an OpenDRIVE file to drive on when no scenario envelope is published (a player started with
  `scenario_files` only); an envelope, when one comes, takes precedence.
"""

from __future__ import annotations

import sys

import rclpy

from txt2sce_ros.contract import Goal, ScenarioEnvelope
from txt2sce_ros.nodes.lifetime import build_node, node_lifetime
from txt2sce_ros.nodes.lockstep_planner import LockStepPlannerNode
from txt2sce_ros.road import RoadNetwork

from .environment import friction_from_xosc
from .faults import Faults
from .params import PlannerParams
from .planner import Planner


class PlannerNode(LockStepPlannerNode):
    """The stand-in on the shared lock-step topic side (txt2sce_ros.nodes.lockstep_planner)."""

    def __init__(self) -> None:
        super().__init__("standin_planner")
        self.declare_parameter("faults", [""])
        self.declare_parameter("config", "")
        self.declare_parameter("road_friction", -1.0)
        self.declare_parameter("map", "")
        self.faults = Faults.from_names(self.get_parameter("faults").value)
        cfg = self.get_parameter("config").value
        self.params = PlannerParams.from_config(cfg or None)
        friction = float(self.get_parameter("road_friction").value)
        self.friction_override = friction if friction >= 0.0 else None
        self.friction: float | None = None
        self.use_fixed_map(str(self.get_parameter("map").value))
        if self.faults.active():
            self.get_logger().warn(f"fault modes on: {', '.join(self.faults.active())}")

    def read_envelope(self, env: ScenarioEnvelope) -> None:
        self.friction = friction_from_xosc(env.xosc, source=env.id) if env.xosc else None

    def set_goal(self, goal: Goal) -> None:
        self.planner.set_goal(goal)

    def make_planner(self, network: RoadNetwork, goal: Goal, envelope: ScenarioEnvelope | None) -> Planner:
        friction = self.friction_override if self.friction_override is not None else self.friction
        return Planner(network, goal, self.params, faults=self.faults, road_friction=friction)


def main(args: list[str] | None = None) -> int:
    rclpy.init(args=args)
    node = build_node(PlannerNode, "planner_node")
    with node_lifetime(node):
        rclpy.spin(node)
    return 0


if __name__ == "__main__":
    sys.exit(main())
