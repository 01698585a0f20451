"""Map sites a sketch can be placed on: junction approaches and road segments, read from the map database (paper
§III-A.2 / §III-C: road matching is a query on the map database, `txt2sce_ros.mapdb`).

A `JunctionSite` is one junction seen from one incoming road (the AV's approach): the other legs as the sketch's
R1–R3 see them (`db.relative_approaches`), the lanes (left to right) driving into the junction and the turns each
lane can make. A `RoadSite` is a non-junction road in one direction of travel (`db.roads`). These records only
re-shape the database's answers into lane references the planner drives on; no map analysis happens here.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from ..mapdb import Control, Layout, MapDatabase, load_map_database
from ..mapdb import Approach as DbApproach
from ..road import LaneRef, RoadNetwork, load_network


@dataclass(frozen=True, slots=True)
class Approach:
    road_id: str
    lanes: tuple[LaneRef, ...]                  # driving into the junction, left to right
    turns: tuple[tuple[LaneRef, tuple[tuple[str, LaneRef], ...]], ...]   # lane -> (turn, connecting lane)
    signals: tuple[str, ...]                    # traffic-light ids controlling the approach
    stop_sign: bool
    length: float

    def lanes_turning(self, turn: str) -> list[int]:
        """Indices (0 = leftmost) of the lanes that can make `turn`."""
        out = []
        for i, ref in enumerate(self.lanes):
            conns = dict(self.turns).get(ref, ())
            if any(t == turn for t, _ in conns):
                out.append(i)
        return out

    def connection(self, index: int, turn: str) -> LaneRef | None:
        ref = self.lanes[index]
        for t, c in dict(self.turns).get(ref, ()):
            if t == turn:
                return c
        return None


@dataclass(frozen=True, slots=True)
class JunctionSite:
    map_path: str
    junction_id: str
    ego: Approach
    legs: dict = field(hash=False, compare=False)        # 'left' | 'opposite' | 'right' -> Approach
    signalised: bool = False
    kind: str = "junction4"                              # junction4 | junction3 | roundabout | junction

    def describe(self) -> dict:
        return {"kind": self.kind, "junction": self.junction_id, "ego_road": self.ego.road_id,
                "legs": {k: v.road_id for k, v in sorted(self.legs.items())}, "signalised": self.signalised}


@dataclass(frozen=True, slots=True)
class RoadSite:
    map_path: str
    road_id: str
    lanes: tuple[LaneRef, ...]          # AV-direction driving lanes, left to right
    oncoming: tuple[LaneRef, ...]       # opposite-direction driving lanes, nearest the AV's first
    length: float
    curvature: float                    # max |curvature| of the reference line, 1/m
    curb_lanes: tuple[str, ...]         # lane types right of the rightmost driving lane (biking, parking, ...)
    kind: str = "straight"              # straight | curve | parking

    def describe(self) -> dict:
        return {"kind": self.kind, "road": self.road_id, "lanes": [r.lane_id for r in self.lanes],
                "oncoming": [r.lane_id for r in self.oncoming], "length": round(self.length, 1)}


def site_network(site: JunctionSite | RoadSite) -> RoadNetwork:
    """The road model of the site's map (cached by the road package per path and mtime)."""
    return load_network(site.map_path)


def _entry_ref(net: RoadNetwork, road_id: str, lane_id: int) -> LaneRef:
    """The connecting lane where traffic enters it: its first section when it drives along +s, else its last."""
    road = net.roads[road_id]
    forward = net.lane_forward(road_id, lane_id)
    return LaneRef(road_id, 0 if forward else len(road.sections) - 1, int(lane_id))


def _approach(net: RoadNetwork, app: DbApproach) -> Approach:
    """The database's approach as lane references; turns sorted by (turn, connecting road) for a stable order."""
    road = net.roads[app.road_id]
    section = len(road.sections) - 1 if app.at_end else 0
    lanes = tuple(LaneRef(app.road_id, section, ln.lane_id) for ln in app.lanes)
    turns = []
    for ref, ln in zip(lanes, app.lanes):
        conns = [(e.turn.value, _entry_ref(net, e.connecting_road, e.connecting_lane)) for e in ln.edges
                 if e.connecting_road is not None and e.connecting_lane is not None]
        turns.append((ref, tuple(sorted(conns, key=lambda c: (c[0], c[1].road_id)))))
    lights = tuple(sorted(s for s in app.signal_ids if s in net.signals and net.signals[s].is_traffic_light))
    return Approach(app.road_id, lanes, tuple(turns), lights, app.control is Control.STOP_SIGN, road.length)


def junction_sites(path: str | Path) -> list[JunctionSite]:
    """One site per junction approach of the map (`db.junctions()`, `db.approaches`, `db.relative_approaches`)."""
    net, db = load_network(path), load_map_database(Path(path))
    out = []
    for info in sorted(db.junctions(), key=lambda j: j.id):
        for app in db.approaches(info.id):
            ego = _approach(net, app)
            legs = {name: _approach(net, other)
                    for name, other in db.relative_approaches(info.id, app.road_id).items() if other is not None}
            signalised = app.control is Control.SIGNAL and bool(ego.signals)
            out.append(JunctionSite(str(path), info.id, ego, legs, signalised, info.layout.value))
    return out


def road_sites(path: str | Path, *, min_length: float = 80.0) -> list[RoadSite]:
    """One site per non-junction road and direction of travel (`db.roads()`), on roads of one lane section (lane
    ids are stable along them) at least `min_length` m long."""
    db: MapDatabase = load_map_database(Path(path))
    out = []
    for m in sorted(db.roads(), key=lambda m: (m.road_id, not m.forward)):
        seg = m.segment
        if seg.length < min_length or len(seg.sections) != 1:
            continue
        same = tuple(LaneRef(seg.road_id, 0, lid) for lid in m.lanes)
        other = tuple(LaneRef(seg.road_id, 0, lid) for lid in m.oncoming)
        if other and (abs(other[0].lane_id) != 1 or abs(same[0].lane_id) != 1):
            other = ()  # a median or other lanes between: no oncoming lane *beside* the AV
        kind = next((k.value for k in (Layout.PARKING, Layout.CURVE, Layout.STRAIGHT) if k in seg.layouts),
                    "straight")
        out.append(RoadSite(str(path), seg.road_id, same, other, seg.length, seg.max_curvature, m.right_side, kind))
    return out
