"""The map database (paper §III-A.2): a networkx graph over the road model, and the queries road matching uses.

Nodes are the roads outside junctions (segments), with name, length, lane ids, lane types, driving directions and
lane-change permissions as attributes. Directed edges are lane-level connections from one segment to the next:
through a junction (with the connecting road, junction id, start/end lane ids, turn type from geometry and the
traffic light controlling the movement) or by a direct road link. Connecting roads are kept as `Segment` records
too (`MapDatabase.segments`), flagged `is_connecting`.
"""

from __future__ import annotations

import hashlib
import math
from collections import defaultdict
from dataclasses import replace
from pathlib import Path
from typing import Any

import networkx as nx
import numpy as np

from ..road import LaneRef, Road, RoadNetwork
from . import classify
from .marks import MarkTable, crossing_allowed, read_marks
from .query import MapQueries
from .records import (Approach, ApproachLane, ConnectionEdge, Control, JunctionInfo, LaneInfo, Layout, SectionInfo,
                      Segment, Turn)


class MapDatabase(MapQueries):
    """The graph and its typed records. Build with `build_map_database(net)` or `load_map_database(path)`."""

    def __init__(self, *, source: str, sha256: str, graph: nx.MultiDiGraph, segments: dict[str, Segment],
                 edges: tuple[ConnectionEdge, ...], junction_infos: dict[str, JunctionInfo],
                 approach_map: dict[str, tuple[Approach, ...]], notes: tuple[str, ...] = ()) -> None:
        self.source = source
        self.sha256 = sha256
        self.graph = graph
        self.segments = segments
        self.edges = edges
        self.junction_infos = junction_infos
        self.approach_map = approach_map
        self.notes = notes           # what the builder skipped, and why (inconsistent lane links, ...)
        self.from_cache = False      # set by `load_map_database` when the graph came from the disk cache

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, MapDatabase):
            return NotImplemented
        return (self.sha256 == other.sha256 and self.segments == other.segments and self.edges == other.edges
                and self.junction_infos == other.junction_infos and self.approach_map == other.approach_map
                and nx.utils.graphs_equal(self.graph, other.graph))

    __hash__ = None  # type: ignore[assignment]

    def to_json(self) -> dict[str, Any]:
        """The graph as node-link JSON (the paper kept it in Neo4j; this loads into any graph store), plus the
        junction records. Plain types only, deterministic order."""
        graph = nx.node_link_data(self.graph, edges="edges")
        junctions = []
        for jid in sorted(self.junction_infos, key=lambda r: (len(r), r)):
            info = self.junction_infos[jid]
            junctions.append({
                "id": info.id, "name": info.name, "layout": info.layout.value, "control": info.control.value,
                "legs": info.legs, "leg_roads": list(info.leg_roads), "x": info.x, "y": info.y,
                "approaches": [{"road": a.road_id, "control": a.control.value, "heading": a.heading,
                                "lanes": [{"id": ln.lane_id, "turns": sorted(t.value for t in ln.turns)}
                                          for ln in a.lanes]} for a in self.approach_map.get(jid, ())],
            })
        return {"source": self.source, "sha256": self.sha256, "graph": graph, "junctions": junctions}

    def __repr__(self) -> str:
        return (f"MapDatabase({self.source!r}, segments={self.graph.number_of_nodes()}, "
                f"connections={len(self.edges)}, junctions={len(self.junction_infos)})")


# --------------------------------------------------------------------------------------------- segments


def _section_infos(net: RoadNetwork, road: Road, marks: MarkTable) -> tuple[SectionInfo, ...]:
    out = []
    for si, sec in enumerate(road.sections):
        end = min(sec.end if sec.end > sec.s else road.length, road.length)
        mid = 0.5 * (sec.s + end)
        borders = sec.borders_t(np.array([mid]), net.lane_offset(road.id, np.array([mid])))
        ids = sorted((i for i in sec.lanes if i != 0), reverse=True)
        forward = {i: net.lane_forward(road.id, i, mid) for i in ids}
        lanes = []
        for lid in ids:
            inner = borders[lid - 1 if lid > 0 else lid + 1] if abs(lid) > 1 else borders[0]
            width = float(abs(borders[lid][0] - inner[0]))
            lane = sec.lanes[lid]
            change = {}
            for side in ("left", "right"):
                plus_t = (side == "left") == forward[lid]  # left of travel is +t for lanes driving along +s
                nid = lid + 1 if plus_t else lid - 1
                nid = nid + (1 if plus_t else -1) if nid == 0 else nid
                ok = (lane.type == "driving" and nid in sec.lanes and sec.lanes[nid].type == "driving"
                      and forward[nid] == forward[lid])
                if ok:
                    permitted = crossing_allowed(marks, road.id, si, lid, plus_t)
                    ok = True if permitted is None else permitted
                change[side] = ok
            lanes.append(LaneInfo(lid, lane.type, round(width, 4), forward[lid], change["left"], change["right"]))
        out.append(SectionInfo(si, float(sec.s), float(end), tuple(lanes)))
    return tuple(out)


