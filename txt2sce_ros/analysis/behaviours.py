"""The behaviour table (paper Table VI): count and share of each unexpected-behaviour category."""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass
from typing import Iterable

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
