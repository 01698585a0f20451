"""Oriented bounding-box overlap (separating axis theorem on the boxes' 2D footprints)."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from .measure import box_corners

if TYPE_CHECKING:
    from .entity import Entity

Poly = list[tuple[float, float]]


def _project(poly: Poly, ax: float, ay: float) -> tuple[float, float]:
    vals = [p[0] * ax + p[1] * ay for p in poly]
    return min(vals), max(vals)


def obb_overlap(a: Poly, b: Poly) -> bool:
    """True if two rectangles (corners in order) overlap or touch."""
    for poly in (a, b):
        for i in (0, 1):
            ex, ey = poly[i + 1][0] - poly[i][0], poly[i + 1][1] - poly[i][1]
            ax, ay = -ey, ex
            amin, amax = _project(a, ax, ay)
            bmin, bmax = _project(b, ax, ay)
            if amax < bmin or bmax < amin:
                return False
    return True


def point_in_box(p: tuple[float, float], poly: Poly) -> bool:
    sign = 0.0
    for i in range(4):
        a, b = poly[i], poly[(i + 1) % 4]
        cross = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])
        if cross != 0:
            if sign == 0:
                sign = cross
            elif (cross > 0) != (sign > 0):
                return False
    return True


def detect(entities: list["Entity"]) -> list[tuple[str, str]]:
    """Pairs of present entities whose footprints overlap; a bounding-circle test prunes far pairs first.

    Runs every step for every pair, so the centres are computed inline (the same expressions as
    `measure.box_center`, hence the same bits) and corners only for the pairs the circles cannot separate. With
    the handful of entities of a scenario, plain floats beat numpy arrays here (array set-up costs more than the
    pairs)."""
    live = [e for e in entities if e.present]
    n = len(live)
    if n < 2:
        return []
    cos, sin, hypot = math.cos, math.sin, math.hypot
    geo = []
    for e in live:
        sp = e.spec
        c, s = cos(e.h), sin(e.h)
        geo.append((e.x + c * sp.center_x - s * sp.center_y, e.y + s * sp.center_x + c * sp.center_y,
                    0.5 * hypot(sp.length, sp.width)))
    pairs: list[tuple[str, str]] = []
    corners: dict[int, Poly] | None = None
    for i in range(n - 1):
        xi, yi, ri = geo[i]
        for j in range(i + 1, n):
            xj, yj, rj = geo[j]
            dx, dy = xi - xj, yi - yj
            r = ri + rj
            if dx * dx + dy * dy > r * r:
                continue
            if corners is None:
                corners = {}
            ci = corners.get(i)
            if ci is None:
                ci = corners[i] = box_corners(live[i])
            cj = corners.get(j)
            if cj is None:
                cj = corners[j] = box_corners(live[j])
            if obb_overlap(ci, cj):
                pairs.append((live[i].name, live[j].name))
    return pairs
