"""Longitudinal laws: IDM/ACC on the nearest in-path object, and a planned stop at a point (stop line, static
obstacle, yield point, goal).

IDM (Treiber, Hennecke & Helbing 2000): a = a_max·[1 − (v/v0)^δ − (s*/s)²],
s* = s0 + v·T + v·Δv / (2·√(a_max·b)), Δv = v − v_lead. The planned stop is kept separate from IDM because IDM's
approach to a standing target brakes harder than `b` at the end; a stop line wants a predictable constant
deceleration that starts where the braking distance (at the deceleration the road allows) says it must.
"""

from __future__ import annotations

import math

from .params import LongitudinalParams


#: Speed-tracking gain inside a curve (1/s): the speed error closes with a ~2 s time constant.
CURVE_GAIN = 0.5
#: Within this distance (m) of a stop point a stop in progress is held through to standstill.
CREEP_ZONE = 3.0
#: Standing within this distance (m) of a stop point, the ego waits there instead of creeping closer (the
#: jerk-limited switch from pulling away to braking would need more room than that).
HOLD_ZONE = 15.0


def free_road_accel(v: float, v0: float, p: LongitudinalParams) -> float:
    """IDM's free-road term: accelerate towards the desired speed v0 (m/s²)."""
    if v0 <= 0.0:
        return -p.comfort_decel if v > 0.0 else 0.0
    # (min/max in this module's per-step functions are written as the builtins' comparisons, max(a, b) being
    # `b if b > a else a` and min(a, b) `b if b < a else a`: the same values at a fifth of the cost)
    ratio = (0.0 if 0.0 > v else v) / v0
    return p.max_accel * (1.0 - ratio ** p.accel_exponent)


def idm_accel(v: float, v0: float, gap: float, v_lead: float, p: LongitudinalParams, *,
              decel: float | None = None, own_brake: float | None = None) -> float:
    """IDM acceleration (m/s²) behind a lead at bumper-to-bumper `gap` (m) moving at `v_lead` (m/s, along the
    path). `decel` replaces the comfortable deceleration b (the friction-aware stack lowers it on slippery roads).
    `own_brake` (m/s²) is the hardest braking the ego can count on; when it is below what a lead can do on a dry
    road (`max_decel`), the desired gap grows by the difference of the two braking distances (Gipps' safe-distance
    idea), so that on a slippery road the ego still stops behind a lead that brakes as hard as it can."""
    b = p.comfort_decel if decel is None else decel
    dv = v - v_lead
    s_star = p.min_gap + max(0.0, v * p.time_headway + v * dv / (2.0 * math.sqrt(p.max_accel * b)))
    if own_brake is not None and own_brake < p.max_decel:
        s_star += max(0.0, v * v / (2.0 * own_brake) - v_lead * v_lead / (2.0 * p.max_decel))
    gap = max(gap, 0.1)
    return free_road_accel(v, v0, p) - p.max_accel * (s_star / gap) ** 2


def braking_decel(p: LongitudinalParams, friction: float) -> float:
    """The deceleration (m/s², positive) the planner plans stops with on a road of `friction` coefficient:
    its planned stop deceleration, capped by a safety share of what the tyres can transmit."""
    tyres = p.friction_safety * friction * p.gravity
    return tyres if tyres < p.planned_stop_decel else p.planned_stop_decel


def stop_accel(v: float, distance: float, p: LongitudinalParams, *, plan_decel: float,
               cruise: float, lag: float = 0.0, braking: bool = False, hold: bool = True) -> float:
    """Acceleration (m/s²) to stop with the front bumper `distance` metres ahead (already net of the stop
    margin). `plan_decel` is the deceleration the stop is planned with; `cruise` is the acceleration wanted
    otherwise; `lag` metres are taken off the distance for the jerk-limited build-up of the braking. Braking starts
    once the required deceleration v²/2d reaches `stop_onset_ratio`·plan_decel; once `braking`, it holds the
    required deceleration down to a standstill (no release-and-creep in between). With `hold`, an ego standing
    within HOLD_ZONE of the point waits there (right for stop lines and obstacles, not for the goal itself).
    """
    if distance <= 0.05:
        if v <= 0.0:
            return min(0.0, cruise)
        # At the point: stop now; hard only if still fast (a crawl is stopped by the comfort taper).
        return -p.max_decel if v > 1.0 else -max(p.comfort_decel, v * v / 0.1)
    # The build-up allowance never takes more than half the distance: near the point it would ask for absurd
    # decelerations (v²/2d stays the honest requirement there).
    half = 0.5 * distance
    room = distance - (half if half < lag else lag)
    need = v * v / (2.0 * (0.05 if 0.05 > room else room))
    onset = p.stop_onset_ratio * plan_decel
    if need >= onset or (braking and v > 0.0 and (need >= 0.3 * onset or distance < CREEP_ZONE)):
        return -need
    if hold and v < 0.1 and distance < HOLD_ZONE:
        return min(cruise, 0.0)                # standing near the point: wait, do not creep up to it
    # Approaching a far stop point from low speed: go, but never faster than the plan can still stop from, and
    # not at all within the last metre (no creeping up to a stop line).
    v_cap = math.sqrt(2.0 * onset * max(distance - lag - CREEP_ZONE / 3.0, 0.0))
    if v >= v_cap:
        return min(cruise, 0.0)
    return cruise


def slow_down_accel(v: float, v_target: float, distance: float, p: LongitudinalParams, *, plan_decel: float,
                    lag: float, cruise: float) -> float:
    """Acceleration (m/s²) to be at `v_target` or slower `distance` metres ahead (a curve). Brakes at the required
    constant deceleration once it reaches `stop_onset_ratio`·plan_decel; `lag` metres are taken off the distance
    for the jerk-limited build-up of the braking. Inside the curve (distance ~0) it holds the curve's speed."""
    if distance <= 0.5:
        # In the curve: track its speed with a gentle proportional law (IDM's free-road term above v0 is harsh).
        return min(cruise, CURVE_GAIN * (v_target - v))
    if v <= v_target:
        return cruise
    need = (v * v - v_target * v_target) / (2.0 * max(distance - min(lag, 0.5 * distance), 0.1))
    if need >= p.stop_onset_ratio * plan_decel:
        return -need
    # Close to the onset: stop accelerating so the braking starts from a steady speed.
    return cruise if need < 0.5 * p.stop_onset_ratio * plan_decel else min(cruise, 0.0)
