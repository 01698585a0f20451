"""RoutingAction family: AssignRouteAction, AcquirePositionAction (FollowTrajectoryAction: trajectory.py).

A route becomes the set of lanes the entity prefers when its lane ends in a junction: the lane-level shortest
path through the route's waypoints on the road model's routing graph.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

from lxml import etree

from txt2sce_ros.errors import InputError

from ..syntax.positions import Position, position_from_xml
from ..syntax.routes import Route
from ..syntax.xml import ParseContext
from .base import ActionRun

if TYPE_CHECKING:
    from ..world.entity import Entity
    from ..world.world import World


@dataclass(frozen=True, slots=True)
class AssignRouteAction:
    route: Route
    is_private = True

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "AssignRouteAction":
        route_el = el.find("Route")
        if route_el is None:
            raise ctx.error(el, "AssignRouteAction holds no Route (or its CatalogReference did not resolve)")
        return cls(Route.from_xml(ctx, route_el))

    def start(self, world: "World", ent: "Entity | None") -> ActionRun | None:
        assert ent is not None
        _, refs = world.route_path(self.route)
        ent.route_lanes = set(refs)
        return None


@dataclass(frozen=True, slots=True)
class AcquirePositionAction:
    position: Position
    is_private = True

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "AcquirePositionAction":
        return cls(position_from_xml(ctx, ctx.child(el, "Position")))

    def start(self, world: "World", ent: "Entity | None") -> ActionRun | None:
        assert ent is not None
        pose = self.position.resolve(world)
        if ent.track is None or pose.road_id is None:
            raise InputError(f"AcquirePositionAction for '{ent.name}': start or target is not on a lane",
                             source=world.source, element="AcquirePositionAction")
        start = ent.track.ref
        goal = world.net.lane_ref(pose.road_id, pose.lane_id, pose.s)
        ent.route_lanes = set(world.net.route(start, goal))
        return AcquireRun(ent, pose.x, pose.y)


class AcquireRun(ActionRun):
    """Ends when the entity reaches the target (within 1 m) or passes it."""

    domains = frozenset()

    def __init__(self, ent: "Entity", x: float, y: float) -> None:
        super().__init__(ent)
        self.x, self.y = x, y
        self.best = math.inf

    def step(self, world: "World", dt: float) -> None:
        d = math.hypot(self.entity.x - self.x, self.entity.y - self.y)
        if d < 1.0 or (d > self.best + 0.5 and self.best < 5.0):
            self.done = True
        self.best = min(self.best, d)
