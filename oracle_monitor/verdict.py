"""From a run's violations and its end status to one verdict: pass, fail (with categories) or error — never mixed.

Rules (paper §IV RQ2, Table VI: "only the last two behaviour types may overlap, while others are mutually
exclusive"):
- error: the scenario placed the ego overlapping another entity in the first frame (`overlap_at_start`): an
  invalid scenario, not a collision of the system under test.
- error: the run itself broke (the player reports `verdict_hint: error`, e.g. planner not responding or an invalid
  scenario), or no frame was observed. "Nothing observed" is never a pass.
- a run that never reported its end (killed, recording cut short) is a fail if a category fired in the part
  observed (that misbehaviour happened whatever came next), else an error — never a pass.
- StartFail, Misinterp and Collisions exclude every other category: when one of them fired, the run gets exactly
  one — the one whose first event came first (a red light run at 5 s that ends in a crash at 6 s is Misinterp:
  the earliest misbehaviour is the cause). Ties break in the order Collisions, Misinterp, StartFail.
- Otherwise PlanFail and Smooth, either or both.
- Struck (`struck_while_stopped`, `struck_from_behind`, reported beside): when the player ended the run on that
  contact (end reason `collision`, no contact of the ego's own), the goal was not reached because the run was cut
  short, not because the ego failed to plan: that goal-not-reached event is kept in `violations` but decides no
  category.
Categories that fired but are excluded stay visible in `RunVerdict.suppressed`; every event in `violations`.
"""

from __future__ import annotations

from collections import defaultdict
from typing import Iterable

from txt2sce_ros.contract import RunStatus, Verdict

from .records import EXCLUSIVE, Category, Finding, Rule, RunVerdict, Violation

#: end reasons that mean the harness, not the system under test, ended the run
ERROR_END_REASONS = frozenset({"planner_not_responding", "invalid_scenario", "simulation_fault", "player_error",
                               "aborted"})


def error_reason(status: RunStatus | None, frames: int) -> str:
    """Why this run is an error, or '' when it can be judged."""
    # The player's own account of a broken run (an invalid scenario has no frames) comes first.
    if status is not None and (status.verdict_hint == "error" or status.end_reason in ERROR_END_REASONS):
        return f"run broke: {status.end_reason or 'player reported an error'}"
    if frames == 0:
        return "nothing observed: no frame of the run was received"
    if status is None:
        return "the run never reported its end (no final run status): recording incomplete"
    if status.state != "finished":
        return f"the run did not finish (last status {status.state!r})"
    return ""


def overlap_reason(violations: Iterable[Violation]) -> str:
    """'invalid scenario: …' when the ego overlapped another entity in the first frame, else ''."""
    names = [n for v in violations if v.rule is Rule.OVERLAP_AT_START for n in v.entities]
    if not names:
        return ""
    return f"invalid scenario: entities overlap at start (ego and {', '.join(names)})"


def findings(violations: Iterable[Violation]) -> dict[Category, Finding]:
    by_cat: dict[Category, list[Violation]] = defaultdict(list)
    for v in violations:
        if v.category is not None:
            by_cat[v.category].append(v)
    out = {}
    for cat, events in by_cat.items():
        first = min(events, key=lambda v: v.t)
        entities = tuple(dict.fromkeys(e for v in events for e in v.entities))
        out[cat] = Finding(cat, first.t, first.rule, first.observed, first.threshold, first.units, entities,
                           first.detail, len(events))
    return out


def _judged(violations: tuple[Violation, ...], status: RunStatus | None) -> tuple[Violation, ...]:
    """The violations that decide categories: all of them, less a goal not reached because the run ended on the
    ego being struck (standing still, or rear-ended)."""
    if status is None or status.end_reason != "collision":
        return violations
    rules = {v.rule for v in violations}
    struck = any(v.rule in (Rule.STRUCK_WHILE_STOPPED, Rule.STRUCK_FROM_BEHIND) for v in violations)
    if not struck or rules & {Rule.CONTACT, Rule.STATIC_OBSTACLE_HIT}:
        return violations
    return tuple(v for v in violations if v.rule is not Rule.GOAL_NOT_REACHED)


def decide(violations: tuple[Violation, ...], status: RunStatus | None, *, frames: int, t_end: float,
           scenario_id: str = "", notes: tuple[str, ...] = ()) -> RunVerdict:
    common = dict(scenario_id=scenario_id or (status.scenario_id if status else ""),
                  end_reason=status.end_reason if status else "", t_end=t_end, frames=frames,
                  violations=violations, notes=notes)
    # An overlap at start names the cause more precisely than the player's end reason ("collision" at step 1).
    overlap = overlap_reason(violations)
    why = overlap or error_reason(status, frames)
    judged = _judged(violations, status)
    found = findings(judged)
    if len(judged) < len(violations):
        notes = notes + ("the run ended when the ego was struck (standing still or rear-ended): goal not reached "
                         "not judged",)
        common["notes"] = notes
    incomplete = status is None and frames > 0
    if why and (overlap or not (incomplete and found)):
        return RunVerdict(Verdict.ERROR, error=why, **common)
    if incomplete:
        # Cut short (crash, kill, damaged recording) after a misbehaviour: that failure is certain whatever
        # came next, so the verdict is fail for the part observed. Without one it stays an error.
        common["notes"] = ("run incomplete (no final run status): judged on the part observed",) + notes
    exclusive = [found[c] for c in EXCLUSIVE if c in found]
    if exclusive:
        # min() keeps the first of equal times, and EXCLUSIVE lists the tie order.
        chosen = min(exclusive, key=lambda f: f.t)
        kept = (chosen,)
    else:
        kept = tuple(found[c] for c in (Category.PLAN_FAIL, Category.SMOOTH) if c in found)
    suppressed = tuple(f for c, f in sorted(found.items(), key=lambda kv: kv[1].t) if f not in kept)
    if not kept:
        return RunVerdict(Verdict.PASS, **common)
    return RunVerdict(Verdict.FAIL, categories=kept, suppressed=suppressed, **common)
