"""Oriented footprints and exact contact between them (separating-axis test on two rectangles).

Pure `math` on purpose for one pair: the oracle runs every step on every entity pair, and numpy's per-call overhead
on 4×2 arrays is larger than the arithmetic itself. Only `BoxGroup` (tens of boxes against one) uses arrays.
"""

from __future__ import annotations

import math
from typing import NamedTuple, Sequence

import numpy as np

from txt2sce_ros.contract import EntityState


class Box(NamedTuple):
    """An oriented rectangle: centre, unit heading vector (c, s) and half extents along / across it."""

    cx: float
    cy: float
    c: float
    s: float
    half_length: float
    half_width: float

    @property
    def radius(self) -> float:
        """Half diagonal: no point of the box is farther than this from its centre."""
        return math.hypot(self.half_length, self.half_width)

    def corners(self) -> list[tuple[float, float]]:
        """Front-left, front-right, rear-right, rear-left."""
        out = []
        for lo, la in ((1, 1), (1, -1), (-1, -1), (-1, 1)):
            dx, dy = lo * self.half_length, la * self.half_width
            out.append((self.cx + dx * self.c - dy * self.s, self.cy + dx * self.s + dy * self.c))
        return out


def footprint(e: EntityState) -> Box:
    """The entity's bounding box on the ground: `length` × `width`, centred `center_x` ahead of (x, y)."""
    c, s = math.cos(e.heading), math.sin(e.heading)
    return Box(e.x + e.center_x * c, e.y + e.center_x * s, c, s, 0.5 * e.length, 0.5 * e.width)


def box_at(x: float, y: float, heading: float, center_x: float, length: float, width: float) -> Box:
    c, s = math.cos(heading), math.sin(heading)
    return Box(x + center_x * c, y + center_x * s, c, s, 0.5 * length, 0.5 * width)


def _projected_radius(b: Box, ax: float, ay: float) -> float:
    return b.half_length * abs(b.c * ax + b.s * ay) + b.half_width * abs(-b.s * ax + b.c * ay)


def penetration(a: Box, b: Box) -> float:
    """Signed overlap depth (m): > 0 when the rectangles overlap (the smallest overlap over the four separating
    axes), <= 0 when they are apart (minus the largest gap along an axis; touching edges give 0)."""
    dx, dy = b.cx - a.cx, b.cy - a.cy
    depth = math.inf
    for ax, ay in ((a.c, a.s), (-a.s, a.c), (b.c, b.s), (-b.s, b.c)):
        overlap = _projected_radius(a, ax, ay) + _projected_radius(b, ax, ay) - abs(dx * ax + dy * ay)
        if overlap < depth:
            depth = overlap
    return depth


def overlaps(a: Box, b: Box) -> bool:
    """True when the two rectangles share interior area (touching edges do not count)."""
    dx, dy = b.cx - a.cx, b.cy - a.cy
    r = a.radius + b.radius
    if dx * dx + dy * dy >= r * r:        # far apart: skip the four projections
        return False
    return penetrates(a, b.cx, b.cy, b.c, b.s, b.half_length, b.half_width)


def penetrates(a: Box, bcx: float, bcy: float, bc: float, bs: float, bhl: float, bhw: float) -> bool:
    """`penetration(a, b) > 0.0` for b = Box(bcx, bcy, bc, bs, bhl, bhw), with the same float operations per axis
    (`_projected_radius` inlined), leaving at the first axis whose overlap is <= 0: the smallest overlap is > 0 exactly when
    no axis's overlap is <= 0 (a NaN overlap never lowers `penetration`'s depth, nor stops this loop)."""
    acx, acy, ac, as_, ahl, ahw = a
    dx, dy = bcx - acx, bcy - acy
    for ax, ay in ((ac, as_), (-as_, ac), (bc, bs), (-bs, bc)):   # the four box axes, in `penetration`'s order
        if (ahl * abs(ac * ax + as_ * ay) + ahw * abs(-as_ * ax + ac * ay)) \
                + (bhl * abs(bc * ax + bs * ay) + bhw * abs(-bs * ax + bc * ay)) - abs(dx * ax + dy * ay) <= 0.0:
            return False
    return True


#: Slack (m) of `far_apart`: far above the rounding of coordinates of a few km, far below any footprint.
FAR_SLACK = 1e-3


