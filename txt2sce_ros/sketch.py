"""The report sketch (`txt2sce.sketch/1`): typed records mirroring `../shared/spec/sketch.md`.

A sketch is the contract between the text side (report -> sketch) and the scenario side (sketch -> seed). The
JSON Schema (`txt2sce_ros/data/sketch.schema.json`, a copy of the project spec so an installed package carries it)
is the authority on shape; `validate_sketch_dict` adds the cross-field rules the schema cannot say (ids numbered
in order, `collision.with` naming a party that exists, lanes only for R5-R7).

Closed vocabularies are `Literal` string types with a tuple of their values beside them: sketches travel as JSON,
and plain strings compare and serialise without conversion.
"""

from __future__ import annotations

import json
from collections.abc import Iterator
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import Any, Literal, get_args

from .errors import InputError

SCHEMA_ID = "txt2sce.sketch/1"
ERROR_SCHEMA_ID = "txt2sce.sketch-error/1"
SCHEMA_PATH = Path(__file__).resolve().parent / "data" / "sketch.schema.json"

Layout = Literal["straight", "curve", "junction4", "junction3", "roundabout", "parking", "unknown"]
Control = Literal["signal", "stop_sign", "none", "unknown"]
Weather = Literal["clear", "cloudy", "rain", "fog", "snow", "unknown"]
Lighting = Literal["day", "dusk_dawn", "night_lit", "night_dark", "unknown"]
Surface = Literal["dry", "wet", "snow_ice", "unknown"]
SignalState = Literal["green", "yellow", "red", "none", "unknown"]
Motion = Literal["moving", "stopped"]
NpcCategory = Literal["car", "van", "truck", "bus", "motorcycle", "bicycle", "scooter", "pedestrian"]
Position = Literal["R1", "R2", "R3", "R4", "R5", "R6", "R7"]
Lane = Literal["same", "left", "right"]
ObstacleCategory = Literal["parked_vehicle", "door", "debris", "cone", "barrier", "pole", "animal", "other"]
ObstaclePosition = Literal["R4", "R5", "R6", "R7"]
ObstacleLane = Literal["same", "left", "right", "shoulder"]
CollisionType = Literal["rear_end", "side_swipe", "head_on", "broadside", "hit_object", "pedestrian", "other", "none"]
#: Parties (NPCs, and obstacles, each) per sketch: no report names more than a handful; the bound keeps every
#: scenario grown from a sketch small (the player bounds entities per scenario too, config/player.yaml).
MAX_PARTIES = 32

MissingItem = Literal["npcs", "position", "actions", "road"]

LAYOUTS: tuple[str, ...] = get_args(Layout)
CONTROLS: tuple[str, ...] = get_args(Control)
WEATHERS: tuple[str, ...] = get_args(Weather)
LIGHTINGS: tuple[str, ...] = get_args(Lighting)
SURFACES: tuple[str, ...] = get_args(Surface)
SIGNAL_STATES: tuple[str, ...] = get_args(SignalState)
MOTIONS: tuple[str, ...] = get_args(Motion)
NPC_CATEGORIES: tuple[str, ...] = get_args(NpcCategory)
POSITIONS: tuple[str, ...] = get_args(Position)
LANES: tuple[str, ...] = get_args(Lane)
OBSTACLE_CATEGORIES: tuple[str, ...] = get_args(ObstacleCategory)
OBSTACLE_POSITIONS: tuple[str, ...] = get_args(ObstaclePosition)
OBSTACLE_LANES: tuple[str, ...] = get_args(ObstacleLane)
COLLISION_TYPES: tuple[str, ...] = get_args(CollisionType)
MISSING_ITEMS: tuple[str, ...] = get_args(MissingItem)

#: Positions on the AV's own road: they carry a lane (sketch.md, "Relative positions").
LANED_POSITIONS: frozenset[str] = frozenset({"R5", "R6", "R7"})

#: The 13 fine-grained actions, code -> name (names as in docs/seed_format.md event names).
ACTION_CODES: dict[str, str] = {
    "a": "go_straight",
    "b": "accelerate",
    "c": "decelerate",
    "d": "turn_left",
    "e": "turn_right",
    "f": "lane_change_left",
    "g": "lane_change_right",
    "h": "stop",
    "i": "start",
    "j": "u_turn",
    "k": "reverse",
    "l": "pull_over",
    "m": "cross",
}
ACTION_NAMES: dict[str, str] = {name: code for code, name in ACTION_CODES.items()}

