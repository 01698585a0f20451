"""Environment mutation family (Table III): WM weather, TLS traffic-signal state, OIM obstacle insertion."""

from __future__ import annotations

import math

from dataclasses import dataclass, fields
from functools import lru_cache
from typing import Any

import numpy as np
from lxml import etree

from ..config import load_config
from ..errors import InputError
from ..seed.context import LanePos, SeedContext
from ..seed.model import SignalPhase, SignalPlan
from ..seed.signal_story import DecodedPlan, EarlyStart, read_plan, write_plan
from .dynamics import initial_speed
from .trajectory import feasible_s, footprint_extent, starts_clear
from .values import Recorder, uniform



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


#: Visibility below which a dry scene is fog (m): the meteorological definition of fog (WMO: under 1 km).
FOG_VISIBILITY = 1000.0


def weather_type(env: etree._Element | None) -> str:
    """The one weather classifier of the project: an `Environment` as one of the WM types (sunny, cloudy, rainy,
    snowy, foggy). Precipitation first (rain or snow with a non-zero intensity, 1.0 `intensity` or 1.2
    `precipitationIntensity`), then fog by visibility, then cloud (1.0 `cloudState` or 1.2 `fractionalCloudCover`
    above 1 okta). The tree's features and the analysis's `weather:` elements both read it."""
    if env is None:
        return "sunny"
    w = env.find("Weather")
    if w is None:
        return "sunny"
    prec = w.find("Precipitation")
    if prec is not None:
        ptype = prec.get("precipitationType", "dry")
        raw = prec.get("intensity", prec.get("precipitationIntensity"))
        if ptype in ("rain", "snow") and (raw is None or _number(raw) > 0.0):
            return "rainy" if ptype == "rain" else "snowy"
    fog = w.find("Fog")
    if fog is not None and _number(fog.get("visualRange"), math.inf) < FOG_VISIBILITY:
        return "foggy"
    cloud = w.get("cloudState", w.get("fractionalCloudCover", ""))
    if cloud in ("cloudy", "overcast", "rainy") or (cloud.startswith("oktas") and cloud not in ("oktas0", "oktas1")):
        return "cloudy"
    return "sunny"


def _number(text: str | None, default: float = 0.0) -> float:
    try:
        return float(text) if text is not None else default
    except ValueError:
        return default


def primary_signal(states: tuple[tuple[str, str], ...], facing: tuple[str, ...] = ()) -> tuple[str, str] | None:
    """The primary (signal id, colour) of a phase's states: the first of `facing` (signal ids facing the AV, per the
    map) the phase sets, else its first; None for a phase that sets no signal. The TLS mutation changes this signal,
    and the analysis labels a scenario by it, so both must pick the same one."""
    if not states:
        return None
    by_id = dict(states)
    return next(((f, by_id[f]) for f in facing if f in by_id), states[0])


def signal_block(parts: list[etree._Element | None]) -> DecodedPlan:
    """The phase plan a signal block holds (its Init GlobalActions, then its Story: `seed.signal_story`)."""
    return read_plan([p for p in parts[:-1] if p is not None], parts[-1] if parts else None)


@dataclass(frozen=True, slots=True)
class SignalTiming:
    """How long the phases the TLS mutation writes last (s); `config/effect.yaml`, section `tls`."""

    yellow: float = 4.0
    red: float = 12.0
    hold: float = 3600.0
    margin: float = 0.7     # the yellow starts when the ego is `yellow + margin` s from the stop line
    lead: float = 1.0       # s an approach start (`approach_start`) drives before the dilemma zone begins
    min_yellow: float = 3.0  # s a dilemma-zone yellow shows at least before its red may come early
    arrival: float = 0.5    # s: the red of a dilemma-zone yellow comes early once the ego is this close to the line


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
    if timing.min_yellow > timing.yellow:
        raise InputError("tls.min_yellow must not exceed tls.yellow (the yellow's red comes at tls.yellow at the "
                         "latest)", source="config/effect.yaml", element="tls.min_yellow")
    if timing.arrival >= timing.margin:
        raise InputError("tls.arrival must be shorter than tls.margin (an ego at constant speed meets the red "
                         "tls.yellow s after the onset, tls.margin s from the line: only one that speeds up "
                         "meets it early)", source="config/effect.yaml", element="tls.arrival")
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


