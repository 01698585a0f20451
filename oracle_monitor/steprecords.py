"""One lock-step step's messages as MCAP Message records, packed by one `struct.pack` call.

A recorded step is /clock, /sim/traffic_lights, one /sim/objects/odom per object, /sim/objects/markers,
/sim/ego/odom and (in a closed loop) /control/command, each a Message record (a 31-byte head: opcode, length,
channel, sequence, log time, publish time) around its CDR bytes. Encoding these message by message
(`cdr.encode_*`, then a record head each) made ~40 bytes objects and joins per step; a recording's cost was
mostly that. But while the same entities and light states are on stage, a step's layout does not change: every
length, every padding and every string is the same, only the numbers move. `StepPacker` compiles that layout
once into a `struct.Struct` whose format holds the constant runs as `s` fields (built by the `cdr` encoders'
own pieces: names, marker tails, the lights body), the zero fields as pad bytes, and the numbers as `d`, `i`,
`I` and `Q` fields; a step is then one list of values and one `pack`.

The bytes are exactly those of the per-message path (`RunWriter._encode` + `recorder._MESSAGE_RECORD`), which
stays the reference and the path for anything else (the view markers on a light change, synthetic time bases);
tests compare the two byte for byte.
"""

from __future__ import annotations

import math
import struct
from typing import Sequence

from txt2sce_ros.contract import ControlCommand, Frame

from . import cdr

_REC_HEAD = struct.Struct("<BQHI")     # opcode 0x05, record length, channel, sequence (log and publish time follow)
_REC_TIMES = "QQ"                     # log time, publish time (the same)
_STAMP = "iI"                         # builtin_interfaces/Time: sec, nanosec


def layout_key(frame: Frame, command: ControlCommand | None) -> tuple:
    """What fixes a step's layout: the entities' names and categories (strings, tails, paddings), the light
    states (the lights body) and whether a command follows. Equal keys, equal layouts."""
    lights = frame.lights if isinstance(frame.lights, tuple) else tuple(frame.lights)   # hashable either way
    return (frame.ego.name, frame.ego.category, lights, command is None,
            *[(o.name, o.category) for o in frame.objects])


