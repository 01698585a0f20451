"""The way ahead of the ego, as the oracle judges "a clear path": the lane route from where the ego starts to its goal
on the road model, and what stands on it or is about to cross it.

A standing ego is only a failure (StartFail, PlanFail `stopped_mid_route`) when nothing gives it a reason to wait.
Two reasons count:
- something stands or moves in the corridor `clear_distance` metres along the path ahead of the front bumper (ego
  width plus `clear_margin` each side): along the route, so an ego waiting to turn looks into the turn, not
  straight across it;
- a mover is about to cross the path: its constant-velocity course meets the path within `conflict_distance`
  metres ahead of the front bumper within `conflict_horizon` seconds, crossing it (heading more than
  `CROSSING_DEG` off the path's there). An ego turning left that waits for an oncoming van is yielding, not failing
  to start. A party coming up behind along the path, or leading away ahead of it, is never a reason: it does not
  cross, so waiting for it is still judged.

The route is the road model's (`RoadNetwork.route`), never the planner's: the oracle must not depend on the system
under test. Without a network, a goal or a route, the path is the straight line ahead of the ego.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from txt2sce_ros.contract import EntityState, Goal

from .geometry import FAR_SLACK, BoxGroup, footprint

#: A mover counts as crossing the path when its heading differs from the path's by more than this (deg).
CROSSING_DEG = 25.0
#: Spacing of the path samples and of the predicted course (m, s).
SAMPLE_DS = 1.0
PREDICT_DT = 0.25
#: The straight stand-in path when there is no route: this long (m).
STRAIGHT_LENGTH = 200.0

#: Paths planned lately, by network and the exact bits of the ego's and the goal's poses (`EgoPath.plan`).
_PLANNED: dict[tuple, tuple[np.ndarray, bool]] = {}
_PLANNED_SIZE = 64


class EgoPath:
    """A polyline (x, y, heading per sample, arc length `s`) the ego is expected to drive along."""

    def __init__(self, xyh: np.ndarray, *, routed: bool) -> None:
        self.xyh = xyh
        seg = np.hypot(np.diff(xyh[:, 0]), np.diff(xyh[:, 1]))
        self.s = np.concatenate([[0.0], np.cumsum(seg)])
        self.routed = routed
        self._s_hint = 0.0
        self._located: tuple[tuple[float, float, float], float] | None = None   # last (x, y, hint) -> answer
        self._corridor: tuple[tuple[float, ...], BoxGroup | None] | None = None  # last corridor by its inputs
        self._answers: tuple[BoxGroup | None, dict] = (None, {})       # the corridor's answers by footprint

    @classmethod
    def straight(cls, ego: EntityState) -> "EgoPath":
        s = np.arange(-10.0, STRAIGHT_LENGTH, SAMPLE_DS)
        c, sn = math.cos(ego.heading), math.sin(ego.heading)
        return cls(np.column_stack([ego.x + s * c, ego.y + s * sn, np.full(len(s), ego.heading)]), routed=False)

    @classmethod
    def plan(cls, network: Any | None, ego: EntityState, goal: Goal | None) -> "EgoPath":
        """The lane route from the ego's pose to the goal on `network`; the straight line ahead when there is no
        network, no goal, or the road model finds no route (a goal off the road, a start on no lane).

        The samples depend on nothing else, so they are remembered (read-only) by network and the exact bits of
        the pose and the goal's pose: a campaign worker runs the nodes of a scenario tree one after another, most
        of them with the ego standing at the same start with the same goal on the same (cached) network. Each
        call still gets its own path (its located point and corridor are its own)."""
        if network is None or goal is None:
            return cls.straight(ego)
        key = (network, *(float(v).hex() for v in (ego.x, ego.y, ego.heading, goal.x, goal.y, goal.heading)))
        known = _PLANNED.get(key)
        if known is None:
            path = cls._plan(network, ego, goal)
            path.xyh.flags.writeable = False
            if len(_PLANNED) >= _PLANNED_SIZE:
                _PLANNED.pop(next(iter(_PLANNED)))
            _PLANNED[key] = known = (path.xyh, path.routed)
        return cls(known[0], routed=known[1])

    @classmethod
    def _plan(cls, network: Any, ego: EntityState, goal: Goal) -> "EgoPath":
        try:
            from txt2sce_ros.road import LanePath

            start = network.locate(ego.x, ego.y, ego.heading)
            end = network.locate(goal.x, goal.y, goal.heading)
            if start is None or end is None:
                return cls.straight(ego)
            lanes = [start.ref] if start.ref == end.ref else network.route(start.ref, end.ref)
            path = LanePath.from_lanes(network, lanes, s_start=start.s, s_end=end.s if start.ref != end.ref
                                       or _ahead(network, start, end) else None)
            n = max(2, int(path.length / SAMPLE_DS) + 1)
            xyh = path.positions(np.linspace(0.0, path.length, n))
        except Exception:           # a map the road model cannot route on: judge along the straight line instead
            return cls.straight(ego)
        if len(xyh) < 2 or path.length < 1.0:
            return cls.straight(ego)
        # Past the goal the way goes on as straight as the last heading: a standing ego near its goal still looks
        # the full corridor ahead.
        h = float(xyh[-1, 2])
        tail = np.arange(SAMPLE_DS, STRAIGHT_LENGTH, SAMPLE_DS)
        ext = np.column_stack([xyh[-1, 0] + tail * math.cos(h), xyh[-1, 1] + tail * math.sin(h), np.full(len(tail), h)])
        return cls(np.vstack([xyh, ext]), routed=True)

    def locate(self, x: float, y: float) -> float:
        """Arc length of the path point nearest to (x, y), searched near the last answer first (the path may come
        back near itself). The answer depends on the point and the last answer only, so the last one is kept: a
        standing ego asks the same question every step."""
        key = (x, y, self._s_hint)
        if self._located is not None and self._located[0] == key:
            s = self._located[1]
            self._s_hint = s
            return s
        lo = int(np.searchsorted(self.s, self._s_hint - 30.0))
        hi = int(np.searchsorted(self.s, self._s_hint + 60.0)) + 1
        d2 = (self.xyh[lo:hi, 0] - x) ** 2 + (self.xyh[lo:hi, 1] - y) ** 2
        if len(d2) == 0 or float(d2.min()) > 25.0:           # lost the thread (or first call): the whole path
            lo, d2 = 0, (self.xyh[:, 0] - x) ** 2 + (self.xyh[:, 1] - y) ** 2
        s = float(self.s[lo + int(np.argmin(d2))])
        self._located = (key, s)
        self._s_hint = s
        return s

    def window(self, s0: float, length: float) -> np.ndarray:
        """The samples with arc length in [s0, s0 + length]: rows x, y, heading."""
        i0, i1 = np.searchsorted(self.s, [s0, s0 + length])
        return self.xyh[i0:max(i1, i0 + 1)]

    def blocker(self, ego: EntityState, front: tuple[float, float], objects: tuple[EntityState, ...], *,
                clear_distance: float, margin: float) -> str:
        """Name of an entity whose footprint lies in the corridor ahead of the front bumper ('' when none): the
        path samples' boxes (`SAMPLE_DS` long, ego width plus `margin` each side) over `clear_distance`."""
        group = self.corridor(self.locate(*front), clear_distance, 0.5 * ego.width + margin)
        if group is None:
            return ""
        # Answers by footprint for this corridor: a standing ego and the parties standing around it ask the same.
        if self._answers[0] is not group:
            self._answers = (group, {})
        answers = self._answers[1]
        for obj in objects:
            fp = footprint(obj)
            hit = answers.get(fp)
            if hit is None:
                if len(answers) >= 256:
                    answers.clear()
                hit = answers[fp] = group.overlapped_by(fp)
            if hit:
                return obj.name
        return ""

    def corridor(self, s0: float, length: float, half_width: float) -> BoxGroup | None:
        """The boxes of the path samples in [s0, s0 + length] (None: no sample there); the last one is kept, since
        a standing ego asks for the same corridor every step."""
        key = (s0, length, half_width)
        if self._corridor is not None and self._corridor[0] == key:
            return self._corridor[1]
        pts = self.window(s0, length)
        group = None if len(pts) == 0 else BoxGroup(pts[:, 0], pts[:, 1], pts[:, 2], 0.5 * SAMPLE_DS + 0.05,
                                                     half_width)
        self._corridor = (key, group)
        return group

    def crossing(self, ego: EntityState, front: tuple[float, float], objects: tuple[EntityState, ...], *,
                 distance: float, horizon: float, margin: float, min_speed: float) -> str:
        """Name of a mover whose constant-velocity course crosses the path within `distance` m ahead of the front
        bumper within `horizon` s ('' when none)."""
        pts = self.window(self.locate(*front), distance)
        if len(pts) == 0:
            return ""
        taus = np.arange(0.0, horizon + 1e-9, PREDICT_DT)
        min_sin = math.sin(math.radians(CROSSING_DEG))
        box = None                              # the window's bounding box, once a mover needs it
        for obj in objects:
            if obj.is_static or obj.speed < min_speed:
                continue
            c, s = math.cos(obj.heading), math.sin(obj.heading)
            cx, cy = obj.x + obj.center_x * c, obj.y + obj.center_x * s
            qx, qy = cx + obj.speed * taus * c, cy + obj.speed * taus * s
            reach = 0.5 * ego.width + 0.5 * obj.width + margin
            if box is None:
                box = (float(pts[:, 0].min()), float(pts[:, 0].max()), float(pts[:, 1].min()),
                       float(pts[:, 1].max()))
            if course_apart(qx, qy, box, reach):
                continue                        # no predicted point within reach of any path sample
            d2 = (qx[:, None] - pts[None, :, 0]) ** 2 + (qy[:, None] - pts[None, :, 1]) ** 2
            hit = np.argwhere(d2 <= reach * reach)
            if len(hit) == 0:
                continue
            j = int(hit[0, 1])
            if abs(math.sin(obj.heading - float(pts[j, 2]))) >= min_sin:
                return obj.name
        return ""


