"""Condition machinery: the base class owns edge detection, delay and history; subclasses only say whether their
check holds now (`holds(world)`). Triggers are an OR of ConditionGroups, each an AND of Conditions.

Edge semantics follow the standard: 'rising' is true in the evaluation where the check goes false -> true,
'falling' the reverse, 'risingOrFalling' either, 'none' the plain value. The first evaluation has no previous
value, so it is never an edge (esmini does the same: a condition already true when first checked does not "rise"). A delay shifts the (edge-processed) result by `delay` seconds of simulation time.
"""

from __future__ import annotations

import operator
from collections import deque
from dataclasses import dataclass
from typing import TYPE_CHECKING, Callable

from lxml import etree

from ..syntax.xml import ParseContext

if TYPE_CHECKING:
    from ..world.world import World

EPS = 1e-9

_RULES: dict[str, Callable[[float, float], bool]] = {
    "greaterThan": lambda a, b: a > b + EPS,
    "lessThan": lambda a, b: a < b - EPS,
    "equalTo": lambda a, b: abs(a - b) <= 1e-6,
    "greaterOrEqual": lambda a, b: a >= b - EPS,
    "lessOrEqual": lambda a, b: a <= b + EPS,
    "notEqualTo": lambda a, b: abs(a - b) > 1e-6,
}


@dataclass(frozen=True, slots=True)
class Rule:
    name: str

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element, attr: str = "rule") -> "Rule":
        name = ctx.req(el, attr)
        if name not in _RULES:
            raise ctx.error(el, f"unknown rule '{name}'")
        return cls(name)

    def __call__(self, a: float, b: float) -> bool:
        return _RULES[self.name](a, b)

    def text(self, a: str, b: str) -> bool:
        if self.name == "equalTo":
            return a == b
        if self.name == "notEqualTo":
            return a != b
        ops = {"greaterThan": operator.gt, "lessThan": operator.lt, "greaterOrEqual": operator.ge,
               "lessOrEqual": operator.le}
        return ops[self.name](a, b)


class Check:
    """What a concrete condition implements: whether it holds now. Stateless unless it needs history."""

    def holds(self, world: "World") -> bool:
        raise NotImplementedError


class Condition:
    """One <Condition>: a named check with edge and delay."""

    __slots__ = ("name", "edge", "delay", "check", "line", "_prev", "_pending", "_history", "last_value")

    def __init__(self, name: str, edge: str, delay: float, check: Check, line: int | None) -> None:
        self.name, self.edge, self.delay, self.check, self.line = name, edge, delay, check, line
        self.reset()

    def reset(self) -> None:
        self._prev: bool | None = None
        self._pending: deque[float] = deque()     # times at which a delayed edge fires
        self._history: deque[tuple[float, bool]] = deque()
        self.last_value = False

    def evaluate(self, world: "World") -> bool:
        raw = bool(self.check.holds(world))
        if self.edge != "none" and self._prev is None:
            value = False
        elif self.edge == "rising":
            value = raw and not self._prev
        elif self.edge == "falling":
            value = self._prev and not raw
        elif self.edge == "risingOrFalling":
            value = raw != self._prev
        else:
            value = raw
        self._prev = raw
        if self.delay > 0.0:
            value = self._delayed(world.t, value)
        self.last_value = value
        return value

    def _delayed(self, t: float, value: bool) -> bool:
        if self.edge == "none":
            # A level: report the value it had `delay` seconds ago.
            self._history.append((t, value))
            cutoff = t - self.delay + EPS
            while len(self._history) >= 2 and self._history[1][0] <= cutoff:
                self._history.popleft()
            return self._history[0][1] if self._history[0][0] <= cutoff else False
        # An edge is an impulse: fire it once, `delay` later.
        if value:
            self._pending.append(t + self.delay)
        if self._pending and self._pending[0] <= t + EPS:
            self._pending.popleft()
            return True
        return False


class ConditionGroup:
    __slots__ = ("conditions",)

    def __init__(self, conditions: list[Condition]) -> None:
        self.conditions = conditions

    def evaluate(self, world: "World") -> bool:
        # Evaluate every condition (no short-circuit): edges need each one's history every step.
        result = True
        for cond in self.conditions:
            if not cond.evaluate(world):
                result = False
        return result


class Trigger:
    """StartTrigger/StopTrigger: OR of groups. An empty trigger never fires (a missing one is handled by callers)."""

    __slots__ = ("groups", "_only")

    def __init__(self, groups: list[ConditionGroup]) -> None:
        self.groups = groups
        # One group of one condition (most triggers): evaluating it is evaluating that condition (its value is
        # a bool), without the two loops; triggers are evaluated every step.
        self._only = groups[0].conditions[0] if len(groups) == 1 and len(groups[0].conditions) == 1 else None

    def evaluate(self, world: "World") -> bool:
        only = self._only
        if only is not None:
            return only.evaluate(world)
        result = False
        for group in self.groups:
            if group.evaluate(world):
                result = True
        return result

    def reset(self) -> None:
        for g in self.groups:
            for c in g.conditions:
                c.reset()
