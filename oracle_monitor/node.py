"""ROS 2 oracle monitor node: subscribes the contract topics, judges online, publishes violations and verdicts on
/oracle/violations (diagnostic_msgs/DiagnosticArray), and records each run to its own rosbag2 MCAP directory.

Parameters:
- `bag_dir` (string, default ""): where the runs are recorded: one rosbag2 directory `monitor_<NNN>` per monitor
  process holding every run it saw, in arrival order, plus `verdicts.jsonl` (one RunVerdict per line with the bag
  and the run's index in it); "" records nothing. One bag rather than one per run: a monitor that falls behind
  receives the next run's first messages before the last ones of the current run, so cutting the stream per run
  would put messages in the wrong bag; one stream re-judged offline gives the live verdicts exactly.
- `config` (string, default ""): oracle thresholds YAML (default `config/oracle.yaml`).
- `flush_interval` (double, default 0.5): seconds between flushes of the recording to disk.

Thin adapter: subscriptions take the serialized bytes (`raw=True`), which are recorded unchanged and decoded with
the same `cdr.decode` the offline judge uses, then handed to the `JudgeSession` the offline judge uses —
so `txt2sce judge` on the recording reproduces the live verdicts. On SIGINT/SIGTERM the monitor first takes what
DDS already delivered to it (until nothing came for `DRAIN_IDLE` s, at most `DRAIN_LIMIT` s; a second signal stops
at once): a monitor lagging behind the lock-step loop would otherwise lose the last frames of the last run when
the launcher stops the graph right after the player's 'finished' (a verdict on a truncated run). Then a run still
open is judged as incomplete, its verdict recorded and the bag closed (metadata.yaml written); a kill -9 leaves the
flushed prefix.
"""

from __future__ import annotations

import json
import signal
import sys
import time
from pathlib import Path
from typing import Callable

import rclpy
from diagnostic_msgs.msg import DiagnosticArray
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from rclpy.serialization import serialize_message
from rclpy.signals import SignalHandlerOptions

from txt2sce_ros import contract as c
from txt2sce_ros.errors import Txt2SceError
from txt2sce_ros.nodes.lifetime import build_node, node_lifetime

from .cdr import decode
from .messages import verdict_to_diagnostics, violations_to_diagnostics
from .params import OracleParams
from .recorder import BagRecorder, typestore
from .records import RunVerdict, Violation
from .replay import message_class
from .session import JudgeSession
from .topics import TOPIC_TYPES

SCENARIO_QOS = QoSProfile(depth=10, reliability=ReliabilityPolicy.RELIABLE, durability=DurabilityPolicy.TRANSIENT_LOCAL)
#: Deep: the monitor is outside the lock-step loop, and on a loaded machine it falls behind by hundreds of steps
#: (one odometry per entity per step); a keep-last history that overflows drops frames from the middle of a run.
STREAM_QOS = QoSProfile(depth=5000, reliability=ReliabilityPolicy.RELIABLE)
VIOLATIONS_QOS = QoSProfile(depth=1000, reliability=ReliabilityPolicy.RELIABLE)
VIEW_QOS = QoSProfile(depth=10, reliability=ReliabilityPolicy.RELIABLE, durability=DurabilityPolicy.TRANSIENT_LOCAL)

