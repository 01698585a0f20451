"""`txt2sce verdict-audit CAMPAIGN --out DIR [--classification FILE]`: how far the nominal verdicts can be trusted.

Re-runs every scenario of a nominal campaign (e.g. `demo_out/campaign` from `make demo`) with the planner and
oracle as they are now, into DIR, and prints the nominal failure rate by category as the campaign stored it
(before) beside the re-run (after), with the failures the oracle now labels unavoidable by the scripted parties.
With `--classification` (default `docs/verdict_audit.jsonl` when it exists), it also prints, per hand-assigned
class of the sampled failing runs, how many still fail now.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from .argtypes import count

HELP = "nominal failure rate by category of a campaign before / after re-running it now, and the classified sample"

DEFAULT_CLASSIFICATION = Path(__file__).resolve().parents[2] / "docs" / "verdict_audit.jsonl"


def register(parser: argparse.ArgumentParser) -> None:
    parser.epilog = __doc__
    parser.add_argument("campaign", type=Path, help="a nominal campaign directory (results.sqlite + trees/)")
    parser.add_argument("--out", type=Path, required=True, help="where the re-run's results.sqlite goes")
    parser.add_argument("--classification", type=Path, default=None,
                        help="hand classification of failing runs (JSON lines; default docs/verdict_audit.jsonl)")
    parser.add_argument("--workers", type=count(ge=1), default=None, help="processes for the re-run")
    parser.add_argument("--no-progress", action="store_true", help="no progress bar")


def _table(header: tuple[str, ...], rows: list[tuple]) -> None:
    widths = [max(len(str(r[i])) for r in [header, *rows]) for i in range(len(header))]
    for r in [header, *rows]:
        print("  ".join(str(c).ljust(w) for c, w in zip(r, widths)).rstrip())


def run(args: argparse.Namespace) -> int:
    from ..campaign.audit import classification_table, load_before, load_classification, rate_table, run_after

    before = load_before(args.campaign)
    after = run_after(args.campaign, args.out, workers=args.workers, progress=not args.no_progress)
    print(f"nominal runs of {args.campaign}: before = as stored there, after = re-run now into {args.out}")
    _table(("category", "before", "after", "after: unavoidable by scripted parties"), rate_table(before, after))
    path = args.classification or (DEFAULT_CLASSIFICATION if DEFAULT_CLASSIFICATION.is_file() else None)
    if path is not None:
        rows = load_classification(path)
        known = [r for r in rows if (r["tree"], r["scenario_id"]) in after.runs]
        print(f"\nhand classification {path} ({len(rows)} failing runs, {len(known)} found in this campaign):")
        _table(("class", "runs", "still failing", "of which labelled unavoidable", "passing now"),
               classification_table(known, after))
    return 0
