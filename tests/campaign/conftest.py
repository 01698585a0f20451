"""Shared inputs of the campaign tests: real seeds built from the first dev-gold sketches (dev set only)."""

from __future__ import annotations

import itertools
import shutil
import tempfile
from pathlib import Path
from typing import Iterator

import pytest

from txt2sce_ros.paths import shared_dir

DEV_GOLD = shared_dir() / "data" / "reports" / "dev_gold.jsonl"
#: Simulated seconds per run in these tests: enough for starts, stops and contacts to show, short enough that a
#: file of tests stays well under a minute on a loaded 2-core machine.
TIME_LIMIT = 8.0


@pytest.fixture(scope="session")
def seed_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    from txt2sce_ros.seed import write_seeds
    from txt2sce_ros.sketch import load_sketches

    out = tmp_path_factory.mktemp("seeds")
    manifest = write_seeds(itertools.islice(load_sketches(DEV_GOLD), 8), out, seed=0)
    assert len(manifest["built"]) >= 6, manifest["refused"]
    return out


@pytest.fixture(scope="session")
def seed_files(seed_dir: Path) -> list[Path]:
    return sorted(seed_dir.glob("*.xosc"))[:6]


@pytest.fixture
def ray_tmp(monkeypatch: pytest.MonkeyPatch) -> Iterator[Path]:
    """A private Ray temp dir and no RAY_ADDRESS: `--executor ray` then finds no cluster of anyone else's (another
    `ray start` on this machine records itself in the default temp dir) and starts its own. Short, because Ray's
    socket paths under it must fit in 107 bytes."""
    d = Path(tempfile.mkdtemp(prefix="t2s_ray_", dir="/tmp"))
    monkeypatch.setenv("RAY_TMPDIR", str(d))
    monkeypatch.delenv("RAY_ADDRESS", raising=False)
    yield d
    from txt2sce_ros.campaign.ray_cluster import stop_processes_under

    stop_processes_under(str(d))      # what a half-started instance left (a shut-down one left nothing)
    shutil.rmtree(d, ignore_errors=True)
