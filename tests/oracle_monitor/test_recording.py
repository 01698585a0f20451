"""Recording round trips (rosbags reader and the mcap reader), offline judging of recordings, damaged bags."""

from __future__ import annotations

import os
import signal
import struct
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import pytest
from mcap.reader import make_reader
from mcap_ros2.decoder import DecoderFactory

from oracle_monitor import Oracle, OracleParams
from oracle_monitor.bagread import read_bag
from oracle_monitor.judge import judge_bag
from oracle_monitor.runwriter import RunWriter
from txt2sce_ros import contract as c
from txt2sce_ros.contract import Goal, RunStatus, ScenarioEnvelope, SignalState, TrafficLightState, Verdict
from txt2sce_ros.errors import InputError

from .oracle_runs import car, esmini_map, straight_run

PARAMS = OracleParams.from_config()
GOAL = Goal(120.0, 0.0, 0.0)


def _frames():
    lights = lambda t: [TrafficLightState("sig1", SignalState.RED if t < 9 else SignalState.GREEN, 50.0, 0.0,
                                          0.0, "1", (-1,))]
    return straight_run(lambda t: 10.0, 8.0, lights=lights, objects=lambda t: [car("npc1", t, 80.0, y=-3.5)])


def _envelope() -> ScenarioEnvelope:
    path = esmini_map("straight_500m.xodr")
    return ScenarioEnvelope(id="rt1", xosc="<OpenSCENARIO/>", map_path=str(path), map_xodr=path.read_text())


def _record(path: Path, frames, status: RunStatus | None, *, live: bool = True):
    """Write a run as the graph would, with the live oracle's violations and verdict; returns that verdict."""
    from txt2sce_ros.road import RoadNetwork

    env = _envelope()
    oracle = Oracle(RoadNetwork.from_string(env.map_xodr, source=env.map_path), GOAL, PARAMS, scenario_id=env.id)
    with RunWriter(path, time_base_ns=1_700_000_000_000_000_000) as w:
        w.begin(env, GOAL)
        for f in frames:
            w.frame(f)
            if live:
                w.violations(f.t, oracle.observe(f))
        verdict = oracle.finish(status)
        w.end(status, verdict if live else None)
    return verdict


def test_round_trip_with_rosbags_and_mcap_readers(tmp_path: Path) -> None:
    frames = _frames()
    live = _record(tmp_path / "bag", frames, RunStatus("rt1", "finished", 8.0, "time_limit"))
    assert (tmp_path / "bag" / "metadata.yaml").is_file()
    reading = read_bag(tmp_path / "bag")
    msgs = list(reading.messages())
    assert reading.method == "rosbags" and reading.complete
    per_topic = {t: sum(1 for m in msgs if m.topic == t) for t in {m.topic for m in msgs}}
    assert per_topic[c.TOPIC_EGO_ODOM] == len(frames) == per_topic[c.TOPIC_OBJECTS_ODOM]
    assert per_topic[c.TOPIC_SCENARIO] == 1 and per_topic[c.TOPIC_RUN_STATUS] == 2
    # The mcap library's own reader with its ROS 2 decoder (what Foxglove uses) sees the same messages.
    with open(tmp_path / "bag" / "bag.mcap", "rb") as fh:
        reader = make_reader(fh, decoder_factories=[DecoderFactory()])
        decoded = list(reader.iter_decoded_messages(topics=[c.TOPIC_EGO_ODOM, c.TOPIC_OBJECTS_MARKERS]))
    odoms = [m for _, ch, _, m in decoded if ch.topic == c.TOPIC_EGO_ODOM]
    assert len(odoms) == len(frames)
    assert odoms[37].pose.pose.position.x == pytest.approx(frames[37].ego.x)
    markers = [m for _, ch, _, m in decoded if ch.topic == c.TOPIC_OBJECTS_MARKERS]
    assert [mk.text for mk in markers[0].markers] == ["ego", "npc1"]
    assert live.verdict is Verdict.FAIL and live.category_names() == ("Misinterp",)


