"""Lane tracks: one lane section's centre line sampled once (numpy) so that moving an entity along its lane costs
a bisection and a lerp per step instead of a road-geometry evaluation.

A track is indexed by road s (ascending). Entities move in road s: a step's travelled distance becomes road s with
the scale 1/(1 - k·t) at the point where the step starts (k the reference line's curvature, t the entity's lateral
position), and any road s left over at a lane's end carries on into the next lane unchanged. That is how esmini
advances an entity (its Position::MoveAlongS with DistanceToDS), so the two players agree step by step through
clothoids and junction turns; an exact arc-length integration differs by up to 0.75 m after a few turns.
"""

from __future__ import annotations

import bisect
import math
import weakref
from typing import Any

import numpy as np

from txt2sce_ros.road import LaneRef, RoadNetwork

SAMPLE_DS = 0.25     # m; chord error on a 50 m radius is 0.16 mm


class LaneTrack:
    __slots__ = ("ref", "forward", "s0", "s1", "s", "x", "y", "h", "nx", "ny", "tc", "length", "_plan", "_sl",
                 "_hint", "_k", "_k_lo", "_k_hi", "__weakref__")

    def __init__(self, net: RoadNetwork, ref: LaneRef) -> None:
        road = net.road(ref.road_id)
        sec = road.sections[ref.section]
        self.ref = ref
        self.s0 = float(sec.s)
        self.s1 = float(min(sec.end, road.length)) if sec.end > sec.s else float(road.length)
        n = max(2, int(math.ceil((self.s1 - self.s0) / SAMPLE_DS)) + 1)
        s = np.linspace(self.s0, self.s1, n)
        s_eval = s.copy()
        s_eval[-1] = self.s1 - 1e-9        # stay inside this section at its end
        x, y, h, href, inner, outer = net.lane_frame_array(ref.road_id, ref.lane_id, s_eval, section=ref.section)
        self.forward = net.lane_forward(ref.road_id, ref.lane_id, float(s_eval[0]))
        self.s = s
        self.x, self.y = np.asarray(x, float), np.asarray(y, float)
        self.h = np.unwrap(np.asarray(h, float))
        self.nx, self.ny = -np.sin(href), np.cos(href)      # unit +t
        self.tc = 0.5 * (inner + outer)
        self.length = float(np.sum(np.hypot(np.diff(self.x), np.diff(self.y))))     # of the lane centre
        self._plan = road.plan_view
        self._k, self._k_lo, self._k_hi = _constant_curvature(road.plan_view, self.s0, self.s1)
        # Scalar lookups run on Python lists: indexing numpy arrays one float at a time is several times slower.
        self._sl = self.s.tolist()
        self.x, self.y, self.h = self.x.tolist(), self.y.tolist(), self.h.tolist()
        self.nx, self.ny, self.tc = self.nx.tolist(), self.ny.tolist(), self.tc.tolist()
        self._hint = 0

    # -- scalar interpolation (bisect on Python lists beats np.interp for one value) --------------------------------
    def _idx(self, keys: list[float], v: float) -> tuple[int, float]:
        i = self._hint
        # Entities move a little each step: try the last segment and its neighbour before bisecting.
        if not (keys[i] <= v < keys[i + 1]):
            if i + 2 < len(keys) and keys[i + 1] <= v < keys[i + 2]:
                i += 1
            else:
                i = bisect.bisect_right(keys, v) - 1
                i = 0 if i < 0 else (len(keys) - 2 if i > len(keys) - 2 else i)
            self._hint = i
        span = keys[i + 1] - keys[i]
        f = (v - keys[i]) / span if span > 0 else 0.0
        return i, f

    def pose(self, s: float, offset: float = 0.0) -> tuple[float, float, float]:
        """World (x, y, heading of the lane's driving direction) at road s, `offset` toward +t."""
        return self.pose_center(s, offset)[:3]

    def pose_center(self, s: float, offset: float = 0.0) -> tuple[float, float, float, float]:
        """`pose(s, offset)` (world x, y, heading of the lane's driving direction at road s, `offset` toward +t)
        and `center_t(s)`, from one segment look-up: a storyboard entity's step needs both at its new s."""
        # `_idx` written out for the common case (s in the hinted segment): every moving entity asks this each step.
        keys = self._sl
        i = self._hint
        k0 = keys[i]
        k1 = keys[i + 1]
        if not (k0 <= s < k1):
            i = self._idx(keys, s)[0]
            k0 = keys[i]
            k1 = keys[i + 1]
        span = k1 - k0
        f = (s - k0) / span if span > 0 else 0.0
        j = i + 1
        xs, ys, hs, tcs = self.x, self.y, self.h, self.tc
        x = xs[i] + f * (xs[j] - xs[i])
        y = ys[i] + f * (ys[j] - ys[i])
        h = hs[i] + f * (hs[j] - hs[i])
        if offset:
            nxs, nys = self.nx, self.ny
            nx = nxs[i] + f * (nxs[j] - nxs[i])
            ny = nys[i] + f * (nys[j] - nys[i])
            x += offset * nx
            y += offset * ny
        return float(x), float(y), float(h), float(tcs[i] + f * (tcs[j] - tcs[i]))

    def center_t(self, s: float) -> float:
        i, f = self._idx(self._sl, s)
        return float(self.tc[i] + f * (self.tc[i + 1] - self.tc[i]))

    def ds_per_metre(self, s: float, offset: float = 0.0) -> float:
        """Road s per metre travelled at `offset` (toward +t) from the lane centre, at road s: 1/(1 - k·t) with
        the reference line's curvature k there. Evaluated once where a step starts, as esmini does, so a step
        that starts on a straight keeps its length in road s even if it ends in the curve that follows."""
        k = self._k if self._k_lo <= s < self._k_hi else self._plan.curvature_at(s)
        if k == 0.0:
            return 1.0
        kt = k * (self.center_t(s) + offset)
        return 1.0 / (1.0 - kt) if kt < 1.0 - 1e-9 else 1.0     # inside the centre of curvature: no scaling

    def advance(self, s: float, ds: float) -> tuple[float, float]:
        """Move `ds` of road s along the driving direction from road s (negative: against it): (new s clamped
        to the track, road s left over beyond its end)."""
        new = s + ds if self.forward else s - ds
        if new > self.s1:
            return self.s1, new - self.s1
        if new < self.s0:
            return self.s0, self.s0 - new
        return new, 0.0

    def entry_s(self) -> float:
        return self.s0 if self.forward else self.s1

    def exit_s(self) -> float:
        return self.s1 if self.forward else self.s0


