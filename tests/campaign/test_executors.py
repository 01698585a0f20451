"""Same results whatever the executor: serial, a local process pool and a local Ray instance (issue 9)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from txt2sce_ros.campaign.executors import run_tasks
from txt2sce_ros.campaign.runs import execute, jobs, make_tasks
from txt2sce_ros.errors import InputError

from .conftest import TIME_LIMIT


def _comparable(runs: Any) -> dict[str, tuple[str, tuple[str, ...], str]]:
    # Everything the run decided; wall_time is the only field that legitimately differs between executors.
    out = {}
    for r in runs:
        rec = {k: v for k, v in r.record.items() if k != "wall_time"}
        out[r.run_key] = (r.verdict, r.categories, repr(sorted(rec.items())))
    return out


def test_serial_pool_and_ray_give_the_same_results(seed_files: list[Path], ray_tmp: Path) -> None:
    # A fault switched on so the runs differ from the nominal ones in their keys and (for some) their verdicts.
    tasks = make_tasks(seed_files[:4], faults=("aggressive_start",), time_limit=TIME_LIMIT)
    serial = _comparable(run_tasks(execute, jobs(tasks), executor="serial"))
    pool = _comparable(run_tasks(execute, jobs(tasks), executor="pool", workers=2))
    assert len(serial) == 4
    assert pool == serial
    pytest.importorskip("ray")
    ray = _comparable(run_tasks(execute, jobs(tasks), executor="ray", workers=2))
    assert ray == serial


def test_unknown_executor_is_an_input_error(seed_files: list[Path]) -> None:
    with pytest.raises(InputError, match="unknown executor 'threads'"):
        list(run_tasks(execute, jobs(make_tasks(seed_files[:1])), executor="threads"))


def _collector_settings(_: int) -> tuple[int, bool]:
    import gc

    return gc.get_threshold()[0], gc.get_freeze_count() > 0


def test_pool_workers_run_the_collector_less_often_over_a_frozen_inheritance() -> None:
    from txt2sce_ros.campaign.executors import WORKER_GC_GEN0

    got = set(run_tasks(_collector_settings, range(4), executor="pool", workers=2))
    assert got == {(WORKER_GC_GEN0, True)}
    assert WORKER_GC_GEN0 > 700                 # above CPython's default, or the setting buys nothing
