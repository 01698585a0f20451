"""Behaviour layer: what constrains the ego's speed and lateral position this step, from the perceived objects,
traffic lights and the goal, all measured along the route's reference line.

Each rule returns `Constraint`s (an acceleration it asks for and why); the planner takes the most restrictive.
Rules: follow the nearest in-path mover (IDM); stop for / pass a static obstacle in the lane; yield to a party whose
predicted path crosses the ego's ahead (constant turn rate and velocity prediction, so objects on curved lanes and
turning in junctions follow their lane); stop at red, and at yellow when the stop is comfortable (else clear); stop
at the goal.
"""

from __future__ import annotations

import enum
import math
import operator
from dataclasses import dataclass

import numpy as np

from txt2sce_ros.contract import OBSTACLE_CATEGORIES, EntityState, SignalState, TrafficLightState
from txt2sce_ros.quick_init import quick_init

from .idm import idm_accel, slow_down_accel, stop_accel
from .params import BehaviourParams, LongitudinalParams
from .refline import RefLine, wrap_angle


class Reason(str, enum.Enum):
    CRUISE = "cruise"
    CURVE = "curve"
    LEAD = "lead"
    OBSTACLE = "obstacle"
    YIELD = "yield"
    RED = "red_light"
    YELLOW = "yellow_light"
    GOAL = "goal"
    WAIT = "wait_clear"    # standing, something in the path close ahead: start only once it is clear
    HOLD = "hold"          # refuses to move (fault no_start_when_close)


@quick_init
@dataclass(frozen=True, slots=True)
class Constraint:
    reason: Reason
    accel: float                 # m/s² asked for
    entity: str = ""
    distance: float = math.inf   # m from the ego's front to what it reacts to
    urgent: bool = False         # needs more than comfortable braking: the jerk limit may be exceeded


@quick_init
@dataclass(frozen=True, slots=True)
class StopPlan:
    """How stops are planned this step: the deceleration allowed for by the road, the acceleration wanted
    otherwise, and the distance (m) the jerk-limited braking build-up still costs."""

    decel: float
    cruise: float
    lag: float = 0.0
    hard: bool = False           # brake late and hard (fault late_braking_low_friction): no comfort jerk limit
    braking: bool = False        # the ego is braking already (hold a stop through to standstill)


def is_static(obj: EntityState) -> bool:
    """A static object: flagged so by the simulator, or of an obstacle category (a parked vehicle is one even when
    it is modelled as a Vehicle; the ROS path derives the flag from the category, so both paths agree)."""
    return obj.is_static or obj.category in OBSTACLE_CATEGORIES


@quick_init
@dataclass(frozen=True, slots=True)
class PathObject:
    """An object measured against the reference line."""

    state: EntityState
    s_min: float                 # rear-most and front-most arc length of its footprint
    s_max: float
    offset: float                # lateral offset of its footprint centre, m (left positive)
    half_lat: float              # half of its lateral extent across the line, m
    v_along: float               # speed component along the line, m/s
    rel_heading: float           # its heading minus the line's, rad


@quick_init
@dataclass(frozen=True, slots=True)
class EgoOnPath:
    s: float                     # rear axle arc length
    s_front: float
    offset: float
    speed: float
    half_width: float


#: Window (m) of the object projections, and how many standing objects' measurements a line remembers.
MEASURE_WINDOW = 150.0
MEASURE_CACHE = 256


def measure(obj: EntityState, line: RefLine, near_s: float) -> PathObject:
    # A standing object (static obstacle, waiting car) is measured the same every step: remembered per line by
    # everything the measurement reads and the segments the projection searches. Only for a speed of +0.0 and a
    # position off both axes, where the sign of a zero cannot reach the result (a zero heading or centre offset
    # then adds nothing to x and y, and the heading enters only through wrap_angle of a difference).
    if obj.speed == 0.0 and obj.x != 0.0 and obj.y != 0.0 and math.copysign(1.0, obj.speed) > 0.0 \
            and obj.length > 0.0 and obj.width > 0.0:
        memo = line.cache.get(_MEASURED)
        if memo is None:
            memo = line.cache[_MEASURED] = {}
        key = (obj.x, obj.y, obj.heading, obj.center_x, obj.length, obj.width,
               line.window(near_s, MEASURE_WINDOW))
        hit = memo.get(key)
        if hit is None:
            if len(memo) >= MEASURE_CACHE:
                memo.clear()
            po = _measure(obj, line, near_s)
            memo[key] = (po.s_min, po.s_max, po.offset, po.half_lat, po.v_along, po.rel_heading)
            return po
        return PathObject(obj, *hit)
    return _measure(obj, line, near_s)


