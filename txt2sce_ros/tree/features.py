"""Feature vectors for pruning and diversity (paper §IV-C): numeric attributes in uniform bins, enumerations by
value, events by driving semantics. Each block version (original or mutated) gets one feature tuple, read from its
XML, so originals and variants are encoded the same way; a node's vector is the tuple of its blocks' features.
"""

from __future__ import annotations

import math
import re
from typing import Any

from lxml import etree

from .blocks import BlockKind
from .dynamics import initial_speed
from ..seed.context import SeedContext, lane_pos
from .environment import configured_approach, primary_signal, signal_block, weather_type
from .physical import entity_element

_EVENT_RE = re.compile(r"^(?P<entity>.+?)_e(?P<k>\d+)_(?P<action>.+)$")


def split_event_name(name: str) -> tuple[str, str]:
    """(entity, action) from `<entity>_e<k>_<action>`; ('', name) when the name does not follow the format."""
    m = _EVENT_RE.match(name)
    return (m.group("entity"), m.group("action")) if m else ("", name)


def bin_of(value: float, lo: float, hi: float, n: int) -> int:
    """Uniform bin index of `value` in [lo, hi] split into n bins (values outside go to the end bins)."""
    if not math.isfinite(value) or hi <= lo:
        return 0
    return int(min(n - 1, max(0, math.floor((value - lo) / (hi - lo) * n))))


def _f(el: etree._Element | None, attr: str, default: float = 0.0) -> float:
    if el is None:
        return default
    try:
        return float(el.get(attr, default))
    except ValueError:
        return default


def weather_features(env: etree._Element, cfg: dict[str, Any], n: int) -> dict[str, Any]:
    kind = weather_type(env)
    spec = cfg["environment"]["weather"][kind]
    w = env.find("Weather")
    sun, fog, prec = (w.find("Sun"), w.find("Fog"), w.find("Precipitation")) if w is not None else (None,) * 3
    return {"type": kind,
            "visibility": bin_of(_f(fog, "visualRange"), *spec["visibility"], n),
            "azimuth": bin_of(_f(sun, "azimuth"), *cfg["environment"]["azimuth"], n),
            "elevation": bin_of(_f(sun, "elevation"), *cfg["environment"]["elevation"], n),
            "precipitation": bin_of(_f(prec, "intensity"), *spec["precipitation"], n),
            "friction": bin_of(_f(env.find("RoadCondition"), "frictionScaleFactor", 1.0), *spec["friction"], n)}


def _is_approach(private: etree._Element | None, ctx: SeedContext, cfg: dict[str, Any]) -> bool:
    """Whether the ego's start is the seed's approach start (`environment.approach_start`): what the yellow
    versions of the signal blocks need under a budget."""
    tele = private.find("PrivateAction/TeleportAction/Position/LanePosition") if private is not None else None
    if tele is None:
        return False
    init = cfg["trajectory"]["init_location"]
    found = configured_approach(ctx, init)
    # the speed too: an approach made from the seed's own start differs from it only in its speed
    speed = initial_speed(private)
    if found is None or abs(lane_pos(tele).s - round(found.s, 3)) >= 1e-6 \
            or (speed is not None and abs(speed - round(found.speed, 3)) >= 1e-6):
        return False
    if found.goal is None:
        return True
    # an approach through the light (`through_light`) also carries the route's end past it
    end = private.find("PrivateAction/RoutingAction/AssignRouteAction/Route/Waypoint[last()]/Position/LanePosition")
    return end is not None and (lane_pos(end).road, lane_pos(end).lane) == (found.goal.road, found.goal.lane) \
        and abs(lane_pos(end).s - round(found.goal.s, 3)) < 1e-6


def _shift_bin(private: etree._Element | None, entity: str, ctx: SeedContext, cfg: dict[str, Any], n: int) -> int:
    tele = private.find("PrivateAction/TeleportAction/Position/LanePosition") if private is not None else None
    start = ctx.starts.get(entity)
    if tele is None or start is None:
        return n // 2
    m = cfg["trajectory"]["init_location"]["max_shift"]
    return bin_of(lane_pos(tele).s - start.s, -m, m, n)