def test_offline_verdict_equals_live_verdict(tmp_path: Path) -> None:
    live = _record(tmp_path / "bag", _frames(), RunStatus("rt1", "finished", 8.0, "time_limit"))
    result = judge_bag(tmp_path / "bag", PARAMS)
    assert result.complete and len(result.verdicts) == 1
    assert result.verdicts[0] == live                           # every field: categories, times, violations
    assert result.live == [live.to_dict()] and result.agrees_with_live() is True


def test_truncated_bag_gives_clear_issue_and_verdict_for_readable_part(tmp_path: Path) -> None:
    _record(tmp_path / "bag", _frames(), RunStatus("rt1", "finished", 8.0, "time_limit"))
    mcap = tmp_path / "bag" / "bag.mcap"
    data = mcap.read_bytes()
    mcap.write_bytes(data[: int(len(data) * 0.8)])              # the tail (summary, last chunk's end) is gone
    result = judge_bag(tmp_path / "bag", PARAMS)
    assert not result.complete
    assert any("truncated" in i for i in result.issues) and any("rosbags cannot open" in i for i in result.issues)
    (verdict,) = result.verdicts
    # The red light (at 4.65 s) lies in the readable part, so the run is known to have failed.
    assert verdict.verdict is Verdict.FAIL and verdict.category_names() == ("Misinterp",)
    # Cut before the red light: no final status, nothing failed yet -> error (incomplete), never pass.
    mcap.write_bytes(data[: int(len(data) * 0.3)])
    result = judge_bag(tmp_path / "bag", PARAMS)
    (verdict,) = result.verdicts
    assert verdict.verdict is Verdict.ERROR and "no final run status" in verdict.error


def test_corrupted_bytes_and_garbage_are_reported(tmp_path: Path) -> None:
    _record(tmp_path / "bag", _frames(), RunStatus("rt1", "finished", 8.0, "time_limit"))
    mcap = tmp_path / "bag" / "bag.mcap"
    data = bytearray(mcap.read_bytes())
    mid = len(data) // 2
    # A 4 KiB burst of damage in the middle: it spans several record headers, so the structure breaks. (Flipped
    # payload bytes alone are undetectable: rosbags writes chunks without CRCs.)
    data[mid:mid + 4096] = b"\xff" * 4096
    mcap.write_bytes(bytes(data))
    result = judge_bag(tmp_path / "bag", PARAMS)
    assert not result.complete and result.verdicts
    assert any("damaged" in i or "truncated" in i for i in result.issues), result.issues
    assert result.verdicts[0].frames < 161
    junk = tmp_path / "junk"
    junk.mkdir()
    (junk / "junk.mcap").write_bytes(b"not an mcap at all")
    with pytest.raises(InputError, match="nothing readable"):
        judge_bag(junk, PARAMS)


def test_killed_recorder_leaves_a_readable_bag(tmp_path: Path) -> None:
    # A child process records frames with the default 0.5 s flush and is killed with SIGKILL mid-run: no
    # metadata.yaml, no MCAP footer. The flushed prefix must still read and judge.
    script = textwrap.dedent(f"""
        import sys, time
        sys.path.insert(0, {str(Path(__file__).resolve().parents[2])!r})
        from oracle_monitor.runwriter import RunWriter
        from tests.oracle_monitor.oracle_runs import straight_run, car
        from txt2sce_ros.contract import Goal
        frames = straight_run(lambda t: 10.0, 60.0, objects=lambda t: [car("lead", t, 30.0)])
        w = RunWriter({str(tmp_path / 'bag')!r})
        w.begin(None, Goal(500.0, 0.0, 0.0), scenario_id="killed")
        for k, f in enumerate(frames):
            w.frame(f)
            if k == 100:
                print("recorded", flush=True)
            time.sleep(0.002)
        time.sleep(60)
    """)
    proc = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, env=dict(os.environ))
    try:
        assert proc.stdout.readline().strip() == b"recorded"
        time.sleep(1.2)                                         # past at least one flush
    finally:
        proc.send_signal(signal.SIGKILL)
        proc.wait(timeout=10)
    assert not (tmp_path / "bag" / "metadata.yaml").exists()
    result = judge_bag(tmp_path / "bag", PARAMS)
    assert any("no metadata.yaml" in i for i in result.issues)
    (verdict,) = result.verdicts
    assert verdict.frames > 100
    # The contact with the lead car at ~2.5 s was recorded before the kill: a known failure despite the crash.
    assert verdict.verdict is Verdict.FAIL and verdict.category_names() == ("Collisions",)
    with open(tmp_path / "bag" / "bag.mcap", "rb") as fh:      # the mcap stream reader reads the prefix too
        from mcap.stream_reader import StreamReader
        from mcap.records import Message

        n = 0
        try:
            for rec in StreamReader(fh, skip_magic=False).records:
                n += isinstance(rec, Message)
        except Exception:
            pass
    assert n > 100 * 4


