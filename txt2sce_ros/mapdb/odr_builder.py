"""A small typed writer for OpenDRIVE 1.7 files: plan-view primitives, lanes, links, junctions, signals, controllers.

Only what the bundled maps need, kept exact: geometry is written as lines, arcs, clothoids and normalised cubic
`paramPoly3` curves, and each primitive's start pose is computed from the previous one, so the chain is continuous
by construction instead of by hand-typed coordinates.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Sequence

import numpy as np
from lxml import etree

#: OpenDRIVE header version written by this module (validated against the 1.7 XSD).
REV_MAJOR, REV_MINOR = 1, 7
#: Fixed so that regenerating the maps gives the same bytes.
HEADER_DATE = "2026-01-01T00:00:00"


@dataclass(frozen=True)
class Pose:
    """A point with a heading: x, y in m, h in rad (CCW from +x)."""

    x: float
    y: float
    h: float

    def local(self, other: "Pose") -> "Pose":
        """`other` expressed in this pose's frame (x forward, y to the left)."""
        dx, dy = other.x - self.x, other.y - self.y
        c, s = math.cos(self.h), math.sin(self.h)
        return Pose(c * dx + s * dy, -s * dx + c * dy, _wrap(other.h - self.h))

    def offset(self, t: float) -> "Pose":
        """The pose shifted `t` m to the left (same heading)."""
        return Pose(self.x - t * math.sin(self.h), self.y + t * math.cos(self.h), self.h)


def _wrap(a: float) -> float:
    return (a + math.pi) % (2.0 * math.pi) - math.pi


# --------------------------------------------------------------------------------------------- plan-view primitives


@dataclass(frozen=True)
class Line:
    length: float


@dataclass(frozen=True)
class Arc:
    length: float
    curvature: float  # 1/m, positive = turning left


@dataclass(frozen=True)
class Spiral:
    length: float
    curv_start: float
    curv_end: float


@dataclass(frozen=True)
class Hermite:
    """A cubic from the start pose to `end` (expressed in the start frame), written as a normalised paramPoly3.

    The tangent magnitude equals the chord length, which keeps quarter turns free of loops and kinks.
    """

    end: Pose

    def coefficients(self) -> tuple[tuple[float, float, float, float], tuple[float, float, float, float]]:
        x1, y1, h1 = self.end.x, self.end.y, self.end.h
        k = math.hypot(x1, y1)
        cu = 3.0 * x1 - 2.0 * k - k * math.cos(h1)
        du = -2.0 * x1 + k + k * math.cos(h1)
        cv = 3.0 * y1 - k * math.sin(h1)
        dv = -2.0 * y1 + k * math.sin(h1)
        return (0.0, k, cu, du), (0.0, 0.0, cv, dv)

    @property
    def length(self) -> float:
        (_, bu, cu, du), (_, bv, cv, dv) = self.coefficients()
        p = np.linspace(0.0, 1.0, 4001)
        speed = np.hypot(bu + 2 * cu * p + 3 * du * p * p, bv + 2 * cv * p + 3 * dv * p * p)
        return float(_simpson(speed, p[1] - p[0]))


Primitive = Line | Arc | Spiral | Hermite


def _simpson(values: np.ndarray, step: float) -> float:
    # Composite Simpson rule on an odd number of samples: exact enough (1e-10 m) for the curves written here.
    return float(step / 3.0 * (values[0] + values[-1] + 4.0 * values[1:-1:2].sum() + 2.0 * values[2:-1:2].sum()))


def advance(pose: Pose, prim: Primitive) -> Pose:
    """The end pose of `prim` started at `pose`."""
    if isinstance(prim, Line):
        return Pose(pose.x + prim.length * math.cos(pose.h), pose.y + prim.length * math.sin(pose.h), pose.h)
    if isinstance(prim, Arc):
        k, length = prim.curvature, prim.length
        if abs(k) < 1e-12:
            return advance(pose, Line(length))
        dh = k * length
        lx, ly = math.sin(dh) / k, (1.0 - math.cos(dh)) / k
        return _compose(pose, lx, ly, dh)
    if isinstance(prim, Spiral):
        n = 4001
        s = np.linspace(0.0, prim.length, n)
        rate = (prim.curv_end - prim.curv_start) / prim.length
        theta = prim.curv_start * s + 0.5 * rate * s * s
        step = s[1] - s[0]
        lx, ly = _simpson(np.cos(theta), step), _simpson(np.sin(theta), step)
        return _compose(pose, lx, ly, float(theta[-1]))
    if isinstance(prim, Hermite):
        return _compose(pose, prim.end.x, prim.end.y, prim.end.h)
    raise TypeError(f"unknown primitive {prim!r}")