def tls(parts: list[etree._Element | None], state: str, rec: Recorder, *, facing: tuple[str, ...] = (),
        timing: SignalTiming | None = None, time_limit: float = 60.0) -> str:
    """Traffic Signal Mutation on a signal block (`parts`: its Init GlobalActions, then its Story): the primary
    signal of the phase the scenario is labelled by — the first of `facing` (the signals facing the AV, per the
    map) that phase sets, else its first — starts showing `state`, and the phases are rewritten so the state means
    something over the run (`_schedule`): a yellow turns red, a red turns green after a while so the goal stays
    reachable, a green stays green. Signals that showed the primary's old state follow the primary; the others
    show the conflicting state. The parts are replaced in place (same count: one Init action per signal, one
    Story). Returns the old state. A yellow is then moved to the ego's dilemma zone by `dilemma_yellow` where the
    ego can reach the line."""
    decoded = signal_block(parts)
    tested = decoded.tested
    first = primary_signal(tested, facing)
    if first is None or len(parts) != len(tested) + 1:
        return ""
    timing = timing or signal_timing()
    old = first[1]
    follows = [colour == old or sid == first[0] for sid, colour in tested]
    phases = tuple(SignalPhase(name, float(rec.db.check_value("Phase", "duration", f"{duration:g}")),
                               tuple((sid, primary if same else conflict)
                                     for (sid, _), same in zip(tested, follows)))
                   for name, duration, primary, conflict in _schedule(state, timing))
    plan = SignalPlan(decoded.plan.name, phases)
    inits, story = write_plan(plan, time_limit=time_limit)
    parts[:] = [*inits, story]
    for el in parts:
        rec.check_tree(el)
    before = " ".join(f"{p.name or 'init'}:{p.duration:g}" for p in decoded.plan.phases)
    after = " ".join(f"{p.name}:{p.duration:g}" for p in phases)
    rec.note(f"Story[@name='{plan.name}']/Event", before, after + f" ({state})")
    return old


def stop_line(ctx: SeedContext, sid: str, *, slack: float = 0.0) -> LanePos | None:
    """Where the ego's route crosses the stop line of signal `sid` (its road, the ego's lane there when the signal
    controls it, the signal's s), or None when the ego cannot reach that line: no map, no such signal, the ego's
    front bumper is not more than `slack` m before the line on its start road (a node may start the ego up to
    that much further ahead, WPM-init), or the signal's road is neither the ego's start road nor a later road of
    its route (an AV standing past the line, inside the junction, faces its approach's light but never drives to
    it)."""
    net = ctx.network
    ego = ctx.starts.get("ego")
    sig = net.signals.get(sid) if net is not None else None
    if sig is None or ego is None or ctx.map is None or not ctx.map.has_road(sig.road_id):
        return None
    road = str(sig.road_id)
    lanes = tuple(getattr(sig, "controlled_lanes", ()) or ())
    if road == ego.road:
        ahead = ctx.map.direction(ego.road, ego.lane) * (sig.s - ego.s)
        if ahead <= footprint_extent(ctx.root.find("Entities/ScenarioObject[@name='ego']"))[1] + slack:
            return None               # the bumper is (or may be moved) over the line: the ego never reaches it
        lane = ego.lane
    else:
        on_route = [wp.lane for wp in ctx.ego_route[1:] if wp.road == road]
        if not on_route:
            return None
        lane = on_route[0]
    if lanes and lane not in lanes:
        lane = lanes[0]
    return LanePos(road=road, lane=int(lane), s=float(sig.s))


