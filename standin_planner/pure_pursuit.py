"""Lateral control: pure pursuit on the route's centre line (Coulter 1992), for a vehicle that takes a yaw rate.

The look-ahead point lies L = lookahead_min + lookahead_gain·v metres ahead of the ego's projection on the line
(shifted sideways by the behaviour layer's lane offset when passing an obstacle). The arc through the rear axle and
that point has curvature κ = 2·sin(α)/L, α being the bearing of the point in the vehicle frame; the yaw rate is v·κ.
"""

from __future__ import annotations

import bisect
import math

import numpy as np

from .params import LateralParams
from .refline import RefLine, wrap_angle


def lookahead_distance(v: float, p: LateralParams) -> float:
    return p.lookahead_min + p.lookahead_gain * max(v, 0.0)


def pursuit_curvature(x: float, y: float, heading: float, s_ego: float, v: float, line: RefLine,
                      p: LateralParams, *, offset: float = 0.0) -> float:
    """Curvature (1/m, positive = left) of the arc that takes the rear axle at (x, y, heading) to the look-ahead
    point of `line` at `offset` metres left of it."""
    L = lookahead_distance(v, p)
    tx, ty, _ = line.position(s_ego + L, offset)
    dx, dy = tx - x, ty - y
    dist = math.hypot(dx, dy)
    if dist < 1e-6:
        return 0.0
    alpha = wrap_angle(math.atan2(dy, dx) - heading)
    return 2.0 * math.sin(alpha) / dist


def curve_speed(kappa: float, p: LateralParams) -> float:
    """Highest speed (m/s) on a curve of curvature `kappa`: min(√(a_lat/κ), ω_max/κ); the second keeps the yaw
    rate inside the smoothness band (±10 °/s), and is the binding one on urban junction turns."""
    k = abs(kappa)
    if k < 1e-4:
        return math.inf
    return min(math.sqrt(p.max_lateral_accel / k), 0.95 * p.max_yaw_rate / k)


def curve_speed_profile(line: RefLine, p: LateralParams) -> list[float]:
    """`curve_speed` of every vertex's |curvature|, computed once per line and parameters (the line's cache):
    the per-step curve check then only compares and slices. Vectorised with the scalar form's operations in its
    order (sqrt and division are correctly rounded in numpy as in `math`), so every value is bit-identical."""
    key = ("curve_speed", p.max_lateral_accel, p.max_yaw_rate)
    cached = line.cache.get(key)
    if cached is None:
        k = np.abs(line.curvature)
        with np.errstate(divide="ignore", invalid="ignore"):
            vc = np.minimum(np.sqrt(p.max_lateral_accel / k), 0.95 * p.max_yaw_rate / k)
        cached = np.where(k < 1e-4, math.inf, vc).tolist()
        line.cache[key] = cached
    return cached


def curve_targets(line: RefLine, s_ego: float, v: float, v_max: float, p: LateralParams, decel: float
                  ) -> list[tuple[float, float]]:
    """(distance ahead, speed limit) of the curve samples from just behind the ego to its braking horizon whose
    limit is below `v_max` (the speed the ego would otherwise aim for)."""
    horizon = max(p.curve_preview, v * v / (2.0 * decel) + 3.0 * v + 5.0)
    limits = curve_speed_profile(line, p)
    # The vertices whose limit is below v_max, once per line and v_max (the planner's v_max is its desired speed).
    key = ("curve_below", p.max_lateral_accel, p.max_yaw_rate, v_max)
    below = line.cache.get(key)
    if below is None:
        below = [i for i, vc in enumerate(limits) if vc < v_max]
        line.cache[key] = below
    s_all = line.s_list
    # The vertices with s0 <= s <= s1, as `max_abs_curvature` selects them (s is sorted): index range [lo, hi).
    lo = bisect.bisect_left(s_all, s_ego - 2.0)
    hi = bisect.bisect_right(s_all, s_ego + horizon)
    return [(max(s_all[i] - s_ego, 0.0), limits[i])
            for i in below[bisect.bisect_left(below, lo):bisect.bisect_left(below, hi)]]
