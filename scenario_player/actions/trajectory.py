"""FollowTrajectoryAction: Polyline, Clothoid and Nurbs shapes, with or without timing.

The shape is turned into a dense polyline (x, y, optional time) once, when the action starts (relative vertex
positions depend on where their reference entity is then). Untimed: the entity moves along it at its own speed
(longitudinal actions still control the speed; the trajectory takes the lateral domain). Timed: the trajectory
dictates position and speed (both domains). At the end the entity goes on straight, attached to the lane under
it if any (esmini continues the same way).
"""

from __future__ import annotations

import bisect
import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from lxml import etree

from ..syntax.positions import WorldPosition
from ..syntax.routes import Clothoid, Nurbs, Polyline, Trajectory
from ..syntax.xml import ParseContext
from .base import LATERAL, LONGITUDINAL, ActionRun

if TYPE_CHECKING:
    from ..world.entity import Entity
    from ..world.world import World


@dataclass(frozen=True, slots=True)
class FollowTrajectoryAction:
    trajectory: Trajectory
    timing: tuple[str, float, float] | None        # (absolute|relative, scale, offset); None = untimed
    following_mode: str
    initial_distance: float
    is_private = True

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "FollowTrajectoryAction":
        holder = el.find("TrajectoryRef")
        traj_el = (holder if holder is not None else el).find("Trajectory")
        if traj_el is None:
            raise ctx.error(el, "FollowTrajectoryAction holds no Trajectory (or its CatalogReference did not resolve)")
        timing_el = el.find("TimeReference/Timing")
        timing = None
        if timing_el is not None:
            timing = (timing_el.get("domainAbsoluteRelative", "relative"), ctx.float(timing_el, "scale", 1.0),
                      ctx.float(timing_el, "offset", 0.0))
        mode_el = el.find("TrajectoryFollowingMode")
        return cls(Trajectory.from_xml(ctx, traj_el), timing,
                   "position" if mode_el is None else mode_el.get("followingMode", "position"),
                   ctx.float(el, "initialDistanceOffset", 0.0))

    def start(self, world: "World", ent: "Entity | None") -> ActionRun | None:
        assert ent is not None
        pts, times = sample_shape(world, self.trajectory)
        timed = self.timing is not None and times is not None
        return TrajectoryRun(ent, pts, times if timed else None, self.timing, self.initial_distance, world.t)


def _xy(world: "World", position: object) -> tuple[float, float]:
    """A shape point's (x, y). A WorldPosition is its own point: resolving it would also locate it on a lane
    (~0.1 ms per vertex, dozens per trajectory), which a shape's points do not use."""
    if isinstance(position, WorldPosition):
        return position.x, position.y
    pose = position.resolve(world)  # type: ignore[attr-defined]
    return pose.x, pose.y


def sample_shape(world: "World", traj: Trajectory) -> tuple[np.ndarray, np.ndarray | None]:
    shape = traj.shape
    if isinstance(shape, Polyline):
        pts = np.array([_xy(world, v.position) for v in shape.vertices], dtype=float)
        times = [v.time for v in shape.vertices]
        return pts, (None if any(t is None for t in times) else np.array(times, dtype=float))
    if isinstance(shape, Clothoid):
        return _clothoid(world, shape)
    assert isinstance(shape, Nurbs)
    return _nurbs(world, shape)


def _clothoid(world: "World", c: Clothoid) -> tuple[np.ndarray, np.ndarray | None]:
    pose = c.position.resolve(world) if c.position is not None else None
    x, y, h = (pose.x, pose.y, pose.h) if pose is not None else (0.0, 0.0, 0.0)
    n = max(2, int(math.ceil(c.length / 0.1)) + 1)
    s = np.linspace(0.0, c.length, n)
    heading = h + c.curvature * s + 0.5 * c.curvature_dot * s * s
    ds = np.diff(s)
    mid = 0.5 * (heading[:-1] + heading[1:])
    xs = x + np.concatenate([[0.0], np.cumsum(ds * np.cos(mid))])
    ys = y + np.concatenate([[0.0], np.cumsum(ds * np.sin(mid))])
    times = None
    if c.start_time is not None and c.stop_time is not None:
        times = c.start_time + (c.stop_time - c.start_time) * s / max(c.length, 1e-9)
    return np.column_stack([xs, ys]), times


