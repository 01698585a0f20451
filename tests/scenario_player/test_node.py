"""The player node over real DDS (its own process) against a trivial planner node in this process:
ROS lock-step gives the same trajectory as the batch core; a planner that stops answering ends the run as an error.
"""

from __future__ import annotations

import math
import os
import subprocess
import time
from pathlib import Path

import numpy as np
import pytest

from scenario_player import Simulation, SimulationConfig, load_scenario
from txt2sce_ros.contract import ControlCommand, RunStatus
from txt2sce_ros.ros_env import pick_domain_id, ros_environment

from .conftest import xosc

SIM_SECONDS = 3.0


def policy(k: int, speed: float) -> ControlCommand:
    """Depends only on the step index and the ego speed, both exact over DDS (float64 fields, ns stamps)."""
    return ControlCommand(t=k * 0.05, speed=min(speed + 0.08, 33.0), yaw_rate=0.04 * math.sin(0.2 * k))


def batch_run() -> dict[str, np.ndarray]:
    sim = Simulation(load_scenario(xosc("cut-in")), SimulationConfig(ego_mode="planner", time_limit=SIM_SECONDS))
    frame = sim.reset()
    k = 0
    while not sim.done:
        frame = sim.step(policy(k, frame.ego.speed))
        k += 1
    return sim.trajectory


@pytest.fixture()
def ros(tmp_path: Path):
    rclpy = pytest.importorskip("rclpy")
    env = ros_environment(domain_id=pick_domain_id(f"{tmp_path}:{os.getpid()}:{time.time_ns()}"),
                          log_dir=tmp_path / "ros_log")
    for key in ("ROS_AUTOMATIC_DISCOVERY_RANGE", "ROS_DOMAIN_ID", "ROS_LOG_DIR", "FASTRTPS_DEFAULT_PROFILES_FILE",
                "RMW_IMPLEMENTATION"):
        os.environ[key] = env[key]
    rclpy.init()
    yield env
    rclpy.shutdown()


def _run_player(env: dict[str, str], tmp_path: Path, answer_steps: int | None, *, lose_first: bool = False,
                **params: object) -> tuple[dict[int, tuple[float, float, float, float]], list[RunStatus],
                                           dict[int, tuple[float, float, float, float]]]:
    """Start the player node (subprocess) on cut-in.xosc with this process as the planner; return the ego states
    by step and the run statuses received. `lose_first`: the planner acts as if DDS lost the first frame's ego
    odometry (it ignores the first copy it receives)."""
    from geometry_msgs.msg import TwistStamped
    from nav_msgs.msg import Odometry
    from rclpy.executors import SingleThreadedExecutor
    from rclpy.node import Node
    from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
    from std_msgs.msg import String

    from txt2sce_ros.contract import TOPIC_COMMAND, TOPIC_EGO_ODOM, TOPIC_OBJECTS_ODOM, TOPIC_RUN_STATUS
    from txt2sce_ros.launcher import node_command
    from txt2sce_ros.ros_io import command_to_twist, quat_to_yaw, stamp_key

    node = Node("trivial_planner")
    ex = SingleThreadedExecutor()
    ex.add_node(node)
    reliable = QoSProfile(depth=100, reliability=ReliabilityPolicy.RELIABLE)
    latched = QoSProfile(depth=50, reliability=ReliabilityPolicy.RELIABLE, durability=DurabilityPolicy.TRANSIENT_LOCAL)
    pub = node.create_publisher(TwistStamped, TOPIC_COMMAND, reliable)
    ego: dict[int, tuple[float, float, float, float]] = {}
    npc: dict[int, tuple[float, float, float, float]] = {}
    statuses: list[RunStatus] = []

    def on_object(msg: Odometry) -> None:
        if msg.child_frame_id == "OverTaker":
            p = msg.pose.pose.position
            npc[round(stamp_key(msg.header.stamp) / 50_000_000)] = (
                p.x, p.y, quat_to_yaw(msg.pose.pose.orientation), msg.twist.twist.linear.x)

    lost: list[int] = []

    def on_ego(msg: Odometry) -> None:
        assert msg.child_frame_id == "ego"       # cut-in calls it 'Ego'; the wire name is the contract's
        k = round(stamp_key(msg.header.stamp) / 50_000_000)
        if lose_first and not lost:
            lost.append(k)
            return
        p, v = msg.pose.pose.position, msg.twist.twist.linear.x
        ego[k] = (p.x, p.y, quat_to_yaw(msg.pose.pose.orientation), v)
        if answer_steps is None or k < answer_steps:
            cmd = command_to_twist(policy(k, v))
            cmd.header.stamp = msg.header.stamp
            pub.publish(cmd)

    node.create_subscription(Odometry, TOPIC_EGO_ODOM, on_ego, reliable)
    node.create_subscription(Odometry, TOPIC_OBJECTS_ODOM, on_object, reliable)
    node.create_subscription(String, TOPIC_RUN_STATUS, lambda m: statuses.append(RunStatus.from_json(m.data)),
                             latched)
    log = open(tmp_path / "player.log", "wb")
    proc = subprocess.Popen(node_command("scenario_player_node", {
        "scenario_files": [str(xosc("cut-in"))], "lock_step": True, "time_limit": SIM_SECONDS,
        "exit_when_idle": True, "startup_timeout": 20.0, **params}), env=env, stdout=log,
        stderr=subprocess.STDOUT, start_new_session=True)
    try:
        deadline = time.monotonic() + 60
        while not any(s.state == "finished" for s in statuses) and time.monotonic() < deadline:
            ex.spin_once(timeout_sec=0.02)
        proc.wait(timeout=20)
    finally:
        if proc.poll() is None:
            proc.terminate()
            proc.wait(timeout=5)
        ex.remove_node(node)
        node.destroy_node()
        log.close()
    assert statuses, (tmp_path / "player.log").read_text()
    return ego, statuses, npc


