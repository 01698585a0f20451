"""The bundled maps: generated deterministically, XSD-valid, and geometrically what their docstrings promise."""

from __future__ import annotations

import math

import numpy as np
import pytest

from txt2sce_ros.mapdb.bundled import BUNDLED, build_bundled_maps, bundled_map_paths, render
from txt2sce_ros.mapdb.xsd import validation_errors
from txt2sce_ros.road import RoadNetwork, load_network

from .conftest import bundled


@pytest.mark.parametrize("name", list(BUNDLED))
def test_committed_map_is_xsd_valid_and_regenerates_byte_for_byte(name: str) -> None:
    path = bundled(name)
    assert validation_errors(path) == []
    assert path.read_bytes() == render(name), "committed map is stale: run `txt2sce mapdb build-maps`"


def test_validator_rejects_a_broken_map() -> None:
    broken = render("one_way.xodr").replace(b'type="driving"', b'type="motorway"', 1)
    errors = validation_errors(broken)
    assert errors and "motorway" in errors[0]


def test_build_writes_every_map(tmp_path) -> None:
    written = build_bundled_maps(tmp_path)
    assert [p.name for p in written] == list(BUNDLED)
    for p in written:
        assert p.read_bytes() == bundled(p.name).read_bytes()


def test_every_bundled_map_loads_in_the_road_model() -> None:
    for path in bundled_map_paths():
        net = load_network(path)
        assert net.roads, path
        assert all(r.rule == "RHT" for r in net.roads.values())


def test_straight_road_lanes_and_length() -> None:
    net = load_network(bundled("straight_3x3.xodr"))
    road = net.roads["1"]
    assert road.length >= 400
    assert net.lane_ids("1", 10.0, types=None) == [6, 5, 4, 3, 2, 1, -1, -2, -3, -4, -5, -6]
    assert [net.lane_type("1", i, 10.0) for i in (-1, -2, -3, -4, -5, -6)] == [
        "driving", "driving", "driving", "biking", "parking", "sidewalk"]
    # Lane -1 drives along +s (east), lane 1 the other way, in right-hand traffic.
    assert net.lane_to_world("1", -1, 100.0)[2] == pytest.approx(0.0)
    assert abs(net.lane_to_world("1", 1, 100.0)[2]) == pytest.approx(math.pi)


def _connector_ends_meet_lanes(net: RoadNetwork) -> list[float]:
    """Gaps (m) between each connecting lane's ends and the centres of the lanes it links at the road ends."""
    gaps = []
    for junction in net.junctions.values():
        for conn in junction.connections:
            con = net.roads[conn.connecting_road]
            for from_lane, con_lane in conn.lane_links:
                inc = net.roads[conn.incoming_road]
                s_in = inc.length if inc.successor and inc.successor.element_id == junction.id else 0.0
                a = net.lane_to_world(inc.id, from_lane, min(s_in, inc.length - 1e-6))
                b = net.lane_to_world(con.id, con_lane, 0.0)
                gaps.append(math.hypot(a[0] - b[0], a[1] - b[1]))
                lane = con.sections[-1].lanes[con_lane]
                out = net.roads[con.successor.element_id]
                s_out = out.length - 1e-6 if out.successor and out.successor.element_id == junction.id else 0.0
                c = net.lane_to_world(con.id, con_lane, con.length - 1e-6)
                d = net.lane_to_world(out.id, lane.link.successor, s_out)
                gaps.append(math.hypot(c[0] - d[0], c[1] - d[1]))
                # The headings agree too: the lanes continue smoothly.
                assert math.cos(c[2] - d[2]) > math.cos(math.radians(1.0))
    return gaps


@pytest.mark.parametrize("name", ["junction4_signal.xodr", "junction3_stop.xodr", "junction4_stop.xodr",
                                  "roundabout.xodr"])
def test_connecting_lanes_join_the_lanes_they_link(name: str) -> None:
    gaps = _connector_ends_meet_lanes(load_network(bundled(name)))
    assert gaps and max(gaps) < 0.01


def test_junction4_signals_sit_at_each_stop_line_and_controllers_group_them() -> None:
    net = load_network(bundled("junction4_signal.xodr"))
    lights = [s for s in net.signals.values() if s.is_traffic_light]
    assert len(lights) == 8  # a main light and a left arrow per approach
    for sig in lights:
        road = net.roads[sig.road_id]
        assert road.length - sig.s < 2.0
        assert sig.dynamic and sig.controlled_lanes
    grouped = sorted(sid for c in net.controllers.values() for sid in c.signal_ids)
    assert grouped == sorted(s.id for s in lights)
    assert sorted(net.junctions["100"].controllers) == sorted(net.controllers)
    # Approach roads are at least 150 m long.
    assert all(net.roads[r].length >= 150 for r in ("1", "2", "3", "4"))


def test_curve_map_has_clothoid_arc_clothoid_transitions() -> None:
    net = load_network(bundled("curve.xodr"))
    road = net.roads["1"]
    s = np.linspace(0.0, road.length, 2001)
    k = road.plan_view.curvature(s)
    assert k.max() == pytest.approx(1 / 100, rel=1e-6)
    assert k.min() == pytest.approx(-1 / 150, rel=1e-6)
    # Curvature changes continuously (clothoids), never in a jump.
    assert np.max(np.abs(np.diff(k))) < 1e-4


@pytest.mark.parametrize("name", list(BUNDLED))
def test_lane_centres_locate_back_to_their_lanes(name: str) -> None:
    """Points on every driving lane's centre outside junctions map back to that lane (no overlapping roads)."""
    net = load_network(bundled(name))
    for rid, road in net.roads.items():
        if road.in_junction:
            continue
        for lid in net.lane_ids(rid, road.length / 2):
            pts = net.lane_centerline(rid, lid, ds=10.0)[1:-1]
            match = net.world_to_lane(pts[:, 0], pts[:, 1])
            assert list(match.road_id) == [rid] * len(pts), (name, rid, lid)
            assert list(match.lane_id) == [lid] * len(pts), (name, rid, lid)


@pytest.mark.parametrize("name", list(BUNDLED))
def test_plan_views_are_continuous(name: str) -> None:
    """Each geometry starts where the road model says the previous one ends (clothoid ends integrated by the
    generator, evaluated independently by the road model)."""
    net = load_network(bundled(name))
    for road in net.roads.values():
        for prev, geo in zip(road.plan_view.geometries, road.plan_view.geometries[1:]):
            x, y, h = prev.evaluate(np.array([prev.length]))
            assert math.hypot(x[0] - geo.x, y[0] - geo.y) < 1e-6, (name, road.id)
            assert math.cos(h[0] - geo.hdg) > 1 - 1e-12