#: What each action code means, in words (sketch.md, "Actions"): legends of the report and the review page.
ACTION_MEANINGS: dict[str, str] = {
    "a": "go straight", "b": "accelerate", "c": "decelerate", "d": "turn left", "e": "turn right",
    "f": "change lane to the left", "g": "change lane to the right", "h": "stop", "i": "start from standstill",
    "j": "U-turn", "k": "reverse", "l": "pull over / park", "m": "cross the AV's path",
}

#: What each relative position means, in the AV's frame (sketch.md, "Relative positions").
POSITION_MEANINGS: dict[str, str] = {
    "R1": "junction, crossing road to the AV's left",
    "R2": "junction, opposite approach facing the AV",
    "R3": "junction, crossing road to the AV's right",
    "R4": "junction, the road the AV exits onto",
    "R5": "same road and direction, ahead of or beside the AV",
    "R6": "same road and direction, behind the AV",
    "R7": "same road, oncoming",
}


def action_names(actions: str) -> list[str]:
    """The action string `"ad"` as names `["go_straight", "turn_left"]`; raises InputError on an unknown code."""
    try:
        return [ACTION_CODES[c] for c in actions]
    except KeyError as exc:
        raise InputError(f"unknown action code {exc.args[0]!r} in {actions!r}", element="actions") from exc


@dataclass(frozen=True, slots=True)
class RoadInfo:
    layout: Layout = "unknown"
    control: Control = "unknown"
    one_way: bool | None = None
    lanes: int | None = None


@dataclass(frozen=True, slots=True)
class Environment:
    weather: Weather = "unknown"
    lighting: Lighting = "unknown"
    surface: Surface = "unknown"


@dataclass(frozen=True, slots=True)
class EgoInfo:
    start: Motion = "moving"
    actions: str = ""


@dataclass(frozen=True, slots=True)
class Party:
    """Another traffic participant (`npcs[]`): vehicle, rider or pedestrian."""

    id: str
    category: NpcCategory
    position: Position
    lane: Lane | None
    start: Motion
    actions: str


@dataclass(frozen=True, slots=True)
class Obstacle:
    """A static object that took part (`obstacles[]`)."""

    id: str
    category: ObstacleCategory
    position: ObstaclePosition
    lane: ObstacleLane


@dataclass(frozen=True, slots=True)
class Collision:
    with_: str | None = None  # `with` in JSON (a Python keyword)
    type: CollisionType = "none"


