"""Environment mutation family (Table III): WM weather, TLS traffic-signal state, OIM obstacle insertion."""

from __future__ import annotations

from typing import Any

import numpy as np
from lxml import etree

from ..seed.context import LanePos, SeedContext
from .values import Recorder, uniform

#: esmini-style lamp encodings (red;yellow;green lamps), used when a seed writes states that way.
_LAMP_STATES = {"red": "on;off;off", "yellow": "off;on;off", "green": "off;off;on"}
_LAMP_NAMES = {v: k for k, v in _LAMP_STATES.items()}


def wm(env: etree._Element, weather: str, rng: np.random.Generator, cfg: dict[str, Any], rec: Recorder) -> None:
    """Weather Mutation: cloud state and precipitation type of the weather type, and its parameters drawn
    uniformly: precipitation intensity, visibility (Fog/@visualRange), sun intensity, azimuth, elevation, and the
    road friction that goes with the weather."""
    spec = cfg["weather"][weather]
    w = env.find("Weather")
    if w is None:  # the 1.0 schema requires it; a seed without it is rejected earlier by validation
        raise KeyError("Environment without Weather")
    rec.set(w, "cloudState", spec["cloudState"])
    sun, fog, prec = w.find("Sun"), w.find("Fog"), w.find("Precipitation")
    rec.set(sun, "intensity", uniform(rng, *spec["intensity"]), digits=1)
    rec.set(sun, "azimuth", uniform(rng, *cfg["azimuth"]), digits=4)
    rec.set(sun, "elevation", uniform(rng, *cfg["elevation"]), digits=4)
    rec.set(fog, "visualRange", uniform(rng, *spec["visibility"]), digits=1)
    rec.set(prec, "precipitationType", spec["precipitationType"])
    rec.set(prec, "intensity", uniform(rng, *spec["precipitation"]), digits=3)
    road = env.find("RoadCondition")
    rec.set(road, "frictionScaleFactor", uniform(rng, *spec["friction"]), digits=3)


def weather_type(env: etree._Element | None) -> str:
    """The seed's weather as one of the WM types (for Table V's abstract representations)."""
    if env is None:
        return "sunny"
    w = env.find("Weather")
    if w is None:
        return "sunny"
    prec = w.find("Precipitation")
    fog = w.find("Fog")
    ptype = prec.get("precipitationType", "dry") if prec is not None else "dry"
    if ptype == "rain":
        return "rainy"
    if ptype == "snow":
        return "snowy"
    if fog is not None and float(fog.get("visualRange", "1e9")) < 200:
        return "foggy"
    return "cloudy" if w.get("cloudState") in ("cloudy", "overcast", "rainy") else "sunny"


def signal_state_name(state: str) -> str:
    return _LAMP_NAMES.get(state, state)


def primary_signal(phase: etree._Element, facing: tuple[str, ...] = ()) -> etree._Element | None:
    """The phase's primary `TrafficSignalState`: the first of `facing` (signal ids facing the AV, per the map) the
    phase sets, else its first; None for a phase that sets no signal. The TLS mutation changes this signal, and
    the analysis labels a scenario by it, so both must pick the same one."""
    states = phase.findall("TrafficSignalState")
    if not states:
        return None
    by_id = {s.get("trafficSignalId"): s for s in states}
    return next((by_id[f] for f in facing if f in by_id), states[0])


def tls(ctrl: etree._Element, state: str, rec: Recorder, *, facing: tuple[str, ...] = ()) -> str:
    """Traffic Signal Mutation: in the controller's first phase (running while the parties interact) the primary
    signal — the first of `facing` (the signals facing the AV, per the map) the phase sets, else the phase's
    first — shows `state`; signals that showed the primary's old state follow it, the others show the
    conflicting state (red while the primary is green/yellow, green otherwise). Returns the old state."""
    phase = ctrl.find("Phase")
    first = primary_signal(phase, facing) if phase is not None else None
    if first is None:
        return ""
    states = phase.findall("TrafficSignalState")
    lamps = ";" in (first.get("state") or "")
    old = signal_state_name(first.get("state", ""))
    conflict = "green" if state == "red" else "red"
    for s in states:
        same = signal_state_name(s.get("state", "")) == old
        target = state if (s is first or same) else conflict
        rec.set(s, "state", _LAMP_STATES[target] if lamps else target)
    return old


