"""Failures the scripted parties made unavoidable: which categories of a failed run say nothing about the planner.

The parties of a scenario follow their storyboard whatever the ego does, so some failures are decided at t = 0.
Each check replays the run's recorded parties against an ego that had done the one safe thing from its start, and
labels the category when even that ego fails:

- Collisions: the ego brakes from its start at `unavoidable_decel` (harder than any planner plans, so a label is
  never given to a crash some braking could have avoided) and a party's recorded footprint still meets its
  footprint: the party reaches the ego before it could stop (a party that hits a standing ego is the limit case).
- Smooth: the ego stops from its start with the smoothest stop the smoothness band allows (jerk ramped at
  `jerk_high` down and back up, so every 1 s mean of jerk stays inside the band) and a party still meets it:
  avoiding that party took braking harder than the band, whoever drives.
- PlanFail (goal not reached): at the end a party that moved during the run is on the ego's path ahead (within
  `clear_distance`): the scripted party set the pace and the story ended first. A parked or static object is not a
  label: a planner is expected to pass it.

The counterfactual ego follows the recorded path of the real ego (so it stays on its lane and route) with the
braking profile's distance-over-time; past the end of the recorded path it goes on straight.
"""

from __future__ import annotations

import bisect
import math
from dataclasses import dataclass, field
from typing import Callable

import numpy as np

from txt2sce_ros.contract import EntityState, Frame

from .geometry import FAR_SLACK, Box, BoxGroup, box_at, far_apart, footprint, overlaps
from .records import Category, Unavoidable


def emergency_stop(v0: float, decel: float) -> Callable[[float], float]:
    """Distance (m) after t s of braking at `decel` from v0, until standstill."""
    t_stop = v0 / decel if decel > 0 else math.inf

    def d(t: float) -> float:
        t = min(max(t, 0.0), t_stop)
        return v0 * t - 0.5 * decel * t * t
    return d


def smooth_stop(v0: float, jerk: float) -> Callable[[float], float]:
    """Distance (m) after t s of the smoothest stop from v0 whose jerk stays within ±`jerk`: deceleration ramps up
    at `jerk` to sqrt(jerk·v0) and back down to zero at standstill (T = 2·sqrt(v0/jerk), distance v0·T/2)."""
    if v0 <= 0.0 or jerk <= 0.0:
        return lambda t: 0.0
    half = math.sqrt(v0 / jerk)
    total = v0 * half

    def d(t: float) -> float:
        if t <= 0.0:
            return 0.0
        if t <= half:
            return v0 * t - jerk * t ** 3 / 6.0
        if t <= 2.0 * half:
            return total - jerk * (2.0 * half - t) ** 3 / 6.0
        return total
    return d


#: How far ahead (s) a party's constant-velocity course is projected to tell when its conflict became foreseeable.
FORESIGHT = 5.0
FORESIGHT_DT = 0.25
#: Where along the ego's path ahead (m) the foreseeable check looks.
AHEAD_STEPS = tuple(float(d) for d in range(0, 61, 2))
#: Slack (m) on `Counterfactual._stretch_circle`'s radius, for the rounding of the path's distances (sums of a few
#: hundred hypots): far above it, far below any footprint.
STRETCH_SLACK = 1e-3


