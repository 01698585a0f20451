"""Recording a run as a rosbag2 directory: `metadata.yaml` + one MCAP file, messages in ROS 2 CDR (via `rosbags`).

Crash tolerance. rosbags buffers messages in 1 MiB chunks and writes `metadata.yaml` and the MCAP summary only on
close. A recorder that waits for that loses the whole run when the process is killed. So `BagRecorder` closes the
pending chunk and flushes the file every `flush_interval` seconds (wall clock) — each flush leaves a prefix of
complete MCAP records on disk — and `close()` (called on shutdown, SIGINT, or by the context manager) writes the
summary and `metadata.yaml`. A bag cut short by a crash has no metadata and no footer; `bagread.read_bag` reads
such a bag record by record up to where it stops.

The flush uses `McapWriter.close_chunk()` of rosbags 0.11 (pinned in requirements.txt): an internal method, kept
behind `_flush` so one place changes if rosbags does.

Log times are the receive times (wall clock, ns, made strictly increasing) as `ros2 bag record` stamps them, so a
reader sees messages in the order the live monitor saw them, and replay reproduces the original timing.
"""

from __future__ import annotations

import time
from pathlib import Path
from typing import Any

from rosbags.rosbag2 import StoragePlugin, Writer, WriterError
from rosbags.typesys import Stores, get_typestore

from txt2sce_ros.errors import InputError

from .topics import TOPIC_TYPES

_TYPESTORE = None


def typestore() -> Any:
    """The ROS 2 Jazzy message definitions rosbags ships (all of common_interfaces the contract uses)."""
    global _TYPESTORE
    if _TYPESTORE is None:
        _TYPESTORE = get_typestore(Stores.ROS2_JAZZY)
    return _TYPESTORE


class BagRecorder:
    """Writes one rosbag2 directory. Topics are added on first use with the type of `topics.TOPIC_TYPES` (or the
    `msgtype` given)."""

    def __init__(self, path: str | Path, *, flush_interval: float = 0.5) -> None:
        self.path = Path(path)
        self.flush_interval = flush_interval
        self._writer = Writer(self.path, version=9, storage_plugin=StoragePlugin.MCAP)
        try:
            self._writer.open()
        except WriterError as exc:
            raise InputError(f"cannot record here: {exc}", source=str(self.path)) from exc
        self._connections: dict[str, Any] = {}
        self._last_ns = 0
        self._last_flush = time.monotonic()
        self.count = 0
        self.closed = False

    def _connection(self, topic: str, msgtype: str | None) -> Any:
        conn = self._connections.get(topic)
        if conn is None:
            msgtype = msgtype or TOPIC_TYPES.get(topic)
            if msgtype is None:
                raise InputError("no message type known for this topic", source=str(self.path), element=topic)
            conn = self._writer.add_connection(topic, msgtype, typestore=typestore())
            self._connections[topic] = conn
        return conn

    def write(self, topic: str, data: bytes | memoryview, *, log_time_ns: int | None = None,
              msgtype: str | None = None) -> int:
        """Append one CDR-serialised message; returns the log time used (ns)."""
        if self.closed:
            raise InputError("recording already closed", source=str(self.path), element=topic)
        ns = time.time_ns() if log_time_ns is None else int(log_time_ns)
        if ns <= self._last_ns and log_time_ns is None:
            ns = self._last_ns + 1               # strictly increasing: readers keep the receive order
        self._last_ns = max(self._last_ns, ns)
        self._writer.write(self._connection(topic, msgtype), ns, data)
        self.count += 1
        if self.flush_interval >= 0 and time.monotonic() - self._last_flush >= self.flush_interval:
            self._flush()
        return ns

    def write_message(self, topic: str, msg: Any, *, log_time_ns: int | None = None) -> int:
        """Serialise an rclpy message (rclpy imported here only: the rest of the recorder works without it)."""
        from rclpy.serialization import serialize_message

        return self.write(topic, serialize_message(msg), log_time_ns=log_time_ns)

    def _flush(self) -> None:
        storage = self._writer.storage
        if storage is not None:
            if storage.chunk.bio.tell():
                storage.close_chunk()
            storage.bio.flush()
        self._last_flush = time.monotonic()

    def flush(self) -> None:
        """Put everything written so far on disk as complete MCAP records."""
        if not self.closed:
            self._flush()

    def close(self) -> None:
        """Write the MCAP summary and `metadata.yaml`. Safe to call twice."""
        if self.closed:
            return
        self.closed = True
        self._writer.close()

    def __enter__(self) -> "BagRecorder":
        return self

    def __exit__(self, *exc: Any) -> None:
        self.close()
