"""One lock-step run of `bench judge`, plain or recorded, marked for callgrind: the recording overhead in
instructions, which the machine's load does not move (the CPU-time ratio of `txt2sce bench judge` swings by ±10
points between pairs on this shared VM).

    valgrind --tool=callgrind --trace-children=yes --dump-before=getppid --callgrind-out-file=cg.%p \\
        python -m txt2sce_ros.bench._judge_callgrind {plain|rec} {pedestrian_collision|traffic_lights}

The run is callgrind's part 2 (`grep totals cg.<pid>.2`): between two `os.getppid()` calls, after one warm-up run
of each kind (imports, map caches, the road message, compiled step layouts) and a full garbage collection (a full
collection of the process's objects costs ~30 M instructions and would otherwise fall into one run or the other
by the allocation count). `--trace-children` because the ROS wheels re-exec the interpreter at start-up. The
recorder flushes by size only here (`flush_interval=1e9`): under valgrind's ~50x slow-down its 0.5 s wall-clock
flush would cut the run into hundreds of tiny drains a native run never makes. Compare a `rec` run with a `plain`
run of the same scenario (and a checkout of the code before a change with one after, via PYTHONPATH).

    ... python -m txt2sce_ros.bench._judge_callgrind {plain|rec} NAME loop

marks the loop alone instead (part 2 starts after the run's set-up: scenario, map, planner, oracle) and keeps the
collector off during it, so a collection falling in or out of the run (±3 M) does not move the difference.

    ... python -m txt2sce_ros.bench._judge_callgrind offline

measures offline judging instead: the bench's judging input with one copy of each scenario (both runs recorded
into one bag, ~10,100 messages), judged once as a warm-up and once as part 2 (`judge_bag`: reading, decoding,
frames, oracle, verdicts). Instructions per message = part 2's total / the message count it prints. Run as a
file (`python .../_judge_callgrind.py offline`) with PYTHONPATH on another checkout, it judges with that code.
"""

from __future__ import annotations

import gc
import os
import shutil
import sys
import tempfile
from pathlib import Path


def main(argv: list[str] | None = None) -> int:
    from oracle_monitor.runwriter import RunWriter

    from .judge import SCENARIOS, _lockstep

    args = sys.argv[1:] if argv is None else argv
    if args == ["offline"]:
        return _offline()
    loop = args[2:] == ["loop"]
    if len(args) != 2 + loop or args[0] not in ("plain", "rec") or args[1] not in SCENARIOS:
        print(f"usage: python -m txt2sce_ros.bench._judge_callgrind {{plain|rec}} {{{'|'.join(SCENARIOS)}}} [loop] "
              f"| offline", file=sys.stderr)
        return 2
    mode, name = args[:2]
    tmp = Path(tempfile.mkdtemp(prefix="txt2sce_judge_callgrind_"))
    try:
        _lockstep(name, None)
        w = RunWriter(tmp / "warm", flush_interval=1e9)
        _lockstep(name, w)
        w.close()
        gc.collect()
        # callgrind dumps part 1 at the first getppid: what follows is the measured run (with `loop`, from the
        # loop's start, marked inside `_lockstep`; its second mark is skipped so the bag's closing counts too).
        marks = [os.getppid] if loop else []
        if loop:
            gc.disable()
        else:
            os.getppid()
        mark = lambda: marks.pop()() if marks else None    # noqa: E731
        if mode == "rec":
            w = RunWriter(tmp / "run", flush_interval=1e9)
            _lockstep(name, w, mark=mark)
            w.close()
        else:
            _lockstep(name, None, mark=mark)
        os.getppid()                        # end of part 2
        gc.enable()
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    return 0


def _offline() -> int:
    from oracle_monitor.bagread import read_bag
    from oracle_monitor.judge import judge_bag
    from oracle_monitor.runwriter import RunWriter
    # Absolute: the file also runs as a script over another checkout's packages (PYTHONPATH), for a before figure.
    from txt2sce_ros.bench.judge import SCENARIOS, _lockstep

    tmp = Path(tempfile.mkdtemp(prefix="txt2sce_judge_callgrind_"))
    try:
        bag = tmp / "judge_input"
        with RunWriter(bag, flush_interval=1e9) as w:
            for name in SCENARIOS:
                _lockstep(name, w)
        messages = sum(1 for _ in read_bag(bag).messages())
        judge_bag(bag)
        gc.collect()
        os.getppid()                        # callgrind dumps part 1 here: what follows is the measured judging
        result = judge_bag(bag)
        os.getppid()                        # end of part 2
        print(f"offline judging: {messages} messages, {len(result.verdicts)} runs")
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(_offline() if sys.argv[1:] == ["offline"] else main())