@dataclass
class Counterfactual:
    """Records the ego's path and every party's footprint per frame, and replays them against a braking ego."""

    times: list[float] = field(default_factory=list)
    ego: list[tuple[float, float, float, float, float]] = field(default_factory=list)  # x, y, heading, speed, dist
    dists: list[float] = field(default_factory=list)      # the ego's travelled distance per frame (for bisect)
    parties: list[list[EntityState]] = field(default_factory=list)                      # per frame
    moved: set[str] = field(default_factory=set)          # parties seen moving at some frame
    first: EntityState | None = None
    # Asked once the run is over (after the last `observe`): the path ahead per frame, and answers by party.
    _ahead_groups: dict[int, BoxGroup] = field(default_factory=dict, repr=False)
    _foreseen: dict[tuple[str, float], int | None] = field(default_factory=dict, repr=False)
    _boxes: dict[int, list[Box]] = field(default_factory=dict, repr=False)     # per frame, kept as recorded
    _ahead_circles: dict[int, tuple[float, float, float]] = field(default_factory=dict, repr=False)
    _reach: tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray] | None = field(default=None, repr=False)

    def observe(self, frame: Frame) -> None:
        if self._ahead_groups or self._foreseen or self._ahead_circles or self._reach is not None:
            self._ahead_groups.clear()        # the path driven grew: what was asked before no longer holds
            self._foreseen.clear()
            self._ahead_circles.clear()
            self._reach = None
        e = frame.ego
        if self.first is None:
            self.first = e
            dist = 0.0
        else:
            x0, y0 = self.ego[-1][0], self.ego[-1][1]
            dist = self.dists[-1] + math.hypot(e.x - x0, e.y - y0)
        self.times.append(frame.t)
        self.ego.append((e.x, e.y, e.heading, max(e.speed, 0.0), dist))
        self.dists.append(dist)
        self.parties.append(list(frame.objects))
        self.moved.update(o.name for o in frame.objects if abs(o.speed) > 0.1 and not o.is_static)

    def _ego_pose(self, dist: float) -> tuple[float, float, float]:
        """The ego's (x, y, heading) `dist` metres along its recorded path (straight on past its end)."""
        i = max(bisect.bisect_right(self.dists, dist) - 1, 0)
        x0, y0, h0, _, d0 = self.ego[i]
        j = i + 1
        while j < len(self.ego) and self.dists[j] - d0 < 1e-6:
            j += 1
        if j < len(self.ego):
            x1, y1, _, _, d1 = self.ego[j]
            u = (dist - d0) / (d1 - d0)
            return x0 + u * (x1 - x0), y0 + u * (y1 - y0), math.atan2(y1 - y0, x1 - x0)
        over = dist - d0
        return x0 + over * math.cos(h0), y0 + over * math.sin(h0), h0

    def _ego_box(self, dist: float) -> Box:
        """The ego's footprint `dist` metres along its recorded path (straight on past its end)."""
        e = self.first
        assert e is not None
        return box_at(*self._ego_pose(dist), e.center_x, e.length, e.width)

    def _stretch_circle(self, d0: float, d1: float) -> tuple[float, float, float]:
        """(x, y, radius): a circle holding the ego's footprint at every distance in [d0, d1] along its recorded
        path (`_ego_box`). `_ego_pose` moves along straight pieces between recorded points (each no longer than the
        distance it adds) and straight on past the end, so the pose at d lies within |d - m| of the pose at the
        midpoint m; the footprint's centre is `center_x` from the pose and its corners its half diagonal from that."""
        e = self.first
        assert e is not None
        mid = 0.5 * (d0 + d1)
        x, y, _ = self._ego_pose(mid)
        half = math.hypot(0.5 * e.length, 0.5 * e.width)
        return x, y, 0.5 * (d1 - d0) + abs(e.center_x) + half + STRETCH_SLACK

    def _ahead_circle(self, k: int) -> tuple[float, float, float]:
        """`_stretch_circle` of the path `_ahead(k)` covers: every box of that group lies inside it, so a party
        clear of it is clear of the group, without the group's 31 poses being worked out."""
        circle = self._ahead_circles.get(k)
        if circle is None:
            d = self.dists[k]
            circle = self._ahead_circles[k] = self._stretch_circle(d + AHEAD_STEPS[0], d + AHEAD_STEPS[-1])
        return circle

    def _ahead(self, k: int) -> BoxGroup:
        """The ego's footprints along the `AHEAD_STEPS` of the path it drove on from frame k (the same for every
        party and braking profile asked about, so built once per frame)."""
        group = self._ahead_groups.get(k)
        if group is None:
            e = self.first
            assert e is not None
            xs, ys, hs = [], [], []
            dists, ego, n = self.dists, self.ego, len(self.ego)
            cos, sin, atan2, center_x = math.cos, math.sin, math.atan2, e.center_x
            lo = 0
            for step in AHEAD_STEPS:
                # `_ego_pose(dist)` written out; the distances increase, so each bisection starts where the last
                # ended (the same index: every recorded distance before it is <= the last distance asked)
                dist = dists[k] + step
                lo = bisect.bisect_right(dists, dist, lo)
                i = lo - 1 if lo > 0 else 0
                x0, y0, h0, _, d0 = ego[i]
                j = i + 1
                while j < n and dists[j] - d0 < 1e-6:
                    j += 1
                if j < n:
                    x1, y1, _, _, d1 = ego[j]
                    u = (dist - d0) / (d1 - d0)
                    x, y, h = x0 + u * (x1 - x0), y0 + u * (y1 - y0), atan2(y1 - y0, x1 - x0)
                else:
                    over = dist - d0
                    x, y, h = x0 + over * cos(h0), y0 + over * sin(h0), h0
                # `box_at`'s centre, so each box is the one `_ego_box` gives
                xs.append(x + center_x * cos(h))
                ys.append(y + center_x * sin(h))
                hs.append(h)
            group = BoxGroup(xs, ys, hs, 0.5 * e.length, 0.5 * e.width)
            self._ahead_groups[k] = group
        return group

    def foreseeable(self, name: str, until: float) -> int | None:
        """Index of the first frame at which `name`'s constant-velocity course (over `FORESIGHT` s) meets the
        path the ego went on to drive (None: never before `until`). Before then no planner could see the conflict
        coming: a party cutting in, or one that starts moving late."""
        key = (name, until)
        if key not in self._foreseen:
            self._foreseen[key] = self._foreseeable(name, until)
        return self._foreseen[key]

    def _foreseeable(self, name: str, until: float) -> int | None:
        taus = np.array([k * FORESIGHT_DT for k in range(int(FORESIGHT / FORESIGHT_DT) + 1)])
        for k in range(0, len(self.times), 2):             # every other frame: 0.1 s at the default step
            if self.times[k] > until:
                return None
            o = next((p for p in self.parties[k] if p.name == name), None)
            if o is None:
                continue
            c, s = math.cos(o.heading), math.sin(o.heading)
            fp = footprint(o)
            dx, dy = o.speed * FORESIGHT * c, o.speed * FORESIGHT * s
            # Clear of a circle round the path ahead: no position on the course overlaps a box of it (the test
            # below would find none), so the boxes need not be built.
            if _course_clear_of(self._ahead_circle(k), fp, dx, dy):
                continue
            # the path it went on to drive (straight on past the end of the run), 60 m of it
            ahead = self._ahead(k)
            if _course_clear(ahead, fp, dx, dy):
                continue
            moved = o.speed * taus
            if ahead.first_overlapped(fp, fp.cx + moved * c, fp.cy + moved * s) is not None:
                return k
        return None

    def meets(self, profile: Callable[[float, float], Callable[[float], float]], until: float, *,
              start: int = 0) -> tuple[str, float] | None:
        """The first party whose recorded footprint meets an ego that drove as recorded up to frame `start` and
        then braked with `profile(speed)` (distance over time), and when (None: no party does)."""
        if self.first is None or start >= len(self.times):
            return None
        t_b, d_b, v_b = self.times[start], self.dists[start], self.ego[start][3]
        brake = profile(v_b)
        end = bisect.bisect_right(self.times, until, lo=start)      # the frames with t <= until (times increase)
        along = [d_b + brake(self.times[k] - t_b) for k in range(start, end)]
        if not along:
            return None
        # Every footprint the braking ego takes lies in this circle: a frame whose parties are all clear of it has
        # no contact, and its ego box need not be built.
        cx, cy, r = self._stretch_circle(min(along), max(along))
        for k in self._frames_near(cx, cy, r, start, end):
            dist = along[k - start]
            parties = self.parties[k]
            boxes = self._footprints(k)
            if all(far_apart(cx, cy, r, b.cx, b.cy, b.radius) for b in boxes):
                continue
            ego = self._ego_box(dist)
            for o, box in zip(parties, boxes):
                if overlaps(ego, box):
                    return o.name, self.times[k]
        return None

    def _party_reach(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """Every recorded party, frame after frame: reference point x, y, the reach round it that holds its
        footprint (`center_x` offset plus half diagonal plus `FAR_SLACK`), and where each frame's parties begin
        (one more entry than frames)."""
        if self._reach is None:
            flat = [o for ps in self.parties for o in ps]
            xs = np.array([o.x for o in flat], dtype=float)
            ys = np.array([o.y for o in flat], dtype=float)
            reach = (np.abs(np.array([o.center_x for o in flat], dtype=float))
                     + np.hypot(0.5 * np.array([o.length for o in flat], dtype=float),
                                0.5 * np.array([o.width for o in flat], dtype=float)) + FAR_SLACK)
            starts = np.zeros(len(self.parties) + 1, dtype=np.int64)
            np.cumsum([len(ps) for ps in self.parties], out=starts[1:])
            self._reach = xs, ys, reach, starts
        return self._reach

    def _frames_near(self, cx: float, cy: float, r: float, start: int, end: int) -> list[int]:
        """The frames in [start, end), in order, with a party whose reach is not clear of the circle (cx, cy, r) by
        `FAR_SLACK`. A frame left out has every party's footprint `far_apart` from the circle (a footprint's
        centre is within `center_x` of its reference point, the rounding far under the slack), so `meets` would
        pass over it; a frame kept gets `meets`' own tests."""
        xs, ys, reach, starts = self._party_reach()
        lo, hi = int(starts[start]), int(starts[end])
        if lo == hi:
            return []
        dx, dy = xs[lo:hi] - cx, ys[lo:hi] - cy
        rr = reach[lo:hi] + (r + FAR_SLACK)
        near = np.flatnonzero(dx * dx + dy * dy <= rr * rr) + lo
        if not len(near):
            return []
        frames = np.searchsorted(starts, near, side="right") - 1
        return np.unique(frames).tolist()

    def _footprints(self, k: int) -> list[Box]:
        """The footprints of frame k's parties (asked again for every braking profile and start)."""
        boxes = self._boxes.get(k)
        if boxes is None:
            boxes = self._boxes[k] = [footprint(o) for o in self.parties[k]]
        return boxes

    def unavoidable(self, profile: Callable[[float], Callable[[float], float]], until: float
                    ) -> tuple[str, float, float, float] | None:
        """(party, time they meet, when braking began, speed then) for a party that meets the ego braking with
        `profile` from its start or from the moment the party's conflict became foreseeable; None otherwise."""
        hit = self.meets(profile, until)
        if hit:
            return hit[0], hit[1], self.times[0], self.ego[0][3]
        for name in sorted(self.moved):
            k = self.foreseeable(name, until)
            if k is None or k == 0:
                continue
            hit = self.meets(profile, until, start=k)
            if hit and hit[0] == name:
                return name, hit[1], self.times[k], self.ego[k][3]
        return None


def _course_clear(group: BoxGroup, box: Box, dx: float, dy: float) -> bool:
    """Whether `box`, slid along (dx, dy) from where it is, stays clear of the circle around the whole group (then
    no position on the way overlaps any of its boxes, and the tests per position can be skipped)."""
    d2 = dx * dx + dy * dy
    # the point of the course nearest to the circle's centre
    u = 0.0 if d2 == 0.0 else min(max(((group.cx - box.cx) * dx + (group.cy - box.cy) * dy) / d2, 0.0), 1.0)
    return group.clear_of(box.cx + u * dx, box.cy + u * dy, box.radius)


def _course_clear_of(circle: tuple[float, float, float], box: Box, dx: float, dy: float) -> bool:
    """`_course_clear` against a circle (x, y, radius) that holds every box of a group."""
    x, y, r = circle
    d2 = dx * dx + dy * dy
    u = 0.0 if d2 == 0.0 else min(max(((x - box.cx) * dx + (y - box.cy) * dy) / d2, 0.0), 1.0)
    return far_apart(x, y, r, box.cx + u * dx, box.cy + u * dy, box.radius)


def assess(cf: Counterfactual, categories: set[Category], *, decel: float, jerk: float, t_end: float,
           blocker: str = "") -> dict[Category, Unavoidable]:
    """The labels of the failed categories (`categories`) the scripted parties made unavoidable. `blocker`: the
    entity on the ego's path ahead at the end of the run ('' when none)."""
    out: dict[Category, Unavoidable] = {}
    if cf.first is None:
        return out

    def when(t_b: float, v_b: float) -> str:
        return f"from its start ({v_b:.1f} m/s)" if t_b <= cf.times[0] else \
            f"from {t_b:.2f} s ({v_b:.1f} m/s), when the party's course first met its path"

    if Category.COLLISIONS in categories:
        hit = cf.unavoidable(lambda v: emergency_stop(v, decel), t_end)
        if hit:
            out[Category.COLLISIONS] = Unavoidable(
                Category.COLLISIONS, hit[0], hit[1],
                f"{hit[0]} meets the ego at {hit[1]:.2f} s even had it braked at {decel:g} m/s² {when(hit[2], hit[3])}")
    if Category.SMOOTH in categories:
        hit = cf.unavoidable(lambda v: smooth_stop(v, jerk), t_end)
        if hit:
            out[Category.SMOOTH] = Unavoidable(
                Category.SMOOTH, hit[0], hit[1],
                f"{hit[0]} meets the ego at {hit[1]:.2f} s even had it begun the smoothest stop the band allows "
                f"(jerk ±{jerk:g} m/s³) {when(hit[2], hit[3])}")
    if Category.PLAN_FAIL in categories and blocker and blocker in cf.moved:
        out[Category.PLAN_FAIL] = Unavoidable(
            Category.PLAN_FAIL, blocker, t_end, f"{blocker} (a moving party) was on the ego's path ahead when the "
                                                f"run ended: it set the pace")
    return out