def oim_position(ctx: SeedContext, obstacle_width: float, rng: np.random.Generator, cfg: dict[str, Any],
                 ) -> LanePos | None:
    """Context-aware obstacle position on the AV's path: a distance ahead of the ego's start drawn uniformly,
    walked along the ego's start road and then the non-junction roads of its route, on the lane the ego uses
    there, with a lateral offset that keeps the obstacle inside that lane. None without a map or an ego start."""
    m = ctx.map
    ego = ctx.starts.get("ego")
    if m is None or ego is None or not m.has_road(ego.road):
        return None
    remaining = uniform(rng, *cfg["ahead"])
    # Path pieces: (road, lane, s_from, s_to) in driving direction.
    pieces: list[tuple[str, int, float, float]] = []
    sign = m.direction(ego.road, ego.lane)
    pieces.append((ego.road, ego.lane, ego.s, m.road_length(ego.road) if sign > 0 else 0.0))
    for wp in ctx.ego_route[1:]:
        if not m.has_road(wp.road) or m.in_junction(wp.road) or wp.road == ego.road:
            continue
        d = m.direction(wp.road, wp.lane)
        pieces.append((wp.road, wp.lane, 0.0 if d > 0 else m.road_length(wp.road), wp.s))
    for road, lane, s0, s1 in pieces:
        span = abs(s1 - s0)
        if remaining <= span - 1.0:
            s = s0 + np.sign(s1 - s0) * remaining
            if m.lane_type(road, lane, s) is None:
                return None
            width = m.lane_width(road, lane, s)
            half = max(0.0, (width - obstacle_width) / 2.0)
            return LanePos(road=road, lane=lane, s=float(s), offset=uniform(rng, -half, half))
        remaining -= span
    # The path is shorter than the draw: put the obstacle halfway along the last piece.
    road, lane, s0, s1 = pieces[-1]
    s = (s0 + s1) / 2.0
    return LanePos(road=road, lane=lane, s=float(s), offset=0.0)


def obstacle_fragments(name: str, pos: LanePos, dims: tuple[float, float, float], cfg: dict[str, Any],
                       rec: Recorder) -> tuple[etree._Element, etree._Element]:
    """A new MiscObject obstacle (ScenarioObject) and its Init Private placing it at `pos`, values checked."""
    obj = etree.Element("ScenarioObject", name=name)
    misc = etree.SubElement(obj, "MiscObject", name=name)
    misc.set("miscObjectCategory", rec.db.check_value("MiscObject", "miscObjectCategory", cfg["category"]))
    misc.set("mass", rec.db.check_value("MiscObject", "mass", str(cfg["mass"])))
    bbox = etree.SubElement(misc, "BoundingBox")
    etree.SubElement(bbox, "Center", x="0", y="0", z=f"{dims[2] / 2:.3f}")
    d = etree.SubElement(bbox, "Dimensions")
    for attr, v in zip(("width", "length", "height"), dims):
        d.set(attr, rec.db.check_value("Dimensions", attr, f"{v:.3f}"))
    props = etree.SubElement(misc, "Properties")
    etree.SubElement(props, "Property", name="txt2sce:category", value="debris")
    priv = etree.Element("Private", entityRef=name)
    lp = etree.SubElement(etree.SubElement(etree.SubElement(etree.SubElement(priv, "PrivateAction"),
                                                            "TeleportAction"), "Position"), "LanePosition")
    lp.set("roadId", pos.road)
    lp.set("laneId", str(pos.lane))
    lp.set("s", rec.db.check_value("LanePosition", "s", f"{pos.s:.3f}"))
    lp.set("offset", rec.db.check_value("LanePosition", "offset", f"{pos.offset:.3f}"))
    rec.check_tree(obj)
    rec.check_tree(priv)
    rec.note(f"Entities/ScenarioObject[@name='{name}']", None, f"MiscObject {dims[0]:.2f}x{dims[1]:.2f}x{dims[2]:.2f}")
    rec.note(f"Init/Private[@entityRef='{name}']/LanePosition", None,
             f"road {pos.road} lane {pos.lane} s {pos.s:.2f} offset {pos.offset:.2f}")
    return obj, priv
