"""The monitor node as a real process over DDS, fed by a test publisher: live verdicts, recordings, shutdown.

Checks the acceptance's equality: the verdict published live == `judge_bag` on the node's recording == the core
`Oracle` on the same frames in-process. Then a second run is cut by SIGINT mid-way: the node must judge it as
incomplete and leave a closed, readable bag holding both runs.
"""

from __future__ import annotations

import json
import signal
from pathlib import Path

import pytest

rclpy = pytest.importorskip("rclpy")

from diagnostic_msgs.msg import DiagnosticArray  # noqa: E402
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy  # noqa: E402

from oracle_monitor import Oracle, OracleParams  # noqa: E402
from oracle_monitor.judge import judge_bag  # noqa: E402
from oracle_monitor.messages import verdicts_in  # noqa: E402
from oracle_monitor.replay import message_class  # noqa: E402
from oracle_monitor.topics import TOPIC_TYPES  # noqa: E402
from tests.integration.rosproc import ros_test_env, start, wait_until  # noqa: E402
from txt2sce_ros import contract as c  # noqa: E402
from txt2sce_ros import ros_io  # noqa: E402
from txt2sce_ros.contract import Goal, RunStatus, ScenarioEnvelope, SignalState, TrafficLightState, Verdict  # noqa: E402
from txt2sce_ros.road import RoadNetwork  # noqa: E402

from .oracle_runs import car, esmini_map, straight_run  # noqa: E402

PARAMS = OracleParams.from_config()
LATCHED = QoSProfile(depth=10, reliability=ReliabilityPolicy.RELIABLE, durability=DurabilityPolicy.TRANSIENT_LOCAL)
STREAM = QoSProfile(depth=1000, reliability=ReliabilityPolicy.RELIABLE)


def _envelope(sid: str) -> ScenarioEnvelope:
    path = esmini_map("straight_500m.xodr")
    return ScenarioEnvelope(id=sid, xosc="<OpenSCENARIO/>", map_path=str(path), map_xodr=path.read_text())


def test_live_verdict_equals_offline_and_sigint_leaves_a_closed_bag(tmp_path: Path, monkeypatch) -> None:
    env = ros_test_env(tmp_path)
    for key in ("ROS_AUTOMATIC_DISCOVERY_RANGE", "ROS_DOMAIN_ID", "ROS_LOG_DIR", "FASTRTPS_DEFAULT_PROFILES_FILE",
                "RMW_IMPLEMENTATION"):
        monkeypatch.setenv(key, env[key])
    bags = tmp_path / "bags"
    proc = start("oracle_monitor_node", {"bag_dir": str(bags)}, env, tmp_path / "monitor.log")
    ctx = rclpy.Context()
    rclpy.init(context=ctx)
    node = rclpy.create_node("oracle_test_feeder", context=ctx)
    executor = rclpy.executors.SingleThreadedExecutor(context=ctx)
    executor.add_node(node)
    spin = lambda: executor.spin_once(timeout_sec=0.02)
    try:
        pubs = {t: node.create_publisher(message_class(TOPIC_TYPES[t]), t, LATCHED if t == c.TOPIC_SCENARIO else STREAM)
                for t in c.CONTRACT_TOPICS}
        live: list[dict] = []
        node.create_subscription(DiagnosticArray, c.TOPIC_VIOLATIONS, lambda m: live.extend(verdicts_in(m)), STREAM)
        assert wait_until(lambda: all(p.get_subscription_count() for p in pubs.values())
                          and node.count_publishers(c.TOPIC_VIOLATIONS) > 0, 30.0, spin), \
            (tmp_path / "monitor.log").read_text()

        def send_run(sid: str, frames, status: RunStatus | None, goal: Goal) -> None:
            pubs[c.TOPIC_SCENARIO].publish(ros_io.string_msg(_envelope(sid).to_json()))
            pubs[c.TOPIC_RUN_STATUS].publish(ros_io.string_msg(RunStatus(sid, "started").to_json()))
            pubs[c.TOPIC_GOAL].publish(ros_io.goal_to_pose(goal))
            for f in frames:
                pubs[c.TOPIC_CLOCK].publish(ros_io.clock_msg(f.t))
                pubs[c.TOPIC_TRAFFIC_LIGHTS].publish(ros_io.lights_to_diagnostics(f.lights, f.t))
                for o in f.objects:
                    pubs[c.TOPIC_OBJECTS_ODOM].publish(ros_io.entity_to_odometry(o))
                pubs[c.TOPIC_OBJECTS_MARKERS].publish(ros_io.frame_to_markers(f))
                pubs[c.TOPIC_EGO_ODOM].publish(ros_io.entity_to_odometry(f.ego))
                spin()
            if status is not None:
                pubs[c.TOPIC_RUN_STATUS].publish(ros_io.string_msg(status.to_json()))

        # Run 1: a red light run; the light never changes, so DDS ordering across topics cannot matter.
        lights = lambda t: [TrafficLightState("sig1", SignalState.RED, 50.0, 0.0, 0.0, "1", (-1,))]
        frames1 = straight_run(lambda t: 10.0, 8.0, lights=lights, objects=lambda t: [car("npc1", t, 90.0, y=-3.5)])
        goal = Goal(120.0, 0.0, 0.0)
        send_run("run1", frames1, RunStatus("run1", "finished", 8.0, "time_limit"), goal)
        assert wait_until(lambda: len(live) >= 1, 30.0, spin), (tmp_path / "monitor.log").read_text()

        env1 = _envelope("run1")
        core = Oracle(RoadNetwork.from_string(env1.map_xodr, source=env1.map_path), goal, PARAMS, scenario_id="run1")
        for f in frames1:
            core.observe(f)
        expected = core.finish(RunStatus("run1", "finished", 8.0, "time_limit"))
        assert expected.category_names() == ("Misinterp",)
        assert live[0] == expected.to_dict()                      # live == in-process core

        # Run 2: rear-ends a stopped car at ~2.55 s, then the monitor is interrupted before the run finishes.
        frames2 = straight_run(lambda t: 10.0, 4.0, objects=lambda t: [car("lead", t, 30.0)])
        send_run("run2", frames2, None, goal)
        wait_until(lambda: False, 1.0, spin)                      # let the last messages be delivered
    finally:
        executor.shutdown()
        node.destroy_node()
        rclpy.shutdown(context=ctx)
        proc.send_signal(signal.SIGINT)
        proc.wait(timeout=30)

    (bag,) = [p for p in bags.iterdir() if p.is_dir()]
    assert bag.name == "monitor_001"
    assert (bag / "metadata.yaml").is_file(), "SIGINT must finalise the bag"
    offline = judge_bag(bag, PARAMS)
    assert offline.complete and len(offline.verdicts) == 2
    assert offline.verdicts[0].to_dict() == live[0]               # offline == live
    assert offline.agrees_with_live() is True                     # and == both verdicts recorded live
    v2 = offline.verdicts[1]
    assert v2.scenario_id == "run2" and v2.verdict is Verdict.FAIL and v2.category_names() == ("Collisions",)
    assert any("incomplete" in n for n in v2.notes)
    lines = [json.loads(x) for x in (bags / "verdicts.jsonl").read_text().splitlines()]
    assert [(x["scenario_id"], x["run"]) for x in lines] == [("run1", 1), ("run2", 2)]
    assert lines[1]["verdict"] == "fail"
