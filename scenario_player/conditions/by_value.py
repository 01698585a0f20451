"""ByValueConditions: SimulationTime, StoryboardElementState, Parameter, TrafficSignal."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from lxml import etree

from ..storyboard.element import State, Transition
from ..syntax.xml import ParseContext
from .base import Check, Rule

if TYPE_CHECKING:
    from ..world.world import World

_STATES = ("startTransition", "endTransition", "stopTransition", "skipTransition", "completeState",
           "runningState", "standbyState")
#: The member each state name asks about (an element's state and last transition are always members, so `is`
#: answers what comparing `.value` with the name's stem did, without the Enum property read every step).
_WANTED: dict[str, State | Transition] = {
    name: (State(name[: -len("State")]) if name.endswith("State") else Transition(name[: -len("Transition")]))
    for name in _STATES}


@dataclass(frozen=True, slots=True)
class SimulationTimeCondition(Check):
    value: float
    rule: Rule

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "SimulationTimeCondition":
        return cls(ctx.float(el, "value"), Rule.from_xml(ctx, el))

    def holds(self, world: "World") -> bool:
        return self.rule(world.t, self.value)


@dataclass(frozen=True, slots=True)
class StoryboardElementStateCondition(Check):
    element_type: str
    ref: str
    state: str
    line: int | None
    where: str = ""

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "StoryboardElementStateCondition":
        state = ctx.req(el, "state")
        if state not in _STATES:
            raise ctx.error(el, f"unknown storyboard element state '{state}'")
        return cls(ctx.req(el, "storyboardElementType"), ctx.req(el, "storyboardElementRef"), state, el.sourceline,
                   ctx.where(el))

    def holds(self, world: "World") -> bool:
        element = world.storyboard_element(self.element_type, self.ref)
        want = _WANTED[self.state]
        if type(want) is State:
            return element.state is want
        # A transition is momentary: visible in the step it happened and the next one, so a condition evaluated
        # earlier in the step than the element still sees it exactly once per evaluation order.
        return element.last_transition is want and world.step_index - element.transition_step <= 1


@dataclass(frozen=True, slots=True)
class ParameterCondition(Check):
    ref: str
    value: str
    rule: Rule

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "ParameterCondition":
        return cls(ctx.req(el, "parameterRef"), ctx.req(el, "value"), Rule.from_xml(ctx, el))

    def holds(self, world: "World") -> bool:
        current = world.parameter(self.ref)
        try:
            return self.rule(float(current), float(self.value))
        except ValueError:
            return self.rule.text(current, self.value)


@dataclass(frozen=True, slots=True)
class TrafficSignalCondition(Check):
    name: str
    state: str

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "TrafficSignalCondition":
        return cls(ctx.req(el, "name"), ctx.req(el, "state"))

    def holds(self, world: "World") -> bool:
        return world.signals.state_text(self.name) == self.state


@dataclass(frozen=True, slots=True)
class TrafficSignalControllerCondition(Check):
    controller: str
    phase: str

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "TrafficSignalControllerCondition":
        return cls(ctx.req(el, "trafficSignalControllerRef"), ctx.req(el, "phase"))

    def holds(self, world: "World") -> bool:
        return world.signals.controller_phase(self.controller) == self.phase


BY_VALUE = {
    "SimulationTimeCondition": SimulationTimeCondition.from_xml,
    "StoryboardElementStateCondition": StoryboardElementStateCondition.from_xml,
    "ParameterCondition": ParameterCondition.from_xml,
    "TrafficSignalCondition": TrafficSignalCondition.from_xml,
    "TrafficSignalControllerCondition": TrafficSignalControllerCondition.from_xml,
}
