"""Distances between entities (and to points), one implementation for every condition and action.

- reference point vs freespace (bounding boxes: gap between the boxes, 0 when they touch or overlap);
- longitudinal / lateral / euclidian (cartesian);
- coordinate system 'entity' (the measuring entity's heading) or 'road'/'lane' (road s and t, on the same road;
  otherwise the entity frame is used).

Longitudinal and lateral results are signed: positive when the other entity is ahead / to the left.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from .pose import Pose

if TYPE_CHECKING:
    from .entity import Entity
    from .world import World


def box_corners(ent: "Entity") -> list[tuple[float, float]]:
    sp = ent.spec
    c, s = math.cos(ent.h), math.sin(ent.h)
    cx = ent.x + c * sp.center_x - s * sp.center_y
    cy = ent.y + s * sp.center_x + c * sp.center_y
    hl, hw = sp.length / 2.0, sp.width / 2.0
    return [(cx + c * dx - s * dy, cy + s * dx + c * dy) for dx, dy in ((hl, hw), (-hl, hw), (-hl, -hw), (hl, -hw))]


def box_center(ent: "Entity") -> tuple[float, float]:
    sp = ent.spec
    c, s = math.cos(ent.h), math.sin(ent.h)
    return ent.x + c * sp.center_x - s * sp.center_y, ent.y + s * sp.center_x + c * sp.center_y


def _seg_dist(p: tuple[float, float], a: tuple[float, float], b: tuple[float, float]) -> float:
    abx, aby = b[0] - a[0], b[1] - a[1]
    den = abx * abx + aby * aby
    u = 0.0 if den == 0 else max(0.0, min(1.0, ((p[0] - a[0]) * abx + (p[1] - a[1]) * aby) / den))
    return math.hypot(p[0] - a[0] - u * abx, p[1] - a[1] - u * aby)


def polygon_gap(pa: list[tuple[float, float]], pb: list[tuple[float, float]]) -> float:
    """Distance between two convex quadrilaterals (0 if they overlap)."""
    from .collision import obb_overlap

    if obb_overlap(pa, pb):
        return 0.0
    best = math.inf
    for poly, other in ((pa, pb), (pb, pa)):
        for p in poly:
            for i in range(4):
                d = _seg_dist(p, other[i], other[(i + 1) % 4])
                if d < best:
                    best = d
    return best


class Measure:
    def __init__(self, world: "World") -> None:
        self.world = world

    def between(self, a: "Entity", b: "Entity", rdt: str, cs: str, freespace: bool) -> float:
        if rdt == "euclidianDistance":
            if freespace:
                return polygon_gap(box_corners(a), box_corners(b))
            return math.hypot(b.x - a.x, b.y - a.y)
        if cs in ("road", "lane") and a.road_id is not None and a.road_id == b.road_id and a.track is not None:
            sign = 1.0 if a.track.forward else -1.0
            if rdt == "longitudinal":
                d = sign * (b.road_s - a.road_s)
                if freespace:
                    d = _shrink(d, _front(a), _rear(a), _front(b), _rear(b))
                return d
            d = sign * (b.road_t - a.road_t)
            return _shrink(d, a.spec.width / 2, a.spec.width / 2, b.spec.width / 2, b.spec.width / 2) if freespace else d
        # entity coordinates of `a`
        if freespace:
            (ax, ay), (bx, by) = box_center(a), box_center(b)
        else:
            ax, ay, bx, by = a.x, a.y, b.x, b.y
        c, s = math.cos(a.h), math.sin(a.h)
        dx, dy = bx - ax, by - ay
        if rdt == "longitudinal":
            d = c * dx + s * dy
            if freespace:
                half_b = _extent_along(b, a.h)
                return _shrink(d, a.spec.length / 2, a.spec.length / 2, half_b, half_b)
            return d
        d = -s * dx + c * dy
        if freespace:
            half_b = _extent_along(b, a.h + math.pi / 2)
            return _shrink(d, a.spec.width / 2, a.spec.width / 2, half_b, half_b)
        return d

    def to_point(self, a: "Entity", pose: Pose, rdt: str, cs: str, freespace: bool) -> float:
        if rdt == "euclidianDistance":
            if freespace:
                from .collision import point_in_box

                corners = box_corners(a)
                if point_in_box((pose.x, pose.y), corners):
                    return 0.0
                return min(_seg_dist((pose.x, pose.y), corners[i], corners[(i + 1) % 4]) for i in range(4))
            return math.hypot(pose.x - a.x, pose.y - a.y)
        if cs in ("road", "lane") and a.road_id is not None and pose.road_id == a.road_id and a.track is not None:
            sign = 1.0 if a.track.forward else -1.0
            if rdt == "longitudinal":
                d = sign * ((pose.s or 0.0) - a.road_s)
                return _shrink(d, _front(a), _rear(a), 0.0, 0.0) if freespace else d
            t = (self.world.tracks.at(pose.road_id, pose.lane_id, pose.s).center_t(pose.s) + pose.offset
                 if pose.lane_id is not None else 0.0)
            return sign * (t - a.road_t)
        c, s = math.cos(a.h), math.sin(a.h)
        dx, dy = pose.x - a.x, pose.y - a.y
        if rdt == "longitudinal":
            d = c * dx + s * dy
            return _shrink(d, _front(a), _rear(a), 0.0, 0.0) if freespace else d
        return -s * dx + c * dy

    def closing_speed(self, a: "Entity", b: "Entity") -> float:
        """Rate at which `a` closes on `b` along `a`'s heading (m/s, positive when approaching)."""
        return a.speed - b.speed * math.cos(b.h - a.h)


def _front(e: "Entity") -> float:
    return e.spec.center_x + e.spec.length / 2.0


def _rear(e: "Entity") -> float:
    return e.spec.length / 2.0 - e.spec.center_x


def _extent_along(e: "Entity", direction: float) -> float:
    """Half extent of `e`'s box projected on `direction`."""
    rel = e.h - direction
    return abs(math.cos(rel)) * e.spec.length / 2 + abs(math.sin(rel)) * e.spec.width / 2


def _shrink(d: float, a_ahead: float, a_behind: float, b_ahead: float, b_behind: float) -> float:
    """Turn a signed reference-point distance into a signed gap between extents (0 when they overlap)."""
    if d >= 0:
        return max(0.0, d - a_ahead - b_behind)
    return min(0.0, d + a_behind + b_ahead)
