"""The structured fields companies file beside the narrative (OL 316 check boxes, NHTSA SGO fields).

Two uses: an OL 316 PDF's boxes fill sketch fields the narrative leaves `unknown` (sketch.md allows it for
environment), and `txt2sce eval-extract --form-labels` reports how often the extractor agrees with the filed labels.
The companies fill these inconsistently (a rear-end marked head-on), so agreement is a noisy second opinion, never
accuracy.
"""

from __future__ import annotations

import json
import re
from collections.abc import Iterable
from dataclasses import dataclass, field, replace
from pathlib import Path

from ..sketch import Environment, Sketch
from .pdf import FormFields

WEATHER = {"clear": "clear", "cloudy": "cloudy", "raining": "rain", "rain": "rain", "snowing": "snow",
           "snow": "snow", "fog/visibility": "fog", "fog": "fog", "fog, smog, smoke": "fog"}
LIGHTING = {"daylight": "day", "dusk-dawn": "dusk_dawn", "dawn or dusk": "dusk_dawn",
            "dark-street lights": "night_lit", "dark - lighted": "night_lit",
            "dark-no street lights": "night_dark", "dark - not lighted": "night_dark",
            "dark-street lights not functioning": "night_dark"}
SURFACE = {"dry": "dry", "wet": "wet", "snowy-icy": "snow_ice", "snow": "snow_ice", "ice": "snow_ice",
           "slippery (muddy, oily, etc.)": "wet"}
COLLISION = {"head-on": "head_on", "side swipe": "side_swipe", "rear end": "rear_end", "broadside": "broadside",
             "hit object": "hit_object", "vehicle/pedestrian": "pedestrian", "overturned": "other",
             "other*": "other", "other": "other"}
#: Movement preceding collision -> action codes that show it (any of them).
MOVEMENT = {"making left turn": "d", "making right turn": "e", "backing": "k", "changing lanes": "fg",
            "merging": "fg", "slowing/stopping": "ch", "proceeding straight": "a", "making u turn": "j",
            "making u-turn": "j", "parking maneuver": "lk", "entering traffic": "mi", "passing other vehicle": "afg",
            "passing": "afg", "crossing into opposing lane": "fg", "traveling wrong way": "a",
            "other unsafe turning": "de", "ran off road": "fg", "turning left": "d", "turning right": "e"}
_STATIC = ("stopped", "parked")
#: SGO "Crash With" / OL 316 vehicle 2 -> party category ("object" for fixed objects and animals).
_CRASH_WITH = (("pedestrian", "pedestrian"), ("cyclist", "bicycle"), ("bicycl", "bicycle"), ("scooter", "scooter"),
               ("motorcycl", "motorcycle"), ("moped", "motorcycle"), ("bus", "bus"), ("heavy truck", "truck"),
               ("pickup", "car"), ("truck", "truck"), ("van", "van"), ("fixed object", "object"), ("animal", "object"),
               ("object", "object"), ("suv", "car"), ("pickup", "car"), ("car", "car"), ("vehicle", "car"))


def _first(values: Iterable[str], table: dict[str, str]) -> str | None:
    for v in values:
        hit = table.get(v.strip().lower())
        if hit:
            return hit
    return None


def form_sketch_fields(form: FormFields) -> dict[str, str | None]:
    """The form's own reading in the sketch vocabulary: environment, collision type (VEH 1's column, else VEH 2's:
    companies tick it per vehicle and often only for one) and the AV's start (the movement table, else section 2's
    "Vehicle was" box). None where the form leaves it blank."""
    ctype = _first(form.get("type_of_collision"), COLLISION) or _first(form.get("type_of_collision", 2), COLLISION)
    moves = [m.lower() for m in form.get("movement_preceding_collision")]
    was = form.get("vehicle_was")
    start: str | None = None
    if moves:
        start = "stopped" if all(m in _STATIC for m in moves) else "moving"
    elif was:
        start = "stopped" if was == ("stopped in traffic",) else "moving"
    return {"weather": _first(form.get("weather"), WEATHER), "lighting": _first(form.get("lighting"), LIGHTING),
            "surface": _first(form.get("roadway_surface"), SURFACE), "collision_type": ctype, "ego_start": start}


