"""GlobalAction family: EnvironmentAction (friction), InfrastructureAction/TrafficSignalAction (signal states and
controller phases), ParameterAction (set / modify)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from lxml import etree

from ..syntax.xml import ParseContext
from .base import ActionRun

if TYPE_CHECKING:
    from ..world.entity import Entity
    from ..world.world import World


@dataclass(frozen=True, slots=True)
class EnvironmentAction:
    """Only the road friction acts on a 2D kinematic world; weather, fog and time of day are recorded as given."""

    friction: float | None
    is_private = False

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "EnvironmentAction":
        env = el.find("Environment")
        if env is None:
            raise ctx.error(el, "EnvironmentAction holds no Environment (or its CatalogReference did not resolve)")
        rc = env.find("RoadCondition")
        return cls(None if rc is None else ctx.float(rc, "frictionScaleFactor", 1.0))

    def start(self, world: "World", ent: "Entity | None") -> ActionRun | None:
        if self.friction is not None:
            world.friction = max(self.friction, 0.0)
        return None


@dataclass(frozen=True, slots=True)
class TrafficSignalStateAction:
    name: str
    state: str
    is_private = False

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "TrafficSignalStateAction":
        return cls(ctx.req(el, "name"), ctx.req(el, "state"))

    def start(self, world: "World", ent: "Entity | None") -> ActionRun | None:
        world.signals.set_state(self.name, self.state)
        return None


@dataclass(frozen=True, slots=True)
class TrafficSignalControllerAction:
    controller: str
    phase: str
    is_private = False

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "TrafficSignalControllerAction":
        return cls(ctx.req(el, "trafficSignalControllerRef"), ctx.req(el, "phase"))

    def start(self, world: "World", ent: "Entity | None") -> ActionRun | None:
        world.signals.set_phase(self.controller, self.phase, world.t)
        return None


@dataclass(frozen=True, slots=True)
class ParameterSetAction:
    ref: str
    value: str
    is_private = False

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element, ref: str) -> "ParameterSetAction":
        return cls(ref, ctx.req(el, "value"))

    def start(self, world: "World", ent: "Entity | None") -> ActionRun | None:
        world.parameters[self.ref] = self.value
        return None


@dataclass(frozen=True, slots=True)
class ParameterModifyAction:
    ref: str
    add: float | None
    multiply: float | None
    is_private = False

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element, ref: str) -> "ParameterModifyAction":
        rule = ctx.only_child(ctx.child(el, "Rule"))
        if rule.tag == "AddValue":
            return cls(ref, ctx.float(rule, "value"), None)
        return cls(ref, None, ctx.float(rule, "value"))

    def start(self, world: "World", ent: "Entity | None") -> ActionRun | None:
        cur = float(world.parameter(self.ref))
        cur = cur + self.add if self.add is not None else cur * (self.multiply or 1.0)
        world.parameters[self.ref] = repr(cur)
        return None
