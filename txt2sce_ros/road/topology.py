"""Lane topology: neighbours, successors/predecessors across sections, roads and junctions, the lane-level
routing graph, routes and turn types.

Successors are derived once for every lane of the network, in each lane's driving direction, and predecessors are
the inverse of that relation, so the two can never disagree. A lane leaves its section at the section end if it
drives along +s, else at the section start; it then follows, in order: the next section of the same road (lane link,
or the same id when the lane has no link at all — many generated maps omit it), the linked road (lane link), or
the junction's connections whose incoming road is this road and whose connecting road touches it.
"""

from __future__ import annotations

import heapq
import itertools
import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from ..errors import InputError
from .model import LaneRef, Road, RoadLink

if TYPE_CHECKING:   # pragma: no cover
    import networkx as nx

    from .network import RoadNetwork

#: Lane types a vehicle may drive on and route through (OpenDRIVE 1.4–1.7 names).
DRIVABLE_TYPES = frozenset({"driving", "entry", "exit", "onRamp", "offRamp", "connectingRamp", "bidirectional",
                            "slipLane"})
#: Routing cost of one lane change (m): a change is preferred over a detour longer than this.
LANE_CHANGE_COST = 5.0
#: Turn classification thresholds on the heading change across a junction (degrees).
STRAIGHT_MAX_DEG = 30.0
UTURN_MIN_DEG = 150.0


def _cache(net: "RoadNetwork") -> dict:
    return net._topology_cache


def _all_refs(net: "RoadNetwork") -> list[LaneRef]:
    return [LaneRef(rid, si, lid) for rid, road in net.roads.items() for si, sec in enumerate(road.sections)
            for lid in sec.lanes if lid != 0]


def _forward(net: "RoadNetwork", ref: LaneRef) -> bool:
    road = net.roads[ref.road_id]
    return net.lane_forward(ref.road_id, ref.lane_id, road.sections[ref.section].s)


def _entry_section(road: Road, contact: str) -> int:
    return 0 if contact == "start" else len(road.sections) - 1


def _lane_if_exists(net: "RoadNetwork", road_id: str, section: int, lane_id: int | None) -> LaneRef | None:
    if lane_id is None or lane_id == 0:
        return None
    road = net.roads.get(road_id)
    if road is None or not (0 <= section < len(road.sections)) or lane_id not in road.sections[section].lanes:
        return None
    return LaneRef(road_id, section, lane_id)


def _contact_of(link: RoadLink, other: Road, this_id: str) -> str:
    """Contact point on `other` for a road link; inferred from the other road's links when the map omits it."""
    if link.contact_point in ("start", "end"):
        return link.contact_point
    if other.predecessor and other.predecessor.element_id == this_id:
        return "start"
    return "end" if other.successor and other.successor.element_id == this_id else "start"


def _drives_away(net: "RoadNetwork", ref: LaneRef | None, contact: str) -> LaneRef | None:
    """`ref` if traffic in it drives away from the road end `contact` (a lane link into a lane that drives
    towards the shared end would be a wrong-way move, not a successor)."""
    if ref is None:
        return None
    return ref if _forward(net, ref) == (contact == "start") else None


