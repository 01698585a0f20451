"""scipy's compiled pieces loaded without their packages (`road/scipy_alone.py`) are scipy's own objects."""

from __future__ import annotations

import subprocess
import sys
import textwrap


def _fresh(code: str) -> None:
    # A fresh interpreter: in this one, other tests may have imported scipy.spatial / scipy.special already.
    out = subprocess.run([sys.executable, "-c", textwrap.dedent(code)], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr[-2000:]
    assert out.stdout.strip() == "ok"


def test_tree_class_loads_alone_and_is_the_one_scipy_spatial_exports() -> None:
    _fresh("""
        import sys
        import numpy as np
        from txt2sce_ros.road.scipy_alone import ckdtree
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


def test_fresnel_loads_alone_and_is_the_one_scipy_special_exports() -> None:
    # Arguments across every branch of the integrals (small, the rational approximations, the asymptotic range),
    # both signs; a spiral of the road model through it before and after scipy.special is imported.
    _fresh("""
        import sys
        import numpy as np
        from txt2sce_ros.road.geometry import Spiral
        from txt2sce_ros.road.scipy_alone import fresnel
        spiral = Spiral(s=0.0, x=1.0, y=2.0, hdg=0.3, length=80.0, k0=-0.01, k1=0.02)
        ds = np.linspace(0.0, 80.0, 801)
        before = [a.tobytes() for a in spiral.local(ds)]
        ufunc = fresnel()
        assert "scipy.special" not in sys.modules, "the package __init__ ran"
        x = np.concatenate([np.linspace(-40.0, 40.0, 20001), np.geomspace(1e-9, 1e6, 5000),
                            -np.geomspace(1e-9, 1e6, 5000)])
        ours = ufunc(x)
        import scipy.special
        assert scipy.special.fresnel is ufunc, "two fresnel ufuncs in one process"
        theirs = scipy.special.fresnel(x)
        assert ours[0].tobytes() == theirs[0].tobytes() and ours[1].tobytes() == theirs[1].tobytes()
        assert [a.tobytes() for a in spiral.local(ds)] == before
        print("ok")
    """)
