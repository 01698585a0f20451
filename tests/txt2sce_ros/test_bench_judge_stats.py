"""`txt2sce bench judge`'s paired-overhead statistics: overheads are printed as signed percentages of a ratio."""

from __future__ import annotations

from txt2sce_ros.bench.judge import _pct


def test_percent_of_a_ratio() -> None:
    assert _pct(1.081) == "+8.1 %" and _pct(0.95) == "-5.0 %"


def test_offline_callgrind_mode_judges_both_runs() -> None:
    # The load-independent figure of offline judging (docs/performance.md) comes from this mode: it must record
    # the bench's two scenarios into one bag and judge the whole of it, from the module and as a file.
    import re
    import subprocess
    import sys
    from pathlib import Path

    import txt2sce_ros.bench._judge_callgrind as mod

    for cmd in ([sys.executable, "-m", "txt2sce_ros.bench._judge_callgrind", "offline"],
                [sys.executable, str(Path(mod.__file__)), "offline"]):
        out = subprocess.run(cmd, capture_output=True, text=True, timeout=300, check=True).stdout
        m = re.search(r"offline judging: (\d+) messages, (\d+) runs", out)
        assert m is not None, out
        assert int(m.group(1)) > 9000 and int(m.group(2)) == 2
