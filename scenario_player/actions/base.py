"""Action machinery. A parsed action (`ActionSpec`, a frozen record) `start`s on one actor and returns an
`ActionRun` that the world steps each step until `done`. Runs declare the control domains they take
(longitudinal, lateral); starting a run on a domain ends the run that held it (as esmini does), so a new
SpeedAction replaces a running one instead of fighting it.

Transition shapes (OpenSCENARIO TransitionDynamics): step, linear, cubic, sinusoidal over a time, distance or rate.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Protocol

from lxml import etree

from ..syntax.xml import ParseContext

if TYPE_CHECKING:
    from ..world.entity import Entity
    from ..world.world import World

LONGITUDINAL = "longitudinal"
LATERAL = "lateral"

#: Peak slope of each normalised shape f(τ) on [0, 1] (f' max): used to stretch a transition so that its peak
#: acceleration stays within the entity's Performance limits (esmini does the same).
SHAPE_PEAK = {"linear": 1.0, "cubic": 1.5, "sinusoidal": math.pi / 2, "step": 0.0}


def shape_value(shape: str, tau: float) -> float:
    """Normalised transition f(τ): 0 at τ=0, 1 at τ>=1."""
    if tau >= 1.0:
        return 1.0
    if tau <= 0.0:
        return 0.0
    if shape == "linear":
        return tau
    if shape == "cubic":
        return tau * tau * (3.0 - 2.0 * tau)
    if shape == "sinusoidal":
        return 0.5 * (1.0 - math.cos(math.pi * tau))
    return 1.0     # step


@dataclass(frozen=True, slots=True)
class TransitionDynamics:
    shape: str            # step | linear | cubic | sinusoidal
    dimension: str        # time | distance | rate
    value: float

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "TransitionDynamics":
        shape = ctx.req(el, "dynamicsShape")
        if shape not in SHAPE_PEAK:
            raise ctx.error(el, f"unknown dynamicsShape '{shape}'")
        dim = ctx.req(el, "dynamicsDimension")
        if dim not in ("time", "distance", "rate"):
            raise ctx.error(el, f"unknown dynamicsDimension '{dim}'")
        return cls(shape, dim, ctx.float(el, "value"))


class ActionRun:
    """A running action on one entity. Subclasses implement `step`; `domains` are the controls it holds."""

    domains: frozenset[str] = frozenset()
    moves_entity = False          # True: the run places the entity itself (default motion skips it)
    consumes_travel = False       # True: its sideways motion takes part of the step's travel (lane changes)
    travels_at_offset = True      # the entity advances at the radius of its offset path, not the lane centre's

    def __init__(self, entity: "Entity") -> None:
        self.entity = entity
        self.done = False

    def step(self, world: "World", dt: float) -> None:
        raise NotImplementedError

    def cancel(self) -> None:
        self.done = True


class ActionSpec(Protocol):
    """A parsed action. Private actions start per actor; global actions ignore `entity` (None)."""

    is_private: bool

    def start(self, world: "World", entity: "Entity | None") -> ActionRun | None: ...
