"""`txt2sce extract`'s batch over several processes gives the same sketches, in the same order, as one process,
and a bad row stays an error record in its place."""

from __future__ import annotations

import json

from txt2sce_ros.paths import shared_dir
from txt2sce_ros.sketch import ErrorRecord
from txt2sce_ros.text.pipeline import PARALLEL_MIN_REPORTS, run_batch
from txt2sce_ros.text.readers import ReportInput


def _inputs() -> list[ReportInput | ErrorRecord]:
    path = shared_dir() / "data" / "reports" / "dev.jsonl"
    rows = [json.loads(x) for x in path.read_text(encoding="utf-8").splitlines() if x.strip()]
    items: list[ReportInput | ErrorRecord] = [ReportInput(report_id=r["id"], text=r["text"], source=str(path))
                                              for r in rows]
    items += [ReportInput(report_id="empty", text="   ", source="t"), ErrorRecord("unreadable", "no text", "t")]
    while len(items) < PARALLEL_MIN_REPORTS:
        items += items[:PARALLEL_MIN_REPORTS - len(items)]
    return items


def test_two_processes_give_the_same_sketches_in_order() -> None:
    items = _inputs()
    one = [r.to_json() for r in run_batch(items)]
    two = [r.to_json() for r in run_batch(items, workers=2)]
    assert len(two) == len(items) and two == one
    assert '"report_id": "empty"' in " ".join(x for x in two if '"error"' in x)  # a bad row: its error, in place
