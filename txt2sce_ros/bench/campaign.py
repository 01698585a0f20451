"""`txt2sce bench campaign`: a paper-scale campaign end to end on this machine, beside baselines from the same run.

1. Scale: the dev-gold sketches -> seeds -> trees with the default mutation settings (config/mutation.yaml) and a
   node budget of 1/8 of the target per tree, seeds taken in manifest order until the trees hold >= the target
   (default 4,000 scenarios, the paper's scale),
   -> every scenario closed-loop in-process on the process pool -> verdicts in the store -> analysis report.
   Printed: wall time per stage and end to end, scenarios/s of the run stage.
2. Baseline: the serial executor on a sample of the same scenarios (same run, same machine load).
3. ROS-graph mode (`--ros` path: one node graph per run in its own ROS domain, verdict from the recorded bag)
   on a small sample, beside the in-process path on the same sample.
4. Profile: cProfile over a few in-process runs, the top functions per package (player / planner / oracle / road),
   so each owner sees where a run's time goes.

`--quick`: 300 scenarios, smaller samples. Another scale from Python:
`run(argparse.Namespace(quick=False, seed=0, scenarios=1000))`. The figures are measurements on whatever load the
machine has; the load average and the run stage's CPU seconds are printed beside them.
"""

from __future__ import annotations

import argparse
import cProfile
import json
import os
import pstats
import resource
import shutil
import tempfile
import time
from collections import defaultdict
from pathlib import Path

DESCRIPTION = "paper-scale campaign (>= 4,000 scenarios) wall time and scenarios/s; serial and ROS-graph baselines"

PACKAGES = ("scenario_player", "standin_planner", "oracle_monitor", "txt2sce_ros/road", "numpy", "lxml")


