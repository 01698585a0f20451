"""The ego's longitudinal acceleration, jerk and yaw rate, differentiated from the frames themselves.

Why differentiate instead of reading `EntityState.accel` / `yaw_rate`: a bag recorded from a real stack carries
speeds and poses but rarely an acceleration, so only finite differences give the same figures live, offline and on
any recording. For the lock-step player (speed = v + a·dt) they equal the simulator's own values.

Sampling: a_k = (v_k - v_{k-1}) / (t_k - t_{k-1}) sits at the midpoint of its interval, and
j_k = (a_k - a_{k-1}) / (mid_k - mid_{k-1}); the yaw rate is the wrapped heading change over the interval.
"""

from __future__ import annotations

import math
from typing import NamedTuple

from txt2sce_ros.contract import EntityState


class Sample(NamedTuple):
    t: float
    dt: float                  # s since the previous frame
    speed: float               # m/s
    accel: float | None        # m/s², None on the first frame
    jerk: float | None         # m/s³, None on the first two frames
    yaw_rate: float | None     # rad/s, None on the first frame


class Differentiator:
    """Feeds on one entity's states in time order; frames with a non-increasing time are ignored (None)."""

    __slots__ = ("_t", "_v", "_h", "_a", "_mid")

    def __init__(self) -> None:
        self._t: float | None = None
        self._v = 0.0
        self._h = 0.0
        self._a: float | None = None
        self._mid = 0.0

    def update(self, e: EntityState) -> Sample | None:
        if self._t is None:
            self._t, self._v, self._h = e.t, e.speed, e.heading
            return Sample(e.t, 0.0, e.speed, None, None, None)
        dt = e.t - self._t
        if dt <= 0.0:
            return None
        accel = (e.speed - self._v) / dt
        mid = 0.5 * (e.t + self._t)
        jerk = None if self._a is None else (accel - self._a) / (mid - self._mid)
        yaw_rate = math.remainder(e.heading - self._h, math.tau) / dt
        self._t, self._v, self._h, self._a, self._mid = e.t, e.speed, e.heading, accel, mid
        return Sample(e.t, dt, e.speed, accel, jerk, yaw_rate)
