"""planView primitives against closed forms and independent numeric integration."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import cumulative_trapezoid

from txt2sce_ros.road.geometry import Arc, Line, ParamPoly3, PlanView, Poly3, Spiral


def _integrate(heading_fn, length: float, n: int = 200_001) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Reference: integrate (cos h, sin h) over a fine grid (independent of the Fresnel formulation)."""
    s = np.linspace(0.0, length, n)
    h = heading_fn(s)
    return s, cumulative_trapezoid(np.cos(h), s, initial=0.0), cumulative_trapezoid(np.sin(h), s, initial=0.0)


def test_line_moves_along_heading() -> None:
    g = Line(s=0.0, x=1.0, y=2.0, hdg=math.radians(30), length=10.0)
    x, y, h = g.evaluate(np.array([10.0]))
    assert x[0] == pytest.approx(1 + 10 * math.cos(math.radians(30)))
    assert y[0] == pytest.approx(2 + 10 * math.sin(math.radians(30)))
    assert h[0] == pytest.approx(math.radians(30))


@pytest.mark.parametrize("k", [0.01, -0.05, 1e-14])
def test_arc_stays_on_its_circle(k: float) -> None:
    g = Arc(s=0.0, x=0.0, y=0.0, hdg=0.3, length=50.0, k=k)
    s = np.linspace(0, 50, 101)
    x, y, h = g.evaluate(s)
    if abs(k) > 1e-9:
        cx, cy = -math.sin(0.3) / k, math.cos(0.3) / k     # centre of curvature, left of the start for k > 0
        assert np.allclose(np.hypot(x - cx, y - cy), 1 / abs(k), atol=1e-9)
        assert np.allclose(h, 0.3 + k * s)
    else:
        assert np.allclose(x, s * math.cos(0.3)) and np.allclose(y, s * math.sin(0.3))


@pytest.mark.parametrize("k0,k1,length", [(0.0, 0.02, 80.0), (0.01, -0.03, 60.0), (-0.05, -0.001, 40.0),
                                          (0.2, 0.2000001, 10.0)])
def test_spiral_matches_numeric_integration(k0: float, k1: float, length: float) -> None:
    g = Spiral(s=0.0, x=5.0, y=-3.0, hdg=1.1, length=length, k0=k0, k1=k1)
    c = (k1 - k0) / length
    s, xi, yi = _integrate(lambda s: 1.1 + k0 * s + 0.5 * c * s * s, length)
    x, y, h = g.evaluate(s[::1000])
    assert np.max(np.hypot(x - (5.0 + xi[::1000]), y - (-3.0 + yi[::1000]))) < 1e-6
    assert np.allclose(h, 1.1 + k0 * s[::1000] + 0.5 * c * s[::1000] ** 2)
    assert np.allclose(g.curvature(np.array([0.0, length])), [k0, k1])


def test_param_poly3_normalized_equals_arclength_with_scaled_coefficients() -> None:
    L = 30.0
    norm = ParamPoly3(s=0, x=0, y=0, hdg=0.2, length=L, au=0, bu=L, cu=0.5, du=-0.2, av=0, bv=0, cv=3.0, dv=-1.0,
                      normalized=True)
    arc = ParamPoly3(s=0, x=0, y=0, hdg=0.2, length=L, au=0, bu=1.0, cu=0.5 / L**2, du=-0.2 / L**3, av=0, bv=0,
                     cv=3.0 / L**2, dv=-1.0 / L**3, normalized=False)
    s = np.linspace(0, L, 31)
    for a, b in zip(norm.evaluate(s), arc.evaluate(s)):
        assert np.allclose(a, b, atol=1e-9)


def test_poly3_uses_arc_length_not_u() -> None:
    # v = 0.01 u^2: the point at arc length L lies at u < L; its arc length from the start must be L.
    g = Poly3(s=0, x=0, y=0, hdg=0.0, length=40.0, a=0, b=0, c=0.01, d=0)
    s = np.linspace(0, 40, 4001)
    x, y, h = g.evaluate(s)
    assert np.sum(np.hypot(np.diff(x), np.diff(y))) == pytest.approx(40.0, abs=1e-3)
    assert np.allclose(y, 0.01 * x**2, atol=1e-9)
    assert np.allclose(np.tan(h), 0.02 * x, atol=1e-9)


def test_planview_is_continuous_across_geometries_of_real_maps() -> None:
    from .conftest import esmini_map

    for name in ("curves", "fabriksgatan", "multi_intersections", "e6mini", "velodrome", "parking_demo"):
        net = esmini_map(name)
        for road in net.roads.values():
            pv: PlanView = road.plan_view
            for a, b in zip(pv.geometries, pv.geometries[1:]):
                xa, ya, ha = a.evaluate(np.array([a.length]))
                xb, yb, hb = b.evaluate(np.array([0.0]))
                assert math.hypot(xa[0] - xb[0], ya[0] - yb[0]) < 0.02, (name, road.id, b.s)


def test_scalar_fast_path_equals_vectorised_evaluation() -> None:
    from .conftest import esmini_map

    for name in ("curves", "e6mini", "fabriksgatan", "multi_intersections"):
        for road in esmini_map(name).roads.values():
            s = np.linspace(-1.0, road.length + 1.0, 37)
            x, y, h = road.plan_view.evaluate(s)
            for i, si in enumerate(s):
                assert road.plan_view.at(float(si)) == pytest.approx((x[i], y[i], h[i]), abs=1e-9)


def test_param_poly3_scalar_curvature_is_bit_equal_to_the_array_form() -> None:
    # The player steps on `curvature_local`; its trajectories are compared byte for byte across versions, so the
    # float form must give the very bits of the one-element array form, not merely close values.
    rng = np.random.default_rng(7)
    for _ in range(200):
        c = rng.normal(0.0, [1.0, 30.0, 2.0, 0.5, 1.0, 0.5, 3.0, 1.0])
        length = float(rng.uniform(1.0, 200.0))
        for normalized in (True, False):
            g = ParamPoly3(s=0.0, x=0.0, y=0.0, hdg=0.3, length=length, au=c[0], bu=c[1], cu=c[2], du=c[3],
                           av=c[4], bv=c[5], cv=c[6], dv=c[7], normalized=normalized)
            for ds in rng.uniform(-1.0, length + 1.0, 20):
                assert g.curvature_local(float(ds)) == float(g.curvature(np.array([float(ds)]))[0])
