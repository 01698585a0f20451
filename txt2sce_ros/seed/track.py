"""A party's drivable path as a polyline over consecutive lanes, with the lane coordinates of every point, so a
distance along the path becomes an OpenSCENARIO LanePosition (road, lane, s, offset) or a world pose."""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from ..errors import InputError
from ..road import LaneRef, RoadNetwork
from .model import LanePose, WorldPose


class Track:
    """Centre line of lanes `refs` (in driving order), sampled every `ds` m.

    `d` is the distance along the track from its first point. Lateral offsets are positive to the left of the
    direction of travel."""

    def __init__(self, net: RoadNetwork, refs: Sequence[LaneRef], *, ds: float = 0.5, reverse: bool = False) -> None:
        if not refs:
            raise InputError("empty track", source=net.source, element="lane")
        self.net = net
        self.refs = tuple(refs)
        self.reverse = reverse  # travelled against the lanes' direction (wrong-way driving)
        xs, ys, ss, seg = [], [], [], []
        for k, ref in enumerate(refs):
            cl = net.lane_centerline(ref.road_id, ref.lane_id, ds, section=ref.section)
            if xs and math.hypot(cl[0, 0] - xs[-1][-1], cl[0, 1] - ys[-1][-1]) < 0.05:
                cl = cl[1:]
            xs.append(cl[:, 0])
            ys.append(cl[:, 1])
            ss.append(cl[:, 2])
            seg.append(np.full(len(cl), k))
        x, y, s, g = np.concatenate(xs), np.concatenate(ys), np.concatenate(ss), np.concatenate(seg)
        if reverse:
            x, y, s, g = x[::-1], y[::-1], s[::-1], g[::-1]
        self.x, self.y, self.s, self.seg = x, y, s, g
        step = np.hypot(np.diff(x), np.diff(y))
        self.d = np.concatenate([[0.0], np.cumsum(step)])
        hx = np.diff(x, append=x[-1] + (x[-1] - x[-2]))
        hy = np.diff(y, append=y[-1] + (y[-1] - y[-2]))
        self.h = np.arctan2(hy, hx)

    @property
    def length(self) -> float:
        return float(self.d[-1])

    def _index(self, d: float) -> int:
        return int(np.clip(np.searchsorted(self.d, d), 0, len(self.d) - 1))

    def world(self, d: float, lateral: float = 0.0) -> WorldPose:
        """World pose at distance d (clamped to the track), shifted `lateral` m to the left."""
        d = float(np.clip(d, 0.0, self.length))
        x = float(np.interp(d, self.d, self.x))
        y = float(np.interp(d, self.d, self.y))
        h = float(self.h[self._index(d)])
        return WorldPose(x - lateral * math.sin(h), y + lateral * math.cos(h), h)

    def world_array(self, d: np.ndarray, lateral: np.ndarray | float = 0.0) -> np.ndarray:
        d = np.clip(d, 0.0, self.length)
        x = np.interp(d, self.d, self.x)
        y = np.interp(d, self.d, self.y)
        idx = np.clip(np.searchsorted(self.d, d), 0, len(self.d) - 1)
        h = self.h[idx]
        lat = np.broadcast_to(np.asarray(lateral, dtype=float), d.shape)
        return np.column_stack([x - lat * np.sin(h), y + lat * np.cos(h), h])

    def lane_at(self, d: float) -> LaneRef:
        return self.refs[int(self.seg[self._index(d)])]

    def lane_pose(self, d: float, lateral: float = 0.0) -> LanePose:
        """LanePosition at distance d: road s interpolated on the lane under d; `lateral` (left of travel) turned
        into OpenSCENARIO's offset (toward +t of the road)."""
        d = float(np.clip(d, 0.0, self.length))
        i = self._index(d)
        ref = self.refs[int(self.seg[i])]
        same = self.seg == self.seg[i]
        s = float(np.interp(d, self.d[same], self.s[same])) if same.sum() > 1 else float(self.s[i])
        road = self.net.roads[ref.road_id]
        s = float(np.clip(s, 0.0, road.length))
        forward = self.net.lane_forward(ref.road_id, ref.lane_id, s)
        travel_forward = forward != self.reverse
        offset = lateral if travel_forward else -lateral
        x, y, h = self.net.lane_to_world(ref.road_id, ref.lane_id, s, offset)
        if self.reverse:
            h = h + math.pi
        return LanePose(ref.road_id, ref.lane_id, round(s, 3), round(offset, 3), x, y, h)

    def project(self, x: float, y: float) -> float:
        """Distance along the track of the sample nearest (x, y)."""
        i = int(np.argmin((self.x - x) ** 2 + (self.y - y) ** 2))
        return float(self.d[i])


def crossing(a: Track, b: Track, *, a_from: float = 0.0) -> tuple[float, float] | None:
    """First point (along `a`, after `a_from`) where the two centre lines cross or come within 0.5 m: returns
    (d on a, d on b), or None."""
    step = 4  # coarse pass on every 4th sample, then refine around the best pair
    ia = np.arange(0, len(a.d), step)
    ib = np.arange(0, len(b.d), step)
    pa = np.column_stack([a.x[ia], a.y[ia]])
    pb = np.column_stack([b.x[ib], b.y[ib]])
    dist = np.hypot(pa[:, None, 0] - pb[None, :, 0], pa[:, None, 1] - pb[None, :, 1])
    close = np.argwhere((dist < 2.5) & (a.d[ia][:, None] >= a_from))
    if close.size == 0:
        return None
    i0 = close[np.argmin(a.d[ia][close[:, 0]]), 0]
    lo, hi = max(ia[i0] - 2 * step, 0), min(ia[i0] + 2 * step, len(a.d) - 1)
    seg_a = np.arange(lo, hi + 1)
    dd = np.hypot(a.x[seg_a, None] - b.x[None, :], a.y[seg_a, None] - b.y[None, :])
    k = np.unravel_index(np.argmin(dd), dd.shape)
    if dd[k] > 0.75:
        return None
    return float(a.d[seg_a[k[0]]]), float(b.d[k[1]])
