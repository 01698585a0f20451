"""The road network as polylines a viewer can draw: lane borders, lane centre lines and stop lines, in the map frame.

Sampled from the one road model (`RoadNetwork`): borders are each lane section's `borders_t` (every border once,
the centre lane's included) on the road reference line; centre lines are `lane_to_world_array`; a stop line crosses
each lane a traffic light controls at the light's road s, from the lane's inner to its outer border. Roads inside a
junction get centre lines only: their borders overlap the junction's other connecting roads and would fill the
junction with lines that bound nothing a driver sees.

Straight runs are thinned (a sample that lies within `tolerance` of the chord of its neighbours is dropped), so a
long straight road is a handful of points, not one per `ds` metres. The outline of a network is computed once per
network object (`outline_of`): the scenarios of a campaign share a few maps.
"""

from __future__ import annotations

import weakref
from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from .network import RoadNetwork
from .topology import DRIVABLE_TYPES


@dataclass(frozen=True)
class Polyline:
    """One drawn line: `kind` 'border' | 'centre' | 'stop_line'; `lane_id` 0 for a road's centre-lane border;
    `points` an (N, 2) array of map x, y (m)."""

    kind: str
    road_id: str
    lane_id: int
    points: np.ndarray


KINDS = ("border", "centre", "stop_line")


def thin(points: np.ndarray, tolerance: float = 0.02) -> np.ndarray:
    """Drop samples while the chord from the last kept point stays within `tolerance` (m) of the samples it skips;
    ends kept. The chord is checked at its middle sample, where a smooth curve (the road model's geometry within a
    lane section) is farthest from it."""
    n = len(points)
    if n <= 2:
        return points
    xs, ys = points[:, 0].tolist(), points[:, 1].tolist()     # floats: a Python loop over numpy scalars is slow
    keep = [0]
    a = 0
    for i in range(2, n):
        m = (a + i) // 2
        ax, ay = xs[a], ys[a]
        bx, by = xs[i] - ax, ys[i] - ay
        norm = (bx * bx + by * by) ** 0.5
        if norm > 1e-9 and abs(bx * (ys[m] - ay) - by * (xs[m] - ax)) / norm > tolerance:
            a = i - 1
            keep.append(a)
    keep.append(n - 1)
    return points[keep]


def road_outline(net: RoadNetwork, *, ds: float = 1.0, tolerance: float = 0.02) -> tuple[Polyline, ...]:
    """Every border, drivable lane centre line and stop line of `net`, in a fixed order (roads in file order)."""
    lines: list[Polyline] = []
    for road in net.roads.values():
        in_junction = road.junction not in ("", "-1")
        for si, sec in enumerate(road.sections):
            s = net._lane_s_samples(road, si, ds)
            if not in_junction:
                borders = sec.borders_t(s, net.lane_offset(road.id, s))
                ids = sorted(borders, reverse=True)
                # All borders of the section in one call: the reference line is evaluated once per sample set.
                x, y, _ = net.road_to_world_array(road.id, np.tile(s, len(ids)),
                                                  np.concatenate([borders[i] for i in ids]))
                for k, lane_id in enumerate(ids):
                    part = slice(k * len(s), (k + 1) * len(s))
                    pts = np.column_stack((x[part], y[part]))
                    lines.append(Polyline("border", road.id, lane_id, thin(pts, tolerance)))
            for lane_id in sorted(sec.lanes, reverse=True):
                if lane_id == 0 or sec.lanes[lane_id].type not in DRIVABLE_TYPES:
                    continue
                x, y, _ = net.lane_to_world_array(road.id, lane_id, s, section=si)
                pts = np.column_stack((x, y))
                if not net.lane_forward(road.id, lane_id, float(s[0])):
                    pts = pts[::-1]              # drawn in the driving direction
                lines.append(Polyline("centre", road.id, lane_id, thin(pts, tolerance)))
    lines.extend(stop_lines(net))
    return tuple(lines)


def stop_lines(net: RoadNetwork) -> list[Polyline]:
    """One segment across every lane a traffic light controls, at the light's s (inner border to outer border)."""
    out = []
    for sig in net.signals.values():
        if not sig.is_traffic_light:
            continue
        for lane_id in sig.controlled_lanes:
            try:
                s = np.array([sig.s])
                inner, outer = net.lane_bounds(sig.road_id, lane_id, s)
                x, y, _ = net.road_to_world_array(sig.road_id, np.array([sig.s, sig.s]),
                                                  np.array([inner[0], outer[0]]))
            except InputError:
                continue                          # a light naming a lane its road lacks: nothing to draw
            out.append(Polyline("stop_line", str(sig.road_id), int(lane_id), np.column_stack((x, y))))
    return out


_CACHE: "weakref.WeakKeyDictionary[RoadNetwork, tuple[Polyline, ...]]" = weakref.WeakKeyDictionary()


def outline_of(net: RoadNetwork) -> tuple[Polyline, ...]:
    """`road_outline(net)` with the default sampling, computed once per network object."""
    lines = _CACHE.get(net)
    if lines is None:
        lines = _CACHE[net] = road_outline(net)
    return lines