def test_batched_wall_clock_recording_reads_back_in_order(tmp_path: Path) -> None:
    # RunWriter without a time base: receive-like wall-clock log times, each step written as one batch.
    frames = _frames()
    with RunWriter(tmp_path / "bag") as w:
        w.begin(_envelope(), GOAL)
        for f in frames:
            w.frame(f)
        w.end(RunStatus("rt1", "finished", 8.0, "time_limit"))
    msgs = list(read_bag(tmp_path / "bag").messages())
    times = [m.log_time_ns for m in msgs]
    assert times == sorted(times) and len(set(times)) == len(times)
    step = [m.topic for m in msgs[3:3 + 5]]
    assert step == [c.TOPIC_CLOCK, c.TOPIC_TRAFFIC_LIGHTS, c.TOPIC_OBJECTS_ODOM, c.TOPIC_OBJECTS_MARKERS,
                    c.TOPIC_EGO_ODOM]
    with open(tmp_path / "bag" / "bag.mcap", "rb") as fh:
        reader = make_reader(fh, decoder_factories=[DecoderFactory()])
        summary = reader.get_summary()
        assert summary.statistics.message_count == len(msgs)
        lights = [m for _, _, _, m in reader.iter_decoded_messages(topics=[c.TOPIC_TRAFFIC_LIGHTS])]
    assert len(lights) == len(frames) and lights[0].status[0].name == "sig1"
    assert lights[0].status[0].message == "red"
    result = judge_bag(tmp_path / "bag", PARAMS)
    assert result.complete and result.verdicts[0].category_names() == ("Misinterp",)


def test_real_closed_loop_runs_recorded_and_rejudged_match(tmp_path: Path) -> None:
    # esmini examples played by the scenario player against the stand-in planner (in-process, lock-step), each
    # recorded with its live verdict; the player's final frame repeats the previous frame's stamp, and the two
    # runs' clocks both restart at 0 — the re-judged verdicts must be the live ones, run for run.
    from txt2sce_ros.bench.judge import _lockstep

    live = []
    with RunWriter(tmp_path / "bag") as w:
        for name in ("slow-lead-vehicle", "traffic_lights", "slow-lead-vehicle"):
            live.append(_lockstep(name, w)[2])
    result = judge_bag(tmp_path / "bag", PARAMS)
    assert result.complete and result.agrees_with_live() is True
    assert [v.to_dict() for v in result.verdicts] == [v.to_dict() for v in live]
    assert [v.frames for v in result.verdicts] == [v.frames for v in live] and live[1].frames > 500


