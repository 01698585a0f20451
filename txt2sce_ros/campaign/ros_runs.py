"""One campaign run over the ROS 2 node graph (`--ros`): player, planner and monitor as separate processes.

The graph runs in a ROS domain of its own (one no other `run_over_ros` on this machine holds at the same time: a
lock file per domain id, so parallel workers never hear each other), the monitor records the run to a bag, and the
verdict stored is the *offline judge's* verdict of that bag: the same `JudgeSession` the live monitor runs, so what
the campaign stores can be re-derived from the recording.

A verdict must be the one the in-process path gives (issue 9), so a graph fault never yields a verdict:
- a node process (player, planner, monitor) exited during the run, or the graph outlived its wall-clock bound:
  the error names the process and its exit status or signal;
- the graph recorded no bag, or not exactly one run (another graph on the same domain);
- the recording lacks frames of the run: a run has one frame per dt from t = 0 to its end, each once, and a
  monitor that matched late misses the first ones (a verdict on part of a run can lose or gain categories);
- the run broke on wall-clock timing (`planner_not_responding`, `wall_clock_limit`), which in-process runs never do.
Such a run is run again (lock-step runs are deterministic, so a rerun is the run the graph should have given), up
to `attempts` times; if every attempt faults, the record is an *error* saying why, never a failure.
"""

from __future__ import annotations

import fcntl
import json
import os
import shutil
import tempfile
import time
from contextlib import contextmanager
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Iterator

from ..closed_loop import RunRecord
from ..config import load_config
from ..contract import ScenarioEnvelope, Verdict

#: Attempts per run before a graph fault is stored as an error.
ATTEMPTS = 3

#: End reasons that are the graph's timing, not the scenario's (an in-process run never ends on them).
GRAPH_END_REASONS = frozenset({"planner_not_responding", "wall_clock_limit"})

#: ROS domain ids handed out (Fast DDS maps domains to UDP ports; ids above ~101 overflow the range on Linux).
DOMAIN_IDS = range(1, 101)


def expected_frames(t_end: float, dt: float | None = None) -> int:
    """Frames of a whole run that ended at `t_end`: t = 0, dt, ..., t_end (the player's step, config/player.yaml)."""
    if dt is None:
        dt = float(load_config("player").get("simulation", {}).get("dt", 0.05))
    return int(round(t_end / dt)) + 1