PEAK_LOOKAHEAD = 1e-3      # in the NURBS parameter (knot units), see _nurbs


def _nurbs(world: "World", nb: Nurbs) -> tuple[np.ndarray, np.ndarray | None]:
    """Sample the rational B-spline about every metre of its control polygon. Times: each control point's time
    belongs to the sample where its basis function peaks, and is interpolated linearly in the parameter in
    between (how esmini times NURBS trajectories; the standard leaves the timing between control points open).

    The peak is the sample whose basis is largest PEAK_LOOKAHEAD after it, not at it: that is the sample the
    shared esmini picks. Measured with its recordings of trajectory-test.xosc and variants (other knot vectors,
    228 and 257 samples): 15 of 15 peaks agree this way, 10 of 15 at the sample itself; a peak one sample off
    shifts the timing of a whole segment (0.7 m at 14 m/s in trajectory-test)."""
    ctrl = np.array([_xy(world, cp.position) for cp in nb.points], dtype=float)
    w = np.array([cp.weight for cp in nb.points], dtype=float)
    ctimes = [cp.time for cp in nb.points]
    knots = np.array(nb.knots, dtype=float)
    k = nb.order
    polygon = float(np.hypot(*np.diff(ctrl, axis=0).T).sum()) if len(ctrl) > 1 else 0.0
    steps = int(1 + polygon / 1.0)
    u = np.minimum(np.arange(steps + 1) * (knots[-1] / steps), knots[-1] - 1e-10)
    u = np.maximum(u, knots[0])
    basis = np.array([_basis(knots, k, i, u) for i in range(len(ctrl))])     # (n, m)
    wb = basis * w[:, None]
    den = wb.sum(axis=0)
    den[den == 0] = 1.0
    pts = (wb.T @ ctrl) / den[:, None]
    times = None
    if all(t is not None for t in ctimes) and len(ctrl) > 1:
        ahead = np.minimum(u + PEAK_LOOKAHEAD, knots[-1] - 1e-10)
        peak_u = u[np.argmax(np.array([_basis(knots, k, i, ahead) for i in range(len(ctrl))]), axis=1)]
        times = np.empty(len(u))
        seg = 0
        for j, uj in enumerate(u):
            if seg + 1 < len(ctrl) - 1 and uj >= peak_u[seg + 1]:
                seg += 1
            span = peak_u[seg + 1] - peak_u[seg]
            f = (uj - peak_u[seg]) / span if span > 0 else 0.0
            times[j] = ctimes[seg] + f * (ctimes[seg + 1] - ctimes[seg])  # type: ignore[operator]
    return pts, times


def _basis(knots: np.ndarray, order: int, i: int, u: np.ndarray) -> np.ndarray:
    """Cox–de Boor B-spline basis N_{i,order}(u); the last knot span is closed so u = end evaluates."""
    last = knots[-1]
    if order == 1:
        upper = (u < knots[i + 1]) | ((u == last) & (knots[i + 1] == last) & (knots[i] < last))
        return ((u >= knots[i]) & upper).astype(float)
    out = np.zeros_like(u)
    d1 = knots[i + order - 1] - knots[i]
    d2 = knots[i + order] - knots[i + 1]
    if d1 > 0:
        out += (u - knots[i]) / d1 * _basis(knots, order - 1, i, u)
    if d2 > 0:
        out += (knots[i + order] - u) / d2 * _basis(knots, order - 1, i + 1, u)
    return out


