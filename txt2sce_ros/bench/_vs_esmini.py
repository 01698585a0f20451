"""The player beside the reference player (esmini, `scenario_player.esmini`), both started cold, in one run:

- cold: one `txt2sce play FILE --ego-mode storyboard` process vs one headless esmini process on the same file;
- batch: one player process over many files vs esmini run one process per file, each file to the same end time
  (esmini's, read from its log: our run gets it as its time limit, so neither simulates longer).

Wall seconds and CPU seconds (user + system of the child processes) are both printed: on a shared machine the CPU
figure is the one other jobs do not inflate. `txt2sce bench player` prints these beside its other figures.
"""

from __future__ import annotations

import json
import os
import re
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

STEP = 0.05        # s, as the shared reference trajectories and `esmini-check`
_TIME = re.compile(r"^\[(\d+(?:\.\d+)?)\]")


@dataclass(frozen=True, slots=True)
class Timed:
    """One measured piece of work done by child processes."""

    wall: float    # s
    cpu: float     # s, user + system of the children


def _children_cpu() -> float:
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def _timed_run(cmd: Sequence[str], cwd: Path | None = None) -> tuple[Timed, int]:
    c0, t0 = _children_cpu(), time.perf_counter()
    rc = subprocess.run(list(cmd), cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                        timeout=300, check=False).returncode
    return Timed(time.perf_counter() - t0, _children_cpu() - c0), rc


def esmini_command(xosc: Path, log: Path) -> list[str]:
    from scenario_player.esmini import esmini_dir

    return [str(esmini_dir() / "esmini"), "--headless", "--osc", str(xosc.resolve()), "--fixed_timestep", f"{STEP:g}",
            "--logfile_path", str(log)]


def run_esmini(xosc: Path, log: Path) -> tuple[Timed, float | None]:
    """One cold esmini run of `xosc` (from its own directory, as `esmini-check`): its cost and the simulation time
    it ended at (the last time stamp of its log; None when it wrote none)."""
    timed, _rc = _timed_run(esmini_command(xosc, log), cwd=xosc.resolve().parent)
    end = None
    if log.is_file():
        for line in log.read_text(encoding="utf-8", errors="replace").splitlines():
            m = _TIME.match(line)
            if m:
                end = float(m.group(1))
    return timed, end


def play_command() -> list[str]:
    """`txt2sce` as a user starts it: the console script beside this interpreter, else the module."""
    script = Path(sys.executable).with_name("txt2sce")
    return [str(script)] if script.is_file() else [sys.executable, "-m", "txt2sce_ros.cli.main"]


def cold_pair(xosc: Path, repeats: int) -> tuple[list[Timed], list[Timed]]:
    """`repeats` alternating cold runs of our `txt2sce play` and of esmini on the same file."""
    ours, theirs = [], []
    with tempfile.TemporaryDirectory(prefix="bench_cold_") as tmp:
        # One untimed run first, allowed to write bytecode: a cold start here is a new process, as a user's second
        # run is, not a first run compiling every module (PYTHONDONTWRITEBYTECODE, set in some shells and CI,
        # would otherwise make every timed run compile the sources again); esmini's first run warms the disk.
        warm_env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
        subprocess.run([*play_command(), "play", str(xosc), "--ego-mode", "storyboard"], env=warm_env,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=300, check=False)
        run_esmini(xosc, Path(tmp) / "warm.log")
        for i in range(repeats):
            t, rc = _timed_run([*play_command(), "play", str(xosc), "--ego-mode", "storyboard"])
            if rc != 0:
                raise RuntimeError(f"txt2sce play {xosc} exited with {rc}")
            ours.append(t)
            theirs.append(run_esmini(xosc, Path(tmp) / f"cold{i}.log")[0])
    return ours, theirs


def batch_child() -> None:
    """In the batch child process: read [[path, end time], ...] from stdin, run each file in the batch player
    (storyboard drives every entity) to that time, print the end times reached (null: the file failed)."""
    from scenario_player import Simulation, SimulationConfig, load_scenario
    from txt2sce_ros.errors import Txt2SceError

    out: list[float | None] = []
    for path, end in json.load(sys.stdin):
        try:
            sim = Simulation(load_scenario(path), SimulationConfig.from_config(
                ego_mode="storyboard", dt=STEP, time_limit=end))
            out.append(sim.run().t)
        except Txt2SceError:
            out.append(None)
    print(json.dumps(out))


@dataclass(frozen=True, slots=True)
class BatchResult:
    files: int
    ours: Timed
    esmini: Timed
    sim_seconds: float           # the sum of esmini's end times
    ours_sim_seconds: float      # the same, as our runs ended
    failed: tuple[str, ...]      # files our player refused


