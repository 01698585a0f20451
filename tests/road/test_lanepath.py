"""LanePath: the concatenated centre line players and planners follow."""

from __future__ import annotations

import math

import numpy as np
import pytest

from txt2sce_ros.errors import InputError
from txt2sce_ros.road import LanePath, LaneRef

from .conftest import esmini_map


@pytest.fixture(scope="module")
def left_turn(esmini_dir):
    net = esmini_map("fabriksgatan")
    refs = net.route(LaneRef("0", 0, 1), LaneRef("3", 0, 1))
    return net, LanePath.from_lanes(net, refs)


def test_path_joins_lanes_without_gaps(left_turn) -> None:
    net, path = left_turn
    assert [r.road_id for r in path.lanes] == ["0", "10", "3"]
    total = sum(net.lane_length(r) for r in path.lanes)
    assert path.length == pytest.approx(total, abs=0.05)
    pts = path.positions(np.linspace(0, path.length, 2000))
    steps = np.hypot(np.diff(pts[:, 0]), np.diff(pts[:, 1]))
    assert steps.max() < 1.05 * path.length / 1999 + 1e-6


def test_position_matches_the_road_model(left_turn) -> None:
    net, path = left_turn
    for s in (0.0, 20.0, path.length * 0.5, path.length - 1.0):
        ref, road_s = path.lane_at(s)
        x, y, h = path.position(s)
        ex, ey, eh = net.lane_to_world(ref.road_id, ref.lane_id, road_s)
        assert math.hypot(x - ex, y - ey) < 0.01
        assert math.cos(h - eh) > 0.9999


def test_project_inverts_position(left_turn) -> None:
    _, path = left_turn
    rng = np.random.default_rng(3)
    for s, off in zip(rng.uniform(0, path.length, 50), rng.uniform(-1.5, 1.5, 50)):
        x, y, _ = path.position(float(s), float(off))
        ps, poff = path.project(x, y)
        assert ps == pytest.approx(s, abs=0.02) and poff == pytest.approx(off, abs=0.01)
        ps2, _ = path.project(x, y, s_hint=float(s) + 5.0)
        assert ps2 == pytest.approx(s, abs=0.02)


def test_offset_is_left_of_travel(left_turn) -> None:
    _, path = left_turn
    x0, y0, h = path.position(10.0)
    x1, y1, _ = path.position(10.0, 1.0)
    assert (x1 - x0, y1 - y0) == pytest.approx((-math.sin(h), math.cos(h)), abs=1e-9)


def test_curvature_on_a_circle(esmini_dir) -> None:
    net = esmini_map("curve_r100")
    road = net.roads["0"]
    arc = road.plan_view.geometries[1]
    path = LanePath.from_lanes(net, [LaneRef("0", 0, -1)])
    s_mid = arc.s + arc.length / 2                     # lane -1 drives along +s: path s == road s here
    t = net.lane_center_t("0", -1, s_mid)
    assert path.curvature(s_mid) == pytest.approx(arc.k / (1 - arc.k * t), rel=1e-3)


def test_partial_path_and_bad_sequences(esmini_dir) -> None:
    net = esmini_map("straight_500m")
    p = LanePath.from_lanes(net, [LaneRef("1", 0, -1)], s_start=100.0, s_end=150.0)
    assert p.length == pytest.approx(50.0, abs=1e-6)
    assert p.lane_at(10.0) == (LaneRef("1", 0, -1), pytest.approx(110.0))
    back = LanePath.from_lanes(net, [LaneRef("1", 0, 1)], s_start=150.0, s_end=100.0)
    assert back.position(0.0)[0] == pytest.approx(net.lane_to_world("1", 1, 150.0)[0])
    with pytest.raises(InputError, match="does not follow"):
        LanePath.from_lanes(esmini_map("fabriksgatan"), [LaneRef("0", 0, 1), LaneRef("3", 0, 1)])


def test_zero_length_and_backward_paths(esmini_dir) -> None:
    net = esmini_map("straight_500m")
    p = LanePath.from_lanes(net, [LaneRef("1", 0, -1)], s_start=100.0, s_end=100.0)
    assert p.length == pytest.approx(0.0, abs=1e-6)
    assert p.position(5.0)[:2] == pytest.approx(net.lane_to_world("1", -1, 100.0)[:2])
    assert p.lane_at(0.0)[0] == LaneRef("1", 0, -1)
    with pytest.raises(InputError, match="behind its start"):
        LanePath.from_lanes(net, [LaneRef("1", 0, -1)], s_start=150.0, s_end=100.0)
