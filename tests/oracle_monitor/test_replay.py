"""Replay: the recorded bytes come back on their topics, in order, with the original gaps divided by the rate."""

from __future__ import annotations

import time
from pathlib import Path

import pytest

rclpy = pytest.importorskip("rclpy")

from nav_msgs.msg import Odometry  # noqa: E402
from rclpy.qos import QoSProfile, ReliabilityPolicy  # noqa: E402

from oracle_monitor import cdr  # noqa: E402
from oracle_monitor.bagread import RawMessage  # noqa: E402
from oracle_monitor.recorder import BagRecorder  # noqa: E402
from oracle_monitor.replay import replay_bag, schedule  # noqa: E402
from txt2sce_ros import contract as c  # noqa: E402
from txt2sce_ros.contract import EntityState  # noqa: E402
from txt2sce_ros.errors import InputError  # noqa: E402

from .replaying import viewer_and_replayer  # noqa: E402

BASE = 1_700_000_000_000_000_000


def _bag(path: Path, n: int = 21, gap_ms: int = 50) -> None:
    with BagRecorder(path) as rec:
        for k in range(n):
            e = EntityState("ego", "car", k * 0.05, float(k), 0.0, 0.0, 1.0)
            rec.write(c.TOPIC_EGO_ODOM, cdr.encode_odometry(e), log_time_ns=BASE + k * gap_ms * 1_000_000)


def test_schedule_scales_gaps_and_never_reorders() -> None:
    msgs = [RawMessage("/a", "t", BASE + d, b"") for d in (0, 100_000_000, 50_000_000, 300_000_000)]
    offsets = [o for o, _ in schedule(msgs, 2.0)]
    assert offsets == pytest.approx([0.0, 0.05, 0.05, 0.15])   # the late-stamped third goes at once, in place
    with pytest.raises(InputError):
        list(schedule(msgs, 0.0))


def test_replay_publishes_the_recorded_messages_with_scaled_timing(tmp_path: Path, monkeypatch) -> None:
    _bag(tmp_path / "bag")                                        # 21 odometries over 1.0 s
    got: list[tuple[float, float]] = []
    with viewer_and_replayer(tmp_path, monkeypatch) as (node, pub_node):
        node.create_subscription(Odometry, c.TOPIC_EGO_ODOM,
                                 lambda m: got.append((time.monotonic(), m.pose.pose.position.x)),
                                 QoSProfile(depth=100, reliability=ReliabilityPolicy.RELIABLE))
        count, issues = replay_bag(tmp_path / "bag", rate=4.0, node=pub_node, discovery_timeout=10.0)
        deadline = time.monotonic() + 5.0
        while len(got) < 21 and time.monotonic() < deadline:
            time.sleep(0.01)
    assert count == 21 and issues == []
    assert [x for _, x in got] == [float(k) for k in range(21)]  # all, in order, the recorded values
    span = got[-1][0] - got[0][0]
    assert 0.2 <= span < 0.6, span                               # 1.0 s recorded, replayed at 4x: ~0.25 s
