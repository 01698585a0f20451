"""Loading the YAML parameter files in `config/` (one file per concern)."""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from dataclasses import fields
from functools import lru_cache
from pathlib import Path
from typing import Any, TypeVar

import yaml

from .errors import InputError
from .paths import config_dir

_T = TypeVar("_T")
# libyaml's safe loader where PyYAML was built with it (the same documents, ~20x faster: every process reads a
# config file at start-up), else PyYAML's own.
_SAFE_LOADER = getattr(yaml, "CSafeLoader", yaml.SafeLoader)


@lru_cache(maxsize=None)
def _load(path: str) -> dict[str, Any]:
    try:
        with open(path, encoding="utf-8") as fh:
            data = yaml.load(fh, Loader=_SAFE_LOADER) or {}
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


def check_sections(data: Mapping[str, Any], known: Iterable[str], source: str) -> None:
    """A misspelled section would silently leave every key in it at its default: refuse unknown sections."""
    names = sorted(known)
    for key in data:
        if key not in names:
            raise InputError(f"unknown section (known: {', '.join(names)})", source=source, element=str(key))


def _checked_number(value: int | float, default: int | float, source: str, element: str) -> int | float:
    """Numbers must be finite, and a parameter whose default is not negative (a threshold, a duration, a distance)
    cannot be made negative: a NaN or negative threshold silently turns an oracle or a planner rule off."""
    if not math.isfinite(value):
        raise InputError(f"must be a finite number, got {value!r}", source=source, element=element)
    if default >= 0 and value < 0:
        raise InputError(f"must be >= 0, got {value!r}", source=source, element=element)
    return value


def section_from_mapping(cls: type[_T], values: Mapping[str, Any] | None, source: str, name: str) -> _T:
    """One frozen parameter dataclass from one YAML section: keys left out keep their defaults, an unknown key or
    a value of the wrong kind is an InputError naming the file and `section.key`. Values are coerced to the type
    of the field's default (bool, int, float, tuple; others as given)."""
    if values is None:
        return cls()
    if not isinstance(values, Mapping):
        raise InputError("must be a mapping", source=source, element=name)
    known = {f.name for f in fields(cls)}  # type: ignore[arg-type]
    defaults = cls()
    kwargs: dict[str, Any] = {}
    for key, value in values.items():
        if key not in known:
            raise InputError(f"unknown key (known: {', '.join(sorted(known))})", source=source,
                             element=f"{name}.{key}")
        default = getattr(defaults, key)
        try:
            if isinstance(default, bool):
                kwargs[key] = bool(value)
            elif isinstance(default, tuple):
                kwargs[key] = tuple(value)
            elif isinstance(default, (int, float)):
                kwargs[key] = _checked_number(type(default)(value), default, source, f"{name}.{key}")
            else:
                kwargs[key] = value
        except (TypeError, ValueError) as exc:
            raise InputError(f"bad value {value!r}: {exc}", source=source, element=f"{name}.{key}") from exc
    return cls(**kwargs)
