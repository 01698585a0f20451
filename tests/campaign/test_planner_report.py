"""The report of a third-party planner's campaign: it names the planner, its version and settings, gives the
differential against the baseline, and draws failures from the trajectories the graph runs kept (a third-party
planner cannot be re-run in-process)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from txt2sce_ros.campaign.reporting import report_from_store
from txt2sce_ros.campaign.runs import execute, jobs, make_tasks
from txt2sce_ros.campaign.store import ResultStore, StoredRun
from txt2sce_ros.closed_loop import run_closed_loop

#: two short dev-gold seeds (tests/campaign/test_ros_runs.py)
SEEDS = ("dmvca-apple-20190919-r70", "dmvca-apple-20211111-r241")


def test_report_names_the_planner_and_separates_own_failures(seed_dir: Path, tmp_path: Path) -> None:
    files = [seed_dir / f"{name}.xosc" for name in SEEDS]
    traj_dir = tmp_path / "trajectories"
    settings = {"desired_speed": 10.0}
    tasks = make_tasks(files, planner="commonroad", planner_settings=settings, trajectory_dir=str(traj_dir),
                       time_limit=8.0)
    baseline = make_tasks(files, time_limit=8.0)
    info = {"name": "commonroad", "package": "commonroad-reactive-planner", "version": "2025.1",
            "adapter": "sut_adapters/commonroad", "settings": settings}
    with ResultStore(tmp_path / "results.sqlite") as store:
        store.set_meta("planner", info)
        store.set_meta("baseline", {"name": "standin", "version": "x", "settings": {}})
        base_verdicts = [store.add(run) and run.verdict for run in map(execute, jobs(baseline))]
        # the planner under test fails every scenario (Smooth), with the trajectory a graph run keeps: its own
        # failures are the scenarios the baseline passes, the rest defeat both
        for t in tasks:
            rec, traj = run_closed_loop(t.scenario_path, time_limit=8.0, keep_trajectory=True)
            traj_dir.mkdir(exist_ok=True)
            np.savez_compressed(traj_dir / f"{t.key}.npz", **traj)
            verdict, cats = "fail", ("Smooth",)
            record = {**rec.to_dict(), "verdict": verdict, "categories": list(cats),
                      "details": {**rec.details, "planner_stats": {"cycles": {"planned": 10,
                                                                              "no_feasible_trajectory": 1,
                                                                              "planner_exception": 0},
                                                                   "plan_time_mean_s": 0.2, "braking_steps": 2}}}
            store.add(StoredRun(t.key, t.scenario_id, t.tree, t.parent, verdict, tuple(cats), record))
        md = report_from_store(store, files, tmp_path / "report", tasks=tasks, baseline_tasks=baseline)
    text = md.read_text(encoding="utf-8")
    assert "Planner under test: **commonroad** 2025.1" in text and "desired_speed=10.0" in text
    assert "commonroad-reactive-planner 2025.1 through sut_adapters/commonroad" in text
    assert "## Differential triage" in text
    own = base_verdicts.count("pass")
    assert own >= 1
    assert f"| commonroad fails, standin passes (the planner's own failures) | {own} |" in text
    assert f"| both fail (the scenario defeats both) | {base_verdicts.count('fail')} |" in text
    assert "Replanning: 22 planning cycles" in text and "no_feasible_trajectory 2" in text
    # the baseline's speed on the same scenarios, beside the planner's
    assert "Speed: " in text and "Baseline speed (standin, in-process, same scenarios): " in text
    figures = sorted((tmp_path / "report").glob("fig_failure*.png"))
    assert len(figures) == 1            # one plot per category: both runs are Smooth
