"""OpenDRIVE planView primitives: the road reference line as a function of s.

Each primitive maps a local arc length `ds` in [0, length] (numpy arrays) to world (x, y, heading). Headings are
radians counter-clockwise from +x and are not wrapped (callers wrap when they need to).

Clothoids use the Fresnel integrals (`scipy.special.fresnel`, loaded by `scipy_alone`), which are exact up to
double precision, rather than a step-wise integration whose error grows with length. `poly3` needs its own
arc-length parametrisation (the polynomial is in the local u coordinate, not in s), which is tabulated once at
construction.
"""

from __future__ import annotations

import bisect
import math
from dataclasses import dataclass, field

import numpy as np

#: Curvature rate below which a spiral is evaluated as an arc (Fresnel scaling becomes ill-conditioned).
_MIN_CURV_RATE = 1e-12
#: Curvature below which an arc is evaluated as a straight line (avoids dividing by ~0).
_MIN_CURV = 1e-12


@dataclass(frozen=True, slots=True)
class Geometry:
    """Common part of every planView `<geometry>`: start s, start pose, length."""

    s: float
    x: float
    y: float
    hdg: float
    length: float

    def local(self, ds: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(u, v, heading change) in the geometry's start frame at local arc length `ds`."""
        raise NotImplementedError

    def curvature(self, ds: np.ndarray) -> np.ndarray:
        """Signed curvature (1/m, positive = turning left) at local arc length `ds`."""
        raise NotImplementedError

    def evaluate(self, ds: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """World (x, y, heading) at local arc length `ds` (array)."""
        ds = np.asarray(ds, dtype=float)
        u, v, dh = self.local(ds)
        c, s = math.cos(self.hdg), math.sin(self.hdg)
        return self.x + c * u - s * v, self.y + s * u + c * v, self.hdg + dh

    def local_at(self, ds: float) -> tuple[float, float, float]:
        """Scalar `local` (subclasses with a closed form override it to skip numpy's per-call overhead)."""
        u, v, dh = self.local(np.array([ds]))
        return float(u[0]), float(v[0]), float(dh[0])

    def curvature_local(self, ds: float) -> float:
        """Scalar `curvature` (closed forms override it)."""
        return float(self.curvature(np.array([ds]))[0])

    def at(self, ds: float) -> tuple[float, float, float]:
        """Scalar world (x, y, heading) at local arc length `ds`."""
        u, v, dh = self.local_at(ds)
        c, s = math.cos(self.hdg), math.sin(self.hdg)
        return self.x + c * u - s * v, self.y + s * u + c * v, self.hdg + dh


class Line(Geometry):
    # No fields of its own: the base's generated methods serve it as they are (`__eq__` compares the exact class),
    # so it is not a dataclass again (that would `exec` the same methods anew at import); `__slots__ = ()` keeps
    # its instances' layout that of its base.
    __slots__ = ()

    def local_at(self, ds: float) -> tuple[float, float, float]:
        return ds, 0.0, 0.0

    def curvature_local(self, ds: float) -> float:
        return 0.0

    def local(self, ds: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        return ds, np.zeros_like(ds), np.zeros_like(ds)

    def curvature(self, ds: np.ndarray) -> np.ndarray:
        return np.zeros_like(np.asarray(ds, dtype=float))


def _arc_local(ds: np.ndarray, k: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    if abs(k) < _MIN_CURV:
        return ds, np.zeros_like(ds), np.zeros_like(ds)
    dh = k * ds
    # u = sin(k s)/k, v = (1 - cos(k s))/k; the second written with sin² to keep precision for small k·s.
    return np.sin(dh) / k, 2.0 * np.sin(dh / 2.0) ** 2 / k, dh


@dataclass(frozen=True, slots=True)
class Arc(Geometry):
    k: float = 0.0

    def curvature_local(self, ds: float) -> float:
        return self.k

    def local_at(self, ds: float) -> tuple[float, float, float]:
        k = self.k
        if abs(k) < _MIN_CURV:
            return ds, 0.0, 0.0
        dh = k * ds
        return math.sin(dh) / k, 2.0 * math.sin(dh / 2.0) ** 2 / k, dh

    def local(self, ds: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        return _arc_local(ds, self.k)

    def curvature(self, ds: np.ndarray) -> np.ndarray:
        return np.full_like(np.asarray(ds, dtype=float), self.k)


@dataclass(frozen=True, slots=True)
class Spiral(Geometry):
    """Clothoid: curvature varies linearly from `k0` to `k1` over the length."""

    k0: float = 0.0
    k1: float = 0.0

    @property
    def rate(self) -> float:
        return (self.k1 - self.k0) / self.length if self.length > 0 else 0.0

    def curvature_local(self, ds: float) -> float:
        return self.k0 + self.rate * ds

    def local(self, ds: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        c = self.rate
        if abs(c) < _MIN_CURV_RATE:
            return _arc_local(ds, self.k0)
        # Place the segment on the standard clothoid k(u) = c·u, starting at u0 = k0/c, then move that start to
        # the origin with heading 0. With a = sqrt(pi/|c|): x(u) = a·C(u/a), y(u) = sign(c)·a·S(u/a).
        a = math.sqrt(math.pi / abs(c))
        sign = 1.0 if c > 0 else -1.0
        u0 = self.k0 / c
        from .scipy_alone import fresnel as fresnel_ufunc   # on first use, without scipy.special's package

        fresnel = fresnel_ufunc()
        s0, c0 = fresnel(u0 / a)
        s1, c1 = fresnel((u0 + ds) / a)
        dx = a * (c1 - c0)
        dy = sign * a * (s1 - s0)
        th0 = 0.5 * c * u0 * u0
        ct, st = math.cos(th0), math.sin(th0)
        u = ct * dx + st * dy
        v = -st * dx + ct * dy
        dh = self.k0 * ds + 0.5 * c * ds * ds
        return u, v, dh

    def curvature(self, ds: np.ndarray) -> np.ndarray:
        return self.k0 + self.rate * np.asarray(ds, dtype=float)


@dataclass(frozen=True, slots=True)
class ParamPoly3(Geometry):
    """u(p), v(p) cubic in p; p = local arc length (`arcLength`) or ds/length (`normalized`).

    As esmini and most tools do, p is taken as proportional to ds (the parametrisation is not re-normalised to
    true arc length); for the near-arc-length polynomials written by road editors the difference is sub-millimetre.
    """

    au: float = 0.0
    bu: float = 1.0
    cu: float = 0.0
    du: float = 0.0
    av: float = 0.0
    bv: float = 0.0
    cv: float = 0.0
    dv: float = 0.0
    normalized: bool = True

    def _p(self, ds: np.ndarray) -> np.ndarray:
        return ds / self.length if (self.normalized and self.length > 0) else ds

    def local_at(self, ds: float) -> tuple[float, float, float]:
        p = ds / self.length if (self.normalized and self.length > 0) else ds
        u = self.au + p * (self.bu + p * (self.cu + p * self.du))
        v = self.av + p * (self.bv + p * (self.cv + p * self.dv))
        du = self.bu + p * (2 * self.cu + 3 * self.du * p)
        dv = self.bv + p * (2 * self.cv + 3 * self.dv * p)
        return u, v, math.atan2(dv, du)

    def local(self, ds: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        p = self._p(ds)
        u = self.au + p * (self.bu + p * (self.cu + p * self.du))
        v = self.av + p * (self.bv + p * (self.cv + p * self.dv))
        du = self.bu + p * (2 * self.cu + 3 * self.du * p)
        dv = self.bv + p * (2 * self.cv + 3 * self.dv * p)
        return u, v, np.arctan2(dv, du)

    def curvature_local(self, ds: float) -> float:
        # The same operations on floats (the player asks this once per entity per step; a one-element array costs
        # ~40 us). The power stays numpy's: its pow differs from libm's in the last bit for some inputs, and a
        # scalar through the ufunc takes the same path as `curvature`'s one-element array.
        p = ds / self.length if (self.normalized and self.length > 0) else ds
        du = self.bu + p * (2 * self.cu + 3 * self.du * p)
        dv = self.bv + p * (2 * self.cv + 3 * self.dv * p)
        ddu = 2 * self.cu + 6 * self.du * p
        ddv = 2 * self.cv + 6 * self.dv * p
        return (du * ddv - dv * ddu) / max(float(np.power(du * du + dv * dv, 1.5)), 1e-12)

    def curvature(self, ds: np.ndarray) -> np.ndarray:
        p = self._p(np.asarray(ds, dtype=float))
        du = self.bu + p * (2 * self.cu + 3 * self.du * p)
        dv = self.bv + p * (2 * self.cv + 3 * self.dv * p)
        ddu = 2 * self.cu + 6 * self.du * p
        ddv = 2 * self.cv + 6 * self.dv * p
        return (du * ddv - dv * ddu) / np.maximum((du * du + dv * dv) ** 1.5, 1e-12)


@dataclass(frozen=True, slots=True)
class Poly3(Geometry):
    """v(u) = a + b·u + c·u² + d·u³ in the local frame (deprecated in OpenDRIVE 1.6, still found in old maps).

    s is arc length along the curve, so u(s) is found from a tabulated arc-length integral (Simpson on a fine grid)
    and linear interpolation; the table is built once per geometry."""

    a: float = 0.0
    b: float = 0.0
    c: float = 0.0
    d: float = 0.0
    _table: tuple[np.ndarray, np.ndarray] = field(default=None, repr=False, compare=False)  # type: ignore[assignment]

    def __post_init__(self) -> None:
        # The curve may be longer in u than needed; extend u until the arc length covers `length`.
        n = max(64, int(self.length / 0.05))
        u = np.linspace(0.0, max(self.length, 1e-9), n + 1)
        dv = self.b + u * (2 * self.c + 3 * self.d * u)
        integrand = np.sqrt(1.0 + dv * dv)
        arclen = np.concatenate(([0.0], np.cumsum(0.5 * (integrand[1:] + integrand[:-1]) * np.diff(u))))
        object.__setattr__(self, "_table", (arclen, u))

    def _u(self, ds: np.ndarray) -> np.ndarray:
        arclen, u = self._table
        return np.interp(ds, arclen, u)

    def local(self, ds: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        u = self._u(ds)
        v = self.a + u * (self.b + u * (self.c + u * self.d))
        dv = self.b + u * (2 * self.c + 3 * self.d * u)
        return u, v, np.arctan(dv)

    def curvature(self, ds: np.ndarray) -> np.ndarray:
        u = self._u(np.asarray(ds, dtype=float))
        dv = self.b + u * (2 * self.c + 3 * self.d * u)
        ddv = 2 * self.c + 6 * self.d * u
        return ddv / (1.0 + dv * dv) ** 1.5


class PlanView:
    """The reference line of one road: an ordered list of geometries, evaluated vectorised over s."""

    def __init__(self, geometries: list[Geometry]) -> None:
        self.geometries = sorted(geometries, key=lambda g: g.s)
        self._starts = np.array([g.s for g in self.geometries], dtype=float)
        self._start_list = [g.s for g in self.geometries]

    @property
    def length(self) -> float:
        if not self.geometries:
            return 0.0
        last = self.geometries[-1]
        return last.s + last.length

    def geometry_at(self, s: float) -> Geometry:
        """The geometry holding road s (the first/last one outside the road)."""
        i = bisect.bisect_right(self._start_list, s) - 1
        return self.geometries[min(max(i, 0), len(self.geometries) - 1)]

    def at(self, s: float) -> tuple[float, float, float]:
        """Scalar world (x, y, heading) of the reference line at road s."""
        g = self.geometry_at(s)
        return g.at(s - g.s)

    def curvature_at(self, s: float) -> float:
        g = self.geometry_at(s)
        return g.curvature_local(s - g.s)

    def _groups(self, s: np.ndarray) -> np.ndarray:
        idx = np.searchsorted(self._starts, s, side="right") - 1
        return np.clip(idx, 0, len(self.geometries) - 1)

    def evaluate(self, s: np.ndarray | float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """World (x, y, heading) of the reference line at road s (array or scalar; s outside the road is
        extrapolated along the first/last geometry)."""
        s_arr = np.atleast_1d(np.asarray(s, dtype=float))
        x = np.empty_like(s_arr)
        y = np.empty_like(s_arr)
        h = np.empty_like(s_arr)
        idx = self._groups(s_arr)
        if len(self.geometries) == 1:
            x[:], y[:], h[:] = self.geometries[0].evaluate(s_arr - self.geometries[0].s)
        else:
            for gi in sorted(set(idx.tolist())):   # = np.unique(idx), without importing numpy.ma
                m = idx == gi
                g = self.geometries[gi]
                x[m], y[m], h[m] = g.evaluate(s_arr[m] - g.s)
        return x, y, h

    def curvature(self, s: np.ndarray | float) -> np.ndarray:
        s_arr = np.atleast_1d(np.asarray(s, dtype=float))
        out = np.empty_like(s_arr)
        idx = self._groups(s_arr)
        for gi in sorted(set(idx.tolist())):   # = np.unique(idx), without importing numpy.ma
            m = idx == gi
            g = self.geometries[gi]
            out[m] = g.curvature(s_arr[m] - g.s)
        return out