@dataclass(frozen=True, slots=True)
class Sketch:
    report_id: str
    road: RoadInfo = field(default_factory=RoadInfo)
    environment: Environment = field(default_factory=Environment)
    signal_state: SignalState = "unknown"
    ego: EgoInfo = field(default_factory=EgoInfo)
    npcs: tuple[Party, ...] = ()
    obstacles: tuple[Obstacle, ...] = ()
    collision: Collision = field(default_factory=Collision)
    missing: tuple[MissingItem, ...] = ()
    #: Where each slot was read: (slot path, ((start, end), ...)) pairs in slot order; offsets index the narrative
    #: as given. Never compared (sketch.md: evidence is not scored), so two readings of a slot stay equal.
    evidence: tuple[tuple[str, tuple[tuple[int, int], ...]], ...] = field(default=(), compare=False)

    @property
    def is_buildable(self) -> bool:
        """True when the text gave all a seed needs (`missing` empty, sketch.md §V-D: refuse rather than invent)."""
        return not self.missing

    def party(self, pid: str) -> Party | Obstacle | None:
        """The NPC or obstacle with id `pid`, or None."""
        for p in (*self.npcs, *self.obstacles):
            if p.id == pid:
                return p
        return None

    def to_dict(self) -> dict[str, Any]:
        """The JSON form, keys in the spec's canonical order (so equal sketches give equal bytes)."""
        return {
            "schema": SCHEMA_ID,
            "report_id": self.report_id,
            "road": {"layout": self.road.layout, "control": self.road.control,
                     "one_way": self.road.one_way, "lanes": self.road.lanes},
            "environment": {"weather": self.environment.weather, "lighting": self.environment.lighting,
                            "surface": self.environment.surface},
            "signal_state": self.signal_state,
            "ego": {"start": self.ego.start, "actions": self.ego.actions},
            "npcs": [{"id": n.id, "category": n.category, "position": n.position, "lane": n.lane,
                      "start": n.start, "actions": n.actions} for n in self.npcs],
            "obstacles": [{"id": o.id, "category": o.category, "position": o.position, "lane": o.lane}
                          for o in self.obstacles],
            "collision": {"with": self.collision.with_, "type": self.collision.type},
            "missing": list(self.missing),
            **({"evidence": {k: [list(sp) for sp in spans] for k, spans in self.evidence}} if self.evidence else {}),
        }

    def evidence_for(self, slot: str) -> tuple[tuple[int, int], ...]:
        """The narrative spans a slot was read from (empty when the extractor recorded none)."""
        return next((spans for k, spans in self.evidence if k == slot), ())

    def to_json(self) -> str:
        """One compact JSON line (a JSONL row)."""
        return json.dumps(self.to_dict(), ensure_ascii=False)

    @classmethod
    def from_dict(cls, d: Any, *, source: str | None = None) -> Sketch:
        """Build a sketch from its JSON form; raises InputError naming the report id and the first bad field."""
        rid = d.get("report_id") if isinstance(d, dict) else None
        where = source or (str(rid) if rid else None)
        if isinstance(d, dict):
            # Bound before validating: every party becomes an entity in every scenario grown from the sketch.
            for key in ("npcs", "obstacles"):
                if isinstance(d.get(key), list) and len(d[key]) > MAX_PARTIES:
                    raise InputError(f"{len(d[key])} {key}: more parties than the limit of {MAX_PARTIES} per sketch",
                                     source=where or "sketch", element=key)
        problems = validate_sketch_dict(d)
        if problems:
            path, _, msg = problems[0].partition(": ")
            more = f" (+{len(problems) - 1} more)" if len(problems) > 1 else ""
            raise InputError(f"invalid sketch: {msg}{more}", source=where or "sketch", element=path or "$")
        r, e, g, c = d["road"], d["environment"], d["ego"], d["collision"]
        return cls(
            report_id=d["report_id"],
            road=RoadInfo(layout=r["layout"], control=r["control"], one_way=r["one_way"], lanes=r["lanes"]),
            environment=Environment(weather=e["weather"], lighting=e["lighting"], surface=e["surface"]),
            signal_state=d["signal_state"],
            ego=EgoInfo(start=g["start"], actions=g["actions"]),
            npcs=tuple(Party(id=n["id"], category=n["category"], position=n["position"], lane=n["lane"],
                             start=n["start"], actions=n["actions"]) for n in d["npcs"]),
            obstacles=tuple(Obstacle(id=o["id"], category=o["category"], position=o["position"], lane=o["lane"])
                            for o in d["obstacles"]),
            collision=Collision(with_=c["with"], type=c["type"]),
            missing=tuple(d["missing"]),
            evidence=tuple((str(k), tuple((int(a), int(b)) for a, b in v))
                           for k, v in (d.get("evidence") or {}).items()),
        )


@dataclass(frozen=True, slots=True)
class ErrorRecord:
    """One input that gave no sketch: written in its place so a batch keeps one line per report."""

    report_id: str
    error: str
    source: str | None = None

    def to_dict(self) -> dict[str, Any]:
        return {"schema": ERROR_SCHEMA_ID, "report_id": self.report_id, "source": self.source, "error": self.error}

    def to_json(self) -> str:
        return json.dumps(self.to_dict(), ensure_ascii=False)


@lru_cache(maxsize=1)
def load_schema() -> dict[str, Any]:
    """The sketch JSON Schema bundled with the package."""
    with open(SCHEMA_PATH, encoding="utf-8") as fh:
        return json.load(fh)


@lru_cache(maxsize=1)
def _validator() -> Any:
    # Imported lazily: jsonschema costs ~50 ms to import and most callers only build sketches.
    from jsonschema import Draft202012Validator

    return Draft202012Validator(load_schema())


