"""Smoothness oracles: 1 s moving averages of the ego's longitudinal jerk and yaw rate (paper §III-D.2, §IV).

The paper's formula is the mean of the last N samples, N spanning one second: jerk_avg(t) = 1/N Σ jerk_i. The
average is judged only once a full window of samples exists (before that it would be the mean of fewer samples
than the formula asks for).

Reading of the jerk interval I_sj = [0, 0.9] m/s³: taken literally, every braking manoeuvre (negative jerk
average) would be "unsmooth" and so would any smooth run whose jerk dips below zero by a hair. The cited comfort
studies (Martin & Litkouhi; Nguyen et al.) bound the *magnitude* of jerk, so the default `jerk_mode: magnitude`
judges |jerk_avg| <= 0.9 m/s³ (the interval [0, 0.9] being the range of |jerk_avg|). `jerk_mode: signed` applies
the interval to the signed average, as printed. The yaw-rate interval ±10 °/s is symmetric already.

One violation is raised when an average leaves its band; the next one only after it has come back.
"""

from __future__ import annotations

import math
from collections import deque

from .params import SmoothnessParams
from .records import Category, Rule, Violation
from .signals import Sample


class MovingAverage:
    """Mean of the samples whose time lies in (t - window, t], with a running sum (O(1) per sample)."""

    __slots__ = ("window", "_q", "_sum", "_start")

    def __init__(self, window: float) -> None:
        self.window = window
        self._q: deque[tuple[float, float]] = deque()
        self._sum = 0.0
        self._start: float | None = None       # start of the first sampled interval

    def push(self, t: float, value: float, dt: float) -> float | None:
        """Add the sample at `t` covering (t - dt, t]; the mean once the samples cover a full window, else None."""
        if self._start is None:
            self._start = t - dt
        q = self._q
        q.append((t, value))
        self._sum += value
        edge = t - self.window + 1e-9
        while q[0][0] <= edge:
            self._sum -= q.popleft()[1]
        if t - self._start < self.window - 1e-9:
            return None
        return self._sum / len(q)


class _Band:
    """Edge detector: fires when a value leaves [low, high] and re-arms when it comes back."""

    __slots__ = ("low", "high", "_out")

    def __init__(self, low: float, high: float) -> None:
        self.low, self.high = low, high
        self._out = False

    def check(self, value: float) -> bool:
        out = value < self.low or value > self.high
        fire = out and not self._out
        self._out = out
        return fire


class SmoothnessOracle:
    def __init__(self, params: SmoothnessParams) -> None:
        self.params = params
        self._jerk = MovingAverage(params.window)
        self._yaw = MovingAverage(params.window)
        self._jerk_band = _Band(params.jerk_low, params.jerk_high)
        lim = params.yaw_rate_limit
        self._yaw_band = _Band(-lim, lim)
        self.peak_jerk = 0.0                   # largest |jerk_avg| seen, m/s³
        self.peak_yaw_rate = 0.0               # largest |yaw_avg| seen, rad/s

    def observe(self, s: Sample) -> list[Violation]:
        out: list[Violation] = []
        if s.speed < self.params.min_speed:
            return out
        p = self.params
        if s.jerk is not None:
            avg = self._jerk.push(s.t, s.jerk, s.dt)
            if avg is not None:
                judged = abs(avg) if p.jerk_mode == "magnitude" else avg
                self.peak_jerk = max(self.peak_jerk, abs(avg))
                if self._jerk_band.check(judged):
                    bound = p.jerk_high if judged > p.jerk_high else p.jerk_low
                    out.append(Violation(Rule.SMOOTH_JERK, Category.SMOOTH, s.t, avg, bound, "m/s³", (),
                                         f"{p.window:g} s mean jerk {avg:+.3f} m/s³ outside "
                                         f"[{p.jerk_low:g}, {p.jerk_high:g}] ({p.jerk_mode})"))
        if s.yaw_rate is not None:
            avg = self._yaw.push(s.t, s.yaw_rate, s.dt)
            if avg is not None:
                self.peak_yaw_rate = max(self.peak_yaw_rate, abs(avg))
                if self._yaw_band.check(avg):
                    deg = math.degrees(avg)
                    out.append(Violation(Rule.SMOOTH_YAW_RATE, Category.SMOOTH, s.t, deg,
                                         math.copysign(p.yaw_rate_limit_deg, deg), "deg/s", (),
                                         f"{p.window:g} s mean yaw rate {deg:+.2f} °/s outside "
                                         f"±{p.yaw_rate_limit_deg:g} °/s"))
        return out
