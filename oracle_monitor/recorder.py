"""Recording a run as a rosbag2 directory: `metadata.yaml` + one MCAP file, messages in ROS 2 CDR (via `rosbags`).

Crash tolerance. rosbags buffers messages in 1 MiB chunks and writes `metadata.yaml` and the MCAP summary only on
close. A recorder that waits for that loses the whole run when the process is killed. So `BagRecorder` closes the
pending chunk and flushes the file every `flush_interval` seconds (wall clock) — each flush leaves a prefix of
complete MCAP records on disk — and `close()` (called on shutdown, SIGINT, or by the context manager) writes the
summary and `metadata.yaml`. A bag cut short by a crash has no metadata and no footer; `bagread.read_bag` reads
such a bag record by record up to where it stops.

A chunk is closed as `McapWriter.close_chunk()` of rosbags 0.11 (pinned in requirements.txt) closes it, by
`_close_chunk` (the same bytes, tested, with the message indexes packed per channel), and `write` goes to the
storage's pending chunk directly with one struct.pack per message (the same record bytes rosbags writes, without
its BytesIO per record and its per-message connection check), keeping the Writer's statistics itself:
internals of that version, kept in `_close_chunk`, `_flush` and `write` so one place changes if rosbags does. The round-trip tests
read every recording back with rosbags' Reader and the mcap library, which catches any drift.

Log times are the receive times (wall clock, ns, made strictly increasing) as `ros2 bag record` stamps them, so a
reader sees messages in the order the live monitor saw them, and replay reproduces the original timing.
"""

from __future__ import annotations

import functools
import json
import re
import struct
import time
from collections import Counter
from dataclasses import replace
from pathlib import Path
from typing import Any, Sequence

import numpy as np
from rosbags.rosbag2 import StoragePlugin, Writer, WriterError
from rosbags.typesys import Stores, get_typestore

from txt2sce_ros.errors import InputError

from .steprecords import StepRun
from .topics import TOPIC_TYPES

_TYPESTORE = None


def _cache_rosbags_version() -> None:
    """rosbags' MCAP writer asks `importlib.metadata` for its own version for every bag it opens (~0.3 ms, a
    twentieth of recording a run): the installed version does not change while the process runs."""
    from rosbags.rosbag2 import storage_mcap

    lookup = getattr(storage_mcap, "version", None)
    if callable(lookup) and not hasattr(lookup, "cache_info"):
        storage_mcap.version = functools.lru_cache(maxsize=None)(lookup)


_cache_rosbags_version()


def typestore() -> Any:
    """The ROS 2 Jazzy message definitions rosbags ships (all of common_interfaces the contract uses)."""
    global _TYPESTORE
    if _TYPESTORE is None:
        _TYPESTORE = get_typestore(Stores.ROS2_JAZZY)
    return _TYPESTORE


_MESSAGE_RECORD = struct.Struct("<BQHIQQ")    # opcode 0x05, record length, channel, sequence, log, publish time


def _fast_write(storage: Any, cid: int, ns: int, data: bytes | memoryview) -> None:
    """What `McapWriter.write` of rosbags 0.11 does, with one struct.pack instead of a BytesIO per record: the
    same bytes (a Message record appended to the pending chunk, indexed, chunk closed past 1 MiB)."""
    if ns < storage.message_start_time:
        storage.message_start_time = ns
    if ns > storage.message_end_time:
        storage.message_end_time = ns
    storage.channel_stats[cid] += 1
    chunk = storage.chunk
    if ns < chunk.message_start_time:
        chunk.message_start_time = ns
    if ns > chunk.message_end_time:
        chunk.message_end_time = ns
    bio = chunk.bio
    chunk.msgs[cid].append((ns, bio.tell()))
    bio.write(_MESSAGE_RECORD.pack(0x05, 22 + len(data), cid, 0, ns, ns))
    bio.write(data)
    if bio.tell() > 2**20:
        _close_chunk(storage)


_CHUNK_HEAD = struct.Struct("<BQQQQIIQ")   # opcode 0x06, record length, start, end, size, CRC, "" (compression), size
_INDEX_HEAD = struct.Struct("<BQHI")       # opcode 0x07, record length, channel, bytes of (time, offset) pairs
_U64 = struct.Struct("<Q")