def entity_category(obj: etree._Element) -> str:
    ent = entity_element(obj)
    if ent is None:
        return "unknown"
    prop = ent.find("Properties/Property[@name='txt2sce:category']")
    if prop is not None and prop.get("value"):
        return prop.get("value", "")
    return ent.get("vehicleCategory") or ent.get("pedestrianCategory") or ent.get("miscObjectCategory") or ent.tag


def npc_features(obj: etree._Element, private: etree._Element | None, ctx: SeedContext, cfg: dict[str, Any],
                 n: int) -> dict[str, Any]:
    cat = entity_category(obj)
    cats = cfg["physical"]["categories"]
    spec = cats.get(cat, cats["car"])
    ent = entity_element(obj)
    dims = ent.find("BoundingBox/Dimensions") if ent is not None else None
    perf = ent.find("Performance") if ent is not None else None
    lo_s, hi_s = cfg["dynamics"]["vpm"]["clip_share"]
    out: dict[str, Any] = {"category": cat}
    for a, lo, hi in zip(("width", "length", "height"), spec["lo"], spec["hi"]):
        out[a] = bin_of(_f(dims, a), lo, hi, n)
    out["max_speed"] = bin_of(_f(perf, "maxSpeed", spec["perf"][0]), lo_s * spec["perf"][0], hi_s * spec["perf"][0], n)
    out["shift"] = _shift_bin(private, obj.get("name", ""), ctx, cfg, n)
    out["start"] = _start_kind(private, obj.get("name", ""), ctx, cfg)
    return out


def _start_kind(private: etree._Element | None, entity: str, ctx: SeedContext, cfg: dict[str, Any]) -> str:
    """`near` when the party starts within the WPM-near distance of the ego's start along the same road (the
    version `trajectory.place_near_ego` makes), else `seed`: a party close to the AV is a condition of its own."""
    tele = private.find("PrivateAction/TeleportAction/Position/LanePosition") if private is not None else None
    ego = ctx.starts.get("ego")
    if tele is None or ego is None:
        return "seed"
    pos = lane_pos(tele)
    reach = 2 * cfg["trajectory"]["init_location"]["near_gap"] + 10.0   # gap + two vehicles' bumper-to-axle
    return "near" if pos.road == ego.road and abs(pos.s - ego.s) <= reach else "seed"


def event_features(ev: etree._Element, original: etree._Element, cfg: dict[str, Any], n: int) -> dict[str, Any]:
    """Driving semantics of one event: its action, how its target speed compares with the seed's (accelerating,
    decelerating, keeping), the speed ratio's bin, the transition shape and value bin, the lateral offset bin."""
    _, action = split_event_name(ev.get("name", ""))
    new_t = next(ev.iter("AbsoluteTargetSpeed"), None)
    old_t = next(original.iter("AbsoluteTargetSpeed"), None)
    ratio = 1.0
    if new_t is not None and old_t is not None and _f(old_t, "value") > 0:
        ratio = _f(new_t, "value") / _f(old_t, "value")
    style = "acc" if ratio > 1.001 else ("dec" if ratio < 0.999 else "keep")
    dyn = next((d for tag in ("SpeedActionDynamics", "LaneChangeActionDynamics") for d in ev.iter(tag)), None)
    shape = dyn.get("dynamicsShape", "") if dyn is not None else ""
    dim = dyn.get("dynamicsDimension", "time") if dyn is not None else "time"
    vlo, vhi = cfg["dynamics"]["dtm"]["value"].get(dim, cfg["dynamics"]["dtm"]["value"]["time"])
    lc = next(ev.iter("LaneChangeAction"), None)
    half = cfg["trajectory"]["wpm"]["default_lane_width"] / 2
    return {"action": action, "style": style, "speed": bin_of(ratio, 0.5, 1.5, n), "shape": shape,
            "dynamics_value": bin_of(_f(dyn, "value"), vlo, vhi, n) if dyn is not None else -1,
            "offset": bin_of(_f(lc, "targetLaneOffset"), -half, half, n) if lc is not None else -1}


