"""The closed-loop stage of a campaign: scenario files -> stored verdicts, resumable, on any executor."""

from __future__ import annotations

import sys
from dataclasses import dataclass, replace
from functools import lru_cache
from pathlib import Path
from typing import Any, Iterable, Iterator, Sequence

from tqdm import tqdm

from ..contract import ScenarioEnvelope
from ..errors import Txt2SceError
from ..scenario_source import envelope_for, iter_scenario_files
from .executors import run_tasks
from .store import ResultStore, StoredRun, run_key


@dataclass(frozen=True)
class RunTask:
    """One closed-loop run to do, as the driver plans it: where its scenario is on the driver's disk. What a worker
    gets is the `RunJob` made from it (`jobs`), which carries the content instead."""

    key: str
    scenario_path: str
    scenario_id: str
    tree: str | None
    parent: str | None
    faults: tuple[str, ...]
    seed: int
    ros: bool = False
    time_limit: float | None = None     # simulated seconds per run (None: the scenario's / player's own limit)
    planner: str = "standin"            # the planner under test: standin | commonroad | none (always over ROS)
    planner_settings: str = ""          # a third-party adapter's settings file
    trajectory_dir: str | None = None   # keep each graph run's judged trajectories here (<key>.npz) for plots


@dataclass(frozen=True)
class RunJob:
    """One run as shipped to a worker: self-contained (the scenario's and its map's text in `scenario`), so a worker
    on another machine, or in another directory, needs none of the driver's files. The paths in the envelope
    (`map_path`, `meta['file']`) only name the files in messages."""

    key: str
    scenario: ScenarioEnvelope
    faults: tuple[str, ...]
    seed: int
    ros: bool = False
    time_limit: float | None = None
    error: str = ""         # the driver could not read the scenario or its map: the run is an error, saying why
    planner: str = "standin"
    planner_settings: str = ""
    trajectory_dir: str | None = None

    def shared_part(self) -> tuple[str, str, "RunJob"]:
        """The map, which every run on the same map shares (`executors.SharesPart`)."""
        env = self.scenario
        return f"{env.map_path}\0{len(env.map_xodr)}", env.map_xodr, replace(self, scenario=replace(env, map_xodr=""))

    def with_shared(self, part: str) -> "RunJob":
        return replace(self, scenario=replace(self.scenario, map_xodr=part))


def jobs(tasks: Iterable[RunTask]) -> Iterator[RunJob]:
    """The jobs of `tasks`, read lazily as an executor draws them (the driver holds only what is in flight); a map
    many scenarios share is read once while they come one after the other."""
    read_map = lru_cache(maxsize=16)(lambda path: Path(path).read_text(encoding="utf-8"))
    for t in tasks:
        error = ""
        try:
            env = envelope_for(Path(t.scenario_path), scenario_id=t.scenario_id, parent=t.parent, tree=t.tree,
                               read_map=read_map)
        except (Txt2SceError, ValueError) as exc:
            # one unreadable file is that run's error verdict; the campaign carries on with the rest
            env = ScenarioEnvelope(id=t.scenario_id, xosc="", parent=t.parent, tree=t.tree,
                                   meta={"file": t.scenario_path})
            error = str(exc) if isinstance(exc, Txt2SceError) else f"{t.scenario_path}: {exc}"
        yield RunJob(t.key, env, t.faults, t.seed, t.ros, t.time_limit, error, t.planner, t.planner_settings,
                     t.trajectory_dir)


def execute(job: RunJob) -> StoredRun:
    """Worker entry point (module level so process pools and Ray can pickle it)."""
    env = job.scenario
    if job.error:
        from ..closed_loop import RunRecord
        from ..contract import Verdict

        record = RunRecord(env.id, Verdict.ERROR, error=job.error)
    elif job.ros or job.planner != "standin":
        from .ros_runs import PlannerSpec, run_over_ros

        traj = str(Path(job.trajectory_dir) / f"{job.key}.npz") if job.trajectory_dir else None
        record = run_over_ros(env, scenario_id=env.id, faults=job.faults, time_limit=job.time_limit, seed=job.seed,
                              keep_trajectory=traj, planner=PlannerSpec(job.planner, job.planner_settings))
    else:
        from ..closed_loop import run_closed_loop

        record, _ = run_closed_loop(env, scenario_id=env.id, faults=job.faults, seed=job.seed,
                                    time_limit=job.time_limit)
    return StoredRun(job.key, env.id, env.tree, env.parent, record.verdict.value, tuple(record.categories),
                     record.to_dict())


