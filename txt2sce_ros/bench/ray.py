"""`txt2sce bench ray`: campaign runs per second on a Ray cluster of one node vs two (simulated on this machine with
`ray.cluster_utils.Cluster`, one CPU per node), beside the serial executor and the process pool on the same runs.

The runs are the closed-loop runs of the first dev-gold seeds (`--scenarios`, default 16, --quick 8), shipped as
self-contained jobs (scenario + map text, maps put once per map). Each Ray configuration first runs one short
warm-up job per CPU so worker start-up (Python imports) is not counted; the figures are wall-clock runs/s on
whatever load the machine has (printed beside them): two simulated nodes on a 2-core machine shared with other
work cannot show what two machines would.
"""

from __future__ import annotations

import argparse
import itertools
import os
import shutil
import tempfile
import time
from dataclasses import replace
from pathlib import Path
from typing import Any

DESCRIPTION = "campaign runs/s on a Ray cluster of 1 node vs 2 (simulated), beside serial and the process pool"

#: Simulated seconds per run: long enough that a run's work dominates the per-task overhead.
TIME_LIMIT = 10.0


def _timed(jobs: list[Any], **kwargs: Any) -> tuple[float, dict[str, str]]:
    from txt2sce_ros.campaign.executors import run_tasks
    from txt2sce_ros.campaign.runs import execute

    t0 = time.perf_counter()
    verdicts = {r.run_key: r.verdict for r in run_tasks(execute, jobs, **kwargs)}
    return time.perf_counter() - t0, verdicts


def _on_cluster(cpus_per_node: list[int], jobs: list[Any], warm: list[Any]) -> tuple[float, dict[str, str]]:
    import ray

    from txt2sce_ros.campaign.ray_cluster import simulated_cluster

    with simulated_cluster(cpus_per_node) as cluster:
        # one driver connection for warm-up and measurement: the workers it started stay up between the two
        ray.init(address=cluster.address, include_dashboard=False, log_to_driver=False, logging_level="ERROR")
        try:
            _timed(warm, executor="ray")
            return _timed(jobs, executor="ray")
        finally:
            ray.shutdown()


def run(args: argparse.Namespace) -> int:
    from txt2sce_ros.campaign.runs import jobs, make_tasks
    from txt2sce_ros.paths import shared_dir
    from txt2sce_ros.seed import write_seeds
    from txt2sce_ros.sketch import load_sketches

    n = getattr(args, "scenarios", None) or (8 if getattr(args, "quick", False) else 16)
    tmp = Path(tempfile.mkdtemp(prefix="txt2sce_bench_ray_"))
    try:
        sketches = shared_dir() / "data" / "reports" / "dev_gold.jsonl"
        manifest = write_seeds(itertools.islice(load_sketches(sketches), n + 8), tmp / "seeds", seed=args.seed)
        files = [tmp / "seeds" / e["file"] for e in manifest["built"]][:n]
        shipped = list(jobs(make_tasks(files, seed=args.seed, time_limit=TIME_LIMIT)))
        # warm-up jobs: same scenarios, a 1 s limit (their results are not kept)
        warm = [replace(j, time_limit=1.0) for j in shipped[:2]]
        print(f"bench ray: {len(shipped)} closed-loop runs of {TIME_LIMIT:g} simulated s from {sketches.name} "
              f"seeds; {os.cpu_count()} cores, load average {os.getloadavg()[0]:.1f} at start")
        rows: list[tuple[str, float, dict[str, str]]] = []
        rows.append(("serial (baseline)", *_timed(shipped, executor="serial")))
        rows.append(("pool, 2 workers", *_timed(shipped, executor="pool", workers=2)))
        rows.append(("ray, 1 node x 1 CPU", *_on_cluster([1], shipped, warm)))
        rows.append(("ray, 2 nodes x 1 CPU", *_on_cluster([1, 1], shipped, warm)))
        # the baseline again: how far the machine's load drifted while the rows above were measured
        rows.append(("serial again (drift)", *_timed(shipped, executor="serial")))
        base = rows[0][1]
        print(f"{'executor':<24}{'wall s':>9}{'runs/s':>9}{'vs serial':>11}")
        for name, secs, _ in rows:
            print(f"{name:<24}{secs:>9.1f}{len(shipped) / secs:>9.2f}{base / secs:>10.2f}x")
        one, two = rows[2][1], rows[3][1]
        print(f"ray 2 nodes vs 1 node: {one / two:.2f}x runs/s (simulated nodes share this machine's cores; "
              f"load average {os.getloadavg()[0]:.1f} at end)")
        same = all(r[2] == rows[0][2] for r in rows[1:])
        print(f"verdicts identical across executors: {'yes' if same else 'NO'}")
        return 0 if same else 1
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
