"""The batch player's work marked for callgrind: set-up and steps apart, in instructions, which the machine's load
does not move (one batch process's CPU seconds swing by a fifth from minute to minute on this shared VM).

    python -m txt2sce_ros.bench._batch_callgrind job DIR        # DIR/job.json: the bench's 75 files, esmini's end times
    valgrind --tool=callgrind --trace-children=yes --dump-before=getppid --callgrind-out-file=cg.%p \\
        python -m txt2sce_ros.bench._batch_callgrind split DIR/job.json

`job` writes the dev seeds into DIR and runs the shared esmini once per file for its end time, as `bench player`
and `bench batch_cpu` do (the seeds stay in DIR, which the job names). `split` loads and resets every file of the
job (imports, XML, maps, lane tracks, routes: callgrind's part 1, `grep totals cg.<pid>.1`), then steps every run
to its end time (part 2), then exits (the last part); it prints the steps taken and the first end times.
`--trace-children` because the ROS wheels re-exec the interpreter at start-up; run with bytecode written
beforehand (one run without PYTHONDONTWRITEBYTECODE), as the bench's untimed first child leaves it. The same job
run by `batch_child` (`python -c "from txt2sce_ros.bench._vs_esmini import batch_child; batch_child()" < job.json`)
gives the whole child's count. A checkout without this module (one before a change) is measured by running this
file by its path with PYTHONPATH set to that checkout: it imports the player and `_vs_esmini.STEP` from there.
"""

from __future__ import annotations

import gc
import json
import os
import sys
from pathlib import Path


def _job(out: Path) -> int:
    from txt2sce_ros.paths import shared_dir

    from txt2sce_ros.bench._vs_esmini import available, dev_seeds, run_esmini

    if not available():
        print("esmini not found (../shared/tools/esmini or $TXT2SCE_ESMINI)")
        return 1
    out.mkdir(parents=True, exist_ok=True)
    examples = sorted((shared_dir() / "data" / "conformance" / "esmini" / "xosc").glob("*.xosc"))
    files = examples + dev_seeds(out / "seeds")
    ends = []
    for i, f in enumerate(files):
        _timed, end = run_esmini(f, out / f"esmini_{i}.log")
        if end is not None and end > 0:
            ends.append([str(f), end])
    (out / "job.json").write_text(json.dumps(ends), encoding="utf-8")
    print(f"{len(ends)} files -> {out / 'job.json'}")
    return 0


def _split(job: Path) -> int:
    from scenario_player import Simulation, SimulationConfig, load_scenario

    from txt2sce_ros.bench._vs_esmini import STEP

    sims = []
    for path, end in json.loads(job.read_text(encoding="utf-8")):
        sim = Simulation(load_scenario(path), SimulationConfig.from_config(ego_mode="storyboard", dt=STEP,
                                                                           time_limit=end))
        sim.reset()
        sims.append(sim)
    gc.collect()
    os.getppid()                # callgrind: part 1 ends (set-up), part 2 begins (steps)
    steps = 0
    for sim in sims:
        while not sim.done:
            sim.advance(None)
            steps += 1
    os.getppid()                # part 2 ends
    print(steps, [s.t for s in sims][:3])
    return 0


def main(argv: list[str] | None = None) -> int:
    args = sys.argv[1:] if argv is None else argv
    if len(args) == 2 and args[0] == "job":
        return _job(Path(args[1]))
    if len(args) == 2 and args[0] == "split":
        return _split(Path(args[1]))
    print(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main())
