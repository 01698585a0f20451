"""No orphans: killing a campaign's main process with SIGKILL (no clean-up runs) takes its pool workers and its ROS
graph's node processes with it (`txt2sce_ros.lifeline`)."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from .cases import _descendants
from .runner import REPO
from .workspace import build, good_seed


def _alive(pid: int) -> bool:
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except OSError:
        return False
    return state != "Z"


def _kill_main_when(argv: list[str], tmp: Path, ready, env_extra: dict[str, str]) -> list[int]:
    env = dict(os.environ, PYTHONPATH=str(REPO), TXT2SCE_CACHE=str(tmp / "cache"), **env_extra)
    proc = subprocess.Popen(argv, cwd=tmp, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        deadline = time.monotonic() + 120
        kids: list[tuple[int, str]] = []
        while time.monotonic() < deadline:
            kids = _descendants(proc.pid)
            if ready(kids):
                break
            assert proc.poll() is None, "the campaign ended before the children were seen"
            time.sleep(0.2)
        else:
            pytest.fail(f"children never appeared: {kids}")
        proc.send_signal(signal.SIGKILL)
        proc.wait()
        pids = [p for p, _ in kids]
        deadline = time.monotonic() + 20
        while time.monotonic() < deadline and any(_alive(p) for p in pids):
            time.sleep(0.2)
        return [p for p in pids if _alive(p)]
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()


def test_pool_workers_die_with_the_campaign(tmp_path: Path) -> None:
    ws = build(tmp_path / "ws")
    argv = [sys.executable, "-m", "txt2sce_ros.cli.main", "campaign", str(ws / "seeds"), "--out", "camp",
            "--executor", "pool", "--workers", "2", "--no-progress", "--no-report"]
    left = _kill_main_when(argv, tmp_path, lambda kids: len(kids) >= 2 and (tmp_path / "camp" / "trees").exists()
                           and (tmp_path / "camp" / "results.sqlite").exists(), {})
    for pid in left:
        os.kill(pid, signal.SIGKILL)
    assert left == []


def test_ros_graph_nodes_die_with_the_campaign(tmp_path: Path) -> None:
    ws = build(tmp_path / "ws")
    argv = [sys.executable, "-m", "txt2sce_ros.cli.main", "campaign", str(good_seed(ws)), "--out", "camp", "--ros",
            "--executor", "serial", "--no-progress", "--no-report"]
    left = _kill_main_when(argv, tmp_path, lambda kids: sum("_node" in c for _, c in kids) >= 3,
                           {"ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST"})
    for pid in left:
        os.kill(pid, signal.SIGKILL)
    assert left == []
