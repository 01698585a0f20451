"""Reading a rosbag2 recording (metadata.yaml + MCAP), whole or cut short.

A finished bag is read with rosbags' `Reader` (index, summary, time order). When that is impossible — no
`metadata.yaml` (the recorder was killed), a file without footer or with a damaged tail — the MCAP file is read
record by record from its start, keeping every complete message up to the first damaged byte, including the
complete messages of a chunk whose end is missing (uncompressed chunks; a compressed chunk needs all its bytes).
What went wrong is collected in `BagReading.issues` so callers can print a clear error *and* judge what was read.
"""

from __future__ import annotations

import struct
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Iterator, NamedTuple

from txt2sce_ros.errors import InputError

MAGIC = b"\x89MCAP0\r\n"


class RawMessage(NamedTuple):
    topic: str
    msgtype: str
    log_time_ns: int
    data: bytes | memoryview


@dataclass
class BagReading:
    """Iterate `messages()` once; afterwards `issues` says what could not be read and `complete` whether the
    recording was whole."""

    path: Path
    issues: list[str] = field(default_factory=list)
    count: int = 0
    method: str = ""

    @property
    def complete(self) -> bool:
        return not self.issues

    def messages(self, topics: frozenset[str] | None = None) -> Iterator[RawMessage]:
        mcaps = _mcap_files(self.path)
        skip = 0
        if (self.path / "metadata.yaml").is_file() if self.path.is_dir() else False:
            try:
                yield from self._rosbags(topics)
                return
            except _Fallback as exc:
                self.issues.append(str(exc))
                skip = self.count             # already delivered (file order = time order for our recordings)
        elif self.path.is_dir():
            self.issues.append("no metadata.yaml: the recording was not closed (crash or kill); "
                               "reading the MCAP file record by record")
        self.method = "scan"
        for f in mcaps:
            for msg in scan_mcap(f, self.issues):
                if topics is None or msg.topic in topics:
                    if skip:
                        skip -= 1
                        continue
                    self.count += 1
                    yield msg

    def _rosbags(self, topics: frozenset[str] | None) -> Iterator[RawMessage]:
        from rosbags.rosbag2 import Reader

        try:
            reader = Reader(self.path)
            reader.open()
        except Exception as exc:          # rosbags raises several types for damaged files; all mean "fall back"
            raise _Fallback(f"rosbags cannot open it ({type(exc).__name__}: {exc}); reading the MCAP file record "
                            f"by record") from exc
        self.method = "rosbags"
        conns = [c for c in reader.connections if topics is None or c.topic in topics]
        try:
            fast = _indexed_messages(reader, conns)
        except Exception:                 # anything rosbags' own reading would have to judge: let it
            fast = None
        if fast is not None:
            try:
                for msg in fast:
                    self.count += 1
                    yield msg
            finally:
                reader.close()
            return
        try:
            for conn, ts, data in reader.messages(connections=conns):
                self.count += 1
                yield RawMessage(conn.topic, conn.msgtype, ts, data)
        except Exception as exc:
            raise _Fallback(f"damaged after {self.count} message(s) ({type(exc).__name__}: {exc}); reading the "
                            f"rest record by record") from exc
        finally:
            reader.close()


class _Fallback(Exception):
    pass


# --- indexed MCAP reading in rosbags' order, without its per-message I/O ----------------------------------------------

_MSG_REC = struct.Struct("<BQHIQQ")         # opcode, record length, channel id, sequence, log time, publish time
#: The largest MCAP file read the fast way (its wanted messages are all held in memory at once).
FAST_READ_MAX_BYTES = 256 * 1024 * 1024


