"""ROS 2 oracle monitor node: subscribes the contract topics, judges online, publishes violations and verdicts on
/oracle/violations (diagnostic_msgs/DiagnosticArray), and records each run to its own rosbag2 MCAP directory.

Parameters:
- `bag_dir` (string, default ""): where runs are recorded, one directory `<NNN>_<scenario id>` per run, plus
  `verdicts.jsonl` (one RunVerdict per line); "" records nothing.
- `config` (string, default ""): oracle thresholds YAML (default `config/oracle.yaml`).
- `flush_interval` (double, default 0.5): seconds between flushes of the recording to disk.

Thin adapter: subscriptions take the serialized bytes (`raw=True`), which are recorded unchanged and decoded with
the same `cdr.decode` the offline judge uses, then handed to the `JudgeSession` the offline judge uses —
so `txt2sce judge` on the recording reproduces the live verdict. On SIGINT/SIGTERM a run still open is judged as
incomplete, its verdict recorded and the bag closed (metadata.yaml written); a kill -9 leaves the flushed prefix.
"""

from __future__ import annotations

import json
import re
import sys
import time
from pathlib import Path

import rclpy
from diagnostic_msgs.msg import DiagnosticArray
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from rclpy.serialization import serialize_message

from txt2sce_ros import contract as c
from txt2sce_ros.contract import RunStatus
from txt2sce_ros.errors import Txt2SceError

from .cdr import decode
from .messages import verdict_to_diagnostics, violations_to_diagnostics
from .params import OracleParams
from .recorder import BagRecorder, typestore
from .records import RunVerdict, Violation
from .replay import message_class
from .session import JudgeSession
from .topics import TOPIC_TYPES

SCENARIO_QOS = QoSProfile(depth=10, reliability=ReliabilityPolicy.RELIABLE, durability=DurabilityPolicy.TRANSIENT_LOCAL)
STREAM_QOS = QoSProfile(depth=1000, reliability=ReliabilityPolicy.RELIABLE)
PENDING_LIMIT = 10_000       # messages held while a run has no name yet; beyond it the bag opens as "run"


class OracleMonitorNode(Node):
    def __init__(self) -> None:
        super().__init__("oracle_monitor")
        self.declare_parameter("bag_dir", "")
        self.declare_parameter("config", "")
        self.declare_parameter("flush_interval", 0.5)
        bag_dir = str(self.get_parameter("bag_dir").value)
        config = str(self.get_parameter("config").value) or None
        self.flush_interval = float(self.get_parameter("flush_interval").value)
        self.bag_dir = Path(bag_dir) if bag_dir else None
        if self.bag_dir:
            self.bag_dir.mkdir(parents=True, exist_ok=True)
        self.session = JudgeSession(OracleParams.from_config(config), on_violations=self._on_violations,
                                    on_verdict=self._on_verdict)
        self.typestore = typestore()
        self.recorder: BagRecorder | None = None
        self._pending: list[tuple[str, bytes, int]] = []
        self.runs = 0
        self.pub = self.create_publisher(DiagnosticArray, c.TOPIC_VIOLATIONS, STREAM_QOS)
        for topic in c.CONTRACT_TOPICS:
            qos = SCENARIO_QOS if topic == c.TOPIC_SCENARIO else STREAM_QOS
            self.create_subscription(message_class(TOPIC_TYPES[topic]), topic,
                                     lambda data, topic=topic: self._on_raw(topic, data), qos, raw=True)
        if self.flush_interval > 0:
            # Also flush while no message arrives (a crashed player): the bag on disk stays current.
            self.create_timer(self.flush_interval, self._flush)
        self.get_logger().info(f"judging {len(c.CONTRACT_TOPICS)} topics, recording to {self.bag_dir or '(off)'}")

    # --- messages ------------------------------------------------------------------------------------------------

    def _on_raw(self, topic: str, data: bytes) -> None:
        try:
            msg = decode(data, TOPIC_TYPES[topic], self.typestore)
        except Exception as exc:          # a malformed message must not stop the monitor
            self.get_logger().error(f"undecodable message on {topic}: {exc}")
            return
        try:
            # Messages that may open the next run (a scenario, a goal, a 'started' status) go to the session first:
            # if they close the previous run (unfinished, or its final status held for late frames), its bag is
            # closed before they are recorded, so they land in the next run's bag.
            starts = topic in (c.TOPIC_SCENARIO, c.TOPIC_GOAL) or (
                topic == c.TOPIC_RUN_STATUS and RunStatus.from_json(msg.data).state == "started")
            if starts:
                self.session.on_message(topic, msg)
                self._record(topic, data)
            else:
                self._record(topic, data)
                self.session.on_message(topic, msg)
        except (Txt2SceError, ValueError, KeyError, TypeError) as exc:
            self.get_logger().error(f"bad message on {topic}: {exc}")

    def _record(self, topic: str, data: bytes, *, force: bool = False) -> None:
        if self.bag_dir is None:
            return
        if self.recorder is None:
            run = self.session.run
            sid = run.scenario_id if run and run.scenario_id else ""
            if not sid and not force and len(self._pending) < PENDING_LIMIT:
                # DDS does not order topics against each other: a run's goal or clock may arrive before its
                # scenario. Hold them (with their receive times) until the run's name is known.
                self._pending.append((topic, data, time.time_ns()))
                return
            self.runs += 1
            path = self.bag_dir / f"{self.runs:03d}_{re.sub(r'[^A-Za-z0-9_.-]+', '_', sid or 'run')}"
            while path.exists():
                path = path.with_name(path.name + "_")
            self.recorder = BagRecorder(path, flush_interval=self.flush_interval)
            self.get_logger().info(f"recording {path}")
            for p_topic, p_data, p_ns in self._pending:
                self.recorder.write(p_topic, p_data, log_time_ns=p_ns)
            self._pending.clear()
        self.recorder.write(topic, data)

    def _on_violations(self, t: float, violations: list[Violation]) -> None:
        msg = violations_to_diagnostics(t, violations)
        self.pub.publish(msg)
        self._record(c.TOPIC_VIOLATIONS, serialize_message(msg))

    def _on_verdict(self, verdict: RunVerdict) -> None:
        msg = verdict_to_diagnostics(verdict)
        try:
            self.pub.publish(msg)
        except Exception:                 # shutting down: the context may be gone, the recording still matters
            pass
        self.get_logger().info(f"{verdict.scenario_id or 'run'}: {verdict.summary()}")
        if self.bag_dir is None:
            return
        self._record(c.TOPIC_VIOLATIONS, serialize_message(msg), force=True)
        path = self.recorder.path if self.recorder else None
        self._close_bag()
        with open(self.bag_dir / "verdicts.jsonl", "a", encoding="utf-8") as fh:
            fh.write(json.dumps({"bag": str(path), **verdict.to_dict()}, sort_keys=True) + "\n")

    def _flush(self) -> None:
        if self.recorder is not None:
            self.recorder.flush()

    def _close_bag(self) -> None:
        if self.recorder is not None:
            self.recorder.close()
            self.recorder = None

    def shutdown(self) -> None:
        """Judge a run still open as incomplete and finalise its recording."""
        self.session.close()
        self._close_bag()


def main(args: list[str] | None = None) -> int:
    rclpy.init(args=args)
    node = OracleMonitorNode()
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        node.shutdown()
        node.destroy_node()
        if rclpy.ok():
            rclpy.shutdown()
    return 0


if __name__ == "__main__":
    sys.exit(main())
