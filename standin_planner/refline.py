"""The route's centre line as a dense polyline: what lane following, path-relative object checks and stop points
work on. Built once per (re)plan from the road model's `LanePath`, so the per-step geometry is plain numpy and the
controllers can be exercised on any polyline.
"""

from __future__ import annotations

import bisect
import math
from dataclasses import dataclass

import numpy as np

from txt2sce_ros.quick_init import quick_init


def wrap_angle(a: float) -> float:
    """Angle in (-pi, pi]."""
    return (a + math.pi) % (2.0 * math.pi) - math.pi


#: Segments per chunk of `project_many`'s pruning.
CHUNK = 16
#: Lines of at most this many chunks are searched whole (measured: the pruning pays from about 250 segments).
MIN_CHUNKS = 16
#: Slack (m) on the chunk distance bounds: far above rounding errors, so pruning never drops the nearest segment.
CHUNK_SLACK = 1e-6

#: Slack (m) on the radius of the circle round a range of chunks (`far_from_straight`'s first test).
GROUP_SLACK = 1e-6

#: Turns at a vertex sharper than this (rad) are not bounded by `far_from` (a lane join's kink).
MAX_BOUNDED_TURN = 1.2

#: Projections a line remembers (it forgets them all when full: they are cheap to recompute).
PROJECTION_CACHE = 256

#: Side (m) of the square cells for which a line remembers which segments can be nearest to a point inside, at
#: most CELL_CANDIDATES of them (more: the cell is searched as a window), for at most CELL_CACHE cells.
CELL = 1.0
CELL_CANDIDATES = 24
CELL_CACHE = 4096
_HALF_DIAGONAL = 0.5 * math.sqrt(2.0) * CELL


@quick_init
@dataclass(frozen=True, slots=True)
class PathPoint:
    s: float
    offset: float        # signed distance to the left of the line, m
    heading: float       # line heading at s, rad


