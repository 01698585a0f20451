"""Shared fixtures: a private cache directory per test session, and the bundled and esmini map paths."""

from __future__ import annotations

from pathlib import Path

import pytest

from txt2sce_ros.mapdb import MapDatabase, load_map_database
from txt2sce_ros.mapdb.bundled import bundled_map_paths
from txt2sce_ros.paths import shared_dir

ESMINI_XODR = shared_dir() / "data" / "conformance" / "esmini" / "xodr"


@pytest.fixture(autouse=True)
def _private_cache(tmp_path_factory: pytest.TempPathFactory, monkeypatch: pytest.MonkeyPatch) -> None:
    # Never read or pollute the user's cache: a stale entry there would hide a build bug.
    monkeypatch.setenv("TXT2SCE_CACHE", str(tmp_path_factory.getbasetemp() / "cache"))


def bundled(name: str) -> Path:
    return next(p for p in bundled_map_paths() if p.name == name)


@pytest.fixture(scope="module")
def dbs() -> dict[str, MapDatabase]:
    """The database of every bundled map, by file name (built without the cache)."""
    return {p.name: load_map_database(p, cache=False) for p in bundled_map_paths()}
