"""Loading the YAML parameter files in `config/` (one file per concern)."""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path
from typing import Any

import yaml

from .errors import InputError
from .paths import config_dir


@lru_cache(maxsize=None)
def _load(path: str) -> dict[str, Any]:
    try:
        with open(path, encoding="utf-8") as fh:
            data = yaml.safe_load(fh) or {}
    except FileNotFoundError as exc:
        raise InputError("configuration file not found", source=path) from exc
    except yaml.YAMLError as exc:
        raise InputError(f"invalid YAML: {exc}", source=path) from exc
    if not isinstance(data, dict):
        raise InputError("top level must be a mapping", source=path)
    return data


def load_config(name: str, path: str | Path | None = None) -> dict[str, Any]:
    """Return the parameters of `config/<name>.yaml` (or of `path` when given). Cached; treat as read-only."""
    target = Path(path) if path else config_dir() / f"{name}.yaml"
    return _load(str(target))
