"""Sketch -> OpenSCENARIO seed: constraints, road matching, placement and timing, writing, validation.

    from txt2sce_ros.seed import generate_seed, write_seeds
    result = generate_seed(sketch, seed=0)               # SeedResult (xosc bytes, plan, manifest); InputError
                                                         # naming the report when it cannot be built
    summary = write_seeds(sketches, "out/", seed=0)      # <report_id>.xosc + maps/ + manifest.json

The same sketch, seed and maps give the same bytes: the only randomness is the site pick, drawn from a numpy
Generator seeded with (seed, crc32(report_id)), so a sketch's seed does not depend on its neighbours in the batch.
"""

from __future__ import annotations

import json
import math
import shutil
import zlib
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Callable, Iterable

import numpy as np

from ..errors import InputError, Txt2SceError
from ..sketch import ErrorRecord, Sketch
from ..xosc.validate import validate_xosc
from .actor import Actor
from .constraints import derive_constraints
from .defaults import SeedDefaults, seed_defaults
from .match import Match, match_site
from .model import EntityPlan, EnvironmentPlan, ScenarioPlan, SignalPhase, SignalPlan
from .plan import Planner, predicted_gap
from .sites import JunctionSite
from .writer import write_xosc

MANIFEST_SCHEMA = "txt2sce.seed-manifest/1"
MAPS_SUBDIR = "maps"


@dataclass(frozen=True, slots=True)
class SeedResult:
    report_id: str
    xosc: bytes
    plan: ScenarioPlan
    map_path: Path                  # the OpenDRIVE file on disk
    manifest: dict                  # one manifest entry (JSON-ready)


def rng_for(report_id: str, seed: int) -> np.random.Generator:
    return np.random.default_rng([int(seed), zlib.crc32(report_id.encode("utf-8"))])


def environment_plan(sketch: Sketch, D: SeedDefaults) -> EnvironmentPlan:
    env = D.raw["environment"]
    light = sketch.environment.lighting
    cloud, ptype, pint, vis = env["weather"][sketch.environment.weather]
    sun_i, sun_e = env["sun"][light]
    return EnvironmentPlan(
        date_time=env["time_of_day"][light], cloud_state=cloud, sun_intensity=float(sun_i),
        sun_elevation=float(sun_e), sun_azimuth=math.pi, precipitation=ptype, precipitation_intensity=float(pint),
        visual_range=float(vis), friction=float(env["friction"][sketch.environment.surface]))


def signal_plan(sketch: Sketch, site: JunctionSite, D: SeedDefaults, ego_first_action: float,
                time_limit: float | None = None) -> SignalPlan | None:
    """Controller for the junction's lights: the AV's approach (and the opposite one) show the reported state when
    the AV's first action begins; the crossing legs show the conflicting state. `unknown` counts as green. A red
    turns green after the AV's first action (it moved off) or else after the conflict (signal_phase_before s
    later)."""
    if not site.signalised or sketch.road.control != "signal":
        return None
    axis = set(site.ego.signals) | (set(site.legs["opposite"].signals) if "opposite" in site.legs else set())
    cross = set()
    for leg in ("left", "right"):
        if leg in site.legs:
            cross |= set(site.legs[leg].signals)
    if not axis:
        return None
    limit = time_limit or D.timing.time_limit

    def phase(name: str, dur: float, ego_state: str) -> SignalPhase:
        other = "red" if ego_state in ("green", "yellow") else "green"
        states = tuple(sorted([(s, ego_state) for s in axis] + [(s, other) for s in cross]))
        return SignalPhase(name, round(dur, 3), states)

    state = sketch.signal_state if sketch.signal_state in ("green", "yellow", "red") else "green"
    moves_off = sketch.ego.actions[:1] == "i" or sketch.ego.start == "stopped" and "i" in sketch.ego.actions
    if state == "green":
        phases = (phase("phase_green", limit, "green"),)
    elif state == "yellow":
        phases = (phase("phase_yellow", 3.0, "yellow"), phase("phase_red", limit, "red"))
    elif moves_off:
        # "an AV stopped at a red light that moves off on green has red": green at its first action
        phases = (phase("phase_red", max(ego_first_action, 0.5), "red"), phase("phase_green", limit, "green"))
    else:
        # held at red: red over the reported conflict, then green, so that a planner standing at the line (behind
        # it, where it belongs) can still reach its goal beyond the junction
        hold = D.timing.time_to_conflict + D.timing.signal_phase_before
        phases = (phase("phase_red", hold, "red"), phase("phase_green", limit, "green"))
    return SignalPlan(f"signal_ctrl_{site.junction_id}", phases)


