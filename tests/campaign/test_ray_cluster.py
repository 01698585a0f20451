"""Campaigns on a real Ray cluster (issue 20): two nodes on this machine, tasks that need none of the driver's files,
the same stored results as the process pool, and a cluster started by `ray start --head` found without RAY_ADDRESS.

Every cluster here lives in a private RAY_TMPDIR with its own ports, so nothing collides with other Ray instances on
the machine, and is torn down by this test also when it fails (`ray stop` is never used: it would stop every Ray
process of the user, other people's included)."""

from __future__ import annotations

import os
import shutil
import signal
import sqlite3
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

import pytest

from txt2sce_ros.campaign.executors import run_tasks
from txt2sce_ros.campaign.ray_cluster import IN_FLIGHT_PER_CPU, free_port, simulated_cluster
from txt2sce_ros.campaign.runs import RunJob, execute, jobs, make_tasks, run_all
from txt2sce_ros.campaign.store import ResultStore
from txt2sce_ros.errors import InputError

from .conftest import TIME_LIMIT

ray = pytest.importorskip("ray")

VENV_BIN = Path(sys.executable).parent


def _comparable(runs: Any) -> dict[str, tuple[str, tuple[str, ...], str]]:
    # wall_time is the one field that legitimately differs between executors
    return {r.run_key: (r.verdict, r.categories, repr(sorted((k, v) for k, v in r.record.items() if k != "wall_time")))
            for r in runs}


def test_two_node_cluster_runs_self_contained_jobs_as_the_pool_does(seed_files: list[Path], tmp_path: Path,
                                                                    ray_tmp: Path,
                                                                    monkeypatch: pytest.MonkeyPatch) -> None:
    # The driver's scenario directory: a copy that is removed once the jobs are made, before anything runs.
    scen_dir = tmp_path / "driver_scenarios"
    scen_dir.mkdir()
    for f in seed_files[:4]:
        shutil.copy(f, scen_dir / f.name)
    shutil.copytree(seed_files[0].parent / "maps", scen_dir / "maps")      # the maps their LogicFile names
    tasks = make_tasks(sorted(scen_dir.glob("*.xosc")), faults=("aggressive_start",), time_limit=TIME_LIMIT)
    pool = _comparable(run_tasks(execute, jobs(tasks), executor="pool", workers=2))
    assert len(pool) == 4
    shipped = list(jobs(tasks))
    assert not any(j.error for j in shipped), [j.error for j in shipped]
    shutil.rmtree(scen_dir)

    puts: list[int] = []
    real_put = ray.put
    monkeypatch.setattr(ray, "put", lambda value, **kw: puts.append(len(value)) or real_put(value, **kw))
    # 1 + 2 logical CPUs: not this machine's core count, so the in-flight bound must come from the cluster
    with simulated_cluster([1, 2]) as cluster:
        notes: list[str] = []
        on_ray = _comparable(run_tasks(execute, shipped, executor="ray", workers=1, ray_address=cluster.address,
                                       note=notes.append))
        assert on_ray == pool
        assert notes and f"2 node(s), 3 CPUs, up to {3 * IN_FLIGHT_PER_CPU} runs in flight" in notes[0], notes
        # the map went into the object store once per distinct map, not once per run
        maps = {j.shared_part()[0] for j in shipped}
        assert len(puts) == len(maps) < len(shipped)
        assert not ray.is_initialized()          # the driver disconnected; the cluster is still up
        assert len(cluster.list_all_nodes()) == 2


def test_a_job_ships_its_map_once_and_is_whole_again_on_the_worker(seed_files: list[Path]) -> None:
    job = next(jobs(make_tasks(seed_files[:1])))
    assert isinstance(job, RunJob) and job.scenario.map_xodr.startswith("<?xml")
    key, part, light = job.shared_part()
    assert light.scenario.map_xodr == "" and part == job.scenario.map_xodr
    assert light.with_shared(part) == job


def test_unreadable_scenario_is_that_runs_error_not_the_campaigns(tmp_path: Path, seed_files: list[Path]) -> None:
    bad = tmp_path / "broken.xosc"
    bad.write_text("<OpenSCENARIO><unclosed></OpenSCENARIO>", encoding="utf-8")
    runs = list(run_tasks(execute, jobs(make_tasks([bad, seed_files[0]], time_limit=2.0)), executor="serial"))
    by_id = {r.scenario_id: r for r in runs}
    assert by_id["broken"].verdict == "error" and "broken.xosc" in by_id["broken"].record["error"]
    assert by_id[seed_files[0].stem].verdict in ("pass", "fail")