def _segment(net: RoadNetwork, road: Road, marks: MarkTable) -> tuple[Segment, float]:
    sections = _section_infos(net, road, marks)
    max_k, turn, abs_turn = classify.curvature_profile(road)
    main = max(sections, key=lambda sec: (sec.length, -sec.index))
    fwd, bwd = len(main.driving(True)), len(main.driving(False))
    layouts = frozenset() if road.in_junction else frozenset(classify.road_layouts(road, main, max_k, abs_turn))

    def junction_of(link: object) -> str | None:
        return link.element_id if link is not None and link.element_type == "junction" else None  # type: ignore

    seg = Segment(road_id=road.id, name=road.name, length=float(road.length), junction_id=road.junction,
                  sections=sections, layouts=layouts, one_way=(fwd + bwd > 0 and min(fwd, bwd) == 0),
                  lanes_forward=fwd, lanes_backward=bwd, max_curvature=round(max_k, 6),
                  heading_change=round(turn, 6), predecessor_junction=junction_of(road.predecessor),
                  successor_junction=junction_of(road.successor), speed_limit=road.speed_limit)
    return seg, abs_turn


# --------------------------------------------------------------------------------------------- connections


def _turn(net: RoadNetwork, inc: LaneRef, conn: LaneRef) -> Turn:
    """Turn type from geometry: the road model compares the incoming lane's and the connecting lane's exit
    headings."""
    return Turn(net.turn_type(inc, conn))


def _follow(road: Road, lane_id: int, from_start: bool) -> tuple[int | None, int, int | None]:
    """Follow a lane through a road's sections from one end to the other.

    Returns (the lane link at the far end, i.e. the lane id on the next road; the far section index; the lane's
    id in that far section), with None where a link is missing.
    """
    order = range(len(road.sections)) if from_start else range(len(road.sections) - 1, -1, -1)
    lid: int | None = lane_id
    last, last_id = order[0], lane_id
    for si in order:
        lane = road.sections[si].lanes.get(lid) if lid is not None else None
        if lane is None:
            return None, last, None
        last, last_id = si, lid
        lid = lane.link.successor if from_start else lane.link.predecessor
    return lid, last, last_id


def _traffic_light(road: Road, lane_id: int, at_end: bool) -> tuple[tuple[float, float] | None, str | None]:
    """The traffic light on `road` controlling `lane_id`, nearest the junction end."""
    best = None
    end_s = road.length if at_end else 0.0
    for sig in road.signals:
        if sig.is_traffic_light and lane_id in sig.controlled_lanes and abs(sig.s - end_s) <= classify.CONTROL_RANGE:
            if best is None or abs(sig.s - end_s) < abs(best.s - end_s):
                best = sig
    return ((round(best.x, 3), round(best.y, 3)), best.id) if best else (None, None)


def _touches(road: Road, jid: str) -> tuple[bool, bool]:
    """(road's end touches junction jid, road's start touches it)."""
    def hit(link: object) -> bool:
        return link is not None and link.element_type == "junction" and link.element_id == jid  # type: ignore

    return hit(road.successor), hit(road.predecessor)


def _is_driving(road: Road, section: int, lane_id: int | None) -> bool:
    lane = road.sections[section].lanes.get(lane_id) if lane_id is not None else None
    return lane is not None and lane.type == "driving"


