"""Lane tracks: one lane section's centre line sampled once (numpy) so that moving an entity along its lane costs
a bisection and a lerp per step instead of a road-geometry evaluation.

A track is indexed by road s (ascending); `arc` is the centre-line arc length, so entities move their true
travelled distance along the lane centre (on curves that differs from the change in road s, as in esmini).
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
    __slots__ = ("ref", "forward", "s0", "s1", "s", "x", "y", "h", "nx", "ny", "tc", "arc", "length", "_sl",
                 "_al", "_hint", "__weakref__")

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
        x, y, h = net.lane_to_world_array(ref.road_id, ref.lane_id, s_eval, section=ref.section)
        _, _, href = net.reference(ref.road_id, s_eval)
        inner, outer = net.lane_bounds(ref.road_id, ref.lane_id, s_eval, ref.section)
        self.forward = net.lane_forward(ref.road_id, ref.lane_id, float(s_eval[0]))
        self.s = s
        self.x, self.y = np.asarray(x, float), np.asarray(y, float)
        self.h = np.unwrap(np.asarray(h, float))
        self.nx, self.ny = -np.sin(href), np.cos(href)      # unit +t
        self.tc = 0.5 * (inner + outer)
        seg = np.hypot(np.diff(self.x), np.diff(self.y))
        self.arc = np.concatenate([[0.0], np.cumsum(seg)])
        self.length = float(self.arc[-1])
        # Scalar lookups run on Python lists: indexing numpy arrays one float at a time is several times slower.
        self._sl = self.s.tolist()
        self._al = self.arc.tolist()
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
        i, f = self._idx(self._sl, s)
        x = self.x[i] + f * (self.x[i + 1] - self.x[i])
        y = self.y[i] + f * (self.y[i + 1] - self.y[i])
        h = self.h[i] + f * (self.h[i + 1] - self.h[i])
        if offset:
            nx = self.nx[i] + f * (self.nx[i + 1] - self.nx[i])
            ny = self.ny[i] + f * (self.ny[i + 1] - self.ny[i])
            x += offset * nx
            y += offset * ny
        return float(x), float(y), float(h)

    def center_t(self, s: float) -> float:
        i, f = self._idx(self._sl, s)
        return float(self.tc[i] + f * (self.tc[i + 1] - self.tc[i]))

    def s_to_arc(self, s: float) -> float:
        i, f = self._idx(self._sl, s)
        return self._al[i] + f * (self._al[i + 1] - self._al[i])

    def arc_to_s(self, a: float) -> float:
        i, f = self._idx(self._al, a)
        return self._sl[i] + f * (self._sl[i + 1] - self._sl[i])

    def centre_per_offset_path(self, s: float, offset: float) -> float:
        """Metres of lane centre per metre travelled at `offset` (toward +t) from it, at road s. On a curve of
        curvature k (dh/ds of the reference line) a path at lateral position t is (1 - k·t) m long per m of s, so
        an entity driving with an offset advances along the lane at the radius of its own path (esmini does)."""
        if not offset:
            return 1.0
        i, _ = self._idx(self._sl, s)
        ds = self._sl[i + 1] - self._sl[i]
        if ds <= 0:
            return 1.0
        centre = (self._al[i + 1] - self._al[i]) / ds        # lane centre m per m of s
        path = centre - (self.h[i + 1] - self.h[i]) / ds * offset
        return centre / path if path > 1e-6 else 1.0

    def travel(self, s: float, distance: float) -> tuple[float, float]:
        """Move `distance` along the driving direction from road s: (new s clamped to the track, leftover m)."""
        a = self.s_to_arc(s) + (distance if self.forward else -distance)
        if a > self.length:
            return self.s1, a - self.length
        if a < 0.0:
            return self.s0, -a
        return self.arc_to_s(a), 0.0

    def entry_s(self) -> float:
        return self.s0 if self.forward else self.s1

    def exit_s(self) -> float:
        return self.s1 if self.forward else self.s0


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