_MEASURED = "behaviour.measure"


def _measure(obj: EntityState, line: RefLine, near_s: float) -> PathObject:
    cx = obj.x + obj.center_x * math.cos(obj.heading)
    cy = obj.y + obj.center_x * math.sin(obj.heading)
    pp = line.project(cx, cy, near_s=near_s, window=MEASURE_WINDOW)
    rel = wrap_angle(obj.heading - pp.heading)
    c, s = abs(math.cos(rel)), abs(math.sin(rel))
    half_long = 0.5 * (c * obj.length + s * obj.width)
    half_lat = 0.5 * (s * obj.length + c * obj.width)
    return PathObject(state=obj, s_min=pp.s - half_long, s_max=pp.s + half_long, offset=pp.offset,
                      half_lat=half_lat, v_along=obj.speed * math.cos(rel), rel_heading=rel)


def in_path(po: PathObject, ego: EgoOnPath, ego_offset: float, p: BehaviourParams) -> bool:
    return abs(po.offset - ego_offset) < ego.half_width + po.half_lat + p.path_half_width_margin


def lead_constraint(objs: list[PathObject], ego: EgoOnPath, ego_offset: float, v0: float,
                    lp: LongitudinalParams, bp: BehaviourParams, decel: float, own_brake: float
                    ) -> Constraint | None:
    """IDM on the nearest moving in-path object ahead travelling roughly our way."""
    best: PathObject | None = None
    for po in objs:
        if po.s_max <= ego.s_front - 0.5 or not in_path(po, ego, ego_offset, bp):
            continue
        if is_static(po.state) or abs(po.rel_heading) > bp.lead_heading_tolerance or po.v_along < 0.3:
            continue
        if best is None or po.s_min < best.s_min:
            best = po
    if best is None:
        return None
    gap = best.s_min - ego.s_front
    a = idm_accel(ego.speed, v0, gap, max(best.v_along, 0.0), lp, decel=decel, own_brake=own_brake)
    return Constraint(Reason.LEAD, a, best.state.name, gap, urgent=a < -decel)


def start_clear(objs: list[PathObject], ego: EgoOnPath, ego_offset: float, bp: BehaviourParams) -> Constraint | None:
    """At standstill, a wait while anything stands or moves in the path within `start_clear_distance` ahead
    (a slowly moving lead is followed by IDM once it has pulled away that far)."""
    if ego.speed >= 0.1:
        return None
    for po in objs:
        gap = po.s_min - ego.s_front
        if -0.5 < gap < bp.start_clear_distance and in_path(po, ego, ego_offset, bp):
            return Constraint(Reason.WAIT, 0.0, po.state.name, gap)
    return None


def stop_constraint(reason: Reason, distance: float, ego: EgoOnPath, lp: LongitudinalParams, sp: StopPlan,
                    entity: str = "") -> Constraint:
    """A planned stop with the front bumper `stop_margin` metres before `distance`."""
    d = distance - lp.stop_margin
    a = stop_accel(ego.speed, d, lp, plan_decel=sp.decel, cruise=sp.cruise, lag=sp.lag, braking=sp.braking)
    # Urgent (the jerk limit may be exceeded) only when even an immediate stop needs more than planned; the
    # build-up lag is a comfort allowance and does not make a stop urgent by itself.
    need_now = ego.speed * ego.speed / (2.0 * max(d, 0.05))
    urgent = (a < 0.0 and need_now > sp.decel * 1.05 and ego.speed > 1.0) or (sp.hard and a < 0.0)
    return Constraint(reason, a, entity, distance, urgent=urgent)


def pass_offset(po: PathObject, ego: EgoOnPath, line: RefLine, bp: BehaviourParams,
                others: list[PathObject] = ()) -> tuple[float, bool] | None:
    """(offset, clear): the lateral offset of the ego's centre (left positive) at which it passes the static object
    with `pass_lateral_margin` clearance — inside its lane when the lane leaves room, else partly or wholly in a
    same-direction neighbour lane — and whether that is free now (`others` checked from behind the ego to past
    the object; a pass inside the lane is always free). None when neither side has room at all."""
    w = line.width_at(0.5 * (po.s_min + po.s_max))
    room_l, room_r = line.neighbour_room(po.s_min - PASS_PREPARE, po.s_max + PASS_RETURN)
    left = po.offset + po.half_lat + bp.pass_lateral_margin + ego.half_width
    right = po.offset - po.half_lat - bp.pass_lateral_margin - ego.half_width
    own = 0.5 * w - ego.half_width
    inside = [o for o in (left, right) if abs(o) <= own + 1e-9]
    if inside:
        return min(inside, key=abs), True
    options = []
    if room_l > 0.0 and left <= own + room_l + 1e-9:
        options.append((left, _clear(others, po, ego, 0.5 * w, 0.5 * w + room_l)))
    if room_r > 0.0 and -right <= own + room_r + 1e-9:
        options.append((right, _clear(others, po, ego, -(0.5 * w + room_r), -0.5 * w)))
    if not options:
        return None
    # A free side first, then the smaller move.
    return min(options, key=lambda o: (not o[1], abs(o[0])))