class RefLine:
    """A polyline with arc length `s`, heading and curvature per vertex, and per-vertex lane facts
    (`in_junction`, `lane_width`) that the behaviour layer needs."""

    def __init__(self, xy: np.ndarray, *, in_junction: np.ndarray | None = None,
                 lane_width: np.ndarray | None = None, room_left: np.ndarray | None = None,
                 room_right: np.ndarray | None = None, lanes: tuple = ()) -> None:
        xy = np.asarray(xy, dtype=float)
        if xy.ndim != 2 or xy.shape[1] != 2 or len(xy) < 2:
            raise ValueError("a reference line needs at least two (x, y) points")
        # Drop repeated vertices (lane joins) so headings are defined everywhere.
        keep = np.ones(len(xy), dtype=bool)
        keep[1:] = np.hypot(*np.diff(xy, axis=0).T) > 1e-6
        self.xy = xy[keep]
        n = len(self.xy)
        self.in_junction = (np.zeros(n, dtype=bool) if in_junction is None
                            else np.asarray(in_junction, dtype=bool)[keep])
        self.lane_width = (np.full(n, 3.5) if lane_width is None else np.asarray(lane_width, dtype=float)[keep])
        # Width of the same-direction driving lane beside the route's lane on each side (0: none there).
        self.room_left = np.zeros(n) if room_left is None else np.asarray(room_left, dtype=float)[keep]
        self.room_right = np.zeros(n) if room_right is None else np.asarray(room_right, dtype=float)[keep]
        self.lanes = lanes
        seg = np.diff(self.xy, axis=0)
        seg_len = np.hypot(seg[:, 0], seg[:, 1])
        self.s = np.concatenate([[0.0], np.cumsum(seg_len)])
        self._seg = seg
        self._seg_len = seg_len
        seg_h = np.arctan2(seg[:, 1], seg[:, 0])
        self._seg_heading = seg_h
        # Curvature from heading change over arc length, smoothed over ~3 m to damp sampling noise at lane joins.
        dh = np.array([wrap_angle(b - a) for a, b in zip(seg_h[:-1], seg_h[1:])])
        ds = 0.5 * (seg_len[:-1] + seg_len[1:])
        k = np.concatenate([[0.0], dh / np.maximum(ds, 1e-6), [0.0]])
        if n > 2:
            k[0], k[-1] = k[1], k[-2]
        step = max(float(np.median(seg_len)), 1e-3)
        win = max(1, int(round(3.0 / step)))
        if win > 1 and n > win:
            k = np.convolve(k, np.ones(win) / win, mode="same")
        self.curvature = k
        # Per-step queries are scalar: plain-Python copies and per-segment constants avoid numpy's per-call
        # overhead (np.searchsorted / np.clip on a float cost microseconds each) without changing any value.
        #: `s` as a Python list, for bisect.
        self.s_list: list[float] = self.s.tolist()
        self._last_seg = len(seg) - 1
        self._x0 = np.ascontiguousarray(self.xy[:-1, 0])
        self._y0 = np.ascontiguousarray(self.xy[:-1, 1])
        self._dx = np.ascontiguousarray(seg[:, 0])
        self._dy = np.ascontiguousarray(seg[:, 1])
        self._L2 = np.maximum(seg_len ** 2, 1e-12)
        # Chunks of CHUNK segments with a circle round each (centre of the vertices' box, radius to the farthest):
        # `project_many` skips chunks that cannot hold the nearest segment.
        nseg = len(seg)
        starts = np.arange(0, nseg, CHUNK)
        centres, radii = [], []
        for a in starts:
            v = self.xy[a:min(a + CHUNK, nseg) + 1]
            c = 0.5 * (v.min(axis=0) + v.max(axis=0))
            centres.append(c)
            radii.append(float(np.hypot(v[:, 0] - c[0], v[:, 1] - c[1]).max()))
        self._chunk_x = np.array([c[0] for c in centres])
        self._chunk_y = np.array([c[1] for c in centres])
        self._chunk_r = np.array(radii)
        # Per chunk, the arc length it spans and 1/cos of the sharpest turn at a vertex of its segments (for
        # `far_from`; inf where a turn is too sharp to bound).
        self._chunk_s0 = self.s[starts]
        self._chunk_s1 = self.s[np.minimum(starts + CHUNK, nseg)]
        turn = np.zeros(nseg + 1)
        if nseg > 1:
            turn[1:-1] = np.abs(np.remainder(np.diff(seg_h) + math.pi, 2.0 * math.pi) - math.pi)
        inv_cos = []
        for a in starts:
            worst = float(turn[a:min(a + CHUNK, nseg) + 1].max())
            inv_cos.append(1.0 / math.cos(worst) if worst < MAX_BOUNDED_TURN else math.inf)
        self._chunk_inv_cos = np.array(inv_cos)
        self._chunk_lists = (self._chunk_s0.tolist(), self._chunk_s1.tolist(), self._chunk_x.tolist(),
                             self._chunk_y.tolist(), self._chunk_r.tolist(), inv_cos)
        # `far_points`: the live chunks' arrays by chunk range, and per end of the line (start, then end) its
        # vertex, the end segment's heading as cos and sin, and which way is beyond it.
        self._live_chunks: dict[tuple[int, int], tuple[np.ndarray, ...] | None] = {}
        self._ends = tuple((float(self.xy[end, 0]), float(self.xy[end, 1]), math.cos(float(self._seg_heading[k])),
                            math.sin(float(self._seg_heading[k])), sign)
                           for end, k, sign in ((0, 0, -1.0), (n - 1, nseg - 1, 1.0)))
        # Projections by (x, y, first segment, end segment), which fully determine the answer: the planner projects
        # the ego twice per step alike (off-route check, then the step), and static objects and stop lines again
        # every step with a window that covers the whole (short) line.
        self._projections: dict[tuple[float, float, int, int] | None, PathPoint] = {}
        self._window: tuple[tuple[float, float] | None, tuple[int, int]] = (None, (0, 0))   # last window asked
        # Per cell of the plane, the segments that can hold the nearest point of a point inside (`_candidates`).
        # Plain-Python copies of the per-segment values for the scalar search over them.
        self._cells: dict[tuple[int, int], tuple[int, ...] | None] = {}
        self._x0_list: list[float] = self._x0.tolist()
        self._y0_list: list[float] = self._y0.tolist()
        self._dx_list: list[float] = self._dx.tolist()
        self._dy_list: list[float] = self._dy.tolist()
        self._L2_list: list[float] = self._L2.tolist()
        self._groups: dict[tuple[int, int], tuple[float, float, float, float] | None] = {}  # `_chunk_group`
        self._widths: dict[float, float] = {}                               # `width_at` by s
        self._rooms: dict[tuple[float, float], tuple[float, float]] = {}    # `neighbour_room` by (s0, s1)
        self._turns: dict[tuple[float, int, int, float], bool] = {}        # `turns_across` by its question
        #: Derived per-vertex arrays keyed by their parameters (e.g. curve speed limits), filled by their users.
        self.cache: dict = {}

    @property
    def length(self) -> float:
        return float(self.s[-1])

    def _index(self, s: float) -> int:
        # bisect_right on the sorted list is searchsorted(side="right"), NaN included (both give len). Clamped to
        # [0, last segment] by comparisons: min/max calls cost ~5x more, and this runs ~6 times a step.
        i = bisect.bisect_right(self.s_list, s) - 1
        if i < 0:
            return 0
        last = self._last_seg
        return last if last < i else i

    def position(self, s: float, offset: float = 0.0) -> tuple[float, float, float]:
        """(x, y, heading) at arc length `s` (extrapolated straight beyond both ends), `offset` to the left."""
        i = self._index(s)
        h = float(self._seg_heading[i])
        u = s - self.s[i]
        x = self.xy[i, 0] + u * math.cos(h) - offset * math.sin(h)
        y = self.xy[i, 1] + u * math.sin(h) + offset * math.cos(h)
        return float(x), float(y), h

    def heading(self, s: float) -> float:
        return float(self._seg_heading[self._index(s)])

    def turns_across(self, heading: float, s0: float, s1: float, min_sin: float) -> bool:
        """Whether the line runs across `heading` anywhere in [s0, s1] (|sin(difference)| at least `min_sin`): a
        turn across the course of a party travelling on beside it or towards it."""
        i0, i1 = self._index(s0), self._index(s1)
        # A party on a straight course asks the same every step, from the same segments: remembered (by the
        # exact heading; the answer is a comparison of |sin|, the same for either sign of a zero).
        key = (heading, i0, i1, min_sin)
        hit = self._turns.get(key)
        if hit is None:
            if len(self._turns) >= PROJECTION_CACHE:
                self._turns.clear()
            hit = self._turns[key] = bool(np.any(np.abs(np.sin(self._seg_heading[i0:i1 + 1] - heading))
                                                 >= min_sin))
        return hit

    def curvature_at(self, s: float) -> float:
        return float(np.interp(s, self.s, self.curvature))

    def max_abs_curvature(self, s0: float, s1: float) -> np.ndarray:
        """(s, |curvature|) samples of the vertices between s0 and s1, for curve speed limiting."""
        mask = (self.s >= s0) & (self.s <= s1)
        return np.stack([self.s[mask], np.abs(self.curvature[mask])], axis=1)

    def width_at(self, s: float) -> float:
        # A static obstacle's pass is planned at the same arc lengths every step: remembered (by the exact s; a
        # zero of either sign interpolates to the first vertex's width).
        hit = self._widths.get(s)
        if hit is None:
            if len(self._widths) >= PROJECTION_CACHE:
                self._widths.clear()
            hit = self._widths[s] = float(np.interp(s, self.s, self.lane_width))
        return hit

    def neighbour_room(self, s0: float, s1: float) -> tuple[float, float]:
        """Narrowest same-direction neighbour lane width (left, right) over [s0, s1] (0 where there is none)."""
        key = (s0, s1)                                  # remembered as `width_at` (asked alike every step)
        hit = self._rooms.get(key)
        if hit is not None:
            return hit
        if len(self._rooms) >= PROJECTION_CACHE:
            self._rooms.clear()
        # The vertices with s0 <= s <= s1 (s is sorted): an index range, the same elements a mask would pick.
        lo, hi = bisect.bisect_left(self.s_list, s0), bisect.bisect_right(self.s_list, s1)
        if lo >= hi or s0 != s0 or s1 != s1:                           # (a NaN bound selects nothing)
            hit = float(np.interp(s0, self.s, self.room_left)), float(np.interp(s0, self.s, self.room_right))
        else:
            hit = float(self.room_left[lo:hi].min()), float(self.room_right[lo:hi].min())
        self._rooms[key] = hit
        return hit

    def junction_at(self, s: float) -> bool:
        return bool(self.in_junction[min(self._index(s) + 1, len(self.s) - 1)])

    def next_junction_entry(self, s: float, horizon: float) -> float | None:
        """Arc length where the line next enters a junction within `horizon` metres after `s` (None if none or
        already inside one)."""
        if self.junction_at(s):
            return None
        mask = (self.s > s) & (self.s <= s + horizon) & self.in_junction
        idx = np.flatnonzero(mask)
        if len(idx) == 0:
            return None
        return float(self.s[max(idx[0] - 1, 0)])

    def junction_exit(self, s: float) -> float:
        """Arc length where the junction stretch containing or following `s` ends."""
        idx = np.flatnonzero((self.s >= s) & ~self.in_junction)
        inside = np.flatnonzero((self.s >= s) & self.in_junction)
        if len(inside) == 0:
            return s
        after = idx[idx > inside[0]]
        return float(self.s[after[0]]) if len(after) else self.length

    def window(self, near_s: float, window: float) -> tuple[int, int]:
        """The segments (first, end) `project` searches for (near_s, window): those within `window` m of near_s."""
        # One step asks with the same (near_s, window) several times: for the ego twice, for every object.
        if self._window[0] == (near_s, window):
            return self._window[1]
        # (`_index` is within [0, last segment]: no clamping to the segments needed)
        lo = self._index(near_s - window)
        hi = self._index(near_s + window) + 1
        self._window = ((near_s, window), (lo, hi))
        return lo, hi

    def project(self, x: float, y: float, *, near_s: float | None = None, window: float = 60.0) -> PathPoint:
        """Nearest point of the line to (x, y): arc length, signed left offset, heading. With `near_s`, only the
        stretch within `window` metres of it is searched, so a route that passes the same place twice (loops,
        U-turns) projects onto the right pass."""
        lo, hi = (0, len(self._seg)) if near_s is None else self.window(near_s, window)
        # (0.0 == -0.0 as a key, but the sign of a zero can reach the answer: such points are not cached.)
        key = (x, y, lo, hi) if x != 0.0 and y != 0.0 else None
        hit = self._projections.get(key)
        if hit is not None:
            return hit
        cand = self._candidates(x, y) if key is not None else None
        if cand is not None and cand[0] >= lo and cand[-1] < hi:
            # Every segment that can be nearest lies in the window: the nearest of them (the first of equals,
            # as argmin) is the window's, found by the plain formula on a few floats.
            i, uj, pxj, pyj = self._nearest_of(x, y, cand)
        else:
            x0 = self._x0[lo:hi]
            y0 = self._y0[lo:hi]
            dx = self._dx[lo:hi]
            dy = self._dy[lo:hi]
            # Same operations in the same order as the plain formula, so the result is bit-identical to it.
            u = np.minimum(np.maximum(((x - x0) * dx + (y - y0) * dy) / self._L2[lo:hi], 0.0), 1.0)
            px = x0 + u * dx
            py = y0 + u * dy
            dist2 = (x - px) ** 2 + (y - py) ** 2
            j = int(dist2.argmin())
            i = lo + j
            uj, pxj, pyj = float(u[j]), float(px[j]), float(py[j])
        h = float(self._seg_heading[i])
        s = self.s_list[i] + uj * float(self._seg_len[i])
        # Beyond the ends, extend straight so objects ahead of the goal still get a sensible s.
        if i == self._last_seg and uj >= 1.0 or i == 0 and uj <= 0.0:
            k = i if uj <= 0.0 else i + 1
            ref_x, ref_y = float(self.xy[k, 0]), float(self.xy[k, 1])
            along = (x - ref_x) * math.cos(h) + (y - ref_y) * math.sin(h)
            s = self.s_list[k] + along
        cross = -(x - pxj) * math.sin(h) + (y - pyj) * math.cos(h)
        pp = PathPoint(s=float(s), offset=float(cross), heading=h)
        if key is not None:
            if len(self._projections) >= PROJECTION_CACHE:
                self._projections.clear()
            self._projections[key] = pp
        return pp

    def _candidates(self, x: float, y: float) -> tuple[int, ...] | None:
        """The segments (increasing) that can hold the nearest point of the line to any point of (x, y)'s cell
        (None: too many to search one by one). A point of the cell is within the half diagonal h of its centre,
        so its nearest segment is within d + h of it (d: the centre's distance to the line), and a segment
        farther than d + 2h from the centre is farther than that from the point: strictly, so it cannot tie
        either. Computed once per cell; a route's line serves every run that drives it."""
        key = (math.floor(x / CELL), math.floor(y / CELL))
        if key in self._cells:
            return self._cells[key]
        cx, cy = (key[0] + 0.5) * CELL, (key[1] + 0.5) * CELL
        u = np.clip(((cx - self._x0) * self._dx + (cy - self._y0) * self._dy) / self._L2, 0.0, 1.0)
        d = np.hypot(cx - (self._x0 + u * self._dx), cy - (self._y0 + u * self._dy))
        idx = np.flatnonzero(d <= float(d.min()) + 2.0 * _HALF_DIAGONAL + CHUNK_SLACK)
        found = tuple(idx.tolist()) if len(idx) <= CELL_CANDIDATES else None
        if len(self._cells) >= CELL_CACHE:
            self._cells.clear()
        self._cells[key] = found
        return found

    def _nearest_of(self, x: float, y: float, segments: tuple[int, ...]) -> tuple[int, float, float, float]:
        """(segment, u, foot x, foot y) of the nearest of `segments` (increasing) to (x, y), the first of
        equals: `project`'s array formula written out per segment, the same operations in the same order
        (np.maximum / np.minimum as comparisons; x ** 2 on an array is x * x)."""
        x0s, y0s, dxs, dys, l2s = self._x0_list, self._y0_list, self._dx_list, self._dy_list, self._L2_list
        best = math.inf
        found = (segments[0], 0.0, 0.0, 0.0)
        for i in segments:
            x0, y0, dx, dy = x0s[i], y0s[i], dxs[i], dys[i]
            u = ((x - x0) * dx + (y - y0) * dy) / l2s[i]
            u = u if u >= 0.0 else 0.0
            u = u if u <= 1.0 else 1.0
            px = x0 + u * dx
            py = y0 + u * dy
            ex, ey = x - px, y - py
            d2 = ex * ex + ey * ey
            if d2 < best:
                best = d2
                found = (i, u, px, py)
        return found

    def project_many(self, xs: np.ndarray, ys: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Vectorised (s, offset) of many points (used for predicted object positions)."""
        xs = np.asarray(xs, dtype=float)[:, None]
        ys = np.asarray(ys, dtype=float)[:, None]
        idx = self._candidate_segments(xs, ys)
        if idx is None:
            x0, y0, dx, dy, L2 = self._x0, self._y0, self._dx, self._dy, self._L2
        else:
            x0, y0, dx, dy, L2 = self._x0[idx], self._y0[idx], self._dx[idx], self._dy[idx], self._L2[idx]
        # The plain formula's operations in its order, so each segment's distance is bit-identical to it.
        u = np.minimum(np.maximum(((xs - x0) * dx + (ys - y0) * dy) / L2, 0.0), 1.0)
        px = x0 + u * dx
        py = y0 + u * dy
        dist2 = (xs - px) ** 2 + (ys - py) ** 2
        jj = np.argmin(dist2, axis=1)
        rows = np.arange(len(jj))
        j = jj if idx is None else idx[rows, jj]
        h = self._seg_heading[j]
        s = self.s[j] + u[rows, jj] * self._seg_len[j]
        off = -(xs[:, 0] - px[rows, jj]) * np.sin(h) + (ys[:, 0] - py[rows, jj]) * np.cos(h)
        return s, off

    def far_from(self, xs: np.ndarray, ys: np.ndarray, reach: float, s0: float, s1: float) -> bool:
        """True only when no point can have, in `project_many`, both |offset| < `reach` and s0 < s < s1: then
        the projection can be skipped (False: it may, project). `far_points` point by point."""
        far = self.far_points(xs, ys, reach, s0, s1)
        return far is not None and bool(far.all())

    def far_points(self, xs: np.ndarray, ys: np.ndarray, reach: float, s0: float, s1: float) -> np.ndarray | None:
        """Per point, True only when it cannot have, in `project_many`, both |offset| < `reach` and s0 < s < s1
        (None: no point can be told so). A point's projection does not depend on the others', so only the points
        not ruled out need projecting.

        A point whose nearest segment lies where the line runs between s0 and s1 is within `reach` of its offset
        only if it is within reach / cos(turn) of that segment: its offset is its distance where its foot is inside
        the segment, and at least the distance times the cosine of the turn where the foot is a vertex (the point
        then lies in the wedge between the two segments' normals). So a point farther than that from the circle
        of each chunk that spans part of (s0, s1) is answered, except beyond one of the line's ends, where the
        offset is only the distance across the end segment: that is tested as it is computed."""
        xs = np.asarray(xs, dtype=float)
        ys = np.asarray(ys, dtype=float)
        cs0, cs1 = self._chunk_lists[0], self._chunk_lists[1]
        k_lo = bisect.bisect_right(cs1, s0 - CHUNK_SLACK)      # the live chunks: a range, as s is sorted
        k_hi = bisect.bisect_left(cs0, s1 + CHUNK_SLACK)
        if k_lo >= k_hi:
            return np.ones(len(xs), dtype=bool)
        live = self._live_chunks.get((k_lo, k_hi))
        if live is None:
            if len(self._live_chunks) >= PROJECTION_CACHE:
                self._live_chunks.clear()
            inv_cos = self._chunk_inv_cos[k_lo:k_hi]
            live = self._live_chunks[(k_lo, k_hi)] = None if np.isinf(inv_cos).any() else (
                self._chunk_x[k_lo:k_hi], self._chunk_y[k_lo:k_hi], self._chunk_r[k_lo:k_hi], inv_cos)
        if live is None:
            return None
        cx, cy, r, inv_cos = live
        gap = np.hypot(xs[:, None] - cx, ys[:, None] - cy) - r
        far = (gap > reach * inv_cos * (1.0 + 1e-9) + CHUNK_SLACK).all(axis=1)
        for is_live, (ex, ey, c, s, sign) in zip((k_lo == 0, k_hi == len(cs0)), self._ends):
            if not is_live:
                continue
            dx, dy = xs - ex, ys - ey
            beyond = sign * (dx * c + dy * s) > -CHUNK_SLACK       # may be clamped to this end
            far &= ~(beyond & (np.abs(dy * c - dx * s) < reach + CHUNK_SLACK))
        return far

    def far_from_straight(self, ax: float, ay: float, bx: float, by: float, reach: float, s0: float,
                          s1: float) -> bool:
        """`far_from` for every point of the straight piece from (ax, ay) to (bx, by) (a course at constant
        heading), in plain floats: the piece's distance to each live chunk's centre bounds its points', and beyond
        an end the offset and the along-distance are affine along the piece, so where both conditions of a near
        point hold is an interval. Twice the slack, for points computed on the piece another way."""
        cs0, cs1, cxs, cys, crs, inv_cos = self._chunk_lists
        slack = 2.0 * CHUNK_SLACK
        k_lo = bisect.bisect_right(cs1, s0 - CHUNK_SLACK)      # the live chunks: a range, as s is sorted
        k_hi = bisect.bisect_left(cs0, s1 + CHUNK_SLACK)
        if k_lo >= k_hi:
            return True
        vx, vy = bx - ax, by - ay
        v2 = vx * vx + vy * vy
        group = self._chunk_group(k_lo, k_hi)
        if group is None:
            return False                   # a turn too sharp to bound: the loop below would stop there
        gx, gy, gr, worst = group
        # (min(max(q, 0.0), 1.0) here and in the loop as the builtins compare: the same value, a fifth of the cost)
        q = 0.0 if v2 == 0.0 else ((gx - ax) * vx + (gy - ay) * vy) / v2
        q = 0.0 if 0.0 > q else q
        t = 1.0 if 1.0 < q else q
        # One circle holding every live chunk's circle: a piece clear of it by the largest bound is clear of each
        # (its distance to a chunk's circle is at least its distance to this one; `_chunk_group` adds slack for
        # the rounding), so the chunk loop would find them all clear.
        if not math.hypot(gx - (ax + t * vx), gy - (ay + t * vy)) - gr > reach * worst * (1.0 + 1e-9) + slack:
            for k in range(k_lo, k_hi):
                cx, cy = cxs[k], cys[k]
                q = 0.0 if v2 == 0.0 else ((cx - ax) * vx + (cy - ay) * vy) / v2
                q = 0.0 if 0.0 > q else q
                t = 1.0 if 1.0 < q else q
                if not math.hypot(cx - (ax + t * vx), cy - (ay + t * vy)) - crs[k] > \
                        reach * inv_cos[k] * (1.0 + 1e-9) + slack:
                    return False
        for end, seg, sign, is_live in ((0, 0, -1.0, k_lo == 0), (len(self.xy) - 1, self._last_seg, 1.0,
                                                                     k_hi == len(cs0))):
            if not is_live:
                continue
            h = float(self._seg_heading[seg])
            c, s = math.cos(h), math.sin(h)
            ex, ey = float(self.xy[end, 0]), float(self.xy[end, 1])
            along = [sign * ((px - ex) * c + (py - ey) * s) for px, py in ((ax, ay), (bx, by))]
            across = [(py - ey) * c - (px - ex) * s for px, py in ((ax, ay), (bx, by))]
            a_lo, a_hi = _affine_interval(along[0], along[1], -slack, math.inf)
            c_lo, c_hi = _affine_interval(across[0], across[1], -(reach + slack), reach + slack)
            if max(a_lo, c_lo) <= min(a_hi, c_hi):
                return False
        return True

    def _chunk_group(self, k_lo: int, k_hi: int) -> tuple[float, float, float, float] | None:
        """(x, y, radius, largest 1/cos) of one circle holding the circles of chunks k_lo..k_hi - 1 (None when a
        turn among them is too sharp to bound), remembered by range. The radius has GROUP_SLACK m added, far
        above the rounding of the distances compared with it."""
        key = (k_lo, k_hi)
        if key in self._groups:
            return self._groups[key]
        if len(self._groups) >= PROJECTION_CACHE:
            self._groups.clear()
        inv_cos = self._chunk_inv_cos[k_lo:k_hi]
        if np.isinf(inv_cos).any():
            found = None
        else:
            cx, cy, r = self._chunk_x[k_lo:k_hi], self._chunk_y[k_lo:k_hi], self._chunk_r[k_lo:k_hi]
            gx, gy = 0.5 * (float(cx.min()) + float(cx.max())), 0.5 * (float(cy.min()) + float(cy.max()))
            gr = float((np.hypot(cx - gx, cy - gy) + r).max()) + GROUP_SLACK
            found = (gx, gy, gr, float(inv_cos.max()))
        self._groups[key] = found
        return found

    def _candidate_segments(self, xs: np.ndarray, ys: np.ndarray) -> np.ndarray | None:
        """Per point (row), increasing segment indices covering every chunk that may hold its nearest segment
        (None: search them all). A chunk is left out only when even its nearest possible point is farther than
        the farthest possible point of another chunk, so the first nearest segment (np.argmin's answer over the
        whole line) is always inside; extra segments in between change nothing. Rows are padded with the last
        segment repeated, which comes after the real one and so never wins a tie."""
        n_chunks = len(self._chunk_r)
        if n_chunks <= MIN_CHUNKS:
            return None                                   # a short line: the bounds would cost more than they save
        dc = np.hypot(xs - self._chunk_x, ys - self._chunk_y)
        lower = dc - self._chunk_r
        upper = (dc + self._chunk_r).min(axis=1, keepdims=True)
        cand = lower <= upper * (1.0 + 1e-9) + CHUNK_SLACK
        first = np.argmax(cand, axis=1)
        last = n_chunks - 1 - np.argmax(cand[:, ::-1], axis=1)
        width = int((last - first).max()) + 1
        if 2 * width > n_chunks:
            return None                                   # little to gain: search the whole line
        idx = first[:, None] * CHUNK + np.arange(width * CHUNK)[None, :]
        return np.minimum(idx, self._last_seg)


def _affine_interval(f0: float, f1: float, lo: float, hi: float) -> tuple[float, float]:
    """The part of [0, 1] where f0 + t (f1 - f0) lies within [lo, hi], as (start, end) (start > end: none)."""
    df = f1 - f0
    if df == 0.0:
        return (0.0, 1.0) if lo <= f0 <= hi else (1.0, 0.0)
    ta, tb = (lo - f0) / df, (hi - f0) / df
    if ta > tb:
        ta, tb = tb, ta
    return max(ta, 0.0), min(tb, 1.0)