def _indexed_messages(reader: Any, conns: list[Any]) -> list[RawMessage] | None:
    """The messages `reader.messages(connections=conns)` would yield, in the same order with the same bytes, read
    with one read per chunk instead of rosbags' few small reads per message (~40 % of an offline judge's time
    went there). Only for the layout rosbags' own reading handles the same way: one MCAP file with a chunk index,
    no per-message compression. None otherwise (the caller uses rosbags); raises on anything malformed (the caller
    then lets rosbags read it, so damage is reported as before). The order is rosbags': each chunk's messages
    stably sorted by log time, chunks merged by (log time, chunk offset).
    """
    from rosbags.rosbag2.storage_mcap import McapReader, decompress

    directory = reader.storage
    storages = getattr(directory, "storages", None)
    if not storages or len(storages) != 1 or directory.metadata.compression_mode == "message":
        return None
    storage = storages[0]
    if type(storage) is not McapReader or not storage.chunks or storage.bio is None:
        return None
    if storage.bio.seek(0, 2) > FAST_READ_MAX_BYTES:
        return None         # the messages are held until sorted: past the bound, rosbags' streaming reading
    # rosbags' matching of the wanted connections to the file's channels (DirectoryReader.messages).
    channels: dict[int, tuple[str, str]] = {}
    for x in storage.connections:
        for y in conns:
            if (y.topic == x.topic and y.msgtype == x.msgtype and y.ext == x.ext
                    and (not x.digest or not y.digest or y.digest == x.digest)):
                channels[x.id] = (y.topic, y.msgtype)
                break
    if not channels:
        return []
    bio = storage.bio
    runs: list[tuple[int, list[RawMessage]]] = []          # (chunk offset, its messages in time order)
    unpack = _MSG_REC.unpack_from
    for chunk in storage.chunks:
        if not any(chunk.channel_count.get(cid, 0) for cid in channels):
            continue
        # One read per chunk (its header and stored records): memory stays one chunk, whatever the bag's size.
        bio.seek(chunk.chunk_start_offset + 9)
        start = 40 + len(chunk.compression)
        piece = bio.read(start + chunk.compressed_size)
        if len(piece) != start + chunk.compressed_size:
            raise ValueError("chunk past the end of the file")
        (crc,) = _U32.unpack_from(piece, 24)
        stored = piece[start:]
        data = decompress(stored, chunk.compression, chunk.uncompressed_size, crc)
        lo, hi = chunk.message_start_time, chunk.message_end_time + 1
        msgs: list[RawMessage] = []
        append = msgs.append
        pos, end = 0, len(data)
        while pos < end:
            body = pos + 9
            if data[pos] == 0x05:
                _op, length, cid, _seq, log_time, _pub = unpack(data, pos)
                if length < 22 or body + length > end:
                    raise ValueError("damaged message record")
                ch = channels.get(cid)
                if ch is not None and lo <= log_time < hi:
                    append(RawMessage(ch[0], ch[1], log_time, data[body + 22:body + length]))
            else:
                (length,) = _U64.unpack_from(data, pos + 1)
                if body + length > end:
                    raise ValueError("record past the end of its chunk")
            pos = body + length
        msgs.sort(key=_log_time)           # stable: file order among equal times, as rosbags' sorted()
        if msgs:
            runs.append((chunk.chunk_start_offset, msgs))
    # rosbags merges the chunks by (log time, chunk offset): when each chunk ends no later than the next one
    # starts, and the chunks are in file order, that is their concatenation.
    in_order = all(o1 < o2 and m1[-1].log_time_ns <= m2[0].log_time_ns
                   for (o1, m1), (o2, m2) in zip(runs, runs[1:]))
    if in_order:
        return [m for _, msgs in runs for m in msgs]
    decorated = [(m.log_time_ns, offset, i, m) for offset, msgs in runs for i, m in enumerate(msgs)]
    decorated.sort(key=_time_offset_key)
    return [m for *_, m in decorated]


def _log_time(m: RawMessage) -> int:
    return m.log_time_ns


def _time_offset_key(item: tuple[int, int, int, RawMessage]) -> tuple[int, int, int]:
    return item[0], item[1], item[2]


def read_bag(path: str | Path) -> BagReading:
    """A recording: a rosbag2 directory or a bare `.mcap` file. Raises InputError if there is nothing to read."""
    p = Path(path)
    if not p.exists():
        raise InputError("no such bag", source=str(p))
    if p.is_dir() and not _mcap_files(p):
        raise InputError("not a rosbag2 MCAP recording (no .mcap file in it)", source=str(p))
    # Checked before anything starts (a replay would otherwise bring up ROS and publish nothing): at least one file
    # must open like an MCAP file. A damaged tail is found, and read up to, later.
    heads = {f.name: _head(f) for f in _mcap_files(p)}
    if not any(h == MAGIC for h in heads.values()):
        raise InputError("nothing readable: " + "; ".join(
            f"{name}: " + ("empty file" if not h else "not an MCAP file (bad magic)") for name, h in heads.items()),
            source=str(p))
    return BagReading(p)


def _head(f: Path) -> bytes:
    try:
        with f.open("rb") as fh:
            return fh.read(len(MAGIC))
    except OSError as exc:
        raise InputError(f"cannot read {f.name}: {exc.strerror or exc}", source=str(f)) from exc


def _mcap_files(p: Path) -> list[Path]:
    if p.is_file():
        return [p]
    return sorted(p.glob("*.mcap"))


# --- record-by-record MCAP scan ------------------------------------------------------------------------------------

_U16 = struct.Struct("<H")
_U32 = struct.Struct("<I")
_U64 = struct.Struct("<Q")
_MSG_HEAD = struct.Struct("<HIQQ")