class _EdgeBuilder:
    """Turns junction connections into lane-level edges, in whichever direction the lanes actually drive.

    Maps list a connection from the road traffic comes from; some (esmini's parking_demo) list two-way connecting
    roads once, with lane links for both directions, so a link whose incoming lane drives away from the junction
    is read backwards. Duplicates from maps that list both directions are dropped.
    """

    def __init__(self, net: RoadNetwork, notes: list[str]) -> None:
        self.net, self.notes = net, notes
        self.edges: dict[tuple, ConnectionEdge] = {}

    def add(self, jid: str, conn_id: str, inc: Road, con: Road, contact_start: bool, from_lane: int,
            con_lane: int) -> None:
        net = self.net
        at_end, at_start = _touches(inc, jid)
        sec_inc = len(inc.sections) - 1 if at_end else 0
        if at_end and at_start:  # both ends on this junction: the lane's direction decides
            sec_inc = len(inc.sections) - 1 if net.lane_forward(inc.id, from_lane) else 0
        if from_lane not in inc.sections[sec_inc].lanes:
            self.notes.append(f"junction {jid} connection {conn_id}: road {inc.id} has no lane {from_lane}")
            return
        if not _is_driving(inc, sec_inc, from_lane):
            return  # sidewalks and borders are linked too by some maps; only driving lanes carry traffic
        forward = net.lane_forward(inc.id, from_lane, inc.sections[sec_inc].s)
        into = forward == (sec_inc == len(inc.sections) - 1 and at_end)
        if not con.in_junction:
            # A direct junction (OpenDRIVE 1.7 `linkedRoad`): lanes continue straight into the linked road.
            src, dst = (inc, con) if into else (con, inc)
            a, b = (from_lane, con_lane) if into else (con_lane, from_lane)
            self._put(ConnectionEdge(src.id, dst.id, a, b, None, None, jid, Turn.STRAIGHT, None, None))
            return
        sec_con = 0 if contact_start else len(con.sections) - 1
        if con_lane not in con.sections[sec_con].lanes:
            self.notes.append(f"junction {jid} connection {conn_id}: connecting road {con.id} has no lane "
                              f"{con_lane}; link skipped")
            return
        far_link = con.successor if contact_start else con.predecessor
        if far_link is None or far_link.element_type != "road" or far_link.element_id not in net.roads:
            self.notes.append(f"junction {jid} connection {conn_id}: connecting road {con.id} leads nowhere")
            return
        far = net.roads[far_link.element_id]
        far_lane, far_sec, far_con_lane = _follow(con, con_lane, contact_start)
        if into:
            turn = _turn(net, LaneRef(inc.id, sec_inc, from_lane), LaneRef(con.id, sec_con, con_lane))
            edge = ConnectionEdge(inc.id, far.id, int(from_lane), None if far_lane is None else int(far_lane),
                                  con.id, int(con_lane), jid, turn, *self._light(inc, from_lane, sec_inc, con,
                                                                                   con_lane, not contact_start))
        else:
            if far_lane is None or far_con_lane is None:
                self.notes.append(f"junction {jid} connection {conn_id}: lane {from_lane} of road {inc.id} leaves "
                                  f"the junction and connecting lane {con_lane} has no link back; skipped")
                return
            far_at_end, _ = _touches(far, jid)
            far_sec_idx = len(far.sections) - 1 if far_at_end else 0
            if far_lane not in far.sections[far_sec_idx].lanes or not _is_driving(far, far_sec_idx, far_lane):
                return
            turn = _turn(net, LaneRef(far.id, far_sec_idx, far_lane), LaneRef(con.id, far_sec, far_con_lane))
            edge = ConnectionEdge(far.id, inc.id, int(far_lane), int(from_lane), con.id, int(far_con_lane), jid,
                                  turn, *self._light(far, far_lane, far_sec_idx, con, far_con_lane, contact_start))
        if edge.from_road == edge.to_road and edge.turn is not Turn.UTURN:
            edge = replace(edge, turn=Turn.UTURN)  # back onto the road it came from
        self._put(edge)

    def _light(self, inc: Road, lane: int, sec: int, con: Road, con_lane: int, con_entry_at_end: bool
               ) -> tuple[tuple[float, float] | None, str | None]:
        """The light on the incoming road at the junction, else one on the connecting road near its entry."""
        light = _traffic_light(inc, lane, sec == len(inc.sections) - 1)
        return light if light[0] is not None else _traffic_light(con, con_lane, con_entry_at_end)

    def _put(self, edge: ConnectionEdge) -> None:
        self.edges.setdefault((edge.from_road, edge.from_lane, edge.connecting_road, edge.connecting_lane,
                               edge.to_road), edge)


def _junction_edges(net: RoadNetwork, notes: list[str]) -> list[ConnectionEdge]:
    builder = _EdgeBuilder(net, notes)
    for jid, junction in net.junctions.items():
        for conn in junction.connections:
            inc, con = net.roads.get(conn.incoming_road), net.roads.get(conn.connecting_road)
            if inc is None or con is None:
                notes.append(f"junction {jid} connection {conn.id}: unknown road")
                continue
            for from_lane, con_lane in conn.lane_links:
                builder.add(jid, conn.id, inc, con, conn.contact_point != "end", int(from_lane), int(con_lane))
    return list(builder.edges.values())


