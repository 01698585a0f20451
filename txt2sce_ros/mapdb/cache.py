"""`load_map_database`: build once per map content, keep the result on disk keyed by the file's SHA-256.

The key also carries a fingerprint of the code that builds it (this package and the road model), so an entry
written by an older version is never read. Writes go through a temporary file and `os.replace`, so concurrent
builders never see half a pickle.
"""

from __future__ import annotations

import hashlib
import os
import pickle
import tempfile
from functools import lru_cache
from pathlib import Path

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
        try:
            with open(target, "rb") as fh:
                db = pickle.load(fh)
            if isinstance(db, MapDatabase) and db.sha256 == sha:
                db.source = str(p)  # the same content may live under another name
                db.from_cache = True
                return db
        except (OSError, pickle.UnpicklingError, EOFError, AttributeError, ImportError):
            pass  # a cache from another code version or a broken write: rebuild below
    net = RoadNetwork.from_string(data, source=str(p))
    db = build_map_database(net, xodr_bytes=data, sha256=sha)
    if cache:
        _store(target, db)
    return db


def _store(target: Path, db: MapDatabase) -> None:
    target.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=target.parent, suffix=".tmp")
    try:
        with os.fdopen(fd, "wb") as fh:
            pickle.dump(db, fh, protocol=pickle.HIGHEST_PROTOCOL)
        os.replace(tmp, target)
    except OSError:
        Path(tmp).unlink(missing_ok=True)  # a read-only cache only costs speed