def batch_pair(files: Sequence[Path]) -> BatchResult:
    """esmini one process per file (which also gives each file's end time), then one player process over all the
    files to those end times."""
    ends: list[tuple[Path, float]] = []
    es_wall = es_cpu = 0.0
    with tempfile.TemporaryDirectory(prefix="bench_batch_") as tmp:
        for i, f in enumerate(files):
            timed, end = run_esmini(f, Path(tmp) / f"{i}.log")
            es_wall += timed.wall
            es_cpu += timed.cpu
            if end is not None and end > 0:
                ends.append((f, end))
    job = json.dumps([[str(f), end] for f, end in ends])
    c0, t0 = _children_cpu(), time.perf_counter()
    # -P: the player PYTHONPATH (or the install) names, not one that happens to sit in the current directory.
    proc = subprocess.run([sys.executable, "-P", "-c", "from txt2sce_ros.bench._vs_esmini import batch_child; "
                           "batch_child()"], input=job, capture_output=True, text=True, timeout=900, check=False)
    ours = Timed(time.perf_counter() - t0, _children_cpu() - c0)
    if proc.returncode != 0:
        raise RuntimeError(f"batch player failed: {proc.stderr.strip()[-300:]}")
    reached = json.loads(proc.stdout.strip().splitlines()[-1])
    failed = tuple(f.name for (f, _), r in zip(ends, reached) if r is None)
    return BatchResult(len(ends), ours, Timed(es_wall, es_cpu), sum(e for _, e in ends),
                       sum(r for r in reached if r is not None), failed)


def dev_seeds(out: Path) -> list[Path]:
    """The dev-gold sketches' seeds, written into `out` (as `txt2sce seed`)."""
    from txt2sce_ros.paths import shared_dir
    from txt2sce_ros.seed import write_seeds
    from txt2sce_ros.sketch import load_sketches

    manifest = write_seeds(load_sketches(shared_dir() / "data" / "reports" / "dev_gold.jsonl"), out, seed=0)
    return [out / e["file"] for e in manifest["built"]]


def available() -> bool:
    from scenario_player.esmini import available as have

    return have()


def report(examples: Sequence[Path], *, quick: bool) -> dict[str, float]:
    """Run both comparisons and print them; the figures as a dict for the bench's JSON line."""
    cut_in = next(f for f in examples if f.name == "cut-in.xosc")
    ours, theirs = cold_pair(cut_in, 3 if quick else 7)
    med = {k: statistics.median(getattr(t, k) for t in ours) for k in ("wall", "cpu")}
    emed = {k: statistics.median(getattr(t, k) for t in theirs) for k in ("wall", "cpu")}
    print(f"\nCold start, {cut_in.name} (one process each, median of {len(ours)} alternating runs)")
    print(f"txt2sce play --ego-mode storyboard: {med['wall'] * 1000:.0f} ms wall, {med['cpu'] * 1000:.0f} ms CPU; "
          f"esmini: {emed['wall'] * 1000:.0f} ms wall, {emed['cpu'] * 1000:.0f} ms CPU; ratio "
          f"{med['wall'] / emed['wall']:.2f}x wall, {med['cpu'] / emed['cpu']:.2f}x CPU (goal <= 3x)")
    with tempfile.TemporaryDirectory(prefix="bench_seeds_") as tmp:
        files = list(examples) + dev_seeds(Path(tmp) / "seeds")
        if quick:
            files = files[::5]
        b = batch_pair(files)
    print(f"\nBatch, {b.files} files (the shared examples + the dev seeds), each to esmini's end time "
          f"({b.sim_seconds:.1f} sim s in all; ours reached {b.ours_sim_seconds:.1f})")
    print(f"batch player, one process: {b.ours.wall:.2f} s wall, {b.ours.cpu:.2f} s CPU "
          f"({b.ours_sim_seconds / b.ours.wall:.0f}x real time, cold process); esmini, one process per file: "
          f"{b.esmini.wall:.2f} s wall, {b.esmini.cpu:.2f} s CPU; speed-up {b.esmini.wall / b.ours.wall:.2f}x wall, "
          f"{b.esmini.cpu / b.ours.cpu:.2f}x CPU (goal >= 1.5x)"
          + (f"; refused by our player: {', '.join(b.failed)}" if b.failed else ""))
    return {"cold_play_ms": round(med["wall"] * 1000), "cold_esmini_ms": round(emed["wall"] * 1000),
            "cold_ratio_wall": round(med["wall"] / emed["wall"], 2), "cold_ratio_cpu": round(med["cpu"] / emed["cpu"], 2),
            "batch_speedup_wall": round(b.esmini.wall / b.ours.wall, 2),
            "batch_speedup_cpu": round(b.esmini.cpu / b.ours.cpu, 2)}
