"""`load_map_database`: build once per map content, keep the result on disk keyed by the file's SHA-256.

The key also carries a fingerprint of the code that builds it (this package and the road model), so an entry
written by an older version is never read. Writes go through a temporary file and `os.replace`, so concurrent
builders never see half a pickle; entries are signed and verified before they are unpickled
(`txt2sce_ros.signed_cache`).
"""

from __future__ import annotations

import hashlib
import os
from functools import lru_cache
from pathlib import Path

from .. import signed_cache
from ..errors import InputError
from ..paths import cache_dir
from ..road import RoadNetwork
from .database import MapDatabase, build_map_database

@lru_cache(maxsize=1)
def code_fingerprint() -> str:
    """A hash of the sources the database depends on: the map-database and road-model modules."""
    here = Path(__file__).resolve().parent
    digest = hashlib.sha256()
    for folder in (here, here.parent / "road"):
        for src in sorted(folder.glob("*.py")):
            digest.update(src.name.encode())
            digest.update(src.read_bytes())
    return digest.hexdigest()[:12]


def cache_path(sha256: str) -> Path:
    """Where the database of a map with this content hash is cached."""
    return cache_dir() / "mapdb" / f"{sha256}-{code_fingerprint()}.pickle"


def load_map_database(path: str | os.PathLike[str], *, cache: bool = True) -> MapDatabase:
    """The map database of an OpenDRIVE file, from the disk cache when the same content was built before.

    Raises `InputError` (naming the file and element) for unreadable or malformed maps.
    """
    p = Path(path)
    try:
        data = p.read_bytes()
    except OSError as exc:
        raise InputError(f"cannot read map: {exc.strerror}", source=str(p)) from exc
    sha = hashlib.sha256(data).hexdigest()
    target = cache_path(sha)
    if cache and target.is_file():
        db = signed_cache.load(target)   # None: missing, not ours (tag), or from another code version
        if isinstance(db, MapDatabase) and db.sha256 == sha:
            db.source = str(p)  # the same content may live under another name
            db.from_cache = True
            return db
    net = RoadNetwork.from_string(data, source=str(p))
    db = build_map_database(net, xodr_bytes=data, sha256=sha)
    if cache:
        _store(target, db)
    return db


def _store(target: Path, db: MapDatabase) -> None:
    signed_cache.store(target, db)
