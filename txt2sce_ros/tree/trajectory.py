"""Trajectory mutation family (Table III): WPM lateral offsets in lane changes and context-aware initial locations.

Initial locations move along the entity's own lane (so its route to the conflict is unchanged), stay on a lane of
the same type on the same road (per the road model), and stay upstream of every position the entity must still
reach (its route waypoints and the ReachPosition triggers it fires), so the scenario still leads to the conflict.
"""

from __future__ import annotations

import math

from typing import Any

import numpy as np
from lxml import etree

from ..errors import Txt2SceError
from ..seed.boxes import START_CLEARANCE, box_corners, boxes_gap
from ..seed.context import LanePos, SeedContext, lane_pos
from .values import Recorder, gaussian, uniform

_LANE_CHANGE_ACTIONS = ("lane_change_left", "lane_change_right")


def wpm_lane_change(event: etree._Element, action: str, entity: str, entity_width: float,
                    rng: np.random.Generator, cfg: dict[str, Any], ctx: SeedContext, rec: Recorder) -> bool:
    """Lateral offset of the target in lane changes: LaneChangeAction/@targetLaneOffset and, in lane-change
    events, the waypoints' LanePosition/@offset. Uniform in ±share·(lane width − entity width)/2, so the entity
    stays inside its target lane. Returns False when the event holds no lane change."""
    changes = list(event.iter("LaneChangeAction"))
    waypoints = list(event.iterfind(".//Waypoint/Position/LanePosition")) if action in _LANE_CHANGE_ACTIONS else []
    if not changes and not waypoints:
        return False
    width = _lane_width_at(ctx, ctx.starts.get(entity), cfg)
    half = max(0.0, cfg["offset_share"] * (width - entity_width) / 2.0)
    for lc in changes:
        rec.set(lc, "targetLaneOffset", uniform(rng, -half, half), digits=3)
    for lp in waypoints:
        pos = lane_pos(lp)
        w = _lane_width_at(ctx, pos, cfg)
        h = max(0.0, cfg["offset_share"] * (w - entity_width) / 2.0)
        rec.set(lp, "offset", uniform(rng, -h, h), digits=3)
    return True


def _lane_width_at(ctx: SeedContext, pos: LanePos | None, cfg: dict[str, Any]) -> float:
    if pos is None or ctx.map is None or not ctx.map.has_road(pos.road):
        return float(cfg["default_lane_width"])
    try:
        w = ctx.map.lane_width(pos.road, pos.lane, pos.s)
    except (KeyError, IndexError):
        return float(cfg["default_lane_width"])
    return w if w > 0.5 else float(cfg["default_lane_width"])


def feasible_s(ctx: SeedContext, entity: str, start: LanePos, new_s: float, margin: float,
               min_gap: float = 6.0) -> bool:
    """Context check for a new start s on the same road and lane: inside the road, on a lane of the original type,
    `min_gap` from (and on the same side of) every other entity starting in that lane, and still upstream (by
    `margin`) of every position on that lane the entity had ahead of it."""
    m = ctx.map
    if m is None or not m.has_road(start.road):
        return False
    length = m.road_length(start.road)
    if not 0.5 <= new_s <= length - 0.5:
        return False
    if m.lane_type(start.road, start.lane, new_s) != m.lane_type(start.road, start.lane, start.s):
        return False
    sign = m.direction(start.road, start.lane)
    for other, pos in ctx.starts.items():
        # never onto or past another entity starting in the same lane: the order of the queue is part of the
        # scenario, and an overlap at t=0 is a collision before anything happened
        if other == entity or (pos.road, pos.lane) != (start.road, start.lane):
            continue
        before, after = start.s - pos.s, new_s - pos.s
        if before * after <= 0 or abs(after) < min_gap:
            return False
    if not _clear_of_neighbours(ctx, entity, start, new_s, min_gap):
        return False
    for target in ctx.must_reach.get(entity, []):
        if target.road != start.road:
            continue
        ahead_before = sign * (target.s - start.s)
        if ahead_before >= 0 and sign * (target.s - new_s) < min(margin, ahead_before):
            return False
    return True


#: m: parties in other lanes whose centres are laterally closer than this to a moved start count as beside it
#: (two car half-widths and a margin: a party offset toward the lane line, as a side-swipe seed writes it).
BESIDE = 2.5


