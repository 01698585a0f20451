"""Effectiveness study: does the pipeline find a planted fault, and does its analysis name the right trigger?

For each stand-in planner fault mode the same scenarios run twice, with the nominal planner and with the fault
switched on. The fault is *found* when some scenario shows the fault's category with the fault and not without it.
The lift ranking is then computed over those differential runs (a scenario counts for the category when the fault
added it), and the rank of the element the fault depends on is reported: 1 means the analysis points straight at it.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Mapping, Sequence

from ..analysis.lift import LiftRow, lift_table


@dataclass(frozen=True)
class FaultSpec:
    name: str
    category: str                   # the category the fault should cause (Table VI)
    triggers: tuple[str, ...]       # element substrings it depends on (any counts as right)
    why: str


#: Ground truth for the stand-in planner's fault modes (standin_planner/faults.py documents the mechanisms).
FAULTS: tuple[FaultSpec, ...] = (
    FaultSpec("ignore_cyclists", "Collisions", ("category:bicycle", "category:scooter"),
              "bicycles and scooters are not treated as obstacles"),
    FaultSpec("late_braking_low_friction", "Collisions", ("weather:rain", "weather:fog", "weather:snow"),
              "braking distance ignores road friction"),
    FaultSpec("no_start_when_close", "StartFail", ("position:R5", "position:R6"),
              "refuses to start with a party within a few metres ahead or behind"),
    FaultSpec("stale_tracking", "Collisions", ("position:R5", "events:ah", "events:ac", "events:h", "events:c"),
              "object states delayed: a braking lead vehicle is seen late"),
    FaultSpec("aggressive_start", "StartFail", ("weather:rain", "weather:fog", "weather:snow"),
              "high throttle and steering at start slip on low friction"),
    FaultSpec("red_light_misread", "Misinterp", ("signal:yellow",),
              "yellow read as green"),
)


@dataclass(frozen=True)
class EffectivenessRow:
    fault: str
    category: str
    found: bool
    runs_with_fault: int            # runs showing the category with the fault
    runs_nominal: int               # runs showing it with the nominal planner
    differential: int               # scenarios where only the faulty planner showed it
    top_trigger: str
    right_rank: int | None          # rank of the first right trigger in the differential lift ranking


def assess(spec: FaultSpec, nominal: Mapping[str, frozenset[str]], faulty: Mapping[str, frozenset[str]],
           elements: Mapping[str, frozenset[str]], *, min_support: int = 2) -> tuple[EffectivenessRow, list[LiftRow]]:
    """`nominal`/`faulty`: scenario id -> categories shown; `elements`: scenario id -> its scenario elements."""
    ids = sorted(set(nominal) & set(faulty) & set(elements))
    with_fault = sum(1 for i in ids if spec.category in faulty[i])
    without = sum(1 for i in ids if spec.category in nominal[i])
    diff = {i for i in ids if spec.category in faulty[i] and spec.category not in nominal[i]}
    runs = [(elements[i], frozenset({spec.category}) if i in diff else frozenset()) for i in ids]
    rows = lift_table(runs, min_support=min_support).get(spec.category, [])
    rank = next((k for k, r in enumerate(rows, 1) if any(t in r.element for t in spec.triggers)), None)
    top = f"{rows[0].element} ({rows[0].lift:.2f}×)" if rows else "–"
    return EffectivenessRow(spec.name, spec.category, bool(diff), with_fault, without, len(diff), top, rank), rows


def format_table(rows: Sequence[EffectivenessRow]) -> str:
    head = f"{'fault':<27} {'category':<11} {'found':<6} {'faulty':>6} {'nominal':>7} {'diff':>5}  " \
           f"{'top trigger':<34} {'right rank':>10}"
    out = [head, "-" * len(head)]
    for r in rows:
        out.append(f"{r.fault:<27} {r.category:<11} {'yes' if r.found else 'no':<6} {r.runs_with_fault:>6} "
                   f"{r.runs_nominal:>7} {r.differential:>5}  {r.top_trigger:<34} "
                   f"{r.right_rank if r.right_rank is not None else '–':>10}")
    return "\n".join(out)
