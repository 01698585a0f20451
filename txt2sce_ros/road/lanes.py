"""Lanes and lane sections: widths, borders and the lateral position t of every lane at a given s.

OpenDRIVE builds lanes outwards from the centre lane (id 0, at t = laneOffset(s)): left lanes (ids 1, 2, …) stack
towards +t, right lanes (-1, -2, …) towards -t. A lane's width (or, alternatively, its outer border) is a list of
cubic polynomials in ds = s - section start - sOffset, each valid from its sOffset to the next one.
"""

from __future__ import annotations

import bisect
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True, slots=True)
class Cubic:
    """a + b·ds + c·ds² + d·ds³ with ds = s - start (start in the frame the owner defines)."""

    start: float
    a: float
    b: float = 0.0
    c: float = 0.0
    d: float = 0.0


def eval_cubics(records: tuple[Cubic, ...], s: np.ndarray, *, default: float = 0.0) -> np.ndarray:
    """Piecewise cubic at `s` (array): each record is valid from its start to the next record's start; before the
    first record the first one is used (a malformed sOffset > 0 then extrapolates rather than breaking)."""
    s = np.asarray(s, dtype=float)
    if not records:
        return np.full_like(s, default)
    if len(records) == 1:
        r = records[0]
        ds = s - r.start
        return r.a + ds * (r.b + ds * (r.c + ds * r.d))
    starts = np.array([r.start for r in records])
    idx = np.clip(np.searchsorted(starts, s, side="right") - 1, 0, len(records) - 1)
    coef = np.array([[r.start, r.a, r.b, r.c, r.d] for r in records])[idx]
    ds = s - coef[..., 0]
    return coef[..., 1] + ds * (coef[..., 2] + ds * (coef[..., 3] + ds * coef[..., 4]))


def cubic_at(records: tuple[Cubic, ...], s: float) -> tuple[float, float]:
    """Scalar value and slope d/ds of a piecewise cubic (same validity rule as `eval_cubics`), without numpy:
    the per-entity, per-step calls of players and planners are dominated by array overhead otherwise."""
    if not records:
        return 0.0, 0.0
    if len(records) == 1:
        r = records[0]
    else:
        i = bisect.bisect_right([c.start for c in records], s) - 1
        r = records[i if i > 0 else 0]
    ds = s - r.start
    return r.a + ds * (r.b + ds * (r.c + ds * r.d)), r.b + ds * (2.0 * r.c + 3.0 * ds * r.d)


@dataclass(frozen=True, slots=True)
class LaneLink:
    predecessor: int | None = None
    successor: int | None = None


@dataclass(frozen=True, slots=True)
class Lane:
    """One `<lane>` of a lane section. Widths' starts are relative to the section start (sOffset)."""

    id: int
    type: str
    widths: tuple[Cubic, ...] = ()
    borders: tuple[Cubic, ...] = ()      # used only when the lane has no <width> (OpenDRIVE allows either)
    link: LaneLink = LaneLink()
    level: bool = False
    direction: str = "standard"           # OpenDRIVE 1.7 @direction: standard | reversed | both

    def width(self, ds: np.ndarray) -> np.ndarray:
        """Width at section-relative ds (array). Negative widths of sloppy maps are clamped to 0."""
        return np.maximum(eval_cubics(self.widths, ds), 0.0)


@dataclass(frozen=True, slots=True)
class LaneSection:
    s: float
    lanes: dict[int, Lane]                 # by id, including the centre lane 0
    single_side: bool = False
    end: float = 0.0                       # s where the next section (or the road) starts

    @property
    def left_ids(self) -> list[int]:
        return sorted(i for i in self.lanes if i > 0)

    @property
    def right_ids(self) -> list[int]:
        return sorted((i for i in self.lanes if i < 0), reverse=True)

    @property
    def length(self) -> float:
        return self.end - self.s

    def lane_bounds_at(self, lane_id: int, s: float, offset: tuple[float, float]) -> tuple[float, float, float, float]:
        """Scalar (inner t, outer t, d inner/ds, d outer/ds) of one lane at road s, given laneOffset value and
        slope there."""
        ds = s - self.s
        base, dbase = offset
        if lane_id == 0:
            return base, base, dbase, dbase
        side = 1.0 if lane_id > 0 else -1.0
        inner, dinner = base, dbase
        step = 1 if lane_id > 0 else -1
        for lid in range(step, lane_id + step, step):
            lane = self.lanes[lid]
            if lane.widths or not lane.borders:
                w, dw = cubic_at(lane.widths, ds)
                if w < 0.0:
                    w, dw = 0.0, 0.0
                outer, douter = inner + side * w, dinner + side * dw
            else:
                b, db = cubic_at(lane.borders, ds)
                outer, douter = base + b, dbase + db
            if lid == lane_id:
                return inner, outer, dinner, douter
            inner, dinner = outer, douter
        raise KeyError(lane_id)

    def borders_t(self, s: np.ndarray, lane_offset: np.ndarray) -> dict[int, np.ndarray]:
        """Outer border t of every lane (and 0: the centre line, at laneOffset) at road s (array).

        A lane described by <border> records gives its outer border directly (relative to the centre lane);
        one described by <width> adds its width to the inner neighbour's border."""
        ds = np.asarray(s, dtype=float) - self.s
        out: dict[int, np.ndarray] = {0: np.asarray(lane_offset, dtype=float) + 0.0 * ds}
        for side, ids in ((1.0, self.left_ids), (-1.0, self.right_ids)):
            inner = out[0]
            for lid in ids:
                lane = self.lanes[lid]
                if lane.widths or not lane.borders:
                    outer = inner + side * lane.width(ds)
                else:
                    outer = out[0] + eval_cubics(lane.borders, ds)
                out[lid] = outer
                inner = outer
        return out