def generate_seed(sketch: Sketch, *, seed: int = 0, maps: str | Path | None = None,
                  map_ref: str | Callable[[Path], str] | None = None,
                  defaults: SeedDefaults | None = None) -> SeedResult:
    """Build one seed. `map_ref` is the LogicFile path written into the scenario (default: the map's absolute
    path), or a function of the matched map's path that gives it (`write_seeds` writes `maps/<file>` beside the
    seed, and learns the map only from the match)."""
    if sketch.missing:
        raise InputError(f"sketch lacks {', '.join(sketch.missing)}: no seed is built from missing facts",
                         source=sketch.report_id, element="missing")
    if sketch.road.layout == "unknown":
        raise InputError("road layout unknown", source=sketch.report_id, element="road.layout")
    D = defaults or seed_defaults()
    constraints = derive_constraints(sketch)
    rng = rng_for(sketch.report_id, seed)
    match, planner, actors = _plan(sketch, match_site(constraints, rng, maps=maps, source=sketch.report_id), D)
    map_path = Path(match.site.map_path)
    ref = str(map_path.resolve()) if map_ref is None else map_ref(map_path) if callable(map_ref) else map_ref
    ego_first = planner.ego.events[0].planned_time if planner.ego.events else 0.0
    signals = ()
    if isinstance(match.site, JunctionSite):
        sp = signal_plan(sketch, match.site, D, ego_first, planner.time_limit)
        signals = (sp,) if sp else ()
    choices = dict(planner.choices)
    choices["constraints"] = constraints.describe()
    choices["relaxed"] = list(match.relaxed)
    choices["candidates"] = match.candidates
    target = fidelity_target(sketch)
    if target and any(a.name == target for a in actors):
        gap, when = predicted_gap(actors, target, planner.time_limit)
        choices["predicted"] = {"party": target, "min_gap_m": round(gap, 2), "at_s": round(when, 2)}
    # entities in the sketch's order (ego, npc1…, obs1…): stable names and positions for the tree's blocks
    rank = {name: k for k, name in enumerate(["ego"] + [n.id for n in sketch.npcs] + [o.id for o in sketch.obstacles])}
    ordered = sorted(actors, key=lambda a: rank.get(a.name, len(rank)))
    plan = ScenarioPlan(
        report_id=sketch.report_id, map_ref=ref, entities=tuple(_with_position(a.freeze(), sketch) for a in ordered),
        environment=environment_plan(sketch, D), goal=planner.goal, goal_tolerance=D.timing.goal_tolerance,
        time_limit=planner.time_limit, signals=signals, choices=choices)
    xosc = write_xosc(plan, performance=(D.max_acceleration, D.max_deceleration, D.max_speed))
    errors = validate_xosc(xosc, source=sketch.report_id)
    if errors:  # a bug in the writer, never a user error: refuse loudly rather than ship an invalid seed
        raise InputError(f"generated seed is not XSD-valid: {errors[0]}", source=sketch.report_id, element="xosc")
    manifest = {
        "report_id": sketch.report_id, "seed": int(seed), "map": map_path.name, "map_ref": ref,
        "fidelity_target": target,
        "road_match": match.site.describe(), "choices": _jsonable(choices),
        "entities": [{"name": e.name, "category": e.category, "kind": e.kind, "speed": e.speed,
                      "events": [{"name": ev.name, "trigger": ev.trigger.kind, "value": ev.trigger.value,
                                  "planned_time": ev.planned_time} for ev in e.events]}
                     for e in plan.entities],
        "signals": [{"name": s.name, "phases": [[p.name, p.duration] for p in s.phases]} for s in signals],
    }
    return SeedResult(sketch.report_id, xosc, plan, map_path, manifest)


