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


def test_judge_callgrind_runs_a_marked_loop_and_refuses_bad_usage() -> None:
    # `... rec NAME loop` (the loop alone, marked inside `_lockstep`) must run through with the bag closed; a
    # scenario it does not know is a usage error.
    import subprocess
    import sys

    from txt2sce_ros.bench import judge

    marks: list[int] = []
    judge._lockstep("pedestrian_collision", None, mark=lambda: marks.append(1))
    assert marks == [1, 1]
    ok = subprocess.run([sys.executable, "-m", "txt2sce_ros.bench._judge_callgrind", "rec", "pedestrian_collision",
                         "loop"], capture_output=True, text=True, timeout=300)
    assert ok.returncode == 0, ok.stderr
    bad = subprocess.run([sys.executable, "-m", "txt2sce_ros.bench._judge_callgrind", "rec", "nowhere", "loop"],
                         capture_output=True, text=True, timeout=60)
    assert bad.returncode == 2 and "usage" in bad.stderr
