"""The generator node publishes scenario envelopes over DDS, one at a time, waiting for each run to finish."""

from pathlib import Path

import pytest

from txt2sce_ros.contract import TOPIC_RUN_STATUS, TOPIC_SCENARIO, RunStatus, ScenarioEnvelope
from txt2sce_ros.launcher import _stop
from txt2sce_ros.paths import shared_dir

from .rosproc import ros_test_env, start, use_env_in_process, wait_until

XOSC = shared_dir() / "data" / "conformance" / "esmini" / "xosc"


@pytest.mark.timeout(120)
def test_generator_publishes_one_scenario_per_finished_run(tmp_path: Path) -> None:
    import rclpy
    from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
    from std_msgs.msg import String

    env = ros_test_env(tmp_path)
    use_env_in_process(env)
    files = [XOSC / "cut-in.xosc", XOSC / "pedestrian.xosc"]
    gen = start("generator_node", {"scenarios": [str(f) for f in files]}, env, tmp_path / "gen.log")
    rclpy.init()
    node = rclpy.create_node("fake_player")
    got: list[ScenarioEnvelope] = []
    try:
        node.create_subscription(String, TOPIC_SCENARIO, lambda m: got.append(ScenarioEnvelope.from_json(m.data)),
                                 QoSProfile(depth=10, reliability=ReliabilityPolicy.RELIABLE,
                                            durability=DurabilityPolicy.TRANSIENT_LOCAL))
        status = node.create_publisher(String, TOPIC_RUN_STATUS, 10)
        spin = lambda: rclpy.spin_once(node, timeout_sec=0.05)  # noqa: E731
        assert wait_until(lambda: len(got) == 1, 30, spin), (tmp_path / "gen.log").read_text()
        first = got[0]
        assert first.id == "cut-in" and "<OpenSCENARIO" in first.xosc
        assert first.map_path.endswith("e6mini.xodr") and "<OpenDRIVE" in first.map_xodr
        # Nothing more until the run is reported finished.
        wait_until(lambda: False, 0.5, spin)
        assert len(got) == 1
        assert wait_until(lambda: status.get_subscription_count() > 0, 10, spin)
        status.publish(String(data=RunStatus("cut-in", "finished").to_json()))
        assert wait_until(lambda: len(got) == 2, 30, spin)
        assert got[1].id == "pedestrian"
        status.publish(String(data=RunStatus("pedestrian", "finished").to_json()))
        assert wait_until(lambda: gen.poll() is not None, 30, spin), "generator did not exit when done"
        assert gen.returncode == 0
    finally:
        _stop(gen)
        node.destroy_node()
        rclpy.shutdown()