def _step_times(received: Sequence[int | None], per_step: int, last: int) -> np.ndarray:
    """The first log time of each step of a run: its receive time (None: now), made strictly increasing after
    `last` with room for the step's `per_step` messages: t[0] = max(r[0], last + 1), t[j] = max(r[j], t[j-1] +
    per_step). As u[j] = t[j] - j * per_step that is a running maximum, computed on the whole column."""
    if None in received:
        received = [time.time_ns() if r is None else r for r in received]
    u = np.fromiter(received, dtype=np.int64, count=len(received))
    shift = np.arange(len(u), dtype=np.int64) * per_step
    u -= shift
    u[0] = max(int(u[0]), last + 1)
    np.maximum.accumulate(u, out=u)
    u += shift
    return u


def _index_body(entries: list[Any]) -> bytes:
    """A channel's message index entries as (log time, offset) uint64 pairs. An entry is one message's
    `(time, offset)` tuple (rosbags' form, written by `_fast_write` and the per-message steps) or a run of packed
    steps' flat pairs (`StepPacker.index`, little-endian uint64), in the order written."""
    parts: list[bytes] = []
    pairs: list[int] = []
    for e in entries:
        if type(e) is tuple:
            pairs += e
        else:
            if pairs:
                parts.append(struct.pack(f"<{len(pairs)}Q", *pairs))
                pairs = []
            parts.append(e.tobytes())
    if pairs:
        parts.append(struct.pack(f"<{len(pairs)}Q", *pairs))
    return b"".join(parts)


class ChunkBuffer:
    """The pending chunk's bytes (what rosbags keeps in a fresh BytesIO per chunk), in one buffer kept from chunk
    to chunk and from recorder to recorder (`_CHUNK_POOL`). A fresh buffer per chunk, and a fresh array per packed
    run of steps, made the recording fault in every page it wrote: ~560 page faults and a fifth of a recorded
    run's CPU time went to the kernel. `reserve` hands out the next bytes for `StepPacker.pack_run` to fill in
    place. Writes and reads as BytesIO does for the calls the writer makes (write, tell, getbuffer, getvalue)."""

    __slots__ = ("_buf", "_len")

    def __init__(self, capacity: int = 3 << 20) -> None:
        self._buf = np.empty(capacity, dtype=np.uint8)
        self._len = 0

    def tell(self) -> int:
        return self._len

    def reserve(self, n: int) -> np.ndarray:
        """The next `n` bytes of the chunk (their content undefined until the caller fills them)."""
        start, end = self._len, self._len + n
        if end > len(self._buf):
            grown = np.empty(max(end, 2 * len(self._buf)), dtype=np.uint8)
            grown[:start] = self._buf[:start]
            self._buf = grown
        self._len = end
        return self._buf[start:end]

    def write(self, data: bytes | bytearray | memoryview | np.ndarray) -> int:
        view = np.frombuffer(data, dtype=np.uint8)
        self.reserve(len(view))[:] = view
        return len(view)

    def writelines(self, parts: Any) -> None:
        for part in parts:
            self.write(part)

    def getbuffer(self) -> memoryview:
        return memoryview(self._buf[:self._len])

    def getvalue(self) -> bytes:
        return self._buf[:self._len].tobytes()

    def clear(self) -> None:
        self._len = 0


#: Chunk buffers of closed recorders, for the next ones (a process records one run after another).
_CHUNK_POOL: list[ChunkBuffer] = []


def _close_chunk(storage: Any) -> None:
    """`McapWriter.close_chunk()` of rosbags 0.11 for an uncompressed chunk, with each channel's message index
    packed in one struct call instead of two 8-byte writes per message (about a tenth of a recording's cost): the
    same bytes (tested against rosbags' own). A compressed chunk goes to rosbags."""
    if storage.compression:
        storage.close_chunk()
        return
    from collections import defaultdict
    from io import BytesIO

    from rosbags.rosbag2.storage_mcap import PendingChunk

    chunk, out = storage.chunk, storage.bio
    data = chunk.bio.getbuffer()
    size = len(data)
    start, end = chunk.message_start_time, chunk.message_end_time
    chunk_start = out.tell()
    out.write(_CHUNK_HEAD.pack(0x06, 40 + size, start, end, size, 0, 0, size))
    out.write(data)
    del data                                  # release the buffer export before the buffer is reused
    chunk_end = out.tell()
    offsets: list[tuple[int, int]] = []
    for cid, msgs in chunk.msgs.items():
        offsets.append((cid, out.tell()))
        body = _index_body(msgs)
        out.write(_INDEX_HEAD.pack(0x07, 6 + len(body), cid, len(body)))
        out.write(body)
    rec = BytesIO()
    rec.write(struct.pack("<QQQQI", start, end, chunk_start, chunk_end - chunk_start, len(offsets) * 10))
    for cid, offset in offsets:
        rec.write(struct.pack("<HQ", cid, offset))
    rec.write(struct.pack("<QIQQ", out.tell() - chunk_end, 0, size, size))
    storage.chunks.append(rec)
    bio = chunk.bio
    if isinstance(bio, ChunkBuffer):
        bio.clear()
    else:
        bio = BytesIO()
    storage.chunk = PendingChunk(2**63 - 1, 0, bio, defaultdict(list))