def _compose(pose: Pose, lx: float, ly: float, dh: float) -> Pose:
    c, s = math.cos(pose.h), math.sin(pose.h)
    return Pose(pose.x + c * lx - s * ly, pose.y + s * lx + c * ly, _wrap(pose.h + dh))


def connector(start: Pose, end: Pose, *, tol: float = 1e-6) -> list[Primitive]:
    """Plan-view primitives from `start` to `end`: exact lines/arcs for straight, quarter and half turns, else a cubic.

    Quarter turns become a line plus an arc whose radius is the shorter of the two offsets, a U-turn two equal
    lines around a semicircle; anything else a `Hermite` cubic.
    """
    rel = start.local(end)
    if abs(rel.h) < tol and abs(rel.y) < tol and rel.x > 0:
        return [Line(rel.x)]
    if abs(abs(rel.h) - math.pi / 2) < tol and rel.x > 0 and rel.y * rel.h > 0:
        fwd, side = rel.x, abs(rel.y)
        r = min(fwd, side)
        arc = Arc(r * math.pi / 2, math.copysign(1.0 / r, rel.h))
        if fwd - side > tol:
            return [Line(fwd - side), arc]
        if side - fwd > tol:
            return [arc, Line(side - fwd)]
        return [arc]
    if abs(abs(rel.h) - math.pi) < tol and abs(rel.x) < tol and abs(rel.y) > tol:
        r = abs(rel.y) / 2.0
        lead = 6.0
        return [Line(lead), Arc(r * math.pi, math.copysign(1.0 / r, rel.y)), Line(lead)]
    return [Hermite(rel)]


# --------------------------------------------------------------------------------------------- lanes, links, signals


@dataclass(frozen=True)
class RoadMark:
    type: str = "none"  # solid, broken, solid solid, none, ...
    color: str = "standard"
    lane_change: str | None = None  # increase, decrease, both, none (OpenDRIVE roadMark/@laneChange)
    width: float = 0.12


SOLID_YELLOW_DOUBLE = RoadMark("solid solid", "yellow", "none")
SOLID_WHITE = RoadMark("solid", "white", "none")
BROKEN_WHITE = RoadMark("broken", "white", "both")
NO_MARK = RoadMark()


@dataclass(frozen=True)
class LaneSpec:
    """One lane: id (OpenDRIVE sign convention), type, width, the mark on its outer border, lane links.

    With `width_end` the width eases from `width` at s=0 to `width_end` at the road's end along a cubic with zero
    slope at both ends (where a roundabout's entry lane widens into the ring lane).
    """

    id: int
    type: str
    width: float
    mark: RoadMark = NO_MARK
    predecessor: int | None = None
    successor: int | None = None
    width_end: float | None = None


@dataclass(frozen=True)
class RoadLink:
    element_type: str  # "road" | "junction"
    element_id: str
    contact_point: str | None = None  # "start" | "end" for roads


@dataclass(frozen=True)
class SignalSpec:
    id: str
    name: str
    s: float
    t: float
    dynamic: bool
    orientation: str  # "+" | "-"
    type: str
    subtype: str = "-1"
    country: str = "DE"
    valid_lanes: tuple[int, int] | None = None  # (fromLane, toLane)
    height: float = 1.0
    z_offset: float = 2.0


@dataclass(frozen=True)
class RoadSpec:
    id: str
    name: str
    start: Pose
    geometry: tuple[Primitive, ...]
    left: tuple[LaneSpec, ...] = ()   # ids 1, 2, ... (inner to outer)
    right: tuple[LaneSpec, ...] = ()  # ids -1, -2, ... (inner to outer)
    center_mark: RoadMark = NO_MARK
    junction: str = "-1"
    predecessor: RoadLink | None = None
    successor: RoadLink | None = None
    road_type: str = "town"
    speed_kmh: float = 50.0
    signals: tuple[SignalSpec, ...] = ()

    @property
    def length(self) -> float:
        return sum(p.length for p in self.geometry)

    def end_pose(self) -> Pose:
        pose = self.start
        for prim in self.geometry:
            pose = advance(pose, prim)
        return pose

    def poses(self) -> list[Pose]:
        """The start pose of every primitive, then the end pose."""
        out = [self.start]
        for prim in self.geometry:
            out.append(advance(out[-1], prim))
        return out


