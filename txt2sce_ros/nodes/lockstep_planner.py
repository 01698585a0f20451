"""The topic side every lock-stepped planner under test shares: inputs in, one command per complete frame out.

Subscribes /txt2sce/scenario (the map), /planning/goal, /sim/ego/odom, /sim/objects/odom, /sim/objects/markers,
/sim/traffic_lights; publishes /control/command stamped with the frame it answers (docs/ads_interface.md). A new run
shows as frames whose time went back; its envelope may arrive before or after its first frames, so a frame of a new
run waits until the envelope received since the previous run has been read. Subclasses build their planner from
(network, goal, envelope) in `make_planner` and answer frames through its `step(frame) -> ControlCommand`.
"""

from __future__ import annotations

import time
from typing import Any, Protocol

from diagnostic_msgs.msg import DiagnosticArray
from geometry_msgs.msg import PoseStamped, TwistStamped
from nav_msgs.msg import Odometry
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from std_msgs.msg import String
from visualization_msgs.msg import MarkerArray

from txt2sce_ros.contract import (TOPIC_COMMAND, TOPIC_EGO_ODOM, TOPIC_GOAL, TOPIC_OBJECTS_MARKERS,
                                  TOPIC_OBJECTS_ODOM, TOPIC_SCENARIO, TOPIC_TRAFFIC_LIGHTS, ControlCommand, Frame,
                                  Goal, ScenarioEnvelope)
from txt2sce_ros.errors import Txt2SceError
from txt2sce_ros.road import RoadNetwork, load_network
from txt2sce_ros.ros_io import FrameAssembler, command_to_twist, pose_to_goal, stamp_key, to_stamp

#: Reliable, deep enough for one odometry message per entity per step.
STREAM_QOS = QoSProfile(depth=200, reliability=ReliabilityPolicy.RELIABLE)
#: The scenario envelope is latched by its publisher; a late planner still gets it.
LATCHED_QOS = QoSProfile(depth=10, reliability=ReliabilityPolicy.RELIABLE,
                         durability=DurabilityPolicy.TRANSIENT_LOCAL)


class SteppingPlanner(Protocol):
    def step(self, frame: Frame) -> ControlCommand: ...


class LockStepPlannerNode(Node):
    """Base node: subclasses implement `make_planner` (and may override `set_goal`, `on_envelope`)."""

    def __init__(self, name: str) -> None:
        super().__init__(name)
        self.network: RoadNetwork | None = None
        self.envelope: ScenarioEnvelope | None = None
        self.goal: Goal | None = None
        self.planner: SteppingPlanner | None = None
        self.pending: Frame | None = None
        self.last_key = -1                  # stamp (ns) of the last frame answered
        self.fresh_scenario = False         # an envelope came after the last answered frame
        self.awaiting_scenario = True       # frames of a new run wait for its envelope (not with a fixed map)
        self.assembler = FrameAssembler()
        self.unsent: TwistStamped | None = None   # a command waiting for the player's subscription to match
        self.retry_timer = None
        self.fixed_map = ""
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

    def use_fixed_map(self, path: str) -> None:
        """Drive on this OpenDRIVE file when no scenario envelope is published (an envelope still takes precedence);
        raises InputError naming the file, so a bad map fails at start-up."""
        if path:
            self.network = load_network(path)
            self.fixed_map = path
            self.awaiting_scenario = False

    # --- hooks ------------------------------------------------------------------------------------------------------

    def make_planner(self, network: RoadNetwork, goal: Goal, envelope: ScenarioEnvelope | None) -> SteppingPlanner:
        raise NotImplementedError

    def read_envelope(self, env: ScenarioEnvelope) -> Any:
        """Extra per-run input a subclass reads from the envelope (raise Txt2SceError to refuse it)."""
        return None

    def set_goal(self, goal: Goal) -> None:
        """A goal changed during a run: by default the planner is rebuilt for the new mission at the next frame."""
        self.planner = None

    # --- inputs -----------------------------------------------------------------------------------------------------

    def _on_scenario(self, msg: String) -> None:
        try:
            env = ScenarioEnvelope.from_json(msg.data)
            if env.map_xodr:
                network = RoadNetwork.from_string(env.map_xodr, source=env.map_path or env.id)
            else:
                network = load_network(env.map_path)
            self.read_envelope(env)
        except Txt2SceError as exc:
            self.get_logger().error(f"cannot use scenario: {exc}")
            return
        self.get_logger().info(f"scenario {env.id}: map {env.map_path or '(inline)'}")
        self.network, self.envelope = network, env
        self.fresh_scenario = True
        self.awaiting_scenario = False
        self.planner = None
        self._try_answer()

    def _on_goal(self, msg: PoseStamped) -> None:
        goal = pose_to_goal(msg)
        if goal != self.goal:
            self.goal = goal
            if self.planner is not None:
                self.set_goal(goal)
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

    # --- stepping ---------------------------------------------------------------------------------------------------

    def _new_run_check(self, key: int) -> None:
        if key >= self.last_key:
            return
        self.assembler.reset()                     # its record of answered steps would drop the new run's frames
        self.last_key = -1
        self.pending = None
        self.planner = None
        self.on_run_end()
        # The envelope of this run came already (it is newer than the last answered frame) or is still to come.
        self.awaiting_scenario = not self.fresh_scenario and not self.fixed_map

    def on_run_end(self) -> None:
        """A new run started (frame time went back): the previous run's planner is gone."""

    def _handle(self, frame: Frame | None) -> None:
        if frame is not None:
            self.pending = frame
            self._try_answer()

    def _try_answer(self) -> None:
        if self.pending is None or self.awaiting_scenario or self.network is None or self.goal is None:
            return
        if self.planner is None:
            t0 = time.monotonic()
            self.planner = self.make_planner(self.network, self.goal, self.envelope)
            # One line a run: if a first frame goes unanswered, the log says whether the planner got that far.
            self.get_logger().info(f"run {self.envelope.id if self.envelope else '?'}: planner ready in "
                                   f"{time.monotonic() - t0:.2f} s, first frame t = {self.pending.t:.2f} s")
        frame, self.pending = self.pending, None
        self.last_key = stamp_key(to_stamp(frame.t))
        self.fresh_scenario = False
        self._send(command_to_twist(self.planner.step(frame)))

    def _send(self, msg: TwistStamped) -> None:
        """Publish a command; while discovery has not yet matched the player's subscription (the player can see
        us before we see it), hold it and retry, since a volatile message sent to nobody is lost and lock-step
        would stall until the player's timeout. After shutdown (Ctrl-C while a slow planner was still planning)
        the answer has no one to go to and is dropped, rather than raising in the middle of the node's exit."""
        if not self.context.ok():
            return
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
