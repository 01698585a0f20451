"""One campaign run over the ROS 2 node graph (`--ros`): player, planner and monitor as separate processes.

The graph runs in a ROS domain of its own (derived from the worker's pid, so parallel workers never hear each
other), the monitor records the run to a bag, and the verdict stored is the *offline judge's* verdict of that bag:
the same `JudgeSession` the live monitor runs, so what the campaign stores can be re-derived from the recording.
A graph that records nothing (bring-up failed, planner never answered) is an *error*, never a failure.
"""

from __future__ import annotations

import os
import shutil
import tempfile
import time
from pathlib import Path

from ..closed_loop import RunRecord
from ..contract import Verdict


def run_over_ros(scenario: str | Path, *, scenario_id: str | None = None, faults: tuple[str, ...] = (),
                 keep_bag: str | Path | None = None, run_timeout: float = 120.0) -> RunRecord:
    """Run `scenario` through `txt2sce_ros.launcher.run_graph` and judge the recorded bag offline.

    `keep_bag`: copy the recording there (otherwise it is deleted with the temporary directory)."""
    from oracle_monitor.judge import judge_bag

    from ..errors import Txt2SceError
    from ..launcher import GraphConfig, run_graph
    from ..ros_env import pick_domain_id

    sid = scenario_id or Path(scenario).stem
    t0 = time.perf_counter()
    work = Path(tempfile.mkdtemp(prefix="txt2sce_ros_run_"))
    try:
        bag_dir = work / "bags"
        cfg = GraphConfig(scenarios=[str(scenario)], bag_dir=str(bag_dir), faults=list(faults),
                          run_timeout=run_timeout, log_dir=str(work / "log"),
                          # one graph per worker process at a time: the pid keeps concurrent workers apart
                          domain_id=pick_domain_id(f"campaign:{os.getpid()}:{work.name}"))
        codes = run_graph(cfg, timeout=run_timeout + 60.0, quiet=True)
        bags = sorted(p for p in bag_dir.rglob("metadata.yaml")) if bag_dir.exists() else []
        if not bags:
            return RunRecord(sid, Verdict.ERROR, error=f"the graph recorded no bag (exit codes {codes})",
                             wall_time=time.perf_counter() - t0)
        verdicts = []
        for meta in bags:
            try:
                verdicts += judge_bag(meta.parent).verdicts
            except Txt2SceError as exc:
                return RunRecord(sid, Verdict.ERROR, error=f"bag not judgeable: {exc}",
                                 wall_time=time.perf_counter() - t0)
        if keep_bag is not None:
            shutil.copytree(bags[0].parent, Path(keep_bag), dirs_exist_ok=True)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    if len(verdicts) != 1:
        return RunRecord(sid, Verdict.ERROR, error=f"expected one judged run in the bag, found {len(verdicts)}",
                         wall_time=time.perf_counter() - t0)
    v = verdicts[0]
    return RunRecord(scenario_id=sid, verdict=Verdict(v.verdict), categories=tuple(v.category_names()),
                     end_reason=v.end_reason, sim_time=v.t_end, wall_time=time.perf_counter() - t0,
                     steps=v.frames, details=v.to_dict(), error=v.error)