def _constant_curvature(plan: Any, s0: float, s1: float) -> tuple[float, float, float]:
    """(k, lo, hi): the reference line's curvature is k at every road s in [lo, hi), which covers [s0, s1] when
    every geometry there is a line or an arc of one curvature (most lanes), so the per-step `ds_per_metre` needs no
    geometry look-up; else an empty range. [lo, hi) is exactly the set of s for which `PlanView.geometry_at`
    picks one of those geometries (its index: bisect over the geometry starts, clamped to the ends), and k is
    the value their `curvature_local` returns, so the answer is the same float either way."""
    from txt2sce_ros.road.geometry import Arc, Line

    starts, geos = plan._start_list, plan.geometries
    last = len(geos) - 1

    def index(s: float) -> int:
        return min(max(bisect.bisect_right(starts, s) - 1, 0), last)

    i0, i1 = index(s0), index(s1)
    values = set()
    for g in geos[i0:i1 + 1]:
        if type(g) in (Line, Arc):
            values.add(g.curvature_local(0.0))
        else:
            return 0.0, math.inf, -math.inf
    if len(values) != 1:
        return 0.0, math.inf, -math.inf
    lo = -math.inf if i0 == 0 else starts[i0]
    hi = math.inf if i1 == last else starts[i1 + 1]
    return values.pop(), lo, hi


class TrackCache:
    """LaneTracks of one network, built on first use."""

    _per_net: "weakref.WeakKeyDictionary[RoadNetwork, TrackCache]" = weakref.WeakKeyDictionary()

    def __init__(self, net: RoadNetwork) -> None:
        self.net = net
        self.tracks: dict[LaneRef, LaneTrack] = {}
        self.succ: dict[LaneRef, list[LaneRef]] = {}
        # Route paths by their waypoints' lane positions: the scenarios of one tree share their routes, and a
        # LanePath costs ~0.5 ms to sample, a fair part of a short run's set-up. LanePaths are not changed after
        # construction (only a lazily built KD-tree), so runs can share them. Bounded: a campaign runs thousands.
        self.paths: dict[tuple, tuple[Any, tuple[LaneRef, ...]]] = {}

    PATHS_KEPT = 512

    @classmethod
    def of(cls, net: RoadNetwork) -> "TrackCache":
        cache = cls._per_net.get(net)
        if cache is None:
            cache = cls(net)
            cls._per_net[net] = cache
        return cache

    def track(self, ref: LaneRef) -> LaneTrack:
        tr = self.tracks.get(ref)
        if tr is None:
            tr = LaneTrack(self.net, ref)
            self.tracks[ref] = tr
        return tr

    def at(self, road_id: str, lane_id: int, s: float) -> LaneTrack:
        return self.track(self.net.lane_ref(road_id, lane_id, s))

    def predecessors(self, ref: LaneRef) -> list[LaneRef]:
        key = ("pred", ref)
        out = self.succ.get(key)  # type: ignore[call-overload]
        if out is None:
            out = self.net.predecessors(ref)
            self.succ[key] = out  # type: ignore[index]
        return out

    def successors(self, ref: LaneRef) -> list[LaneRef]:
        out = self.succ.get(ref)
        if out is None:
            out = self.net.successors(ref)
            self.succ[ref] = out
        return out
