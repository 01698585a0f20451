"""Regression fingerprints of closed-loop runs with the REAL stand-in planner, to prove that a speed-up of the
planner changed no command. (`scenario_player.fingerprint` drives a toy policy, so it cannot see the planner.)

Per run: SHA-256 of every trajectory row of every entity (raw float64 bytes), and SHA-256 of the verdict record
(verdict, categories, end reason, steps, details). Record the reference with the old code and check the new one
right after: the verdicts also depend on the oracle, which other people change. Also adds up the CPU time of
the whole runs and of their parts: the planner's, the player's and the oracle's calls per step, the oracle's
end of run, and the rest (set-up, the loop itself).

    python -m standin_planner.regress record REF.json FILE_OR_DIR...   # writes the digests
    python -m standin_planner.regress check REF.json FILE_OR_DIR...    # recomputes, lists runs that differ
    python -m standin_planner.regress time FILE_OR_DIR...              # timing only
    python -m standin_planner.regress settings FILE_OR_DIR... --dt 0.1 # what a result-changing setting costs

`settings` runs every file twice, with the defaults and with the settings given (`--dt`: the whole loop's step;
`--time-limit`; `--planner-every N`: the stand-in plans on every N-th frame only and holds its acceleration and
yaw rate in between, as a stack whose planner cycle is N steps), and prints both CPU times and how many verdicts
and categories differ: the price in results of a speed-up that does not leave them identical.

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


#: The parts of a closed-loop run whose CPU time is added up: (label, module, class, method).
_PARTS = (("planner", "standin_planner.planner", "Planner", "step"),
          ("player", "scenario_player.simulation", "Simulation", "step"),
          ("oracle", "oracle_monitor.oracle", "Oracle", "observe"),
          ("oracle end", "oracle_monitor.oracle", "Oracle", "finish"))


class _Timed:
    """CPU time (process_time_ns: the machine is shared, wall time is noise) and calls per part of a run."""

    ns: dict[str, int] = {}
    calls: dict[str, int] = {}


def _install_timer() -> None:
    import importlib

    for label, module, cls_name, method in _PARTS:
        cls = getattr(importlib.import_module(module), cls_name)
        original = getattr(cls, method)
        if getattr(original, "_timed", False):
            continue
        _Timed.ns[label] = _Timed.calls[label] = 0

        def timed(self, *args, _original=original, _label=label):  # type: ignore[no-untyped-def]
            t0 = time.process_time_ns()
            out = _original(self, *args)
            _Timed.ns[_label] += time.process_time_ns() - t0
            _Timed.calls[_label] += 1
            return out

        timed._timed = True  # type: ignore[attr-defined]
        setattr(cls, method, timed)


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


def _hold_between_plans(every: int):  # type: ignore[no-untyped-def]
    """Patch `Planner.step` to plan on every `every`-th frame only, holding the last plan's acceleration and yaw
    rate in between (the perception still sees every frame); returns the original to put back."""
    from txt2sce_ros.contract import ControlCommand

    from .planner import Planner

    original = Planner.step

    def step(self, frame):  # type: ignore[no-untyped-def]
        k = getattr(self, "_regress_k", 0)
        self._regress_k = k + 1
        if k % every == 0 or self.decision is None:
            cmd = original(self, frame)
            self._regress_plan = (frame.t, cmd)
            return cmd
        self.perception.objects(frame)
        t0, cmd = self._regress_plan
        return ControlCommand(t=frame.t, speed=max(0.0, cmd.speed + self.decision.accel * (frame.t - t0)),
                              yaw_rate=cmd.yaw_rate)

    Planner.step = step
    return original


def compare_settings(files: list[Path], *, dt: float | None = None, time_limit: float | None = None,
                     planner_every: int = 1) -> None:
    """Print CPU, steps and verdict deltas of the files run with the defaults and with the given settings. Each
    file is run both ways one after the other, in alternating order (so neither side pays the first run's map
    and route set-up more often), after one untimed run that pays the imports."""
    from txt2sce_ros.closed_loop import run_closed_loop

    from .planner import Planner

    def run(f: Path, label: str) -> tuple[tuple[str, tuple[str, ...]], int, float]:
        original = _hold_between_plans(planner_every) if label == "settings" and planner_every > 1 else None
        try:
            c0 = time.process_time()
            rec, _ = run_closed_loop(f, **({"dt": dt, "time_limit": time_limit} if label == "settings" else {}))
            return (rec.verdict.value, tuple(sorted(rec.categories))), rec.steps, time.process_time() - c0
        finally:
            if original is not None:
                Planner.step = original

    if files:
        run_closed_loop(files[0])
    results: dict[str, dict[Path, tuple[str, tuple[str, ...]]]] = {"defaults": {}, "settings": {}}
    steps = {"defaults": 0, "settings": 0}
    cpu = {"defaults": 0.0, "settings": 0.0}
    for i, f in enumerate(files):
        for label in (("defaults", "settings") if i % 2 == 0 else ("settings", "defaults")):
            results[label][f], n, c = run(f, label)
            steps[label] += n
            cpu[label] += c
    for label, out in results.items():
        counts = {v: sum(1 for got in out.values() if got[0] == v) for v in ("pass", "fail", "error")}
        print(f"{label}: {len(files)} runs, {steps[label]} steps, CPU {cpu[label]:.2f} s "
              f"({cpu[label] / max(len(files), 1) * 1e3:.1f} ms/run); verdicts {counts}")
    a, b = results["defaults"], results["settings"]
    changes: dict[str, int] = {}
    for f in files:
        for c in sorted(set(a[f][1]) ^ set(b[f][1])):
            key = f"{c} {'gained' if c in b[f][1] else 'lost'}"
            changes[key] = changes.get(key, 0) + 1
    print(f"settings (dt {dt or 'default'}, time limit {time_limit or 'default'}, planner every {planner_every} "
          f"frame(s)): CPU x{cpu['settings'] / max(cpu['defaults'], 1e-9):.2f}; verdict differs in "
          f"{sum(a[f][0] != b[f][0] for f in files)} of {len(files)} runs, verdict or categories in "
          f"{sum(a[f] != b[f] for f in files)}; categories: {changes or 'none'}")


def _report(files: list[str] | list[Path], steps: int, cpu: float) -> None:
    ns = _Timed.ns.get("planner", 0)
    per_step = ns / max(_Timed.calls.get("planner", 0), 1) / 1e3
    print(f"{len(files)} runs, {steps} steps, CPU {cpu:.2f} s -> {len(files) / cpu:.2f} runs/s; "
          f"planner {per_step:.1f} us/step ({ns / 1e9:.2f} s, {100 * ns / 1e9 / cpu:.0f}% of CPU)")
    # Where the rest goes: per step for the per-step parts, per run for the end of run; set-up and the loop
    # itself are what remains.
    rest = cpu - sum(_Timed.ns.values()) / 1e9
    parts = [f"{label} {_Timed.ns[label] / max(steps, 1) / 1e3:.1f} us/step" for label in ("player", "oracle")]
    parts.append(f"oracle end {_Timed.ns['oracle end'] / max(len(files), 1) / 1e6:.1f} ms/run")
    parts.append(f"set-up and rest {rest / max(len(files), 1) * 1e3:.1f} ms/run")
    print(f"  CPU {cpu / max(len(files), 1) * 1e3:.1f} ms/run: " + ", ".join(parts))


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m standin_planner.regress")
    ap.add_argument("mode", choices=("record", "check", "time", "settings"))
    ap.add_argument("paths", nargs="+")
    ap.add_argument("--every", type=int, default=1)
    ap.add_argument("--faults", default="", help="comma-separated fault modes switched on in every run")
    ap.add_argument("--dt", type=float, default=None, help="settings: the loop's step (s)")
    ap.add_argument("--time-limit", type=float, default=None, help="settings: simulated seconds per run")
    ap.add_argument("--planner-every", type=int, default=1, help="settings: plan on every N-th frame only")
    args = ap.parse_args(argv)
    if args.mode == "settings":
        if args.planner_every < 1:
            ap.error("--planner-every must be at least 1")
        compare_settings(_files(args.paths, args.every), dt=args.dt, time_limit=args.time_limit,
                         planner_every=args.planner_every)
        return 0
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
