"""Mission planning, as Autoware's mission planner does it: from the ego's pose and the goal, a lane-level route
over the road model's lane graph (`topology.shortest_lane_path`), turned into the reference line the controllers
follow. Replanning happens when the ego is found off the route.

Lane changes in a route (the graph's `change_left` / `change_right` edges) are blended into the line: it leaves
the first lane a few metres ahead of the ego and joins the target lane over 30 m per lane crossed.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from txt2sce_ros.contract import Goal
from txt2sce_ros.errors import InputError
from txt2sce_ros.road import LaneRef, RoadNetwork
from txt2sce_ros.road.topology import shortest_lane_path

from .refline import RefLine

#: Sample spacing of the reference line (m).
DS = 0.5
#: The line runs on past the goal so the pure-pursuit look-ahead has a point to aim at near the end (m).
GOAL_EXTENSION = 30.0
#: A lane change in the route starts this far ahead of the ego (m) and takes this long per lane crossed (m).
LANE_CHANGE_START = 5.0
LANE_CHANGE_LENGTH = 30.0
#: The line starts this far behind the ego, so its projection is never clipped at the start (m).
START_BACKOFF = 10.0


@dataclass(frozen=True, slots=True)
class Route:
    lanes: tuple[LaneRef, ...]
    line: RefLine
    goal_s: float               # arc length of the goal's projection on the line


def _edge_kind(net: RoadNetwork, a: LaneRef, b: LaneRef) -> str:
    """'follow', 'change_left' or 'change_right' (the routing graph's edge kinds, docs/road_api.md)."""
    edge = net.lane_graph.succ.get(a, {}).get(b)
    return "follow" if edge is None else edge[0]


def lane_route(net: RoadNetwork, start: LaneRef, goal: LaneRef) -> list[LaneRef]:
    """Shortest lane sequence start -> goal, preferring one without lane changes (a stand-in keeps its lane when it
    can); raises InputError when the goal cannot be reached at all."""
    path = shortest_lane_path(net.lane_graph, start, goal, follow_only=True)
    return net.route(start, goal) if path is None else path


def lane_widths(net: RoadNetwork, road_id: str, lane_id: int, road_s: np.ndarray) -> np.ndarray:
    """`net.lane_width` at each of the road s values, in one array call when they lie in one lane section.

    `lane_bounds` adds the same widths in the same order as the scalar `lane_width` (laneOffset, then each inner
    lane's width outward), so the values are bit-identical; the scalar form is kept for samples spanning
    sections (each sample then takes the section holding it, as `lane_width` does)."""
    road_s = np.asarray(road_s, dtype=float)
    if len(road_s) == 0:
        return np.zeros(0)
    lo, hi = float(road_s.min()), float(road_s.max())
    si = net.section_index(road_id, lo)
    if si != net.section_index(road_id, hi):
        return np.array([net.lane_width(road_id, lane_id, float(s)) for s in road_s])
    inner, outer = net.lane_bounds(road_id, lane_id, road_s, section=si)
    return np.abs(outer - inner)


def _lane_points(net: RoadNetwork, ref: LaneRef) -> tuple[np.ndarray, bool, np.ndarray]:
    pts = net.lane_centerline(ref.road_id, ref.lane_id, DS, section=ref.section)
    road = net.roads[ref.road_id]
    widths = lane_widths(net, ref.road_id, ref.lane_id, pts[:, 2])
    return pts, road.junction not in ("-1", ""), widths


def _neighbour_widths(net: RoadNetwork, ref: LaneRef, road_s: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Widths of the same-direction driving lanes left and right of `ref` along its samples (0 where none):
    the room an obstacle may be passed in."""
    out = []
    for side in ("left", "right"):
        other = net.neighbour(ref, side)
        if other is None or net.lane_type(other.road_id, other.lane_id, float(road_s[0])) != "driving":
            out.append(np.zeros(len(road_s)))
        else:
            out.append(lane_widths(net, other.road_id, other.lane_id, road_s))
    return out[0], out[1]


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


def _groups(lanes: list[LaneRef], kinds: list[str]) -> list[list[int]]:
    """Indices of the lanes split into runs joined by lane changes (one run = one stretch of road)."""
    groups: list[list[int]] = [[0]]
    for i, kind in enumerate(kinds):
        if kind == "follow":
            groups.append([i + 1])
        else:
            groups[-1].append(i + 1)
    return groups


def _smoothstep(u: np.ndarray) -> np.ndarray:
    u = np.clip(u, 0.0, 1.0)
    return u * u * (3.0 - 2.0 * u)


def build_line(net: RoadNetwork, lanes: list[LaneRef], kinds: list[str], *,
               start_xy: tuple[float, float] | None = None) -> tuple[RefLine, list[tuple[float, float]]]:
    """Concatenate the lanes' centre lines (driving direction) into one reference line; `kinds[i]` is the edge
    from lanes[i] to lanes[i+1]. Lanes joined by lane changes (neighbours in one lane section, sampled at the same
    s) are blended: the line leaves the first `LANE_CHANGE_START` m after the ego (or after the section start)
    and reaches the last over `LANE_CHANGE_LENGTH` m per lane crossed. Returns the line and, per lane, the
    (start, end) arc length of the stretch it belongs to."""
    xy_parts, junction_parts, width_parts, left_parts, right_parts, group_of = [], [], [], [], [], {}
    for g, idx in enumerate(_groups(lanes, kinds)):
        src, junction, _ = _lane_points(net, lanes[idx[0]])
        dst, _, widths = _lane_points(net, lanes[idx[-1]])
        xy = dst[:, :2]
        if len(idx) > 1 and len(src) == len(dst):
            arc = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(src[:, :2], axis=0).T))])
            begin = 0.0
            if g == 0 and start_xy is not None:
                begin = float(arc[int(np.argmin(np.hypot(src[:, 0] - start_xy[0], src[:, 1] - start_xy[1])))])
            begin += LANE_CHANGE_START
            length = min(LANE_CHANGE_LENGTH * (len(idx) - 1), max(arc[-1] - begin - 1.0, 1.0))
            w = _smoothstep((arc - begin) / length)[:, None]
            xy = (1.0 - w) * src[:, :2] + w * dst[:, :2]
        xy_parts.append(xy)
        junction_parts.append(np.full(len(xy), junction))
        width_parts.append(widths)
        room_l, room_r = _neighbour_widths(net, lanes[idx[-1]], dst[:, 2])
        left_parts.append(room_l)
        right_parts.append(room_r)
        for i in idx:
            group_of[i] = g
    xy = np.vstack(xy_parts)
    seg = np.hypot(*np.diff(xy, axis=0).T)
    s = np.concatenate([[0.0], np.cumsum(seg)])
    bounds = np.cumsum([0] + [len(p) for p in xy_parts])
    spans = [(float(s[bounds[group_of[i]]]), float(s[bounds[group_of[i] + 1] - 1])) for i in range(len(lanes))]
    line = RefLine(xy, in_junction=np.concatenate(junction_parts), lane_width=np.concatenate(width_parts),
                   room_left=np.concatenate(left_parts), room_right=np.concatenate(right_parts), lanes=tuple(lanes))
    return line, spans


def _locate(net: RoadNetwork, x: float, y: float, heading: float, what: str) -> LaneRef:
    point = net.locate(x, y, heading)
    if point is None:
        raise InputError(f"the {what} at ({x:.1f}, {y:.1f}) is on no driving lane", source=net.source,
                         element="route")
    return point.ref


#: Routes planned lately, by network and the exact bits of pose and goal (see `plan_route`).
_PLANNED: dict[tuple, Route] = {}
_PLANNED_SIZE = 64


def plan_route(net: RoadNetwork, x: float, y: float, heading: float, goal: Goal) -> Route:
    """Route from the pose (x, y, heading) to `goal`, with its reference line trimmed to start a little behind the
    ego and run `GOAL_EXTENSION` metres past the goal.

    The answer depends on nothing else, so it is remembered: a campaign worker runs the nodes of a scenario tree
    one after another, and most of them start the ego at the same pose with the same goal on the same (cached)
    network. A remembered route is shared; its line only fills memo caches of values it derives the same way
    every time. Keyed by the floats' bits, so 0.0 and -0.0 are not taken for each other."""
    key = (net, *(float(v).hex() for v in (x, y, heading, goal.x, goal.y, goal.heading, goal.tolerance)))
    route = _PLANNED.get(key)
    if route is None:
        route = _plan_route(net, x, y, heading, goal)
        if len(_PLANNED) >= _PLANNED_SIZE:
            _PLANNED.pop(next(iter(_PLANNED)))
        _PLANNED[key] = route
    return route


def _plan_route(net: RoadNetwork, x: float, y: float, heading: float, goal: Goal) -> Route:
    start = _locate(net, x, y, heading, "ego")
    target = _locate(net, goal.x, goal.y, goal.heading, "goal")
    lanes = lane_route(net, start, target)
    if lanes == [start] and _behind(net, start, (x, y), (goal.x, goal.y)):
        lanes = _loop_route(net, start)
    kinds = [_edge_kind(net, a, b) for a, b in zip(lanes[:-1], lanes[1:])]
    tail = _extend(net, lanes[-1], GOAL_EXTENSION)
    full = list(lanes) + tail
    kinds += ["follow"] * len(tail)
    line, spans = build_line(net, full, kinds, start_xy=(x, y))
    # Each pose is projected onto its own lane's stretch of the line, so a route crossing itself (or passing the
    # goal's neighbourhood earlier) cannot confuse the two.
    e0, e1 = spans[0]
    ego_s = line.project(x, y, near_s=0.5 * (e0 + e1), window=0.5 * (e1 - e0) + 1.0).s
    g0, g1 = spans[len(lanes) - 1]
    goal_s = line.project(goal.x, goal.y, near_s=0.5 * (g0 + g1), window=0.5 * (g1 - g0) + 1.0).s
    trimmed, shift = _trim(line, max(0.0, ego_s - START_BACKOFF), min(line.length, goal_s + GOAL_EXTENSION))
    return Route(lanes=tuple(lanes), line=trimmed, goal_s=goal_s - shift)


def _behind(net: RoadNetwork, ref: LaneRef, ego: tuple[float, float], goal: tuple[float, float]) -> bool:
    """True when, on one lane, the goal lies behind the ego (the route must go round and come back)."""
    pts = net.lane_centerline(ref.road_id, ref.lane_id, DS, section=ref.section)

    def index(p: tuple[float, float]) -> int:
        return int(np.argmin(np.hypot(pts[:, 0] - p[0], pts[:, 1] - p[1])))

    return index(goal) < index(ego) - 2


def _loop_route(net: RoadNetwork, start: LaneRef) -> list[LaneRef]:
    """The shortest way from `start` round and back onto it (a ring road, a block)."""
    best: list[LaneRef] | None = None
    for nxt in net.successors(start):
        tail = shortest_lane_path(net.lane_graph, nxt, start, follow_only=True)
        if tail is None:
            continue
        path = [start] + tail
        if best is None or len(path) < len(best):
            best = path
    if best is None:
        raise InputError(f"the goal lies behind the ego on lane {start} and no way leads round to it",
                         source=net.source, element="route")
    return best


def _trim(line: RefLine, s0: float, s1: float) -> tuple[RefLine, float]:
    """The stretch [s0, s1] of the line (to the enclosing vertices) and the arc length its new start had."""
    idx = np.flatnonzero((line.s >= s0) & (line.s <= s1))
    if len(idx) < 2:
        return line, 0.0
    lo, hi = max(idx[0] - 1, 0), min(idx[-1] + 2, len(line.s))
    return RefLine(line.xy[lo:hi], in_junction=line.in_junction[lo:hi], lane_width=line.lane_width[lo:hi],
                   room_left=line.room_left[lo:hi], room_right=line.room_right[lo:hi], lanes=line.lanes), \
        float(line.s[lo])


def off_route(line: RefLine, x: float, y: float, heading: float, s_hint: float, max_offset: float) -> bool:
    """True when the pose is too far from the line, or heads against it, to keep following it."""
    pp = line.project(x, y, near_s=s_hint)
    if abs(pp.offset) > max_offset:
        return True
    dh = abs(math.remainder(heading - pp.heading, 2.0 * math.pi))
    return dh > 0.5 * math.pi