def merge_form(sketch: Sketch, form: FormFields | None) -> Sketch:
    """Fill the environment fields the narrative left `unknown` from the form's boxes (the narrative wins where it
    speaks), and a collision type the text could not tell."""
    if form is None:
        return sketch
    env = sketch.environment
    boxes = form_sketch_fields(form)
    new_env = Environment(
        weather=env.weather if env.weather != "unknown" else (boxes["weather"] or "unknown"),
        lighting=env.lighting if env.lighting != "unknown" else (boxes["lighting"] or "unknown"),
        surface=env.surface if env.surface != "unknown" else (boxes["surface"] or "unknown"),
    )  # type: ignore[arg-type]
    out = replace(sketch, environment=new_env)
    ctype = boxes["collision_type"]
    if ctype and sketch.collision.with_ is not None and sketch.collision.type == "other":
        out = replace(out, collision=replace(sketch.collision, type=ctype))  # type: ignore[arg-type]
    return out


def form_disagreements(sketch: Sketch, form: FormFields) -> list[str]:
    """Where the narrative's reading (the sketch before the boxes were merged) and the form's boxes differ; the
    narrative decides, these notes say so."""
    boxes = form_sketch_fields(form)
    told = {"weather": sketch.environment.weather, "lighting": sketch.environment.lighting,
            "surface": sketch.environment.surface, "collision_type": sketch.collision.type,
            "ego_start": sketch.ego.start}
    notes = []
    for key, said in told.items():
        ticked = boxes[key]
        if ticked and said not in ("unknown", "none", "other") and ticked != said:
            notes.append(f"{key}: the form ticks {ticked}, the narrative reads {said}; the narrative's reading is kept")
    return notes


@dataclass
class Agreement:
    agree: int = 0
    total: int = 0
    disagreements: list[tuple[str, str, str]] = field(default_factory=list)  # (form, predicted, report id)

    def add(self, ok: bool, form: str, pred: str, rid: str) -> None:
        self.total += 1
        self.agree += ok
        if not ok:
            self.disagreements.append((form, pred, rid))


def _party_category_from_form(row: dict) -> str | None:
    if "ol316" in row:
        o = row["ol316"]
        involved = [x.lower() for x in o.get("involved_in_accident_v1", []) + o.get("involved_in_accident_v2", [])]
        if "pedestrian" in involved:
            return "pedestrian"
        if "bicyclist" in involved:
            return "bicycle"
        model = (o.get("vehicle_2_model") or "").lower()
        if not model or model in ("n/a", "na", "none", "-"):
            return None
        return next((cat for key, cat in _CRASH_WITH if key in model), "car")
    crash = (row.get("sgo", {}).get("Crash With") or "").lower()
    if not crash:
        return None
    return next((cat for key, cat in _CRASH_WITH if key in crash), None)


def _movements(row: dict) -> tuple[list[str], list[str]]:
    if "ol316" in row:
        o = row["ol316"]
        return ([m.lower() for m in (o.get("vehicle_1_av") or {}).get("movement_preceding_collision", [])],
                [m.lower() for m in (o.get("vehicle_2_other") or {}).get("movement_preceding_collision", [])])
    s = row.get("sgo", {})
    return ([str(s.get("SV Pre-Crash Movement", "")).lower()], [str(s.get("CP Pre-Crash Movement", "")).lower()])


def _movement_ok(moves: list[str], start: str, actions: str) -> tuple[bool, str] | None:
    """Does the action string show the filed movement? None when the form's movement tells nothing checkable."""
    for mv in moves:
        mv = re.sub(r"\s+", " ", mv.strip())
        if mv in _STATIC:
            # The movement just before the contact: a party that came to a stop ("ah") or pulled over ("al")
            # before it was struck was stopped or parked then.
            return (start == "stopped" or actions in ("", "k") or actions.endswith(("h", "l"))), mv
        codes = MOVEMENT.get(mv)
        if codes:
            return any(c in actions for c in codes), mv
    return None


