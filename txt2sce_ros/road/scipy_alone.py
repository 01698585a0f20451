"""scipy's compiled pieces the road model uses, loaded without the rest of their scipy packages.

The road model needs two things from scipy: the compiled k-d tree (lane index, lane paths) and the Fresnel
integrals (clothoid geometries). Importing them as `from scipy.spatial import cKDTree` / `from scipy.special import
fresnel` first runs the package's `__init__`: scipy.spatial's also imports Delaunay/qhull, distance, transforms,
scipy.linalg and scipy.special (about half of a ~0.4 s CPU import), scipy.special's its whole Python layer and
scipy's array-API support (~0.2 s CPU; the compiled module holding `fresnel` loads in ~0.01 s). A cold process
(one `txt2sce play`, the batch player, each campaign worker) pays that the first time a scenario needs a lane
located from (x, y) or a spiral evaluated. So the compiled module is loaded from its own file under its own name
and entered in `sys.modules` under that name: a later `import scipy.spatial` / `import scipy.special` (by anyone)
finds it there and reuses the same module, so there is one `cKDTree` class and one `fresnel` ufunc in the process
either way. It is the same compiled code, so results are the same bit for bit. Anything unexpected (another layout
of scipy's files, a loader error, a module without the name) falls back to the plain import.
"""

from __future__ import annotations

import importlib.machinery
import importlib.util
import sys
from pathlib import Path
from typing import Any


def _load_alone(package: str, module: str) -> Any:
    """`scipy.<package>.<module>` (a compiled module) loaded from its file without `scipy.<package>.__init__`."""
    import scipy

    name = f"scipy.{package}.{module}"
    loaded = sys.modules.get(name)
    if loaded is not None:
        return loaded
    folder = Path(scipy.__file__).parent / package
    for suffix in importlib.machinery.EXTENSION_SUFFIXES:
        path = folder / f"{module}{suffix}"
        if path.is_file():
            loader = importlib.machinery.ExtensionFileLoader(name, str(path))
            spec = importlib.util.spec_from_file_location(name, str(path), loader=loader)
            if spec is None:
                return None
            loaded = importlib.util.module_from_spec(spec)
            loader.exec_module(loaded)
            return sys.modules.setdefault(name, loaded)
    return None


def _attribute(package: str, module: str, attr: str) -> Any:
    """`attr` of the compiled module loaded alone, or None when that cannot be done."""
    try:
        loaded = _load_alone(package, module)
    except Exception:  # any surprise: the caller's ordinary import is always right
        return None
    return getattr(loaded, attr, None)


def ckdtree() -> type:
    """The `cKDTree` class (scipy.spatial's own), loaded as cheaply as possible."""
    tree = _attribute("spatial", "_ckdtree", "cKDTree")
    if tree is None:
        from scipy.spatial import cKDTree

        return cKDTree
    return tree  # type: ignore[no-any-return]


def fresnel() -> Any:
    """The `fresnel` ufunc (scipy.special's own), loaded as cheaply as possible."""
    ufunc = _attribute("special", "_special_ufuncs", "fresnel")
    if ufunc is None:
        from scipy.special import fresnel as ufunc
    return ufunc
