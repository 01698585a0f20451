"""Lock-step steps' messages as MCAP Message records, packed a run of steps at a time.

A recorded step is /clock, /sim/traffic_lights, one /sim/objects/odom per object, /sim/objects/markers,
/sim/ego/odom and (in a closed loop) /control/command, each a Message record (a 31-byte head: opcode, length,
channel, sequence, log time, publish time) around its CDR bytes. While the same entities and light states are on
stage, a step's layout does not change: every length, every padding and every string is the same, only the
numbers move. `StepPacker` compiles that layout once into a template (the constant runs, built by the `cdr`
encoders' own pieces: names, marker tails, the lights body; zeros elsewhere) and a numpy record type naming each
number's offset. A step's numbers are read when it is recorded (`add_step_values`: one `attrgetter` call per
entity), and a run of steps of one layout is packed column by column: the derived values computed on whole
columns, and the numbers written into copies of the template by a few dozen array assignments for the whole run.
The message index entries of the run are computed the same way (`StepPacker.index`).

Packing step by step (one value list and one `struct.pack` per step, the previous version) cost ~7 µs a step of
Python; a run costs ~1-2 µs a step. The float results are the ones the encoders compute: the same IEEE operations
on the same doubles (numpy's elementwise `+`, `*` and `/` round each result as Python does; `rint` rounds half to
even as `round` does), and the trigonometry by `math.sin`/`math.cos` themselves (numpy's own may differ in the
last bit).

The bytes are exactly those of the per-message path (`RunWriter._encode` + `recorder._MESSAGE_RECORD`), which
stays the reference and the path for anything else (the view markers on a light change, synthetic time bases);
tests compare the two byte for byte.
"""

from __future__ import annotations

import math
import struct
from operator import attrgetter
from typing import Iterable, Sequence

import numpy as np

from txt2sce_ros.contract import ControlCommand, Frame

from . import cdr

_REC_HEAD = struct.Struct("<BQHI")     # opcode 0x05, record length, channel, sequence (log and publish time follow)
_NUMPY = {"d": "<f8", "i": "<i4", "I": "<u4", "Q": "<u8"}

#: An entity's numbers a step's records hold, read in one call per entity and step.
_ENTITY = attrgetter("t", "x", "y", "heading", "speed", "accel", "yaw_rate", "center_x", "length", "width", "height")
_T, _X, _Y, _H, _V, _A, _YAW, _CX, _LEN, _WID, _HGT = _ATTRS = range(11)
_COMMAND = attrgetter("t", "speed", "yaw_rate")


def add_step_values(values: list[float], frame: Frame, command: ControlCommand | None) -> None:
    """Append a step's numbers as `StepPacker.pack_run` reads them: the ego's `_ENTITY` attributes, each object's,
    the frame's time, then the command's `_COMMAND` attributes if there is one. (The float objects themselves:
    packing each step into doubles at once cost the loop more than keeping them, session 19.)"""
    values += _ENTITY(frame.ego)
    for obj in frame.objects:
        values += _ENTITY(obj)
    values.append(frame.t)
    if command is not None:
        values += _COMMAND(command)


def cast_key(frame: Frame, command: ControlCommand | None) -> tuple:
    """The part of a step's layout the lights leave out: the entities' names and categories (strings, tails,
    paddings) and whether a command follows."""
    return (frame.ego.name, frame.ego.category, command is None, *[(o.name, o.category) for o in frame.objects])


def layout_key(frame: Frame, command: ControlCommand | None) -> tuple:
    """What fixes a step's layout: its cast (`cast_key`) and the light states (the lights body). Equal keys, equal
    layouts."""
    lights = frame.lights if isinstance(frame.lights, tuple) else tuple(frame.lights)   # hashable either way
    return (lights, *cast_key(frame, command))


_COMPILED: dict[tuple, "StepPacker"] = {}
_COMPILED_MAX = 256


def step_packer(frame: Frame, command: ControlCommand | None, cids: Sequence[int | None]) -> "StepPacker":
    """The compiled layout of this step with these channel ids, shared by every recorder of the process: compiling
    one costs ~1 ms, a run has a few, and the runs of a campaign or a bench repeat the same ones. A packer is not
    changed after it is built."""
    key = (layout_key(frame, command), tuple(cids))
    packer = _COMPILED.get(key)
    if packer is None:
        if len(_COMPILED) >= _COMPILED_MAX:
            _COMPILED.clear()
        packer = _COMPILED[key] = StepPacker(frame, command, cids)
    return packer


class StepRun:
    """Consecutive steps of one layout, to be packed together: their receive times (None: now) and their numbers,
    flat, in `add_step_values`' order."""

    __slots__ = ("packer", "received", "values")

    def __init__(self, packer: "StepPacker", received: Sequence[int | None], values: Sequence[float]) -> None:
        self.packer = packer
        self.received = received
        self.values = values


_DOUBLES: dict[int, struct.Struct] = {}