def course_apart(qx: np.ndarray, qy: np.ndarray, box: tuple[float, float, float, float], reach: float) -> bool:
    """Whether the predicted course (qx, qy) keeps more than `reach` + `FAR_SLACK` from the box (x0, x1, y0, y1)
    along x or along y: then every point of it is that far from every path sample in the box, and `crossing`'s
    distance test (d² <= reach²) holds for none (a conservative pre-test; 1 mm of slack is far above the
    rounding of d²). The course is start + speed·tau·(cos, sin) over increasing tau, each coordinate computed
    by operations that keep order, so its first and last points bound it."""
    far = reach + FAR_SLACK
    x0, x1, y0, y1 = box
    qx0, qx1, qy0, qy1 = float(qx[0]), float(qx[-1]), float(qy[0]), float(qy[-1])
    return (min(qx0, qx1) - x1 > far or x0 - max(qx0, qx1) > far
            or min(qy0, qy1) - y1 > far or y0 - max(qy0, qy1) > far)


def _ahead(network: Any, start: Any, end: Any) -> bool:
    """On one lane: whether the goal lies ahead of the start in the lane's driving direction."""
    forward = network.lane_forward(start.ref.road_id, start.ref.lane_id, start.s)
    return (end.s >= start.s) if forward else (end.s <= start.s)
