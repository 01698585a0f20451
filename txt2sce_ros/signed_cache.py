"""Disk caches of built objects (map databases, the OpenSCENARIO entity database) that cannot run code on load.

Unpickling runs whatever the file says, and the cache directory (`$TXT2SCE_CACHE`, ~/.cache/txt2sce) may be
writable by others or filled from elsewhere. So every entry carries an HMAC-SHA256 of its bytes under a secret key
that lives outside the cache (`$TXT2SCE_CACHE_KEY`, default ~/.config/txt2sce/cache.key, created 0600 on first use),
and is unpickled only when the tag verifies. An entry that does not verify is a cache miss: rebuilt and rewritten.
Writes go through a temporary file and `os.replace`, so concurrent builders never read half an entry.
"""

from __future__ import annotations

import hashlib
import hmac
import os
import pickle
import secrets
import stat
import tempfile
from functools import lru_cache
from pathlib import Path
from typing import Any

TAG_BYTES = 32
MAGIC = b"txt2sce-signed-cache/1\n"


def key_path() -> Path:
    env = os.environ.get("TXT2SCE_CACHE_KEY")
    if env:
        return Path(env)
    base = Path(os.environ.get("XDG_CONFIG_HOME") or Path.home() / ".config")
    return base / "txt2sce" / "cache.key"


@lru_cache(maxsize=4)
def _key(path: str) -> bytes | None:
    """The secret, created on first use; None (no caching) when it is not ours alone to read."""
    p = Path(path)
    try:
        p.parent.mkdir(parents=True, exist_ok=True, mode=0o700)
        try:
            fd = os.open(p, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600)
        except FileExistsError:
            pass
        else:
            with os.fdopen(fd, "wb") as fh:
                fh.write(secrets.token_bytes(32))
        st = p.stat()
        if st.st_uid != os.getuid() or st.st_mode & (stat.S_IRWXG | stat.S_IRWXO):
            return None           # someone else could know or set it
        key = p.read_bytes()
    except OSError:
        return None
    return key if len(key) >= 16 else None


def _tag(key: bytes, payload: bytes) -> bytes:
    return hmac.new(key, MAGIC + payload, hashlib.sha256).digest()


def load(path: str | Path) -> Any | None:
    """The object stored at `path`, or None when there is none or its tag does not verify."""
    key = _key(str(key_path()))
    if key is None:
        return None
    try:
        data = Path(path).read_bytes()
    except OSError:
        return None
    tag, payload = data[:TAG_BYTES], data[TAG_BYTES:]
    if len(tag) != TAG_BYTES or not hmac.compare_digest(tag, _tag(key, payload)):
        return None
    try:
        return pickle.loads(payload)
    except (pickle.UnpicklingError, EOFError, AttributeError, ImportError, ValueError, TypeError, IndexError):
        return None               # written by another code version: rebuild


def store(path: str | Path, obj: Any) -> None:
    """Write `obj` with its tag; a cache that cannot be written only costs speed."""
    key = _key(str(key_path()))
    if key is None:
        return
    target = Path(path)
    try:
        target.parent.mkdir(parents=True, exist_ok=True)
        payload = pickle.dumps(obj, protocol=pickle.HIGHEST_PROTOCOL)
        fd, tmp = tempfile.mkstemp(dir=target.parent, suffix=".tmp")
    except OSError:
        return
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(_tag(key, payload))
            fh.write(payload)
        os.replace(tmp, target)
    except OSError:
        Path(tmp).unlink(missing_ok=True)