def dilemma_yellow(parts: list[etree._Element | None], ctx: SeedContext, rec: Recorder, *,
                   timing: SignalTiming | None = None, slack: float = 0.0, time_limit: float = 60.0,
                   approach: "Approach | None" = None) -> bool:
    """For a signal block `tls` set to yellow: the lights start in the schedule's final green (Init) and the
    yellow starts once the ego is in the dilemma zone — then red, then green as `_schedule` says, each phase its
    duration after the yellow began. False (the block unchanged: the yellow then shows from t = 0, as `tls` wrote
    it) when the ego cannot reach the primary signal's stop line (`stop_line`; `slack`: how far ahead another
    block may move the ego's start).

    A yellow tests a stack only where stopping and going are both possible: shown from t = 0 to an ego 50 m away
    it turns red long before the ego arrives, and a stack that reads yellow as green still stops for the red.
    Started `yellow + margin` s of travel before the line, a stack that stops at yellow needs ~1 m/s^2, while
    one that keeps going meets red a fraction of a second (~6 m at 9 m/s) before the line, cannot stop and enters
    on red (config/effect.yaml `tls.margin` says how the margin was chosen). The trigger is a
    TimeToCollisionCondition to the stop line (front bumper, `freespace`) rather than a distance, because the
    stack under test drives at its own speed: the time to the line is what fixes where red finds it. `alongRoute`
    is false (distance along the ego's heading): the approach to a stop line is straight, and every player
    measures that the same way. The yellow stays the plan's first phase, so the scenario is still labelled by it
    (tree features, analysis `signal_label`); only the Init actions show green. `approach` (`approach_start`):
    its line is used even where the seed's own AV cannot reach it (it stands at the line), for the nodes that
    start the AV back on its approach."""
    timing = timing or signal_timing()
    decoded = signal_block(parts)
    phases = decoded.plan.phases
    first = primary_signal(decoded.tested, ctx.ego_signals)
    schedule = _schedule("yellow", timing)
    if decoded.triggered or first is None or len(phases) != len(schedule):
        return False
    shown = [dict(p.states).get(first[0]) for p in phases]
    if shown != [primary for _n, _d, primary, _c in schedule]:      # not the schedule `tls` writes for a yellow
        return False
    # Read back, a timed plan has no name for its first phase (Init) nor a duration for its last (it outlasts
    # the run): the schedule's own are used.
    phases = tuple(SignalPhase(n, d, p.states) for p, (n, d, _a, _b) in zip(phases, schedule))
    line = stop_line(ctx, first[0], slack=slack)
    if line is None and approach is not None and approach.signal == first[0]:
        line = approach.line          # the seed's AV stands at the line; the approach start drives up to it
    if line is None:
        return False
    name = decoded.plan.name
    cond = _time_to_line(f"{name}_dilemma_zone", line, timing.yellow + timing.margin)
    # The red comes early when the ego arrives early: an AV that speeds up after the onset (from a slow approach,
    # out of a turn) would otherwise clear on yellow whatever it made of it, and one that slows for a turn would
    # meet the red far enough back to stop. Once the yellow has shown `min_yellow` s (a legal amber), the red
    # starts as the ego comes within `arrival` s of the line, which no stack that stopped at yellow reaches
    # (its time to the line grows as it stops); `yellow` s after the onset it starts regardless.
    early = EarlyStart(timing.min_yellow, _time_to_line(f"{name}_arrival", line, timing.arrival))
    inits, story = write_plan(SignalPlan(name, phases), time_limit=time_limit, trigger=cond, early=early)
    parts[:] = [*inits, story]
    for el in parts:
        rec.check_tree(el)
    rec.note(f"Story[@name='{name}']/Event[@name='{name}_tls_yellow']", None,
             f"tls_yellow when ego TTC to stop line road {line.road} lane {line.lane} s {line.s:.2f} < "
             f"{timing.yellow + timing.margin:g} s (lights green until then); red {timing.yellow:g} s later, or "
             f"after {timing.min_yellow:g} s once the TTC < {timing.arrival:g} s")
    return True