def signal_features(parts: list[etree._Element | None], facing: tuple[str, ...]) -> dict[str, Any]:
    """`ego`: the state the AV's own signal shows in the phase the scenario is labelled by (its first: the yellow of
    a dilemma-zone plan); `states`: all of that phase's states."""
    tested = signal_block(parts).tested
    primary = primary_signal(tested, facing)
    return {"ego": primary[1] if primary is not None else "none", "states": "/".join(c for _, c in tested)}


def obstacle_features(obj: etree._Element | None, private: etree._Element | None, ctx: SeedContext,
                      cfg: dict[str, Any], n: int) -> dict[str, Any]:
    if obj is None:
        return {"category": "none", "where": "none", "distance": -1, "width": -1, "length": -1, "height": -1}
    spec = cfg["environment"]["obstacle"]
    ent = entity_element(obj)
    dims = ent.find("BoundingBox/Dimensions") if ent is not None else None
    where = "off_path"
    dist_bin = -1
    tele = private.find("PrivateAction/TeleportAction/Position/LanePosition") if private is not None else None
    ego = ctx.starts.get("ego")
    if tele is not None and ego is not None:
        pos = lane_pos(tele)
        if pos.road == ego.road and ctx.map is not None and ctx.map.has_road(ego.road):
            ahead = ctx.map.direction(ego.road, ego.lane) * (pos.s - ego.s)
            where = "ego_lane" if pos.lane == ego.lane else "other_lane"
            dist_bin = bin_of(ahead, *spec["ahead"], n)
        else:
            where = "route"
    out: dict[str, Any] = {"category": entity_category(obj), "where": where, "distance": dist_bin}
    for a, lo, hi in zip(("width", "length", "height"), spec["dims_lo"], spec["dims_hi"]):
        out[a] = bin_of(_f(dims, a), lo, hi, n)
    return out


def all_features(kind: BlockKind, elements: list[etree._Element | None], originals: list[etree._Element | None],
                 ctx: SeedContext, cfg: dict[str, Any]) -> dict[str, Any]:
    """Every feature one version of a block offers, by name (see `features:` in config/mutation.yaml)."""
    n = int(cfg["bins"])
    if kind is BlockKind.WEATHER:
        return weather_features(elements[0], cfg, n)
    if kind is BlockKind.EGO:
        speed = initial_speed(elements[0])
        start = "standing" if speed is not None and speed <= 0.0 else "moving"
        if start == "moving" and _is_approach(elements[0], ctx, cfg):
            start = "approach"
        return {"shift": _shift_bin(elements[0], "ego", ctx, cfg, n), "start": start}
    if kind is BlockKind.NPC:
        return npc_features(elements[0], elements[1] if len(elements) > 1 else None, ctx, cfg, n)
    if kind is BlockKind.NEW_PARTY:
        if elements[0] is None:
            return {"category": "none", "start": "none", "events": ""}
        feats = npc_features(elements[0], elements[1] if len(elements) > 1 else None, ctx, cfg, n)
        story = elements[2] if len(elements) > 2 else None
        feats["events"] = "".join(split_event_name(e.get("name", ""))[1] for e in story.iter("Event")) \
            if story is not None else ""
        return feats
    if kind in (BlockKind.SIGNAL, BlockKind.NEW_SIGNAL):
        return signal_features(elements, ctx.ego_signals)
    if kind is BlockKind.EVENT:
        return event_features(elements[0], originals[0], cfg, n)
    return obstacle_features(elements[0], elements[1] if len(elements) > 1 else None, ctx, cfg, n)


def block_features(kind: BlockKind, elements: list[etree._Element | None], originals: list[etree._Element | None],
                   ctx: SeedContext, cfg: dict[str, Any]) -> tuple:
    """The feature tuple of one version of a block: the kind, then the configured features in order. The first
    feature named for a kind is its abstract representation (Table V)."""
    feats = all_features(kind, elements, originals, ctx, cfg)
    key = {BlockKind.NEW_OBSTACLE: "obstacle", BlockKind.NEW_SIGNAL: "signal"}.get(kind, kind.value)
    return (key, *(feats[name] for name in cfg["features"][key]))
