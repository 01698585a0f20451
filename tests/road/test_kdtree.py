"""The k-d tree loaded without the rest of scipy.spatial (`road/kdtree.py`) is scipy's own class."""

from __future__ import annotations

import subprocess
import sys
import textwrap


def test_tree_class_loads_alone_and_is_the_one_scipy_spatial_exports() -> None:
    # A fresh interpreter: in this one, other tests may have imported scipy.spatial already.
    code = textwrap.dedent("""
        import sys
        import numpy as np
        from txt2sce_ros.road.kdtree import ckdtree
        tree_class = ckdtree()
        assert "scipy.spatial" not in sys.modules, "the package __init__ ran"
        pts = np.random.default_rng(3).random((500, 2)) * 100
        ours = tree_class(pts, balanced_tree=False, compact_nodes=False).query((40.0, 60.0), k=12)
        from scipy.spatial import cKDTree
        assert cKDTree is tree_class, "two tree classes in one process"
        theirs = cKDTree(pts, balanced_tree=False, compact_nodes=False).query((40.0, 60.0), k=12)
        assert ours[0].tobytes() == theirs[0].tobytes() and ours[1].tobytes() == theirs[1].tobytes()
        print("ok")
    """)
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr[-2000:]
    assert out.stdout.strip() == "ok"
