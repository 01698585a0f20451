"""A straight path off the lane network (a pedestrian crossing the road, a car leaving a driveway)."""

from __future__ import annotations

import math

import numpy as np

from .model import WorldPose


class LineTrack:
    """Polyline through world points; same interface as `Track` for timing (world, world_array, length)."""

    reverse = False

    def __init__(self, points: list[tuple[float, float]], *, ds: float = 0.5) -> None:
        p = np.asarray(points, dtype=float)
        self.corners = p  # the polyline as given: the trajectory's vertices
        seg = np.hypot(np.diff(p[:, 0]), np.diff(p[:, 1]))
        keep = np.concatenate([[True], seg > 1e-6])
        p = p[keep]
        # densify so that sampled distance tests (conflict search) cannot step over a crossing
        cum = np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(p[:, 0]), np.diff(p[:, 1])))])
        self.corners, self.corner_d = p, cum
        n = max(int(np.ceil(cum[-1] / ds)) + 1, 2)
        u = np.linspace(0.0, cum[-1], n)
        self.x, self.y = np.interp(u, cum, p[:, 0]), np.interp(u, cum, p[:, 1])
        seg = np.hypot(np.diff(self.x), np.diff(self.y))
        self.d = np.concatenate([[0.0], np.cumsum(seg)])
        hs = np.arctan2(np.diff(self.y), np.diff(self.x))
        self.h = np.concatenate([hs, hs[-1:]])

    @property
    def length(self) -> float:
        return float(self.d[-1])

    def world(self, d: float, lateral: float = 0.0) -> WorldPose:
        arr = self.world_array(np.array([d]), lateral)
        return WorldPose(float(arr[0, 0]), float(arr[0, 1]), float(arr[0, 2]))

    def world_array(self, d: np.ndarray, lateral: np.ndarray | float = 0.0) -> np.ndarray:
        d = np.clip(d, 0.0, self.length)
        x = np.interp(d, self.d, self.x)
        y = np.interp(d, self.d, self.y)
        idx = np.clip(np.searchsorted(self.d, d, side="right") - 1, 0, len(self.h) - 1)
        h = self.h[idx]
        lat = np.broadcast_to(np.asarray(lateral, dtype=float), d.shape)
        return np.column_stack([x - lat * np.sin(h), y + lat * np.cos(h), h])

    def lane_pose(self, d: float, lateral: float = 0.0) -> WorldPose:
        return self.world(d, lateral)

    def vertices(self, from_d: float = 0.0) -> tuple[WorldPose, ...]:
        """The corner points from distance `from_d` on (the first vertex is the point at `from_d`), with the
        heading of the segment leaving each. A trajectory assigned while the entity is already under way must start
        where it is: players follow a polyline from its first vertex."""
        keep = self.corner_d > from_d + 0.5
        first = self.world(from_d)
        p = np.vstack([[first.x, first.y], self.corners[keep]])
        if len(p) < 2:  # at (or past) the end: a polyline needs two vertices; continue 1 m along the last heading
            p = np.vstack([p, [first.x + math.cos(first.h), first.y + math.sin(first.h)]])
        hs = np.arctan2(np.diff(p[:, 1]), np.diff(p[:, 0]))
        hs = np.concatenate([hs, hs[-1:]])
        return tuple(WorldPose(round(float(x), 3), round(float(y), 3), round(float(h), 4))
                     for (x, y), h in zip(p, hs))


def perpendicular(px: float, py: float, heading: float, side: str, before: float, after: float) -> LineTrack:
    """A crossing through (px, py) perpendicular to `heading`, starting `before` m on `side` ('right'|'left' of
    the heading) and ending `after` m beyond."""
    sign = -1.0 if side == "right" else 1.0
    nx, ny = -math.sin(heading) * sign, math.cos(heading) * sign   # unit normal toward the start side
    start = (px + nx * before, py + ny * before)
    end = (px - nx * after, py - ny * after)
    return LineTrack([start, (px, py), end])