def _plan(sketch: Sketch, match: Match, D: SeedDefaults) -> tuple[Match, Planner, list[Actor]]:
    """Plan the sketch on the drawn site. Where two entities would still overlap at t=0 there (the start
    separation found no shift: a scenario that starts in a collision is invalid, every run of it ends in error),
    plan on the next site of the same tier instead; refuse the sketch when no site of the tier holds the plan."""
    overlaps: list[str] = []
    for k, (site, relaxed) in enumerate(((match.site, match.relaxed),) + match.others):
        planner = Planner(sketch, site, D)
        try:
            actors = planner.plan()
        except Txt2SceError:
            raise
        except (ValueError, IndexError, KeyError) as exc:  # geometry that does not fit: a refused sketch, not a crash
            if k == 0:
                raise InputError(f"cannot place the sketch on {Path(site.map_path).name}: {exc!r}",
                                 source=sketch.report_id, element="road") from exc
            continue                                       # a fallback site that does not fit: try the next
        overlap = planner.choices.get("start_overlap")
        if not overlap:
            if overlaps:
                planner.choices["site_fallback"] = {"tried": k, "why": "entities overlapping at t=0 on "
                                                    + "; ".join(overlaps)}
            return Match(site, match.candidates, relaxed), planner, actors
        overlaps.append(f"{Path(site.map_path).name} ({', '.join(overlap)})")
    raise InputError(f"no site of the matched tier ({match.candidates}) lets the entities start apart: they overlap "
                     f"at t=0 on {'; '.join(overlaps)}", source=sketch.report_id, element="road")


def _with_position(e: EntityPlan, sketch: Sketch) -> EntityPlan:
    """The entity with the sketch's relative position (and lane) of the party or obstacle it realises."""
    src = {p.id: (p.position, p.lane) for p in sketch.npcs} | {o.id: (o.position, o.lane) for o in sketch.obstacles}
    if e.name not in src:
        return e
    position, lane = src[e.name]
    return replace(e, position=position, lane=lane)


def fidelity_target(sketch: Sketch) -> str | None:
    """The party a faithful seed brings into conflict with the AV: the one it touched, else (a no-contact report)
    the first party named."""
    if sketch.collision.with_:
        return sketch.collision.with_
    if sketch.npcs:
        return sketch.npcs[0].id
    return sketch.obstacles[0].id if sketch.obstacles else None


def _jsonable(x):
    if isinstance(x, dict):
        return {str(k): _jsonable(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_jsonable(v) for v in x]
    if isinstance(x, float):
        return round(x, 3) if math.isfinite(x) else None
    if isinstance(x, (np.floating, np.integer)):
        return _jsonable(x.item())
    return x


def safe_file_name(report_id: str) -> str:
    return "".join(c if c.isalnum() or c in "-_." else "_" for c in report_id)


def _local_map_ref(map_path: Path) -> str:
    """The LogicFile reference of a seed `write_seeds` writes: the map's copy in `maps/` beside it."""
    return f"{MAPS_SUBDIR}/{map_path.name}"


def write_seeds(items: Iterable[Sketch | ErrorRecord], out_dir: str | Path, *, seed: int = 0,
                maps: str | Path | None = None) -> dict:
    """Write `<report_id>.xosc` per buildable sketch into `out_dir`, the maps they use into `out_dir/maps/`, and
    `manifest.json` (built seeds and refused sketches with the reason). Returns the manifest."""
    out = Path(out_dir)
    (out / MAPS_SUBDIR).mkdir(parents=True, exist_ok=True)
    built, refused = [], []
    files: dict[str, str] = {}            # seed file name -> report id written there
    for item in items:
        if isinstance(item, ErrorRecord):
            refused.append({"report_id": item.report_id, "error": item.error})
            continue
        name = f"{safe_file_name(item.report_id)}.xosc"
        if name in files:
            # Never overwrite a seed written in this batch: the second sketch of an id is refused, with the reason.
            refused.append({"report_id": item.report_id,
                            "error": f"duplicate report_id (seed {name} already "
                                     f"written from report {files[name]!r})"})
            continue
        try:
            # the relative reference to the map's copy beside the seed, so the output directory is self-contained
            res = generate_seed(item, seed=seed, maps=maps, map_ref=_local_map_ref)
        except Txt2SceError as exc:
            refused.append({"report_id": item.report_id, "error": str(exc)})
            continue
        local_map = out / MAPS_SUBDIR / res.map_path.name
        if not local_map.exists() or local_map.read_bytes() != res.map_path.read_bytes():
            shutil.copyfile(res.map_path, local_map)
        files[name] = item.report_id
        (out / name).write_bytes(res.xosc)
        entry = dict(res.manifest)
        entry["file"] = name
        built.append(entry)
    manifest = {"schema": MANIFEST_SCHEMA, "seed": int(seed), "built": built, "refused": refused}
    (out / "manifest.json").write_text(json.dumps(manifest, indent=1, sort_keys=True) + "\n", encoding="utf-8")
    return manifest
