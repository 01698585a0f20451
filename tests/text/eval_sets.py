"""Every gold set at once: one row per set with issue 13's slots and the user's figure, and pooled rows for the sets
rules may be written from and for the sets that are scored only.

    python -m tests.text.eval_sets                                # the offline rules
    python -m tests.text.eval_sets --hybrid-ceiling               # + `hybrid` with a perfect model (no model run)
    python -m tests.text.eval_sets --backend llm --base-url URL --model NAME   # a model server's reading

Each row is what `txt2sce extract X --out P && txt2sce eval-extract --gold G --pred P` prints for that set; this runs
them in one process and one table. The sets: the shared data's three (`dev_gold` and `dev_gold_study` studyable,
`dev_gold_check` scored only) and the five pairs under tests/text (csvr, sgo, sgo4, sgo5, sgo6; `studyN` studyable,
`checkN` scored only; each directory's README says where its narratives come from and how they were labelled).
"""

from __future__ import annotations

import argparse
import sys
import time
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from txt2sce_ros.errors import InputError
from txt2sce_ros.paths import shared_dir
from txt2sce_ros.sketch import Sketch, load_sketches
from txt2sce_ros.text.evaluate import Evaluation, evaluate

HERE = Path(__file__).parent


@dataclass(frozen=True)
class GoldSet:
    name: str
    narratives: Path
    gold: Path
    studyable: bool  # rules may be written from it; else scored only, never read


def gold_sets() -> list[GoldSet]:
    reports = shared_dir() / "data" / "reports"
    out = [GoldSet("dev_gold", reports / "dev.jsonl", reports / "dev_gold.jsonl", True),
           GoldSet("dev_gold_study", reports / "dev.jsonl", reports / "dev_gold_study.jsonl", True),
           GoldSet("dev_gold_check", reports / "dev.jsonl", reports / "dev_gold_check.jsonl", False)]
    for folder, n in (("csvr", 2), ("sgo", 3), ("sgo4", 4), ("sgo5", 5), ("sgo6", 6)):
        for kind, studyable in (("study", True), ("check", False)):
            name = f"{kind}{n}"
            out.append(GoldSet(name, HERE / folder / f"{name}.jsonl", HERE / folder / f"{name}_gold.jsonl", studyable))
    return out


#: The columns: issue 13's floors, then the parts of the user's figure.
SLOTS = ("npc_quantity", "npc_type", "npc_position", "npc_events", "obstacle_quantity", "completeness", "layout",
         "ego_start", "ego_actions")
HEADS = {"npc_quantity": "quantity", "npc_type": "type", "npc_position": "position", "npc_events": "events",
         "obstacle_quantity": "obstacles", "completeness": "complete", "layout": "layout", "ego_start": "AV start",
         "ego_actions": "AV actions"}


@dataclass
class Row:
    name: str
    ev: Evaluation
    ceiling: Evaluation | None = None


def _load_gold(path: Path) -> list[Sketch]:
    out = []
    for g in load_sketches(path):
        if not isinstance(g, Sketch):
            raise InputError(f"bad gold line: {g.error}", source=str(path))
        out.append(g)
    return out


def run_sets(sets: Sequence[GoldSet], *, backend: str = "offline", llm: object = None,
             hybrid_ceiling: bool = False, progress: bool = False,
             errors: list[str] | None = None) -> list[Row]:
    """One evaluation per set: each narratives file is extracted once (and once more for the ceiling), whatever the
    number of sets it serves. A report that got no sketch (an error record: a server that failed, an answer that
    never formed a valid sketch) scores as wrong in every slot, and its reason is added to `errors`."""
    errors = [] if errors is None else errors
    from txt2sce_ros.text.pipeline import run_batch
    from txt2sce_ros.text.readers import iter_inputs

    def extract(path: Path, **kw: object) -> dict[str, Sketch]:
        results = run_batch(iter_inputs([str(path)]), **kw)
        if progress:
            from tqdm import tqdm

            results = tqdm(results, unit="report", file=sys.stderr, desc=path.name, leave=False)
        out = {}
        for s in results:
            if isinstance(s, Sketch):
                out[s.report_id] = s
            else:
                errors.append(f"{path.name}: {s.report_id}: {s.error}")
        return out

    golds = {gs.name: _load_gold(gs.gold) for gs in sets}
    preds: dict[Path, dict[str, Sketch]] = {}
    ceilings: dict[Path, dict[str, Sketch]] = {}
    for path in dict.fromkeys(gs.narratives for gs in sets):
        preds[path] = extract(path, backend=backend, llm=llm)
        if hybrid_ceiling:
            from txt2sce_ros.text.ceiling import PerfectModel

            # One perfect model for every set these narratives serve (a report is in one set): one pass each.
            model = PerfectModel({g.report_id: g for gs in sets if gs.narratives == path for g in golds[gs.name]})
            ceilings[path] = extract(path, backend="hybrid", llm=model)
    rows = []
    for gs in sets:
        row = Row(gs.name, evaluate(golds[gs.name], preds[gs.narratives]))
        if hybrid_ceiling:
            row.ceiling = evaluate(golds[gs.name], ceilings[gs.narratives])
        rows.append(row)
    return rows