def _direct_edges(net: RoadNetwork) -> list[ConnectionEdge]:
    """Lane continuations between two roads outside junctions (a road's successor/predecessor is a road)."""
    edges = []
    for road in net.roads.values():
        if road.in_junction:
            continue
        for at_end, link in ((True, road.successor), (False, road.predecessor)):
            if link is None or link.element_type != "road":
                continue
            other = net.roads.get(link.element_id)
            if other is None or other.in_junction:
                continue
            sec = road.sections[-1] if at_end else road.sections[0]
            for lid, lane in sec.lanes.items():
                if lid == 0 or lane.type != "driving" or net.lane_forward(road.id, lid, sec.s) != at_end:
                    continue
                to_lane = lane.link.successor if at_end else lane.link.predecessor
                if to_lane is None:
                    continue
                edges.append(ConnectionEdge(road.id, other.id, int(lid), int(to_lane), None, None, "-1",
                                            Turn.STRAIGHT, None, None))
    return edges


# --------------------------------------------------------------------------------------------- junctions


def _approaches(net: RoadNetwork, segments: dict[str, Segment], edges: list[ConnectionEdge]
                ) -> dict[str, tuple[Approach, ...]]:
    by_jr: dict[tuple[str, str], list[ConnectionEdge]] = defaultdict(list)
    for e in edges:
        if e.junction_id != "-1":
            by_jr[(e.junction_id, e.from_road)].append(e)
    out: dict[str, list[Approach]] = defaultdict(list)
    for (jid, rid), group in sorted(by_jr.items()):
        road, seg = net.roads[rid], segments[rid]
        at_end = seg.successor_junction == jid
        if seg.successor_junction == jid and seg.predecessor_junction == jid:
            at_end = net.lane_forward(rid, group[0].from_lane)
        section = seg.sections[-1] if at_end else seg.sections[0]
        drive = section.driving(at_end)
        lanes = []
        for k, lane in enumerate(drive):
            mine = tuple(e for e in group if e.from_lane == lane.id)
            lanes.append(ApproachLane(lane.id, k, frozenset(e.turn for e in mine), mine, k > 0, k < len(drive) - 1))
        s_stop = road.length if at_end else 0.0
        x, y, h = net.road_to_world(rid, s_stop)
        heading = h if at_end else h + math.pi
        heading = math.atan2(math.sin(heading), math.cos(heading))
        sigs = classify.approach_signals(net, road, at_end, [ln.id for ln in drive])
        control = Control.SIGNAL if any(e.traffic_light for e in group) else classify.signal_control(sigs)
        ids = sorted({s.id for s in sigs} | {e.signal_id for e in group if e.signal_id})
        out[jid].append(Approach(jid, rid, at_end, float(s_stop), round(x, 3), round(y, 3), round(heading, 6),
                                 tuple(lanes), control, tuple(ids), len(section.driving(not at_end))))
    return {jid: tuple(v) for jid, v in out.items()}


def _junction_infos(net: RoadNetwork, segments: dict[str, Segment], approach_map: dict[str, tuple[Approach, ...]], ring: set[str]) -> dict[str, JunctionInfo]:
    infos = {}
    for jid, junction in net.junctions.items():
        legs = sorted({rid for rid, seg in segments.items() if not seg.is_connecting
                       and jid in (seg.predecessor_junction, seg.successor_junction)},
                      key=lambda r: (len(r), r))
        points, headings = [], []
        for rid in legs:
            seg = segments[rid]
            at_end = seg.successor_junction == jid
            s = seg.length if at_end else 0.0
            x, y, h = net.road_to_world(rid, s)
            points.append((x, y))
            h = h if at_end else h + math.pi  # the direction of travel toward the junction along this road
            headings.append((rid, round(math.atan2(math.sin(h), math.cos(h)), 6)))
        cx, cy = (float(np.mean([p[0] for p in points])), float(np.mean([p[1] for p in points]))) if points \
            else (0.0, 0.0)
        bearings = [math.atan2(py - cy, px - cx) for px, py in points if math.hypot(px - cx, py - cy) > 0.5]
        n_legs = classify.count_legs(bearings)
        name = junction.name.lower()
        if any(r in ring for r in legs) or "roundabout" in name or "circle" in name:
            layout = Layout.ROUNDABOUT
        else:
            layout = {4: Layout.JUNCTION4, 3: Layout.JUNCTION3}.get(n_legs, Layout.JUNCTION)
        approaches = approach_map.get(jid, ())
        controls = {a.control for a in approaches}
        control = next((c for c in (Control.SIGNAL, Control.STOP_SIGN) if c in controls), Control.NONE)
        infos[jid] = JunctionInfo(jid, junction.name, layout, control, n_legs, tuple(legs), tuple(headings),
                                  tuple(a.road_id for a in approaches),
                                  tuple(sorted({c.connecting_road for c in junction.connections},
                                               key=lambda r: (len(r), r))),
                                  tuple(junction.controllers), round(cx, 3), round(cy, 3))
    return infos