_EMPTY_QOS: str | None = None


def _empty_qos() -> str:
    """The offered QoS profiles of a connection without any, as `Writer.add_connection` of rosbags 0.11 dumps them
    (its own dump, made once: the Writer builds a ruamel YAML object per connection, ~0.3 ms each)."""
    global _EMPTY_QOS
    if _EMPTY_QOS is None:
        from io import StringIO

        from rosbags.rosbag2.writer import dump_qos_v9
        from ruamel.yaml import YAML

        dumped = dump_qos_v9([])
        if not isinstance(dumped, str):
            stream = StringIO()
            yaml = YAML(typ="safe")
            yaml.default_flow_style = False
            yaml.dump(dumped, stream)
            dumped = stream.getvalue().strip()
        _EMPTY_QOS = dumped
    return _EMPTY_QOS


def _add_connection(w: Writer, topic: str, msgtype: str, msgdef: str, rihs01: str) -> Any:
    """`Writer.add_connection(topic, msgtype, msgdef=..., rihs01=...)` of rosbags 0.11 (version 9 bag, CDR, no
    QoS profiles) with the QoS dump made once: the same connection and the same records (tested against the
    Writer's own). A topic is added once per recorder (`BagRecorder._connection`), so the Writer's duplicate
    check has nothing to find."""
    from rosbags.interfaces import Connection, ConnectionExtRosbag2, MessageDefinition, MessageDefinitionFormat

    if w.version < 9 or w.storage is None:
        return w.add_connection(topic, msgtype, msgdef=msgdef, rihs01=rihs01)
    fmt = MessageDefinitionFormat.IDL if msgdef.startswith("=" * 80 + "\nIDL: ") else MessageDefinitionFormat.MSG
    conn = Connection(id=len(w.connections) + 1, topic=topic, msgtype=msgtype, msgdef=MessageDefinition(fmt, msgdef),
                      digest=rihs01, msgcount=0,
                      ext=ConnectionExtRosbag2(serialization_format="cdr", offered_qos_profiles=[]), owner=w)
    if msgtype not in w.added_types:
        w.storage.add_msgtype(conn)
        w.added_types.add(msgtype)
    w.storage.add_connection(conn, _empty_qos())
    w.connections.append(conn)
    w.counts[conn.id] = 0
    return conn


_DEFINITIONS: dict[str, tuple[str, str]] = {}


