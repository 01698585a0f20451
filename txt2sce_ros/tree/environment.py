"""Environment mutation family (Table III): WM weather, TLS traffic-signal state, OIM obstacle insertion."""

from __future__ import annotations

from dataclasses import dataclass, fields
from functools import lru_cache
from typing import Any

import numpy as np
from lxml import etree

from ..config import load_config
from ..errors import InputError
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


@dataclass(frozen=True, slots=True)
class SignalTiming:
    """How long the phases the TLS mutation writes last (s); `config/effect.yaml`, section `tls`."""

    yellow: float = 4.0
    red: float = 12.0
    hold: float = 3600.0


@lru_cache(maxsize=1)
def signal_timing() -> SignalTiming:
    """The TLS phase timing from `config/effect.yaml` (defaults for keys left out; unknown keys are errors)."""
    section = load_config("effect").get("tls", {}) or {}
    known = {f.name for f in fields(SignalTiming)}
    for key, value in section.items():
        if key not in known:
            raise InputError(f"unknown key (known: {', '.join(sorted(known))})", source="config/effect.yaml",
                             element=f"tls.{key}")
        if not isinstance(value, (int, float)) or value <= 0:
            raise InputError(f"must be a positive number of seconds, got {value!r}", source="config/effect.yaml",
                             element=f"tls.{key}")
    timing = SignalTiming(**{k: float(v) for k, v in section.items()})
    if timing.red <= timing.yellow:
        raise InputError("tls.red must exceed tls.yellow (the conflicting signals' yellow is part of the red)",
                         source="config/effect.yaml", element="tls.red")
    return timing


def _schedule(state: str, timing: SignalTiming) -> list[tuple[str, float, str, str]]:
    """The phases that make `state` meaningful: (phase name, duration, primary's state, conflicting signals').

    green: green for the run. yellow: yellow for `yellow` s, then red, then green. red: red for `red` s, then
    green. While the primary is red the conflicting signals are green, and yellow for its last `yellow` s so
    they clear before the primary turns green; the last phase holds for the rest of the run."""
    red = [("tls_red", timing.red - timing.yellow, "red", "green"),
           ("tls_red_clear", timing.yellow, "red", "yellow"),
           ("tls_green", timing.hold, "green", "red")]
    if state == "green":
        return red[-1:]
    if state == "yellow":
        return [("tls_yellow", timing.yellow, "yellow", "red")] + red
    return red


def tls(ctrl: etree._Element, state: str, rec: Recorder, *, facing: tuple[str, ...] = (),
        timing: SignalTiming | None = None) -> str:
    """Traffic Signal Mutation: the controller's primary signal — the first of `facing` (the signals facing the
    AV, per the map) its first phase sets, else that phase's first — starts showing `state`, and the controller's
    phases are rewritten so the state means something over the run (`_schedule`): a yellow turns red, a red turns
    green after a while so the goal stays reachable, a green stays green. Signals that showed the primary's old
    state in the first phase follow the primary; the others show the conflicting state. Returns the old state."""
    phase = ctrl.find("Phase")
    first = primary_signal(phase, facing) if phase is not None else None
    if first is None:
        return ""
    timing = timing or signal_timing()
    lamps = ";" in (first.get("state") or "")
    old = signal_state_name(first.get("state", ""))
    follows = [signal_state_name(s.get("state", "")) == old or s is first for s in phase.findall("TrafficSignalState")]
    ids = [s.get("trafficSignalId") for s in phase.findall("TrafficSignalState")]
    before = [(p.get("name"), p.get("duration")) for p in ctrl.findall("Phase")]
    for p in ctrl.findall("Phase"):
        ctrl.remove(p)
    for name, duration, primary, conflict in _schedule(state, timing):
        ph = etree.SubElement(ctrl, "Phase", name=name)
        ph.set("duration", rec.db.check_value("Phase", "duration", f"{duration:g}"))
        for sid, same in zip(ids, follows):
            shown = primary if same else conflict
            etree.SubElement(ph, "TrafficSignalState", trafficSignalId=sid,
                             state=_LAMP_STATES[shown] if lamps else shown)
    rec.check_tree(ctrl)
    after = [(p.get("name"), p.get("duration")) for p in ctrl.findall("Phase")]
    rec.note(f"TrafficSignalController[@name='{ctrl.get('name')}']/Phase",
             " ".join(f"{n}:{d}" for n, d in before), " ".join(f"{n}:{d}" for n, d in after) + f" ({state})")
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
