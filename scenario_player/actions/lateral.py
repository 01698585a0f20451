"""LateralAction family: LaneChangeAction, LaneOffsetAction, LateralDistanceAction.

Lateral position is the entity's `offset` from its lane centre (toward +t of the road). A lane change moves the
entity onto the target lane at once with an offset that keeps it where it is, then shapes that offset to the
target lane offset: the same geometry esmini uses, and no jump in position.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

from lxml import etree

from txt2sce_ros.errors import InputError

from ..syntax.xml import ParseContext
from .base import LATERAL, SHAPE_PEAK, ActionRun, TransitionDynamics, shape_value

if TYPE_CHECKING:
    from ..world.entity import Entity
    from ..world.world import World


def lanes_left(lane_id: int, forward: bool, k: int) -> int:
    """The lane `k` lanes to the left (k<0: right) of `lane_id` in its driving direction (skipping lane 0)."""
    step = k if forward else -k
    target = lane_id + step
    if lane_id < 0 <= target or lane_id > 0 >= target:
        target += 1 if step > 0 else -1
    return target


def _switch_lane(world: "World", ent: "Entity", target_lane: int) -> None:
    """Move the entity's tracking to `target_lane` at the same s, keeping its world position."""
    tr = ent.track
    assert tr is not None
    road_t = tr.center_t(ent.s) + ent.offset
    new = world.tracks.at(tr.ref.road_id, target_lane, ent.s)
    if new.forward != tr.forward:
        ent.reverse = not ent.reverse       # keep travelling the same way in the world
    ent.track = new
    ent.offset = road_t - new.center_t(ent.s)
    ent._sync_road()


@dataclass(frozen=True, slots=True)
class LaneChangeAction:
    dynamics: TransitionDynamics
    absolute_lane: int | None
    ref: str | None
    relative: int
    target_offset: float
    is_private = True

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "LaneChangeAction":
        target = ctx.only_child(ctx.child(el, "LaneChangeTarget"))
        dyn = TransitionDynamics.from_xml(ctx, ctx.child(el, "LaneChangeActionDynamics"))
        offset = ctx.float(el, "targetLaneOffset", 0.0)
        if target.tag == "AbsoluteTargetLane":
            return cls(dyn, ctx.int(target, "value"), None, 0, offset)
        if target.tag == "RelativeTargetLane":
            return cls(dyn, None, ctx.req(target, "entityRef"), ctx.int(target, "value"), offset)
        raise ctx.error(target, f"unknown lane change target <{target.tag}>")

    def start(self, world: "World", ent: "Entity | None") -> ActionRun | None:
        assert ent is not None
        if ent.track is None:
            raise InputError(f"LaneChangeAction on '{ent.name}', which is not on a lane", source=world.source,
                             element="LaneChangeAction")
        if self.absolute_lane is not None:
            lane = self.absolute_lane
        else:
            ref = world.entity(self.ref or "")
            if ref.track is None:
                raise InputError(f"LaneChangeAction reference '{ref.name}' is not on a lane", source=world.source,
                                 element="RelativeTargetLane")
            lane = lanes_left(ref.track.ref.lane_id, ref.track.forward, self.relative)
            if ref.track.ref.road_id != ent.track.ref.road_id:
                lane = lanes_left(ent.track.ref.lane_id, ent.track.forward, self.relative)
        _switch_lane(world, ent, lane)
        run = OffsetRun(ent, ent.offset, self.target_offset, self.dynamics)
        run.consumes_travel = True      # a lane change moves along the path it curves on (esmini's model)
        return run


class OffsetRun(ActionRun):
    """Shapes the lateral offset from `start` to `end` over time or travelled distance."""

    domains = frozenset({LATERAL})

    def __init__(self, ent: "Entity", start: float, end: float, dyn: TransitionDynamics,
                 duration: float | None = None, continuous: bool = False) -> None:
        super().__init__(ent)
        self.o0, self.o1, self.dyn = start, end, dyn
        self.progress = 0.0
        self.continuous = continuous
        if duration is not None:
            self.total = duration
            self.by_distance = False
        elif dyn.dimension == "rate":
            # The rate is the lateral speed (m/s) the change may reach: the shape's peak, not its mean. OpenSCENARIO
            # (TransitionDynamics, DynamicsDimension "rate") gives only "the rate at which the target value is
            # acquired"; a shaped change has no single rate, and the reading that stays within the stated value is
            # the peak, as esmini does. So a sinusoidal change of |Δ| lasts π·|Δ|/(2·rate), a cubic 1.5·|Δ|/rate,
            # a linear |Δ|/rate (conformance case lane_change_rate).
            self.total = SHAPE_PEAK[dyn.shape] * abs(end - start) / dyn.value if dyn.value > 0 else 0.0
            self.by_distance = False
        else:
            self.total = dyn.value
            self.by_distance = dyn.dimension == "distance"
        if self.total <= 0.0 or dyn.shape == "step":
            ent.offset = end
            self.done = not continuous

    def step(self, world: "World", dt: float) -> None:
        ent = self.entity
        self.progress += abs(ent.speed) * dt if self.by_distance else dt
        f = shape_value(self.dyn.shape, self.progress / self.total) if self.total > 0 else 1.0
        ent.offset = self.o0 + (self.o1 - self.o0) * f
        if f >= 1.0 and not self.continuous:
            self.done = True


