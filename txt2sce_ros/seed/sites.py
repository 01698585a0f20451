"""Map sites a sketch can be placed on, read from the road model: junction approaches and road segments.

A `JunctionSite` is one junction seen from one incoming road (the AV's approach): the other legs classified as
left / opposite / right by their approach headings, the lanes (left to right) driving into the junction and the
turns each lane can make. A `RoadSite` is a non-junction road in one direction of travel.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path

import numpy as np

from ..road import LaneRef, RoadNetwork, load_network


def _wrap(a: float) -> float:
    return math.atan2(math.sin(a), math.cos(a))


@dataclass(frozen=True, slots=True)
class Approach:
    road_id: str
    lanes: tuple[LaneRef, ...]                  # driving into the junction, left to right
    heading: float                              # travel heading at the junction entry
    turns: tuple[tuple[LaneRef, tuple[tuple[str, LaneRef], ...]], ...]   # lane -> (turn, connecting lane)
    signals: tuple[str, ...]                    # dynamic signal ids on this road
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
    kind: str = "junction4"                              # junction4 | junction3 | roundabout

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


def _sorted_left_to_right(net: RoadNetwork, refs: list[LaneRef], s: float) -> list[LaneRef]:
    if not refs:
        return []
    forward = net.lane_forward(refs[0].road_id, refs[0].lane_id, s)
    return sorted(refs, key=lambda r: -r.lane_id if not forward else r.lane_id, reverse=True) if forward else \
        sorted(refs, key=lambda r: r.lane_id)


def _approach(net: RoadNetwork, junction_id: str, road_id: str) -> Approach | None:
    road = net.roads[road_id]
    at_end = road.successor is not None and road.successor.element_type == "junction" and \
        road.successor.element_id == junction_id
    s_j = road.length - 0.01 if at_end else 0.01
    si = road.section_index(s_j)
    lanes = []
    for lid in net.lane_ids(road_id, s_j):
        forward = net.lane_forward(road_id, lid, s_j)
        if forward == at_end:  # drives toward the junction
            lanes.append(LaneRef(road_id, si, lid))
    lanes = _sorted_left_to_right(net, lanes, s_j)
    if not lanes:
        return None
    turns = []
    for ref in lanes:
        conns = []
        for nxt in net.successors(ref):
            if net.roads[nxt.road_id].in_junction and net.roads[nxt.road_id].junction == junction_id:
                conns.append((net.turn_type(ref, nxt), nxt))
        turns.append((ref, tuple(sorted(conns, key=lambda c: (c[0], c[1].road_id)))))
    _, _, h = net.lane_to_world(road_id, lanes[0].lane_id, s_j)
    sigs = tuple(sorted(sg.id for sg in road.signals if sg.is_traffic_light))
    stop = any(sg.type in ("206", "294") for sg in road.signals)
    return Approach(road_id, tuple(lanes), h, tuple(turns), sigs, stop, road.length)


@lru_cache(maxsize=64)
def _net(path: str) -> RoadNetwork:
    return load_network(path)


def _map_db(path: str | Path):
    """The map database (paper §III-A.2) of a file: its layout and control classification is what road matching
    filters on. None when it cannot be built (the road model's own reading is used then)."""
    try:
        from ..mapdb import load_map_database

        return load_map_database(Path(path))
    except Exception:  # noqa: BLE001 - the database is an accelerator and classifier, never a hard dependency
        return None


def junction_sites(path: str | Path) -> list[JunctionSite]:
    net = _net(str(path))
    out = []
    db = _map_db(path)
    ring_junctions = _roundabout_junctions(net)
    for jid in sorted(net.junctions):
        j = net.junctions[jid]
        incoming = sorted({c.incoming_road for c in j.connections if not net.roads[c.incoming_road].in_junction})
        approaches = {rid: a for rid in incoming if (a := _approach(net, jid, rid)) is not None}
        kind = "roundabout" if jid in ring_junctions else ("junction4" if len(approaches) >= 4 else "junction3")
        for rid, a in approaches.items():
            legs = {}
            for other, b in approaches.items():
                if other == rid:
                    continue
                rel = math.degrees(_wrap(b.heading - a.heading))
                name = "opposite" if abs(rel) > 135 else ("left" if rel < 0 else "right") if abs(rel) > 45 else None
                if name and name not in legs:
                    legs[name] = b
            signalised = bool(a.signals)
            site_kind = kind
            if db is not None and jid in db.junction_infos:
                site_kind = db.junction_infos[jid].layout.value
                try:
                    control = db.approach(jid, rid).control.value
                    signalised = control == "signal" and bool(a.signals)
                    if control == "stop_sign" and not a.stop_sign:
                        a = Approach(a.road_id, a.lanes, a.heading, a.turns, a.signals, True, a.length)
                except Exception:  # noqa: BLE001 - an approach the database did not list keeps the road reading
                    pass
            out.append(JunctionSite(str(path), jid, a, legs, signalised, site_kind))
    return out


def _roundabout_junctions(net: RoadNetwork) -> set[str]:
    """Junctions whose incoming roads include a curved non-junction road linking two junctions (a ring arc)."""
    out = set()
    for road in net.roads.values():
        if road.in_junction:
            continue
        p, s = road.predecessor, road.successor
        if p and s and p.element_type == "junction" and s.element_type == "junction":
            k = abs(float(np.asarray(road.plan_view.curvature(road.length / 2)).ravel()[0]))
            if k > 1e-3:
                out.update({p.element_id, s.element_id})
    return out


def road_sites(path: str | Path, *, min_length: float = 80.0) -> list[RoadSite]:
    net = _net(str(path))
    out = []
    db = _map_db(path)
    import numpy as np

    for rid in sorted(net.roads):
        road = net.roads[rid]
        if road.in_junction or road.length < min_length:
            continue
        s_mid = road.length / 2
        if road.section_index(0.0) != road.section_index(road.length - 0.01):
            continue  # keep to single-section roads: lane ids are stable along them
        ids = net.lane_ids(rid, s_mid)
        curv = float(np.max(np.abs(road.plan_view.curvature(np.linspace(0, road.length, 64)))))
        for forward in (True, False):
            same = [LaneRef(rid, 0, lid) for lid in ids if net.lane_forward(rid, lid, s_mid) == forward]
            other = [LaneRef(rid, 0, lid) for lid in ids if net.lane_forward(rid, lid, s_mid) != forward]
            if not same:
                continue
            same = _sorted_left_to_right(net, same, s_mid)
            other = sorted(other, key=lambda r: abs(r.lane_id))
            if other and (abs(other[0].lane_id) != 1 or abs(same[0].lane_id) != 1):
                other = []  # a median or other lanes between: no oncoming lane *beside* the AV
            right = same[-1].lane_id
            step = -1 if right < 0 else 1
            curb = []
            lid = right + step
            all_ids = net.lane_ids(rid, s_mid, types=None)
            while lid in all_ids:
                curb.append(net.lane_type(rid, lid, s_mid))
                lid += step
            kind = "parking" if road.road_type == "lowSpeed" or "parking" in road.name else (
                "curve" if curv > 1.0 / 400.0 else "straight")
            if db is not None and rid in db.segments:
                layouts = {lay.value for lay in db.segments[rid].layouts}
                kind = next((k for k in ("parking", "curve", "straight") if k in layouts), kind)
            out.append(RoadSite(str(path), rid, tuple(same), tuple(other), road.length, curv, tuple(curb), kind))
    return out