_REAR_AREAS = frozenset({"rear", "rear left", "rear right"})
_FRONT_AREAS = frozenset({"front", "front left", "front right"})


def _av_struck_end(row: dict) -> str | None:
    """'rear' or 'front' when the SGO form's AV ("SV") contact areas all lie at that end of the AV, else None."""
    areas = {a.strip().lower() for a in row.get("sgo", {}).get("SV Contact Area", []) or []}
    if areas and areas <= _REAR_AREAS:
        return "rear"
    if areas and areas <= _FRONT_AREAS:
        return "front"
    return None


def form_agreement(rows: Iterable[dict], predicted: dict[str, Sketch]) -> dict[str, Agreement]:
    """Agreement of predicted sketches with the filed labels: collision type, the other party's category, the
    movement preceding the collision (AV and other party) shown in the action strings, and, where an SGO form puts
    every contact on the AV at its rear (or its front), whether the party the AV touched is placed behind it (R6)
    (or not behind it)."""
    out = {k: Agreement() for k in ("collision_type", "party_category", "av_movement", "party_movement",
                                    "party_front_rear")}
    for row in rows:
        rid = row.get("id", "")
        p = predicted.get(rid)
        if p is None:
            continue
        if "ol316" in row:
            form_type = _first((row["ol316"].get("vehicle_1_av") or {}).get("type_of_collision", []), COLLISION)
            if form_type:
                out["collision_type"].add(form_type == p.collision.type, form_type, p.collision.type, rid)
        partner = p.party(p.collision.with_) if p.collision.with_ else None
        pcat = getattr(partner, "category", None)
        if pcat in ("parked_vehicle", "door"):
            pred_cat = "car"  # the form files a parked car (or the car whose door opened) as vehicle 2
        elif p.collision.with_ and p.collision.with_.startswith("obs"):
            pred_cat = "object"
        else:
            pred_cat = pcat or "-"
        form_cat = _party_category_from_form(row)
        if form_cat:
            out["party_category"].add(form_cat == pred_cat, form_cat, pred_cat, rid)
        end = _av_struck_end(row)
        pos = getattr(partner, "position", None)
        if end and pos:
            behind = pos == "R6"
            out["party_front_rear"].add(behind == (end == "rear"), f"AV {end}", pos, rid)
        av_moves, other_moves = _movements(row)
        r = _movement_ok(av_moves, p.ego.start, p.ego.actions)
        if r is not None:
            out["av_movement"].add(r[0], r[1], f"{p.ego.start}/{p.ego.actions or '-'}", rid)
        if partner is not None and hasattr(partner, "actions"):
            r = _movement_ok(other_moves, partner.start, partner.actions)  # type: ignore[union-attr]
            if r is not None:
                out["party_movement"].add(r[0], r[1], f"{partner.start}/{partner.actions or '-'}", rid)  # type: ignore
    return out


def load_form_labels(path: str | Path) -> list[dict]:
    with open(path, encoding="utf-8") as fh:
        return [json.loads(line) for line in fh if line.strip()]


def format_agreement(ag: dict[str, Agreement], *, examples: int = 3) -> str:
    lines = ["Agreement with company-filed form labels (noisy second opinion, not accuracy)", "",
             f"{'item':<18}{'agree':>8}{'count':>8}{'total':>7}", "-" * 41]
    for name, a in ag.items():
        pct = f"{a.agree / a.total:.1%}" if a.total else "n/a"
        lines.append(f"{name:<18}{pct:>8}{a.agree:>8}{a.total:>7}")
    for name, a in ag.items():
        if a.disagreements:
            from collections import Counter

            top = Counter((f, p) for f, p, _ in a.disagreements).most_common(examples)
            lines.append(f"  {name}: " + "; ".join(f"form {f} vs {p} x{k}" for (f, p), k in top))
    return "\n".join(lines)
