"""`txt2sce review SKETCHES [--seeds DIR] [--reports FILE...] --out page.html`: one self-contained HTML page to check
a batch of sketches against their narratives (evidence highlighted), and their seeds (top-down picture, fidelity),
before building from them.

    txt2sce extract ../shared/data/reports/dev.jsonl --out sketches.jsonl
    txt2sce seed sketches.jsonl --out seeds
    txt2sce review sketches.jsonl --seeds seeds --reports ../shared/data/reports/dev.jsonl --out review.html
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from ..errors import InputError

HELP = "write one self-contained HTML page to review sketches: narrative with evidence, sketch table, seed picture"


def register(parser: argparse.ArgumentParser) -> None:
    parser.epilog = __doc__
    parser.add_argument("sketches", type=Path, help="JSONL of sketches (txt2sce extract's output, or hand-labelled)")
    parser.add_argument("--seeds", type=Path, default=None,
                        help="seed directory built from these sketches (txt2sce seed --out DIR): adds the pictures")
    parser.add_argument("--reports", type=Path, action="append", default=None, metavar="FILE",
                        help="where the narratives are (.jsonl {id, text}, .txt, directories; repeatable; default: "
                             "the bundled reports and ../shared/data/reports/dev.jsonl)")
    parser.add_argument("--out", type=Path, required=True, help="HTML file to write")


def default_report_files() -> list[Path]:
    """Narratives looked up when --reports is not given: the bundled ones and the shared dev set."""
    from ..paths import BUNDLED_REPORTS, shared_dir

    found = sorted(BUNDLED_REPORTS.glob("*.jsonl"))
    dev = shared_dir() / "data" / "reports" / "dev.jsonl"
    return found + ([dev] if dev.is_file() else [])


def load_narratives(paths: list[Path]) -> dict[str, str]:
    from ..sketch import ErrorRecord
    from ..text.readers import iter_inputs

    out: dict[str, str] = {}
    for item in iter_inputs(paths):
        if isinstance(item, ErrorRecord):
            print(f"txt2sce review: warning: {item.error}", file=sys.stderr)
            continue
        out.setdefault(item.report_id, item.text)
    return out


def run(args: argparse.Namespace) -> int:
    from ..analysis.review import review_page
    from ..sketch import load_sketches

    if not args.sketches.is_file():
        raise InputError("no such sketch file", source=str(args.sketches))
    if args.seeds is not None and not (args.seeds / "manifest.json").is_file():
        raise InputError("not a seed directory (no manifest.json; make one with `txt2sce seed SKETCHES --out DIR`)",
                         source=str(args.seeds))
    items = list(load_sketches(args.sketches))
    if not items:
        raise InputError("no sketches in the file", source=str(args.sketches))
    narratives = load_narratives(args.reports if args.reports else default_report_files())
    page, stats = review_page(items, narratives, seed_dir=args.seeds, title=f"txt2sce review: {args.sketches.name}")
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(page, encoding="utf-8")
    missing = sum(1 for it in items if it.report_id not in narratives)
    print(f"review: {stats.reports} reports ({stats.buildable} buildable, {stats.with_evidence} with evidence"
          + (f", {stats.faithful}/{stats.seeds} seeds faithful" if args.seeds else "")
          + (f", {missing} narratives not found" if missing else "") + f") -> {args.out}")
    return 0