def _clear(others: list[PathObject], po: PathObject, ego: EgoOnPath, lo: float, hi: float) -> bool:
    """No other object overlaps the lateral band [lo, hi] between PASS_BEHIND m behind the ego and PASS_RETURN m
    past the obstacle."""
    for o in others:
        if o is po or o.s_max < ego.s - PASS_BEHIND or o.s_min > po.s_max + PASS_RETURN:
            continue
        if o.offset + o.half_lat > lo and o.offset - o.half_lat < hi:
            return False
    return True


#: Static obstacles closer than this (m) are passed when there is room (farther ones are only stopped for).
PASS_LOOKAHEAD = 60.0
#: A pass into a neighbour lane needs it free from this far behind the ego (m, for traffic coming up), from this
#: far before the obstacle (m, to move over) and to this far past it (m, to move back).
PASS_BEHIND = 30.0
PASS_PREPARE = 15.0
PASS_RETURN = 10.0
#: Waiting to pass, the ego stops this much further back (m) so it can move over when the lane beside is free.
PASS_SETUP = 8.0
#: Travel needed per metre of sideways move at a crawl (m/m), and the crawl speed while moving over (m/s).
PASS_SLOPE = 4.0
PASS_CRAWL = 1.0


_S_MIN = operator.attrgetter("s_min")        # the sort key of `obstacle_rules` (a C call, not a lambda)


def obstacle_rules(objs: list[PathObject], ego: EgoOnPath, line: RefLine, lp: LongitudinalParams,
                   bp: BehaviourParams, sp: StopPlan) -> tuple[list[Constraint], float]:
    """Static (or standing, not-following) objects in the lane: pass them when there is room, else stop before
    them. Returns the stop constraints and the lateral offset to drive at (0 = lane centre). While the ego has not
    yet moved over far enough (its measured offset, not the commanded one: the vehicle lags the command), the stop
    stays in force, so it slows down rather than clip the obstacle; an obstacle alongside keeps the offset until
    the ego's rear has passed it."""
    out: list[Constraint] = []
    offset = 0.0
    behind = ego.s - 1.0
    ahead = sorted([po for po in objs if po.s_max > behind], key=_S_MIN)
    for po in ahead:
        moving_lead = (not is_static(po.state) and abs(po.rel_heading) <= bp.lead_heading_tolerance
                       and po.v_along >= 0.3)
        if moving_lead or not in_path(po, ego, offset, bp):
            continue
        distance = po.s_min - ego.s_front
        if is_static(po.state) and distance < PASS_LOOKAHEAD:
            found = pass_offset(po, ego, line, bp, objs)
            if found is not None:
                shift, free = found
                blocked = in_path(po, ego, ego.offset, bp)        # measured: the vehicle lags the command
                if free or not blocked:
                    # Go (or carry on with a pass already under way). Not yet clear: approach at a crawl while
                    # the remaining sideways move still fits before the object (about PASS_SLOPE m of travel per
                    # metre sideways), else stop at it.
                    offset = shift
                    if blocked and distance > -0.5:
                        need = lp.stop_margin + PASS_SLOPE * max(abs(shift - ego.offset) - 0.05, 0.0)
                        if distance > need + 0.5:
                            a = slow_down_accel(ego.speed, PASS_CRAWL, distance - need, lp, plan_decel=sp.decel,
                                                lag=sp.lag, cruise=sp.cruise)
                            out.append(Constraint(Reason.OBSTACLE, a, po.state.name, distance))
                        else:
                            out.append(stop_constraint(Reason.OBSTACLE, distance, ego, lp, sp, po.state.name))
                else:
                    # Lane beside busy: line up inside the own lane and wait PASS_SETUP m short of the object,
                    # leaving room to move over once it is free.
                    own = 0.5 * line.width_at(po.s_min) - ego.half_width
                    offset = max(-own, min(own, shift))
                    wait_at = distance - PASS_SETUP if distance - PASS_SETUP > lp.stop_margin else distance
                    if distance > -0.5:
                        out.append(stop_constraint(Reason.OBSTACLE, wait_at, ego, lp, sp, po.state.name))
                continue
        if distance > -0.5:
            out.append(stop_constraint(Reason.OBSTACLE, distance, ego, lp, sp, po.state.name))
            break
    return out, offset