def _doubles(values: Iterable[float], count: int) -> np.ndarray:
    """`count` Python floats as a float64 array: one `struct.pack` of native doubles (a C loop of
    PyFloat_AsDouble and an 8-byte copy per item, ~2.7x faster than `np.fromiter`, which converts each item
    through numpy's scalar machinery; `array.array` parses each item through a format). The packer of each count
    is kept: a run has a few counts (the batch size and the last batch's). A value that is not a number raises."""
    packer = _DOUBLES.get(count)
    if packer is None:
        if len(_DOUBLES) >= 64:
            _DOUBLES.clear()
        packer = _DOUBLES[count] = struct.Struct(f"@{count}d")
    return np.frombuffer(packer.pack(*values), dtype=np.float64)


def _ns(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """builtin_interfaces/Time (sec, nanosec) of times in seconds: `ns = int(round(t * 1e9))` split, on a column."""
    ns = np.rint(t * 1e9).astype(np.int64)
    sec = ns // 1_000_000_000
    if len(sec) and (sec.min() < -2**31 or sec.max() >= 2**31):
        raise struct.error("'i' format requires -2147483648 <= number <= 2147483647")
    return sec, ns % 1_000_000_000


class StepPacker:
    """The compiled layout of one kind of step. `cids`: the channel ids of clock, lights, objects' odometry,
    markers, ego odometry and command, in that order."""

    __slots__ = ("_template", "_dtype", "_fields", "topics_cids", "offsets", "size", "_n_entities", "_command",
                 "_channels")

    def __init__(self, frame: Frame, command: ControlCommand | None, cids: Sequence[int]) -> None:
        clock_cid, lights_cid, odom_cid, markers_cid, ego_cid, command_cid = cids
        tmpl = bytearray()
        fields: list[tuple[int, str, tuple]] = []     # (offset, struct code, source) of every number
        offsets: list[int] = []                        # each record's offset in the step
        record_cids: list[int] = []

        def num(code: str, *source: object) -> None:
            fields.append((len(tmpl), code, source))
            tmpl.extend(bytes(struct.calcsize("<" + code)))

        def record(cid: int, body_size: int) -> None:
            offsets.append(len(tmpl))
            record_cids.append(cid)
            tmpl.extend(_REC_HEAD.pack(0x05, 22 + body_size, cid, 0))
            num("Q", "time", len(offsets) - 1)        # log time
            num("Q", "time", len(offsets) - 1)        # publish time (the same)

        def stamp(*source: object) -> None:
            num("i", "sec", *source)
            num("I", "nsec", *source)

        def odometry(name: str, cid: int, j: int) -> None:
            child = cdr._cdr_string(name)
            pad = (-(16 + len(child))) % 8
            # header, stamp, "map", child frame, padding, then pose (x, y; z, qx, qy zero; qz, qw), its covariance
            # (zeros), twist (linear x, y; zeros; angular z) and its covariance (zeros): `cdr._ODOM_BODY`'s layout.
            record(cid, 4 + 8 + len(cdr._MAP) + len(child) + pad + cdr._ODOM_BODY.size)
            tmpl.extend(cdr.HEADER)
            stamp("entity", j)
            tmpl.extend(cdr._MAP + child + bytes(pad))
            num("d", "col", j, _X)
            num("d", "col", j, _Y)
            tmpl.extend(bytes(24))
            num("d", "qz", j)
            num("d", "qw", j)
            tmpl.extend(bytes(288))
            num("d", "col", j, _V)
            num("d", "col", j, _A)
            tmpl.extend(bytes(24))
            num("d", "col", j, _YAW)
            tmpl.extend(bytes(288))

        # /clock: header, stamp.
        record(clock_cid, 12)
        tmpl.extend(cdr.HEADER)
        stamp("frame")
        # /sim/traffic_lights: header, stamp, then "map" and the body of these light states (constant).
        lights = cdr.encode_lights(frame.lights, frame.t)
        record(lights_cid, len(lights))
        tmpl.extend(cdr.HEADER)
        stamp("frame")
        tmpl.extend(lights[12:])
        # One odometry per object, then the markers, then the ego's odometry.
        for j, obj in enumerate(frame.objects, start=1):
            odometry(obj.name, odom_cid, j)
        entities = (frame.ego, *frame.objects)
        body = cdr.encode_markers(frame)
        record(markers_cid, len(body))
        tmpl.extend(cdr.HEADER + struct.pack("<I", len(entities)))
        off = 4
        for j, e in enumerate(entities):
            # The offset arithmetic of `cdr.encode_markers`, which this layout must follow exactly.
            pad = (-off) % 4
            ns = cdr._cdr_string(e.category)
            off += pad + 16 + len(ns)
            pad2 = (-off) % 4
            off += pad2 + 12
            pad3 = (-off) % 8
            off += pad3 + 80
            tail = cdr._MARKER_TAIL[(e.category, e.name)]     # made by the encode_markers call above
            off += len(tail)
            tmpl.extend(bytes(pad))
            stamp("entity", j)
            tmpl.extend(cdr._MAP + ns + bytes(pad2) + struct.pack("<iii", j, 1, 0) + bytes(pad3))
            num("d", "mx", j)                  # position x, y, z; orientation x, y (zero), z, w; scale
            num("d", "my", j)
            num("d", "mz", j)
            tmpl.extend(bytes(16))
            num("d", "qz", j)
            num("d", "qw", j)
            num("d", "col", j, _LEN)
            num("d", "col", j, _WID)
            num("d", "col", j, _HGT)
            tmpl.extend(tail)
        assert off + 4 == len(body), "marker layout out of step with cdr.encode_markers"
        odometry(frame.ego.name, ego_cid, 0)
        if command is not None:
            cmd = cdr.encode_command(command)
            record(command_cid, len(cmd))
            tmpl.extend(cdr.HEADER)
            stamp("command")
            fid = cdr._cdr_string("ego")
            tmpl.extend(fid + bytes((-(8 + len(fid))) % 8))
            num("d", "command", 1)             # linear x; linear y, z and angular x, y (zero); angular z
            tmpl.extend(bytes(32))
            num("d", "command", 2)
        size = len(tmpl)
        self._template = np.frombuffer(bytes(tmpl), dtype=np.uint8)
        self._dtype = np.dtype({"names": [f"f{k}" for k in range(len(fields))],
                                "formats": [_NUMPY[code] for _, code, _ in fields],
                                "offsets": [o for o, _, _ in fields], "itemsize": size})
        self._fields = tuple((f"f{k}", source) for k, (_, _, source) in enumerate(fields))
        self.topics_cids = tuple(record_cids)
        self.offsets = tuple(offsets)
        self.size = size
        self._n_entities = len(entities)
        self._command = command is not None
        # Each channel's records in the step, in order (the objects' odometry has one per object).
        channels: dict[int, list[int]] = {}
        for r, cid in enumerate(record_cids):
            channels.setdefault(cid, []).append(r)
        self._channels = tuple((cid, tuple(rs)) for cid, rs in channels.items())

    def pack_run(self, times: np.ndarray, values: Sequence[float], out: np.ndarray | None = None) -> np.ndarray:
        """The records of a run of steps of this layout, as one array of bytes: step k's log (and publish) times
        are times[k], times[k] + 1, ... in record order; its numbers are the k-th `add_step_values` stretch of
        `values`. `out`: the uint8 array (of `size` bytes per step) to pack them into, else a new one."""
        n, m = len(times), self._n_entities
        width = len(_ATTRS)
        per_step = m * width + 1 + (3 if self._command else 0)
        if len(values) != n * per_step:
            raise ValueError(f"{len(values)} step values for {n} steps of {per_step}")
        steps = _doubles(values, n * per_step).reshape(n, per_step)
        ent = steps[:, :m * width].reshape(n, m, width)
        heading = ent[:, :, _H]
        half = (heading / 2.0).ravel().tolist()
        sin, cos = math.sin, math.cos
        shape = (n, m)
        k = n * m
        qz = _doubles(map(sin, half), k).reshape(shape)
        qw = _doubles(map(cos, half), k).reshape(shape)
        full = heading.ravel().tolist()
        cos_h = _doubles(map(cos, full), k).reshape(shape)
        sin_h = _doubles(map(sin, full), k).reshape(shape)
        cx = ent[:, :, _CX]
        derived = {"qz": qz, "qw": qw, "mx": ent[:, :, _X] + cx * cos_h, "my": ent[:, :, _Y] + cx * sin_h,
                   "mz": ent[:, :, _HGT] / 2.0}
        frame_sec, frame_nsec = _ns(steps[:, m * width])
        ent_sec, ent_nsec = _ns(ent[:, :, _T])
        if self._command:
            cmd = steps[:, m * width + 1:]
            cmd_sec, cmd_nsec = _ns(cmd[:, 0])
        if out is None:
            buf = np.tile(self._template, n)
        else:
            buf = out
            buf.reshape(n, self.size)[:] = self._template
        rec = buf.view(self._dtype)
        for name, source in self._fields:
            kind = source[0]
            if kind == "time":
                rec[name] = times + source[1]
            elif kind == "col":
                rec[name] = ent[:, source[1], source[2]]
            elif kind in derived:
                rec[name] = derived[kind][:, source[1]]
            elif kind == "sec" or kind == "nsec":
                where = source[1]
                if where == "frame":
                    rec[name] = frame_sec if kind == "sec" else frame_nsec
                elif where == "entity":
                    rec[name] = (ent_sec if kind == "sec" else ent_nsec)[:, source[2]]
                else:
                    rec[name] = cmd_sec if kind == "sec" else cmd_nsec
            else:                               # "command"
                rec[name] = cmd[:, source[1]]
        return buf

    def index(self, times: np.ndarray, start: int) -> list[tuple[int, np.ndarray]]:
        """Each channel's message index entries of a run packed at `start` in the chunk: (channel, flat (log
        time, offset) pairs as little-endian uint64), in record order."""
        n = len(times)
        at = start + np.arange(n, dtype=np.int64) * self.size
        out = []
        for cid, rs in self._channels:
            pairs = np.empty((n, len(rs), 2), dtype="<u8")
            for i, r in enumerate(rs):
                pairs[:, i, 0] = times + r
                pairs[:, i, 1] = at + self.offsets[r]
            out.append((cid, pairs.ravel()))
        return out
