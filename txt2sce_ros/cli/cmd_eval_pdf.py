"""`txt2sce eval-pdf DIR`: read every OL 316 PDF in DIR and score it against DIR/forms.jsonl, beside the baseline."""

from __future__ import annotations

import argparse
import json
from pathlib import Path

HELP = "score the OL 316 PDF reader on a directory of PDFs with forms.jsonl (narrative, check boxes, scans)"


def register(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("directory", help="a directory of OL 316 PDFs with forms.jsonl beside them "
                                          "(e.g. ../shared/data/ol316)")
    parser.add_argument("--json", dest="json_out", default=None, help="also write per-file scores and totals here")


def run(args: argparse.Namespace) -> int:
    from ..errors import InputError
    from ..text.ol316 import ocr
    from ..text.ol316.score import format_report, load_forms, score_baseline, score_reader, totals

    d = Path(args.directory)
    if not d.is_dir():
        raise InputError("not a directory", source=str(d))
    rows = load_forms(d)
    missing = [r["file"] for r in rows if not (d / r["file"]).is_file()]
    if missing:
        raise InputError(f"forms.jsonl names {len(missing)} file(s) not in the directory: {', '.join(missing[:3])}",
                         source=str(d))
    print(f"OL 316 reader on {len(rows)} PDFs in {d} (Tesseract OCR: "
          f"{'available' if ocr.available() else 'not installed, scans are refused'})")
    scores = [score_reader(r, d / r["file"]) for r in rows]
    base = [score_baseline(r, d / r["file"]) for r in rows]
    print(format_report(scores, base))
    if args.json_out:
        Path(args.json_out).write_text(json.dumps(
            {"files": [s.__dict__ for s in scores], "totals": totals(scores), "baseline": totals(base)},
            indent=1, ensure_ascii=False), encoding="utf-8")
    return 0