def _string(buf: memoryview, pos: int) -> tuple[str, int]:
    (n,) = _U32.unpack_from(buf, pos)
    return bytes(buf[pos + 4:pos + 4 + n]).decode(), pos + 4 + n


def scan_mcap(path: Path, issues: list[str]) -> Iterator[RawMessage]:
    """Every complete message of an MCAP file in file order; stops at the first damaged record (noted in
    `issues`)."""
    data = memoryview(path.read_bytes())
    if bytes(data[:8]) != MAGIC:
        issues.append(f"{path.name}: not an MCAP file (bad magic)")
        return
    schemas: dict[int, str] = {}
    channels: dict[int, tuple[str, str]] = {}
    yield from _records(data, 8, len(data), schemas, channels, issues, path.name, top=True)


def _records(buf: memoryview, pos: int, end: int, schemas: dict[int, str], channels: dict[int, tuple[str, str]],
             issues: list[str], name: str, *, top: bool) -> Iterator[RawMessage]:
    while pos < end:
        if end - pos < 9:
            issues.append(f"{name}: truncated at byte {pos} (partial record header)")
            return
        op = buf[pos]
        (length,) = _U64.unpack_from(buf, pos + 1)
        body = pos + 9
        if body + length > end:
            if op == 0x06 and top:
                # A chunk cut short: read its complete inner records if it is uncompressed.
                yield from _partial_chunk(buf, body, end, schemas, channels, issues, name)
            else:
                issues.append(f"{name}: truncated at byte {pos} (record 0x{op:02x} of {length} bytes, "
                              f"{end - body} present)")
            return
        try:
            if op == 0x05:
                cid, _seq, log_time, _pub = _MSG_HEAD.unpack_from(buf, body)
                ch = channels.get(cid)
                if ch is not None:
                    yield RawMessage(ch[0], ch[1], log_time, buf[body + 22:body + length])
            elif op == 0x03:
                (sid,) = _U16.unpack_from(buf, body)
                sname, _ = _string(buf, body + 2)
                schemas[sid] = sname
            elif op == 0x04:
                cid, sid = struct.unpack_from("<HH", buf, body)
                topic, _ = _string(buf, body + 4)
                channels[cid] = (topic, schemas.get(sid, ""))
            elif op == 0x06:
                yield from _chunk(buf, body, body + length, schemas, channels, issues, name)
            elif op == 0x02:                 # footer: the end
                return
        except (struct.error, UnicodeDecodeError, ValueError) as exc:
            issues.append(f"{name}: damaged record 0x{op:02x} at byte {pos} ({exc})")
            return
        pos = body + length


def _chunk_head(buf: memoryview, body: int) -> tuple[str, int, int]:
    """(compression, start of the records, their stored length) of a chunk record."""
    compression, p = _string(buf, body + 28)
    (size,) = _U64.unpack_from(buf, p)
    return compression, p + 8, size


def _chunk(buf: memoryview, body: int, end: int, schemas: dict[int, str], channels: dict[int, tuple[str, str]],
           issues: list[str], name: str) -> Iterator[RawMessage]:
    compression, start, size = _chunk_head(buf, body)
    if compression:
        inner = memoryview(_decompress(compression, bytes(buf[start:start + size]),
                                       _U64.unpack_from(buf, body + 16)[0]))
        yield from _records(inner, 0, len(inner), schemas, channels, issues, name, top=False)
    else:
        yield from _records(buf, start, start + size, schemas, channels, issues, name, top=False)


def _partial_chunk(buf: memoryview, body: int, end: int, schemas: dict[int, str],
                   channels: dict[int, tuple[str, str]], issues: list[str], name: str) -> Iterator[RawMessage]:
    try:
        compression, start, _size = _chunk_head(buf, body)
    except (struct.error, UnicodeDecodeError):
        issues.append(f"{name}: truncated inside a chunk header at byte {body - 9}")
        return
    if compression:
        issues.append(f"{name}: truncated inside a {compression} chunk at byte {body - 9}: its messages are lost")
        return
    inner: list[str] = []
    yield from _records(buf, start, end, schemas, channels, inner, name, top=False)
    issues.append(f"{name}: truncated inside the last chunk (at byte {end}); its complete messages were kept")


def _decompress(kind: str, data: bytes, size: int) -> bytes:
    if kind == "zstd":
        import zstandard

        return zstandard.ZstdDecompressor().decompress(data, max_output_size=size)
    if kind == "lz4":
        import lz4.frame

        return lz4.frame.decompress(data)
    raise ValueError(f"unknown chunk compression {kind!r}")
