"""OpenSCENARIO Position choices as typed records; `resolve(world)` turns one into a world pose at run time
(relative positions depend on where their reference entity is then).

Supported: WorldPosition, RelativeWorldPosition, RelativeObjectPosition, RoadPosition, RelativeRoadPosition,
LanePosition, RelativeLanePosition, RoutePosition. Others (GeoPosition, TrajectoryPosition) are reported at load.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Callable, Protocol

from lxml import etree

from ..world.pose import Pose
from .xml import ParseContext, first

if TYPE_CHECKING:
    from ..world.world import World


@dataclass(frozen=True, slots=True)
class Orientation:
    type: str = "relative"   # 'relative' to the road / reference, or 'absolute'
    h: float = 0.0

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element | None, default_type: str = "relative") -> "Orientation | None":
        if el is None:
            return None
        return cls(type=el.get("type", default_type), h=ctx.float(el, "h", 0.0))

    def apply(self, base: float) -> float:
        return self.h if self.type == "absolute" else base + self.h


class Position(Protocol):
    def resolve(self, world: "World") -> Pose: ...


@dataclass(frozen=True, slots=True)
class WorldPosition:
    x: float
    y: float
    h: float | None

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "WorldPosition":
        h = el.get("h")
        return cls(ctx.float(el, "x"), ctx.float(el, "y"), None if h is None else ctx.float(el, "h"))

    def resolve(self, world: "World") -> Pose:
        return world.locate_pose(self.x, self.y, self.h)


@dataclass(frozen=True, slots=True)
class _EntityOffset:
    """An (dx, dy) offset from an entity with an optional orientation: the shared syntax of RelativeWorldPosition
    and RelativeObjectPosition (they differ only in the frame the offset is taken in)."""

    entity: str
    dx: float
    dy: float
    orientation: Orientation | None

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "_EntityOffset":
        return cls(ctx.req(el, "entityRef"), ctx.float(el, "dx"), ctx.float(el, "dy"),
                   Orientation.from_xml(ctx, first(el, "Orientation")))


class RelativeWorldPosition(_EntityOffset):
    # No fields of its own: the base's generated methods serve it as they are (`__eq__` compares the exact class),
    # so it is not a dataclass again (that would `exec` the same methods anew at import); `__slots__ = ()` keeps
    # its instances' layout that of its base.
    __slots__ = ()

    def resolve(self, world: "World") -> Pose:
        ref = world.entity(self.entity)
        h = self.orientation.apply(ref.h) if self.orientation else ref.h
        return world.locate_pose(ref.x + self.dx, ref.y + self.dy, h)


class RelativeObjectPosition(_EntityOffset):
    __slots__ = ()   # the base's dataclass methods serve it (see RelativeWorldPosition)

    def resolve(self, world: "World") -> Pose:
        ref = world.entity(self.entity)
        c, s = math.cos(ref.h), math.sin(ref.h)
        x = ref.x + c * self.dx - s * self.dy
        y = ref.y + s * self.dx + c * self.dy
        h = self.orientation.apply(ref.h) if self.orientation else ref.h
        return world.locate_pose(x, y, h)


@dataclass(frozen=True, slots=True)
class RoadPosition:
    road_id: str
    s: float
    t: float
    orientation: Orientation | None

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "RoadPosition":
        return cls(ctx.req(el, "roadId"), ctx.float(el, "s"), ctx.float(el, "t"),
                   Orientation.from_xml(ctx, first(el, "Orientation")))

    def resolve(self, world: "World") -> Pose:
        return world.road_pose(self.road_id, self.s, self.t, self.orientation)


@dataclass(frozen=True, slots=True)
class RelativeRoadPosition:
    entity: str
    ds: float
    dt: float
    orientation: Orientation | None

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "RelativeRoadPosition":
        return cls(ctx.req(el, "entityRef"), ctx.float(el, "ds"), ctx.float(el, "dt"),
                   Orientation.from_xml(ctx, first(el, "Orientation")))

    def resolve(self, world: "World") -> Pose:
        road_id, s, t = world.road_coordinates(self.entity)
        return world.road_pose(road_id, s + self.ds, t + self.dt, self.orientation)


@dataclass(frozen=True, slots=True)
class LanePosition:
    road_id: str
    lane_id: int
    s: float
    offset: float
    orientation: Orientation | None

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "LanePosition":
        return cls(ctx.req(el, "roadId"), ctx.int(el, "laneId"), ctx.float(el, "s"), ctx.float(el, "offset", 0.0),
                   Orientation.from_xml(ctx, first(el, "Orientation")))

    def resolve(self, world: "World") -> Pose:
        return world.lane_pose(self.road_id, self.lane_id, self.s, self.offset, self.orientation)


@dataclass(frozen=True, slots=True)
class RelativeLanePosition:
    entity: str
    d_lane: int
    ds: float
    offset: float
    orientation: Orientation | None

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "RelativeLanePosition":
        if el.get("dsLane") is not None and el.get("ds") is None:
            ds = ctx.float(el, "dsLane")
        else:
            ds = ctx.float(el, "ds", 0.0)
        return cls(ctx.req(el, "entityRef"), ctx.int(el, "dLane"), ds, ctx.float(el, "offset", 0.0),
                   Orientation.from_xml(ctx, first(el, "Orientation")))

    def resolve(self, world: "World") -> Pose:
        return world.relative_lane_pose(self.entity, self.d_lane, self.ds, self.offset, self.orientation)


@dataclass(frozen=True, slots=True)
class RoutePosition:
    route: "object"          # syntax.routes.Route
    path_s: float
    lane_id: int | None
    lane_offset: float
    from_entity: str | None

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "RoutePosition":
        from .routes import Route

        ref = ctx.child(el, "RouteRef")
        route_el = first(ref, "Route")
        if route_el is None:
            raise ctx.error(ref, "RouteRef holds no Route (or its CatalogReference did not resolve)")
        route = Route.from_xml(ctx, route_el)
        inr = ctx.only_child(ctx.child(el, "InRoutePosition"))
        if inr.tag == "FromLaneCoordinates":
            return cls(route, ctx.float(inr, "pathS"), ctx.int(inr, "laneId"), ctx.float(inr, "laneOffset", 0.0), None)
        if inr.tag == "FromRoadCoordinates":
            return cls(route, ctx.float(inr, "pathS"), None, ctx.float(inr, "t", 0.0), None)
        if inr.tag == "FromCurrentEntity":
            return cls(route, 0.0, None, 0.0, ctx.req(inr, "entityRef"))
        raise ctx.error(inr, f"unknown InRoutePosition choice <{inr.tag}>")

    def resolve(self, world: "World") -> Pose:
        return world.route_pose(self)


_POSITIONS: dict[str, Callable[[ParseContext, etree._Element], Position]] = {
    "WorldPosition": WorldPosition.from_xml,
    "RelativeWorldPosition": RelativeWorldPosition.from_xml,
    "RelativeObjectPosition": RelativeObjectPosition.from_xml,
    "RoadPosition": RoadPosition.from_xml,
    "RelativeRoadPosition": RelativeRoadPosition.from_xml,
    "LanePosition": LanePosition.from_xml,
    "RelativeLanePosition": RelativeLanePosition.from_xml,
    "RoutePosition": RoutePosition.from_xml,
}


class UnsupportedPosition:
    """Placeholder for a position choice we do not implement; resolving it raises (it was reported at load)."""

    def __init__(self, note: str) -> None:
        self.note = note

    def resolve(self, world: "World") -> Pose:
        from txt2sce_ros.errors import UnsupportedFeature

        raise UnsupportedFeature(self.note)


def position_from_xml(ctx: ParseContext, el: etree._Element) -> Position:
    """Parse a <Position> element (or directly one of its choices)."""
    # <Position> and the wrappers that hold a position choice directly (TargetPositionMaster, …).
    choice = el if el.tag in _POSITIONS else ctx.only_child(el)
    parser = _POSITIONS.get(str(choice.tag))
    if parser is None:
        return UnsupportedPosition(ctx.note_unsupported(choice))
    return parser(ctx, choice)
