"""Mission planning, as Autoware's mission planner does it: from the ego's pose and the goal, a lane-level route
over the road model's routing graph (networkx shortest path), turned into the reference line the controllers
follow. Replanning happens when the ego is found off the route.

Lane changes in a route (the graph's `change_left` / `change_right` edges) become a diagonal across the lane
section: the line leaves the first lane a third of the way along it and joins the next lane two thirds along.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import networkx as nx
import numpy as np

from txt2sce_ros.contract import Goal
from txt2sce_ros.errors import InputError
from txt2sce_ros.road import LaneRef, RoadNetwork

from .refline import RefLine

#: Sample spacing of the reference line (m).
DS = 0.5
#: The line runs on past the goal so the pure-pursuit look-ahead has a point to aim at near the end (m).
GOAL_EXTENSION = 30.0
#: The line starts this far behind the ego, so its projection is never clipped at the start (m).
START_BACKOFF = 10.0


@dataclass(frozen=True, slots=True)
class Route:
    lanes: tuple[LaneRef, ...]
    line: RefLine
    goal_s: float               # arc length of the goal's projection on the line


def _edge_kind(graph: nx.DiGraph, a: LaneRef, b: LaneRef) -> str:
    data = graph.get_edge_data(a, b) or {}
    for key in ("kind", "type", "edge", "label"):
        if key in data:
            return str(data[key])
    return "follow"


def _follow_only(graph: nx.DiGraph) -> nx.DiGraph:
    return nx.subgraph_view(graph, filter_edge=lambda a, b: _edge_kind(graph, a, b) == "follow")


def lane_route(net: RoadNetwork, start: LaneRef, goal: LaneRef) -> list[LaneRef]:
    """Shortest lane sequence start -> goal, preferring one without lane changes (a stand-in keeps its lane when it
    can); raises InputError when the goal cannot be reached at all."""
    graph = net.routing_graph
    try:
        return list(nx.shortest_path(_follow_only(graph), start, goal, weight="weight"))
    except (nx.NetworkXNoPath, nx.NodeNotFound):
        return net.route(start, goal)


def _lane_points(net: RoadNetwork, ref: LaneRef) -> tuple[np.ndarray, bool, np.ndarray]:
    pts = net.lane_centerline(ref.road_id, ref.lane_id, DS, section=ref.section)
    road = net.roads[ref.road_id]
    widths = np.array([net.lane_width(ref.road_id, ref.lane_id, float(s)) for s in pts[:, 2]])
    return pts, road.junction not in ("-1", ""), widths


def _extend(net: RoadNetwork, last: LaneRef, length: float) -> list[LaneRef]:
    """Lanes after the goal lane (first successor each time) covering about `length` metres."""
    out: list[LaneRef] = []
    ref, total = last, 0.0
    while total < length:
        nxt = net.successors(ref)
        if not nxt or nxt[0] in out or nxt[0] == last:
            break
        ref = nxt[0]
        out.append(ref)
        total += net.lane_length(ref)
    return out


def build_line(net: RoadNetwork, lanes: list[LaneRef], kinds: list[str]) -> tuple[RefLine, list[float]]:
    """Concatenate the lanes' centre lines (driving direction) into one reference line; `kinds[i]` is the edge
    from lanes[i] to lanes[i+1]. Also returns the arc length at which each lane starts on the line."""
    xy_parts, junction_parts, width_parts = [], [], []
    cut_start = 0.0                                    # fraction of the lane skipped at its start
    for i, ref in enumerate(lanes):
        pts, junction, widths = _lane_points(net, ref)
        n = len(pts)
        lo = int(round(cut_start * (n - 1)))
        hi = n
        cut_start = 0.0
        if i < len(kinds) and kinds[i] != "follow":
            hi = max(lo + 2, int(round((n - 1) / 3.0)) + 1)
            cut_start = 2.0 / 3.0
        xy_parts.append(pts[lo:hi, :2])
        junction_parts.append(np.full(hi - lo, junction))
        width_parts.append(widths[lo:hi])
    xy = np.vstack(xy_parts)
    starts = np.cumsum([0] + [len(p) for p in xy_parts[:-1]])
    seg = np.hypot(*np.diff(xy, axis=0).T)
    s = np.concatenate([[0.0], np.cumsum(seg)])
    line = RefLine(xy, in_junction=np.concatenate(junction_parts), lane_width=np.concatenate(width_parts),
                   lanes=tuple(lanes))
    return line, [float(s[i]) for i in starts]


def _locate(net: RoadNetwork, x: float, y: float, heading: float, what: str) -> LaneRef:
    point = net.locate(x, y, heading)
    if point is None:
        raise InputError(f"the {what} at ({x:.1f}, {y:.1f}) is on no driving lane", source=net.source,
                         element="route")
    return point.ref


def plan_route(net: RoadNetwork, x: float, y: float, heading: float, goal: Goal) -> Route:
    """Route from the pose (x, y, heading) to `goal`, with its reference line trimmed to start a little behind the
    ego and run `GOAL_EXTENSION` metres past the goal."""
    start = _locate(net, x, y, heading, "ego")
    target = _locate(net, goal.x, goal.y, goal.heading, "goal")
    lanes = lane_route(net, start, target)
    graph = net.routing_graph
    kinds = [_edge_kind(graph, a, b) for a, b in zip(lanes[:-1], lanes[1:])]
    tail = _extend(net, lanes[-1], GOAL_EXTENSION)
    full = list(lanes) + tail
    kinds += ["follow"] * len(tail)
    line, starts = build_line(net, full, kinds)
    # Each pose is projected onto its own lane's stretch of the line, so a route crossing itself (or passing the
    # goal's neighbourhood earlier) cannot confuse the two.
    first_end = starts[1] if len(starts) > 1 else line.length
    ego_s = line.project(x, y, near_s=0.5 * first_end, window=0.5 * first_end + 1.0).s
    g0 = starts[len(lanes) - 1]
    g1 = starts[len(lanes)] if len(starts) > len(lanes) else line.length
    goal_s = line.project(goal.x, goal.y, near_s=0.5 * (g0 + g1), window=0.5 * (g1 - g0) + 1.0).s
    trimmed, shift = _trim(line, max(0.0, ego_s - START_BACKOFF), min(line.length, goal_s + GOAL_EXTENSION))
    return Route(lanes=tuple(lanes), line=trimmed, goal_s=goal_s - shift)


def _trim(line: RefLine, s0: float, s1: float) -> tuple[RefLine, float]:
    """The stretch [s0, s1] of the line (to the enclosing vertices) and the arc length its new start had."""
    idx = np.flatnonzero((line.s >= s0) & (line.s <= s1))
    if len(idx) < 2:
        return line, 0.0
    lo, hi = max(idx[0] - 1, 0), min(idx[-1] + 2, len(line.s))
    return RefLine(line.xy[lo:hi], in_junction=line.in_junction[lo:hi], lane_width=line.lane_width[lo:hi],
                   lanes=line.lanes), float(line.s[lo])


def off_route(line: RefLine, x: float, y: float, heading: float, s_hint: float, max_offset: float) -> bool:
    """True when the pose is too far from the line, or heads against it, to keep following it."""
    pp = line.project(x, y, near_s=s_hint)
    if abs(pp.offset) > max_offset:
        return True
    dh = abs(math.remainder(heading - pp.heading, 2.0 * math.pi))
    return dh > 0.5 * math.pi
