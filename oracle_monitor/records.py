"""Typed records the oracles produce: violations (online events) and the run verdict (after `finish`)."""

from __future__ import annotations

import enum
import json
from dataclasses import dataclass
from typing import Any

from txt2sce_ros.contract import Verdict


class Category(str, enum.Enum):
    """The paper's five behaviour categories (Table VI). The first three are mutually exclusive with everything
    else; PlanFail and Smooth may overlap (see `verdict.py`)."""

    START_FAIL = "StartFail"
    MISINTERP = "Misinterp"
    COLLISIONS = "Collisions"
    PLAN_FAIL = "PlanFail"
    SMOOTH = "Smooth"


#: The exclusive categories, in the order that breaks a tie between events at the same instant.
EXCLUSIVE = (Category.COLLISIONS, Category.MISINTERP, Category.START_FAIL)


class Rule(str, enum.Enum):
    """Which oracle rule raised a violation (finer than the category)."""

    CONTACT = "contact"                          # footprints overlap (safety)
    JERK_COLLISION = "jerk_collision"            # |jerk| > T_cj (safety, the paper's rule, reported beside)
    SMOOTH_JERK = "smooth_jerk"                  # 1 s average jerk outside I_sj
    SMOOTH_YAW_RATE = "smooth_yaw_rate"          # 1 s average yaw rate outside I_yr
    NO_START = "no_start"                        # still too long at the start with a clear path / never moved
    STOPPED_MID_ROUTE = "stopped_mid_route"      # still too long after starting, path clear, goal not reached
    PARKED_OUTSIDE_LANE = "parked_outside_lane"  # standing with part of the footprint outside the allowed lanes
    GOAL_NOT_REACHED = "goal_not_reached"        # run over (time out or end of story) with the goal not reached
    RED_LIGHT = "red_light"                      # crossed a stop line whose signal showed red
    STATIC_OBSTACLE_HIT = "static_obstacle_hit"  # contact with a static object that had been in view
    STRUCK_WHILE_STOPPED = "struck_while_stopped"  # contact while the ego stood still (reported beside)
    STRUCK_FROM_BEHIND = "struck_from_behind"    # rear-ended: the other closed from behind, in line (beside)
    OVERLAP_AT_START = "overlap_at_start"        # contact in the first frame: invalid scenario (verdict error)


@dataclass(frozen=True, slots=True)
class Violation:
    """One oracle event, raised online at its onset.

    `category` is None for events reported beside the verdict without deciding it (the jerk rule when collisions
    come from contact, and vice versa)."""

    rule: Rule
    category: Category | None
    t: float                                  # s, sim time of onset (contact time refined between frames)
    observed: float
    threshold: float
    units: str
    entities: tuple[str, ...] = ()
    detail: str = ""

    def to_dict(self) -> dict[str, Any]:
        # Field by field rather than `asdict`, whose deep copy was most of a recorded verdict's cost (tested to
        # cover every field).
        return {"rule": self.rule.value, "category": self.category.value if self.category else None, "t": self.t,
                "observed": self.observed, "threshold": self.threshold, "units": self.units,
                "entities": list(self.entities), "detail": self.detail}

    @classmethod
    def from_dict(cls, d: dict[str, Any]) -> "Violation":
        return cls(rule=Rule(d["rule"]), category=Category(d["category"]) if d.get("category") else None,
                   t=float(d["t"]), observed=float(d["observed"]), threshold=float(d["threshold"]),
                   units=str(d["units"]), entities=tuple(d.get("entities", ())), detail=str(d.get("detail", "")))


@dataclass(frozen=True, slots=True)
class Finding:
    """One category of a failed run: its first event and how many the run had."""

    category: Category
    t: float                                  # first event, s
    rule: Rule
    observed: float
    threshold: float
    units: str
    entities: tuple[str, ...]
    detail: str
    count: int

    def to_dict(self) -> dict[str, Any]:
        return {"category": self.category.value, "t": self.t, "rule": self.rule.value, "observed": self.observed,
                "threshold": self.threshold, "units": self.units, "entities": list(self.entities),
                "detail": self.detail, "count": self.count}


@dataclass(frozen=True, slots=True)
class Unavoidable:
    """Why one category of a failed run was unavoidable by the scripted parties (`unavoidable.py`)."""

    category: Category
    entity: str
    t: float                     # s, when the party meets the counterfactual ego (PlanFail: the end of the run)
    detail: str

    def to_dict(self) -> dict[str, Any]:
        return {"category": self.category.value, "entity": self.entity, "t": self.t, "detail": self.detail}


@dataclass(frozen=True, slots=True)
class RunVerdict:
    """The verdict of one run. Never mixed: `error` runs carry no categories, `pass` runs carry none either."""

    verdict: Verdict
    categories: tuple[Finding, ...] = ()
    error: str = ""                           # why the run is an error (empty otherwise)
    scenario_id: str = ""
    end_reason: str = ""
    t_end: float = 0.0
    frames: int = 0
    violations: tuple[Violation, ...] = ()    # every event, in order (including those reported beside)
    suppressed: tuple[Finding, ...] = ()      # categories that fired but are excluded by Table VI's exclusivity
    notes: tuple[str, ...] = ()
    unavoidable: tuple[Unavoidable, ...] = ()   # failed categories the scripted parties made unavoidable

    def category_names(self) -> tuple[str, ...]:
        return tuple(f.category.value for f in self.categories)

    def finding(self, category: Category) -> Finding | None:
        return next((f for f in self.categories if f.category == category), None)

    def to_dict(self) -> dict[str, Any]:
        return {
            "verdict": self.verdict.value, "categories": [f.to_dict() for f in self.categories],
            "error": self.error, "scenario_id": self.scenario_id, "end_reason": self.end_reason,
            "t_end": self.t_end, "frames": self.frames, "violations": [v.to_dict() for v in self.violations],
            "suppressed": [f.to_dict() for f in self.suppressed], "notes": list(self.notes),
            "unavoidable": [u.to_dict() for u in self.unavoidable],
        }

    def planner_relevant(self) -> bool:
        """A failure that says something about the planner: some category of it was not made unavoidable by the
        scripted parties."""
        labelled = {u.category for u in self.unavoidable}
        return self.verdict is Verdict.FAIL and any(f.category not in labelled for f in self.categories)

    def to_json(self) -> str:
        return json.dumps(self.to_dict(), sort_keys=True)

    def summary(self) -> str:
        """One line: `fail Collisions@3.42s(npc1) Smooth@1.00s` / `pass` / `error: planner not responding`."""
        if self.verdict is Verdict.ERROR:
            return f"error: {self.error}"
        if self.verdict is Verdict.PASS:
            return "pass"
        parts = []
        for f in self.categories:
            who = f"({','.join(f.entities)})" if f.entities else ""
            parts.append(f"{f.category.value}@{f.t:.2f}s{who} [{f.rule.value} {f.observed:.3g} vs {f.threshold:.3g}"
                         f" {f.units}]")
        line = "fail " + " ".join(parts)
        if self.unavoidable:
            line += " | unavoidable by scripted parties: " + ", ".join(
                f"{u.category.value} ({u.entity})" for u in self.unavoidable)
        return line