@contextmanager
def reserved_domain(tag: str) -> Iterator[int]:
    """A ROS domain id no other holder on this machine has while the block runs (an exclusive lock file per id in
    the temp directory), starting the search at the id `tag` hashes to. Two graphs on one domain hear each other:
    a planner answering another player's frames, a monitor recording two runs."""
    from ..ros_env import pick_domain_id

    lock_dir = Path(tempfile.gettempdir()) / "txt2sce_ros_domains"
    lock_dir.mkdir(exist_ok=True)
    first = pick_domain_id(tag)
    ids = [d for d in DOMAIN_IDS if d >= first] + [d for d in DOMAIN_IDS if d < first]
    while True:
        for domain in ids:
            fh = open(lock_dir / f"{domain}.lock", "a+")
            try:
                fcntl.flock(fh, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except BlockingIOError:
                fh.close()
                continue
            try:
                yield domain
            finally:
                fcntl.flock(fh, fcntl.LOCK_UN)
                fh.close()
            return
        time.sleep(0.5)                 # every id taken (100 graphs at once): wait for one to finish


@dataclass(frozen=True)
class PlannerSpec:
    """The planner under test in a graph run: its launcher name and, for a third-party adapter, its settings file."""

    name: str = "standin"
    settings: str = ""


@contextmanager
def _domain_for(planner: PlannerSpec, tag: str) -> Iterator[int]:
    """A reserved domain of its own, except for `--planner none`: the user's stack listens on $ROS_DOMAIN_ID."""
    if planner.name == "none":
        yield int(os.environ.get("ROS_DOMAIN_ID", "0"))
        return
    with reserved_domain(tag) as domain:
        yield domain


def run_over_ros(scenario: str | Path | ScenarioEnvelope, *, scenario_id: str | None = None,
                 faults: tuple[str, ...] = (), keep_bag: str | Path | None = None, run_timeout: float | None = None,
                 attempts: int = ATTEMPTS, time_limit: float | None = None, seed: int | None = None,
                 planner: PlannerSpec = PlannerSpec(), keep_trajectory: str | Path | None = None) -> RunRecord:
    """Run `scenario` through `txt2sce_ros.launcher.run_graph` and judge the recorded bag offline; a graph fault
    (module docstring) runs it again, up to `attempts` times. `details['ros_attempts']` says how many it took.

    `keep_bag`: copy the recording there (otherwise it is deleted with the temporary directory). `time_limit`
    (simulated s) and `seed` go to the player, as `run_closed_loop` takes them, so both paths run the same run.
    `planner`: which planner answers (a third-party adapter's per-run statistics land in
    `details['planner_stats']`; a crashed adapter is an error naming it, not retried). `keep_trajectory`: write
    every entity's judged path (t, x, y, heading, speed) there as .npz, for plots. An envelope (what a campaign
    ships to a worker) is written to the run's temporary directory first. `run_timeout` (wall-clock s per run)
    defaults per planner (`launcher.RUN_TIMEOUTS`, else 120 s)."""
    from ..launcher import RUN_TIMEOUTS

    sid = scenario_id or (scenario.id if isinstance(scenario, ScenarioEnvelope) else Path(scenario).stem)
    if run_timeout is None:
        run_timeout = RUN_TIMEOUTS.get(planner.name, 120.0)
    t0 = time.perf_counter()
    faults_seen: list[str] = []
    record = RunRecord(sid, Verdict.ERROR, error="no attempt made")
    for attempt in range(1, max(1, attempts) + 1):
        record, fault = _attempt(scenario, sid, faults, keep_bag, run_timeout, time_limit, seed, planner,
                                 keep_trajectory)
        if not fault or record.details.get("adapter_crashed"):
            break
        faults_seen.append(fault)
    details = {**record.details, "ros_attempts": attempt}
    if faults_seen:
        details["ros_graph_faults"] = faults_seen
        if len(faults_seen) == attempt:
            record = replace(record, error=f"{record.error} (graph fault on every one of {attempt} attempts)")
    return replace(record, details=details, wall_time=time.perf_counter() - t0)


def _attempt(scenario: str | Path | ScenarioEnvelope, sid: str, faults: tuple[str, ...], keep_bag: str | Path | None,
             run_timeout: float, time_limit: float | None, seed: int | None, planner: PlannerSpec,
             keep_trajectory: str | Path | None) -> tuple[RunRecord, str]:
    """One graph run: (record, why it is a graph fault, '' when it is not)."""
    from oracle_monitor.judge import judge_bag

    from ..errors import Txt2SceError
    from ..launcher import PLANNER_TIMEOUTS, GraphConfig, describe_exit, run_graph

    work = Path(tempfile.mkdtemp(prefix="txt2sce_ros_run_"))
    extra: dict[str, object] = {}
    try:
        bag_dir = work / "bags"
        if isinstance(scenario, ScenarioEnvelope):
            from ..scenario_source import write_envelope

            scenario = write_envelope(scenario, work / "input")
        stats_file = work / "planner_stats.json"
        with _domain_for(planner, f"campaign:{os.getpid()}:{work.name}") as domain:
            cfg = GraphConfig(scenarios=[str(scenario)], bag_dir=str(bag_dir), faults=list(faults),
                              run_timeout=run_timeout, log_dir=str(work / "log"), domain_id=domain,
                              time_limit=time_limit, seed=seed, planner=planner.name,
                              planner_timeout=PLANNER_TIMEOUTS.get(planner.name, 5.0),
                              planner_settings=planner.settings,
                              planner_stats=str(stats_file) if planner.name != "standin" else "")
            codes = run_graph(cfg, timeout=run_timeout + 60.0, quiet=True)
        if stats_file.is_file():
            runs = json.loads(stats_file.read_text(encoding="utf-8")).get("runs", {})
            if runs:
                extra["planner_stats"] = next(iter(runs.values()))
        if planner.name != "standin" and "planner" in codes.early:
            # the adapter process died under the run (an exception, a segfault): the run says nothing of the planner;
            # an error naming the adapter, not retried
            tail = _log_tail(work / "log" / "planner.log")
            why = (f"planner adapter '{planner.name}' crashed ({describe_exit(codes.early['planner'])}): {tail}")
            return RunRecord(sid, Verdict.ERROR, error=why, details={**extra, "adapter_crashed": True}), why
        # A node that died under the run (crashed, killed, out of memory) is a graph fault, whatever the bag says:
        # name it and how it ended, so the stored error says which process to look at.
        if codes.early:
            why = "; ".join(f"{name} process {describe_exit(code)} during the run"
                            for name, code in sorted(codes.early.items()))
            return RunRecord(sid, Verdict.ERROR, error=why, details=extra), why
        if codes.timed_out:
            live = "; ".join(f"{name}: {what}" for name, what in codes.stuck.items()) or "none"
            why = f"the graph did not finish within {run_timeout + 60.0:g} s; still running then: {live}"
            return RunRecord(sid, Verdict.ERROR, error=why, details=extra), why
        bags = sorted(p for p in bag_dir.rglob("metadata.yaml")) if bag_dir.exists() else []
        if not bags:
            why = f"the graph recorded no bag (exit codes {codes})"
            return RunRecord(sid, Verdict.ERROR, error=why, details=extra), why
        verdicts = []
        paths: dict[str, list[tuple[float, float, float, float, float]]] = {}

        def keep(frame) -> None:
            for e in (frame.ego, *frame.objects):
                paths.setdefault(e.name, []).append((frame.t, e.x, e.y, e.heading, e.speed))

        for meta in bags:
            try:
                verdicts += judge_bag(meta.parent, on_frame=keep if keep_trajectory else None).verdicts
            except Txt2SceError as exc:
                why = f"bag not judgeable: {exc}"
                return RunRecord(sid, Verdict.ERROR, error=why, details=extra), why
        if any(v.end_reason in GRAPH_END_REASONS for v in verdicts):
            # What the planner and the player said last, for a run that broke on timing (the logs go with `work`).
            extra["last_log_lines"] = {name: _log_tail(work / "log" / f"{name}.log", 20, 4000)
                                       for name in ("planner", "player")}
        if keep_bag is not None:
            shutil.copytree(bags[0].parent, Path(keep_bag), dirs_exist_ok=True)
        if keep_trajectory is not None and paths:
            import numpy as np

            Path(keep_trajectory).parent.mkdir(parents=True, exist_ok=True)
            np.savez_compressed(keep_trajectory, **{k: np.asarray(v) for k, v in paths.items()})
    finally:
        shutil.rmtree(work, ignore_errors=True)
    if len(verdicts) != 1:
        why = f"expected one judged run in the bag, found {len(verdicts)}"
        return RunRecord(sid, Verdict.ERROR, error=why), why
    v = verdicts[0]
    # steps = frames after the first, as the in-process run counts them
    common = dict(end_reason=v.end_reason, sim_time=v.t_end, steps=max(0, v.frames - 1),
                  details={**v.to_dict(), **extra})
    if v.end_reason in GRAPH_END_REASONS:
        return RunRecord(sid, Verdict.ERROR, error=v.error or v.end_reason, **common), f"run broke: {v.end_reason}"
    want = expected_frames(v.t_end)
    if Verdict(v.verdict) is not Verdict.ERROR and v.frames != want:
        why = f"recording incomplete: {v.frames} of {want} frames judged"
        return RunRecord(sid, Verdict.ERROR, error=f"{why} (its verdict would have been {Verdict(v.verdict).value} "
                                                   f"{list(v.category_names())})", **common), why
    return RunRecord(scenario_id=sid, verdict=Verdict(v.verdict), categories=tuple(v.category_names()),
                     error=v.error, **common), ""


def _log_tail(path: Path, lines: int = 3, limit: int = 400) -> str:
    """The last meaningful lines of a node's log, one line of at most `limit` characters (for an error verdict)."""
    try:
        text = path.read_text(encoding="utf-8", errors="replace").splitlines()
    except OSError:
        return "no log"
    keep = [t.strip() for t in text if t.strip() and "nanobind" not in t and "leaked" not in t]
    return " | ".join(keep[-lines:])[:limit] or "empty log"
