"""Actions by family; `action_from_xml` / `private_action_from_xml` dispatch on the XSD element names.

Anything not in the tables is reported at load as "unsupported: <element> at line N" and becomes an
`UnsupportedAction` that does nothing when started (the run lists it; it is never silently skipped).
"""

from __future__ import annotations

import importlib
from dataclasses import dataclass
from typing import TYPE_CHECKING, Callable

from lxml import etree

from ..syntax.xml import ParseContext
from .base import ActionRun, ActionSpec

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

# Element name -> (module of this package, class). A family's module is imported when a scenario first uses one of
# its actions, so a cold `txt2sce play` pays (class creation, imports) only for the families its file has.
PRIVATE: dict[str, tuple[str, str]] = {
    "SpeedAction": ("longitudinal", "SpeedAction"),
    "SpeedProfileAction": ("longitudinal", "SpeedProfileAction"),
    "LongitudinalDistanceAction": ("longitudinal", "LongitudinalDistanceAction"),
    "LaneChangeAction": ("lateral", "LaneChangeAction"),
    "LaneOffsetAction": ("lateral", "LaneOffsetAction"),
    "LateralDistanceAction": ("lateral", "LateralDistanceAction"),
    "TeleportAction": ("teleport", "TeleportAction"),
    "AssignRouteAction": ("routing", "AssignRouteAction"),
    "AcquirePositionAction": ("routing", "AcquirePositionAction"),
    "FollowTrajectoryAction": ("trajectory", "FollowTrajectoryAction"),
    "SynchronizeAction": ("synchronize", "SynchronizeAction"),
}

GLOBAL: dict[str, tuple[str, str]] = {
    "EnvironmentAction": ("global_", "EnvironmentAction"),
    "TrafficSignalStateAction": ("global_", "TrafficSignalStateAction"),
    "TrafficSignalControllerAction": ("global_", "TrafficSignalControllerAction"),
}


def _action_class(module: str, name: str) -> type:
    return getattr(importlib.import_module(f".{module}", __package__), name)


def _parser(table: dict[str, tuple[str, str]], tag: str) -> Parser | None:
    where = table.get(tag)
    return None if where is None else _action_class(*where).from_xml


def _unwrap(ctx: ParseContext, el: etree._Element) -> etree._Element:
    while el.tag in _WRAPPERS:
        el = ctx.only_child(el)
    return el


def private_action_from_xml(ctx: ParseContext, el: etree._Element) -> ActionSpec:
    """Parse a <PrivateAction>."""
    inner = _unwrap(ctx, ctx.only_child(el))
    parser = _parser(PRIVATE, str(inner.tag))
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
            return _action_class("global_", "ParameterSetAction").from_xml(ctx, choice, ref)
        if choice.tag == "ModifyAction":
            return _action_class("global_", "ParameterModifyAction").from_xml(ctx, choice, ref)
    parser = _parser(GLOBAL, str(inner.tag))
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