class TrajectoryRun(ActionRun):
    moves_entity = True
    def __init__(self, ent: "Entity", pts: np.ndarray, times: np.ndarray | None,
                 timing: tuple[str, float, float] | None, initial: float, t0: float) -> None:
        super().__init__(ent)
        keep = np.concatenate([[True], np.hypot(*np.diff(pts, axis=0).T) > 1e-9])
        pts = pts[keep]
        self.times = None if times is None else times[keep]
        self.xs, self.ys = pts[:, 0].tolist(), pts[:, 1].tolist()
        seg = np.hypot(*np.diff(pts, axis=0).T) if len(pts) > 1 else np.zeros(0)
        self.arc = np.concatenate([[0.0], np.cumsum(seg)]).tolist()
        self.length = self.arc[-1]
        self.pos = initial
        self.t0 = t0
        self.timing = timing
        self.domains = frozenset({LATERAL, LONGITUDINAL}) if self.times is not None else frozenset({LATERAL})
        ent.track = None
        ent.lane_locked = False
        ent.heading_override = None
        ent.present = True              # a trajectory in Init places an entity that was never teleported
        # A vehicle whose reference point sits ahead of its rear axle (esmini's refpoint_x_offset property) steers
        # like a bicycle: the point follows the path and the body heading trails it (a tractrix).
        try:
            self.axle_offset = float(ent.spec.properties.get("refpoint_x_offset", "0") or 0.0)
        except ValueError:
            self.axle_offset = 0.0
        self._place(self.pos, initial=True)

    def _at(self, a: float) -> tuple[float, float, float]:
        arc = self.arc
        if len(arc) < 2:
            return self.xs[0], self.ys[0], self.entity.h
        a = min(max(a, 0.0), self.length)
        i = min(max(bisect.bisect_right(arc, a) - 1, 0), len(arc) - 2)
        span = arc[i + 1] - arc[i]
        f = (a - arc[i]) / span if span > 0 else 0.0
        x = self.xs[i] + f * (self.xs[i + 1] - self.xs[i])
        y = self.ys[i] + f * (self.ys[i + 1] - self.ys[i])
        h = math.atan2(self.ys[i + 1] - self.ys[i], self.xs[i + 1] - self.xs[i])
        return x, y, h

    def _place(self, a: float, initial: bool = False) -> None:
        x, y, h = self._at(a)
        ent = self.entity
        if self.axle_offset > 0 and not initial:
            rx = ent.x - self.axle_offset * math.cos(ent.h)
            ry = ent.y - self.axle_offset * math.sin(ent.h)
            h = math.atan2(y - ry, x - rx)
        ent.x, ent.y, ent.h = x, y, h

    def step(self, world: "World", dt: float) -> None:
        ent = self.entity
        if self.times is not None:
            scale, offset = (self.timing[1], self.timing[2]) if self.timing else (1.0, 0.0)
            local_t = world.t + dt if self.timing and self.timing[0] == "absolute" else world.t + dt - self.t0
            traj_t = (local_t - offset) / scale if scale else local_t
            tl = self.times.tolist()
            if traj_t >= tl[-1]:
                new = self.length
            elif traj_t <= tl[0]:
                new = 0.0
            else:
                j = min(max(bisect.bisect_right(tl, traj_t) - 1, 0), len(tl) - 2)
                span = tl[j + 1] - tl[j]
                f = (traj_t - tl[j]) / span if span > 0 else 1.0
                new = self.arc[j] + f * (self.arc[j + 1] - self.arc[j])
            ent.speed = (new - self.pos) / dt
            self.pos = new
        else:
            self.pos += ent.speed * dt
        over = self.pos - self.length
        if over > 0:
            h = ent.h if self.axle_offset > 0 else self._at(self.length)[2]
            ent.x, ent.y = self._at(self.length)[:2]
            ent.x += over * math.cos(h)
            ent.y += over * math.sin(h)
            ent.h = h
        else:
            self._place(self.pos)
        if self.pos >= self.length - 1e-9:
            self.done = True
            world.reattach(ent)
            ent.placed = True           # already moved this step: default motion takes over from the next one

