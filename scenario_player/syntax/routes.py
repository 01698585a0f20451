"""Route (waypoints + route strategy) and Trajectory shapes as typed records."""

from __future__ import annotations

from dataclasses import dataclass

from lxml import etree

from .xml import ParseContext


@dataclass(frozen=True, slots=True)
class Waypoint:
    position: object          # a syntax.positions Position
    strategy: str             # fastest | shortest | leastIntersections | random


@dataclass(frozen=True, slots=True)
class Route:
    name: str
    closed: bool
    waypoints: tuple[Waypoint, ...]

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "Route":
        from .positions import position_from_xml

        wps = tuple(Waypoint(position_from_xml(ctx, ctx.child(w, "Position")), w.get("routeStrategy", "shortest"))
                    for w in el.findall("Waypoint"))
        if len(wps) < 2:
            raise ctx.error(el, "a Route needs at least two Waypoints")
        return cls(el.get("name", ""), ctx.bool(el, "closed", False), wps)


@dataclass(frozen=True, slots=True)
class Vertex:
    time: float | None
    position: object


@dataclass(frozen=True, slots=True)
class Polyline:
    vertices: tuple[Vertex, ...]


@dataclass(frozen=True, slots=True)
class Clothoid:
    curvature: float
    curvature_dot: float
    length: float
    start_time: float | None
    stop_time: float | None
    position: object | None


@dataclass(frozen=True, slots=True)
class ControlPoint:
    time: float | None
    weight: float
    position: object


@dataclass(frozen=True, slots=True)
class Nurbs:
    order: int
    points: tuple[ControlPoint, ...]
    knots: tuple[float, ...]


@dataclass(frozen=True, slots=True)
class Trajectory:
    name: str
    closed: bool
    shape: Polyline | Clothoid | Nurbs

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "Trajectory":
        from .positions import position_from_xml

        shape_el = ctx.only_child(ctx.child(el, "Shape"))
        opt = lambda e, n: None if e.get(n) is None else ctx.float(e, n)  # noqa: E731
        if shape_el.tag == "Polyline":
            shape: Polyline | Clothoid | Nurbs = Polyline(tuple(
                Vertex(opt(v, "time"), position_from_xml(ctx, ctx.child(v, "Position")))
                for v in shape_el.findall("Vertex")))
        elif shape_el.tag == "Clothoid":
            pos = shape_el.find("Position")
            curv_dot = shape_el.get("curvaturePrime", shape_el.get("curvatureDot", "0"))
            shape = Clothoid(ctx.float(shape_el, "curvature"), float(curv_dot), ctx.float(shape_el, "length"),
                             opt(shape_el, "startTime"), opt(shape_el, "stopTime"),
                             None if pos is None else position_from_xml(ctx, pos))
        elif shape_el.tag == "Nurbs":
            shape = Nurbs(ctx.int(shape_el, "order"),
                          tuple(ControlPoint(opt(c, "time"), ctx.float(c, "weight", 1.0),
                                             position_from_xml(ctx, ctx.child(c, "Position")))
                                for c in shape_el.findall("ControlPoint")),
                          tuple(ctx.float(k, "value") for k in shape_el.findall("Knot")))
        else:
            raise ctx.error(shape_el, f"unknown trajectory shape <{shape_el.tag}>")
        return cls(el.get("name", ""), ctx.bool(el, "closed", False), shape)


__all__ = ["Route", "Waypoint", "Trajectory", "Polyline", "Clothoid", "Nurbs", "Vertex", "ControlPoint"]