def _time_to_line(name: str, line: LanePos, seconds: float) -> etree._Element:
    """A Condition: the ego's front bumper is less than `seconds` of travel at its speed from the stop line `line`
    (TimeToCollisionCondition to the line's LanePosition, `freespace`, along its heading)."""
    cond = etree.Element("Condition", name=name, delay="0", conditionEdge="none")
    by = etree.SubElement(cond, "ByEntityCondition")
    etree.SubElement(etree.SubElement(by, "TriggeringEntities", triggeringEntitiesRule="any"), "EntityRef",
                     entityRef="ego")
    ttc = etree.SubElement(etree.SubElement(by, "EntityCondition"), "TimeToCollisionCondition",
                           value=f"{seconds:g}", freespace="true", alongRoute="false", rule="lessThan")
    etree.SubElement(etree.SubElement(etree.SubElement(ttc, "TimeToCollisionConditionTarget"), "Position"),
                     "LanePosition", roadId=line.road, laneId=str(line.lane), s=f"{line.s:.3f}", offset="0")
    return cond


@dataclass(frozen=True, slots=True)
class Approach:
    """A start on the AV's approach to the first traffic light facing it on its start road (`approach_start`)."""

    signal: str         # the light's id
    line: LanePos       # its stop line on the AV's lane
    s: float            # the AV's new start s (same road and lane as the seed's start)
    speed: float        # m/s at the start
    goal: LanePos | None = None     # the route's new end beyond the light's junction (`through_light`); None: the
                                    # seed's route (it already crosses the line)


def approach_start(ctx: SeedContext, *, speed: float, margin: float, min_gap: float,
                   timing: SignalTiming | None = None, lateral_accel: float | None = None,
                   min_speed: float | None = None) -> Approach | None:
    """WPM on the AV's initial location for a dilemma-zone yellow (TLS): where the seed starts the AV too close to
    the light it faces to arrive at speed (standing at the line, as in a report of an AV waiting at a red light,
    or moving but already inside the zone), a start further back on the same lane from which the AV, at its seed
    speed (`speed` when it stood), drives `lead` s before it is `yellow + margin` s from the line: the yellow then
    turns while it approaches, as the dilemma zone intends, instead of showing from t = 0 to an AV that is at the
    line or cannot stop anyway.

    The zone is timed at the AV's speed (`dilemma_yellow`), so the approach is made at a speed it can keep to the
    line: where its route turns in the junction beyond the light, no faster than that turn allows at
    `lateral_accel` m/s^2 (`turn_speed`; an AV that slows for the turn after the onset would meet the red far
    enough back to stop, whatever it made of the yellow) — a seed whose own start is far enough back but faster
    than that gets the approach too (from its own start, at the turn's speed, where the turn's start would lie
    past a place the AV must still reach), and where the turn's start is not free, the approach at the seed's
    speed is kept. Where the lane behind is taken (a party that started behind the AV in its lane stays behind
    it), the start furthest back that is free, at the speed that still gives the `lead`, down to `min_speed`
    (None: the full distance or nothing).

    None when the seed's start already gives that approach, no traffic light faces the AV on its start road, or
    no start is feasible (`feasible_s`: on the road and lane, never behind a party that started behind the AV in
    its lane; `margin`, `min_gap` as there)."""
    net, m, ego = ctx.network, ctx.map, ctx.starts.get("ego")
    if net is None or m is None or ego is None or not m.has_road(ego.road):
        return None
    timing = timing or signal_timing()
    seed_v = initial_speed(ctx.root.find("Storyboard/Init/Actions/Private[@entityRef='ego']")) or 0.0
    v = seed_v if seed_v > 0.0 else float(speed)
    front = footprint_extent(ctx.root.find("Entities/ScenarioObject[@name='ego']"))[1]
    sign = m.direction(ego.road, ego.lane)
    window = timing.yellow + timing.margin + timing.lead
    for sid in ctx.ego_signals:
        sig = net.signals.get(sid)
        if sig is None or not sig.is_traffic_light or str(sig.road_id) != ego.road:
            continue
        ahead = sign * (sig.s - ego.s)          # reference point to the line
        if ahead <= 0.0:
            return None                          # the AV starts past the light: it never approaches it
        turn = turn_speed(ctx, lateral_accel) if lateral_accel else None
        slowed = turn is not None and turn < v
        v_seed, v = v, (min(v, turn) if turn is not None else v)
        need = v * window + front
        if ahead >= need and not slowed:
            return None                          # the seed's own start already arrives at speed
        lanes = tuple(getattr(sig, "controlled_lanes", ()) or ())
        lane = ego.lane if not lanes or ego.lane in lanes else lanes[0]
        line = LanePos(road=ego.road, lane=int(lane), s=float(sig.s))
        new_s = sig.s - sign * need
        if _free_start(ctx, ego, new_s, margin, min_gap):
            return Approach(str(sid), line, float(new_s), v)
        if slowed and ahead >= need:
            # the turn's start would lie ahead of the seed's, past a place the AV must still reach: the seed's
            # own start, at the turn's speed (a longer lead)
            return Approach(str(sid), line, float(ego.s), v)
        need_seed = v_seed * window + front
        if slowed and ahead < need_seed and _free_start(ctx, ego, sig.s - sign * need_seed, margin, min_gap):
            # no room for the turn's approach: the approach at the seed's speed (it slows for the turn)
            return Approach(str(sid), line, float(sig.s - sign * need_seed), v_seed)
        if min_speed is None:
            return None
        # the lane behind is taken: the furthest-back free start (1 m steps toward the line), slower
        for back in np.arange(math.floor(need) - 1.0, front, -1.0):
            v_short = (back - front) / window
            if v_short < min_speed:
                return None
            new_s = sig.s - sign * float(back)
            if _free_start(ctx, ego, new_s, margin, min_gap):
                return Approach(str(sid), line, float(new_s), float(round(v_short, 3)))
        return None
    return None