def make_tasks(inputs: Sequence[str | Path], *, faults: tuple[str, ...] = (), seed: int = 0,
               ros: bool = False, time_limit: float | None = None, planner: str = "standin",
               planner_settings: dict[str, Any] | None = None, planner_settings_file: str = "",
               trajectory_dir: str | None = None) -> list[RunTask]:
    """One task per scenario file under `inputs` (files, directories, tree directories), keyed by content and by
    the planner set-up (name, settings), so runs of different planners never share a key."""
    tasks = []
    ros = ros or planner != "standin"
    config: dict[str, object] = {"planner": planner, "faults": sorted(faults), "ros": ros}
    if planner_settings:
        config["planner_settings"] = planner_settings
    if time_limit is not None:
        # only when set, so the keys of stores written without it stay valid
        config["time_limit"] = float(time_limit)
    for path, sid, parent, tree in iter_scenario_files(list(inputs)):
        key = run_key(Path(path).read_bytes(), config, seed)
        tasks.append(RunTask(key, str(path), sid, tree, parent, tuple(sorted(faults)), seed, ros, time_limit,
                             planner, planner_settings_file, trajectory_dir))
    return tasks


@dataclass(frozen=True)
class RunsSummary:
    """What the run stage did with its scenarios: total = skipped + duplicates + ran + left (by `limit`)."""

    total: int                 # scenario files given
    skipped: int               # already judged in the store (a resumed campaign), not run again
    ran: int                   # run now
    verdicts: dict[str, int]   # of the runs done now
    duplicates: int = 0        # byte-identical to another scenario of this batch: judged once, by that run
    left: int = 0              # not run because of `limit` (rerun without it to finish)


def count_duplicates(tasks: Sequence[RunTask]) -> int:
    """Scenarios whose run key (bytes + planner set-up + seed) another task of the list already has."""
    return len(tasks) - len({t.key for t in tasks})


def run_all(tasks: Iterable[RunTask], store: ResultStore, *, executor: str = "pool", workers: int | None = None,
            progress: bool = True, limit: int | None = None, ray_address: str | None = None) -> RunsSummary:
    """Run every task whose key the store does not hold yet; each result is committed as it arrives, so a killed
    campaign resumes where it stopped (`limit` stops after that many new runs: used to test exactly that)."""
    tasks = list(tasks)
    done = store.done_keys()
    # A scenario listed twice (identical bytes, e.g. two tree nodes whose mutations came out equal) runs once; the
    # duplicates are counted apart so that total = skipped + duplicates + ran + left always adds up.
    first: dict[str, RunTask] = {}
    for t in tasks:
        first.setdefault(t.key, t)
    distinct = list(first.values())
    duplicates = len(tasks) - len(distinct)
    skipped = sum(1 for t in distinct if t.key in done)
    todo = [t for t in distinct if t.key not in done]
    left = 0
    if limit is not None:
        left = max(0, len(todo) - limit)
        todo = todo[:limit]
    if progress and skipped:
        print(f"[campaign] resuming: {skipped} of {len(distinct)} distinct scenarios already judged in "
              f"{store.path}, {len(todo)} to run", file=sys.stderr)
    # fixed key order so the bar's counts do not jump around as verdicts first appear
    verdicts: dict[str, int] = {"pass": 0, "fail": 0, "error": 0}
    bar = tqdm(total=len(todo), desc="closed-loop runs", unit="run", disable=not progress, file=sys.stderr,
               dynamic_ncols=True, mininterval=0.5, smoothing=0.05,
               bar_format="{desc}: {percentage:3.0f}%|{bar}| {n_fmt}/{total_fmt} [{elapsed}<{remaining} ETA, "
                          "{rate_fmt}{postfix}]")

    def note(text: str) -> None:
        if progress:
            bar.write(f"[campaign] {text}", file=sys.stderr)    # above the bar, not through it

    try:
        for run in run_tasks(execute, jobs(todo), executor=executor, workers=workers, ray_address=ray_address,
                             note=note):
            store.add(run)
            verdicts[run.verdict] = verdicts.get(run.verdict, 0) + 1
            bar.update(1)
            bar.set_postfix(verdicts, refresh=False)
    finally:
        bar.close()
    verdicts = {k: v for k, v in verdicts.items() if v}
    return RunsSummary(total=len(tasks), skipped=skipped, ran=sum(verdicts.values()), verdicts=verdicts,
                       duplicates=duplicates, left=left)
