"""Oriented bounding-box overlap (separating axis theorem on the boxes' 2D footprints)."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

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
    """Pairs of present entities whose footprints overlap; a bounding-circle test prunes far pairs first."""
    from .measure import box_center, box_corners

    live = [e for e in entities if e.present]
    centres = [box_center(e) for e in live]
    radii = [0.5 * math.hypot(e.spec.length, e.spec.width) for e in live]
    pairs: list[tuple[str, str]] = []
    corners: dict[int, Poly] = {}
    for i in range(len(live)):
        for j in range(i + 1, len(live)):
            dx, dy = centres[i][0] - centres[j][0], centres[i][1] - centres[j][1]
            r = radii[i] + radii[j]
            if dx * dx + dy * dy > r * r:
                continue
            ci = corners.setdefault(i, box_corners(live[i]))
            cj = corners.setdefault(j, box_corners(live[j]))
            if obb_overlap(ci, cj):
                pairs.append((live[i].name, live[j].name))
    return pairs