def _free_start(ctx: SeedContext, ego: LanePos, new_s: float, margin: float, min_gap: float) -> bool:
    """`feasible_s` for the AV at `new_s`, and its footprint `min_gap` m clear of the footprint of every party
    starting in its lane (`feasible_s` spaces reference points: a bus's reference point 6 m behind the AV's
    start leaves its front inside the AV)."""
    if not feasible_s(ctx, "ego", ego, new_s, margin, min_gap):
        return False
    sign = ctx.map.direction(ego.road, ego.lane)
    e_rear, e_front = footprint_extent(ctx.root.find("Entities/ScenarioObject[@name='ego']"))
    lo, hi = sorted((new_s + sign * e_rear, new_s + sign * e_front))
    for other, pos in ctx.starts.items():
        if other == "ego" or (pos.road, pos.lane) != (ego.road, ego.lane):
            continue
        rear, front = footprint_extent(ctx.root.find(f"Entities/ScenarioObject[@name='{other}']"))
        o_lo, o_hi = sorted((pos.s + sign * rear, pos.s + sign * front))
        if o_lo - hi < min_gap and lo - o_hi < min_gap:
            return False
    return True


def configured_approach(ctx: SeedContext, init: dict[str, Any]) -> Approach | None:
    """The AV's approach start for a dilemma-zone yellow with the settings of `config/mutation.yaml`
    `trajectory.init_location` (`init`): `through_light` where the seed's route ends short of the light it faces,
    else `approach_start`."""
    through = through_light(ctx, speed=float(init["approach_speed"]), beyond=float(init["through_beyond"]),
                            slack=float(init["max_shift"]), lateral_accel=float(init["approach_lateral_accel"]))
    if through is not None:
        return through
    return approach_start(ctx, speed=float(init["approach_speed"]), margin=float(init["margin"]),
                          min_gap=float(init["min_gap"]), lateral_accel=float(init["approach_lateral_accel"]),
                          min_speed=float(init["approach_min_speed"]))


