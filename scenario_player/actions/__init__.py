"""Actions by family; `action_from_xml` / `private_action_from_xml` dispatch on the XSD element names.

Anything not in the tables is reported at load as "unsupported: <element> at line N" and becomes an
`UnsupportedAction` that does nothing when started (the run lists it; it is never silently skipped).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Callable

from lxml import etree

from ..syntax.xml import ParseContext
from .base import ActionRun, ActionSpec
from .global_ import (EnvironmentAction, ParameterModifyAction, ParameterSetAction, TrafficSignalControllerAction,
                      TrafficSignalStateAction)
from .lateral import LaneChangeAction, LaneOffsetAction, LateralDistanceAction
from .longitudinal import LongitudinalDistanceAction, SpeedAction, SpeedProfileAction
from .routing import AcquirePositionAction, AssignRouteAction
from .synchronize import SynchronizeAction
from .teleport import TeleportAction
from .trajectory import FollowTrajectoryAction

if TYPE_CHECKING:
    from ..world.entity import Entity
    from ..world.world import World

Parser = Callable[[ParseContext, etree._Element], ActionSpec]


@dataclass(frozen=True, slots=True)
class UnsupportedAction:
    note: str
    is_private: bool = True

    def start(self, world: "World", ent: "Entity | None") -> ActionRun | None:
        world.note(self.note)
        return None


# Wrapper elements whose single child is the action proper.
_WRAPPERS = {"LongitudinalAction", "LateralAction", "RoutingAction", "InfrastructureAction", "TrafficSignalAction"}

PRIVATE: dict[str, Parser] = {
    "SpeedAction": SpeedAction.from_xml,
    "SpeedProfileAction": SpeedProfileAction.from_xml,
    "LongitudinalDistanceAction": LongitudinalDistanceAction.from_xml,
    "LaneChangeAction": LaneChangeAction.from_xml,
    "LaneOffsetAction": LaneOffsetAction.from_xml,
    "LateralDistanceAction": LateralDistanceAction.from_xml,
    "TeleportAction": TeleportAction.from_xml,
    "AssignRouteAction": AssignRouteAction.from_xml,
    "AcquirePositionAction": AcquirePositionAction.from_xml,
    "FollowTrajectoryAction": FollowTrajectoryAction.from_xml,
    "SynchronizeAction": SynchronizeAction.from_xml,
}

GLOBAL: dict[str, Parser] = {
    "EnvironmentAction": EnvironmentAction.from_xml,
    "TrafficSignalStateAction": TrafficSignalStateAction.from_xml,
    "TrafficSignalControllerAction": TrafficSignalControllerAction.from_xml,
}


def _unwrap(ctx: ParseContext, el: etree._Element) -> etree._Element:
    while el.tag in _WRAPPERS:
        el = ctx.only_child(el)
    return el


def private_action_from_xml(ctx: ParseContext, el: etree._Element) -> ActionSpec:
    """Parse a <PrivateAction>."""
    inner = _unwrap(ctx, ctx.only_child(el))
    parser = PRIVATE.get(str(inner.tag))
    if parser is None:
        return UnsupportedAction(ctx.note_unsupported(inner), True)
    return parser(ctx, inner)


def global_action_from_xml(ctx: ParseContext, el: etree._Element) -> ActionSpec:
    """Parse a <GlobalAction>."""
    inner = _unwrap(ctx, ctx.only_child(el))
    if inner.tag == "ParameterAction":          # OpenSCENARIO 1.0/1.1 form
        ref = ctx.req(inner, "parameterRef")
        choice = ctx.only_child(inner)
        if choice.tag == "SetAction":
            return ParameterSetAction.from_xml(ctx, choice, ref)
        if choice.tag == "ModifyAction":
            return ParameterModifyAction.from_xml(ctx, choice, ref)
    parser = GLOBAL.get(str(inner.tag))
    if parser is None:
        return UnsupportedAction(ctx.note_unsupported(inner), False)
    return parser(ctx, inner)


def action_from_xml(ctx: ParseContext, el: etree._Element) -> ActionSpec:
    """Parse a storyboard <Action> (Global, Private or UserDefined)."""
    body = ctx.only_child(el)
    if body.tag == "PrivateAction":
        return private_action_from_xml(ctx, body)
    if body.tag == "GlobalAction":
        return global_action_from_xml(ctx, body)
    return UnsupportedAction(ctx.note_unsupported(body), False)


__all__ = ["ActionSpec", "ActionRun", "action_from_xml", "private_action_from_xml", "global_action_from_xml",
           "UnsupportedAction"]