def _clear_of_neighbours(ctx: SeedContext, entity: str, start: LanePos, new_s: float, min_gap: float) -> bool:
    """No party starting in another lane sits beside the moved start: within BESIDE m across and `min_gap` m
    along (in the moved start's frame). A shift must not push one start onto another (an overlap at t = 0 is an
    invalid scenario, not a test)."""
    net = ctx.network
    if net is None:
        return True
    try:
        x, y, h = net.lane_to_world(start.road, start.lane, new_s, start.offset)
    except (KeyError, IndexError, ValueError):
        return True
    c, s_ = math.cos(h), math.sin(h)
    for other, pos in ctx.starts.items():
        if other == entity or (pos.road, pos.lane) == (start.road, start.lane):
            continue                  # same lane: the queue check of `feasible_s`
        try:
            ox, oy, _ = net.lane_to_world(pos.road, pos.lane, pos.s, pos.offset)
        except (KeyError, IndexError, ValueError):
            continue
        dx, dy = ox - x, oy - y
        if abs(-s_ * dx + c * dy) < BESIDE and abs(c * dx + s_ * dy) < min_gap:
            return False
    return True


def shift_init_location(private: etree._Element, entity: str, rng: np.random.Generator, cfg: dict[str, Any],
                        ctx: SeedContext, rec: Recorder, *, tries: int = 20, max_back: float | None = None) -> float:
    """Context-aware initial location: Gaussian shift of the start along its lane, retried until `feasible_s`
    holds. The ego's route starts where the ego does, so its first waypoint moves with it. `max_back`: the most
    the start may move against its lane's driving direction (m). Returns the shift (m); 0 when no feasible shift
    was found or the start is not a LanePosition."""
    tele = private.find("PrivateAction/TeleportAction/Position/LanePosition")
    if tele is None:
        return 0.0
    start = lane_pos(tele)
    sign = ctx.map.direction(start.road, start.lane) if ctx.map is not None and ctx.map.has_road(start.road) else 1
    for _ in range(tries):
        shift = gaussian(rng, 0.0, cfg["sigma"], -cfg["max_shift"], cfg["max_shift"])
        if abs(shift) < 0.05 or (max_back is not None and sign * shift < -max_back):
            continue
        new_s = start.s + shift
        if feasible_s(ctx, entity, start, new_s, cfg["margin"], cfg["min_gap"]):
            return move_start(private, new_s, rec) - start.s
    return 0.0


def move_start(private: etree._Element, new_s: float, rec: Recorder) -> float:
    """Set the start s of an entity's Init (its TeleportAction LanePosition) and, when its route's first waypoint
    is that start, the waypoint with it (the route starts where the entity does). Returns the s as written."""
    tele = private.find("PrivateAction/TeleportAction/Position/LanePosition")
    start = lane_pos(tele)
    text = rec.set(tele, "s", new_s, digits=3)
    for wp in private.iterfind("PrivateAction/RoutingAction/AssignRouteAction/Route/Waypoint[1]/Position/"
                               "LanePosition"):
        wpp = lane_pos(wp)
        if (wpp.road, wpp.lane, wpp.s) == (start.road, start.lane, start.s):
            rec.set(wp, "s", text)
    return float(text)


def route_through(parts: list[etree._Element | None], goal: LanePos, rec: Recorder) -> None:
    """Carry the ego's route to `goal` (`environment.through_light`): the route's last waypoint becomes `goal` and
    the waypoints between its first and last go (they lay on the way to the old end, some now behind the moved
    start); the ego block's goal condition (`parts[1]`, the StopTrigger's ReachPosition) moves with it, so the run
    ends there and not at the old goal, short of the light."""
    route = parts[0].find("PrivateAction/RoutingAction/AssignRouteAction/Route")
    if route is None:
        return
    points = route.findall("Waypoint")
    for wp in points[1:-1]:
        rec.note(f"Route/Waypoint/LanePosition[@s='{wp.find('Position/LanePosition').get('s')}']", "waypoint", None)
        route.remove(wp)
    targets = [points[-1].find("Position/LanePosition")]
    if len(parts) > 1 and parts[1] is not None:
        targets.append(parts[1].find("ByEntityCondition/EntityCondition/ReachPositionCondition/Position/"
                                     "LanePosition"))
    for lp in targets:
        if lp is None:
            continue
        rec.set(lp, "roadId", goal.road)
        rec.set(lp, "laneId", str(goal.lane))
        rec.set(lp, "s", goal.s, digits=3)
        rec.set(lp, "offset", goal.offset, digits=3)