def _pooled(name: str, rows: Sequence[Row]) -> tuple[str, dict[str, tuple[int, int]], tuple[int, int],
                                                      tuple[int, int] | None]:
    slots = {k: (sum(r.ev.slots[k].correct for r in rows), sum(r.ev.slots[k].total for r in rows)) for k in SLOTS}
    conflict = (sum(len(r.ev.conflict_ok) for r in rows), sum(len(r.ev.complete) for r in rows))
    ceiling = None
    if rows and all(r.ceiling is not None for r in rows):
        ceiling = (sum(len(r.ceiling.conflict_ok) for r in rows), sum(len(r.ceiling.complete) for r in rows))  # type: ignore[union-attr]
    return name, slots, conflict, ceiling


def format_rows(rows: Sequence[Row], studyable: set[str]) -> str:
    """The table: a row per set, then the pooled studyable and scored-only rows (slot figures in %, the user's
    figure and the ceiling as counts)."""
    heads = [HEADS[k] for k in SLOTS]
    has_ceiling = any(r.ceiling is not None for r in rows)
    lines = [f"{'set':<17}" + "".join(f"{h:>12}" for h in heads) + f"{'conflict':>12}"
             + (f"{'ceiling':>12}" if has_ceiling else "")]

    def line(name: str, slots: dict[str, tuple[int, int]], conflict: tuple[int, int],
             ceiling: tuple[int, int] | None) -> str:
        cells = "".join(f"{(100 * a / b if b else float('nan')):>12.1f}" for a, b in slots.values())
        text = f"{name:<17}{cells}{f'{conflict[0]}/{conflict[1]}':>12}"
        return text + (f"{f'{ceiling[0]}/{ceiling[1]}':>12}" if ceiling else "")

    for r in rows:
        lines.append(line(*_pooled(r.name + ("" if r.name in studyable else " *"), [r])))
    lines.append("")
    for label, keep in (("studyable", True), ("scored only *", False)):
        part = [r for r in rows if (r.name in studyable) == keep]
        if part:
            lines.append(line(*_pooled(label, part)))
    lines.append("(* scored only: never read. Slots in %; conflict = the user's figure, complete reports whose "
                 "conflict is reproduced exactly" + ("; ceiling = the same with `hybrid` and a perfect model)"
                                                       if has_ceiling else ")"))
    return "\n".join(lines)


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m tests.text.eval_sets", description=__doc__.split("\n\n")[0])
    parser.add_argument("--backend", choices=("offline", "llm", "hybrid"), default="offline")
    parser.add_argument("--base-url", default=None, help="OpenAI-compatible server for llm/hybrid (default DeepSeek)")
    parser.add_argument("--model", default=None, help="model name for llm/hybrid")
    parser.add_argument("--hybrid-ceiling", action="store_true",
                        help="also score `hybrid` with a perfect model answering each question it asks")
    parser.add_argument("--sets", default=None, help="comma-separated set names (default: all)")
    args = parser.parse_args(argv)
    sets = gold_sets()
    if args.sets:
        wanted = [s.strip() for s in args.sets.split(",") if s.strip()]
        unknown = sorted(set(wanted) - {s.name for s in sets})
        if unknown:
            print(f"eval_sets: error: unknown set(s) {', '.join(unknown)} (one of {', '.join(s.name for s in sets)})",
                  file=sys.stderr)
            return 2
        sets = [s for s in sets if s.name in wanted]
    llm = None
    try:
        if args.backend != "offline":
            from txt2sce_ros.config import load_config
            from txt2sce_ros.text.llm import configured_llm

            llm = configured_llm(args.backend, load_config("extract").get("llm"), base_url=args.base_url,
                                 model=args.model)
        t0 = time.perf_counter()
        errors: list[str] = []
        rows = run_sets(sets, backend=args.backend, llm=llm, hybrid_ceiling=args.hybrid_ceiling,
                        progress=args.backend != "offline" and sys.stderr.isatty(), errors=errors)
    except InputError as exc:
        print(f"eval_sets: error: {exc}", file=sys.stderr)
        return 2
    print(f"backend: {args.backend}; {len(rows)} sets in {time.perf_counter() - t0:.1f} s")
    print(format_rows(rows, {s.name for s in sets if s.studyable}))
    if errors:
        print(f"warning: {len(errors)} report(s) got no sketch and were scored wrong in every slot; the first: "
              f"{errors[0]}", file=sys.stderr)
    if llm is not None and getattr(llm, "not_consulted", None):
        print(f"warning: the server did not answer for {len(llm.not_consulted)} report(s): the rules' sketch was "
              f"scored for those", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