#: sin of the angle below which a mover counts as travelling parallel to the route (25°).
PARALLEL_SIN = math.sin(math.radians(25.0))


def predict(obj: EntityState, horizon: float, step: float) -> np.ndarray:
    """Constant turn rate and velocity prediction of the footprint centre: rows (tau, x, y)."""
    taus = np.arange(0.0, horizon + 1e-9, step)
    h0, v, w = obj.heading, max(obj.speed, 0.0), obj.yaw_rate
    if abs(w) < 1e-3:
        hs = np.full_like(taus, h0)
        xs = obj.x + v * taus * math.cos(h0)
        ys = obj.y + v * taus * math.sin(h0)
    else:
        hs = h0 + w * taus
        xs = obj.x + v / w * (np.sin(hs) - math.sin(h0))
        ys = obj.y - v / w * (np.cos(hs) - math.cos(h0))
    xs = xs + obj.center_x * np.cos(hs)
    ys = ys + obj.center_x * np.sin(hs)
    return np.stack([taus, xs, ys], axis=1)


def yield_constraints(objs: list[PathObject], ego: EgoOnPath, line: RefLine, lp: LongitudinalParams,
                      bp: BehaviourParams, sp: StopPlan, v0: float) -> list[Constraint]:
    """Yield to movers whose predicted path crosses the ego's path ahead unless the ego clearly passes first."""
    out: list[Constraint] = []
    for po in objs:
        o = po.state
        if is_static(o) or o.speed < 0.3:
            continue
        if in_path(po, ego, 0.0, bp) and abs(po.rel_heading) <= bp.lead_heading_tolerance:
            continue                                     # a lead or a follower: IDM's business, not a crossing
        parallel = abs(math.sin(po.rel_heading)) < PARALLEL_SIN and abs(o.yaw_rate) < 0.05
        if parallel and not line.turns_across(o.heading, ego.s_front - 1.0, ego.s_front + 80.0, PARALLEL_SIN):
            continue                                     # keeps to a lane the route runs beside
        reach = ego.half_width + po.half_lat + bp.conflict_margin
        s_lo, s_hi = ego.s_front - 1.0, ego.s_front + 80.0
        if abs(o.yaw_rate) < 1e-3:
            # A straight course (as `predict` makes it): tested as one piece, before any point is computed.
            c, sn = math.cos(o.heading), math.sin(o.heading)
            ax, ay = o.x + o.center_x * c, o.y + o.center_x * sn
            run = max(o.speed, 0.0) * (bp.prediction_horizon + 1e-9)
            if line.far_from_straight(ax, ay, ax + run * c, ay + run * sn, reach, s_lo, s_hi):
                continue                                 # its course keeps clear of the path ahead
        traj = predict(o, bp.prediction_horizon, bp.prediction_step)
        far = line.far_points(traj[:, 1], traj[:, 2], reach, s_lo, s_hi)
        # Only the points that may come near the path ahead are projected (a point's projection does not depend
        # on the others': the hits are those of projecting them all).
        rows = np.arange(len(traj)) if far is None else np.flatnonzero(~far)
        if len(rows) == 0:
            continue                                     # its course keeps clear of the path ahead
        s, off = line.project_many(traj[rows, 1], traj[rows, 2])
        radius = 0.5 * max(o.length, o.width)
        hit = (np.abs(off) < reach) & (s > s_lo) & (s < s_hi)
        if parallel:
            # A mover keeping to a parallel lane (same way or oncoming) meets the route only where the route turns
            # across its course: the right turn across a cyclist riding on in the bike lane beside the ego. Where
            # the route runs beside it, it is not a crossing.
            hit &= np.array([abs(math.sin(line.heading(float(x)) - o.heading)) >= PARALLEL_SIN for x in s],
                            dtype=bool)
        idx = np.flatnonzero(hit)
        if len(idx) == 0:
            continue
        k = int(rows[idx[0]])
        tau, s_conf = float(traj[k, 0]), float(s[idx[0]])
        d = max(s_conf - radius - ego.s_front, 0.0)
        t_ego = _time_to_cover(d + 2.0 * radius + 2.0 * ego.half_width, ego.speed, v0, lp.max_accel)
        if t_ego + bp.conflict_time_gap < tau:
            continue                                     # the ego is through well before the other arrives
        stop_at = s_conf - radius
        entry = line.next_junction_entry(ego.s, stop_at - ego.s + 0.1)
        if entry is not None and entry < stop_at and _comfortable(entry - ego.s_front - lp.stop_margin, ego, sp):
            # Wait at the junction entry, not inside it; when that stop is no longer comfortable (a conflict seen
            # late), stop short of the conflict itself rather than brake hard for the entry.
            stop_at = entry
        dist = stop_at - ego.s_front
        if dist < -0.5:
            continue                                     # already committed past the conflict point
        out.append(stop_constraint(Reason.YIELD, dist, ego, lp, sp, o.name))
    return out


