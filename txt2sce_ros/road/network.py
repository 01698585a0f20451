"""`RoadNetwork`: the one OpenDRIVE road model (geometry, lanes, lookup, topology) every stage uses.

Coordinates: s along a road's reference line, t to its left; headings radians CCW from +x. Lane ids follow
OpenDRIVE; in right-hand traffic (RHT) lanes with negative ids drive along +s, in left-hand traffic (LHT) the
positive ones do (an OpenDRIVE 1.7 lane `direction="reversed"` flips that).
"""

from __future__ import annotations

import bisect
import math
import os
import threading
from functools import cached_property
from pathlib import Path
from typing import TYPE_CHECKING, Iterable

import numpy as np

from ..errors import InputError
from .lanes import LaneSection, cubic_at, eval_cubics
from .model import Controller, Junction, LaneRef, Road, Signal
from .parse import parse_network

if TYPE_CHECKING:   # pragma: no cover
    import networkx as nx

    from .lookup import LaneIndex, LaneMatch, LanePoint
    from .topology import LaneGraph

DRIVING_TYPES = ("driving",)


class RoadNetwork:
    """An OpenDRIVE network loaded into memory. Build with `load_network(path)` or `RoadNetwork.from_string`."""

    def __init__(self, data: bytes, source: str) -> None:
        parsed = parse_network(data, source)
        self.source = source
        self.header = parsed.header
        self.geo_reference = parsed.geo_reference
        self.roads: dict[str, Road] = parsed.roads
        self.junctions: dict[str, Junction] = parsed.junctions
        self.controllers: dict[str, Controller] = parsed.controllers
        self._section_starts = {rid: np.array([sec.s for sec in r.sections]) for rid, r in self.roads.items()}
        self._section_start_lists = {rid: [sec.s for sec in r.sections] for rid, r in self.roads.items()}
        self._topology_cache: dict[str, dict] = {}     # filled lazily by `topology` (successors, lane lengths)
        self.signals: dict[str, Signal] = self._place_signals()
        self._index_lock = threading.Lock()
        self._indices: dict[tuple[str, ...], "LaneIndex"] = {}

    @classmethod
    def from_string(cls, text: str | bytes, source: str = "<string>") -> "RoadNetwork":
        data = text.encode("utf-8") if isinstance(text, str) else text
        return cls(data, source)

    @classmethod
    def from_file(cls, path: str | Path) -> "RoadNetwork":
        p = Path(path)
        try:
            data = p.read_bytes()
        except OSError as exc:
            raise InputError(f"cannot read map: {exc.strerror}", source=str(p)) from exc
        return cls(data, str(p))

    def __repr__(self) -> str:
        return f"RoadNetwork({self.source!r}, roads={len(self.roads)}, junctions={len(self.junctions)})"

    # --- lookups of records ----------------------------------------------------------------------------------------

    def road(self, road_id: str | int) -> Road:
        try:
            return self.roads[str(road_id)]
        except KeyError:
            raise InputError(f"no road with id {road_id!r}", source=self.source, element="road") from None

    def section_index(self, road_id: str | int, s: float) -> int:
        # s exactly on a boundary (to 1e-9) belongs to the section starting there
        starts = self._section_start_lists[self.road(road_id).id]
        return max(0, bisect.bisect_right(starts, s + 1e-9) - 1)

    def section(self, road_id: str | int, s: float) -> LaneSection:
        road = self.road(road_id)
        return road.sections[self.section_index(road.id, s)]

    def _lane(self, road: Road, lane_id: int, s: float) -> tuple[int, LaneSection]:
        si = self.section_index(road.id, s)
        sec = road.sections[si]
        if int(lane_id) not in sec.lanes:
            raise InputError(f"road {road.id} has no lane {lane_id} at s={s:.3f} (lanes {sorted(sec.lanes)})",
                             source=self.source, element="lane")
        return si, sec

    def lane_forward(self, road_id: str | int, lane_id: int, s: float | None = None) -> bool:
        """True if traffic in the lane drives along +s."""
        road = self.road(road_id)
        forward = (lane_id < 0) if road.rule == "RHT" else (lane_id > 0)
        if s is not None:
            lane = self.section(road.id, s).lanes.get(int(lane_id))
            if lane is not None and lane.direction == "reversed":
                forward = not forward
        return forward

    # --- vectorised geometry ---------------------------------------------------------------------------------------

    def reference(self, road_id: str | int, s: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Reference line (x, y, heading) at road s (array)."""
        return self.road(road_id).plan_view.evaluate(s)

    def lane_offset(self, road_id: str | int, s: np.ndarray) -> np.ndarray:
        return eval_cubics(self.road(road_id).lane_offsets, np.asarray(s, dtype=float))

    def lane_bounds(self, road_id: str | int, lane_id: int, s: np.ndarray, section: int | None = None
                    ) -> tuple[np.ndarray, np.ndarray]:
        """(inner t, outer t) of a lane at road s (array), inner = nearer the centre lane."""
        road = self.road(road_id)
        s_arr = np.atleast_1d(np.asarray(s, dtype=float))
        si = section if section is not None else self.section_index(road.id, float(s_arr[0]))
        sec = road.sections[si]
        if int(lane_id) not in sec.lanes:
            raise InputError(f"road {road.id} has no lane {lane_id} in section {si}", source=self.source,
                             element="lane")
        borders = sec.borders_t(s_arr, self.lane_offset(road.id, s_arr))
        outer = borders[int(lane_id)]
        inner = borders[int(lane_id) - (1 if lane_id > 0 else -1)] if lane_id != 0 else outer
        return inner, outer

    def road_to_world_array(self, road_id: str | int, s: np.ndarray, t: np.ndarray | float = 0.0
                            ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        x, y, h = self.reference(road_id, s)
        t = np.asarray(t, dtype=float)
        return x - t * np.sin(h), y + t * np.cos(h), h

    def lane_to_world_array(self, road_id: str | int, lane_id: int, s: np.ndarray, offset: np.ndarray | float = 0.0,
                            *, section: int | None = None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Lane centre + offset (toward +t) at road s (array, all in one lane section); heading = driving
        direction of the lane, including the lane centre's slope relative to the reference line."""
        return self.lane_frame_array(road_id, lane_id, s, offset, section=section)[:3]

    def lane_frame_array(self, road_id: str | int, lane_id: int, s: np.ndarray, offset: np.ndarray | float = 0.0,
                         *, section: int | None = None) -> tuple[np.ndarray, ...]:
        """`lane_to_world_array`'s (x, y, heading), then what it computed on the way: the reference line's
        heading at s and the lane's (inner t, outer t) there (the values `reference` and `lane_bounds` give), for
        a caller that needs all of them (a lane track) without evaluating the road twice."""
        road = self.road(road_id)
        s_arr = np.atleast_1d(np.asarray(s, dtype=float))
        inner, outer, t, x, y, href = self._lane_points(road, lane_id, s_arr, offset, section)
        # Slope of the lane centre: dt/ds over (1 - k t) is the angle between lane centre and reference line.
        eps = 0.05
        i2, o2 = self.lane_bounds(road.id, lane_id, s_arr + eps, section)
        dt = (0.5 * (i2 + o2) - 0.5 * (inner + outer)) / eps
        k = road.plan_view.curvature(s_arr)
        h = href + np.arctan2(dt, np.maximum(1.0 - k * t, 1e-3))
        if not self.lane_forward(road.id, lane_id, float(s_arr[0])):
            h = h + math.pi
        return x, y, np.arctan2(np.sin(h), np.cos(h)), href, inner, outer

    def _lane_points(self, road: Road, lane_id: int, s_arr: np.ndarray, offset: np.ndarray | float,
                     section: int | None) -> tuple[np.ndarray, ...]:
        """(inner t, outer t, t, x, y, reference heading) of the lane centre + offset at road s: the positions
        part of `lane_to_world_array`, which `lane_centerline` needs alone (the heading costs as much again)."""
        inner, outer = self.lane_bounds(road.id, lane_id, s_arr, section)
        t = 0.5 * (inner + outer) + np.asarray(offset, dtype=float)
        x, y, h = self.road_to_world_array(road.id, s_arr, t)
        return inner, outer, t, x, y, h

    # --- scalar API ------------------------------------------------------------------------------------------------

    def road_to_world(self, road_id: str | int, s: float, t: float = 0.0) -> tuple[float, float, float]:
        """World (x, y, h) of road coordinates (s, t); h = reference-line heading at s."""
        xr, yr, hr = self._ref_scalar(self.road(road_id), float(s))
        return xr - t * math.sin(hr), yr + t * math.cos(hr), hr

    def _ref_scalar(self, road: Road, s: float) -> tuple[float, float, float]:
        return road.plan_view.at(s)

    def road_heading(self, road_id: str | int, s: float) -> float:
        return self._ref_scalar(self.road(road_id), float(s))[2]

    def _bounds_scalar(self, road: Road, lane_id: int, s: float) -> tuple[int, float, float, float, float]:
        si, sec = self._lane(road, lane_id, s)
        inner, outer, di, do = sec.lane_bounds_at(int(lane_id), s, cubic_at(road.lane_offsets, s))
        return si, inner, outer, di, do

    def lane_center_t(self, road_id: str | int, lane_id: int, s: float) -> float:
        _, inner, outer, _, _ = self._bounds_scalar(self.road(road_id), lane_id, float(s))
        return 0.5 * (inner + outer)

    def lane_width(self, road_id: str | int, lane_id: int, s: float) -> float:
        _, inner, outer, _, _ = self._bounds_scalar(self.road(road_id), lane_id, float(s))
        return abs(outer - inner)

    def lane_type(self, road_id: str | int, lane_id: int, s: float) -> str:
        road = self.road(road_id)
        _, sec = self._lane(road, lane_id, s)
        return sec.lanes[int(lane_id)].type

    def lane_ids(self, road_id: str | int, s: float, *, types: Iterable[str] | None = DRIVING_TYPES) -> list[int]:
        """Lane ids at s (centre lane excluded), left to right across the road (descending id); `types=None`
        returns every lane."""
        sec = self.section(road_id, s)
        wanted = None if types is None else set(types)
        return sorted((i for i, ln in sec.lanes.items() if i != 0 and (wanted is None or ln.type in wanted)),
                      reverse=True)

    def lane_to_world(self, road_id: str | int, lane_id: int, s: float, offset: float = 0.0
                      ) -> tuple[float, float, float]:
        """World (x, y, h) of a lane position: lane centre at road s shifted by `offset` toward +t of the road
        (OpenSCENARIO LanePosition/@offset, as esmini reads it); h = driving direction of the lane, including the
        lane centre's slope relative to the reference line (widening lanes, laneOffset)."""
        road = self.road(road_id)
        s = float(s)
        si, inner, outer, di, do = self._bounds_scalar(road, lane_id, s)
        t = 0.5 * (inner + outer) + offset
        xr, yr, hr = self._ref_scalar(road, s)
        k = road.plan_view.curvature_at(s)
        h = hr + math.atan2(0.5 * (di + do), max(1.0 - k * t, 1e-3))
        if not self.lane_forward(road.id, lane_id, road.sections[si].s):
            h += math.pi
        return xr - t * math.sin(hr), yr + t * math.cos(hr), math.atan2(math.sin(h), math.cos(h))

    # --- lanes as polylines ----------------------------------------------------------------------------------------

    def _lane_s_samples(self, road: Road, si: int, ds: float) -> np.ndarray:
        sec = road.sections[si]
        end = min(sec.end, road.length)
        n = max(2, int(math.ceil((end - sec.s) / ds)) + 1)
        s = np.linspace(sec.s, end, n)
        s[-1] = end - 1e-6 if end > sec.s else end   # stay inside this section at its end (section_index tolerates 1e-9)
        return s

    def lane_centerline(self, road_id: str | int, lane_id: int, ds: float = 0.5, *, section: int | None = None
                        ) -> np.ndarray:
        """Lane centre line as an (N, 3) array of x, y, s in the lane's driving direction. Without `section`,
        all sections holding the lane id are concatenated."""
        road = self.road(road_id)
        sections = [section] if section is not None else [
            i for i, sec in enumerate(road.sections) if int(lane_id) in sec.lanes]
        if not sections:
            raise InputError(f"road {road.id} has no lane {lane_id}", source=self.source, element="lane")
        parts = []
        for si in sections:
            s = self._lane_s_samples(road, si, ds)
            _, _, _, x, y, _ = self._lane_points(road, lane_id, s, 0.0, si)
            parts.append(np.column_stack([x, y, s]))
        out = np.vstack(parts)
        return out if self.lane_forward(road.id, lane_id) else out[::-1].copy()

    def lane_borders(self, road_id: str | int, lane_id: int, ds: float = 0.5, *, section: int | None = None
                     ) -> tuple[np.ndarray, np.ndarray]:
        """(left, right) borders of a lane, (N, 2) each, ordered along and sided by its driving direction."""
        road = self.road(road_id)
        sections = [section] if section is not None else [
            i for i, sec in enumerate(road.sections) if int(lane_id) in sec.lanes]
        if not sections:
            raise InputError(f"road {road.id} has no lane {lane_id}", source=self.source, element="lane")
        plus, minus = [], []
        for si in sections:
            s = self._lane_s_samples(road, si, ds)
            inner, outer = self.lane_bounds(road.id, lane_id, s, si)
            hi = np.maximum(inner, outer)
            lo = np.minimum(inner, outer)
            xh, yh, _ = self.road_to_world_array(road.id, s, hi)
            xl, yl, _ = self.road_to_world_array(road.id, s, lo)
            plus.append(np.column_stack([xh, yh]))
            minus.append(np.column_stack([xl, yl]))
        hi_pts, lo_pts = np.vstack(plus), np.vstack(minus)
        if self.lane_forward(road.id, lane_id):
            return hi_pts, lo_pts            # +t is left when driving along +s
        return lo_pts[::-1].copy(), hi_pts[::-1].copy()

    # --- signals ---------------------------------------------------------------------------------------------------

    def _place_signals(self) -> dict[str, Signal]:
        from dataclasses import replace

        out: dict[str, Signal] = {}
        self.signal_references: list[Signal] = []   # <signalReference>: a signal reused on another road
        for road in self.roads.values():
            placed = []
            for sig in road.signals:
                s = min(max(sig.s, 0.0), road.length)
                x, y, h = self.road_to_world(road.id, s, sig.t)
                if sig.orientation == "-":
                    h += math.pi
                lanes = self._signal_lanes(road, sig, s)
                new = replace(sig, x=x, y=y, heading=math.atan2(math.sin(h), math.cos(h)), controlled_lanes=lanes)
                placed.append(new)
                if sig.is_reference:
                    self.signal_references.append(new)
                else:
                    out[sig.id] = new
            road.signals[:] = placed
        return out

    def _signal_lanes(self, road: Road, sig: Signal, s: float) -> tuple[int, ...]:
        sec = road.sections[self.section_index(road.id, s)]
        ids = [i for i, ln in sec.lanes.items() if i != 0 and ln.type == "driving"]
        if sig.validity:
            keep = set()
            for v in sig.validity:
                lo, hi = sorted((v.from_lane, v.to_lane))
                keep.update(i for i in ids if lo <= i <= hi)
            ids = sorted(keep)
        if sig.orientation in ("+", "-"):
            along = sig.orientation == "+"
            ids = [i for i in ids if self.lane_forward(road.id, i, s) == along]
        return tuple(sorted(ids, reverse=True))

    def signals_of_controller(self, controller_id: str) -> list[Signal]:
        ctrl = self.controllers.get(str(controller_id))
        return [self.signals[sid] for sid in ctrl.signal_ids if sid in self.signals] if ctrl else []

    # --- lookup, topology and routing live in their own modules -----------------------------------------------------

    def lane_index(self, lane_types: Iterable[str] | None = DRIVING_TYPES) -> "LaneIndex":
        """The spatial index over sampled lane centres of the given types (built once, then cached)."""
        from .lookup import LaneIndex

        key = tuple(sorted(lane_types)) if lane_types is not None else ("*",)
        with self._index_lock:
            idx = self._indices.get(key)
            if idx is None:
                idx = LaneIndex(self, None if lane_types is None else key)
                self._indices[key] = idx
        return idx

    def world_to_lane(self, xs: np.ndarray | Iterable[float], ys: np.ndarray | Iterable[float], *,
                      lane_types: Iterable[str] | None = DRIVING_TYPES) -> "LaneMatch":
        """Nearest lane (of `lane_types`) of each point, with road s, t, offset from the lane centre, distance and
        whether the point lies within the lane's borders. Vectorised over points."""
        return self.lane_index(lane_types).query(np.asarray(xs, dtype=float), np.asarray(ys, dtype=float))

    def locate(self, x: float, y: float, heading: float | None = None, *,
               lane_types: Iterable[str] | None = DRIVING_TYPES) -> "LanePoint | None":
        """The lane at (x, y), preferring lanes whose driving direction matches `heading` (radians)."""
        return self.lane_index(lane_types).locate(float(x), float(y), heading)

    def lane_ref(self, road_id: str | int, lane_id: int, s: float) -> LaneRef:
        road = self.road(road_id)
        si, _ = self._lane(road, lane_id, s)
        return LaneRef(road.id, si, int(lane_id))

    def lane_length(self, ref: LaneRef) -> float:
        """Length of a lane's centre line within its section (m)."""
        from .topology import lane_length

        return lane_length(self, ref)

    def neighbour(self, ref: LaneRef, side: str) -> LaneRef | None:
        from .topology import neighbour

        return neighbour(self, ref, side)

    def successors(self, ref: LaneRef) -> list[LaneRef]:
        from .topology import successors

        return successors(self, ref)

    def predecessors(self, ref: LaneRef) -> list[LaneRef]:
        from .topology import predecessors

        return predecessors(self, ref)

    @cached_property
    def lane_graph(self) -> "LaneGraph":
        """The lane-level routing graph as plain dicts (`topology.LaneGraph`); `route` searches it."""
        from .topology import build_lane_graph

        return build_lane_graph(self)

    @cached_property
    def routing_graph(self) -> "nx.DiGraph":
        from .topology import build_routing_graph

        return build_routing_graph(self)

    def route(self, start: LaneRef, goal: LaneRef) -> list[LaneRef]:
        from .topology import route

        return route(self, start, goal)

    def turn_type(self, incoming: LaneRef, connecting: LaneRef) -> str:
        from .topology import turn_type

        return turn_type(self, incoming, connecting)


_CACHE: dict[str, tuple[float, int, RoadNetwork]] = {}
_CACHE_LOCK = threading.Lock()


def load_network(path: str | os.PathLike[str]) -> RoadNetwork:
    """Load an OpenDRIVE file, cached per absolute path + mtime + size (safe to call from every stage)."""
    p = Path(path).resolve()
    try:
        st = p.stat()
    except OSError as exc:
        raise InputError(f"cannot read map: {exc.strerror}", source=str(path)) from exc
    key = str(p)
    with _CACHE_LOCK:
        hit = _CACHE.get(key)
        if hit and hit[0] == st.st_mtime and hit[1] == st.st_size:
            return hit[2]
    net = RoadNetwork.from_file(p)
    with _CACHE_LOCK:
        _CACHE[key] = (st.st_mtime, st.st_size, net)
    return net


_TEXT_CACHE: dict[tuple[str, str], RoadNetwork] = {}
_TEXT_CACHE_SIZE = 8


def load_network_text(text: str | bytes, source: str = "<string>") -> RoadNetwork:
    """`RoadNetwork.from_string`, cached by the SHA-256 of the content and the source name (a campaign worker or a
    player receiving the same map in every scenario envelope parses it once, and builds its routing graph, lane
    index and topology once; the name is part of the key because error messages quote it). Keeps the last few
    maps. The network is shared, so its users must treat it as read-only (its lazily filled caches aside)."""
    import hashlib

    data = text.encode("utf-8") if isinstance(text, str) else text
    key = (hashlib.sha256(data).hexdigest(), source)
    with _CACHE_LOCK:
        hit = _TEXT_CACHE.get(key)
    if hit is not None:
        return hit
    net = RoadNetwork(data, source)
    with _CACHE_LOCK:
        if len(_TEXT_CACHE) >= _TEXT_CACHE_SIZE:
            _TEXT_CACHE.pop(next(iter(_TEXT_CACHE)))
        _TEXT_CACHE[key] = net
    return net