#: Shutdown drain: stop taking messages once none came for this long (s), or after this long in all (s) — below
#: the launcher's 10 s grace before it escalates to SIGTERM.
DRAIN_IDLE = 0.3
DRAIN_LIMIT = 8.0


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
        self.verdict_count = 0
        self.received = 0                 # messages taken (the shutdown drain watches it)
        self.pub = self.create_publisher(DiagnosticArray, c.TOPIC_VIOLATIONS, VIOLATIONS_QOS)
        # The view topics (the road, goal and light markers) are recorded only, never decoded: latched, so a
        # monitor that matches after the player published them still gets them.
        for topic in c.VIEW_TOPICS:
            self.create_subscription(message_class(TOPIC_TYPES[topic]), topic,
                                     lambda data, topic=topic: self._on_view(topic, data), VIEW_QOS, raw=True)
        # The ego topic last: endpoints are announced in creation order, so a player that sees this node on the
        # ego topic (its `await_subscribers`) knows all its other subscriptions, and waits until they matched.
        for topic in sorted(c.CONTRACT_TOPICS, key=lambda t: t == c.TOPIC_EGO_ODOM):
            qos = SCENARIO_QOS if topic == c.TOPIC_SCENARIO else STREAM_QOS
            self.create_subscription(message_class(TOPIC_TYPES[topic]), topic,
                                     lambda data, topic=topic: self._on_raw(topic, data), qos, raw=True)
        if self.flush_interval > 0:
            # Also flush while no message arrives (a crashed player): the bag on disk stays current.
            self.create_timer(self.flush_interval, self._flush)
        self.get_logger().info(f"judging {len(c.CONTRACT_TOPICS)} topics, recording to {self.bag_dir or '(off)'}")

    # --- messages ------------------------------------------------------------------------------------------------

    def _on_raw(self, topic: str, data: bytes) -> None:
        self.received += 1
        try:
            msg = decode(data, TOPIC_TYPES[topic], self.typestore)
        except Exception as exc:          # a malformed message must not stop the monitor
            self.get_logger().error(f"undecodable message on {topic}: {exc}")
            self._record(topic, data)     # kept: the offline judge meets (and skips) it the same way
            return
        # Recorded before it is judged, in arrival order: the offline judge replays exactly this sequence.
        self._record(topic, data)
        try:
            self.session.on_message(topic, msg)
        except (Txt2SceError, ValueError, KeyError, TypeError) as exc:
            self.get_logger().error(f"bad message on {topic}: {exc}")

    def _on_view(self, topic: str, data: bytes) -> None:
        self.received += 1
        self._record(topic, data)

    def _record(self, topic: str, data: bytes) -> None:
        if self.bag_dir is None:
            return
        if self.recorder is None:
            n = 1
            while (self.bag_dir / f"monitor_{n:03d}").exists():
                n += 1
            self.recorder = BagRecorder(self.bag_dir / f"monitor_{n:03d}", flush_interval=self.flush_interval)
            self.get_logger().info(f"recording {self.recorder.path}")
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
        self._record(c.TOPIC_VIOLATIONS, serialize_message(msg))
        self.recorder.flush()             # the verdict is on disk even if the process is killed next
        self.verdict_count += 1
        with open(self.bag_dir / "verdicts.jsonl", "a", encoding="utf-8") as fh:
            fh.write(json.dumps({"bag": str(self.recorder.path), "run": self.verdict_count, **verdict.to_dict()},
                                sort_keys=True) + "\n")

    def _flush(self) -> None:
        if self.recorder is not None:
            self.recorder.flush()

    def drain(self, executor: SingleThreadedExecutor, give_up: Callable[[], bool]) -> None:
        """Take the messages DDS already delivered, until none came for DRAIN_IDLE s (at most DRAIN_LIMIT s)."""
        start = idle_since = time.monotonic()
        seen = self.received
        while not give_up() and time.monotonic() - start < DRAIN_LIMIT:
            executor.spin_once(timeout_sec=0.05)
            now = time.monotonic()
            if self.received != seen:
                seen, idle_since = self.received, now
            elif now - idle_since >= DRAIN_IDLE:
                return

    def shutdown(self) -> None:
        """Judge the runs still open (as incomplete if they never ended) and finalise the recording."""
        self.session.close()
        if self.recorder is not None:
            self.recorder.close()
            self.recorder = None


def main(args: list[str] | None = None) -> int:
    # Our own signal handling: rclpy's would shut the context down at once, and the messages already delivered
    # (the end of the last run, when the monitor lags) could no longer be taken.
    rclpy.init(args=args, signal_handler_options=SignalHandlerOptions.NO)
    node = build_node(OracleMonitorNode, "oracle_monitor_node")
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    signals: list[int] = []
    for sig in (signal.SIGINT, signal.SIGTERM):
        signal.signal(sig, lambda signum, _frame: signals.append(signum))

    def leave() -> None:
        node.shutdown()                 # the bag is closed before the node goes
        executor.remove_node(node)

    with node_lifetime(node, on_exit=leave):
        while rclpy.ok() and not signals:
            executor.spin_once(timeout_sec=0.1)
        if rclpy.ok():
            node.drain(executor, give_up=lambda: len(signals) > 1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