def footprint_extent(obj: etree._Element | None) -> tuple[float, float]:
    """(rear, front) m of a ScenarioObject's footprint from its reference point along its heading (0, 0 unknown)."""
    bb = obj.find("*/BoundingBox") if obj is not None else None
    if bb is None or bb.find("Center") is None or bb.find("Dimensions") is None:
        return 0.0, 0.0
    cx, half = float(bb.find("Center").get("x", "0")), 0.5 * float(bb.find("Dimensions").get("length", "0"))
    return cx - half, cx + half


def keep_clear_of_queue(private: etree._Element, entity: str, obj: etree._Element, ctx: SeedContext,
                        rec: Recorder, cfg: dict[str, Any], *, gap: float = 0.5) -> float:
    """After NCM/DM changed a party's size (a car becoming an 11 m bus), move its start along its lane just far
    enough that its footprint keeps `gap` m from every party starting in the same lane: away from the one it now
    reaches, never past it (the queue's order is part of the scenario). Returns the shift (m); 0 when none was
    needed or no feasible one exists (the node then starts overlapped and the player reports it)."""
    tele = private.find("PrivateAction/TeleportAction/Position/LanePosition")
    if tele is None or ctx.map is None or not ctx.map.has_road(lane_pos(tele).road):
        return 0.0
    start = lane_pos(tele)
    sign = ctx.map.direction(start.road, start.lane)
    rear, front = footprint_extent(obj)
    shift = 0.0
    for other, pos in ctx.starts.items():
        if other == entity or (pos.road, pos.lane) != (start.road, start.lane):
            continue
        o_rear, o_front = footprint_extent(ctx.root.find(f"Entities/ScenarioObject[@name='{other}']"))
        u, u_o = sign * (start.s + shift), sign * pos.s       # along the lane's driving direction
        if u <= u_o:                                          # behind it: our front must stay behind its rear
            need = (u + front + gap) - (u_o + o_rear)
            shift -= max(need, 0.0) * sign
        else:                                                 # ahead of it: our rear must stay ahead of its front
            need = (u_o + o_front + gap) - (u + rear)
            shift += max(need, 0.0) * sign
    if abs(shift) < 1e-6:
        return 0.0
    new_s = start.s + shift
    if not feasible_s(ctx, entity, start, new_s, cfg["margin"], min_gap=0.0):
        return 0.0
    rec.set(tele, "s", new_s, digits=3)
    return shift


def place_near_ego(private: etree._Element, entity: str, obj: etree._Element, ctx: SeedContext, rec: Recorder,
                   cfg: dict[str, Any]) -> float:
    """WPM on the initial location, toward the AV: a party starting on the ego's road and travelling its way
    (R5/R6, any lane) is moved along its own lane so that `near_gap` m of bumper gap separate it from the ego at
    the start, on the side it already was (ahead stays ahead, so the queue's order and the report's position
    hold). A party close to the AV at the start is the condition of start refusals and of a cyclist or a car
    riding beside the ego as it turns; a seed rarely places one, so the tree brings it in. Returns the shift (m);
    0 when the party is elsewhere, already that close, or the new start is not feasible (`feasible_s`)."""
    tele = private.find("PrivateAction/TeleportAction/Position/LanePosition")
    ego = ctx.starts.get("ego")
    if tele is None or ego is None or ctx.map is None or not ctx.map.has_road(ego.road):
        return 0.0
    start = lane_pos(tele)
    if start.road != ego.road:
        return 0.0
    sign = ctx.map.direction(start.road, start.lane)
    if sign != ctx.map.direction(ego.road, ego.lane):
        return 0.0                                         # oncoming: closeness at the start is no condition
    e_rear, e_front = footprint_extent(ctx.root.find("Entities/ScenarioObject[@name='ego']"))
    p_rear, p_front = footprint_extent(obj)
    gap = float(cfg["near_gap"])
    ahead = sign * (start.s - ego.s) > 0
    # reference-point distance along the lane that leaves `gap` between the facing bumpers
    dist = (e_front - p_rear + gap) if ahead else (p_front - e_rear + gap)
    new_s = ego.s + sign * (dist if ahead else -dist)
    if abs(new_s - start.s) < 0.5 or abs(start.s - ego.s) < abs(new_s - ego.s):
        return 0.0                                         # already at least that close
    if not feasible_s(ctx, entity, start, new_s, cfg["margin"], min_gap=0.0):
        return 0.0
    text = rec.set(tele, "s", new_s, digits=3)
    return float(text) - start.s


