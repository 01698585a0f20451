"""Regression fingerprints of closed-loop runs with the REAL stand-in planner, to prove that a speed-up of the
planner changed no command. (`scenario_player.fingerprint` drives a toy policy, so it cannot see the planner.)

Per run: SHA-256 of every trajectory row of every entity (raw float64 bytes), and SHA-256 of the verdict record
(verdict, categories, end reason, steps, details). Record the reference with the old code and check the new one
right after: the verdicts also depend on the oracle, which other people change. Also times the planner's `step` calls (CPU time) and the whole runs.

    python -m standin_planner.regress record REF.json FILE_OR_DIR...   # writes the digests
    python -m standin_planner.regress check REF.json FILE_OR_DIR...    # recomputes, lists runs that differ
    python -m standin_planner.regress time FILE_OR_DIR...              # timing only

A directory contributes its .xosc files (recursively, sorted); `--every N` keeps every N-th file of a directory,
so a sample of tree nodes stays small.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import sys
import time
from pathlib import Path

import numpy as np


def _files(paths: list[str], every: int) -> list[Path]:
    out: list[Path] = []
    for p in paths:
        path = Path(p)
        if path.is_dir():
            out += sorted(path.rglob("*.xosc"))[::every]
        else:
            out.append(path)
    return out


class _TimedPlanner:
    """Wraps `Planner.step` to add up its CPU time (process_time_ns: the machine is shared, wall time is noise)."""

    ns = 0
    calls = 0


def _install_timer() -> None:
    from standin_planner import planner as planner_mod

    original = planner_mod.Planner.step
    if getattr(original, "_timed", False):
        return

    def step(self, frame):  # type: ignore[no-untyped-def]
        t0 = time.process_time_ns()
        cmd = original(self, frame)
        _TimedPlanner.ns += time.process_time_ns() - t0
        _TimedPlanner.calls += 1
        return cmd

    step._timed = True  # type: ignore[attr-defined]
    planner_mod.Planner.step = step  # type: ignore[method-assign]


def digest_run(path: Path, faults: tuple[str, ...] = ()) -> tuple[dict[str, str], int]:
    """({"trajectory": hex digest, "verdict": hex digest}, steps) of one closed-loop run of `path`. Two digests, so
    a change of the oracle (another package, edited meanwhile) is told apart from a change of the driving."""
    from txt2sce_ros.closed_loop import run_closed_loop

    rec, traj = run_closed_loop(path, faults=faults, keep_trajectory=True)
    v = hashlib.sha256()
    summary = {"verdict": str(rec.verdict), "categories": list(rec.categories), "end_reason": rec.end_reason,
               "steps": rec.steps, "details": rec.details, "error": rec.error}
    v.update(json.dumps(summary, sort_keys=True, default=str).encode())
    h = hashlib.sha256()
    for name in sorted(traj or {}):
        h.update(name.encode() + b"\0")
        h.update(np.ascontiguousarray(traj[name], dtype=np.float64).tobytes())
    return {"trajectory": h.hexdigest(), "verdict": v.hexdigest()}, rec.steps


def run_all(files: list[Path], faults: tuple[str, ...] = ()) -> tuple[dict[str, dict[str, str]], int, float]:
    """Digests by file, total steps, total CPU seconds."""
    _install_timer()
    out: dict[str, dict[str, str]] = {}
    steps = 0
    c0 = time.process_time()
    for f in files:
        d, n = digest_run(f, faults)
        out[str(f)] = d
        steps += n
    return out, steps, time.process_time() - c0


def _report(files: list[Path], steps: int, cpu: float) -> None:
    per_step = _TimedPlanner.ns / max(_TimedPlanner.calls, 1) / 1e3
    print(f"{len(files)} runs, {steps} steps, CPU {cpu:.2f} s -> {len(files) / cpu:.2f} runs/s; "
          f"planner {per_step:.1f} us/step ({_TimedPlanner.ns / 1e9:.2f} s, "
          f"{100 * _TimedPlanner.ns / 1e9 / cpu:.0f}% of CPU)")


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m standin_planner.regress")
    ap.add_argument("mode", choices=("record", "check", "time"))
    ap.add_argument("paths", nargs="+")
    ap.add_argument("--every", type=int, default=1)
    ap.add_argument("--faults", default="", help="comma-separated fault modes switched on in every run")
    args = ap.parse_args(argv)
    ref = None
    if args.mode != "time":
        ref, *args.paths = args.paths
    files = _files(args.paths, args.every)
    digests, steps, cpu = run_all(files, tuple(f for f in args.faults.split(",") if f))
    _report(files, steps, cpu)
    if args.mode == "record":
        Path(ref).write_text(json.dumps(digests, indent=1, sort_keys=True))
        print(f"recorded {len(digests)} digests -> {ref}")
    elif args.mode == "check":
        want = json.loads(Path(ref).read_text())
        bad = 0
        for k, got in digests.items():
            differ = [part for part in ("trajectory", "verdict") if (want.get(k) or {}).get(part) != got[part]]
            if differ:
                bad += 1
                print(f"DIFFERS ({', '.join(differ)}): {k}")
        print(f"{len(digests) - bad}/{len(digests)} identical (trajectories and verdicts)")
        return 1 if bad else 0
    return 0


if __name__ == "__main__":
    sys.exit(main())