def _offset_duration(shape: str, delta: float, max_lat_acc: float) -> float:
    """Duration of an offset change whose peak lateral acceleration is `max_lat_acc`."""
    d = abs(delta)
    if d < 1e-9 or max_lat_acc <= 0:
        return 0.0
    if shape == "cubic":
        return math.sqrt(6.0 * d / max_lat_acc)
    if shape == "sinusoidal":
        return math.pi * math.sqrt(d / (2.0 * max_lat_acc))
    if shape == "linear":
        return math.sqrt(4.0 * d / max_lat_acc)   # as if accelerating then braking at the limit
    return 0.0


@dataclass(frozen=True, slots=True)
class LaneOffsetAction:
    shape: str
    max_lat_acc: float
    absolute: float | None
    ref: str | None
    relative: float
    continuous: bool
    is_private = True

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "LaneOffsetAction":
        dyn = ctx.child(el, "LaneOffsetActionDynamics")
        target = ctx.only_child(ctx.child(el, "LaneOffsetTarget"))
        shape, acc = dyn.get("dynamicsShape", "step"), ctx.float(dyn, "maxLateralAcc", 0.5)
        if target.tag == "AbsoluteTargetLaneOffset":
            return cls(shape, acc, ctx.float(target, "value"), None, 0.0, ctx.bool(el, "continuous", False))
        return cls(shape, acc, None, ctx.req(target, "entityRef"), ctx.float(target, "value"),
                   ctx.bool(el, "continuous", False))

    def start(self, world: "World", ent: "Entity | None") -> ActionRun | None:
        assert ent is not None
        if self.absolute is not None:
            end = self.absolute
        else:
            ref = world.entity(self.ref or "")
            end = ref.offset + self.relative
        dyn = TransitionDynamics(self.shape, "time", 0.0)
        return OffsetRun(ent, ent.offset, end, dyn, _offset_duration(self.shape, end - ent.offset, self.max_lat_acc))


@dataclass(frozen=True, slots=True)
class LateralDistanceAction:
    """Keep a lateral distance to `ref` (road t), optionally within lateral speed/acceleration limits."""

    ref: str
    distance: float
    freespace: bool
    continuous: bool
    displacement: str
    max_speed: float | None
    max_accel: float | None
    is_private = True

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "LateralDistanceAction":
        dc = el.find("DynamicConstraints")
        get = (lambda n: None if dc is None or dc.get(n) is None else ctx.float(dc, n))  # noqa: E731
        return cls(ctx.req(el, "entityRef"), ctx.float(el, "distance", 0.0), ctx.bool(el, "freespace", False),
                   ctx.bool(el, "continuous", False), el.get("displacement", "any"), get("maxSpeed"),
                   get("maxAcceleration"))

    def start(self, world: "World", ent: "Entity | None") -> ActionRun | None:
        assert ent is not None
        return LateralDistanceRun(ent, self, world)


class LateralDistanceRun(ActionRun):
    domains = frozenset({LATERAL})
    # esmini advances an entity keeping a lateral distance along the lane centre (keep_lateral_distance agrees to
    # 0.38 m this way, 0.75 m at the offset radius), unlike offsets set by lane changes and LaneOffsetActions.
    travels_at_offset = False

    def __init__(self, ent: "Entity", spec: LateralDistanceAction, world: "World") -> None:
        super().__init__(ent)
        self.spec = spec
        self.ref = world.entity(spec.ref)
        self.vel = 0.0

    def step(self, world: "World", dt: float) -> None:
        ent, ref, sp = self.entity, self.ref, self.spec
        if ent.track is None or ref.track is None:
            self.done = True
            return
        forward = ent.track.forward
        # Side in the actor's driving direction, expressed in road t.
        side = sp.displacement
        if side == "any":
            left = (ent.road_t - ref.road_t) * (1 if forward else -1) >= 0
        else:
            left = side == "leftToReferencedEntity"
        sign_t = (1.0 if left else -1.0) * (1.0 if forward else -1.0)
        dist = sp.distance + ((ent.spec.width + ref.spec.width) / 2.0 if sp.freespace else 0.0)
        want_t = ref.road_t + sign_t * dist
        want_offset = want_t - ent.track.center_t(ent.s)
        err = want_offset - ent.offset
        if sp.max_speed is None and sp.max_accel is None:
            ent.offset = want_offset
        else:
            vmax = sp.max_speed if sp.max_speed is not None else math.inf
            if sp.max_accel is None:
                # Rigid move at most at the lateral speed limit.
                self.vel = math.copysign(min(vmax, abs(err) / dt), err)
            else:
                # Critically damped spring toward the wanted offset, within the acceleration and speed limits.
                k = 0.4 * sp.max_accel
                acc = err * k - self.vel * 2.0 * math.sqrt(k)
                acc = max(-sp.max_accel, min(sp.max_accel, acc))
                self.vel = max(-vmax, min(vmax, self.vel + acc * dt))
            ent.offset += self.vel * dt
        if not sp.continuous and abs(want_offset - ent.offset) < 0.01:
            self.done = True
