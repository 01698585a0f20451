"""`txt2sce bench extract`: offline extraction throughput over dev.jsonl, beside two baselines from the same run.

Baselines: a plain regex pass (one compiled pattern scanned over every text: the floor cost of touching the text)
and schema validation alone (jsonschema over the extracted sketches). Besides the extractor alone, the batch path
of `txt2sce extract` (extract, then validate the sketch's JSON form) is timed too, in one process and as the CLI
runs a batch of 200+ reports: over the usable cores (the per-CPU-second column counts this process only there). Each loop is repeated until it
has run at least the minimum time, so the rate is not a single noisy pass.
"""

from __future__ import annotations

import argparse
import json
import os
import re
import time
from collections.abc import Callable

DESCRIPTION = "offline report->sketch extraction, reports/s over dev.jsonl, vs a regex pass and schema validation"


def _rate(fn: Callable[[], int], min_s: float) -> tuple[float, int, float, float]:
    """(reports/s wall, reports, wall s, reports/s of this process's CPU time). The machine is shared: the CPU
    rate is the extractor's own cost, the wall rate what a user saw under the current load."""
    done, t0, c0 = 0, time.perf_counter(), time.process_time()
    while True:
        done += fn()
        dt = time.perf_counter() - t0
        if dt >= min_s:
            return done / dt, done, dt, done / max(time.process_time() - c0, 1e-9)


def run(args: argparse.Namespace) -> int:
    from ..paths import shared_dir
    from ..sketch import validate_sketch_dict
    from ..text.extractor import extract
    from ..text.pipeline import sketch_report
    from ..text.readers import ReportInput

    path = shared_dir() / "data" / "reports" / "dev.jsonl"
    rows = [json.loads(line) for line in path.read_text(encoding="utf-8").splitlines() if line.strip()]
    min_s = 0.5 if getattr(args, "quick", False) else 2.0
    rx = re.compile(r"\b(?:struck|contact|collided|hit|turn(?:ed|ing)?|lane|stopp?ed|travel\w*)\b", re.I)
    sketches = [extract(r["text"], r["id"]).to_dict() for r in rows]

    def regex_pass() -> int:
        for r in rows:
            rx.findall(r["text"])
        return len(rows)

    def extraction() -> int:
        for r in rows:
            extract(r["text"], r["id"])
        return len(rows)

    inputs = [ReportInput(report_id=r["id"], text=r["text"], source=str(path)) for r in rows]

    def batch_path() -> int:
        for inp in inputs:
            sketch_report(inp)
        return len(inputs)

    from ..text.pipeline import PARALLEL_MIN_REPORTS, default_workers, run_batch

    workers = default_workers()
    # The CLI's batch of 200+ reports over the usable cores (the pool's start is inside the loop, as for a user).
    big = inputs * -(-PARALLEL_MIN_REPORTS // len(inputs)) * 2

    def parallel_batch() -> int:
        for _ in run_batch(big, workers=workers):
            pass
        return len(big)

    def validation() -> int:
        for d in sketches:
            validate_sketch_dict(d)
        return len(sketches)

    print(f"bench extract: {len(rows)} reports from {path} (each loop >= {min_s:.1f} s)")
    results = [("regex pass (baseline)", _rate(regex_pass, min_s)),
               ("schema validation (baseline)", _rate(validation, min_s)),
               ("offline extractor", _rate(extraction, min_s)),
               ("extract + validate (batch)", _rate(batch_path, min_s)),
               (f"batch, {workers} processes", _rate(parallel_batch, min_s))]
    ext, ext_cpu = results[2][1][0], results[2][1][3]
    print(f"{'loop':<30}{'reports/s':>11}{'per CPU s':>11}{'reports':>9}{'wall s':>8}{'extractor x':>13}")
    for name, (rate, n, dt, cpu_rate) in results:
        print(f"{name:<30}{rate:>11.0f}{cpu_rate:>11.0f}{n:>9}{dt:>8.2f}{ext / rate:>13.3f}")
    target = 500
    print(f"offline extractor: {ext:.0f} reports/s wall, {ext_cpu:.0f} per CPU second "
          f"({'>=' if ext >= target else 'BELOW'} target {target} wall; load average "
          f"{os.getloadavg()[0]:.1f} on {os.cpu_count()} cores)")
    par = results[4][1][0]
    print(f"`txt2sce extract` batch of {len(big)} over {workers} processes: {par:.0f} reports/s wall "
          f"({'>=' if par >= target else 'BELOW'} target {target}; the same sketches as one process gives)")
    _scaling(rows, quick=getattr(args, "quick", False))
    return 0


def _scaling(rows: list[dict], *, quick: bool) -> None:
    """Time per character on one long narrative made of the dev texts, at growing lengths up to the limit: linear
    time keeps the per-character cost flat (the baseline is the shortest length)."""
    from ..text.extractor import MAX_NARRATIVE_CHARS, extract

    joined = " ".join(r["text"] for r in rows)
    while len(joined) < MAX_NARRATIVE_CHARS:
        joined += " " + joined
    sizes = [MAX_NARRATIVE_CHARS // 8, MAX_NARRATIVE_CHARS // 2] if quick else \
        [MAX_NARRATIVE_CHARS // 8, MAX_NARRATIVE_CHARS // 4, MAX_NARRATIVE_CHARS // 2, MAX_NARRATIVE_CHARS]
    base = None
    print("scaling (one narrative, dev texts joined):")
    for n in sizes:
        t0 = time.process_time()
        extract(joined[:n], "scaling")
        per = (time.process_time() - t0) / n * 1e6
        base = base or per
        print(f"  {n:>8} chars  {per:6.1f} us/char CPU  x{per / base:.2f} of the {sizes[0]}-char cost")
