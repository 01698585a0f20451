"""1-D speed profiles and lateral-offset profiles of the planned events, and the box-overlap test, used to time
the seed (who must start where so that both parties reach the conflict together) and to predict its outcome."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .boxes import box_corners, boxes_gap  # noqa: F401  (the box tests live in `boxes`; seed modules import them here)

DT = 0.05


@dataclass(frozen=True, slots=True)
class SpeedStep:
    t: float          # s, start of the transition
    target: float     # m/s
    duration: float   # s, linear ramp


@dataclass(frozen=True, slots=True)
class LateralStep:
    t: float
    delta: float      # m, to the left of travel
    duration: float


def transition_time(v_from: float, v_to: float, *, accel: float = 3.0, minimum: float = 1.0) -> float:
    """Seconds for a comfortable linear speed change (a_comfort = 3 m/s², at least `minimum`)."""
    return round(max(minimum, abs(v_to - v_from) / accel), 2)


def speed_profile(v0: float, steps: list[SpeedStep], horizon: float, dt: float = DT
                  ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(t, v, d): speed and travelled distance at every dt up to `horizon` (signed: reverse runs d down)."""
    t = np.arange(0.0, horizon + dt / 2, dt)
    v = np.full_like(t, v0, dtype=float)
    cur = v0
    for st in sorted(steps, key=lambda s: s.t):
        i0 = int(round(st.t / dt))
        if i0 >= len(t):
            break
        start_v = v[i0]
        dur = max(st.duration, dt)
        n = int(round(dur / dt))
        ramp = start_v + (st.target - start_v) * np.clip(np.arange(1, len(t) - i0 + 1) / n, 0.0, 1.0)
        v[i0:] = ramp
        cur = st.target
    del cur
    d = np.concatenate([[0.0], np.cumsum((v[1:] + v[:-1]) / 2 * dt)])
    return t, v, d


def lateral_profile(lat0: float, steps: list[LateralStep], t: np.ndarray) -> np.ndarray:
    lat = np.full_like(t, lat0, dtype=float)
    for st in steps:
        u = np.clip((t - st.t) / max(st.duration, 1e-6), 0.0, 1.0)
        lat += st.delta * (0.5 - 0.5 * np.cos(math.pi * u))  # sinusoidal, as the LaneChangeAction's shape
    return lat


def time_to_reach(t: np.ndarray, d: np.ndarray, target: float) -> float | None:
    """First time the travelled distance reaches `target` (None if never)."""
    idx = np.nonzero(d >= target - 1e-6)[0]
    return float(t[idx[0]]) if idx.size else None