def _definition(msgtype: str) -> tuple[str, str]:
    """(message definition text, RIHS01 hash) of a type, computed once per process (a few ms each)."""
    if msgtype not in _DEFINITIONS:
        ts = typestore()
        _DEFINITIONS[msgtype] = (ts.generate_msgdef(msgtype, ros_version=2)[0], ts.hash_rihs01(msgtype))
    return _DEFINITIONS[msgtype]


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
        storage = self._writer.storage
        self._chunk_buffer: ChunkBuffer | None = None
        if storage is not None and not storage.compression and not storage.chunk.bio.tell():
            self._chunk_buffer = _CHUNK_POOL.pop() if _CHUNK_POOL else ChunkBuffer()
            storage.chunk = replace(storage.chunk, bio=self._chunk_buffer)
        self._connections: dict[str, Any] = {}
        self._cids: dict[str, int] = {}
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
            msgdef, rihs01 = _definition(msgtype)
            conn = _add_connection(self._writer, topic, msgtype, msgdef, rihs01)
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
        conn = self._connections.get(topic) or self._connection(topic, msgtype)
        # Writer.write() checks `conn in connections` (a list of dataclasses compared field by field) on every
        # message; the connection is ours, so write to the storage and keep the Writer's statistics ourselves.
        w = self._writer
        _fast_write(w.storage, conn.id, ns, data)
        w.counts[conn.id] += 1
        if ns < w.min_timestamp:
            w.min_timestamp = ns
        if ns > w.max_timestamp:
            w.max_timestamp = ns
        self.count += 1
        if self.flush_interval >= 0 and time.monotonic() - self._last_flush >= self.flush_interval:
            self._flush()
        return ns

    def write_batch(self, items: list[tuple[str, bytes]], received_ns: int | None = None) -> None:
        """Append several messages received together (one lock-step step, at `received_ns` or now), with
        consecutive log times: one buffer write instead of one per message, for the in-process hot path."""
        self.write_steps([(received_ns, items)])

    def channel(self, topic: str) -> int:
        """The channel id of `topic` (its connection added on first use)."""
        cid = self._cids.get(topic)
        if cid is None:
            cid = self._cids[topic] = self._connection(topic, None).id
        return cid

    def write_steps(self, steps: list[Any]) -> None:
        """`write_batch` for several steps at once: one buffer write and one round of bookkeeping for all of them.
        Each step is (received time or None for now, its messages as a list of (topic, CDR bytes)), or a
        `steprecords.StepRun` of consecutive steps of one layout, packed and indexed together."""
        if self.closed:
            raise InputError("recording already closed", source=str(self.path))
        for step in steps:
            if not isinstance(step, StepRun):
                for topic, _ in step[1]:
                    if topic not in self._cids:
                        # A new channel writes its record into the pending chunk: add it before the messages'
                        # offsets in the chunk are counted from where the chunk ends.
                        self.channel(topic)
        w = self._writer
        storage = w.storage
        chunk = storage.chunk
        bio = chunk.bio
        pos = bio.tell()
        reserve = getattr(bio, "reserve", None)      # a ChunkBuffer packs steps in place
        parts: list[Any] = []
        index = chunk.msgs
        pack = _MESSAGE_RECORD.pack
        cids = self._cids
        last = self._last_ns
        first = None
        n = 0
        written: Counter[int] = Counter()       # messages per channel, added to the statistics at the end
        for step in steps:
            if isinstance(step, StepRun):
                packer = step.packer
                per_step = len(packer.offsets)
                at = _step_times(step.received, per_step, last)
                k = len(at)
                last = int(at[-1]) + per_step - 1
                if first is None:
                    first = int(at[0])
                if reserve is None:
                    parts.append(packer.pack_run(at, step.values))
                else:
                    # Packed in place, at the chunk's end: what came before it is written first.
                    bio.writelines(parts)
                    parts.clear()
                    packer.pack_run(at, step.values, out=reserve(packer.size * k))
                for cid, flat in packer.index(at, pos):
                    index[cid].append(flat)
                for cid in packer.topics_cids:
                    written[cid] += k
                pos += packer.size * k
                n += per_step * k
                continue
            received_ns, items = step
            t = max(time.time_ns() if received_ns is None else received_ns, last + 1)
            if first is None:
                first = t
            for topic, data in items:
                cid = cids[topic]
                size = len(data)
                index[cid].append((t, pos))
                pos += 31 + size            # the 31-byte record header, then the message
                parts += (pack(0x05, 22 + size, cid, 0, t, t), data)
                written[cid] += 1
                t += 1
            n += len(items)
            last = t - 1
        if first is None or not n:
            return
        counts = w.counts
        stats = storage.channel_stats
        for cid, k in written.items():
            counts[cid] += k
            stats[cid] += k
        bio.writelines(parts)                   # each part copied once, with no joined copy in between
        if first < storage.message_start_time:
            storage.message_start_time = first
        storage.message_end_time = max(storage.message_end_time, last)
        if first < chunk.message_start_time:
            chunk.message_start_time = first
        chunk.message_end_time = max(chunk.message_end_time, last)
        w.min_timestamp = min(w.min_timestamp, first)
        w.max_timestamp = max(w.max_timestamp, last)
        self._last_ns = last
        self.count += n
        if bio.tell() > 2**20:
            _close_chunk(storage)
        if self.flush_interval >= 0 and time.monotonic() - self._last_flush >= self.flush_interval:
            self._flush()

    def write_message(self, topic: str, msg: Any, *, log_time_ns: int | None = None) -> int:
        """Serialise an rclpy message (rclpy imported here only: the rest of the recorder works without it)."""
        from rclpy.serialization import serialize_message

        return self.write(topic, serialize_message(msg), log_time_ns=log_time_ns)

    def _flush(self) -> None:
        storage = self._writer.storage
        if storage is not None:
            if storage.chunk.bio.tell():
                _close_chunk(storage)
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
        _close_writer(self._writer)
        if self._chunk_buffer is not None and len(_CHUNK_POOL) < 2:
            self._chunk_buffer.clear()
            _CHUNK_POOL.append(self._chunk_buffer)
        self._chunk_buffer = None

    def __enter__(self) -> "BagRecorder":
        return self

    def __exit__(self, *exc: Any) -> None:
        self.close()


