"""scipy's `cKDTree` without the rest of `scipy.spatial`.

The road model needs one thing from scipy.spatial: the compiled k-d tree (lane index, lane paths). Importing it as
`from scipy.spatial import cKDTree` first runs the package's `__init__`, which also imports Delaunay/qhull,
distance, transforms, scipy.linalg and scipy.special: about half of a ~0.4 s CPU import that a cold process (one
`txt2sce play`, the batch player, each campaign worker) pays the first time a scenario needs a lane located from
(x, y). The compiled module itself needs only numpy and scipy.sparse. So it is loaded from its own file under its
own name and entered in `sys.modules` under that name: a later `import scipy.spatial` (by anyone) finds it there
and reuses the same module, so there is one `cKDTree` class in the process either way. It is the same compiled
code, so queries give the same results bit for bit. Anything unexpected (another layout of scipy's files, a
loader error) falls back to the plain import.
"""

from __future__ import annotations

import importlib.machinery
import importlib.util
import sys
from pathlib import Path
from typing import Any

_NAME = "scipy.spatial._ckdtree"


def _load_alone() -> Any:
    import scipy

    spatial = Path(scipy.__file__).parent / "spatial"
    for suffix in importlib.machinery.EXTENSION_SUFFIXES:
        path = spatial / f"_ckdtree{suffix}"
        if path.is_file():
            loader = importlib.machinery.ExtensionFileLoader(_NAME, str(path))
            spec = importlib.util.spec_from_file_location(_NAME, str(path), loader=loader)
            if spec is None:
                return None
            module = importlib.util.module_from_spec(spec)
            loader.exec_module(module)
            return module
    return None


def ckdtree() -> type:
    """The `cKDTree` class (scipy.spatial's own), loaded as cheaply as possible."""
    module = sys.modules.get(_NAME)
    if module is None:
        try:
            module = _load_alone()
        except Exception:  # any surprise: the ordinary import below is always right
            module = None
        if module is None or not hasattr(module, "cKDTree"):
            from scipy.spatial import cKDTree

            return cKDTree
        module = sys.modules.setdefault(_NAME, module)
    return module.cKDTree  # type: ignore[no-any-return]
