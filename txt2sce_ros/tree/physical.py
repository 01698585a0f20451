"""Physical attribute mutation family (Table III): DM dimensions and NCM category.

NCM rebuilds the entity element for the new category: a car becoming a pedestrian turns its `Vehicle` into a
`Pedestrian` (with `model`, `mass`, `pedestrianCategory`, and no Performance/Axles, which the 1.0 schema does not
allow there), and dimensions and performance follow the category's defaults (then DM/VPM Gaussian noise).
"""

from __future__ import annotations

from typing import Any

import numpy as np
from lxml import etree

from .dynamics import vpm
from .values import Recorder, gaussian

ENTITY_TAGS = ("Vehicle", "Pedestrian", "MiscObject")
DIM_ATTRS = ("width", "length", "height")


def entity_element(obj: etree._Element) -> etree._Element | None:
    for tag in ENTITY_TAGS:
        el = obj.find(tag)
        if el is not None:
            return el
    return None


def dm(dims: etree._Element, mean: tuple[float, float, float], lo: tuple[float, float, float],
       hi: tuple[float, float, float], rng: np.random.Generator, cfg: dict[str, Any], rec: Recorder) -> None:
    """Dimension Mutation: width, length, height Gaussian around `mean` (sigma = share x mean), bounded to
    [lo, hi] per dimension (the category's plausible range)."""
    for attr, m, a, b in zip(DIM_ATTRS, mean, lo, hi):
        rec.set(dims, attr, gaussian(rng, m, cfg["sigma_share"] * m, a, b), digits=3)


def _sub(parent: etree._Element, tag: str, **attrs: str) -> etree._Element:
    el = etree.SubElement(parent, tag)
    for k, v in attrs.items():
        el.set(k, v)
    return el


def _copy_attrs(old: etree._Element | None, path: str, new: etree._Element) -> None:
    """Start from the old values so the recorded changes read old -> new."""
    src = old.find(path) if old is not None else None
    if src is not None:
        for k in new.attrib:
            if src.get(k) is not None:
                new.set(k, src.get(k))


def ncm(obj: etree._Element, category: str, rng: np.random.Generator, cfg: dict[str, Any], rec: Recorder) -> str:
    """NPC Category Mutation: replace the entity element of ScenarioObject `obj` by one of `category`, with
    dimensions (DM) and, for vehicles, performance (VPM) drawn around the category's defaults. Returns the
    original category."""
    cats = cfg["physical"]["categories"]
    spec = cats[category]
    old = entity_element(obj)
    name = obj.get("name", "")
    old_cat = ""
    props_src = None
    if old is not None:
        p = old.find("Properties/Property[@name='txt2sce:category']")
        old_cat = p.get("value", "") if p is not None else old.get("vehicleCategory", old.tag.lower())
        props_src = old.find("Properties")
    new = etree.Element(spec["element"])
    rec_tag = spec["element"]
    new.set("name", old.get("name", name) if old is not None else name)
    # The replacement is written whole, but each attribute still passes the entity-database check.
    if rec_tag == "Vehicle":
        new.set("vehicleCategory", rec.db.check_value("Vehicle", "vehicleCategory", spec["osc"]))
    else:
        new.set("mass", rec.db.check_value("Pedestrian", "mass", str(spec["mass"])))
        new.set("model", rec.db.check_value("Pedestrian", "model", spec.get("model", category)))
        new.set("pedestrianCategory", rec.db.check_value("Pedestrian", "pedestrianCategory", spec["osc"]))
    bbox = _sub(new, "BoundingBox")
    center = _sub(bbox, "Center", x="0", y="0", z="0")
    dims = _sub(bbox, "Dimensions", width="1", length="1", height="1")
    _copy_attrs(old, "BoundingBox/Center", center)
    _copy_attrs(old, "BoundingBox/Dimensions", dims)
    if old is not None:
        obj.replace(old, new)
    else:
        obj.insert(0, new)
    rec.note(f"ScenarioObject[@name='{name}']/@txt2sce:category", old_cat or None, category)
    if old is None or old.tag != new.tag:
        rec.note(f"ScenarioObject[@name='{name}']/EntityObject", old.tag if old is not None else None, new.tag)
    dm(dims, tuple(spec["dims"]), tuple(spec["lo"]), tuple(spec["hi"]), rng, cfg["physical"]["dm"], rec)
    width, length, height = (float(dims.get(a)) for a in DIM_ATTRS)
    # Reference point as our seeds place it: vehicles at the rear axle (centre ahead of it), pedestrians central.
    if rec_tag == "Vehicle":
        rec.set(center, "x", 0.3 * length, digits=3)
    rec.set(center, "z", height / 2.0, digits=3)
    if rec_tag == "Vehicle":
        perf = _sub(new, "Performance", maxSpeed="1", maxAcceleration="1", maxDeceleration="1")
        _copy_attrs(old, "Performance", perf)
        vpm(perf, tuple(spec["perf"]), rng, cfg["dynamics"]["vpm"], rec)
        axles = _sub(new, "Axles")
        wheel = "0.7" if category in ("bicycle", "motorcycle") else ("1.0" if category in ("truck", "bus") else "0.6")
        _sub(axles, "FrontAxle", maxSteering="0.5", wheelDiameter=wheel, trackWidth=f"{width:.3f}",
             positionX=f"{0.6 * length:.3f}", positionZ=f"{float(wheel) / 2:.3f}")
        _sub(axles, "RearAxle", maxSteering="0", wheelDiameter=wheel, trackWidth=f"{width:.3f}", positionX="0",
             positionZ=f"{float(wheel) / 2:.3f}")
    props = _sub(new, "Properties")
    if props_src is not None:
        for prop in props_src:
            if isinstance(prop.tag, str) and prop.get("name") != "txt2sce:category":
                props.append(etree.fromstring(etree.tostring(prop, with_tail=False)))
    _sub(props, "Property", name="txt2sce:category", value=category)
    rec.check_tree(new)
    return old_cat


def init_speed_follow(private: etree._Element | None, category: str, cfg: dict[str, Any], rec: Recorder) -> None:
    """A new category keeps its initial speed only if it can go that fast: capped at the category's default
    travel speed when the category changed (a pedestrian does not start at a car's 6 m/s)."""
    if private is None:
        return
    cap = float(cfg["physical"]["categories"][category]["speed"])
    for t in private.iterfind("PrivateAction/LongitudinalAction/SpeedAction/SpeedActionTarget/AbsoluteTargetSpeed"):
        if float(t.get("value", "0")) > cap:
            rec.set(t, "value", cap, digits=3)
