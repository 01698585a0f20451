"""Batch player vs esmini in CPU seconds, over interleaved rounds, for one or more checkouts side by side.

`txt2sce bench player` makes one esmini pass over its 75 files (one process per file) and one batch-player process
over the same files, and prints their ratio. On this shared machine the CPU seconds of either pass move by a fifth
from one minute to the next (cache and sibling-thread contention grow with the load), so one ratio moves as much
as a change worth measuring. Here each of R rounds runs the esmini pass and the batch player of every checkout
given, in an order that rotates from round to round; every round's CPU seconds and speed-ups are printed, then
the median per checkout, so two checkouts (main before a change, and after) are compared in the same minutes
against the same esmini passes. The files, end times and batch child are `bench player`'s (`_vs_esmini`).

    txt2sce bench batch_cpu                          # this checkout, 3 rounds (--quick: 1 round, a fifth of the files)
    python -m txt2sce_ros.bench.batch_cpu --rounds 5 --checkouts /work/base10 /work/h19

A checkout's batch child is started with PYTHONPATH set to that checkout (and as `python -P`, so that the current
directory, perhaps another checkout, does not come first), so any checkout with `scenario_player` and
`txt2sce_ros.bench._vs_esmini.batch_child` can be measured. The children must reach the same end times
(checked: the comparison is only meaningful between runs doing the same work).
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

DESCRIPTION = "batch player vs esmini, CPU s: interleaved rounds, checkouts side by side; load-robust"


def _here() -> Path:
    """The checkout this module was imported from."""
    return Path(__file__).resolve().parents[2]


def _child(checkout: Path, job: str, *, write_bytecode: bool = False) -> tuple[float, float, list]:
    """(CPU s, wall s, end times reached) of one batch-player process of `checkout` over the job."""
    env = dict(os.environ, PYTHONPATH=str(checkout), OPENBLAS_NUM_THREADS=os.environ.get("OPENBLAS_NUM_THREADS", "1"))
    if write_bytecode:
        env.pop("PYTHONDONTWRITEBYTECODE", None)
    r0 = os.times()
    t0 = time.perf_counter()
    # -P: `python -c` would otherwise put the current directory first on sys.path, so a bench started inside one
    # checkout ran that checkout's player for every checkout given (PYTHONPATH comes after it).
    proc = subprocess.run([sys.executable, "-P", "-c", "from txt2sce_ros.bench._vs_esmini import batch_child; "
                           "batch_child()"], input=job, capture_output=True, text=True, env=env, timeout=900,
                          check=False)
    wall = time.perf_counter() - t0
    r1 = os.times()
    if proc.returncode != 0:
        raise SystemExit(f"batch player of {checkout} failed: {proc.stderr.strip()[-300:]}")
    reached = json.loads(proc.stdout.strip().splitlines()[-1])
    return (r1.children_user - r0.children_user) + (r1.children_system - r0.children_system), wall, reached


def _esmini_pass(files: list[Path], tmp: Path) -> tuple[float, float, list[tuple[Path, float]]]:
    """(CPU s, wall s, [(file, end time)]) of esmini run once per file, as `bench player` runs it."""
    from txt2sce_ros.bench._vs_esmini import run_esmini

    cpu = wall = 0.0
    ends: list[tuple[Path, float]] = []
    for i, f in enumerate(files):
        timed, end = run_esmini(f, tmp / f"{i}.log")
        cpu += timed.cpu
        wall += timed.wall
        if end is not None and end > 0:
            ends.append((f, end))
    return cpu, wall, ends


def _load() -> str:
    try:
        return f"{os.getloadavg()[0]:.1f}"
    except OSError:
        return "?"


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m txt2sce_ros.bench.batch_cpu", description=__doc__.split("\n")[0])
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--checkouts", nargs="+", type=Path, default=None,
                    help="checkout directories (each holding scenario_player and txt2sce_ros); default: this one")
    ap.add_argument("--every", type=int, default=1, help="keep every N-th file (1: all 75)")
    args = ap.parse_args(argv)
    from txt2sce_ros.bench._vs_esmini import available, dev_seeds
    from txt2sce_ros.paths import shared_dir

    if args.rounds < 1 or args.every < 1:
        raise SystemExit("--rounds and --every must be at least 1")
    if not available():
        print("esmini not found (../shared/tools/esmini or $TXT2SCE_ESMINI): nothing to compare with")
        return 0
    checkouts = [c.resolve() for c in (args.checkouts or [_here()])]
    for c in checkouts:
        if not (c / "scenario_player").is_dir():
            raise SystemExit(f"{c}: no scenario_player here; not a checkout")
    examples = sorted((shared_dir() / "data" / "conformance" / "esmini" / "xosc").glob("*.xosc"))
    with tempfile.TemporaryDirectory(prefix="bench_batch_cpu_") as tmp_s:
        tmp = Path(tmp_s)
        files = (examples + dev_seeds(tmp / "seeds"))[::args.every]
        _, _, ends = _esmini_pass(files, tmp)        # warms the disk and gives each file's end time
        job = json.dumps([[str(f), end] for f, end in ends])
        for c in checkouts:                          # untimed: may write bytecode, as a user's second run finds it
            _child(c, job, write_bytecode=True)
        print(f"{len(ends)} files, each to esmini's end time; CPU seconds (user + system of the child processes), "
              f"{args.rounds} rounds, order rotating")
        names = [str(c) for c in checkouts]
        ratios: dict[str, list[float]] = {n: [] for n in names}
        cpus: dict[str, list[float]] = {n: [] for n in names}
        es_cpus: list[float] = []
        reached_by: dict[str, list] = {}
        for r in range(args.rounds):
            load0, t0 = _load(), time.strftime("%H:%M:%S")
            order = ["esmini", *names]
            k = r % len(order)
            order = order[k:] + order[:k]
            got: dict[str, float] = {}
            for who in order:
                if who == "esmini":
                    got[who] = _esmini_pass([f for f, _ in ends], tmp)[0]
                else:
                    got[who], _, reached = _child(Path(who), job)
                    reached_by.setdefault(who, reached)
            es_cpus.append(got["esmini"])
            cells = []
            for n in names:
                cpus[n].append(got[n])
                ratios[n].append(got["esmini"] / got[n])
                cells.append(f"{n}: {got[n]:.2f} s, {got['esmini'] / got[n]:.2f}x")
            print(f"round {r + 1} ({t0}, load {load0}; order {', '.join('esmini' if w == 'esmini' else Path(w).name for w in order)}): "
                  f"esmini {got['esmini']:.2f} s; " + "; ".join(cells))
        same = len({json.dumps(v) for v in reached_by.values()}) == 1
        print(f"median esmini {statistics.median(es_cpus):.2f} s CPU")
        for n in names:
            print(f"{n}: median {statistics.median(cpus[n]):.2f} s CPU, speed-up over esmini median "
                  f"{statistics.median(ratios[n]):.2f}x (rounds {', '.join(f'{v:.2f}' for v in ratios[n])}; "
                  f"goal >= 1.5x)")
        print("end times reached: " + ("the same in every checkout" if same else "DIFFER between checkouts"))
        return 0 if same else 1


def run(args: argparse.Namespace) -> int:
    """`txt2sce bench batch_cpu`: this checkout, 3 rounds (`--quick`: 1 round over every fifth file)."""
    return main(["--rounds", "1", "--every", "5"] if args.quick else [])


if __name__ == "__main__":
    sys.exit(main())
