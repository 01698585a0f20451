"""Moving entities one step, and the states derived from the motion.

Storyboard-driven entities on a lane move their speed·dt along the lane, turned into road s where the step starts
(`LaneTrack.ds_per_metre`) and carried in road s through successor lanes at the lane's end (preferring lanes of an
assigned route, else the straightest continuation); their lateral position is the offset their lateral action
set. Entities off the lanes move straight along their heading. The planner-driven ego moves with the kinematic
bicycle of `kinematics.py`.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from txt2sce_ros.contract import ControlCommand

from .kinematics import bicycle_command, integrate

if TYPE_CHECKING:
    from .entity import Entity
    from .lanes import LaneTrack
    from .world import World


_PI = math.pi
_TWO_PI = 2.0 * math.pi


def _wrap(a: float) -> float:
    return (a + _PI) % _TWO_PI - _PI


def _next_track(world: "World", route_lanes: set, track: "LaneTrack", backward: bool = False
                ) -> "LaneTrack | None":
    refs = world.tracks.predecessors(track.ref) if backward else world.tracks.successors(track.ref)
    if not refs:
        return None
    if len(refs) > 1 and route_lanes:
        on_route = [r for r in refs if r in route_lanes]
        if on_route:
            refs = on_route
    if len(refs) == 1:
        return world.tracks.track(refs[0])
    # Straightest continuation: smallest heading change between this lane's end and the successor's start.
    end_h = track.pose(track.s1 if track.forward != backward else track.s0)[2]
    best, best_dh = None, math.inf
    for ref in refs:
        cand = world.tracks.track(ref)
        if backward:
            far = cand.advance(cand.exit_s(), -min(10.0, cand.s1 - cand.s0))[0]
        else:
            far = cand.advance(cand.entry_s(), min(10.0, cand.s1 - cand.s0))[0]
        dh = abs(_wrap(cand.pose(far)[2] - end_h))
        if dh < best_dh:
            best, best_dh = cand, dh
    return best


def lane_walk(world: "World", track: "LaneTrack", s: float, ds: float, route_lanes: set | None = None
              ) -> tuple["LaneTrack", float, bool, int]:
    """Go `ds` of road s along the driving direction from road s (negative: against it, through predecessors);
    what is left at a lane's end continues, in road s, on the next lane (as esmini carries it).
    Returns (track, s, completed, direction flips) — flips: how often +t reversed relative to travel."""
    s, left = track.advance(s, ds)
    backward = ds < 0
    flips = 0
    guard = 0
    while left > 1e-12 and guard < 50:
        guard += 1
        nxt = _next_track(world, route_lanes or set(), track, backward)
        if nxt is None:
            return track, s, False, flips
        if nxt.forward != track.forward:
            flips += 1
        track = nxt
        s, left = (track.advance(track.exit_s(), -left) if backward else track.advance(track.entry_s(), left))
    return track, s, True, flips


def move_on_lane(world: "World", ent: "Entity", dist: float) -> bool:
    """Advance `dist` metres along the lane's driving direction (negative: against it); False when the lane
    network ends (the entity stays at the end)."""
    track = ent.track
    assert track is not None
    lateral = ent.runs.get("lateral")
    # The entity advances at the radius of its own path (its offset), unless its lateral action keeps it
    # measured along the lane centre.
    offset = ent.offset if lateral is None or lateral.travels_at_offset else 0.0
    ds = dist * track.ds_per_metre(ent.s, offset)
    s, left = track.advance(ent.s, ds)
    if left <= 1e-12:
        ent.s = s                       # within the lane (what `lane_walk` returns when nothing is left over)
        return True
    track, s, ok, flips = lane_walk(world, track, ent.s, ds, ent.route_lanes)
    if flips % 2:
        ent.offset = -ent.offset        # +t of the new road points the other way relative to travel
    ent.track, ent.s = track, s
    return ok


def move_storyboard(world: "World", ent: "Entity", dt: float, prev_t: float, prev_road: str | None) -> None:
    runs = ent.runs
    if runs:
        for run in runs.values():
            if run.moves_entity:
                return
    if ent.placed:
        ent.placed = False          # teleported this step: it appears there, and moves from the next step
        return
    dist = ent.speed * dt
    if dist == 0.0 and not runs:
        still = ent.still
        if (still is not None and still[0] is ent.track and still[1] is ent.s and still[2] is ent.offset
                and still[3] is ent.heading_override and still[4] is ent.reverse and ent.lane_locked):
            _stand_again(ent, still, dt)
            return
    if ent.track is not None and ent.lane_locked:
        s_before, track_before = ent.s, ent.track
        along = dist
        lateral_run = ent.runs.get("lateral")
        if prev_road == ent.track.ref.road_id and lateral_run is not None and lateral_run.consumes_travel:
            # A lane change's sideways motion uses part of the step's travel, as in esmini (offsets do not).
            lat = ent.track.center_t(ent.s) + ent.offset - prev_t
            if 0.0 < abs(lat) < abs(dist):
                along = math.copysign(math.sqrt(dist * dist - lat * lat), dist)
        ok = move_on_lane(world, ent, -along if ent.reverse else along)
        if ok and along == 0.0:
            # Standing: still "at the end of the road" if parked on a dead end's last point.
            tr = ent.track
            end_s = tr.exit_s() if not ent.reverse else tr.entry_s()
            nxt = world.tracks.predecessors(tr.ref) if ent.reverse else world.tracks.successors(tr.ref)
            ok = not (abs(ent.s - end_s) < 1e-6 and not nxt)
        tr = ent.track
        x, y, h, tc = tr.pose_center(ent.s, ent.offset)
        # The entity's road coordinates from its track (as `Entity._sync_road`, with the centre just computed).
        ent._road = road = (tr.ref.road_id, tr.ref.lane_id, ent.s, tc + ent.offset)
        ent.road_stale = False
        if ent.heading_override is not None and ent.offset == ent.offset:
            h = ent.heading_override
        else:
            if ent.reverse:
                h += math.pi
            if dist > 1e-9 and prev_road == road[0]:
                # Heading follows the lateral motion too (lane changes): atan of lateral over travel.
                lateral = (road[3] - prev_t) * (1.0 if ent.track.forward != ent.reverse else -1.0)
                h = h + math.atan2(lateral, along)
        ent.x, ent.y, ent.h = x, y, h
        if ok:
            ent.end_of_road_time = None
        else:
            # Stuck at the end of the lane network: the entity stops there (esmini does the same).
            ent.end_of_road_time = (0.0 if ent.end_of_road_time is None else ent.end_of_road_time + dt)
            if ent.s == s_before and ent.track is track_before:
                ent.speed = 0.0     # could not move at all: stuck at the end (esmini stops it there)
        # A step that stood on its lane (no distance, no runs) at an s inside the track, away from s = 0 (where
        # s + 0.0 could turn -0.0 into 0.0), gives the same result again while its inputs stay the same objects:
        # the standing branch above is then a function of (track, s, offset, heading override, reverse) alone.
        ent.still = ((ent.track, ent.s, ent.offset, ent.heading_override, ent.reverse, ok, x, y, h, road)
                     if dist == 0.0 and not runs and ent.track is track_before and ent.s != 0.0
                     and track_before.s0 <= s_before <= track_before.s1 else None)
    elif dist != 0.0:
        ent.x += dist * math.cos(ent.h)
        ent.y += dist * math.sin(ent.h)


def _stand_again(ent: "Entity", still: tuple, dt: float) -> None:
    """`move_storyboard`'s lane branch for an entity standing where its last step left it (see `Entity.still`):
    the same assignments with the values that step computed."""
    ok, ent.x, ent.y, ent.h, ent._road = still[5:]
    ent.road_stale = False
    if ok:
        ent.end_of_road_time = None
    else:
        ent.end_of_road_time = 0.0 if ent.end_of_road_time is None else ent.end_of_road_time + dt
        ent.speed = 0.0


def move_planner(world: "World", ent: "Entity", cmd: ControlCommand | None, dt: float) -> bool:
    """Apply the planner's command to the ego; returns True if the wheels slipped."""
    sp = ent.spec
    v_cmd, w_cmd = (ent.speed, 0.0) if cmd is None else (cmd.speed, cmd.yaw_rate)
    res = bicycle_command(ent.speed, v_cmd, w_cmd, dt, wheelbase=sp.wheelbase, max_steer=sp.max_steering,
                          max_accel=sp.max_accel, max_decel=sp.max_decel, max_speed=sp.max_speed,
                          friction=world.friction, is_vehicle=sp.kind == "vehicle")
    ent.x, ent.y, ent.h = integrate(ent.x, ent.y, ent.h, ent.speed, res.speed, res.yaw_rate, dt)
    ent.speed = res.speed
    ent.track = None
    ent.lane_locked = False
    return res.slipping


def derive(world: "World", ent: "Entity", dt: float, px: float, py: float, locate: bool) -> None:
    """Acceleration, yaw rate, odometer, stand-still time, and road coordinates of free-moving entities."""
    ent.accel = (ent.speed - ent._prev_speed) / dt
    ent.yaw_rate = ((ent.h - ent._prev_h + _PI) % _TWO_PI - _PI) / dt       # _wrap, written out (every step)
    ent.odometer += math.hypot(ent.x - px, ent.y - py)
    ent.standstill_time = ent.standstill_time + dt if abs(ent.speed) < 1e-3 else 0.0
    if ent.track is None or not ent.lane_locked:
        if not locate:
            ent.road_stale = True           # located on demand
            return
        lp = world.net.locate(ent.x, ent.y, ent.h)
        if lp is not None and lp.inside:
            ent.set_road(lp.road_id, lp.lane_id, lp.s, lp.t)
            ent.offroad_time = None
        else:
            ent.offroad_time = (ent.offroad_time or 0.0) + dt
            if lp is not None:
                ent.set_road(lp.road_id, lp.lane_id, lp.s, lp.t)
            else:
                ent.set_road(None, None, 0.0, 0.0)
