"""A replay under test: DDS settings of a test run, a viewer node spun in a thread, a publisher node for the replay."""

from __future__ import annotations

import threading
from contextlib import contextmanager
from pathlib import Path
from typing import Any, Iterator

import rclpy

from tests.integration.rosproc import ros_test_env

_ENV = ("ROS_AUTOMATIC_DISCOVERY_RANGE", "ROS_DOMAIN_ID", "ROS_LOG_DIR", "FASTRTPS_DEFAULT_PROFILES_FILE",
        "RMW_IMPLEMENTATION")


@contextmanager
def viewer_and_replayer(tmp_path: Path, monkeypatch: Any) -> Iterator[tuple[Any, Any]]:
    """(viewer node, spinning; replay node) in a private context; subscribe on the viewer, replay with the other."""
    env = ros_test_env(tmp_path)
    for key in _ENV:
        monkeypatch.setenv(key, env[key])
    ctx = rclpy.Context()
    rclpy.init(context=ctx)
    try:
        node = rclpy.create_node("viewer", context=ctx)
        ex = rclpy.executors.SingleThreadedExecutor(context=ctx)
        ex.add_node(node)
        stop = threading.Event()

        def spin() -> None:
            while not stop.is_set():
                ex.spin_once(timeout_sec=0.01)

        spinner = threading.Thread(target=spin)
        spinner.start()
        pub_node = rclpy.create_node("txt2sce_replay", context=ctx)
        try:
            yield node, pub_node
        finally:
            stop.set()
            spinner.join()
            pub_node.destroy_node()
            node.destroy_node()
    finally:
        rclpy.shutdown(context=ctx)