def start_box(ctx: SeedContext, name: str, obj: etree._Element | None, pos: LanePos | None = None
               ) -> np.ndarray | None:
    """Corners of `name`'s footprint at its start (`pos` on its lane instead, where given); None where the object
    has no bounding box or the start cannot be placed on the map."""
    bb = obj.find("*/BoundingBox") if obj is not None else None
    dims = bb.find("Dimensions") if bb is not None else None
    if dims is None:
        return None
    try:
        if pos is None:
            st = ctx.start(name)
            x, y, h = st.x, st.y, st.h
        else:
            x, y, h = ctx.network.lane_to_world(pos.road, pos.lane, pos.s, pos.offset)
    except (Txt2SceError, KeyError, IndexError, ValueError, AttributeError):
        return None
    center = bb.find("Center")
    return box_corners(x, y, h, float(dims.get("length", "0")), float(dims.get("width", "0")),
                       float(center.get("x", "0")) if center is not None else 0.0)


def starts_clear(ctx: SeedContext, entity: str, obj: etree._Element | None, pos: LanePos | None = None) -> bool:
    """Whether `entity`'s footprint (object `obj`) at its start, or at `pos` on a lane, keeps START_CLEARANCE m
    from the footprint of every other entity's start in the seed, in any lane (True where it has no footprint)."""
    box = start_box(ctx, entity, obj, pos)
    if box is None:
        return True
    for name in ctx.entities:
        other = start_box(ctx, name, ctx.root.find(f"Entities/ScenarioObject[@name='{name}']")) \
            if name != entity else None
        if other is not None and boxes_gap(box, other) < START_CLEARANCE:
            return False
    return True


def clear_of_starts(private: etree._Element, entity: str, obj: etree._Element, ctx: SeedContext, rec: Recorder,
                    cfg: dict[str, Any], *, step: float = 0.5) -> bool:
    """After NCM gave a party another category's size at the seed's start, keep its footprint clear of every other
    entity's start, in any lane (`starts_clear`): a motorcycle riding beside the AV becomes a car, van or truck
    whose footprint reaches into the AV's (the same-lane queue is `keep_clear_of_queue`'s; `feasible_s` compares
    reference points, not footprints, and only across `BESIDE` m). Where it overlaps, the start moves back along
    its own lane (then, failing that, forward) by the smallest multiple of `step` up to `max_shift` m that clears
    every footprint and stays `feasible_s`; a world start (the first vertex of the party's own path) is not moved.
    Returns False where no clear start exists: the caller drops the version (an overlap at t = 0 is an invalid
    scenario, not a test). Another layer's version (the AV's start shifted) is not seen here; the seed's starts
    are."""
    tele = private.find("PrivateAction/TeleportAction/Position/LanePosition")
    if tele is None or ctx.map is None or not ctx.map.has_road(lane_pos(tele).road):
        # a world start (a party starting on a path of its own, its trajectory's first vertex): moving it would
        # leave the path's start where it was, so it stays, or the version goes where its footprint overlaps
        return starts_clear(ctx, entity, obj)
    start = lane_pos(tele)
    if starts_clear(ctx, entity, obj, start):
        return True
    sign = ctx.map.direction(start.road, start.lane)
    for k in range(1, int(float(cfg["max_shift"]) / step) + 1):
        for way in (-sign, sign):                       # back along the lane's driving direction first
            new_s = start.s + way * k * step
            if feasible_s(ctx, entity, start, new_s, cfg["margin"], min_gap=0.0) and \
                    starts_clear(ctx, entity, obj, LanePos(start.road, start.lane, new_s, start.offset)):
                move_start(private, new_s, rec)
                return True
    return False
