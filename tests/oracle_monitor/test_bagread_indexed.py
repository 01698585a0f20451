"""`bagread`'s indexed reading gives exactly what rosbags' `Reader.messages` gives: the same messages, bytes and
order, on bags whose log times go back within and across chunks, with equal times, compressed chunks and a topic
filter."""

from __future__ import annotations

import random
from pathlib import Path

import pytest
from rosbags.rosbag2 import Reader, Writer
from rosbags.rosbag2.enums import CompressionFormat, CompressionMode, StoragePlugin
from rosbags.typesys import Stores, get_typestore

from oracle_monitor import bagread
from oracle_monitor.bagread import _indexed_messages, read_bag


def _write(path: Path, *, compress: bool, seed: int) -> None:
    """Two topics, 600 messages with log times drawn so that they repeat and go back, many small chunks."""
    ts = get_typestore(Stores.ROS2_JAZZY)
    rng = random.Random(seed)
    writer = Writer(path, version=9, storage_plugin=StoragePlugin.MCAP)
    if compress:
        writer.set_compression(CompressionMode.STORAGE, CompressionFormat.ZSTD)
    with writer:
        conns = [writer.add_connection("/a", "std_msgs/msg/String", typestore=ts),
                 writer.add_connection("/b", "std_msgs/msg/String", typestore=ts)]
        String = ts.types["std_msgs/msg/String"]
        for i in range(600):
            t = 1_000 + rng.randrange(0, 400) * 10           # many equal times, in no order
            data = ts.serialize_cdr(String(data=f"m{i}" + "x" * rng.randrange(0, 20000)), "std_msgs/msg/String")
            writer.write(conns[rng.randrange(2)], t, data)


def _rosbags(path: Path, topics: set[str] | None) -> list[tuple[str, str, int, bytes]]:
    with Reader(path) as reader:
        conns = [c for c in reader.connections if topics is None or c.topic in topics]
        return [(c.topic, c.msgtype, t, bytes(d)) for c, t, d in reader.messages(connections=conns)]


@pytest.mark.parametrize("compress", [False, True])
@pytest.mark.parametrize("seed", [1, 2])
def test_indexed_reading_is_rosbags_reading(tmp_path: Path, compress: bool, seed: int) -> None:
    bag = tmp_path / "bag"
    _write(bag, compress=compress, seed=seed)
    for topics in (None, {"/b"}):
        expected = _rosbags(bag, topics)
        assert len(expected) > (250 if topics else 590)
        reading = read_bag(bag)
        got = [(m.topic, m.msgtype, m.log_time_ns, bytes(m.data))
               for m in reading.messages(frozenset(topics) if topics else None)]
        assert got == expected
        assert reading.complete and reading.count == len(expected)
    # The fast path is the one taken (not rosbags' own reading behind it).
    with Reader(bag) as reader:
        assert _indexed_messages(reader, list(reader.connections)) is not None


def test_chunks_overlapping_in_time_merge_as_rosbags_does(tmp_path: Path) -> None:
    # Times that go back from chunk to chunk: the concatenation of the chunks is not rosbags' order.
    bag = tmp_path / "bag"
    _write(bag, compress=False, seed=3)
    with Reader(bag) as reader:
        chunks = reader.storage.storages[0].chunks
        assert len(chunks) > 3
        assert any(a.message_end_time > b.message_start_time for a, b in zip(chunks, chunks[1:]))
        fast = _indexed_messages(reader, list(reader.connections))
        assert fast is not None
        file_order = [m.log_time_ns for m in fast]
    assert file_order == sorted(file_order)
    assert [(m.topic, m.log_time_ns, bytes(m.data)) for m in fast] == [
        (t, ts, d) for t, _, ts, d in _rosbags(bag, None)]


def test_damaged_chunk_is_left_to_rosbags(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # A chunk whose bytes were changed: the fast path gives up, and the reading (messages, issues) is what it was
    # without the fast path.
    bag = tmp_path / "bag"
    _write(bag, compress=True, seed=4)
    mcap = bag / "bag.mcap"
    with Reader(bag) as reader:
        chunk = reader.storage.storages[0].chunks[2]
    data = bytearray(mcap.read_bytes())
    mid = chunk.chunk_start_offset + 9 + 60
    data[mid:mid + 64] = bytes(64)
    mcap.write_bytes(bytes(data))
    with Reader(bag) as reader:
        with pytest.raises(Exception):
            _indexed_messages(reader, list(reader.connections))

    def read() -> tuple[list[tuple[str, int, bytes]], list[str], int]:
        reading = read_bag(bag)
        msgs = [(m.topic, m.log_time_ns, bytes(m.data)) for m in reading.messages()]
        return msgs, reading.issues, reading.count

    got = read()
    monkeypatch.setattr(bagread, "_indexed_messages", lambda reader, conns: None)
    assert got == read()
    assert 0 < len(got[0]) < 600


def test_a_file_past_the_bound_is_read_by_rosbags(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # The fast path holds every wanted message at once: a bag larger than the bound streams through rosbags.
    bag = tmp_path / "bag"
    _write(bag, compress=False, seed=5)
    with Reader(bag) as reader:
        assert _indexed_messages(reader, list(reader.connections)) is not None
        monkeypatch.setattr(bagread, "FAST_READ_MAX_BYTES", (bag / "bag.mcap").stat().st_size - 1)
        assert _indexed_messages(reader, list(reader.connections)) is None
    reading = read_bag(bag)
    got = [(m.topic, m.msgtype, m.log_time_ns, bytes(m.data)) for m in reading.messages()]
    assert got == _rosbags(bag, None) and reading.complete
