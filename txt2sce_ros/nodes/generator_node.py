"""Generator node: publishes scenario files on /txt2sce/scenario, one at a time.

Parameters:
- `scenarios` (string or string[]): .xosc files, directories of them, or scenario-tree directories (with manifest.json).
- `wait_for_result` (bool, default true): publish the next scenario only after the player reports the current
  one `finished` on /txt2sce/run_status; false publishes all at once (the player queues them).
- `subscriber_timeout` (float s, default 30): how long to wait for a player to subscribe before giving up.
- `exit_when_done` (bool, default true): shut down after the last scenario finished.

The envelope is published reliable + transient-local so a player that subscribes late still gets it.
"""

from __future__ import annotations

import sys
import time

import rclpy
from rcl_interfaces.msg import ParameterDescriptor
from rclpy.duration import Duration
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from std_msgs.msg import String

from ..contract import TOPIC_RUN_STATUS, TOPIC_SCENARIO, RunStatus
from ..errors import InputError
from ..scenario_source import iter_envelopes
from .lifetime import build_node, node_lifetime

SCENARIO_QOS = QoSProfile(depth=10, reliability=ReliabilityPolicy.RELIABLE, durability=DurabilityPolicy.TRANSIENT_LOCAL)


def _paths(value: object) -> list[str]:
    """The `scenarios` parameter as a list of paths (a string or a string array)."""
    items = [value] if isinstance(value, str) else value
    if not isinstance(items, (list, tuple)) or not all(isinstance(x, str) for x in items):
        raise InputError(f"parameter scenarios: expected a path or a list of paths, got {value!r}")
    return [x for x in items if x]


class GeneratorNode(Node):
    def __init__(self) -> None:
        super().__init__("txt2sce_generator")
        # One path or a list of them: `-p scenarios:=trees` is what a user types first.
        self.declare_parameter("scenarios", [""], ParameterDescriptor(dynamic_typing=True))
        self.declare_parameter("wait_for_result", True)
        self.declare_parameter("subscriber_timeout", 30.0)
        self.declare_parameter("exit_when_done", True)
        inputs = _paths(self.get_parameter("scenarios").value)
        self.wait = bool(self.get_parameter("wait_for_result").value)
        self.timeout = float(self.get_parameter("subscriber_timeout").value)
        self.exit_when_done = bool(self.get_parameter("exit_when_done").value)
        self.pub = self.create_publisher(String, TOPIC_SCENARIO, SCENARIO_QOS)
        # Volatile: compatible with whatever durability the player offers.
        self.create_subscription(String, TOPIC_RUN_STATUS, self._on_status,
                                 QoSProfile(depth=50, reliability=ReliabilityPolicy.RELIABLE))
        self.pending = list(iter_envelopes(inputs))
        self.in_flight: str | None = None
        self.finished: list[str] = []
        self.done = not self.pending
        self.started = time.monotonic()
        self.get_logger().info(f"{len(self.pending)} scenario(s) to publish")
        self.timer = self.create_timer(0.05, self._tick)

    def _tick(self) -> None:
        if self.done or (self.wait and self.in_flight):
            return
        if self.pub.get_subscription_count() == 0:
            if time.monotonic() - self.started > self.timeout:
                self.get_logger().error(f"no subscriber on {TOPIC_SCENARIO} after {self.timeout:.0f} s")
                self.done = True
            return
        while self.pending:
            env = self.pending.pop(0)
            self.pub.publish(String(data=env.to_json()))
            self.get_logger().info(f"published scenario {env.id}")
            self.in_flight = env.id
            if self.wait:
                return
        if not self.wait:
            self.done = True

    def _on_status(self, msg: String) -> None:
        status = RunStatus.from_json(msg.data)
        if status.state == "finished" and status.scenario_id == self.in_flight:
            self.finished.append(status.scenario_id)
            self.in_flight = None
            if not self.pending:
                self.done = True


def main(args: list[str] | None = None) -> int:
    rclpy.init(args=args)
    node = build_node(GeneratorNode, "generator_node")
    with node_lifetime(node):
        while rclpy.ok() and not (node.done and node.exit_when_done):
            rclpy.spin_once(node, timeout_sec=0.1)
        if rclpy.ok():
            # Without `wait_for_result` the last envelopes go out just before the process ends, and a reliable
            # message is delivered (and repaired) only while its writer lives: let the player acknowledge them.
            node.pub.wait_for_all_acked(Duration(seconds=2.0))
    return 0


if __name__ == "__main__":
    sys.exit(main())