def test_fast_chunk_close_writes_the_bytes_rosbags_writes(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # The recorder closes chunks (every flush, every MiB) with its own packing of the message indexes: the MCAP
    # file must be byte for byte what rosbags' McapWriter.close_chunk writes. A flush after every write makes
    # many chunks, with one and several channels each.
    from oracle_monitor import cdr, recorder

    frames = _frames()

    def write(path: Path) -> bytes:
        rec = recorder.BagRecorder(path, flush_interval=0.0)
        ns = 1_700_000_000_000_000_000
        for i, f in enumerate(frames):
            rec.write(c.TOPIC_CLOCK, cdr.encode_clock(f.t), log_time_ns=ns + 4 * i)
            rec.write_batch([(c.TOPIC_EGO_ODOM, cdr.encode_odometry(f.ego)),
                             (c.TOPIC_OBJECTS_MARKERS, cdr.encode_markers(f))], ns + 4 * i + 1)
        rec.close()
        return b"".join(p.read_bytes() for p in sorted(path.glob("*.mcap")))

    ours = write(tmp_path / "ours" / "bag")           # the same directory name: the file embeds its name
    monkeypatch.setattr(recorder, "_close_chunk", lambda storage: storage.close_chunk())
    theirs = write(tmp_path / "theirs" / "bag")
    assert len(ours) > 10_000 and ours == theirs


def _closed_loop(name: str):
    """(simulation, [(frame, command)]) of an esmini example played against the stand-in planner."""
    from txt2sce_ros.bench.judge import _frames
    from standin_planner import Faults, Planner, PlannerParams

    sim, frames = _frames(name)
    planner = Planner(sim.network, sim.goal, PlannerParams.from_config(), faults=Faults())
    return sim, [(f, planner.step(f)) for f in frames]


def _per_message(monkeypatch: pytest.MonkeyPatch) -> None:
    """Makes `RunWriter` write every waiting step by the per-message encoders (`RunWriter._encode`), the reference
    the packed path must equal byte for byte: the same batches and receive times, each step's frame kept aside."""
    from collections import deque

    from oracle_monitor import runwriter

    kept: deque = deque()
    frame = runwriter.RunWriter.frame

    def keep(self, f, cmd=None) -> None:
        kept.append((f, cmd))
        frame(self, f, cmd)

    def per_message(self, segment, out) -> None:
        for ns in segment.received:
            f, cmd = kept.popleft()
            self._messages(ns, f, cmd, out)

    monkeypatch.setattr(runwriter.RunWriter, "frame", keep)
    monkeypatch.setattr(runwriter.RunWriter, "_pack", per_message)


def _message_indexes(mcap: bytes) -> list[tuple[int, tuple[int, ...]]]:
    """(channel, flat (log time, offset) pairs) of every MessageIndex record, with each chunk's data start."""
    import struct

    out, p, chunk_data = [], 8, 0
    while p < len(mcap) - 8:
        op, length = struct.unpack_from("<BQ", mcap, p)
        if op == 0x06:                                        # Chunk: start, end, size, crc, "", size, then data
            chunk_data = p + 9 + 8 * 3 + 4 + 4 + 8
        elif op == 0x07:
            cid, nbytes = struct.unpack_from("<HI", mcap, p + 9)
            out.append((cid, chunk_data, struct.unpack_from(f"<{nbytes // 8}Q", mcap, p + 15)))
        elif op in (0x02, 0x0F):                              # footer, data end
            break
        p += 9 + length
    return out


def test_packed_steps_are_the_per_message_bytes(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # The whole-step packing (steprecords.StepPacker) must write what the per-message encoders and record heads
    # write: the same bag byte for byte, on real closed-loop runs (traffic_lights: 2 pedestrians, 3 signals whose
    # changes take the per-message path for the view markers; pedestrian_collision: 1 pedestrian, no signals),
    # and with an entity stamped apart from its frame and steps without a command.
    import dataclasses
    import itertools

    from oracle_monitor import runwriter

    def record(path: Path, sim, steps) -> bytes:
        clock = itertools.count(1_700_000_000_000_000_000, 1000)
        monkeypatch.setattr(runwriter.time, "time_ns", lambda: next(clock))
        with RunWriter(path, flush_interval=1e9) as w:        # chunks closed by size only: same in both
            w.begin(None, sim.goal, "x", network=sim.network, lights=steps[0][0].lights)
            for f, cmd in steps:
                w.frame(f, cmd)
        return (path / "bag.mcap").read_bytes()

    for name in ("traffic_lights", "pedestrian_collision"):
        sim, steps = _closed_loop(name)
        steps[3] = (dataclasses.replace(steps[3][0], ego=dataclasses.replace(steps[3][0].ego, t=0.123456789)),
                    steps[3][1])
        steps[-1] = (steps[-1][0], None)
        with monkeypatch.context() as m:
            ours = record(tmp_path / name / "packed" / "bag", sim, steps)
        with monkeypatch.context() as m:
            _per_message(m)
            theirs = record(tmp_path / name / "per_message" / "bag", sim, steps)
        assert len(ours) > 1_000_000 and ours == theirs


@pytest.mark.parametrize("name, view, runs", [
    # The last frame of a run has no command: the steps before it are one run; that step, a segment of its own,
    # is written message by message (a segment of fewer than SHORT_SEGMENT steps).
    ("pedestrian_collision", True, [199]),
    # Lights change at steps 82 and 142 (and the tuple the player hands over changes only then): with the view
    # markers on, each change step is written message by message (it redraws the lights), the steps between are
    # runs; without them, the change steps begin the runs.
    ("traffic_lights", True, [82, 59, 56]),
    ("traffic_lights", False, [82, 60, 57]),
])
def test_a_batch_is_cut_into_runs_where_its_layout_changes(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                                           name: str, view: bool, runs: list[int]) -> None:
    # Steps wait in segments of one lights tuple and one cast; a batch is packed a segment at a time, each as one
    # run with its layout looked up once. The bytes are the per-message path's
    # (test_packed_steps_are_the_per_message_bytes).
    from oracle_monitor import runwriter
    from oracle_monitor.recorder import BagRecorder
    from oracle_monitor.steprecords import StepRun

    sim, steps = _closed_loop(name)
    steps = steps[:200]
    steps[-1] = (steps[-1][0], None)
    got: list[int] = []
    lookups: list[int] = []
    write_steps, packer = BagRecorder.write_steps, runwriter.RunWriter._packer
    monkeypatch.setattr(BagRecorder, "write_steps", lambda self, batch: (
        got.extend(len(s.received) for s in batch if isinstance(s, StepRun)), write_steps(self, batch))[1])
    monkeypatch.setattr(runwriter.RunWriter, "_packer",
                        lambda self, f, cmd: (lookups.append(1), packer(self, f, cmd))[1])
    with RunWriter(tmp_path / "bag", flush_interval=1e9) as w:
        w.begin(None, sim.goal, "x", network=sim.network if view else None, lights=steps[0][0].lights)
        for f, cmd in steps:
            w.frame(f, cmd)
    assert got == runs and len(lookups) == len(runs)


def test_message_indexes_point_at_their_records(tmp_path: Path) -> None:
    # Each MessageIndex entry (log time, offset in the chunk's data) must land on a Message record of that channel
    # and log time - also for the first batch, whose new channels write their records into the same chunk.
    import struct

    sim, steps = _closed_loop("traffic_lights")
    with RunWriter(tmp_path / "bag") as w:
        w.begin(None, sim.goal, "x", network=sim.network, lights=steps[0][0].lights)
        for f, cmd in steps:
            w.frame(f, cmd)
    mcap = (tmp_path / "bag" / "bag.mcap").read_bytes()
    checked = 0
    for cid, data_start, flat in _message_indexes(mcap):
        for log_time, offset in zip(flat[::2], flat[1::2]):
            op, _, rec_cid, _, rec_time = struct.unpack_from("<BQHIQ", mcap, data_start + offset)
            assert (op, rec_cid, rec_time) == (0x05, cid, log_time)
            checked += 1
    assert checked == sum(1 for _ in read_bag(tmp_path / "bag").messages())


def test_connections_and_metadata_are_what_rosbags_writes(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # The recorder adds its connections with the QoS dump made once, and writes the metadata (in the MCAP summary
    # and metadata.yaml) with its own emitter: the bag must be byte for byte the one rosbags' Writer.add_connection
    # and PyYAML's dump make (flush after every write and fixed log times, so both runs chunk alike).
    import yaml

    from oracle_monitor import recorder

    def record(path: Path) -> tuple[bytes, str]:
        with RunWriter(path, flush_interval=0.0, time_base_ns=1_700_000_000_000_000_000) as w:
            w.begin(_envelope(), GOAL)
            for f in _frames():
                w.frame(f, c.ControlCommand(f.t, 9.5, 0.0))
            w.end(RunStatus("rt1", "finished", 8.0, "time_limit"))
        return (path / "bag.mcap").read_bytes(), (path / "metadata.yaml").read_text()

    ours = record(tmp_path / "ours" / "bag")
    monkeypatch.setattr(recorder, "_add_connection",
                        lambda w, topic, msgtype, msgdef, rihs01: w.add_connection(topic, msgtype, msgdef=msgdef,
                                                                                   rihs01=rihs01))
    monkeypatch.setattr(recorder, "metadata_yaml", lambda value: yaml.dump(
        value, Dumper=yaml.CSafeDumper, default_flow_style=False, sort_keys=True).strip())
    theirs = record(tmp_path / "theirs" / "bag")
    assert len(ours[0]) > 10_000 and ours == theirs
    assert "/control/command" in ours[1] and "type_description_hash: RIHS01_" in ours[1]


@pytest.mark.parametrize("name", ["my bag: one", "yes", "No", "123", "1.5", "", "-x", " lead", "a\"b'c", "ünï",
                                  "#x", "x #y", "null", "~", "a\tb", "line\nbreak", "[x]", "{y}", "&a", "*b", "!c"])
def test_metadata_yaml_reads_back_as_written(name: str) -> None:
    # Awkward names (a bag directory, a topic) must read back as the same string, by PyYAML and by ruamel (which
    # rosbags reads metadata with).
    import io

    import yaml
    from ruamel.yaml import YAML

    from oracle_monitor.recorder import _metadata_texts, metadata_yaml

    value = {"rosbag2_bagfile_information": {"relative_file_paths": [name + ".mcap", name],
                                             "files": [{"path": name, "message_count": 3,
                                                        "starting_time": {"nanoseconds_since_epoch": 17}}],
                                             "custom_data": None, "name": name, "empty": [], "none": {}}}
    text = metadata_yaml(value)
    assert yaml.safe_load(text) == value
    assert YAML(typ="safe").load(io.StringIO(text)) == value
    # The bag writes the info twice (MCAP summary, metadata.yaml under its key), emitted once.
    inner = value["rosbag2_bagfile_information"]
    assert _metadata_texts(inner) == (metadata_yaml(inner), text)


def test_frames_with_list_lights_record_as_tuples_do(tmp_path: Path) -> None:
    # A Frame built with lists (not the contract's tuples) must record, and give the same bag as with tuples.
    import dataclasses
    import itertools

    from oracle_monitor import runwriter

    def record(path: Path, frames) -> bytes:
        clock = itertools.count(1_700_000_000_000_000_000, 1000)
        original = runwriter.time.time_ns
        runwriter.time.time_ns = lambda: next(clock)
        try:
            with RunWriter(path, flush_interval=1e9) as w:
                for f in frames:
                    w.frame(f)
        finally:
            runwriter.time.time_ns = original
        return (path / "bag.mcap").read_bytes()

    frames = _frames()
    as_lists = [dataclasses.replace(f, lights=list(f.lights), objects=list(f.objects)) for f in frames]
    assert record(tmp_path / "lists" / "bag", as_lists) == record(tmp_path / "tuples" / "bag", frames)


def test_messages_between_steps_keep_their_place(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # A violation written while steps wait to be packed joins them in order (no drain of its own): the bag is
    # byte for byte the one the per-message path writes, each message at its place in the stream.
    import itertools

    from oracle_monitor import runwriter
    from oracle_monitor.records import Category, Rule, Violation

    sim, steps = _closed_loop("pedestrian_collision")
    drains = []

    def counting_drain(self) -> None:
        drains.append(self._waiting)
        packed_drain(self)

    def record(path: Path) -> bytes:
        clock = itertools.count(1_700_000_000_000_000_000, 1000)
        monkeypatch.setattr(runwriter.time, "time_ns", lambda: next(clock))
        with RunWriter(path, flush_interval=1e9) as w:
            w.begin(None, sim.goal, "x", network=sim.network, lights=steps[0][0].lights)
            for k, (f, cmd) in enumerate(steps):
                w.frame(f, cmd)
                if k % 97 == 5:
                    w.violations(f.t, [Violation(Rule.CONTACT, Category.COLLISIONS, f.t, 0.5, 0.0, "m", ("x",))])
            w.end(RunStatus("x", "finished", steps[-1][0].t, "goal_reached"))
        return (path / "bag.mcap").read_bytes()

    packed_drain = runwriter.RunWriter._drain
    with monkeypatch.context() as m:
        m.setattr(runwriter.RunWriter, "_drain", counting_drain)
        ours = record(tmp_path / "packed" / "bag")
    assert len(drains) <= -(-len(steps) // runwriter.BATCH_STEPS) + 1      # batches only, none per violation
    with monkeypatch.context() as m:
        _per_message(m)
        theirs = record(tmp_path / "per_message" / "bag")
    assert ours == theirs
    topics = [m.topic for m in read_bag(tmp_path / "packed" / "bag").messages()]
    assert topics.count(c.TOPIC_VIOLATIONS) == len(range(5, len(steps), 97))
    # Each violation right after the step it was written after (steps are kept a few at a time before they are
    # read into segments: a message between them must not overtake them).
    clocks, before = 0, []
    for topic in topics:
        if topic == c.TOPIC_CLOCK:
            clocks += 1
        elif topic == c.TOPIC_VIOLATIONS:
            before.append(clocks)
    assert before == [k + 1 for k in range(5, len(steps), 97)]


def test_shared_step_layouts_record_the_same_bytes(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # Step layouts are compiled once per process and shared by every recorder (steprecords.step_packer); a run
    # recorded with layouts another recorder compiled must be byte for byte the run recorded with fresh ones.
    import itertools

    from oracle_monitor import runwriter, steprecords

    sim, steps = _closed_loop("traffic_lights")

    def record(path: Path) -> bytes:
        clock = itertools.count(1_700_000_000_000_000_000, 1000)
        monkeypatch.setattr(runwriter.time, "time_ns", lambda: next(clock))
        with RunWriter(path, flush_interval=1e9) as w:
            w.begin(None, sim.goal, "x", network=sim.network, lights=steps[0][0].lights)
            for f, cmd in steps:
                w.frame(f, cmd)
        return (path / "bag.mcap").read_bytes()

    steprecords._COMPILED.clear()
    fresh = record(tmp_path / "a" / "bag")
    compiled = len(steprecords._COMPILED)
    shared = record(tmp_path / "b" / "bag")
    assert compiled >= 2 and len(steprecords._COMPILED) == compiled     # the second run compiled nothing new
    assert fresh == shared


def test_a_file_that_is_no_mcap_is_refused_before_reading(tmp_path: Path) -> None:
    # Refused up front, so `txt2sce replay` names the file instead of bringing up ROS and publishing nothing.
    (tmp_path / "j.mcap").write_bytes(b"not an mcap at all")
    (tmp_path / "empty.mcap").write_bytes(b"")
    with pytest.raises(InputError, match=r"j\.mcap: not an MCAP file"):
        read_bag(tmp_path / "j.mcap")
    with pytest.raises(InputError, match=r"empty\.mcap: empty file"):
        read_bag(tmp_path / "empty.mcap")
    both = tmp_path / "bag"
    both.mkdir()
    (both / "a.mcap").write_bytes(b"junk")
    with pytest.raises(InputError, match=r"a\.mcap: not an MCAP file"):
        read_bag(both)


def test_step_values_convert_to_the_same_doubles_as_numpy() -> None:
    # `steprecords._doubles` packs the step values with struct; each double must be the one numpy would make,
    # bit for bit (signed zero, infinities, NaN, ints and numpy scalars included), and a non-number must raise.
    import math

    import numpy as np

    from oracle_monitor import steprecords

    values = [0.0, -0.0, 1.5, -2.25e-300, 1e308, math.inf, -math.inf, math.nan, 3, np.float64(0.1), True]
    got = steprecords._doubles(iter(values), len(values))
    want = np.fromiter(values, dtype=np.float64, count=len(values))
    assert got.dtype == np.float64 and got.tobytes() == want.tobytes()
    for bad in (["x"], [None], [1.0, 2.0]):
        with pytest.raises((struct.error, TypeError)):
            steprecords._doubles(bad, 1)


def test_layout_changes_inside_a_batch_record_the_per_message_bytes(tmp_path: Path,
                                                                     monkeypatch: pytest.MonkeyPatch) -> None:
    # Steps wait in segments of one layout (`RunWriter.frame`); each kind of change inside a batch must start a
    # new segment where the per-message path would differ: an entity leaving and
    # coming back, one renamed, one recategorised (an equal name in a new string object is no change), lights
    # changing with no view markers shown, steps without a command among steps with one; and receive times that
    # repeat and go back, which the log times must still order.
    import dataclasses
    import itertools

    from oracle_monitor import runwriter

    sim, steps = _closed_loop("traffic_lights")
    edited = []
    for k, (f, cmd) in enumerate(steps[:600]):
        objects = f.objects
        if 40 <= k < 45:
            objects = objects[1:]
        elif k == 70:
            objects = (dataclasses.replace(objects[0], name="renamed"), *objects[1:])
        elif k == 90:
            objects = (dataclasses.replace(objects[0], category="bicycle"), *objects[1:])
        elif k >= 100:
            objects = (dataclasses.replace(objects[0], name="".join(objects[0].name)), *objects[1:])
        lights = f.lights
        if k in (300, 301, 420):
            lights = tuple(dataclasses.replace(light, state=SignalState.YELLOW) for light in lights)
        edited.append((dataclasses.replace(f, objects=objects, lights=lights),
                       None if k % 150 in (7, 8, 9) else cmd))

    def record(path: Path) -> bytes:
        ticks = itertools.chain.from_iterable((t, t, t - 5_000) for t in itertools.count(1_700_000_000_000_000_000,
                                                                                       1000))
        monkeypatch.setattr(runwriter.time, "time_ns", lambda: next(ticks))
        with RunWriter(path, flush_interval=1e9) as w:
            w.begin(None, sim.goal, "x")
            for f, cmd in edited:
                w.frame(f, cmd)
        return (path / "bag.mcap").read_bytes()

    ours = record(tmp_path / "packed" / "bag")
    with monkeypatch.context() as m:
        _per_message(m)
        theirs = record(tmp_path / "per_message" / "bag")
    assert ours == theirs
    times = [m.log_time_ns for m in read_bag(tmp_path / "packed" / "bag").messages()]
    assert times == sorted(times) and len(set(times)) == len(times)


def test_each_kind_of_layout_change_starts_a_segment(tmp_path: Path) -> None:
    # A step joins the waiting segment only if it has its lights tuple and cast: a change of either, or of whether
    # a command follows, starts a new one (told by identity: an equal name in a new string object starts one too,
    # which costs a layout lookup, never a wrong layout).
    import dataclasses

    sim, steps = _closed_loop("traffic_lights")
    frames = [f for f, _ in steps[:50]]
    commands = [cmd for _, cmd in steps[:50]]
    f = frames[20]
    changes = [
        dataclasses.replace(f, objects=f.objects[1:]),
        dataclasses.replace(f, objects=(*f.objects, f.objects[0])),
        dataclasses.replace(f, objects=(dataclasses.replace(f.objects[1], name="other"), f.objects[0])),
        dataclasses.replace(f, ego=dataclasses.replace(f.ego, category="truck")),
        dataclasses.replace(f, lights=f.lights[1:]),
        dataclasses.replace(f, ego=dataclasses.replace(f.ego, name="".join(["", f.ego.name]))),
    ]

    def segments(frames, commands) -> list[int]:
        w = RunWriter(tmp_path / f"bag{len(list(tmp_path.iterdir()))}", flush_interval=1e9)
        w.begin(None, sim.goal, "x")
        for fr, cmd in zip(frames, commands):
            w.frame(fr, cmd)
        w._take()                                  # the last steps, still kept as they came
        got = [len(s.received) for s in w._pending]
        w.close()
        return got

    assert segments(frames, commands) == [50] and segments(frames, [None] * 50) == [50]
    for changed in changes:
        assert segments([*frames[:20], changed, *frames[21:]], commands) == [20, 1, 29]
    assert segments(frames, [*commands[:49], None]) == [49, 1]


def test_step_times_follow_the_stepwise_rule() -> None:
    import random

    from oracle_monitor.recorder import _step_times

    rng = random.Random(7)
    for _ in range(200):
        n, per_step, last = rng.randint(1, 40), rng.randint(1, 9), rng.randint(0, 10**6)
        received = [rng.choice((last + rng.randint(-500, 500), rng.randint(0, 2 * 10**6))) for _ in range(n)]
        want, prev = [], last
        for r in received:                      # the rule, step by step
            t = max(r, prev + 1)
            want.append(t)
            prev = t + per_step - 1
        assert _step_times(received, per_step, last).tolist() == want
