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
from diagnostic_msgs.msg import DiagnosticArray
from geometry_msgs.msg import PoseStamped, TwistStamped
from nav_msgs.msg import Odometry
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from std_msgs.msg import String
from visualization_msgs.msg import MarkerArray

from txt2sce_ros.contract import (TOPIC_COMMAND, TOPIC_EGO_ODOM, TOPIC_GOAL, TOPIC_OBJECTS_MARKERS,
                                  TOPIC_OBJECTS_ODOM, TOPIC_SCENARIO, TOPIC_TRAFFIC_LIGHTS, Frame, Goal,
                                  ScenarioEnvelope)
from txt2sce_ros.errors import Txt2SceError
from txt2sce_ros.nodes.lifetime import node_lifetime
from txt2sce_ros.road import RoadNetwork, load_network
from txt2sce_ros.ros_io import FrameAssembler, command_to_twist, pose_to_goal, stamp_key, to_stamp

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
        self.declare_parameter("map", "")
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
        self.last_key = -1                  # stamp (ns) of the last frame answered
        self.fresh_scenario = False         # an envelope came after the last answered frame
        self.awaiting_scenario = True       # frames of a new run wait for its envelope (not with a fixed map)
        self.assembler = FrameAssembler()
        self.unsent: TwistStamped | None = None   # a command waiting for the player's subscription to match
        self.retry_timer = None
        self.fixed_map = str(self.get_parameter("map").value)
        if self.fixed_map:
            self.network = load_network(self.fixed_map)     # raises InputError naming the file: fail at start-up
            self.awaiting_scenario = False
        # Creation order matters: the player starts a run once a /control/command publisher exists and the ego topic
        # has a subscriber, and then waits only for the subscriptions the graph already knows. Endpoints are
        # announced in creation order, so with the ego subscription last and the command publisher after it, every
        # other input of frame 0 is known (and waited for) by then: a planner that missed frame 0's lights or
        # markers never answered it, and the run ended 'planner_not_responding' at t = 0.
        self.create_subscription(String, TOPIC_SCENARIO, self._on_scenario, LATCHED_QOS)
        # Volatile subscription: matches a goal publisher of either durability.
        self.create_subscription(PoseStamped, TOPIC_GOAL, self._on_goal, STREAM_QOS)
        self.create_subscription(DiagnosticArray, TOPIC_TRAFFIC_LIGHTS, self._on_lights, STREAM_QOS)
        self.create_subscription(MarkerArray, TOPIC_OBJECTS_MARKERS, self._on_markers, STREAM_QOS)
        self.create_subscription(Odometry, TOPIC_OBJECTS_ODOM, self._on_odom, STREAM_QOS)
        self.create_subscription(Odometry, TOPIC_EGO_ODOM, self._on_odom, STREAM_QOS)
        self.pub = self.create_publisher(TwistStamped, TOPIC_COMMAND, STREAM_QOS)
        if self.faults.active():
            self.get_logger().warn(f"fault modes on: {', '.join(self.faults.active())}")

    # --- inputs -------------------------------------------------------------------------------------------------
    #
    # A new run shows as frames whose time went back. Its scenario envelope (the map) may arrive before or after
    # its first frames (different topics, no order between them), so a frame of a new run waits until the
    # envelope received since the previous run has been read; the latched goal is taken whenever it comes.

    def _on_scenario(self, msg: String) -> None:
        try:
            env = ScenarioEnvelope.from_json(msg.data)
            if env.map_xodr:
                network = RoadNetwork.from_string(env.map_xodr, source=env.map_path or env.id)
            else:
                network = load_network(env.map_path)
            friction = friction_from_xosc(env.xosc, source=env.id) if env.xosc else None
        except Txt2SceError as exc:
            self.get_logger().error(f"cannot use scenario: {exc}")
            return
        self.get_logger().info(f"scenario {env.id}: map {env.map_path or '(inline)'}, friction {friction}")
        self.network, self.friction = network, friction
        self.fresh_scenario = True
        self.awaiting_scenario = False
        self.planner = None
        self._try_answer()

    def _on_goal(self, msg: PoseStamped) -> None:
        goal = pose_to_goal(msg)
        if goal != self.goal:
            self.goal = goal
            if self.planner is not None:
                self.planner.set_goal(goal)
            self._try_answer()

    def _on_markers(self, msg: MarkerArray) -> None:
        if msg.markers:
            self._new_run_check(stamp_key(msg.markers[0].header.stamp))
        self._handle(self.assembler.add_markers(msg))

    def _on_odom(self, msg: Odometry) -> None:
        self._new_run_check(stamp_key(msg.header.stamp))
        self._handle(self.assembler.add_odometry(msg))

    def _on_lights(self, msg: DiagnosticArray) -> None:
        # Part of the step (ros_io.FrameAssembler): it may complete the frame, and it may be a new run's first.
        self._new_run_check(stamp_key(msg.header.stamp))
        self._handle(self.assembler.add_lights(msg))

    # --- stepping -----------------------------------------------------------------------------------------------

    def _new_run_check(self, key: int) -> None:
        if key >= self.last_key:
            return
        self.assembler.reset()                     # its record of answered steps would drop the new run's frames
        self.last_key = -1
        self.pending = None
        self.planner = None
        # The envelope of this run came already (it is newer than the last answered frame) or is still to come.
        self.awaiting_scenario = not self.fresh_scenario and not self.fixed_map

    def _handle(self, frame: Frame | None) -> None:
        if frame is not None:
            self.pending = frame
            self._try_answer()

    def _try_answer(self) -> None:
        if self.pending is None or self.awaiting_scenario or self.network is None or self.goal is None:
            return
        if self.planner is None:
            friction = self.friction_override if self.friction_override is not None else self.friction
            self.planner = Planner(self.network, self.goal, self.params, faults=self.faults,
                                   road_friction=friction)
        frame, self.pending = self.pending, None
        self.last_key = stamp_key(to_stamp(frame.t))
        self.fresh_scenario = False
        self._send(command_to_twist(self.planner.step(frame)))

    def _send(self, msg: TwistStamped) -> None:
        """Publish a command; while discovery has not yet matched the player's subscription (the player can see
        us before we see it), hold it and retry, since a volatile message sent to nobody is lost and lock-step
        would stall until the player's timeout."""
        if self.pub.get_subscription_count() > 0:
            self.pub.publish(msg)
            return
        self.unsent = msg
        if self.retry_timer is None:
            self.retry_timer = self.create_timer(0.01, self._flush_unsent)

    def _flush_unsent(self) -> None:
        if self.unsent is not None and self.pub.get_subscription_count() > 0:
            self.pub.publish(self.unsent)
            self.unsent = None
        if self.unsent is None and self.retry_timer is not None:
            self.retry_timer.cancel()
            self.destroy_timer(self.retry_timer)
            self.retry_timer = None


def main(args: list[str] | None = None) -> int:
    rclpy.init(args=args)
    with node_lifetime(PlannerNode()) as node:
        rclpy.spin(node)
    return 0


if __name__ == "__main__":
    sys.exit(main())
