"""Road matching (paper §III-B.2, step 1): filter the map sites by the sketch's constraints and pick one with the
caller's seeded RNG. Hard constraints filter; soft ones rank (only the best-ranked tier is drawn from), and every
soft constraint that could not be met is reported as a relaxation in the manifest."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..errors import InputError
from ..paths import BUNDLED_MAPS, cache_dir
from .constraints import JUNCTION_LAYOUTS, RoadConstraints
from .sites import JunctionSite, RoadSite, junction_sites, road_sites


@dataclass(frozen=True, slots=True)
class Match:
    site: JunctionSite | RoadSite
    candidates: int                 # sites in the drawn tier
    relaxed: tuple[str, ...]        # soft constraints not met
    # The rest of the drawn tier, in order after the pick (site, relaxed): where the plan cannot start on the pick
    # (two entities overlapping at t=0), the seed is planned on the next of these instead.
    others: tuple[tuple[JunctionSite | RoadSite, tuple[str, ...]], ...] = ()


def map_files(maps: str | Path | None = None) -> list[Path]:
    """The OpenDRIVE files to match against: `maps` (a directory or one file), else the bundled maps (rendered
    into the cache by the map-database generator when the package holds none yet)."""
    if maps:
        p = Path(maps)
        files = sorted(p.glob("*.xodr")) if p.is_dir() else [p]
        if not files:
            raise InputError("no .xodr maps found", source=str(p))
        return files
    files = sorted(BUNDLED_MAPS.glob("*.xodr"))
    if files:
        return files
    try:
        from ..mapdb.bundled import build_bundled_maps
    except ImportError as exc:  # pragma: no cover - mapdb ships with the package
        raise InputError("no bundled maps and no map generator; pass --maps DIR", source=str(BUNDLED_MAPS)) from exc
    target = cache_dir() / "bundled_maps"
    files = sorted(target.glob("*.xodr"))
    return files or sorted(build_bundled_maps(target))


def _junction_score(c: RoadConstraints, s: JunctionSite) -> tuple[int, list[str]] | None:
    if not s.ego.lanes_turning(c.ego_turn):
        return None
    for leg, _turn in c.legs:
        if leg != "exit" and leg not in s.legs:
            return None
    relaxed = []
    want_kind = c.layout if c.layout in JUNCTION_LAYOUTS else None
    if want_kind and s.kind != want_kind:
        relaxed.append(f"layout {want_kind} -> {s.kind}")
    elif not want_kind:
        relaxed.append(f"layout {c.layout} -> junction ({s.kind}) for the reported turn/positions")
        if s.kind == "roundabout":
            relaxed.append("a roundabout is the least like a driveway or mid-block turn")
    if c.control == "signal" and not s.signalised:
        relaxed.append("control signal -> unsignalised")
    if c.control == "stop_sign" and not s.ego.stop_sign:
        relaxed.append("control stop_sign -> " + ("signalised, lights off" if s.signalised else "no sign"))
    if c.control == "none" and (s.signalised or s.ego.stop_sign):
        relaxed.append("control none -> controlled junction, controls unused")
    if len(s.ego.lanes) < c.min_lanes:
        relaxed.append(f"lanes {c.min_lanes} -> {len(s.ego.lanes)}")
    for leg, turn in c.legs:
        if leg != "exit" and not s.legs[leg].lanes_turning(turn):
            relaxed.append(f"{leg} leg cannot turn {turn}")
    return len(relaxed), relaxed


def _road_score(c: RoadConstraints, s: RoadSite) -> tuple[int, list[str]] | None:
    if len(s.lanes) < c.min_lanes:
        return None
    if c.needs_oncoming and not s.oncoming:
        return None
    relaxed = []
    want = c.layout if c.layout in ("straight", "curve", "parking") else "straight"
    if s.kind != want:
        relaxed.append(f"layout {want} -> {s.kind}")
    if c.one_way is True and s.oncoming:
        relaxed.append("one_way -> two-way road")
    if c.control == "stop_sign":
        relaxed.append("control stop_sign -> none (mid-block)")
    if c.needs_shoulder and not s.curb_lanes:
        relaxed.append("no curb lane")
    # prefer the lane count the report states; with no stated count any road with enough lanes is as good.
    # Long roads rank first: they leave room for run-ups behind and goals beyond the conflict.
    extra = len(s.lanes) - c.min_lanes if c.stated_lanes else 0
    return len(relaxed) * 10 + min(extra, 3) + (1 if s.length < 180.0 else 0), relaxed


def match_site(c: RoadConstraints, rng: np.random.Generator, *, maps: str | Path | None = None,
               source: str | None = None) -> Match:
    """Pick a site for the constraints; InputError naming the report when no map fits."""
    files = map_files(maps)
    junction = c.junction or c.ego_turn != "straight"
    scored: list[tuple[int, str, JunctionSite | RoadSite, list[str]]] = []
    for f in files:
        if junction:
            for s in junction_sites(f):
                r = _junction_score(c, s)
                if r is not None:
                    scored.append((r[0], f"{f.name}:{s.junction_id}:{s.ego.road_id}", s, r[1]))
        else:
            for s in road_sites(f):
                r = _road_score(c, s)
                if r is not None:
                    scored.append((r[0], f"{f.name}:{s.road_id}:{s.lanes[0].lane_id}", s, r[1]))
    if not scored:
        raise InputError(f"no map site fits {c.describe()} among {len(files)} map(s)", source=source,
                         element="road")
    best = min(x[0] for x in scored)
    tier = sorted((x for x in scored if x[0] == best), key=lambda x: x[1])
    k = int(rng.integers(len(tier)))
    pick = tier[k]
    others = tuple((x[2], tuple(x[3])) for x in tier[k + 1:] + tier[:k])
    return Match(pick[2], len(tier), tuple(pick[3]), others)