def _close_writer(w: Writer) -> None:
    """`Writer.close()` of rosbags 0.11 for our configuration (MCAP, no compression, no QoS profiles), with the
    metadata written by `metadata_yaml` instead of ruamel: the same `metadata.yaml` content in ~0.1 ms instead of
    ~10 ms, which is a per-run cost the recording-overhead budget notices on short runs."""
    storage = w.storage
    start = w.min_timestamp if w.counts and sum(w.counts.values()) else 0
    duration = max(0, w.max_timestamp - w.min_timestamp) if start else 0
    count = sum(w.counts.values())
    name = storage.path.name
    info = {
        "version": w.version,
        "storage_identifier": w.storage_plugin.name.lower(),
        "relative_file_paths": [name],
        "duration": {"nanoseconds": duration},
        "starting_time": {"nanoseconds_since_epoch": start},
        "message_count": count,
        "topics_with_message_count": [
            {"topic_metadata": {"name": c.topic, "type": c.msgtype, "serialization_format": "cdr",
                                "offered_qos_profiles": [], "type_description_hash": c.digest},
             "message_count": w.counts[c.id]}
            for c in w.connections
        ],
        "compression_format": "",
        "compression_mode": "",
        "files": [{"path": name, "starting_time": {"nanoseconds_since_epoch": start},
                   "duration": {"nanoseconds": duration}, "message_count": count}],
        "custom_data": None,
        "ros_distro": "rosbags",
    }
    if storage.chunk.bio.tell():
        _close_chunk(storage)                 # the last chunk, as storage.close would close it (same bytes)
    inner, outer = _metadata_texts(info)
    storage.close(w.version, inner)
    w.storage = None
    tmp = w.metapath.with_suffix(".yaml.tmp")
    tmp.write_text(outer + "\n", "utf8")
    tmp.replace(w.metapath)


def _metadata_texts(info: dict[str, Any]) -> tuple[str, str]:
    """`metadata_yaml(info)` (the MCAP summary's copy) and `metadata_yaml({"rosbag2_bagfile_information": info})`
    (metadata.yaml), emitted once: the second is the first's lines indented under that key."""
    lines: list[str] = []
    if not _emit(info, "", lines):
        return metadata_yaml(info), metadata_yaml({"rosbag2_bagfile_information": info})
    return "\n".join(lines), "rosbag2_bagfile_information:\n  " + "\n  ".join(lines)


_PLAIN = re.compile(r"[A-Za-z/][A-Za-z0-9_/.\-]*")
_NOT_PLAIN = {"y", "n", "yes", "no", "on", "off", "true", "false", "null"}     # would read back as bool / null


def metadata_yaml(value: dict[str, Any]) -> str:
    """The block-style YAML of the bag metadata (no trailing newline): what `yaml.dump(value,
    default_flow_style=False, sort_keys=True)` writes for it, in ~0.1 ms instead of ~1.2 ms (two per bag). Names
    that are not plain identifiers and paths are double-quoted (JSON's quoting, which YAML reads the same); a
    string YAML could not hold in that form (non-printable characters) goes to PyYAML."""
    lines: list[str] = []
    if not _emit(value, "", lines):
        import yaml

        dump = getattr(yaml, "CSafeDumper", yaml.SafeDumper)
        return yaml.dump(value, Dumper=dump, default_flow_style=False, sort_keys=True).strip()
    return "\n".join(lines)


def _scalar(v: Any) -> str | None:
    if v is None:
        return "null"
    if v is True or v is False:
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, str):
        if v == "":
            return "''"
        if _PLAIN.fullmatch(v) and v.lower() not in _NOT_PLAIN:
            return v
        if not v.isprintable():
            return None
        return json.dumps(v, ensure_ascii=False)
    return None


def _emit(value: dict[str, Any], indent: str, lines: list[str]) -> bool:
    """Append a mapping's lines (keys sorted; a sequence in a mapping at the key's indentation, as PyYAML
    writes it); False where a value is not one this emitter writes."""
    for key in sorted(value):
        head = _scalar(key)
        if head is None or not isinstance(key, str):
            return False
        v = value[key]
        if isinstance(v, dict) and v:
            lines.append(f"{indent}{head}:")
            if not _emit(v, indent + "  ", lines):
                return False
        elif isinstance(v, list) and v:
            lines.append(f"{indent}{head}:")
            for item in v:
                if isinstance(item, dict) and item:
                    sub: list[str] = []
                    if not _emit(item, indent + "  ", sub):
                        return False
                    lines.append(f"{indent}- {sub[0][len(indent) + 2:]}")
                    lines.extend(sub[1:])
                else:
                    text = _scalar(item)
                    if text is None:
                        return False
                    lines.append(f"{indent}- {text}")
        else:
            text = "{}" if v == {} else "[]" if v == [] else _scalar(v)
            if text is None:
                return False
            lines.append(f"{indent}{head}: {text}")
    return True
