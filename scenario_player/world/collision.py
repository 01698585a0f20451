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
    """Pairs of present entities whose footprints overlap; bounding circles prune far pairs first.

    Runs every step for every pair. A pair whose reference points lie farther apart than their `Entity.reach`
    (enclosing radius, the box centre's offset from the reference point, and 0.5 m of slack for rounding) is
    skipped before any trigonometry: their box centres are then farther apart than the two radii, so the circle
    test below would skip it too (the slack is far above the rounding of these sums; a heading that is not finite
    makes the centres NaN, which that test never skips, so such a pair is not skipped here either). For the other
    pairs the centres are computed inline (the same expressions as `measure.box_center`, hence the same bits) and
    corners only for the pairs the circles cannot separate. With the handful of entities of a scenario, plain
    floats beat numpy arrays here (array set-up costs more than the pairs)."""
    live = [e for e in entities if e.present]
    n = len(live)
    if n < 2:
        return []
    pairs: list[tuple[str, str]] = []
    geo: list[tuple[float, float, float] | None] = [None] * n
    corners: dict[int, Poly] | None = None
    for i in range(n - 1):
        ei = live[i]
        exi, eyi, reach_i, hi = ei.x, ei.y, ei.reach, ei.h
        for j in range(i + 1, n):
            ej = live[j]
            dx, dy = exi - ej.x, eyi - ej.y
            reach = reach_i + ej.reach
            if dx * dx + dy * dy > reach * reach and hi - hi == 0.0 and ej.h - ej.h == 0.0:
                continue
            gi = geo[i]
            if gi is None:
                gi = geo[i] = _centre(ei)
            gj = geo[j]
            if gj is None:
                gj = geo[j] = _centre(ej)
            dx, dy = gi[0] - gj[0], gi[1] - gj[1]
            r = gi[2] + gj[2]
            if dx * dx + dy * dy > r * r:
                continue
            if corners is None:
                corners = {}
            ci = corners.get(i)
            if ci is None:
                ci = corners[i] = box_corners(ei)
            cj = corners.get(j)
            if cj is None:
                cj = corners[j] = box_corners(ej)
            if obb_overlap(ci, cj):
                pairs.append((ei.name, ej.name))
    return pairs


def _centre(e: "Entity") -> tuple[float, float, float]:
    """The footprint's centre and enclosing radius (the centre as `measure.box_center` computes it)."""
    sp = e.spec
    c, s = math.cos(e.h), math.sin(e.h)
    return e.x + c * sp.center_x - s * sp.center_y, e.y + s * sp.center_x + c * sp.center_y, e.radius