def _raw_successors(net: "RoadNetwork", ref: LaneRef) -> list[LaneRef]:
    road = net.roads[ref.road_id]
    sec = road.sections[ref.section]
    lane = sec.lanes[ref.lane_id]
    forward = _forward(net, ref)
    linked_id = lane.link.successor if forward else lane.link.predecessor
    no_link = lane.link.successor is None and lane.link.predecessor is None
    # 1. next section of the same road
    nxt = ref.section + (1 if forward else -1)
    if 0 <= nxt < len(road.sections):
        # Links may be declared on either side of the boundary: this lane's successor, or the next lane's
        # predecessor pointing back at it.
        back_side = "predecessor" if forward else "successor"
        targets = {linked_id} if linked_id is not None else set()
        targets |= {lid for lid, ln in road.sections[nxt].lanes.items()
                    if lid != 0 and getattr(ln.link, back_side) == ref.lane_id}
        if not targets and no_link:
            targets = {ref.lane_id}
        hits = [_lane_if_exists(net, road.id, nxt, t) for t in sorted(targets)]
        return [h for h in hits if h is not None]
    # 2. the linked road or junction at this end of the road
    link = road.successor if forward else road.predecessor
    if link is None:
        return []
    if link.element_type == "road":
        other = net.roads.get(link.element_id)
        if other is None:
            return []
        contact = _contact_of(link, other, road.id)
        entry = _entry_section(other, contact)
        targets = {linked_id} if linked_id is not None else set()
        other_link = other.predecessor if contact == "start" else other.successor
        if other_link is not None and other_link.element_type == "road" and other_link.element_id == road.id:
            back_side = "predecessor" if contact == "start" else "successor"
            targets |= {lid for lid, ln in other.sections[entry].lanes.items()
                        if lid != 0 and getattr(ln.link, back_side) == ref.lane_id}
        if not targets and no_link:
            # No lane links anywhere: keep the lane's side of the road; roads meeting end to end (or start to
            # start) run in opposite directions, so the side's sign flips.
            same_way = (contact == "start") == (link is road.successor)
            targets = {ref.lane_id if same_way else -ref.lane_id}
        hits = [_drives_away(net, _lane_if_exists(net, other.id, entry, t), contact) for t in sorted(targets)]
        return [h for h in hits if h is not None]
    junction = net.junctions.get(link.element_id)
    if junction is None:
        return []
    out: list[LaneRef] = []
    for conn in junction.connections:
        if conn.incoming_road != road.id:
            continue
        conn_road = net.roads.get(conn.connecting_road)
        if conn_road is None:
            continue
        # The connecting road must touch this road at the contact point (guards roads entering a junction twice).
        back = conn_road.predecessor if conn.contact_point == "start" else conn_road.successor
        if back is not None and back.element_type == "road" and back.element_id != road.id:
            continue
        for frm, to in conn.lane_links:
            if frm == ref.lane_id:
                hit = _drives_away(net, _lane_if_exists(net, conn_road.id, _entry_section(conn_road, conn.contact_point),
                                                        to), conn.contact_point)
                if hit and hit not in out:
                    out.append(hit)
    return out


def _relations(net: "RoadNetwork") -> tuple[dict[LaneRef, list[LaneRef]], dict[LaneRef, list[LaneRef]]]:
    cache = _cache(net)
    if "succ" not in cache:
        succ: dict[LaneRef, list[LaneRef]] = {}
        pred: dict[LaneRef, list[LaneRef]] = {}
        for ref in _all_refs(net):
            succ.setdefault(ref, [])
            pred.setdefault(ref, [])
        for ref in list(succ):
            for nxt in _raw_successors(net, ref):
                if nxt not in succ[ref]:
                    succ[ref].append(nxt)
                    pred.setdefault(nxt, []).append(ref)
        cache["succ"], cache["pred"] = succ, pred
    return cache["succ"], cache["pred"]


def _check(net: "RoadNetwork", ref: LaneRef) -> LaneRef:
    ref = LaneRef(str(ref[0]), int(ref[1]), int(ref[2]))
    road = net.roads.get(ref.road_id)
    if road is None or not (0 <= ref.section < len(road.sections)) or ref.lane_id not in road.sections[ref.section].lanes:
        raise InputError(f"no lane {ref}", source=net.source, element="lane")
    return ref


def successors(net: "RoadNetwork", ref: LaneRef) -> list[LaneRef]:
    """Lanes that follow `ref` in its driving direction (across sections, roads and junctions)."""
    return list(_relations(net)[0].get(_check(net, ref), []))


def predecessors(net: "RoadNetwork", ref: LaneRef) -> list[LaneRef]:
    return list(_relations(net)[1].get(_check(net, ref), []))


def neighbour(net: "RoadNetwork", ref: LaneRef, side: str, *, types: frozenset[str] = DRIVABLE_TYPES
              ) -> LaneRef | None:
    """The adjacent lane on `side` ('left'|'right' of the driving direction) with the same direction of travel."""
    if side not in ("left", "right"):
        raise InputError(f"side must be 'left' or 'right', not {side!r}", source=net.source)
    ref = _check(net, ref)
    sec = net.roads[ref.road_id].sections[ref.section]
    towards_plus_t = (side == "left") == _forward(net, ref)
    lid = ref.lane_id + (1 if towards_plus_t else -1)
    if lid == 0:
        lid = 1 if towards_plus_t else -1
    lane = sec.lanes.get(lid)
    if lane is None or lane.type not in types:
        return None
    other = LaneRef(ref.road_id, ref.section, lid)
    return other if _forward(net, other) == _forward(net, ref) else None


