"""Association between scenario elements and unexpected-behaviour categories, ranked by lift.

lift(e, c) = P(c | e) / P(c): how much more often category c occurs in runs whose scenario contains element e
than in runs overall. Support (runs with both) is reported beside it, since a lift measured on three runs says
little; `min_support` filters those out of the ranking, and `prior` (pseudo-runs) ranks by a lift shrunk towards
1, (O + prior) / (E + prior): two runs that both show the category (14× on an expected 0.14) then rank below
twenty that show it 1.7 times as often as expected, instead of above them.

Stratified (`strata`: one label per run, e.g. the tree a scenario grew in): the lift is measured within each
stratum and pooled as observed over expected, O/E = sum a_s / sum n_e,s * P_s(c), over every stratum. A scenario
tree holds one seed's scenarios, which all share the seed's own elements (its parties' positions and events, its
map): across trees those ride along with whatever the tree's mutations caused and can outrank the cause, while
within a tree only what a mutation changed differs between a run that shows the category and one that does not.
So a stratum where the element is constant adds as much to O as to E (it shows the category as often as
expected there): it earns the element nothing and pulls its lift towards 1, and every element is measured over
the same runs (measured only where it varies, a party's position that the seed holds in one tree and a mutation
adds in another was judged on the second tree alone, against a lower base rate than the category's own cause).
An element that varies in no stratum (or with fewer than `min_support` runs showing the category where it varies)
says nothing about what it does and is not ranked.

Elements that occur in exactly the same runs (one mutation always brings them in together: a car standing close
behind the AV adds `position:R6`, `position:R6/same` and `near_start:yes`) cannot be told apart by any count: they
are ranked as one joint condition, `near_start:yes & position:R6 & position:R6/same`, rather than one of them
winning a tie on its name. Distinct elements with the same stratified lift are ordered by the lift over all runs,
where the one that is common without the category (cars everywhere) ranks lower.
"""

from __future__ import annotations

from collections import Counter, defaultdict
from dataclasses import dataclass
from typing import Iterable, Sequence

#: Separates the parts of a joint condition (elements that occur in exactly the same runs).
JOINT = " & "


@dataclass(frozen=True)
class LiftRow:
    category: str
    element: str          # one element, or a joint condition of several (`JOINT`-separated, sorted)
    lift: float
    support: int          # runs with the element and the category
    with_element: int     # runs with the element
    confidence: float     # P(category | element)
    base_rate: float      # P(category) (stratified: the confidence expected were the element without effect)
    score: float = 0.0    # the ranking key: the lift shrunk towards 1 by `prior` pseudo-runs (= lift without)


def joint_parts(element: str) -> list[str]:
    """The elements a (possibly joint) lift element stands for."""
    return element.split(JOINT)


def lift_table(runs: Iterable[tuple[frozenset[str], frozenset[str]]], *, min_support: int = 3,
               strata: Sequence[str] | None = None, prior: float = 0.0) -> dict[str, list[LiftRow]]:
    """`runs`: (elements of the scenario, categories the run showed); `strata`: one label per run (None: all runs
    are one population, and every element is ranked); `prior`: pseudo-runs of shrinkage for the ranking (0: by
    the lift itself). Returns rows per category, best first (ties broken by the pooled lift, support, then
    element name, so the ranking is deterministic)."""
    runs = _joint(list(runs))
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
    varying: Counter[tuple[str, str]] = Counter()      # of `observed`, in strata where the element varies
    expected: defaultdict[tuple[str, str], float] = defaultdict(float)
    with_element: Counter[tuple[str, str]] = Counter()
    cats: set[str] = set()
    for label in sorted(groups):
        n, n_elem, n_cat, n_both = _counts(groups[label])
        cats.update(n_cat)
        for e, ne in n_elem.items():
            for c, nc in n_cat.items():
                both = n_both.get((e, c), 0)
                observed[(e, c)] += both
                expected[(e, c)] += ne * nc / n
                with_element[(e, c)] += ne
                if strata is None or ne < n:
                    varying[(e, c)] += both
    table: dict[str, list[LiftRow]] = {}
    for c in sorted(cats):
        rows = []
        for (e, cc), exp in expected.items():
            both = observed[(e, cc)]
            if cc != c or varying[(e, cc)] < min_support or exp <= 0.0:
                continue
            ne = with_element[(e, c)]
            rows.append(LiftRow(c, e, both / exp, both, ne, both / ne, exp / ne, (both + prior) / (exp + prior)))
        # rounded: equal counts pooled in a different order must tie, so the pooled lift can break the tie
        rows.sort(key=lambda r: (-round(r.score, 9), -pooled.get((r.element, c), 0.0), -r.support, r.element))
        table[c] = rows
    return table


def _joint(runs: list[tuple[frozenset[str], frozenset[str]]]) -> list[tuple[frozenset[str], frozenset[str]]]:
    """The runs with every group of elements that occur in exactly the same runs renamed to one joint condition
    (parts sorted, `JOINT`-separated)."""
    members: defaultdict[str, list[int]] = defaultdict(list)
    for i, (elements, _) in enumerate(runs):
        for e in elements:
            members[e].append(i)
    together: defaultdict[tuple[int, ...], list[str]] = defaultdict(list)
    for e, where in members.items():
        together[tuple(where)].append(e)
    rename = {e: JOINT.join(sorted(group)) for group in together.values() if len(group) > 1 for e in group}
    if not rename:
        return runs
    return [(frozenset(rename.get(e, e) for e in elements), shown) for elements, shown in runs]


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
