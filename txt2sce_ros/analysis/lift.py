"""Association between scenario elements and unexpected-behaviour categories, ranked by lift.

lift(e, c) = P(c | e) / P(c): how much more often category c occurs in runs whose scenario contains element e
than in runs overall. Support (runs with both) is reported beside it, since a lift measured on three runs says
little; `min_support` filters those out of the ranking.

Stratified (`strata`: one label per run, e.g. the tree a scenario grew in): the lift is measured within each
stratum and pooled as observed over expected, O/E = sum a_s / sum n_e,s * P_s(c), over the strata in which the
element *varies* (some runs have it, some do not). A scenario tree holds one seed's scenarios, which all share the
seed's own elements (its parties' positions and events, its map): across trees those ride along with whatever
the tree's mutations caused and can outrank the cause, while within a tree only what a mutation changed differs
between a run that shows the category and one that does not. An element constant in every stratum says nothing
about what it does and is not ranked. Elements one mutation always brings in together (a car standing close behind
the AV: `category:car`, `position:R6/same`, `near_start:yes`) have the same stratified lift; the tie is broken by
the lift over all runs, where the one that is common without the category (cars everywhere) ranks lower.
"""

from __future__ import annotations

from collections import Counter, defaultdict
from dataclasses import dataclass
from typing import Iterable, Sequence


@dataclass(frozen=True)
class LiftRow:
    category: str
    element: str
    lift: float
    support: int          # runs with the element and the category (stratified: in the strata it varies in)
    with_element: int     # runs with the element (stratified: in the strata it varies in)
    confidence: float     # P(category | element)
    base_rate: float      # P(category) (stratified: the confidence expected were the element without effect)


def lift_table(runs: Iterable[tuple[frozenset[str], frozenset[str]]], *, min_support: int = 3,
               strata: Sequence[str] | None = None) -> dict[str, list[LiftRow]]:
    """`runs`: (elements of the scenario, categories the run showed); `strata`: one label per run (None: all runs
    are one population, and every element is ranked). Returns rows per category, best first (ties broken by
    support, then element name, so the ranking is deterministic)."""
    runs = list(runs)
    if not runs:
        return {}
    labels = list(strata) if strata is not None else [""] * len(runs)
    if len(labels) != len(runs):
        raise ValueError(f"{len(labels)} strata for {len(runs)} runs")
    groups: dict[str, list[tuple[frozenset[str], frozenset[str]]]] = defaultdict(list)
    for label, run in zip(labels, runs):
        groups[label].append(run)
    pooled = _pooled(runs) if strata is not None else {}
    observed: Counter[tuple[str, str]] = Counter()
    expected: defaultdict[tuple[str, str], float] = defaultdict(float)
    with_element: Counter[tuple[str, str]] = Counter()
    cats: set[str] = set()
    for label in sorted(groups):
        n, n_elem, n_cat, n_both = _counts(groups[label])
        cats.update(n_cat)
        for e, ne in n_elem.items():
            if strata is not None and ne == n:      # constant in this stratum: no contrast to learn from
                continue
            for c, nc in n_cat.items():
                observed[(e, c)] += n_both.get((e, c), 0)
                expected[(e, c)] += ne * nc / n
                with_element[(e, c)] += ne
    table: dict[str, list[LiftRow]] = {}
    for c in sorted(cats):
        rows = []
        for (e, cc), exp in expected.items():
            both = observed[(e, cc)]
            if cc != c or both < min_support or exp <= 0.0:
                continue
            ne = with_element[(e, c)]
            rows.append(LiftRow(c, e, both / exp, both, ne, both / ne, exp / ne))
        # rounded: equal counts pooled in a different order must tie, so the pooled lift can break the tie
        rows.sort(key=lambda r: (-round(r.lift, 9), -pooled.get((r.element, c), 0.0), -r.support, r.element))
        table[c] = rows
    return table


def _counts(runs: list[tuple[frozenset[str], frozenset[str]]]
            ) -> tuple[int, Counter[str], Counter[str], Counter[tuple[str, str]]]:
    """Runs, runs per element, runs per category, runs per (element, category)."""
    n_elem: Counter[str] = Counter()
    n_cat: Counter[str] = Counter()
    n_both: Counter[tuple[str, str]] = Counter()
    for elements, shown in runs:
        n_elem.update(elements)
        n_cat.update(shown)
        for c in shown:
            for e in elements:
                n_both[(e, c)] += 1
    return len(runs), n_elem, n_cat, n_both


def _pooled(runs: list[tuple[frozenset[str], frozenset[str]]]) -> dict[tuple[str, str], float]:
    """(element, category) -> the lift over all runs as one population (the tie-break of a stratified ranking)."""
    n, n_elem, n_cat, n_both = _counts(runs)
    return {(e, c): both * n / (n_elem[e] * n_cat[c]) for (e, c), both in n_both.items()}


def rank_of(rows: list[LiftRow], *, contains: str) -> int | None:
    """1-based rank of the first row whose element contains `contains` (None when absent)."""
    for i, row in enumerate(rows, 1):
        if contains in row.element:
            return i
    return None