def lane_length(net: "RoadNetwork", ref: LaneRef) -> float:
    """Arc length of the lane's centre line within its section (m), cached."""
    cache = _cache(net).setdefault("length", {})
    ref = _check(net, ref)
    if ref not in cache:
        pts = net.lane_centerline(ref.road_id, ref.lane_id, ds=0.5, section=ref.section)
        cache[ref] = float(np.sum(np.hypot(np.diff(pts[:, 0]), np.diff(pts[:, 1]))))
    return cache[ref]


@dataclass(frozen=True, slots=True)
class LaneGraph:
    """The lane-level routing graph as plain dicts (no networkx: a cold process that routes need not import it).

    `succ[a][b]` and `pred[b][a]` hold the edge a -> b as (kind, weight); every dict keeps the order in which
    `build_lane_graph` added its keys, which is the order networkx keeps for the same additions, so
    `shortest_lane_path` visits neighbours as networkx's search over `routing_graph` does."""

    nodes: dict[LaneRef, dict[str, object]]          # lane -> length, road, junction, type
    succ: dict[LaneRef, dict[LaneRef, tuple[str, float]]]
    pred: dict[LaneRef, dict[LaneRef, tuple[str, float]]]


def build_lane_graph(net: "RoadNetwork") -> LaneGraph:
    """Lane-level graph over drivable lanes: 'follow' edges (weight = length of the lane left behind) and
    'change_left'/'change_right' edges between same-direction neighbours (weight LANE_CHANGE_COST)."""
    succ_rel, _ = _relations(net)
    nodes: dict[LaneRef, dict[str, object]] = {}
    for ref in succ_rel:
        road = net.roads[ref.road_id]
        lane = road.sections[ref.section].lanes[ref.lane_id]
        if lane.type in DRIVABLE_TYPES:
            nodes[ref] = {"length": lane_length(net, ref), "road": ref.road_id, "junction": road.junction,
                          "type": lane.type}
    succ: dict[LaneRef, dict[LaneRef, tuple[str, float]]] = {ref: {} for ref in nodes}
    pred: dict[LaneRef, dict[LaneRef, tuple[str, float]]] = {ref: {} for ref in nodes}

    def add(a: LaneRef, b: LaneRef, kind: str, weight: float) -> None:
        # A second edge a -> b replaces the first's data in place (its position in both dicts stays).
        succ[a][b] = pred[b][a] = (kind, weight)

    for ref in nodes:
        for nxt in succ_rel[ref]:
            if nxt in nodes:
                add(ref, nxt, "follow", nodes[ref]["length"])  # type: ignore[arg-type]
        for side in ("left", "right"):
            nb = neighbour(net, ref, side)
            if nb is not None and nb in nodes:
                add(ref, nb, f"change_{side}", LANE_CHANGE_COST)
    return LaneGraph(nodes, succ, pred)


def build_routing_graph(net: "RoadNetwork") -> nx.DiGraph:
    """`net.lane_graph` as a networkx DiGraph (edge attributes `kind` and `weight`, node attributes as there),
    nodes and edges added in the lane graph's order, for callers that want networkx's algorithms."""
    import networkx as nx   # on first use: a cold start that never asks for this graph does not pay for networkx

    lg = net.lane_graph
    g = nx.DiGraph()
    for ref, attrs in lg.nodes.items():
        g.add_node(ref, **attrs)
    for a, out in lg.succ.items():
        for b, (kind, weight) in out.items():
            g.add_edge(a, b, kind=kind, weight=weight)
    return g