@dataclass(frozen=True)
class ConnectionSpec:
    id: str
    incoming: str
    connecting: str
    contact_point: str  # on the connecting road: "start" | "end"
    lane_links: tuple[tuple[int, int], ...]


@dataclass(frozen=True)
class JunctionSpec:
    id: str
    name: str
    connections: tuple[ConnectionSpec, ...]
    controllers: tuple[str, ...] = ()  # controller ids, in signal-phase sequence
    priorities: tuple[tuple[str, str], ...] = ()  # (high road id, low road id)


@dataclass(frozen=True)
class ControllerSpec:
    id: str
    name: str
    signal_ids: tuple[str, ...]
    sequence: int = 0


@dataclass(frozen=True)
class MapSpec:
    name: str
    roads: tuple[RoadSpec, ...]
    junctions: tuple[JunctionSpec, ...] = ()
    controllers: tuple[ControllerSpec, ...] = ()
    description: str = ""


# --------------------------------------------------------------------------------------------- XML


def _num(v: float) -> str:
    # Fixed formatting so regenerated files are byte-identical across runs and platforms.
    text = f"{v:.12g}"
    return "0" if text in ("-0", "0") else text


def _sub(parent: etree._Element, tag: str, **attrs: object) -> etree._Element:
    return etree.SubElement(parent, tag, {k.rstrip("_"): (_num(v) if isinstance(v, float) else str(v))
                                          for k, v in attrs.items() if v is not None})


def _write_geometry(plan: etree._Element, road: RoadSpec) -> None:
    s = 0.0
    for pose, prim in zip(road.poses(), road.geometry):
        geo = _sub(plan, "geometry", s=float(s), x=float(pose.x), y=float(pose.y), hdg=float(pose.h),
                   length=float(prim.length))
        if isinstance(prim, Line):
            _sub(geo, "line")
        elif isinstance(prim, Arc):
            _sub(geo, "arc", curvature=float(prim.curvature))
        elif isinstance(prim, Spiral):
            _sub(geo, "spiral", curvStart=float(prim.curv_start), curvEnd=float(prim.curv_end))
        else:
            (au, bu, cu, du), (av, bv, cv, dv) = prim.coefficients()
            _sub(geo, "paramPoly3", aU=au, bU=bu, cU=cu, dU=du, aV=av, bV=bv, cV=cv, dV=dv, pRange="normalized")
        s += prim.length


def _write_mark(lane_el: etree._Element, mark: RoadMark) -> None:
    _sub(lane_el, "roadMark", sOffset=0.0, type=mark.type, weight="standard", color=mark.color,
         width=float(mark.width if mark.type != "none" else 0.0), laneChange=mark.lane_change)


def _write_lane(parent: etree._Element, lane: LaneSpec, length: float) -> None:
    el = _sub(parent, "lane", id=lane.id, type=lane.type, level="false")
    if lane.predecessor is not None or lane.successor is not None:
        link = _sub(el, "link")
        if lane.predecessor is not None:
            _sub(link, "predecessor", id=lane.predecessor)
        if lane.successor is not None:
            _sub(link, "successor", id=lane.successor)
    c = d = 0.0
    if lane.width_end is not None:
        delta = lane.width_end - lane.width
        c, d = 3.0 * delta / length ** 2, -2.0 * delta / length ** 3
    _sub(el, "width", sOffset=0.0, a=float(lane.width), b=0.0, c=float(c), d=float(d))
    _write_mark(el, lane.mark)


