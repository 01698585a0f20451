"""ROS 2 node of the scenario player: a thin adapter that runs `Simulation` cores one at a time and moves their
frames and the planner's commands over the topic interface (txt2sce_ros.contract, txt2sce_ros.ros_io).

Scenarios come from `/txt2sce/scenario` (std_msgs/String, JSON ScenarioEnvelope) and from the `scenario_files`
parameter; they are queued and run one after the other.

Per step k (lock-step protocol of txt2sce_ros.contract): `/clock`, `/sim/traffic_lights`, one `/sim/objects/odom`
per entity, `/sim/objects/markers`, `/planning/goal`, then `/sim/ego/odom`; then the player waits for the
`/control/command` stamped t_k and steps. For viewers, once per scenario before its first frame: the road on
`/sim/map/markers` (latched; the serialised message is built once per map), and the goal with the lights' states
on `/sim/scenario/markers` (latched; again in a step whose lights changed state: a comparison per step, a message
only on change). Run life cycle on `/txt2sce/run_status` (JSON RunStatus: 'started',
then 'finished' with end_reason, verdict_hint and the unsupported elements).

Parameters (defaults from config/player.yaml `node:`):
- `scenario_files` (string[]): .xosc files to run at start-up.
- `lock_step` (bool): lock-step (true) or real-time mode (false).
- `planner_timeout` (double, s wall): no command in time -> run ends, verdict_hint 'error',
  end_reason 'planner_not_responding'. The first frame of a run may take up to `startup_timeout` (the stack
  loads the map and plans then).
- `startup_timeout` (double, s wall): how long a run waits for its subscribers before the first frame (below).
- `first_frame_resend` (double, s wall; <= 0: never): lock-step sends a run's first frame again when it has gone
  this long unanswered (below).
- `await_subscribers` (string[]): names of nodes (e.g. 'oracle_monitor') that must subscribe `/sim/ego/odom`
  before a run starts; default `node.await_subscribers` of config/player.yaml, else none.
- `run_timeout` (double, s wall): a run never takes longer (end_reason 'wall_clock_limit', 'error').
- `realtime_factor` (double): real-time mode speed (sim s per wall s).
- `ego_mode` ('planner' | 'storyboard'), `time_limit` (double, sim s; <= 0: config default), `dt`, `seed`.
- `exit_when_idle` (bool): shut down once the queue is empty and every file has run (default false).

Start of a run: frames are volatile, so a subscriber matched after frame k never gets frames 0..k (a monitor that
matched two frames late judged a run without its first frames). Before the 'started' status and the first frame the
player therefore waits (up to `startup_timeout`) until, on every topic it publishes, each subscription the graph
knows of (QoS-compatible) has matched its publisher, a planner is there (planner mode) and every
`await_subscribers` node subscribes the ego topic. Missing planner -> 'planner_not_responding' (error); other
subscribers still missing -> a warning, and the run goes ahead.

Even then DDS may lose the first frame: a publisher that has just matched a subscription can send before the
subscriber has matched it back, and a volatile subscriber drops what came before (a known race of DDS
implementations). Lock-step would then stall on frame 0 until `planner_timeout` (seen with planners that start
slowly, such as the CommonRoad adapter). So the first frame (the goal with it) is sent again every
`first_frame_resend` seconds while unanswered; subscribers drop copies of a step they have completed
(`ros_io.FrameAssembler`), and a copy answered twice gives a command the player has already taken and ignores.
"""

from __future__ import annotations

import collections
import gc
import math
import sys
import time
from dataclasses import replace
from typing import Callable

import rclpy
from geometry_msgs.msg import PoseStamped, TwistStamped
from nav_msgs.msg import Odometry
from rclpy.duration import Duration
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSCompatibility, QoSProfile, ReliabilityPolicy, qos_check_compatible
from rosgraph_msgs.msg import Clock
from diagnostic_msgs.msg import DiagnosticArray
from std_msgs.msg import String
from visualization_msgs.msg import MarkerArray

from oracle_monitor import cdr
from txt2sce_ros.config import load_config
from txt2sce_ros.contract import (EGO_NAME, TOPIC_CLOCK, TOPIC_COMMAND, TOPIC_EGO_ODOM, TOPIC_GOAL,
                                  TOPIC_MAP_MARKERS, TOPIC_OBJECTS_MARKERS, TOPIC_OBJECTS_ODOM, TOPIC_RUN_STATUS,
                                  TOPIC_SCENARIO, TOPIC_SCENARIO_MARKERS, TOPIC_TRAFFIC_LIGHTS, ControlCommand, Frame,
                                  RunStatus, ScenarioEnvelope)