def _path(parts: Any) -> str:
    out = ""
    for p in parts:
        out += f"[{p}]" if isinstance(p, int) else (f".{p}" if out else str(p))
    return out


def validate_sketch_dict(d: Any) -> list[str]:
    """Every problem with a sketch's JSON form, as `"<field path>: <message>"`; an empty list means valid.

    Checks the JSON Schema first, then (only on schema-valid input) the rules sketch.md states in prose:
    ids `npc1..n` / `obs1..n` in order, `collision.with` naming an existing party, `lane` null exactly for R1-R4,
    `type: none` exactly when `with` is null and there was no contact.
    """
    errs = sorted(_validator().iter_errors(d), key=lambda e: list(map(str, e.absolute_path)))
    if errs:
        return [f"{_path(e.absolute_path)}: {e.message}" for e in errs]
    out: list[str] = []
    for i, n in enumerate(d["npcs"]):
        if n["id"] != f"npc{i + 1}":
            out.append(f"npcs[{i}].id: expected npc{i + 1} (numbered in order), got {n['id']}")
        if n["position"] in LANED_POSITIONS and n["lane"] is None:
            out.append(f"npcs[{i}].lane: required for {n['position']}")
        if n["position"] not in LANED_POSITIONS and n["lane"] is not None:
            out.append(f"npcs[{i}].lane: must be null for {n['position']}")
    for i, o in enumerate(d["obstacles"]):
        if o["id"] != f"obs{i + 1}":
            out.append(f"obstacles[{i}].id: expected obs{i + 1} (numbered in order), got {o['id']}")
    ids = {n["id"] for n in d["npcs"]} | {o["id"] for o in d["obstacles"]}
    w = d["collision"]["with"]
    if w is not None and w not in ids:
        out.append(f"collision.with: {w} names no npc or obstacle")
    if w is not None and d["collision"]["type"] == "none":
        out.append("collision.type: 'none' but collision.with names a party")
    return out


def iter_jsonl(path: str | Path) -> Iterator[tuple[int, Any | InputError]]:
    """(line number, parsed object or InputError) for each non-blank line of a JSON Lines file.

    The file is read as bytes and each line decoded on its own, so one row with a byte that is not UTF-8 becomes
    an InputError for that row and the rows before and after it are still read."""
    p = Path(path)
    try:
        fh = open(p, "rb")
    except OSError as exc:
        raise InputError(f"cannot read: {exc.strerror}", source=str(p)) from exc
    with fh:
        for lineno, raw in enumerate(fh, 1):
            try:
                line = raw.decode("utf-8")
            except UnicodeDecodeError as exc:
                yield lineno, InputError(f"not UTF-8 (byte 0x{raw[exc.start]:02x} at column {exc.start + 1})",
                                         source=str(p), line=lineno)
                continue
            if not line.strip():
                continue
            try:
                yield lineno, json.loads(line)
            except json.JSONDecodeError as exc:
                yield lineno, InputError(f"invalid JSON: {exc.msg}", source=str(p), line=lineno)
            except RecursionError:
                yield lineno, InputError("invalid JSON: nested too deeply", source=str(p), line=lineno)


def load_sketches(path: str | Path) -> Iterator[Sketch | ErrorRecord]:
    """Each line of a sketch JSONL file (e.g. dev_gold.jsonl) as a Sketch, or an ErrorRecord for a bad line.

    Error-record lines written by `txt2sce extract` come back as ErrorRecords too, so a predictions file
    round-trips.
    """
    for lineno, obj in iter_jsonl(path):
        src = f"{path}:{lineno}"
        if isinstance(obj, InputError):
            yield ErrorRecord(report_id=f"line{lineno}", error=str(obj), source=src)
            continue
        rid = str(obj.get("report_id") or f"line{lineno}") if isinstance(obj, dict) else f"line{lineno}"
        if isinstance(obj, dict) and obj.get("schema") == ERROR_SCHEMA_ID:
            yield ErrorRecord(report_id=rid, error=str(obj.get("error", "")), source=obj.get("source"))
            continue
        try:
            yield Sketch.from_dict(obj, source=f"{src} ({rid})")
        except InputError as exc:
            yield ErrorRecord(report_id=rid, error=str(exc), source=src)