def _grow_trees(seed_dir: Path, out: Path, target: int, seed: int) -> tuple[int, int]:
    """Trees from the seeds in manifest order until they hold `target` scenarios; (trees, scenarios)."""
    from txt2sce_ros.tree.build import build_trees, tree_config

    manifest = json.loads((seed_dir / "manifest.json").read_text(encoding="utf-8"))
    seeds = [seed_dir / e["file"] for e in manifest["built"]]
    # Default mutation settings, but a node budget of target/8 per tree: the campaign then spans >= 8 seeds (the
    # config's 2,000-node budget would make a 4,000-scenario campaign out of the first two seeds alone).
    cfg = tree_config(max_nodes=max(50, target // 8))
    total, trees, i = 0, 0, 0
    while total < target and i < len(seeds):
        batch = seeds[i:i + 2]            # two at a time: the two cores
        i += len(batch)
        for r in build_trees(batch, out, seed=seed, cfg=cfg, jobs=2):
            total += r.nodes
            trees += 1
    return trees, total


def _cpu() -> float:
    """CPU seconds used so far by this process and its finished children (pool workers, once the pool closed)."""
    me, kids = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
    return me.ru_utime + me.ru_stime + kids.ru_utime + kids.ru_stime


def _rate(n: int, seconds: float) -> str:
    return f"{n / seconds:.2f} scenarios/s" if seconds > 0 else "–"


def _profile(files: list[str], time_limit: float | None) -> dict[str, list[tuple[str, float, int]]]:
    """Own time (tottime) per function over in-process runs, grouped by package, top 5 each."""
    from txt2sce_ros.closed_loop import run_closed_loop

    prof = cProfile.Profile()
    prof.enable()
    for f in files:
        run_closed_loop(f, time_limit=time_limit)
    prof.disable()
    stats = pstats.Stats(prof)
    per: dict[str, list[tuple[str, float, int]]] = defaultdict(list)
    totals: dict[str, float] = defaultdict(float)
    for (path, line, name), (_cc, ncalls, tottime, _ct, _callers) in stats.stats.items():  # type: ignore[attr-defined]
        pkg = next((p for p in PACKAGES if f"/{p}/" in path), "other")
        totals[pkg] += tottime
        short = path.split(f"/{pkg}/", 1)[-1] if pkg != "other" else Path(path).name
        per[pkg].append((f"{short}:{line} {name}", tottime, ncalls))
    out = {}
    for pkg in sorted(per, key=lambda p: -totals[p]):
        out[f"{pkg} ({totals[pkg]:.2f} s)"] = sorted(per[pkg], key=lambda r: -r[1])[:5]
    return out


_PLAIN_RUNS = """
import sys, time
from txt2sce_ros.closed_loop import run_closed_loop
run_closed_loop(sys.argv[1])            # imports and first-use caches out of the figure, as in the pool's workers
t0 = time.process_time()
for f in sys.argv[1:]:
    run_closed_loop(f)
print((time.process_time() - t0) / (len(sys.argv) - 1))
"""

# (the first file once before: imports and first-use caches are not what a campaign's runs spend)
_PLAIN_PROFILE = """
import json, sys
from txt2sce_ros.bench.campaign import _profile
from txt2sce_ros.closed_loop import run_closed_loop
run_closed_loop(sys.argv[1])
print(json.dumps(_profile(sys.argv[1:], None)))
"""


def _compiled_here() -> bool:
    from txt2sce_ros import accel

    return not accel.switched_off() and "built" in accel.status().values()


def _in_plain_process(code: str, files: list[str], what: str) -> str | None:
    """The last line `code` prints, run over `files` in a process with the compiled build switched off (None, and a
    note, when it fails)."""
    import subprocess
    import sys

    from txt2sce_ros import accel

    done = subprocess.run([sys.executable, "-c", code, *files], capture_output=True, text=True,
                          env={**os.environ, accel.ENV_SWITCH: "0"})
    if done.returncode != 0 or not done.stdout.strip():
        print(f"  ({what} failed: {done.stderr.strip().splitlines()[-1:]})")
        return None
    return done.stdout.strip().splitlines()[-1]


def _plain_cpu_per_run(files: list[str]) -> float | None:
    """CPU seconds a run of `files` costs from the plain source, in a fresh process; None when there is nothing to
    compare (no compiled build here, or it is switched off already)."""
    if not files or not _compiled_here():
        return None
    out = _in_plain_process(_PLAIN_RUNS, files, "plain-source baseline")
    return None if out is None else float(out)


def _plain_profile(files: list[str]) -> dict[str, list[tuple[str, float, int]]]:
    """`_profile` of the plain source: here when nothing is compiled, else in a process with the build switched
    off (cProfile sees no function of a compiled module)."""
    if not _compiled_here():
        return _profile(files, None)
    out = _in_plain_process(_PLAIN_PROFILE, files, "profile")
    return {} if out is None else {pkg: [tuple(r) for r in rows] for pkg, rows in json.loads(out).items()}


def run(args: argparse.Namespace) -> int:
    from txt2sce_ros.campaign.pipeline import CampaignConfig, seed_stage
    from txt2sce_ros.campaign.reporting import report_from_store
    from txt2sce_ros.campaign.runs import make_tasks, run_all
    from txt2sce_ros.campaign.store import ResultStore
    from txt2sce_ros.paths import shared_dir

    quick = getattr(args, "quick", False)
    # `scenarios` is not a `txt2sce bench` option (yet): set it from Python to measure another scale
    target = getattr(args, "scenarios", None) or (300 if quick else 4000)
    serial_n = 20 if quick else 60
    ros_n = 2 if quick else 4
    prof_n = 3 if quick else 8
    sketches = shared_dir() / "data" / "reports" / "dev_gold.jsonl"
    tmp = Path(tempfile.mkdtemp(prefix="txt2sce_bench_campaign_"))
    workers = os.cpu_count() or 2
    from txt2sce_ros import accel

    print(f"bench campaign: {sketches.name} -> >= {target} scenarios, {workers} cores, "
          f"load average {os.getloadavg()[0]:.1f} at start; work dir {tmp}; {accel.describe()}")
    try:
        cfg = CampaignConfig(out=tmp, seed=args.seed, progress=True)
        t_start = time.perf_counter()
        seed_dir, manifest = seed_stage(sketches, cfg)
        t_seeds = time.perf_counter()
        trees, scenarios = _grow_trees(seed_dir, tmp / "trees", target, args.seed)
        t_trees = time.perf_counter()
        tasks = make_tasks([tmp / "trees"], seed=args.seed)
        with ResultStore(tmp / "results.sqlite") as store:
            cpu0 = _cpu()
            summary = run_all(tasks, store, executor="pool", workers=workers, progress=True)
            t_runs = time.perf_counter()
            cpu_runs = _cpu() - cpu0
            report_from_store(store, [tmp / "trees"], tmp / "report", tasks=tasks)
        t_end = time.perf_counter()
        runs_s = t_runs - t_trees
        print(f"\nscale ({len(manifest['built'])} seeds built, {trees} trees grown, default mutation settings):")
        print(f"  seeds        {t_seeds - t_start:7.1f} s")
        print(f"  trees        {t_trees - t_seeds:7.1f} s  ({scenarios} scenarios)")
        print(f"  closed loop  {runs_s:7.1f} s  ({summary.ran} runs, pool x{workers}: {_rate(summary.ran, runs_s)}; "
              f"verdicts {dict(sorted(summary.verdicts.items()))})")
        print(f"  report       {t_end - t_runs:7.1f} s")
        # The machine is shared: CPU seconds say what the same work costs on {workers} idle cores.
        print(f"  closed loop CPU time {cpu_runs:.1f} s -> on {workers} idle cores about {cpu_runs / workers:.0f} s "
              f"({summary.ran * workers / cpu_runs:.2f} scenarios/s)")
        print(f"  end to end   {t_end - t_start:7.1f} s = {(t_end - t_start) / 60:.1f} min "
              f"({_rate(len(tasks), t_end - t_start)}; goal <= 2 min for 4,000)")
        if target != 4000:
            proj = (t_trees - t_start) + cpu_runs / workers * 4000 / max(1, summary.ran) + (t_end - t_runs)
            print(f"  projection to 4,000 scenarios on {workers} idle cores (run CPU time scaled): "
                  f"{proj / 60:.1f} min")

        # Baseline: the serial executor on every k-th task (a spread sample), in a fresh store.
        step = max(1, len(tasks) // serial_n)
        sample = tasks[::step][:serial_n]
        with ResultStore(tmp / "serial.sqlite") as store:
            t0, c0 = time.perf_counter(), _cpu()
            run_all(sample, store, executor="serial", progress=False)
            t_serial, cpu_serial = time.perf_counter() - t0, _cpu() - c0
        plain = _plain_cpu_per_run([t.scenario_path for t in sample])
        pool_rate = summary.ran / runs_s if runs_s > 0 else 0.0
        serial_rate = len(sample) / t_serial
        # Wall rates taken minutes apart on a shared machine are not comparable; CPU seconds per run are.
        print(f"\nbaseline: serial executor, {len(sample)} of the same scenarios (every {step}th): "
              f"{_rate(len(sample), t_serial)} wall, {cpu_serial / len(sample):.3f} CPU s/run "
              f"(pool above: {pool_rate:.2f} scenarios/s wall, {cpu_runs / max(1, summary.ran):.3f} CPU s/run "
              f"incl. worker start-up and result shipping)")
        if plain is not None:
            print(f"baseline: the same {len(sample)} runs from the plain Python source (TXT2SCE_ACCEL=0, one "
                  f"process): {plain:.3f} CPU s/run vs {cpu_serial / len(sample):.3f} as set up here "
                  f"(x{plain / max(cpu_serial / len(sample), 1e-9):.2f})")

        # ROS-graph mode on a small sample, beside the in-process path on the same sample.
        ros_sample = sample[:ros_n]
        ros_tasks = make_tasks([t.scenario_path for t in ros_sample], seed=args.seed, ros=True)
        with ResultStore(tmp / "ros.sqlite") as store:
            t0 = time.perf_counter()
            ros_summary = run_all(ros_tasks, store, executor="pool", workers=workers, progress=False)
            t_ros = time.perf_counter() - t0
            # keyed by file: scenario ids repeat across trees (every tree has an n0)
            ros_path = {t.key: t.scenario_path for t in ros_tasks}
            ros_runs = {ros_path[r.run_key]: (r.verdict, r.categories) for r in store.runs()}
        with ResultStore(tmp / "serial.sqlite") as store:
            in_path = {t.key: t.scenario_path for t in sample}
            inproc = {in_path[r.run_key]: (r.verdict, r.categories) for r in store.runs() if r.run_key in in_path}
        agree = sum(ros_runs.get(t.scenario_path) == inproc.get(t.scenario_path) for t in ros_sample)
        for t in ros_sample:
            if ros_runs.get(t.scenario_path) != inproc.get(t.scenario_path):
                print(f"  differs: {t.tree}/{t.scenario_id}: ROS {ros_runs.get(t.scenario_path)} "
                      f"vs in-process {inproc.get(t.scenario_path)}")
        print(f"ROS graph (--ros, one domain per worker, pool x{workers}), {len(ros_tasks)} scenarios: "
              f"{_rate(len(ros_tasks), t_ros)} (verdicts {dict(sorted(ros_summary.verdicts.items()))}); "
              f"in-process serial on the same: {serial_rate:.2f} scenarios/s; "
              f"same verdict and categories in {agree}/{len(ros_sample)}")

        # Where a run's time goes. cProfile sees no function of a compiled module: the profile runs the plain
        # source (in a process of its own when this one runs compiled code).
        prof_files = [t.scenario_path for t in sample[:prof_n]]
        print(f"\nprofile: cProfile own time over {len(prof_files)} in-process runs from the plain source, top "
              f"functions per package")
        for pkg, rows in _plain_profile(prof_files).items():
            print(f"  {pkg}")
            for name, tottime, ncalls in rows:
                print(f"    {tottime:6.2f} s  {ncalls:>8} calls  {name}")
        print(f"\nload average at end: {os.getloadavg()[0]:.1f} (1 min), {os.getloadavg()[2]:.1f} (15 min)")
    finally:
        if not getattr(args, "keep", False):
            shutil.rmtree(tmp, ignore_errors=True)
    return 0
