"""The planner node over DDS: a separate `planner_node` process driven in lock-step by this test, which plays the
player's part with the real player core (publishing each frame through `ros_io`, stepping on each command). The
trajectory must equal the in-process run of the same cores, and fault parameters must reach the node."""

from __future__ import annotations

import math
import os
import signal
from pathlib import Path

import pytest

rclpy = pytest.importorskip("rclpy")

from geometry_msgs.msg import PoseStamped, TwistStamped  # noqa: E402
from nav_msgs.msg import Odometry  # noqa: E402
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy  # noqa: E402
from std_msgs.msg import String  # noqa: E402
from visualization_msgs.msg import MarkerArray  # noqa: E402
from diagnostic_msgs.msg import DiagnosticArray  # noqa: E402

from scenario_player import Simulation, SimulationConfig, load_scenario  # noqa: E402
from standin_planner import Faults, Planner, PlannerParams, friction_from_xosc  # noqa: E402
from txt2sce_ros import contract as c  # noqa: E402
from txt2sce_ros.cli.cmd_planner_check import DEFAULT_DIR  # noqa: E402
from txt2sce_ros.ros_io import (entity_to_odometry, frame_to_markers, goal_to_pose, lights_to_diagnostics,  # noqa: E402
                                stamp_key, to_stamp, twist_to_command)

from ..integration.rosproc import ros_test_env, start, use_env_in_process, wait_until  # noqa: E402

RELIABLE = QoSProfile(depth=200, reliability=ReliabilityPolicy.RELIABLE)
LATCHED = QoSProfile(depth=10, reliability=ReliabilityPolicy.RELIABLE, durability=DurabilityPolicy.TRANSIENT_LOCAL)
STEP_TIMEOUT = 10.0       # s wall clock for one command (generous: two shared cores)


class PlayerSide:
    """The test's stand-in for the player node: publishes frames, collects commands."""

    def __init__(self, context) -> None:
        self.node = rclpy.create_node("planner_node_test", context=context)
        n = self.node
        self.scenario = n.create_publisher(String, c.TOPIC_SCENARIO, LATCHED)
        self.goal = n.create_publisher(PoseStamped, c.TOPIC_GOAL, LATCHED)
        self.ego = n.create_publisher(Odometry, c.TOPIC_EGO_ODOM, RELIABLE)
        self.objects = n.create_publisher(Odometry, c.TOPIC_OBJECTS_ODOM, RELIABLE)
        self.markers = n.create_publisher(MarkerArray, c.TOPIC_OBJECTS_MARKERS, RELIABLE)
        self.lights = n.create_publisher(DiagnosticArray, c.TOPIC_TRAFFIC_LIGHTS, RELIABLE)
        self.commands: dict[int, TwistStamped] = {}
        n.create_subscription(TwistStamped, c.TOPIC_COMMAND, self._on_cmd, RELIABLE)
        self.executor = rclpy.executors.SingleThreadedExecutor(context=context)
        self.executor.add_node(n)

    def _on_cmd(self, msg: TwistStamped) -> None:
        self.commands[stamp_key(msg.header.stamp)] = msg

    def spin(self) -> None:
        self.executor.spin_once(timeout_sec=0.05)

    def matched(self) -> bool:
        pubs = (self.scenario, self.goal, self.ego, self.objects, self.markers, self.lights)
        return all(p.get_subscription_count() > 0 for p in pubs) and \
            self.node.count_publishers(c.TOPIC_COMMAND) > 0

    def publish_frame(self, frame: c.Frame) -> None:
        self.lights.publish(lights_to_diagnostics(frame.lights, frame.t))
        for obj in frame.objects:
            self.objects.publish(entity_to_odometry(obj))
        self.markers.publish(frame_to_markers(frame))
        self.ego.publish(entity_to_odometry(frame.ego))

    def command_for(self, t: float) -> c.ControlCommand:
        key = stamp_key(to_stamp(t))
        assert wait_until(lambda: key in self.commands, STEP_TIMEOUT, self.spin), f"no command for t={t}"
        return twist_to_command(self.commands.pop(key))


