"""Verdict audit (`txt2sce verdict-audit`): the nominal failure rate by category of a stored campaign ("before": as
the code that ran it judged it) beside the same scenarios re-run now ("after"), and a hand classification of
failing runs re-checked against the re-run.

The classification file (JSON lines, e.g. `docs/verdict_audit.jsonl`) holds one failing nominal run per line:
`tree`, `scenario_id`, `before` (its categories then), `class` (one of `CLASSES`) and `reason` (a short sentence).
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Iterable

from ..analysis.behaviours import CATEGORIES, Attribution, attribution
from ..errors import InputError
from .runs import make_tasks, run_all
from .store import ResultStore, StoredRun

#: The classes a failing nominal run is put in by hand (issue 16).
CLASSES = ("stand-in deficiency", "oracle false alarm", "unavoidable by scripted parties", "harness bug")


@dataclass(frozen=True)
class Side:
    """One side of the comparison: verdicts by (tree, scenario id)."""

    runs: dict[tuple[str, str], StoredRun]

    @property
    def judged(self) -> int:
        return sum(1 for r in self.runs.values() if r.verdict in ("pass", "fail"))

    def count(self, category: str | None) -> int:
        """Runs failing with `category` (None: failing at all)."""
        return sum(1 for r in self.runs.values() if r.verdict == "fail" and (category is None or category in
                                                                            r.categories))

    def attribution(self) -> Attribution:
        return attribution((r.verdict, tuple(r.categories), r.record) for r in self.runs.values())


def _by_scenario(runs: Iterable[StoredRun]) -> dict[tuple[str, str], StoredRun]:
    return {(r.tree or "", r.scenario_id): r for r in runs}


def load_before(campaign: Path) -> Side:
    path = campaign / "results.sqlite"
    if not path.is_file():
        raise InputError("no results.sqlite: not a campaign directory (run `txt2sce campaign` or `make demo`)",
                         source=str(campaign))
    with ResultStore(path) as store:
        if store.meta("faults", []):
            raise InputError(f"the campaign ran with faults {store.meta('faults')}: a nominal campaign is needed",
                             source=str(path))
        return Side(_by_scenario(store.runs()))


def run_after(campaign: Path, out: Path, *, workers: int | None = None, progress: bool = True) -> Side:
    """Re-run every scenario of the campaign's trees nominally with the code as it is now, into `out`."""
    trees = campaign / "trees"
    if not trees.is_dir():
        raise InputError("no trees/ directory beside results.sqlite", source=str(campaign))
    tasks = make_tasks(sorted(p for p in trees.iterdir() if p.is_dir()))
    out.mkdir(parents=True, exist_ok=True)
    with ResultStore(out / "results.sqlite") as store:
        store.set_meta("faults", [])
        run_all(tasks, store, executor="pool" if (workers or 2) > 1 else "serial", workers=workers,
                progress=progress)
        return Side(_by_scenario(store.runs()))


def rate_table(before: Side, after: Side) -> list[tuple[str, str, str, str]]:
    """Rows (category, before, after, after: of which unavoidable by scripted parties) over the scenarios both
    sides judged."""
    keys = set(before.runs) & set(after.runs)
    b, a = Side({k: before.runs[k] for k in keys}), Side({k: after.runs[k] for k in keys})
    who = a.attribution()

    def cell(side: Side, cat: str | None) -> str:
        n = side.count(cat)
        return f"{n} ({100.0 * n / side.judged:.1f} %)" if side.judged else "0"

    rows = [("any failure", cell(b, None), cell(a, None), str(who.failed - who.planner))]
    rows += [(c, cell(b, c), cell(a, c), str(who.unavoidable.get(c, 0))) for c in CATEGORIES]
    rows.append(("judged runs", str(b.judged), str(a.judged), ""))
    rows.append(("failures saying something about the planner", "–", str(who.planner), ""))
    return rows


def load_classification(path: Path) -> list[dict[str, Any]]:
    rows = []
    for i, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        if not line.strip():
            continue
        try:
            row = json.loads(line)
        except json.JSONDecodeError as exc:
            raise InputError(f"line {i} is not JSON: {exc.msg}", source=str(path)) from None
        missing = [k for k in ("tree", "scenario_id", "before", "class", "reason") if k not in row]
        if missing or row.get("class") not in CLASSES:
            raise InputError(f"line {i}: needs tree, scenario_id, before, class (one of {', '.join(CLASSES)}) and "
                             f"reason", source=str(path))
        rows.append(row)
    return rows


def classification_table(rows: list[dict[str, Any]], after: Side) -> list[tuple[str, int, int, int, int]]:
    """Per class: (class, runs, still failing now, of which labelled unavoidable now, passing now)."""
    out = []
    for cls in CLASSES:
        mine = [r for r in rows if r["class"] == cls]
        now = [after.runs.get((r["tree"], r["scenario_id"])) for r in mine]
        failing = [r for r in now if r is not None and r.verdict == "fail"]
        labelled = sum(1 for r in failing if r.record.get("details", {}).get("unavoidable"))
        out.append((cls, len(mine), len(failing), labelled, sum(1 for r in now if r is not None and
                                                                 r.verdict == "pass")))
    return out
