"""`python -m tests.reliability.catalogue [-j N] [-k PATTERN]`: run the whole catalogue of bad inputs and faults
and print the counts (cases, clean, crashes, hangs, losses), then one line per case that is not clean.

Exit status 0 when every case is clean (cases marked expected-to-fail-until another issue lands are listed apart).
"""

from __future__ import annotations

import argparse
import re
import sys
import tempfile
import time
from collections import Counter
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from .cases import cases
from .runner import Outcome, run_case
from .workspace import build


def run_catalogue(jobs: int = 2, pattern: str | None = None, root: Path | None = None) -> list[Outcome]:
    root = Path(root or tempfile.mkdtemp(prefix="txt2sce_reliability_"))
    ws = build(root / "workspace")
    selected = [c for c in cases() if not pattern or re.search(pattern, c.name)]
    with ThreadPoolExecutor(max_workers=jobs) as pool:
        return list(pool.map(lambda c: run_case(c, ws, root), selected))


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m tests.reliability.catalogue", description=__doc__)
    ap.add_argument("-j", "--jobs", type=int, default=2, help="cases run at once (default 2)")
    ap.add_argument("-k", dest="pattern", help="only cases whose name matches this regular expression")
    ap.add_argument("-v", "--verbose", action="store_true", help="one line per case, clean ones too")
    a = ap.parse_args(argv)
    t0 = time.monotonic()
    outcomes = run_catalogue(a.jobs, a.pattern)
    expected = {c.name: c.expected_to_fail_until for c in cases() if c.expected_to_fail_until}
    counts = Counter(o.kind for o in outcomes)
    waived = [o for o in outcomes if o.kind != "clean" and o.case in expected]
    print(f"cases {len(outcomes)}, clean {counts['clean']}, crashes {counts['crash']}, hangs {counts['hang']}, "
          f"losses {counts['loss']} ({time.monotonic() - t0:.0f} s, peak RSS "
          f"{max((o.max_rss_mb for o in outcomes), default=0):.0f} MB)")
    for o in outcomes:
        if o.kind != "clean" or a.verbose:
            note = f"  [expected until {expected[o.case]}]" if o.case in expected and o.kind != "clean" else ""
            print(f"  {o.kind:5s} {o.case:40s} exit {o.exit} {o.seconds:5.1f} s {o.max_rss_mb:5.0f} MB  {o.detail}{note}")
    return 0 if all(o.kind == "clean" or o.case in expected for o in outcomes) else 1


if __name__ == "__main__":
    sys.exit(main())
