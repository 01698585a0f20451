"""Association between scenario elements and unexpected-behaviour categories, ranked by lift.

lift(e, c) = P(c | e) / P(c): how much more often category c occurs in runs whose scenario contains element e
than in runs overall. Support (runs with both) is reported beside it, since a lift measured on three runs says
little; `min_support` filters those out of the ranking.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass
from typing import Iterable


@dataclass(frozen=True)
class LiftRow:
    category: str
    element: str
    lift: float
    support: int          # runs with the element and the category
    with_element: int     # runs with the element
    confidence: float     # P(category | element)
    base_rate: float      # P(category)


def lift_table(runs: Iterable[tuple[frozenset[str], frozenset[str]]], *, min_support: int = 3
               ) -> dict[str, list[LiftRow]]:
    """`runs`: (elements of the scenario, categories the run showed). Returns rows per category, best first
    (ties broken by support, then element name, so the ranking is deterministic)."""
    runs = list(runs)
    n = len(runs)
    if n == 0:
        return {}
    n_elem: Counter[str] = Counter()
    n_cat: Counter[str] = Counter()
    n_both: Counter[tuple[str, str]] = Counter()
    for elements, cats in runs:
        n_elem.update(elements)
        n_cat.update(cats)
        for c in cats:
            for e in elements:
                n_both[(e, c)] += 1
    table: dict[str, list[LiftRow]] = {}
    for c, nc in sorted(n_cat.items()):
        base = nc / n
        rows = []
        for e, ne in n_elem.items():
            both = n_both.get((e, c), 0)
            if both < min_support:
                continue
            conf = both / ne
            rows.append(LiftRow(c, e, conf / base, both, ne, conf, base))
        rows.sort(key=lambda r: (-r.lift, -r.support, r.element))
        table[c] = rows
    return table


def rank_of(rows: list[LiftRow], *, contains: str) -> int | None:
    """1-based rank of the first row whose element contains `contains` (None when absent)."""
    for i, row in enumerate(rows, 1):
        if contains in row.element:
            return i
    return None