def far_apart(ax: float, ay: float, ar: float, bx: float, by: float, br: float) -> bool:
    """Whether two circles (centre, radius) are more than `FAR_SLACK` apart: then no box inside one overlaps a box
    inside the other, and the exact tests between them can be skipped (a conservative pre-test: it never skips a
    pair `overlaps` would call overlapping)."""
    r = ar + br + FAR_SLACK
    dx, dy = bx - ax, by - ay
    return dx * dx + dy * dy > r * r


class BoxGroup:
    """Boxes of one size at many poses (centre and heading), tested together against one other box at a time:
    `overlapped_by(b)` answers `any(overlaps(a, b) for a in boxes)` with the same tests on the same floats, after
    one test of `b` against the circle around them all and the boxes' own circle tests in one array expression.
    A box is built only where its exact test runs. (The oracle's corridor along the ego's path ahead and the
    counterfactual ego's path are such groups.)"""

    __slots__ = ("xs", "ys", "headings", "half_length", "half_width", "radius", "cx", "cy", "reach", "_built")

    def __init__(self, xs: Sequence[float], ys: Sequence[float], headings: Sequence[float], half_length: float,
                 half_width: float) -> None:
        self.xs = np.asarray(xs, dtype=float)
        self.ys = np.asarray(ys, dtype=float)
        self.headings = np.asarray(headings, dtype=float)
        if not len(self.xs) == len(self.ys) == len(self.headings) > 0:
            raise ValueError("a box group needs one centre and heading per box, and at least one box")
        self.half_length, self.half_width = half_length, half_width
        self.radius = math.hypot(half_length, half_width)           # every box's `Box.radius`
        self.cx, self.cy = float(self.xs.mean()), float(self.ys.mean())
        self.reach = float(np.hypot(self.xs - self.cx, self.ys - self.cy).max()) + self.radius
        self._built: dict[int, Box] = {}

    def box(self, i: int) -> Box:
        b = self._built.get(i)
        if b is None:
            h = float(self.headings[i])
            b = Box(float(self.xs[i]), float(self.ys[i]), math.cos(h), math.sin(h), self.half_length,
                    self.half_width)
            self._built[i] = b
        return b

    @property
    def boxes(self) -> list[Box]:
        return [self.box(i) for i in range(len(self.xs))]

    def clear_of(self, x: float, y: float, radius: float) -> bool:
        """Whether the circle (x, y, radius) is clear of every box of the group (`far_apart` of the circles)."""
        return far_apart(self.cx, self.cy, self.reach, x, y, radius)

    def overlapped_by(self, b: Box) -> bool:
        rb = b.radius
        if far_apart(self.cx, self.cy, self.reach, b.cx, b.cy, rb):
            return False
        # `overlaps(a, b)` per box: its circle test for all boxes at once (the same float operations,
        # elementwise), then the exact test on the boxes that pass it, in order.
        dx, dy = b.cx - self.xs, b.cy - self.ys
        r = self.radius + rb
        for i in np.flatnonzero(dx * dx + dy * dy < r * r).tolist():
            if penetrates(self.box(i), *b):
                return True
        return False

    def first_overlapped(self, b: Box, cxs: np.ndarray, cys: np.ndarray) -> int | None:
        """Index of the first of the centres (cxs, cys) at which `b`, moved there, overlaps a box of the group
        (None: at none): `overlapped_by` per position, its circle tests for all positions at once."""
        r = self.radius + b.radius
        dx = cxs[:, None] - self.xs[None, :]
        dy = cys[:, None] - self.ys[None, :]
        near = dx * dx + dy * dy < r * r
        _, _, c, s, hl, hw = b
        box = self.box
        for t in np.flatnonzero(near.any(axis=1)).tolist():
            x, y = float(cxs[t]), float(cys[t])        # b moved there
            for i in np.flatnonzero(near[t]).tolist():
                if penetrates(box(i), x, y, c, s, hl, hw):
                    return t
        return None


def interpolate(e0: EntityState, e1: EntityState, u: float) -> tuple[float, float, float]:
    """Pose between two samples of one entity (linear in position, shortest-arc in heading), u in [0, 1]."""
    dh = math.remainder(e1.heading - e0.heading, math.tau)
    return e0.x + u * (e1.x - e0.x), e0.y + u * (e1.y - e0.y), e0.heading + u * dh