def through_light(ctx: SeedContext, *, speed: float, beyond: float, slack: float = 10.0,
                  timing: SignalTiming | None = None, lateral_accel: float | None = None) -> Approach | None:
    """WPM on the AV's route for a dilemma-zone yellow where the seed's route ends short of the light the AV faces
    on its start road (a report about a side-swipe on a signalised approach: its conflict, and so its goal, lie
    before the junction). A yellow there tests nothing, the run ending before the AV meets the line; this carries
    the AV's route, and with it the run's end, through the light: `beyond` m into the road the AV's lane leads to
    across the junction (straight on where it can, else the gentlest turn), with the AV started on its approach,
    `lead` s of driving short of the zone (as `approach_start`), at its seed speed (`speed` when it stood), no
    faster than the turn through the junction allows at `lateral_accel` m/s^2.

    The approach start must leave the AV's way to the line free: its footprint clear of every other start (any
    lane) and no entity starting in its lane between it and the line (a queue or an obstacle there would stop it
    before the line, masking the yellow). It is taken up to `slack` m further back where the first place is not
    free, else the seed's own start where that is far enough back and its way free; None where neither is, no
    traffic light faces the AV on its start road ahead of it, the route already crosses the line, or no lane
    leads on across the junction."""
    net, m, ego = ctx.network, ctx.map, ctx.starts.get("ego")
    route = ctx.ego_route
    if net is None or m is None or ego is None or not m.has_road(ego.road) or len(route) < 2:
        return None
    timing = timing or signal_timing()
    sign = m.direction(ego.road, ego.lane)
    end = route[-1]
    for sid in ctx.ego_signals:
        sig = net.signals.get(sid)
        if sig is None or not sig.is_traffic_light or str(sig.road_id) != ego.road:
            continue
        if sign * (sig.s - ego.s) <= 0.0 or end.road != ego.road or sign * (sig.s - end.s) <= 0.0:
            return None                  # past the light, or the route already crosses its line
        lanes = tuple(getattr(sig, "controlled_lanes", ()) or ())
        line = LanePos(road=ego.road, lane=int(ego.lane if not lanes or ego.lane in lanes else lanes[0]),
                       s=float(sig.s))
        exit_ = _across_junction(ctx, ego.road, ego.lane, float(sig.s), beyond)
        if exit_ is None:
            return None
        goal, connecting = exit_
        seed_v = initial_speed(ctx.root.find("Storyboard/Init/Actions/Private[@entityRef='ego']")) or 0.0
        v = seed_v if seed_v > 0.0 else float(speed)
        k = _max_curvature(ctx, [connecting])
        if lateral_accel and k >= 1e-3:
            v = min(v, math.sqrt(lateral_accel / k))
        front = footprint_extent(ctx.root.find("Entities/ScenarioObject[@name='ego']"))[1]
        need = v * (timing.yellow + timing.margin + timing.lead) + front
        for back in np.arange(need, need + slack + 1e-9, 1.0):
            new_s = float(sig.s - sign * back)
            if _way_free(ctx, ego, new_s, float(sig.s)):
                return Approach(str(sid), line, new_s, float(round(v, 3)), goal)
        if sign * (sig.s - ego.s) >= need and _way_free(ctx, ego, ego.s, float(sig.s)):
            return Approach(str(sid), line, float(ego.s), float(round(v, 3)), goal)
        return None
    return None


