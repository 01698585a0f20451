"""ByEntityConditions: each check is evaluated per triggering entity (rule 'any' or 'all' combines them).

Distances come from `world/measure.py` (one implementation of freespace / reference-point, longitudinal / lateral /
cartesian distance in entity or road coordinates) so every condition and action measures the same way.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

from lxml import etree

from ..syntax.positions import Position, position_from_xml
from ..syntax.xml import ParseContext
from .base import Check, Rule

if TYPE_CHECKING:
    from ..world.entity import Entity
    from ..world.world import World

LARGE = 1e10


class EntityCheck:
    """A check about one triggering entity."""

    def holds_for(self, world: "World", ent: "Entity") -> bool:
        raise NotImplementedError


def _distance_kind(el: etree._Element) -> tuple[str, str]:
    """(relativeDistanceType, coordinateSystem) with the 1.0 alongRoute attribute mapped to road coordinates."""
    rdt = el.get("relativeDistanceType", "euclidianDistance")
    rdt = {"euclideanDistance": "euclidianDistance", "cartesianDistance": "euclidianDistance"}.get(rdt, rdt)
    cs = el.get("coordinateSystem")
    if cs is None:
        cs = "road" if el.get("alongRoute", "false").lower() == "true" else "entity"
    return rdt, cs


@dataclass(frozen=True, slots=True)
class ByEntityCondition(Check):
    entities: tuple[str, ...]
    rule: str                     # 'any' | 'all'
    check: EntityCheck

    def holds(self, world: "World") -> bool:
        if len(self.entities) == 1:     # the usual case, evaluated every step: skip the generator
            return bool(self.check.holds_for(world, world.entity(self.entities[0])))
        results = (self.check.holds_for(world, world.entity(n)) for n in self.entities)
        return any(results) if self.rule == "any" else all(results)


@dataclass(frozen=True, slots=True)
class _ValueCheck(EntityCheck):
    """A quantity of the entity compared with `value` by `rule` (Speed, Acceleration): one parser for both."""

    value: float
    rule: Rule

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "_ValueCheck":
        return cls(ctx.float(el, "value"), Rule.from_xml(ctx, el))


class SpeedCondition(_ValueCheck):
    # No fields of its own: the base's generated methods serve it as they are (`__eq__` compares the exact class),
    # so it is not a dataclass again (that would `exec` the same methods anew at import); `__slots__ = ()` keeps
    # its instances' layout that of its base.
    __slots__ = ()

    def holds_for(self, world: "World", ent: "Entity") -> bool:
        return self.rule(ent.speed, self.value)


@dataclass(frozen=True, slots=True)
class RelativeSpeedCondition(EntityCheck):
    ref: str
    value: float
    rule: Rule

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "RelativeSpeedCondition":
        return cls(ctx.req(el, "entityRef"), ctx.float(el, "value"), Rule.from_xml(ctx, el))

    def holds_for(self, world: "World", ent: "Entity") -> bool:
        return self.rule(ent.speed - world.entity(self.ref).speed, self.value)


class AccelerationCondition(_ValueCheck):
    __slots__ = ()   # the base's dataclass methods serve it (see SpeedCondition)

    def holds_for(self, world: "World", ent: "Entity") -> bool:
        return self.rule(ent.accel, self.value)


@dataclass(frozen=True, slots=True)
class _DurationCheck(EntityCheck):
    """A state that must have lasted `duration` seconds (StandStill, EndOfRoad, Offroad): one parser for all."""

    duration: float

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "_DurationCheck":
        return cls(ctx.float(el, "duration"))


class StandStillCondition(_DurationCheck):
    __slots__ = ()   # the base's dataclass methods serve it (see SpeedCondition)

    def holds_for(self, world: "World", ent: "Entity") -> bool:
        return ent.standstill_time >= self.duration - 1e-9 and abs(ent.speed) < 1e-3


class EndOfRoadCondition(_DurationCheck):
    __slots__ = ()   # the base's dataclass methods serve it (see SpeedCondition)

    def holds_for(self, world: "World", ent: "Entity") -> bool:
        return ent.end_of_road_time is not None and ent.end_of_road_time >= self.duration - 1e-9


class OffroadCondition(_DurationCheck):
    __slots__ = ()   # the base's dataclass methods serve it (see SpeedCondition)

    def holds_for(self, world: "World", ent: "Entity") -> bool:
        return ent.offroad_time is not None and ent.offroad_time >= self.duration - 1e-9


@dataclass(frozen=True, slots=True)
class TraveledDistanceCondition(EntityCheck):
    value: float

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "TraveledDistanceCondition":
        return cls(ctx.float(el, "value"))

    def holds_for(self, world: "World", ent: "Entity") -> bool:
        return ent.odometer >= self.value - 1e-9


@dataclass(frozen=True, slots=True)
class CollisionCondition(EntityCheck):
    ref: str | None
    by_type: str | None

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "CollisionCondition":
        ref = el.find("EntityRef")
        by_type = el.find("ByType")
        return cls(None if ref is None else ctx.req(ref, "entityRef"),
                   None if by_type is None else ctx.req(by_type, "type"))

    def holds_for(self, world: "World", ent: "Entity") -> bool:
        if self.ref is not None:
            return self.ref in ent.colliding
        if self.by_type is not None:
            return any(world.entity(o).spec.kind == {"vehicle": "vehicle", "pedestrian": "pedestrian"}.get(
                self.by_type, "misc") for o in ent.colliding)
        return bool(ent.colliding)


@dataclass(frozen=True, slots=True)
class ReachPositionCondition(EntityCheck):
    position: Position
    tolerance: float

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "ReachPositionCondition":
        return cls(position_from_xml(ctx, ctx.child(el, "Position")), ctx.float(el, "tolerance"))

    def holds_for(self, world: "World", ent: "Entity") -> bool:
        pose = world.resolve_cached(self.position)
        return math.hypot(ent.x - pose.x, ent.y - pose.y) <= self.tolerance


@dataclass(frozen=True, slots=True)
class DistanceCondition(EntityCheck):
    position: Position
    value: float
    freespace: bool
    rule: Rule
    rdt: str
    cs: str

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "DistanceCondition":
        rdt, cs = _distance_kind(el)
        return cls(position_from_xml(ctx, ctx.child(el, "Position")), ctx.float(el, "value"),
                   ctx.bool(el, "freespace"), Rule.from_xml(ctx, el), rdt, cs)

    def holds_for(self, world: "World", ent: "Entity") -> bool:
        pose = world.resolve_cached(self.position)
        d = world.measure.to_point(ent, pose, self.rdt, self.cs, self.freespace)
        return self.rule(abs(d), self.value)


@dataclass(frozen=True, slots=True)
class RelativeDistanceCondition(EntityCheck):
    ref: str
    value: float
    freespace: bool
    rule: Rule
    rdt: str
    cs: str

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "RelativeDistanceCondition":
        rdt, cs = _distance_kind(el)
        return cls(ctx.req(el, "entityRef"), ctx.float(el, "value"), ctx.bool(el, "freespace"),
                   Rule.from_xml(ctx, el), rdt, cs)

    def holds_for(self, world: "World", ent: "Entity") -> bool:
        d = world.measure.between(ent, world.entity(self.ref), self.rdt, self.cs, self.freespace)
        return self.rule(abs(d), self.value)


@dataclass(frozen=True, slots=True)
class TimeHeadwayCondition(EntityCheck):
    """Headway of the triggering entity to `ref` ahead of it: distance / own speed. The distance is the one the
    condition names: in 1.0 (`alongRoute`) the cartesian distance unless along the route (1.0: "if false, the
    cartesian distance is used"; esmini too), in 1.1+ its `relativeDistanceType`; a cartesian distance carries
    the sign of the longitudinal one (negative: `ref` behind), as esmini's does."""

    ref: str
    value: float
    freespace: bool
    rule: Rule
    cs: str
    rdt: str = "longitudinal"

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "TimeHeadwayCondition":
        rdt, cs = _distance_kind(el)
        if cs in ("road", "lane") and rdt == "euclidianDistance":
            rdt = "longitudinal"          # along the route: the distance along it
        return cls(ctx.req(el, "entityRef"), ctx.float(el, "value"), ctx.bool(el, "freespace"),
                   Rule.from_xml(ctx, el), cs, rdt)

    def holds_for(self, world: "World", ent: "Entity") -> bool:
        ref = world.entity(self.ref)
        d = world.measure.between(ent, ref, self.rdt, self.cs, self.freespace)
        if self.rdt == "euclidianDistance" and world.measure.between(ent, ref, "longitudinal", "entity",
                                                                      self.freespace) < 0:
            d = -d
        # Signed: a reference behind the triggering entity gives a negative headway (so 'greaterThan' waits
        # until it has pulled ahead, as in cut-in scenarios); standing still, the headway is ±infinite.
        if ent.speed <= 1e-6:
            hwt = LARGE if d > 0 else -LARGE
        else:
            hwt = d / ent.speed
        return self.rule(hwt, self.value)


@dataclass(frozen=True, slots=True)
class TimeToCollisionCondition(EntityCheck):
    ref: str | None
    position: Position | None
    value: float
    freespace: bool
    rule: Rule
    rdt: str
    cs: str

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "TimeToCollisionCondition":
        rdt, cs = _distance_kind(el)
        if el.get("relativeDistanceType") is None:
            rdt = "longitudinal"
        target = ctx.only_child(ctx.child(el, "TimeToCollisionConditionTarget"))
        ref = ctx.req(target, "entityRef") if target.tag == "EntityRef" else None
        pos = position_from_xml(ctx, target) if target.tag == "Position" else None
        return cls(ref, pos, ctx.float(el, "value"), ctx.bool(el, "freespace"), Rule.from_xml(ctx, el), rdt, cs)

    def holds_for(self, world: "World", ent: "Entity") -> bool:
        if self.ref is not None:
            other = world.entity(self.ref)
            d = world.measure.between(ent, other, self.rdt, self.cs, self.freespace)
            closing = world.measure.closing_speed(ent, other)
        else:
            pose = world.resolve_cached(self.position)
            d = world.measure.to_point(ent, pose, self.rdt, self.cs, self.freespace)
            closing = ent.speed
        if self.rdt != "euclidianDistance" and d < 0.0:
            ttc = LARGE          # the target is behind
        elif closing <= 1e-6:
            ttc = LARGE
        else:
            ttc = abs(d) / closing
        return self.rule(ttc, self.value)


BY_ENTITY = {
    "SpeedCondition": SpeedCondition.from_xml,
    "RelativeSpeedCondition": RelativeSpeedCondition.from_xml,
    "AccelerationCondition": AccelerationCondition.from_xml,
    "StandStillCondition": StandStillCondition.from_xml,
    "EndOfRoadCondition": EndOfRoadCondition.from_xml,
    "OffroadCondition": OffroadCondition.from_xml,
    "TraveledDistanceCondition": TraveledDistanceCondition.from_xml,
    "CollisionCondition": CollisionCondition.from_xml,
    "ReachPositionCondition": ReachPositionCondition.from_xml,
    "DistanceCondition": DistanceCondition.from_xml,
    "RelativeDistanceCondition": RelativeDistanceCondition.from_xml,
    "TimeHeadwayCondition": TimeHeadwayCondition.from_xml,
    "TimeToCollisionCondition": TimeToCollisionCondition.from_xml,
}