class StepPacker:
    """The compiled layout of one kind of step. `cids`: the channel ids of clock, lights, objects' odometry,
    markers, ego odometry and command, in that order."""

    __slots__ = ("_struct", "_consts", "topics_cids", "offsets", "size", "_n_objects", "_command")

    def __init__(self, frame: Frame, command: ControlCommand | None, cids: Sequence[int]) -> None:
        clock_cid, lights_cid, odom_cid, markers_cid, ego_cid, command_cid = cids
        fmt: list[str] = ["<"]
        consts: list[bytes] = []               # the constant `s` fields, in format order
        offsets: list[int] = []                # each record's offset in the step
        record_cids: list[int] = []
        size = 0

        def record(cid: int, body_size: int) -> None:
            nonlocal size
            offsets.append(size)
            record_cids.append(cid)
            head = _REC_HEAD.pack(0x05, 22 + body_size, cid, 0)
            fmt.append(f"{len(head)}s{_REC_TIMES}")
            consts.append(head)
            size += 31 + body_size

        def const(raw: bytes) -> None:
            fmt.append(f"{len(raw)}s")
            consts.append(raw)

        # /clock: header, stamp.
        record(clock_cid, 12)
        const(cdr.HEADER)
        fmt.append(_STAMP)
        # /sim/traffic_lights: header, stamp, then "map" and the body of these light states (constant).
        lights = cdr.encode_lights(frame.lights, frame.t)
        record(lights_cid, len(lights))
        const(cdr.HEADER)
        fmt.append(_STAMP)
        const(lights[12:])
        # One odometry per object, then the markers, then the ego's odometry.
        for obj in frame.objects:
            self._odometry(obj.name, odom_cid, record, const, fmt)
        entities = (frame.ego, *frame.objects)
        body = cdr.encode_markers(frame)
        record(markers_cid, len(body))
        const(cdr.HEADER + struct.pack("<I", len(entities)))
        off = 4
        for i, e in enumerate(entities):
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
            if pad:
                fmt.append(f"{pad}x")
            fmt.append(_STAMP)
            const(cdr._MAP + ns + bytes(pad2) + struct.pack("<iii", i, 1, 0) + bytes(pad3))
            fmt.append("3d16x2d3d")            # position x, y, z; orientation x, y (zero), z, w; scale
            const(tail)
        assert off + 4 == len(body), "marker layout out of step with cdr.encode_markers"
        self._odometry(frame.ego.name, ego_cid, record, const, fmt)
        if command is not None:
            cmd = cdr.encode_command(command)
            record(command_cid, len(cmd))
            const(cdr.HEADER)
            fmt.append(_STAMP)
            fid = cdr._cdr_string("ego")
            const(fid + bytes((-(8 + len(fid))) % 8))
            fmt.append("d32xd")                # linear x; linear y, z and angular x, y (zero); angular z
        self._struct = struct.Struct("".join(fmt))
        assert self._struct.size == size, "step layout size differs from its records"
        self._consts = tuple(consts)
        self.topics_cids = tuple(record_cids)
        self.offsets = tuple(offsets)
        self.size = size
        self._n_objects = len(frame.objects)
        self._command = command is not None

    @staticmethod
    def _odometry(name: str, cid: int, record, const, fmt: list[str]) -> None:
        child = cdr._cdr_string(name)
        pad = (-(16 + len(child))) % 8
        # header, stamp, "map", child frame, padding, then pose (x, y; z, qx, qy zero; qz, qw), its covariance
        # (zeros), twist (linear x, y; zeros; angular z) and its covariance (zeros): `cdr._ODOM_BODY`'s layout.
        record(cid, 4 + 8 + len(cdr._MAP) + len(child) + pad + cdr._ODOM_BODY.size)
        const(cdr.HEADER)
        fmt.append(_STAMP)
        const(cdr._MAP + child + bytes(pad))
        fmt.append("2d24x2d288x2d24xd288x")

    def pack(self, t: int, frame: Frame, command: ControlCommand | None) -> bytes:
        """The step's records, log (and publish) times t, t + 1, ... in record order."""
        c = self._consts
        sin, cos = math.sin, math.cos
        ft = frame.t
        ns = int(round(ft * 1e9))
        sec, nsec = ns // 1_000_000_000, ns % 1_000_000_000
        v: list = [c[0], t, t, c[1], sec, nsec,
                   c[2], t + 1, t + 1, c[3], sec, nsec, c[4]]
        k = 5                                   # next constant
        t += 2
        ego = frame.ego
        entities = (ego, *frame.objects)
        # Each entity's stamp once (its odometry and its marker carry the same one); most share the frame's.
        stamps = [(sec, nsec) if e.t == ft else divmod(int(round(e.t * 1e9)), 1_000_000_000) for e in entities]
        for e, (s, n) in zip(entities[1:], stamps[1:]):
            h = e.heading
            v += (c[k], t, t, c[k + 1], s, n, c[k + 2], e.x, e.y, sin(h / 2.0), cos(h / 2.0),
                  e.speed, e.accel, e.yaw_rate)
            k += 3
            t += 1
        v += (c[k], t, t, c[k + 1])
        k += 2
        t += 1
        for e, (s, n) in zip(entities, stamps):
            h = e.heading
            co, si = cos(h), sin(h)
            v += (s, n, c[k], e.x + e.center_x * co, e.y + e.center_x * si, e.height / 2.0,
                  sin(h / 2.0), cos(h / 2.0), e.length, e.width, e.height, c[k + 1])
            k += 2
        s, n = stamps[0]
        h = ego.heading
        v += (c[k], t, t, c[k + 1], s, n, c[k + 2], ego.x, ego.y, sin(h / 2.0), cos(h / 2.0),
              ego.speed, ego.accel, ego.yaw_rate)
        if command is not None:
            cns = int(round(command.t * 1e9))
            v += (c[k + 3], t + 1, t + 1, c[k + 4], cns // 1_000_000_000, cns % 1_000_000_000, c[k + 5],
                  command.speed, command.yaw_rate)
        return self._struct.pack(*v)