def _across_junction(ctx: SeedContext, road: str, lane: int, s: float, beyond: float
                     ) -> tuple[LanePos, str] | None:
    """(the position `beyond` m into the road that lane `lane` of `road` leads to across the junction at its end,
    the connecting road taken): straight on where a connection goes straight, else the one of least curvature.
    None where the lane leads into no junction."""
    net, m = ctx.network, ctx.map
    try:
        ref = net.lane_ref(road, lane, s)
        options = [c for c in net.successors(ref) if m.has_road(c.road_id) and m.in_junction(c.road_id)]
    except (KeyError, IndexError, ValueError):
        return None
    if not options:
        return None
    straight = [c for c in options if net.turn_type(ref, c) == "straight"]
    conn = (straight or sorted(options, key=lambda c: (_max_curvature(ctx, [c.road_id]), c.road_id)))[0]
    outs = [o for o in net.successors(conn) if m.has_road(o.road_id) and not m.in_junction(o.road_id)]
    if not outs:
        return None
    out = outs[0]
    length = m.road_length(out.road_id)
    d = m.direction(out.road_id, out.lane_id)
    at = min(beyond, 0.5 * length)
    return LanePos(road=str(out.road_id), lane=int(out.lane_id), s=float(round(at if d > 0 else length - at, 3))), \
        str(conn.road_id)


def _way_free(ctx: SeedContext, ego: LanePos, new_s: float, line_s: float) -> bool:
    """The AV started at `new_s` on its lane: on the road and the lane's type there, its footprint START_CLEARANCE
    m clear of every other start (any lane), and no entity starting in its lane between it and the line."""
    m = ctx.map
    if not 0.5 <= new_s <= m.road_length(ego.road) - 0.5 or \
            m.lane_type(ego.road, ego.lane, new_s) != m.lane_type(ego.road, ego.lane, ego.s):
        return False
    sign = m.direction(ego.road, ego.lane)
    if any((p.road, p.lane) == (ego.road, ego.lane) and 0.0 <= sign * (p.s - new_s) <= sign * (line_s - new_s)
           for name, p in ctx.starts.items() if name != "ego"):
        return False
    return starts_clear(ctx, "ego", ctx.root.find("Entities/ScenarioObject[@name='ego']"),
                        LanePos(ego.road, ego.lane, new_s, ego.offset))


def turn_speed(ctx: SeedContext, lateral_accel: float) -> float | None:
    """The speed (m/s) at which the AV's route through the junction beyond its start road takes its sharpest bend
    with `lateral_accel` m/s^2 of lateral acceleration: sqrt(a / k) for the largest mean curvature k over 5 m of
    the route's junction roads (None when the route crosses no junction or goes straight through it)."""
    if ctx.network is None or ctx.map is None:
        return None
    k_max = _max_curvature(ctx, [wp.road for wp in ctx.ego_route[1:]])
    if k_max < 1e-3:                 # radius over 1 km: straight on
        return None
    return math.sqrt(lateral_accel / k_max)


def _max_curvature(ctx: SeedContext, roads: list[str]) -> float:
    """The largest mean curvature (1/m) over 5 m of the junction roads among `roads` (0 for none)."""
    net, m = ctx.network, ctx.map
    k_max = 0.0
    for road in roads:
        if not m.has_road(road) or not m.in_junction(road):
            continue
        length = m.road_length(road)
        ss = np.linspace(0.0, length, max(int(length), 2) + 1)
        heading = np.unwrap([net.road_heading(road, float(x)) for x in ss])
        span = min(5.0, length)
        for a in ss:
            b = min(a + span, length)
            if b - a < span - 1e-6:
                break
            ha, hb = np.interp([a, b], ss, heading)
            k_max = max(k_max, abs(hb - ha) / (b - a))
    return k_max


#: m: the map's lights within this distance of the light facing the AV belong to its junction (a new plan sets them).
JUNCTION_RADIUS = 60.0
#: rad: a light whose heading is within this of the AV's light's (or of its opposite) is on the AV's approach or
#: the opposite one and shares its phase; the others are the crossing legs and show the conflicting state.
_AXIS = math.radians(45.0)


