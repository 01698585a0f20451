"""ROS 2 node of the stand-in planner: a thin adapter moving messages to and from the `Planner` core.

Subscribes: /txt2sce/scenario (the map and road condition), /planning/goal, /sim/ego/odom, /sim/objects/odom,
/sim/objects/markers, /sim/traffic_lights. Publishes: /control/command (geometry_msgs/TwistStamped, stamped with
the time of the frame it answers). Lock-step: one command per complete frame (see txt2sce_ros.contract).

Parameters:
- `faults` (string[]): fault modes to switch on (see standin_planner.faults), default none.
- `config` (string): planner YAML, default the package's config/planner.yaml.
- `road_friction` (double): friction the stack assumes; < 0 (default) reads it from the scenario's environment.
"""

from __future__ import annotations

import sys

import rclpy
from diagnostic_msgs.msg import DiagnosticArray
from geometry_msgs.msg import PoseStamped, TwistStamped
from nav_msgs.msg import Odometry
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from std_msgs.msg import String
from visualization_msgs.msg import MarkerArray

from txt2sce_ros.contract import (TOPIC_COMMAND, TOPIC_EGO_ODOM, TOPIC_GOAL, TOPIC_OBJECTS_MARKERS,
                                  TOPIC_OBJECTS_ODOM, TOPIC_SCENARIO, TOPIC_TRAFFIC_LIGHTS, Frame, Goal,
                                  ScenarioEnvelope)
from txt2sce_ros.errors import Txt2SceError
from txt2sce_ros.road import RoadNetwork, load_network
from txt2sce_ros.ros_io import FrameAssembler, command_to_twist, pose_to_goal

from .environment import friction_from_xosc
from .faults import Faults
from .params import PlannerParams
from .planner import Planner

#: Reliable, deep enough for one odometry message per entity per step.
STREAM_QOS = QoSProfile(depth=200, reliability=ReliabilityPolicy.RELIABLE)
#: The scenario envelope is latched by its publisher; a late planner still gets it.
LATCHED_QOS = QoSProfile(depth=10, reliability=ReliabilityPolicy.RELIABLE,
                         durability=DurabilityPolicy.TRANSIENT_LOCAL)


class PlannerNode(Node):
    def __init__(self) -> None:
        super().__init__("standin_planner")
        self.declare_parameter("faults", [""])
        self.declare_parameter("config", "")
        self.declare_parameter("road_friction", -1.0)
        self.faults = Faults.from_names(self.get_parameter("faults").value)
        cfg = self.get_parameter("config").value
        self.params = PlannerParams.from_config(cfg or None)
        friction = float(self.get_parameter("road_friction").value)
        self.friction_override = friction if friction >= 0.0 else None
        self.network: RoadNetwork | None = None
        self.friction: float | None = None
        self.goal: Goal | None = None
        self.planner: Planner | None = None
        self.pending: Frame | None = None
        self.last_t = -1.0
        self.assembler = FrameAssembler()
        self.pub = self.create_publisher(TwistStamped, TOPIC_COMMAND, STREAM_QOS)
        self.create_subscription(String, TOPIC_SCENARIO, self._on_scenario, LATCHED_QOS)
        # Volatile subscription: matches a goal publisher of either durability.
        self.create_subscription(PoseStamped, TOPIC_GOAL, self._on_goal, STREAM_QOS)
        self.create_subscription(Odometry, TOPIC_EGO_ODOM, self._on_odom, STREAM_QOS)
        self.create_subscription(Odometry, TOPIC_OBJECTS_ODOM, self._on_odom, STREAM_QOS)
        self.create_subscription(MarkerArray, TOPIC_OBJECTS_MARKERS, self._on_markers, STREAM_QOS)
        self.create_subscription(DiagnosticArray, TOPIC_TRAFFIC_LIGHTS, self.assembler.add_lights, STREAM_QOS)
        if self.faults.active():
            self.get_logger().warn(f"fault modes on: {', '.join(self.faults.active())}")

    # --- inputs -------------------------------------------------------------------------------------------------

    def _on_scenario(self, msg: String) -> None:
        try:
            env = ScenarioEnvelope.from_json(msg.data)
            if env.map_xodr:
                self.network = RoadNetwork.from_string(env.map_xodr, source=env.map_path or env.id)
            else:
                self.network = load_network(env.map_path)
            self.friction = friction_from_xosc(env.xosc, source=env.id) if env.xosc else None
        except Txt2SceError as exc:
            self.get_logger().error(f"cannot use scenario: {exc}")
            return
        self.get_logger().info(f"scenario {env.id}: map {env.map_path or '(inline)'}, friction {self.friction}")
        # A new run starts at t = 0 again: forget the old run's frames.
        self.assembler.reset()
        self.pending = None
        self._restart()

    def _on_goal(self, msg: PoseStamped) -> None:
        goal = pose_to_goal(msg)
        if goal != self.goal:
            self.goal = goal
            if self.planner is not None:
                self.planner.set_goal(goal)
            else:
                self._restart()

    def _on_markers(self, msg: MarkerArray) -> None:
        self._handle(self.assembler.add_markers(msg))

    def _on_odom(self, msg: Odometry) -> None:
        self._handle(self.assembler.add_odometry(msg))

    # --- stepping -----------------------------------------------------------------------------------------------

    def _restart(self) -> None:
        """A new scenario (or the first goal): a fresh planner; a frame that waited for it is answered now."""
        self.planner = None
        self.last_t = -1.0
        if self.network is not None and self.goal is not None:
            friction = self.friction_override if self.friction_override is not None else self.friction
            self.planner = Planner(self.network, self.goal, self.params, faults=self.faults,
                                   road_friction=friction)
        if self.pending is not None and self.planner is not None:
            frame, self.pending = self.pending, None
            self._handle(frame)

    def _handle(self, frame: Frame | None) -> None:
        if frame is None:
            return
        if self.planner is None:
            self.pending = frame                       # answered once the map and the goal are here
            return
        self.last_t = frame.t
        self.pub.publish(command_to_twist(self.planner.step(frame)))


def main(args: list[str] | None = None) -> int:
    rclpy.init(args=args)
    node = PlannerNode()
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        node.destroy_node()
        if rclpy.ok():
            rclpy.shutdown()
    return 0


if __name__ == "__main__":
    sys.exit(main())
