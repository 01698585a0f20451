"""Lazy package exports (PEP 562): a package's `__init__` names what it offers without importing it, so a command
that uses one light module of a package does not pay, at start-up, for the heavy ones beside it.

    __getattr__, __dir__ = lazy_exports(__name__, {"Planner": ".planner", "Faults": ".faults"})

`from package import Planner` then imports `.planner` on first use, exactly as an eager import would have.
"""

from __future__ import annotations

import importlib
import sys
from collections.abc import Callable


def lazy_exports(package: str, exports: dict[str, str]) -> tuple[Callable[[str], object], Callable[[], list[str]]]:
    """Module-level `__getattr__` and `__dir__` for `package` resolving each name of `exports` (name -> module,
    relative to the package) on first access; the value is then stored on the package, so later accesses are plain
    attribute reads."""

    def __getattr__(name: str) -> object:
        where = exports.get(name)
        if where is None:
            raise AttributeError(f"module {package!r} has no attribute {name!r}")
        value = getattr(importlib.import_module(where, package), name)
        setattr(sys.modules[package], name, value)
        return value

    def __dir__() -> list[str]:
        return sorted(set(vars(sys.modules[package])) | set(exports))

    return __getattr__, __dir__
