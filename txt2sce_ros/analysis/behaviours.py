"""The behaviour table (paper Table VI): count and share of each unexpected-behaviour category."""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass
from typing import Any, Iterable, Mapping

#: Table VI's categories, in its column order. StartFail, Misinterp and Collisions are exclusive; PlanFail and
#: Smooth may overlap with the others.
CATEGORIES = ("StartFail", "Misinterp", "Collisions", "PlanFail", "Smooth")


@dataclass(frozen=True)
class BehaviourRow:
    category: str
    count: int
    share_of_behaviours: float   # the paper's "Prop." (count / all unexpected behaviours)
    share_of_runs: float         # count / runs judged (pass + fail)


def behaviour_table(runs: Iterable[tuple[str, tuple[str, ...]]]) -> tuple[list[BehaviourRow], dict[str, int]]:
    """`runs`: (verdict, categories). Returns the rows and the verdict counts (errors are counted, never judged)."""
    verdicts: Counter[str] = Counter()
    cats: Counter[str] = Counter()
    for verdict, categories in runs:
        verdicts[verdict] += 1
        if verdict == "fail":
            cats.update(set(categories))
    judged = verdicts["pass"] + verdicts["fail"]
    total = sum(cats.values())
    rows = [BehaviourRow(c, cats[c], cats[c] / total if total else 0.0, cats[c] / judged if judged else 0.0)
            for c in CATEGORIES]
    return rows, dict(verdicts)


@dataclass(frozen=True)
class Attribution:
    """Which failures say something about the planner: per category, the failing runs in which the oracle labelled
    it unavoidable by the scripted parties (`oracle_monitor/unavoidable.py`), and the failing runs left with some
    category not so labelled."""

    failed: int                       # runs with verdict fail
    planner: int                      # of which some category was not made unavoidable by the scripted parties
    by_category: dict[str, int]       # category -> failing runs with it
    unavoidable: dict[str, int]       # category -> failing runs in which it was labelled unavoidable

    def line(self) -> str:
        """`329 failures: 120 unavoidable by scripted parties (every failing category labelled); labels by category:
        Collisions 10, ...; 209 say something about the planner`."""
        cats = ", ".join(f"{c} {self.unavoidable[c]}" for c in CATEGORIES if self.unavoidable.get(c))
        # A run counts as unavoidable only when every one of its failing categories is labelled; the per-category
        # labels are counted apart (a run failing Smooth, labelled, and PlanFail, not, is the planner's).
        return (f"{self.failed} failures: {self.failed - self.planner} unavoidable by scripted parties (every "
                f"failing category labelled)" + (f"; labels by category: {cats}" if cats else "")
                + f"; {self.planner} say something about the planner")


def attribution(runs: Iterable[tuple[str, tuple[str, ...], Mapping[str, Any]]]) -> Attribution:
    """`runs`: (verdict, categories, the stored record). Records written before the label existed count as labelled
    nothing (every failure then says something about the planner)."""
    failed = planner = 0
    by_cat: Counter[str] = Counter()
    unavoidable: Counter[str] = Counter()
    for verdict, categories, record in runs:
        if verdict != "fail":
            continue
        failed += 1
        labelled = {u.get("category") for u in (record.get("details") or {}).get("unavoidable", [])}
        by_cat.update(set(categories))
        unavoidable.update(set(categories) & labelled)
        if set(categories) - labelled:
            planner += 1
    return Attribution(failed, planner, dict(by_cat), dict(unavoidable))