@pytest.fixture
def graph(tmp_path):
    """A planner_node process (parameters set per test) and the test's player side on a private DDS domain."""
    env = ros_test_env(tmp_path)
    use_env_in_process(env)
    context = rclpy.context.Context()
    rclpy.init(context=context)
    procs = []

    def launch(faults: list[str], **params) -> PlayerSide:
        procs.append(start("planner_node", {"faults": faults or [""], **params}, env, tmp_path / "planner.log"))
        side = PlayerSide(context)
        assert wait_until(side.matched, 30.0, side.spin), (tmp_path / "planner.log").read_text()
        return side

    yield launch
    for p in procs:
        if p.poll() is None:
            os.killpg(p.pid, signal.SIGINT)
            try:
                p.wait(10)
            except Exception:
                os.killpg(p.pid, signal.SIGKILL)
    rclpy.shutdown(context=context)


def _closed_loop_over_dds(side: PlayerSide, path: Path, steps: int, *, envelope: bool = True):
    text = path.read_text(encoding="utf-8")
    sim = Simulation(load_scenario(str(path)), SimulationConfig.from_config(ego_mode="planner"))
    frame = sim.reset()
    xodr = sim.network.source
    env = c.ScenarioEnvelope(id=path.stem, xosc=text, map_path=str(xodr),
                             map_xodr=Path(xodr).read_text(encoding="utf-8"))
    if envelope:
        side.scenario.publish(String(data=env.to_json()))
    side.goal.publish(goal_to_pose(sim.goal))
    for _ in range(steps):
        side.publish_frame(frame)
        frame = sim.step(side.command_for(frame.t))
        if sim.done:
            break
    return sim


def _closed_loop_in_process(path: Path, steps: int, faults: tuple[str, ...] = ()):
    sim = Simulation(load_scenario(str(path)), SimulationConfig.from_config(ego_mode="planner"))
    frame = sim.reset()
    planner = Planner(sim.network, sim.goal, PlannerParams.from_config(), faults=Faults.from_names(faults),
                      road_friction=friction_from_xosc(path.read_text(encoding="utf-8")))
    for _ in range(steps):
        frame = sim.step(planner.step(frame))
        if sim.done:
            break
    return sim


def test_node_drives_the_same_trajectory_as_the_in_process_core(graph):
    path = DEFAULT_DIR / "benign_junction_left.xosc"
    steps = 300                                   # 15 s: start, approach and the turn into the junction
    over_dds = _closed_loop_over_dds(graph([]), path, steps).trajectory["ego"]
    in_process = _closed_loop_in_process(path, steps).trajectory["ego"]
    assert over_dds.shape == in_process.shape
    assert in_process[-1, 4] > 3.0                # it really drove
    # Poses travel as float64 and yaw quaternions: agreement to well under a millimetre.
    assert abs(over_dds - in_process).max() < 1e-6


def test_fault_parameter_reaches_the_node(graph):
    path = DEFAULT_DIR / "fault_no_start_when_close.xosc"
    sim = _closed_loop_over_dds(graph(["no_start_when_close"]), path, 60)
    assert math.isclose(sim.trajectory["ego"][-1, 4], 0.0, abs_tol=1e-9)     # 3 s and still standing


def test_without_an_envelope_the_map_parameter_serves(graph):
    path = DEFAULT_DIR / "benign_straight.xosc"
    xodr = Simulation(load_scenario(str(path)), SimulationConfig.from_config()).network.source
    over_dds = _closed_loop_over_dds(graph([], map=str(xodr)), path, 100, envelope=False).trajectory["ego"]
    in_process = _closed_loop_in_process(path, 100).trajectory["ego"]
    assert over_dds[-1, 4] > 2.0 and abs(over_dds - in_process).max() < 1e-6