from txt2sce_ros.errors import Txt2SceError
from txt2sce_ros.nodes.lifetime import build_node, node_lifetime
from txt2sce_ros.nodes.waiter import SubscriptionWaiter
from txt2sce_ros.ros_io import road_markers_bytes, scenario_markers, string_msg

from .simulation import Simulation, SimulationConfig
from .syntax.scenario import load_scenario

#: How long (s) an exiting player waits for its subscribers to acknowledge the last run status.
EXIT_ACK_TIMEOUT = 2.0


def qos(depth: int, latched: bool = False) -> QoSProfile:
    return QoSProfile(depth=depth, reliability=ReliabilityPolicy.RELIABLE,
                      durability=DurabilityPolicy.TRANSIENT_LOCAL if latched else DurabilityPolicy.VOLATILE)


class PlayerNode(Node):
    def __init__(self) -> None:
        super().__init__("scenario_player")
        cfg = load_config("player")
        node_cfg, sim_cfg = cfg.get("node", {}), cfg.get("simulation", {})
        self.declare_parameter("scenario_files", [""])
        self.declare_parameter("lock_step", node_cfg.get("mode", "lockstep") == "lockstep")
        self.declare_parameter("planner_timeout", float(node_cfg.get("command_timeout", 2.0)))
        self.declare_parameter("run_timeout", float(node_cfg.get("run_wall_limit", 300.0)))
        self.declare_parameter("realtime_factor", float(node_cfg.get("realtime_factor", 1.0)))
        self.declare_parameter("startup_timeout", float(node_cfg.get("startup_timeout", 10.0)))
        self.declare_parameter("first_frame_resend", float(node_cfg.get("first_frame_resend", 5.0)))
        self.declare_parameter("ego_mode", "planner")
        self.declare_parameter("time_limit", 0.0)
        self.declare_parameter("dt", float(sim_cfg.get("dt", 0.05)))
        self.declare_parameter("seed", int(sim_cfg.get("seed", 0)))
        self.declare_parameter("exit_when_idle", False)
        self.declare_parameter("await_subscribers", [str(n) for n in node_cfg.get("await_subscribers") or [""]])
        p = self.get_parameter
        self.lock_step = bool(p("lock_step").value)
        self.planner_timeout = float(p("planner_timeout").value)
        self.run_timeout = float(p("run_timeout").value)
        self.rt_factor = max(float(p("realtime_factor").value), 1e-3)
        self.startup_timeout = float(p("startup_timeout").value)
        self.first_frame_resend = float(p("first_frame_resend").value)
        self.ego_mode = str(p("ego_mode").value)
        self.time_limit = float(p("time_limit").value)
        self.exit_when_idle = bool(p("exit_when_idle").value)
        self.await_subscribers = [str(n) for n in p("await_subscribers").value or [] if n]
        self.base_config = SimulationConfig.from_config(dt=float(p("dt").value), seed=int(p("seed").value),
                                                        ego_mode=self.ego_mode)
        depth = int(node_cfg.get("qos_depth", 100))
        self.pub_clock = self.create_publisher(Clock, TOPIC_CLOCK, qos(10))
        self.pub_lights = self.create_publisher(DiagnosticArray, TOPIC_TRAFFIC_LIGHTS, qos(depth))
        self.pub_objects = self.create_publisher(Odometry, TOPIC_OBJECTS_ODOM, qos(depth))
        self.pub_markers = self.create_publisher(MarkerArray, TOPIC_OBJECTS_MARKERS, qos(depth))
        self.pub_goal = self.create_publisher(PoseStamped, TOPIC_GOAL, qos(10, latched=True))
        self.pub_ego = self.create_publisher(Odometry, TOPIC_EGO_ODOM, qos(depth))
        self.pub_status = self.create_publisher(String, TOPIC_RUN_STATUS, qos(50, latched=True))
        self.pub_map = self.create_publisher(MarkerArray, TOPIC_MAP_MARKERS, qos(1, latched=True))
        self.pub_scene = self.create_publisher(MarkerArray, TOPIC_SCENARIO_MARKERS, qos(1, latched=True))
        # What a run publishes, with its QoS: every subscription to these must have matched before a run starts.
        self.outputs = [
            (TOPIC_CLOCK, self.pub_clock, qos(10)), (TOPIC_TRAFFIC_LIGHTS, self.pub_lights, qos(depth)),
            (TOPIC_OBJECTS_ODOM, self.pub_objects, qos(depth)), (TOPIC_OBJECTS_MARKERS, self.pub_markers, qos(depth)),
            (TOPIC_GOAL, self.pub_goal, qos(10, latched=True)), (TOPIC_EGO_ODOM, self.pub_ego, qos(depth)),
            (TOPIC_RUN_STATUS, self.pub_status, qos(50, latched=True)),
            (TOPIC_MAP_MARKERS, self.pub_map, qos(1, latched=True)),
            (TOPIC_SCENARIO_MARKERS, self.pub_scene, qos(1, latched=True)),
        ]
        # The per-step messages go out as CDR bytes straight through the publishers' handles: `Publisher.publish`
        # adds a type dispatch and a handle guard per call (~1 µs each, five or more calls per step); the node
        # owns these publishers for its whole life.
        self.send_clock, self.send_lights, self.send_object, self.send_markers, self.send_goal, self.send_ego = (
            p.handle.publish_raw for p in (self.pub_clock, self.pub_lights, self.pub_objects, self.pub_markers,
                                           self.pub_goal, self.pub_ego))
        self.create_subscription(String, TOPIC_SCENARIO, self._on_scenario, qos(10, latched=True))
        sub_command = self.create_subscription(TwistStamped, TOPIC_COMMAND, self._on_command, qos(depth), raw=True)
        # Lock-step waits for commands on this subscription alone (an executor's spin_once costs a round trip).
        self.command_wait = SubscriptionWaiter(self, sub_command)
        self.queue: collections.deque[ScenarioEnvelope] = collections.deque()
        for path in p("scenario_files").value or []:
            if path:
                self.queue.append(ScenarioEnvelope(id=path, xosc="", map_path="", meta={"file": path}))
        self.commands: dict[int, ControlCommand] = {}
        self.latest: ControlCommand | None = None
        self.latest_wall = 0.0
        self.shown_lights: tuple | None = None    # the lights last drawn on /sim/scenario/markers

    # -- callbacks ------------------------------------------------------------------------------------------------
    def _on_scenario(self, msg: String) -> None:
        try:
            self.queue.append(ScenarioEnvelope.from_json(msg.data))
        except Txt2SceError as exc:
            self._status(RunStatus(scenario_id="?", state="finished", end_reason=f"input_error: {exc}",
                                   verdict_hint="error"))

    def _on_command(self, data: bytes) -> None:
        # Taken raw (the subscription's `raw=True`) and read by the CDR decoder: no rclpy message per step.
        key, cmd = cdr.decode_command(data)
        self.commands[key] = cmd
        self.latest, self.latest_wall = cmd, time.monotonic()

    # -- publishing -----------------------------------------------------------------------------------------------
    def _status(self, status: RunStatus) -> None:
        self.pub_status.publish(string_msg(status.to_json()))

    def publish_frame(self, sim: Simulation, frame: Frame) -> None:
        # The contract names the ego 'ego' on the wire (child frame, marker text), whatever the scenario calls it:
        # the encoders take the wire name (a renamed copy of the frame cost more than all the encoding).
        t = frame.t
        # Every per-step message goes out already serialised (`publish_raw`), by the fast CDR
        # encoders that give rclpy's bytes for the same `ros_io` conversions (tested): building and serialising
        # rclpy message objects cost more per step than the DDS round trip lock-step waits for.
        self.send_clock(cdr.encode_clock(t))
        self.send_lights(cdr.encode_lights(frame.lights, t))
        send_object, encode_odometry = self.send_object, cdr.encode_odometry
        for obj in frame.objects:
            send_object(encode_odometry(obj))
        self.send_markers(cdr.encode_markers(frame, ego_name=EGO_NAME))
        if frame.lights != self.shown_lights:
            self.pub_scene.publish(scenario_markers(sim.goal, frame.lights, t))
            self.shown_lights = frame.lights
        if sim.goal is not None:
            self.send_goal(cdr.encode_goal(sim.goal, t))
        self.send_ego(cdr.encode_odometry(frame.ego, name=EGO_NAME))

    # -- runs -----------------------------------------------------------------------------------------------------
    def load(self, env: ScenarioEnvelope) -> Simulation:
        file = env.meta.get("file") if env.meta else None
        if file:
            scenario = load_scenario(file)
        else:
            scenario = load_scenario(env.xosc, source=env.id or "<envelope>", map_text=env.map_xodr or None,
                                     map_path=env.map_path or None)
        cfg = replace(self.base_config, scenario_id=env.id,
                      time_limit=self.time_limit if self.time_limit > 0 else None)
        return Simulation(scenario, cfg)

    def missing_planner(self) -> str:
        """Why no planner can answer the first frame yet ('' when one can)."""
        if self.count_publishers(TOPIC_COMMAND) == 0:
            return f"no publisher on {TOPIC_COMMAND}"
        if self.pub_ego.get_subscription_count() == 0:
            return f"no subscriber on {TOPIC_EGO_ODOM}"
        return ""

    def missing_subscribers(self) -> str:
        """Which known subscriber would miss the first frame ('' when none would)."""
        ego_nodes = {i.node_name for i in self.get_subscriptions_info_by_topic(TOPIC_EGO_ODOM)}
        for name in self.await_subscribers:
            if name not in ego_nodes:
                return f"node {name!r} not subscribed to {TOPIC_EGO_ODOM}"
        for topic, pub, offered in self.outputs:
            # The graph may list a subscription before discovery matched it to our publisher (or never: an
            # incompatible QoS never matches, so it is not waited for).
            known = sum(qos_check_compatible(offered, i.qos_profile)[0] != QoSCompatibility.ERROR
                        for i in self.get_subscriptions_info_by_topic(topic))
            matched = pub.get_subscription_count()
            if matched < known:
                return f"{topic}: {matched} of {known} subscriptions matched"
        return ""

    def wait_for_subscribers(self, executor: SingleThreadedExecutor, needs_planner: bool) -> tuple[str, str]:
        """Wait (up to `startup_timeout`) until the first frame reaches everyone; (planner missing, others
        missing) when the time runs out, ('', '') when all is ready."""
        deadline = time.monotonic() + self.startup_timeout
        while True:
            planner = self.missing_planner() if needs_planner else ""
            others = self.missing_subscribers()
            if not (planner or others) or time.monotonic() >= deadline:
                return planner, others
            executor.spin_once(timeout_sec=0.02)

    def run_one(self, env: ScenarioEnvelope, executor: SingleThreadedExecutor) -> RunStatus:
        try:
            sim = self.load(env)
            self._current = sim         # the command wait aborts the run it belongs to
        except Txt2SceError as exc:
            status = RunStatus(scenario_id=env.id, state="finished", end_reason=f"input_error: {exc}",
                               verdict_hint="error")
            self._status(status)
            return status
        needs_planner = self.ego_mode == "planner"
        self.commands.clear()
        self.latest = None              # a command of the previous run must not drive this one
        frame = sim.reset()
        # 'started' goes out after the wait too: the run status is volatile for some subscribers (the monitor).
        no_planner, others = self.wait_for_subscribers(executor, needs_planner)
        if others:
            self.get_logger().warn(f"run {env.id} starts although {others} (waited {self.startup_timeout:g} s)")
        # The road and the goal for viewers, before 'started': a recorder then has them with the run's start.
        self.pub_map.publish(road_markers_bytes(sim.network))
        self.pub_scene.publish(scenario_markers(sim.goal, frame.lights, frame.t))
        self.shown_lights = frame.lights
        self._status(replace(sim.status, state="started"))
        if no_planner:
            sim.abort("planner_not_responding")
        # Everything loaded so far (the scenario, the road, rclpy, the libraries) lives as long as the run: frozen,
        # the collector's full passes skip it instead of walking it again every few hundred steps. Thawed at the
        # run's end, so what the run leaves behind is collected as usual.
        gc.freeze()
        try:
            return self._play(sim, frame, needs_planner, env, executor)
        finally:
            gc.unfreeze()

    def _play(self, sim: Simulation, frame: Frame, needs_planner: bool, env: ScenarioEnvelope,
              executor: SingleThreadedExecutor) -> RunStatus:
        """The run's steps, from its first frame to the final status (published)."""
        wall0 = time.monotonic()
        next_wall = wall0
        # The first frame of a run waits as long as start-up may take: the stack loads the new map and plans its
        # route then, which on a loaded machine can outlast the per-step limit without anything being wrong.
        timeout = max(self.planner_timeout, self.startup_timeout)
        first = True
        while not sim.done:
            self.publish_frame(sim, frame)
            cmd: ControlCommand | None = None
            if needs_planner:
                key = round(frame.t * 1e9)      # = stamp_key(to_stamp(t)), without building a stamp
                if self.lock_step:
                    # What the next step does without the command (triggers, actions, the other entities'
                    # motion) is done while the planner works on this frame: only the rest of the step lies
                    # between its answer and the next frame (Simulation.prepare_step; same bits as sim.step).
                    sim.prepare_step()
                    resend = (lambda f=frame: self.publish_frame(sim, f)) if first else None
                    cmd = self._await_command(executor, key, wall0, timeout, resend)
                    timeout = self.planner_timeout
                    first = False
                    if cmd is None:
                        break
                else:
                    next_wall += sim.config.dt / self.rt_factor
                    while time.monotonic() < next_wall:
                        executor.spin_once(timeout_sec=max(0.0, min(0.005, next_wall - time.monotonic())))
                    cmd = self.latest
                    if cmd is None or time.monotonic() - self.latest_wall > self.planner_timeout:
                        if time.monotonic() - wall0 > self.planner_timeout:
                            sim.abort("planner_not_responding")
                            break
                self.commands.pop(key, None)
            else:
                executor.spin_once(timeout_sec=0.0)
                if not self.lock_step:
                    next_wall += sim.config.dt / self.rt_factor
                    time.sleep(max(0.0, next_wall - time.monotonic()))
            if time.monotonic() - wall0 > self.run_timeout:
                sim.abort("wall_clock_limit")
                break
            frame = sim.step(cmd)
        if sim.done and not sim.verdict_hint:
            # The final state, for recorders and oracles. In lock-step the planner answers it like any frame:
            # waiting (briefly) for that answer means the frame has gone round before 'finished' is announced,
            # so a monitor does not close the run on the status while the last frame is still in flight.
            self.publish_frame(sim, frame)
            if needs_planner and self.lock_step:
                key = round(frame.t * 1e9)      # = stamp_key(to_stamp(t)), without building a stamp
                deadline = time.monotonic() + min(self.planner_timeout, 1.0)
                while key not in self.commands and time.monotonic() < deadline:
                    self.command_wait.wait(0.01)
                self.commands.clear()
        status = sim.status
        self._status(status)
        self.get_logger().info(f"run {env.id}: {status.end_reason} at t={status.t:.2f}s")
        return status

    def _await_command(self, executor: SingleThreadedExecutor, key: int, wall0: float, timeout: float,
                       resend: Callable[[], None] | None = None) -> ControlCommand | None:
        """The command stamped `key`, or None when the run ended waiting. `resend` (the first frame): called every
        `first_frame_resend` seconds the frame goes unanswered (the module's docstring says why)."""
        start = time.monotonic()
        deadline = start + timeout
        every = self.first_frame_resend if resend is not None and self.first_frame_resend > 0 else math.inf
        next_send = start + every
        while key not in self.commands:
            now = time.monotonic()
            if now > deadline:
                self._current.abort("planner_not_responding")
                return None
            if now - wall0 > self.run_timeout:
                self._current.abort("wall_clock_limit")
                return None
            if now >= next_send:
                self.get_logger().info(f"first frame unanswered after {now - start:.1f} s: sent again")
                resend()                        # type: ignore[misc]
                next_send = now + every
            self.command_wait.wait(0.01)
        return self.commands[key]

    def serve(self, executor: SingleThreadedExecutor) -> None:
        while rclpy.ok():
            if self.queue:
                self.run_one(self.queue.popleft(), executor)
            elif self.exit_when_idle:
                # The last 'finished' goes out just before the process ends: a reliable message is delivered (and
                # repaired) only while its writer lives, and a subscriber then sometimes never got it (seen: a test
                # waited 60 s for the status of a run the log shows finished). Give the subscribers a moment.
                self.pub_status.wait_for_all_acked(Duration(seconds=EXIT_ACK_TIMEOUT))
                return
            else:
                executor.spin_once(timeout_sec=0.1)


def main(args: list[str] | None = None) -> int:
    rclpy.init(args=args)
    node = build_node(PlayerNode, "scenario_player_node")
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    with node_lifetime(node, on_exit=lambda: executor.remove_node(node)):
        node.serve(executor)
    return 0


if __name__ == "__main__":
    sys.exit(main())
