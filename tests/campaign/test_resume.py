"""A killed campaign resumes where it stopped: no duplicate and no lost result (issue 9, acceptance)."""

from __future__ import annotations

import os
import signal
import sqlite3
import subprocess
import sys
import time
from pathlib import Path

from txt2sce_ros.campaign.pipeline import CampaignConfig, run_campaign
from txt2sce_ros.campaign.store import ResultStore

from .conftest import TIME_LIMIT


def _rows(store_path: Path) -> list[tuple[str, str, tuple[str, ...]]]:
    with ResultStore(store_path) as store:
        return sorted((r.run_key, r.verdict, r.categories) for r in store.runs())


def _count(store_path: Path) -> int:
    if not store_path.exists():
        return 0
    try:
        with sqlite3.connect(store_path, timeout=1.0) as db:
            return int(db.execute("SELECT COUNT(*) FROM runs").fetchone()[0])
    except sqlite3.OperationalError:     # table not created yet
        return 0


def _cfg(out: Path, **kw: object) -> CampaignConfig:
    return CampaignConfig(out=out, executor="serial", progress=False, report=False, time_limit=TIME_LIMIT, **kw)


def test_sigkilled_campaign_resumes_without_duplicates_or_losses(seed_files: list[Path], tmp_path: Path) -> None:
    # Reference: the same campaign, uninterrupted.
    ref = run_campaign(seed_files, _cfg(tmp_path / "ref"))
    assert ref.runs is not None and ref.runs.ran == len(seed_files)
    expected = _rows(tmp_path / "ref" / "results.sqlite")

    # A real campaign process, killed with SIGKILL (no clean-up) once two results are stored.
    out = tmp_path / "killed"
    cmd = [sys.executable, "-m", "txt2sce_ros.cli.main", "campaign", *map(str, seed_files), "--out", str(out),
           "--executor", "serial", "--time-limit", str(TIME_LIMIT), "--no-report", "--no-progress"]
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
    deadline = time.monotonic() + 40
    try:
        while _count(out / "results.sqlite") < 2 and proc.poll() is None and time.monotonic() < deadline:
            time.sleep(0.05)
    finally:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.wait()
    stored = _count(out / "results.sqlite")
    assert 2 <= stored < len(seed_files), f"kill came too late or too early ({stored} stored)"

    # Resume: only the missing runs run, and the store ends up equal to the uninterrupted one.
    resumed = run_campaign(seed_files, _cfg(out))
    assert resumed.runs is not None
    assert resumed.runs.skipped == stored
    assert resumed.runs.ran == len(seed_files) - stored
    assert _rows(out / "results.sqlite") == expected
    # A third pass has nothing left to do.
    again = run_campaign(seed_files, _cfg(out))
    assert again.runs is not None and again.runs.ran == 0 and again.runs.skipped == len(seed_files)


def test_limit_stops_and_resume_completes(seed_files: list[Path], tmp_path: Path) -> None:
    files = seed_files[:4]
    first = run_campaign(files, _cfg(tmp_path / "c", limit=1))
    assert first.runs is not None and first.runs.ran == 1
    assert not (tmp_path / "c" / "report").exists()     # a partial campaign writes no report
    rest = run_campaign(files, _cfg(tmp_path / "c"))
    assert rest.runs is not None and (rest.runs.skipped, rest.runs.ran) == (1, 3)
    rows = _rows(tmp_path / "c" / "results.sqlite")
    assert len({k for k, _, _ in rows}) == len(rows) == 4


def test_counts_add_up_with_duplicates_and_limit(seed_files: list[Path], tmp_path: Path) -> None:
    # Two byte-identical scenarios under different names: judged once, and the summary says so (issue 18). The
    # copy sits beside the original so its relative map path still resolves.
    twin = seed_files[0].with_name(f"{seed_files[0].stem}_twin_{tmp_path.name}.xosc")
    twin.write_bytes(seed_files[0].read_bytes())
    try:
        files = [*seed_files[:3], twin]
        first = run_campaign(files, _cfg(tmp_path / "c", limit=1))
        r = first.runs
        assert r is not None and (r.total, r.duplicates, r.ran, r.left, r.skipped) == (4, 1, 1, 2, 0)
        rest = run_campaign(files, _cfg(tmp_path / "c"))
        r = rest.runs
        assert r is not None and (r.total, r.duplicates, r.skipped, r.ran, r.left) == (4, 1, 1, 2, 0)
        assert r.total == r.skipped + r.duplicates + r.ran + r.left
        assert "error" not in r.verdicts
    finally:
        twin.unlink()
