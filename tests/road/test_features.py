"""OpenDRIVE features the esmini maps do not exercise, on a tiny hand-written map (tests/road/data)."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from txt2sce_ros.road import LaneRef, load_network

FEATURES = Path(__file__).parent / "data" / "features.xodr"


@pytest.fixture(scope="module")
def net():
    return load_network(FEATURES)


def test_poly3_and_normalized_param_poly3(net) -> None:
    x, y, h = net.road_to_world("1", 40.0)
    # poly3 v = 0.002 u^2 over 20 m of arc: u a little under 20
    assert 39.9 < x < 40.0 and y == pytest.approx(0.002 * (x - 20) ** 2, abs=1e-6)
    assert math.tan(h) == pytest.approx(0.004 * (x - 20), abs=1e-6)
    assert net.road_to_world("2", 15.0)[:2] == pytest.approx((55.0, 0.0))


def test_border_lane_and_reversed_direction(net) -> None:
    assert net.lane_center_t("1", 1, 5.0) == pytest.approx(1.5)
    assert net.lane_width("1", 1, 5.0) == pytest.approx(3.0)
    # lane -1 of road 1 is reversed: in RHT it would drive along +s, here along -s
    assert not net.lane_forward("1", -1, 5.0)
    assert math.cos(net.lane_to_world("1", -1, 5.0)[2] - math.pi) == pytest.approx(1.0)


def test_end_to_end_road_link(net) -> None:
    # road 1 lane 1 drives along -s (RHT): no successor at s = 0; lane -1 is reversed: same
    assert net.successors(LaneRef("1", 0, 1)) == []
    # road 2 lane -1 drives along +s into road 1's end, where road 1 lane 1 (along -s) continues
    assert net.predecessors(LaneRef("1", 0, 1)) == [LaneRef("2", 0, -1)]


def test_signal_reference_and_controller(net) -> None:
    sig = net.signals["s1"]
    assert sig.dynamic and sig.controlled_lanes == ()      # lane -1 drives against '+'
    assert len(net.signal_references) == 1 and net.signal_references[0].road_id == "2"
    assert [s.id for s in net.signals_of_controller("c1")] == ["s1"]
