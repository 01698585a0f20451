"""Oriented bounding-box overlap (separating axis theorem on the boxes' 2D footprints)."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from .measure import box_corners

if TYPE_CHECKING:
    from .entity import Entity

Poly = list[tuple[float, float]]


def obb_overlap(a: Poly, b: Poly) -> bool:
    """True if two rectangles (corners in order) overlap or touch."""
    # The projections are written out (no helper call, one list per box and axis): the contact scan runs this for
    # every pair whose circles meet, every step.
    for poly in (a, b):
        for i in (0, 1):
            p, q = poly[i], poly[i + 1]
            ex, ey = q[0] - p[0], q[1] - p[1]
            ax, ay = -ey, ex
            va = [c[0] * ax + c[1] * ay for c in a]
            vb = [c[0] * ax + c[1] * ay for c in b]
            if max(va) < min(vb) or max(vb) < min(va):
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
    cos, sin = math.cos, math.sin
    geo = []
    for e in live:
        sp = e.spec
        c, s = cos(e.h), sin(e.h)
        geo.append((e.x + c * sp.center_x - s * sp.center_y, e.y + s * sp.center_x + c * sp.center_y, e.radius))
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