def new_signal(ctx: SeedContext, state: str, rec: Recorder, *, timing: SignalTiming | None = None,
               slack: float = 0.0, time_limit: float = 60.0, approach: "Approach | None" = None,
               ) -> list[etree._Element] | None:
    """TLS on a seed without a signal plan (its report named no light, yet its map has lights facing the AV): the
    parts of a new signal block (one Init `GlobalAction` per light, then the signal Story, in the timed form of
    `seed.signal_story`) for the lights of the AV's junction — the map's traffic lights within `JUNCTION_RADIUS`
    m of the first light facing the AV. The AV's approach and the opposite one show `state` and the crossing legs
    the conflicting one, phase by phase as `_schedule` says (as `tls` rewrites a seed's own plan), so a yellow can
    then wait for the dilemma zone (`dilemma_yellow`). Lights nothing sets stay `off`, which a stack passes as if
    there were none: this is what brings a light into such a seed. None when no traffic light faces the AV or the
    AV cannot reach its stop line (`stop_line`, `slack` as there) nor start back on its approach (`approach`): a
    light it never meets tests nothing."""
    net = ctx.network
    if net is None:
        return None
    facing = [sid for sid in ctx.ego_signals if sid in net.signals and net.signals[sid].is_traffic_light]
    if not facing or (stop_line(ctx, facing[0], slack=slack) is None
                      and (approach is None or approach.signal != facing[0])):
        return None
    primary = net.signals[facing[0]]
    junction = sorted(str(sid) for sid, sg in net.signals.items()
                      if sg.is_traffic_light and math.hypot(sg.x - primary.x, sg.y - primary.y) <= JUNCTION_RADIUS)
    axis = {sid for sid in junction if abs(math.cos(net.signals[sid].heading - primary.heading)) >= math.cos(_AXIS)}
    timing = timing or signal_timing()
    phases = tuple(SignalPhase(name, float(rec.db.check_value("Phase", "duration", f"{duration:g}")),
                               tuple((sid, colour if sid in axis else conflict) for sid in junction))
                   for name, duration, colour, conflict in _schedule(state, timing))
    inits, story = write_plan(SignalPlan(f"signal_ctrl_at_{primary.id}", phases), time_limit=time_limit)
    parts: list[etree._Element] = [*inits, story]
    for el in parts:
        rec.check_tree(el)
    rec.note(f"Story[@name='signal_ctrl_at_{primary.id}']", None,
             f"{len(junction)} lights, {' '.join(f'{p.name}:{p.duration:g}' for p in phases)} ({state})")
    return parts


def oim_position(ctx: SeedContext, obstacle_width: float, rng: np.random.Generator, cfg: dict[str, Any],
                 ) -> LanePos | None:
    """Context-aware obstacle position on the AV's path: a distance ahead of the ego's start drawn uniformly
    (`ahead_on_path`), with a lateral offset that keeps the obstacle inside the lane there. None without a map or
    an ego start."""
    found = ahead_on_path(ctx, uniform(rng, *cfg["ahead"]))
    if found is None:
        return None
    pos, within = found
    if within and ctx.map is not None:
        half = max(0.0, (ctx.map.lane_width(pos.road, pos.lane, pos.s) - obstacle_width) / 2.0)
        return LanePos(road=pos.road, lane=pos.lane, s=pos.s, offset=uniform(rng, -half, half))
    return pos


def ahead_on_path(ctx: SeedContext, distance: float) -> tuple[LanePos, bool] | None:
    """The lane position `distance` m ahead of the ego's start along its path (its start road, then the
    non-junction roads of its route, on the lane the ego uses there; offset 0) and True; a path shorter than that
    gives halfway along its last piece and False. None without a map or an ego start, or where no lane is."""
    m = ctx.map
    ego = ctx.starts.get("ego")
    if m is None or ego is None or not m.has_road(ego.road):
        return None
    remaining = distance
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
            return LanePos(road=road, lane=lane, s=float(s), offset=0.0), True
        remaining -= span
    # The path is shorter than the draw: halfway along the last piece.
    road, lane, s0, s1 = pieces[-1]
    return LanePos(road=road, lane=lane, s=float((s0 + s1) / 2.0), offset=0.0), False


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