def _write_road(root: etree._Element, road: RoadSpec) -> None:
    el = _sub(root, "road", name=road.name, length=float(road.length), id=road.id, junction=road.junction,
              rule="RHT")
    if road.predecessor or road.successor:
        link = _sub(el, "link")
        for tag, target in (("predecessor", road.predecessor), ("successor", road.successor)):
            if target:
                _sub(link, tag, elementType=target.element_type, elementId=target.element_id,
                     contactPoint=target.contact_point)
    rtype = _sub(el, "type", s=0.0, type=road.road_type)
    _sub(rtype, "speed", max=float(road.speed_kmh), unit="km/h")
    _write_geometry(_sub(el, "planView"), road)
    lanes = _sub(el, "lanes")
    _sub(lanes, "laneOffset", s=0.0, a=0.0, b=0.0, c=0.0, d=0.0)
    section = _sub(lanes, "laneSection", s=0.0)
    if road.left:
        left = _sub(section, "left")
        for lane in sorted(road.left, key=lambda ln: -ln.id):  # the schema wants descending ids
            _write_lane(left, lane, road.length)
    center = _sub(_sub(section, "center"), "lane", id=0, type="none", level="false")
    _write_mark(center, road.center_mark)
    if road.right:
        right = _sub(section, "right")
        for lane in sorted(road.right, key=lambda ln: -ln.id):
            _write_lane(right, lane, road.length)
    if road.signals:
        sigs = _sub(el, "signals")
        for sig in road.signals:
            sel = _sub(sigs, "signal", s=float(sig.s), t=float(sig.t), id=sig.id, name=sig.name,
                       dynamic="yes" if sig.dynamic else "no", orientation=sig.orientation,
                       zOffset=float(sig.z_offset), country=sig.country, type=sig.type, subtype=sig.subtype,
                       height=float(sig.height), width=0.4)
            if sig.valid_lanes:
                _sub(sel, "validity", fromLane=sig.valid_lanes[0], toLane=sig.valid_lanes[1])


def _bounds(spec: MapSpec) -> tuple[float, float, float, float]:
    xs, ys = [], []
    for road in spec.roads:
        for pose in road.poses():
            xs.append(pose.x)
            ys.append(pose.y)
    return max(ys), min(ys), max(xs), min(xs)


def to_xml(spec: MapSpec) -> bytes:
    """The OpenDRIVE 1.7 document for `spec`, as UTF-8 bytes (deterministic)."""
    root = etree.Element("OpenDRIVE")
    north, south, east, west = _bounds(spec)
    _sub(root, "header", revMajor=REV_MAJOR, revMinor=REV_MINOR, name=spec.name, version="1.0",
         date=HEADER_DATE, north=float(north), south=float(south), east=float(east), west=float(west),
         vendor="txt2sce")
    if spec.description:
        root[0].append(etree.Comment(f" {spec.description} "))
    for road in spec.roads:
        _write_road(root, road)
    for ctrl in spec.controllers:
        cel = _sub(root, "controller", id=ctrl.id, name=ctrl.name, sequence=ctrl.sequence)
        for sid in ctrl.signal_ids:
            _sub(cel, "control", signalId=sid, type="0")
    for junction in spec.junctions:
        jel = _sub(root, "junction", id=junction.id, name=junction.name, type="default")
        for conn in junction.connections:
            cel = _sub(jel, "connection", id=conn.id, incomingRoad=conn.incoming, connectingRoad=conn.connecting,
                       contactPoint=conn.contact_point)
            for a, b in conn.lane_links:
                _sub(cel, "laneLink", from_=a, to=b)
        for high, low in junction.priorities:
            _sub(jel, "priority", high=high, low=low)
        for seq, cid in enumerate(junction.controllers):
            _sub(jel, "controller", id=cid, type="signal", sequence=seq)
    return etree.tostring(root, xml_declaration=True, encoding="UTF-8", pretty_print=True)


def lane_border_t(lanes: Sequence[LaneSpec], lane_id: int, *, outer: bool) -> float:
    """Lateral position t of a lane's inner or outer border (lanes of one side, constant widths)."""
    sign = 1.0 if lane_id > 0 else -1.0
    t = 0.0
    for lane in sorted(lanes, key=lambda ln: abs(ln.id)):
        if lane.id == lane_id:
            return sign * (t + lane.width if outer else t)
        t += lane.width
    raise KeyError(lane_id)


__all__ = [
    "Pose", "Line", "Arc", "Spiral", "Hermite", "Primitive", "advance", "connector", "RoadMark", "LaneSpec",
    "RoadLink", "SignalSpec", "RoadSpec", "ConnectionSpec", "JunctionSpec", "ControllerSpec", "MapSpec", "to_xml",
    "lane_border_t", "SOLID_YELLOW_DOUBLE", "SOLID_WHITE", "BROKEN_WHITE", "NO_MARK",
]