# --------------------------------------------------------------------------------------------- build


def build_map_database(network: RoadNetwork, *, xodr_bytes: bytes | None = None, sha256: str = "",
                       use_marks: bool = True) -> MapDatabase:
    """Build the map database of a loaded road network.

    Lane-change permissions follow the road marks, read from `xodr_bytes` (the file's content) or else from
    `network.source` when that is a file (the road model does not keep marks). With `use_marks=False`, or with
    no file to read, a change is allowed between any two adjacent same-direction driving lanes. `sha256` names
    the content (computed from the bytes when not given).
    """
    if xodr_bytes is None and use_marks and Path(network.source).is_file():
        xodr_bytes = Path(network.source).read_bytes()
    if not sha256 and xodr_bytes:
        sha256 = hashlib.sha256(xodr_bytes).hexdigest()
    marks = read_marks(xodr_bytes, network.source) if (xodr_bytes and use_marks) else {}
    notes: list[str] = []
    segments: dict[str, Segment] = {}
    abs_turns: dict[str, float] = {}
    for rid, road in _roads_sorted(network):
        segments[rid], abs_turns[rid] = _segment(network, road, marks)
    edges = _junction_edges(network, notes) + _direct_edges(network)

    graph = nx.MultiDiGraph(source=network.source)
    for rid, seg in segments.items():
        if seg.is_connecting:
            continue
        main = seg.main_section
        graph.add_node(rid, name=seg.name, length=seg.length, lane_ids=[ln.id for ln in main.lanes],
                       lane_types=[ln.type for ln in main.lanes],
                       lane_directions=[ln.direction for ln in main.lanes],
                       lane_change=[(ln.change_left, ln.change_right) for ln in main.lanes],
                       layouts=sorted(t.value for t in seg.layouts), one_way=seg.one_way,
                       heading_change=seg.heading_change)
    for e in edges:
        if e.from_road in graph and e.to_road in graph:
            graph.add_edge(e.from_road, e.to_road, key=e.key, connecting_road=e.connecting_road,
                           junction_id=e.junction_id, start_lane_id=e.from_lane, end_lane_id=e.to_lane,
                           connecting_lane_id=e.connecting_lane, turn_type=e.turn.value,
                           traffic_light_x=e.traffic_light[0] if e.traffic_light else None,
                           traffic_light_y=e.traffic_light[1] if e.traffic_light else None, signal_id=e.signal_id)

    ring_like = {rid for rid, seg in segments.items() if not seg.is_connecting and seg.one_way
                 and abs(seg.heading_change) >= classify.CURVE_MIN_TURN
                 and abs(seg.heading_change) >= 0.9 * abs_turns[rid]}
    ring = classify.roundabout_roads(graph, ring_like,
                                     {rid: seg.heading_change for rid, seg in segments.items()})
    for rid in ring:
        seg = segments[rid]
        segments[rid] = _with_layouts(seg, seg.layouts | {Layout.ROUNDABOUT})
        graph.nodes[rid]["layouts"] = sorted(t.value for t in segments[rid].layouts)

    approach_map = _approaches(network, segments, edges)
    infos = _junction_infos(network, segments, approach_map, ring)
    for jid, info in infos.items():  # connecting roads carry their junction's layout
        for rid in info.connecting_roads:
            if rid in segments:
                segments[rid] = _with_layouts(segments[rid], frozenset({info.layout}))
    return MapDatabase(source=network.source, sha256=sha256, graph=graph, segments=segments, edges=tuple(edges),
                       junction_infos=infos, approach_map=approach_map, notes=tuple(notes))


def _roads_sorted(network: RoadNetwork) -> list[tuple[str, Road]]:
    """Roads in a stable order (numeric ids numerically), so graphs and summaries do not depend on file order."""
    return sorted(network.roads.items(), key=lambda kv: (len(kv[0]), kv[0]))


def _with_layouts(seg: Segment, layouts: frozenset[Layout]) -> Segment:
    return replace(seg, layouts=frozenset(layouts))