def shortest_lane_path(graph: LaneGraph, start: LaneRef, goal: LaneRef, *, follow_only: bool = False
                       ) -> list[LaneRef] | None:
    """The least-weight lane sequence start -> goal (inclusive) over the graph's edges (only 'follow' edges with
    `follow_only`); None when either lane is not in the graph or no path exists.

    A bidirectional Dijkstra search that expands, alternately, the nearest unsettled lane from the start (along
    `succ`) and from the goal (along `pred`), and stops when a lane is settled from both sides, answering with the
    best meeting lane seen while relaxing. It is written to give exactly the path `networkx.shortest_path(
    routing_graph, start, goal, weight="weight")` gives, ties included (tested against it on every map): the two
    heaps order equal distances by one shared push counter, neighbours are visited in insertion order, a lane's
    tentative distance and predecessor change only on a strict improvement, and a meeting lane replaces the best
    one only when strictly shorter."""
    if start not in graph.nodes or goal not in graph.nodes:
        return None
    if start == goal:
        return [start]
    sides = (graph.succ, graph.pred)
    settled: tuple[dict[LaneRef, float], dict[LaneRef, float]] = ({}, {})
    tentative: tuple[dict[LaneRef, float], dict[LaneRef, float]] = ({start: 0.0}, {goal: 0.0})
    parent: tuple[dict[LaneRef, LaneRef | None], dict[LaneRef, LaneRef | None]] = ({start: None}, {goal: None})
    pushes = itertools.count()
    heaps: tuple[list, list] = ([(0, next(pushes), start)], [(0, next(pushes), goal)])
    best: float | None = None
    meet: LaneRef | None = None
    side = 1
    while heaps[0] and heaps[1]:
        side = 1 - side
        dist, _, lane = heapq.heappop(heaps[side])
        done = settled[side]
        if lane in done:
            continue
        done[lane] = dist
        if lane in settled[1 - side]:
            return _joined(parent, meet)
        seen, other_seen, back, heap = tentative[side], tentative[1 - side], parent[side], heaps[side]
        for nb, (kind, weight) in sides[side][lane].items():
            if follow_only and kind != "follow":
                continue
            via = dist + weight
            if nb in done:
                continue
            if nb not in seen or via < seen[nb]:
                seen[nb] = via
                heapq.heappush(heap, (via, next(pushes), nb))
                back[nb] = lane
                if nb in other_seen:
                    total = via + other_seen[nb]
                    if best is None or best > total:
                        best, meet = total, nb
    return None


def _joined(parent: tuple[dict[LaneRef, LaneRef | None], dict[LaneRef, LaneRef | None]], meet: LaneRef | None
            ) -> list[LaneRef]:
    """The path through `meet`: its forward predecessors back to the start, then its backward ones to the goal."""
    head: list[LaneRef] = []
    cur = meet
    while cur is not None:
        head.append(cur)
        cur = parent[0][cur]
    head.reverse()
    cur = parent[1][meet]  # type: ignore[index]
    while cur is not None:
        head.append(cur)
        cur = parent[1][cur]
    return head


def route(net: "RoadNetwork", start: LaneRef, goal: LaneRef) -> list[LaneRef]:
    """Shortest lane-level path from `start` to `goal` (inclusive), lane changes allowed."""
    start, goal = _check(net, start), _check(net, goal)
    graph = net.lane_graph
    for ref in (start, goal):
        if ref not in graph.nodes:
            raise InputError(f"lane {ref} is not drivable", source=net.source, element="lane")
    path = shortest_lane_path(graph, start, goal)
    if path is None:
        raise InputError(f"no route from {start} to {goal}", source=net.source, element="lane")
    return path


def lane_end_heading(net: "RoadNetwork", ref: LaneRef, at_exit: bool) -> float:
    """Driving-direction heading of a lane where traffic enters it (`at_exit=False`) or leaves it."""
    pts = net.lane_centerline(ref.road_id, ref.lane_id, ds=0.25, section=ref.section)
    a, b = (pts[-2], pts[-1]) if at_exit else (pts[0], pts[1])
    return math.atan2(b[1] - a[1], b[0] - a[0])


def turn_type(net: "RoadNetwork", incoming: LaneRef, connecting: LaneRef) -> str:
    """'straight' | 'left' | 'right' | 'uturn' from the heading change between the incoming lane's exit and the
    connecting lane's exit (thresholds STRAIGHT_MAX_DEG, UTURN_MIN_DEG)."""
    incoming, connecting = _check(net, incoming), _check(net, connecting)
    h_in = lane_end_heading(net, incoming, at_exit=True)
    h_out = lane_end_heading(net, connecting, at_exit=True)
    d = math.degrees(math.atan2(math.sin(h_out - h_in), math.cos(h_out - h_in)))
    if abs(d) <= STRAIGHT_MAX_DEG:
        return "straight"
    if abs(d) >= UTURN_MIN_DEG:
        return "uturn"
    return "left" if d > 0 else "right"