def test_lockstep_ros_run_equals_batch_run(ros, tmp_path: Path) -> None:
    ego, statuses, npc = _run_player(ros, tmp_path, None, planner_timeout=10.0)
    final = statuses[-1]
    assert final.state == "finished" and final.end_reason == "time_limit" and final.verdict_hint == ""
    runs = batch_run()
    batch = runs["Ego"]
    steps = sorted(ego)
    assert steps == list(range(len(batch))), "every step published once, in order"
    ros_rows = np.array([ego[k] for k in steps])
    # Positions and speeds bit-identical; heading through a quaternion round trip to 1e-12.
    assert np.array_equal(ros_rows[:, [0, 1, 3]], batch[:, [1, 2, 4]])
    assert np.allclose(np.unwrap(ros_rows[:, 2]), np.unwrap(batch[:, 3]), atol=1e-12)
    assert batch[-1, 4] > batch[0, 4] + 1.0          # the planner's commands really drove the ego
    # The storyboard-driven OverTaker too (it reacts to the ego through its headway conditions).
    other = runs["OverTaker"]
    assert sorted(npc) == list(range(len(other)))
    assert np.array_equal(np.array([npc[k] for k in sorted(npc)])[:, [0, 1, 3]], other[:, [1, 2, 4]])


def test_planner_that_stops_answering_ends_the_run_as_error(ros, tmp_path: Path) -> None:
    ego, statuses, _ = _run_player(ros, tmp_path, 10, planner_timeout=0.5)
    final = statuses[-1]
    assert final.state == "finished"
    assert final.end_reason == "planner_not_responding" and final.verdict_hint == "error"
    assert max(ego) == 10                           # it waited at step 10 and went no further


def test_a_lost_first_frame_is_sent_again_and_the_run_goes_on(ros, tmp_path: Path) -> None:
    # DDS can lose the first frame right after discovery (scenario_player/node.py); lock-step then stalled at t = 0
    # until the planner timeout. The player sends an unanswered first frame again.
    ego, statuses, _ = _run_player(ros, tmp_path, None, lose_first=True, planner_timeout=10.0,
                                   first_frame_resend=0.3)
    final = statuses[-1]
    assert final.state == "finished" and final.end_reason == "time_limit" and final.verdict_hint == ""
    assert sorted(ego) == list(range(len(batch_run()["Ego"])))
    assert "first frame unanswered after" in (tmp_path / "player.log").read_text()


def test_scenarios_from_the_topic_run_in_order_and_bad_ones_report_errors(ros, tmp_path: Path) -> None:
    """Envelopes on /txt2sce/scenario (xosc and map as text): a malformed one is reported as an input error and
    the next one still runs (storyboard mode, real-time mode at 50x)."""
    from rclpy.executors import SingleThreadedExecutor
    from rclpy.node import Node
    from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
    from std_msgs.msg import String

    from txt2sce_ros.contract import TOPIC_RUN_STATUS, TOPIC_SCENARIO, ScenarioEnvelope
    from txt2sce_ros.launcher import node_command

    good_path = xosc("slow-lead-vehicle")
    scenario = load_scenario(good_path)
    good = ScenarioEnvelope(id="good", xosc=good_path.read_text(encoding="utf-8").replace(
        "../xosc/Catalogs", str(good_path.parent / "Catalogs")),
        map_xodr=Path(scenario.map_path).read_text(encoding="utf-8"), map_path=scenario.map_path)
    bad = ScenarioEnvelope(id="bad", xosc="<OpenSCENARIO><Entities>", map_xodr="")
    node = Node("generator_stub")
    ex = SingleThreadedExecutor()
    ex.add_node(node)
    latched = QoSProfile(depth=10, reliability=ReliabilityPolicy.RELIABLE, durability=DurabilityPolicy.TRANSIENT_LOCAL)
    pub = node.create_publisher(String, TOPIC_SCENARIO, latched)
    statuses: list[RunStatus] = []
    node.create_subscription(String, TOPIC_RUN_STATUS, lambda m: statuses.append(RunStatus.from_json(m.data)),
                             QoSProfile(depth=50, reliability=ReliabilityPolicy.RELIABLE,
                                        durability=DurabilityPolicy.TRANSIENT_LOCAL))
    for env in (bad, good):
        pub.publish(String(data=env.to_json()))
    log = open(tmp_path / "player.log", "wb")
    proc = subprocess.Popen(node_command("scenario_player_node", {
        "ego_mode": "storyboard", "lock_step": False, "realtime_factor": 50.0, "time_limit": 4.0}),
        env=ros, stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
    try:
        deadline = time.monotonic() + 60
        while sum(s.state == "finished" for s in statuses) < 2 and time.monotonic() < deadline:
            ex.spin_once(timeout_sec=0.05)
    finally:
        proc.terminate()
        proc.wait(timeout=10)
        ex.remove_node(node)
        node.destroy_node()
        log.close()
    finished = {s.scenario_id: s for s in statuses if s.state == "finished"}
    assert set(finished) == {"bad", "good"}, (tmp_path / "player.log").read_text()
    assert finished["bad"].verdict_hint == "error" and "malformed XML" in finished["bad"].end_reason
    assert finished["good"].verdict_hint == "" and finished["good"].end_reason == "time_limit"
    assert finished["good"].t == pytest.approx(4.0)
