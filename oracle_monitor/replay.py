"""Re-publishing a recording on its topics with its original timing (× a rate factor), for other consumers:
a planner under test, Foxglove, a second monitor.

`schedule()` is the timing core (no rclpy): each message's wall-clock offset from the start, (log time - first log
time) / rate. `replay_bag()` publishes the recorded CDR bytes unchanged (rclpy publishes serialized bytes as they
are), so what consumers receive is exactly what was recorded. `/txt2sce/scenario` is offered transient-local, as
the generator offers it, and so are the road and scenario markers (depth 1, as the player offers them), so a
consumer that subscribes late still gets the scenario, and a viewer joining mid-replay still draws the road.
"""

from __future__ import annotations

import importlib
import time
from pathlib import Path
from typing import Any, Callable, Iterable, Iterator

from txt2sce_ros import contract as c
from txt2sce_ros.errors import InputError

from .bagread import RawMessage, read_bag


def schedule(messages: Iterable[RawMessage], rate: float) -> Iterator[tuple[float, RawMessage]]:
    """(seconds after the start at which to publish, message); log times earlier than their predecessor's (a bag
    merged from several sources) are published right away, never reordered."""
    if rate <= 0:
        raise InputError(f"rate must be positive, got {rate}", element="--rate")
    first: int | None = None
    last = 0.0
    for msg in messages:
        if first is None:
            first = msg.log_time_ns
        offset = max(last, (msg.log_time_ns - first) * 1e-9 / rate)
        last = offset
        yield offset, msg


def message_class(msgtype: str) -> Any:
    """'nav_msgs/msg/Odometry' -> the rclpy class."""
    try:
        pkg, kind, name = msgtype.split("/")
        return getattr(importlib.import_module(f"{pkg}.{kind}"), name)
    except (ValueError, ImportError, AttributeError) as exc:
        raise InputError(f"unknown message type {msgtype!r}", element=msgtype) from exc


def replay_bag(path: str | Path, *, rate: float = 1.0, topics: frozenset[str] | None = None,
               discovery_timeout: float = 3.0, node: Any | None = None,
               on_published: Callable[[RawMessage], None] | None = None) -> tuple[int, list[str]]:
    """Publish the recording; returns (messages published, issues met while reading). Uses `node` if given (tests,
    tools), else creates its own node `txt2sce_replay` (rclpy must be initialised by the caller)."""
    from rclpy.node import Node
    from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy

    reading = read_bag(path)
    own = node is None
    node = node or Node("txt2sce_replay")
    publishers: dict[str, Any] = {}
    normal = QoSProfile(depth=100, reliability=ReliabilityPolicy.RELIABLE)
    latched = QoSProfile(depth=10, reliability=ReliabilityPolicy.RELIABLE, durability=DurabilityPolicy.TRANSIENT_LOCAL)
    view = QoSProfile(depth=1, reliability=ReliabilityPolicy.RELIABLE, durability=DurabilityPolicy.TRANSIENT_LOCAL)
    # Read the whole recording first: publishers exist before the first message and discovery can complete.
    msgs = [m for m in reading.messages(topics) if m.topic != c.TOPIC_VIOLATIONS or topics is not None]
    for m in msgs:
        if m.topic not in publishers:
            qos = latched if m.topic == c.TOPIC_SCENARIO else view if m.topic in c.VIEW_TOPICS else normal
            publishers[m.topic] = node.create_publisher(message_class(m.msgtype), m.topic, qos)
    deadline = time.monotonic() + discovery_timeout
    while time.monotonic() < deadline and not any(p.get_subscription_count() for p in publishers.values()):
        time.sleep(0.02)
    count = 0
    start = time.monotonic()
    try:
        for offset, m in schedule(msgs, rate):
            wait = start + offset - time.monotonic()
            if wait > 0:
                time.sleep(wait)
            publishers[m.topic].publish(bytes(m.data))
            count += 1
            if on_published:
                on_published(m)
    finally:
        if own:
            node.destroy_node()
    return count, list(reading.issues)
