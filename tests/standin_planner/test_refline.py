import math

import numpy as np
import pytest

from standin_planner.refline import RefLine


def _circle(radius: float, n: int = 400) -> RefLine:
    a = np.linspace(0.0, math.pi, n)
    return RefLine(np.stack([radius * np.cos(a), radius * np.sin(a)], axis=1))


def test_projection_on_a_straight_gives_arc_length_and_left_offset():
    line = RefLine(np.array([[0.0, 0.0], [50.0, 0.0], [100.0, 0.0]]))
    pp = line.project(30.0, 2.0)
    assert pp.s == pytest.approx(30.0) and pp.offset == pytest.approx(2.0)
    assert line.project(30.0, -1.5).offset == pytest.approx(-1.5)
    # Beyond the end the line is extended straight.
    assert line.project(110.0, 0.0).s == pytest.approx(110.0)


def test_circle_curvature_and_position():
    line = _circle(20.0)
    mid = line.length / 2
    assert line.curvature_at(mid) == pytest.approx(1 / 20.0, rel=0.02)
    x, y, h = line.position(mid)
    assert math.hypot(x, y) == pytest.approx(20.0, abs=0.01)
    # Left of a counter-clockwise circle is towards its centre.
    x2, y2, _ = line.position(mid, offset=1.0)
    assert math.hypot(x2, y2) == pytest.approx(19.0, abs=0.01)


def test_project_many_matches_scalar_projection():
    line = _circle(30.0)
    pts = np.array([[25.0, 10.0], [-5.0, 31.0], [0.0, 28.0]])
    s, off = line.project_many(pts[:, 0], pts[:, 1])
    for (x, y), si, oi in zip(pts, s, off):
        pp = line.project(x, y)
        assert si == pytest.approx(pp.s, abs=1e-6) and oi == pytest.approx(pp.offset, abs=1e-6)


def test_junction_entry_and_exit():
    xy = np.stack([np.arange(0.0, 101.0), np.zeros(101)], axis=1)
    flags = (xy[:, 0] > 40) & (xy[:, 0] < 60)
    line = RefLine(xy, in_junction=flags)
    assert line.next_junction_entry(10.0, 100.0) == pytest.approx(40.0)
    assert line.next_junction_entry(10.0, 20.0) is None
    assert line.next_junction_entry(50.0, 100.0) is None           # already inside
    assert line.junction_exit(45.0) == pytest.approx(60.0)