def test_unreachable_cluster_is_one_clear_error(seed_files: list[Path], ray_tmp: Path) -> None:
    port = free_port()       # nothing listens there
    with pytest.raises(InputError, match=f"no Ray cluster answers at 127.0.0.1:{port} \\(--ray-address\\)"):
        list(run_tasks(execute, jobs(make_tasks(seed_files[:1])), executor="ray", ray_address=f"127.0.0.1:{port}"))


def test_a_recorded_cluster_that_is_gone_is_one_clear_error(seed_files: list[Path], ray_tmp: Path) -> None:
    # what a head node killed without `ray stop` leaves behind: ray.init("auto") would retry it for minutes
    recorded = ray_tmp / "ray" / "ray_current_cluster"
    recorded.parent.mkdir()
    port = free_port()
    recorded.write_text(f"127.0.0.1:{port}", encoding="utf-8")
    with pytest.raises(InputError, match=f"no Ray cluster answers at 127.0.0.1:{port} \\(the cluster `ray start` "
                                         "recorded in"):
        list(run_tasks(execute, jobs(make_tasks(seed_files[:1])), executor="ray"))


def _stored(db: Path) -> list[tuple[str, str, str]]:
    with sqlite3.connect(db) as con:
        return list(con.execute("SELECT run_key, verdict, categories FROM runs ORDER BY run_key"))


def _kill_group(proc: subprocess.Popen[bytes]) -> None:
    """Stop the `ray start` session this test began: its whole process group (GCS, raylet, workers), nothing else."""
    for sig, wait in ((signal.SIGTERM, 10.0), (signal.SIGKILL, 5.0)):
        try:
            os.killpg(proc.pid, sig)
        except ProcessLookupError:
            return
        deadline = time.monotonic() + wait
        while time.monotonic() < deadline:
            try:
                os.killpg(proc.pid, 0)
            except ProcessLookupError:
                return
            time.sleep(0.2)


def _ray_start_head(env: dict[str, str], recorded: Path, attempts: int = 3) -> subprocess.Popen[bytes]:
    """`ray start --head --block` in a process group of its own, up once it has recorded its address. Ray gives a
    node 30 s to register (hard-coded): on a loaded 2-core machine that can run out, so a failed start is retried."""
    why = ""
    for _ in range(attempts):
        head = subprocess.Popen(
            [str(VENV_BIN / "ray"), "start", "--head", "--block", "--num-cpus", "2", "--port", str(free_port()),
             "--include-dashboard=false", "--dashboard-agent-listen-port", str(free_port()),
             "--disable-usage-stats"],
            env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, start_new_session=True)
        deadline = time.monotonic() + 120
        while not recorded.is_file() and head.poll() is None and time.monotonic() < deadline:
            time.sleep(0.5)
        if recorded.is_file() and head.poll() is None:
            return head
        why = head.stderr.read().decode()[-1500:] if head.poll() is not None else "no address after 120 s"
        _kill_group(head)
        recorded.unlink(missing_ok=True)
    pytest.fail(f"ray start --head did not come up in {attempts} attempts: {why}")


def test_campaign_finds_a_cluster_started_with_ray_start_head(seed_files: list[Path], tmp_path: Path,
                                                               ray_tmp: Path) -> None:
    env = {**os.environ, "RAY_TMPDIR": str(ray_tmp), "PYTHONPATH": os.pathsep.join(sys.path)}
    env.pop("RAY_ADDRESS", None)
    inputs = [str(f) for f in seed_files[:3]]
    # what the pool stores (the pool's equality with serial is test_executors'; here the cheaper serial run)
    with ResultStore(tmp_path / "pool.sqlite") as store:
        run_all(make_tasks(inputs, time_limit=TIME_LIMIT), store, executor="serial", progress=False)

    head = _ray_start_head(env, ray_tmp / "ray" / "ray_current_cluster")
    try:
        # a driver in another directory, without RAY_ADDRESS, as Ray's docs run one on the head node
        res = subprocess.run([str(VENV_BIN / "txt2sce"), "campaign", *inputs, "--out", str(tmp_path / "ray"),
                              "--executor", "ray", "--time-limit", str(TIME_LIMIT), "--no-report"],
                             env=env, cwd=tmp_path, capture_output=True, text=True, timeout=300)
        assert res.returncode == 0, res.stderr[-2000:]
        assert "Traceback" not in res.stderr
        assert "connected to" in res.stderr and "ray start` recorded" in res.stderr, res.stderr[-2000:]
        assert _stored(tmp_path / "ray" / "results.sqlite") == _stored(tmp_path / "pool.sqlite")
        assert len(_stored(tmp_path / "ray" / "results.sqlite")) == 3
    finally:
        _kill_group(head)
