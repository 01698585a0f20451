"""The disk cache: keyed by the map's content hash, hit on the second load, equal to a fresh build."""

from __future__ import annotations

import shutil
from pathlib import Path

from txt2sce_ros.mapdb import load_map_database
from txt2sce_ros.mapdb.cache import cache_path

from .conftest import ESMINI_XODR


def test_second_load_hits_the_cache_and_equals_the_first(tmp_path: Path, monkeypatch) -> None:
    monkeypatch.setenv("TXT2SCE_CACHE", str(tmp_path / "cache"))
    src = ESMINI_XODR / "multi_intersections.xodr"
    first = load_map_database(src)
    assert not first.from_cache
    assert cache_path(first.sha256).is_file()
    second = load_map_database(src)
    assert second.from_cache
    assert second == first
    assert second.junctions("junction4") == first.junctions("junction4")
    assert load_map_database(src, cache=False) == first


def test_cache_follows_content_not_name(tmp_path: Path, monkeypatch) -> None:
    monkeypatch.setenv("TXT2SCE_CACHE", str(tmp_path / "cache"))
    copy = tmp_path / "renamed.xodr"
    shutil.copy(ESMINI_XODR / "fabriksgatan.xodr", copy)
    a = load_map_database(ESMINI_XODR / "fabriksgatan.xodr")
    b = load_map_database(copy)
    assert b.from_cache and b.source == str(copy) and b == a
    # Changing the content changes the key: the edited map is built afresh.
    copy.write_bytes(copy.read_bytes().replace(b"</OpenDRIVE>", b"<!-- edited --></OpenDRIVE>"))
    c = load_map_database(copy)
    assert not c.from_cache and c.sha256 != a.sha256


def test_corrupt_cache_entry_is_rebuilt(tmp_path: Path, monkeypatch) -> None:
    monkeypatch.setenv("TXT2SCE_CACHE", str(tmp_path / "cache"))
    src = ESMINI_XODR / "straight_500m.xodr"
    first = load_map_database(src)
    cache_path(first.sha256).write_bytes(b"not a pickle")
    again = load_map_database(src)
    assert not again.from_cache and again == first
    assert load_map_database(src).from_cache  # and the rebuilt entry was stored
