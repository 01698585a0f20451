"""What the planner perceives: the player's ground-truth objects, optionally delayed and noisy.

Perception here is a stand-in for Autoware's detection + tracking: it passes the objects of the `/sim/objects/*`
topics through, with (a) latency: object states as they were `latency` seconds ago (a tracker that publishes late and
does not predict to the present), (b) Gaussian position / speed noise from a seeded generator. The ego's own state
(localisation) is never degraded.

The `stale_tracking` fault is a tracker whose measurements are `stale_tracking_delay` seconds old but which predicts
them to the present at constant velocity: while a lead keeps its speed this is exact, when it brakes the planner
sees it still moving (ahead of where it is, too fast) for that long, which is what makes a stale tracker rear-end.
"""

from __future__ import annotations

import dataclasses
import math
from collections import deque

import numpy as np

from txt2sce_ros.contract import EntityState, Frame

from .behaviour import is_static
from .faults import CYCLIST_CATEGORIES, Faults
from .params import FaultParams, PerceptionParams


class Perception:
    """Turns each frame's objects into the planner's object list. Deterministic for a given seed."""

    def __init__(self, params: PerceptionParams, faults: Faults, fault_params: FaultParams) -> None:
        self.params = params
        self.faults = faults
        self.stale = fault_params.stale_tracking_delay if faults.stale_tracking else 0.0
        self.delay = max(params.latency, self.stale)
        self._rng = np.random.default_rng(params.seed)
        self._history: deque[tuple[float, tuple[EntityState, ...]]] = deque()

    def objects(self, frame: Frame) -> tuple[EntityState, ...]:
        objs = frame.objects
        if self.faults.ignore_cyclists:
            objs = tuple(o for o in objs if o.category not in CYCLIST_CATEGORIES)
        if self.delay > 0.0:
            objs = self._delayed(frame.t, objs)
            if self.stale > 0.0:
                objs = tuple(_predict(o, frame.t) for o in objs)
        if self.params.position_noise > 0.0 or self.params.speed_noise > 0.0:
            objs = tuple(self._noisy(o) for o in objs)
        return objs

    def _delayed(self, t: float, objs: tuple[EntityState, ...]) -> tuple[EntityState, ...]:
        self._history.append((t, objs))
        # Keep exactly what is needed: the newest snapshot at least `delay` old (or the oldest one held).
        while len(self._history) > 1 and self._history[1][0] <= t - self.delay + 1e-9:
            self._history.popleft()
        # Entities that appeared since then are not yet tracked; entities that left are still reported.
        return self._history[0][1]

    def _noisy(self, o: EntityState) -> EntityState:
        pn, sn = self.params.position_noise, self.params.speed_noise
        dx = float(self._rng.normal(0.0, pn)) if pn > 0 else 0.0
        dy = float(self._rng.normal(0.0, pn)) if pn > 0 else 0.0
        # A static object's speed is known to be zero (the tracker classifies it as static).
        dv = float(self._rng.normal(0.0, sn)) if sn > 0 and not is_static(o) else 0.0
        return dataclasses.replace(o, x=o.x + dx, y=o.y + dy, speed=o.speed + dv)


def _predict(o: EntityState, t: float) -> EntityState:
    """The state `o` predicted to time t at constant speed and heading."""
    dt = t - o.t
    if dt <= 0.0 or is_static(o):
        return o
    return dataclasses.replace(o, t=t, x=o.x + o.speed * dt * math.cos(o.heading),
                               y=o.y + o.speed * dt * math.sin(o.heading))