def _comfortable(d: float, ego: EgoOnPath, sp: StopPlan) -> bool:
    """Whether a stop within d metres needs no more than the planned deceleration (after the brake build-up)."""
    return ego.speed * ego.speed / (2.0 * max(d - sp.lag, 0.01)) <= sp.decel


def _time_to_cover(d: float, v: float, v_max: float, a: float) -> float:
    """Time to drive `d` metres from speed v accelerating at a up to v_max (s)."""
    v = max(v, 0.0)
    v_max = max(v_max, v, 0.1)
    d_acc = (v_max * v_max - v * v) / (2.0 * a)
    if d <= d_acc:
        return (-v + math.sqrt(v * v + 2.0 * a * d)) / a
    return (v_max - v) / a + (d - d_acc) / v_max


def signal_constraints(lights: tuple[TrafficLightState, ...], ego: EgoOnPath, line: RefLine,
                       lp: LongitudinalParams, bp: BehaviourParams, sp: StopPlan, emergency_decel: float, *,
                       misread_yellow: bool, yellow_stops: set[str] | None = None) -> list[Constraint]:
    """Stops for red and yellow lights on the route. `yellow_stops` (the planner's memory, updated here) holds the
    lights the ego decided to stop for at yellow onset: that decision is kept through the yellow (re-deciding
    while braking gently finds the stop "no longer comfortable", gives up and meets the red)."""
    out: list[Constraint] = []
    memory = yellow_stops if yellow_stops is not None else set()
    for light in lights:
        state = light.state
        if misread_yellow and state is SignalState.YELLOW:
            state = SignalState.GREEN                    # fault red_light_misread
        if state is not SignalState.YELLOW:
            memory.discard(light.id)
        if state not in (SignalState.RED, SignalState.YELLOW):
            continue
        lane_known = bool(light.road_id and light.lane_ids and line.lanes)
        if lane_known and not any(ref.road_id == light.road_id and ref.lane_id in light.lane_ids
                                  for ref in line.lanes):
            continue                                     # the signal governs lanes the route does not use
        pp = line.project(light.stop_x, light.stop_y, near_s=ego.s, window=bp.signal_lookahead + 20.0)
        # The stop point marks one of the lanes it governs: when the route's lane is known to be one of them it
        # may lie a lane or two to the side; otherwise only a stop point on the route's own lane counts.
        if (not lane_known and abs(pp.offset) > bp.signal_lateral_tolerance) \
                or abs(wrap_angle(light.heading - pp.heading)) > 0.8:
            continue
        dist = pp.s - ego.s_front
        if dist < -0.5 or dist > bp.signal_lookahead:
            continue
        d_stop = max(dist - lp.stop_margin, 0.01)
        need = ego.speed * ego.speed / (2.0 * d_stop)
        # Yellow: stop only if the stop is comfortable, counting the jerk-limited build-up of braking.
        need_planned = ego.speed * ego.speed / (2.0 * max(d_stop - min(sp.lag, 0.5 * d_stop), 0.01))
        if state is SignalState.YELLOW and light.id not in memory:
            if need_planned > bp.yellow_clear_decel:
                continue                                 # cannot stop comfortably: clear the junction
            memory.add(light.id)
        if state is SignalState.YELLOW and need > emergency_decel:
            continue                                     # committed, but cannot stop at all any more: clear it
        if state is SignalState.RED and need > emergency_decel:
            continue                                     # cannot stop before the line at all: clear it
        out.append(stop_constraint(Reason.RED if state is SignalState.RED else Reason.YELLOW, dist, ego, lp, sp,
                                   light.id))
    return out
