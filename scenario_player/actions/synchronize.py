"""SynchronizeAction: the actor arrives at its target position when the master arrives at its own, with a final
speed (absolute, or relative to the master's; optionally reached a steady-state distance/time before).

Each step the actor re-plans a two-phase profile — constant acceleration a, then −a until the final speed — that
covers the remaining distance in the master's remaining time, and applies its first dt (without a final speed the
required mean speed is taken at once). Remaining distances are measured
along the lanes once at start and then decreased by the distance actually travelled (odometer), so junctions and
curves are handled without projecting every step.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

from lxml import etree

from txt2sce_ros.road import LanePath

from ..syntax.positions import Pose, Position, position_from_xml
from ..syntax.xml import ParseContext
from .base import LONGITUDINAL, ActionRun

if TYPE_CHECKING:
    from ..world.entity import Entity
    from ..world.world import World


@dataclass(frozen=True, slots=True)
class SynchronizeAction:
    master: str
    master_target: Position
    target: Position
    final_absolute: float | None
    final_relative: tuple[str, float] | None      # (delta|factor, value)
    steady_distance: float | None
    steady_time: float | None
    tolerance: float
    tolerance_master: float
    is_private = True

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "SynchronizeAction":
        final_abs = final_rel = None
        sd = st = None
        fs = el.find("FinalSpeed")
        if fs is not None:
            choice = ctx.only_child(fs)
            if choice.tag == "AbsoluteSpeed":
                final_abs = ctx.float(choice, "value")
                holder = choice
            else:
                final_rel = (choice.get("speedTargetValueType", "delta"), ctx.float(choice, "value"))
                holder = choice
            steady = holder.find("SteadyState")
            steady = steady[0] if steady is not None and len(steady) else holder.find("TargetDistanceSteadyState")
            if steady is None:
                steady = holder.find("TargetTimeSteadyState")
            if steady is not None:
                if steady.tag == "TargetDistanceSteadyState":
                    sd = ctx.float(steady, "distance")
                else:
                    st = ctx.float(steady, "time")
        return cls(ctx.req(el, "masterEntityRef"), position_from_xml(ctx, ctx.child(el, "TargetPositionMaster")),
                   position_from_xml(ctx, ctx.child(el, "TargetPosition")), final_abs, final_rel, sd, st,
                   ctx.float(el, "targetTolerance", 1.0), ctx.float(el, "targetToleranceMaster", 1.0))

    def start(self, world: "World", ent: "Entity | None") -> ActionRun | None:
        assert ent is not None
        return SynchronizeRun(ent, self, world)


def path_distance(world: "World", ent: "Entity", pose: Pose) -> float:
    """Distance from the entity to a pose along the lanes (straight line when no lane route exists)."""
    if ent.track is not None and pose.road_id is not None and pose.s is not None:
        try:
            start = ent.track.ref
            goal = world.net.lane_ref(pose.road_id, pose.lane_id, pose.s)
            if start.road_id == goal.road_id and start.lane_id == goal.lane_id:
                return (pose.s - ent.s) * (1.0 if ent.track.forward else -1.0)
            refs = world.net.route(start, goal)
            path = LanePath.from_lanes(world.net, refs, s_start=ent.s, s_end=pose.s)
            return path.length
        except Exception:  # noqa: BLE001 - no lane route: fall back to the straight line
            pass
    return math.hypot(pose.x - ent.x, pose.y - ent.y)


class SynchronizeRun(ActionRun):
    domains = frozenset({LONGITUDINAL})

    def __init__(self, ent: "Entity", spec: SynchronizeAction, world: "World") -> None:
        super().__init__(ent)
        self.spec = spec
        self.master = world.entity(spec.master)
        self.d_actor = path_distance(world, ent, spec.target.resolve(world))
        self.d_master = path_distance(world, self.master, spec.master_target.resolve(world))
        self.odo_actor, self.odo_master = ent.odometer, self.master.odometer

    def _final(self) -> float | None:
        sp = self.spec
        if sp.final_absolute is not None:
            return sp.final_absolute
        if sp.final_relative is not None:
            kind, value = sp.final_relative
            return self.master.speed * value if kind == "factor" else self.master.speed + value
        return None

    def step(self, world: "World", dt: float) -> None:
        ent, master = self.entity, self.master
        da = self.d_actor - (ent.odometer - self.odo_actor)
        dm = self.d_master - (master.odometer - self.odo_master)
        vf = self._final()
        if dm <= 0.0 or master.speed <= 1e-6 and dm > 0 and ent.speed <= 1e-6:
            if vf is not None:
                ent.speed = vf
            self.done = dm <= 0.0
            return
        t_left = dm / max(master.speed, 1e-6)
        if vf is not None and self.spec.steady_distance is not None:
            da -= self.spec.steady_distance
            t_left -= self.spec.steady_distance / max(vf, 1e-6)
        elif vf is not None and self.spec.steady_time is not None:
            da -= self.spec.steady_time * vf
            t_left -= self.spec.steady_time
        if t_left <= dt or da <= 0.0:
            if vf is not None:
                ent.speed = vf
            if dm <= self.spec.tolerance_master or t_left <= 0:
                self.done = True
            return
        if vf is None:
            ent.speed = da / t_left
        else:
            a = _two_phase_accel(ent.speed, vf, t_left, da)
            t1 = 0.5 * (t_left + (vf - ent.speed) / a) if abs(a) > 1e-9 else t_left
            t1 = min(max(t1, 0.0), t_left)
            ent.speed = max(0.0, ent.speed + a * min(dt, t1) - a * max(0.0, dt - t1))
        ent.speed = min(ent.speed, ent.spec.max_speed)


def _two_phase_accel(v0: float, vf: float, T: float, D: float) -> float:
    """Acceleration a of the profile 'a for t1, then −a for T − t1' from v0 to vf covering D in T."""
    d_lin = 0.5 * (v0 + vf) * T
    if abs(D - d_lin) < 1e-9:
        return (vf - v0) / T if T > 0 else 0.0
    sign = 1.0 if D > d_lin else -1.0

    def dist(mag: float) -> float:
        a = sign * mag
        t1 = 0.5 * (T + (vf - v0) / a)
        t2 = T - t1
        vp = v0 + a * t1
        return 0.5 * (v0 + vp) * t1 + 0.5 * (vp + vf) * t2

    lo = abs(vf - v0) / T + 1e-9         # below this the two phases cannot meet vf in time
    hi = max(lo * 2.0, 1.0)
    while (dist(hi) - D) * sign < 0 and hi < 1e4:
        hi *= 2.0
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if (dist(mid) - D) * sign < 0:
            lo = mid
        else:
            hi = mid
    return sign * 0.5 * (lo + hi)
