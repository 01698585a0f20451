"""Entities: ScenarioObject -> EntitySpec (kind, category, bounding box, performance, axles, controller; the record
itself lives with the world, `world/spec.py`)."""

from __future__ import annotations

import math

from lxml import etree

from ..world.spec import EntitySpec
from .xml import ParseContext

#: Defaults when a file leaves Performance/Axles out (a mid-size car; pedestrians walk).
_DEFAULT_PERF = {"vehicle": (70.0, 10.0, 10.0), "pedestrian": (10.0, 5.0, 5.0), "misc": (0.0, 0.0, 0.0)}

#: OpenSCENARIO vehicleCategory -> contract category (txt2sce_ros.contract.PARTY_CATEGORIES).
_VEHICLE_CATEGORY = {"car": "car", "van": "van", "truck": "truck", "trailer": "truck", "semitrailer": "truck",
                     "bus": "bus", "motorbike": "motorcycle", "bicycle": "bicycle", "train": "truck",
                     "tram": "bus"}


def entity_spec_from_xml(ctx: ParseContext, obj: etree._Element) -> EntitySpec:
    """ScenarioObject -> EntitySpec (defaults where Performance, Axles or the bounding box are left out)."""
    name = ctx.req(obj, "name")
    body = next((c for c in obj if c.tag in ("Vehicle", "Pedestrian", "MiscObject")), None)
    if body is None:
        other = next((c for c in obj if isinstance(c.tag, str)), obj)
        ctx.note_unsupported(other, f"{other.tag} (entity {name})")
        body = obj
    kind = {"Vehicle": "vehicle", "Pedestrian": "pedestrian", "MiscObject": "misc"}.get(str(body.tag), "misc")
    props = {p.get("name", ""): p.get("value", "") for p in body.iter("Property")}
    if kind == "vehicle":
        category = _VEHICLE_CATEGORY.get(body.get("vehicleCategory", "car"), "car")
    elif kind == "pedestrian":
        category = "pedestrian" if body.get("pedestrianCategory", "pedestrian") != "animal" else "animal"
    else:
        category = "other"
    category = props.get("txt2sce:category", category)
    bb = body.find("BoundingBox")
    if bb is not None:
        dim, cen = ctx.child(bb, "Dimensions"), bb.find("Center")
        length, width, height = ctx.float(dim, "length"), ctx.float(dim, "width"), ctx.float(dim, "height")
        cx = ctx.float(cen, "x", 0.0) if cen is not None else 0.0
        cy = ctx.float(cen, "y", 0.0) if cen is not None else 0.0
    else:
        length, width, height, cx, cy = (4.5, 1.8, 1.5, 1.4, 0.0) if kind == "vehicle" else (0.6, 0.6, 1.8, 0, 0)
    vmax, amax, dmax = _DEFAULT_PERF[kind]
    perf = body.find("Performance")
    if perf is not None:
        vmax = ctx.float(perf, "maxSpeed", vmax)
        amax = ctx.float(perf, "maxAcceleration", amax)
        dmax = ctx.float(perf, "maxDeceleration", dmax)
    wheelbase, max_steer = max(0.6 * length, 0.5), math.radians(30.0)
    axles = body.find("Axles")
    if axles is not None:
        front, rear = axles.find("FrontAxle"), axles.find("RearAxle")
        if front is not None and rear is not None:
            wheelbase = max(ctx.float(front, "positionX", 0.0) - ctx.float(rear, "positionX", 0.0), 0.1)
            max_steer = ctx.float(front, "maxSteering", max_steer)
    external = any(p.get("name") == "txt2sce:controller" and p.get("value") == "external"
                   for p in obj.iter("Property"))
    return EntitySpec(name=name, kind=kind, category=category, length=length, width=width, height=height,
                      center_x=cx, center_y=cy, max_speed=vmax, max_accel=amax, max_decel=dmax,
                      wheelbase=wheelbase, max_steering=max_steer, external=external, properties=props,
                      line=obj.sourceline)
