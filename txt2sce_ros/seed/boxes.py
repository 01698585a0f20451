"""Footprint boxes: corners, the separating-axis gap between two boxes, and the first contacts of a run.

Kept apart from the seed generator (`kinematics`, `fidelity`) so that `txt2sce play`, which prints a run's
contacts, imports only this: the generator's modules cost a cold start their imports and record classes."""

from __future__ import annotations

import math
from collections.abc import Iterable
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from ..contract import EntityState


#: m kept between any two footprints at t=0: a contact in the first frame is an invalid scenario, not a collision.
#: 0.3 m asked for, plus 5 cm for the player placing a lane position a little differently from the plan's samples.
#: (The seed planner's start separation and the tree's category mutation keep the same clearance.)
START_CLEARANCE = 0.35


def box_corners(x: float, y: float, h: float, length: float, width: float, center_x: float) -> np.ndarray:
    c, s = math.cos(h), math.sin(h)
    cx, cy = x + center_x * c, y + center_x * s
    hl, hw = length / 2, width / 2
    pts = [(hl, hw), (hl, -hw), (-hl, -hw), (-hl, hw)]
    return np.array([(cx + a * c - b * s, cy + a * s + b * c) for a, b in pts])


def boxes_gap(a: np.ndarray, b: np.ndarray) -> float:
    """Separating-axis distance between two convex quadrilaterals: ≤ 0 when they overlap, else the largest gap
    along any edge normal (a lower bound of the true distance, exact for aligned boxes)."""
    best = -math.inf
    for poly in (a, b):
        for i in range(4):
            e = poly[(i + 1) % 4] - poly[i]
            n = np.array([-e[1], e[0]]) / (math.hypot(*e) or 1.0)
            pa, pb = a @ n, b @ n
            gap = max(pb.min() - pa.max(), pa.min() - pb.max())
            best = max(best, gap)
    return best


def state_corners(e: EntityState, dt: float = 0.0) -> np.ndarray:
    x = e.x + e.speed * math.cos(e.heading) * dt
    y = e.y + e.speed * math.sin(e.heading) * dt
    return box_corners(x, y, e.heading, e.length, e.width, e.center_x)


def first_contacts(frames: Iterable) -> list[tuple[str, str, float]]:
    """Every pair of entities whose footprints touched during a run, with the first time they did, in time order
    (the ego first in its pairs)."""
    seen: dict[tuple[str, str], float] = {}
    for fr in frames:
        states = [fr.ego, *fr.objects]
        # Box centres and half-diagonals: two boxes whose enclosing circles are apart cannot touch, so the exact
        # (and, on numpy's small arrays, slow) separating-axis test, and the corners it needs, are built only for
        # pairs that are close. The centre is the box's own (reference point moved by center_x along the heading).
        centres = [(e.x + e.center_x * math.cos(e.heading), e.y + e.center_x * math.sin(e.heading)) for e in states]
        radii = [0.5 * math.hypot(e.length, e.width) for e in states]
        for i in range(len(states)):
            for j in range(i + 1, len(states)):
                pair = (states[i].name, states[j].name)
                if pair in seen:
                    continue
                reach = radii[i] + radii[j] + 1e-6
                dx, dy = centres[i][0] - centres[j][0], centres[i][1] - centres[j][1]
                if dx * dx + dy * dy > reach * reach:
                    continue
                if boxes_gap(state_corners(states[i]), state_corners(states[j])) <= 0.0:
                    seen[pair] = fr.t
    return sorted(((a, b, t) for (a, b), t in seen.items()), key=lambda c: (c[2], c[0], c[1]))
