"""The map database built from the bundled maps: nodes, edges, turn types, lights, control, lane changes."""

from __future__ import annotations

import math

import networkx as nx
import pytest

from txt2sce_ros.mapdb import Control, Layout, MapDatabase, Turn, build_map_database
from txt2sce_ros.road import load_network

from .conftest import bundled


def test_graph_nodes_carry_the_papers_lane_metadata(dbs: dict[str, MapDatabase]) -> None:
    g = dbs["straight_3x3.xodr"].graph
    assert isinstance(g, nx.MultiDiGraph) and list(g.nodes) == ["1"]
    node = g.nodes["1"]
    assert node["name"] == "main_street" and node["length"] == pytest.approx(500.0)
    assert node["lane_ids"] == [6, 5, 4, 3, 2, 1, -1, -2, -3, -4, -5, -6]
    assert node["lane_types"][:3] == ["sidewalk", "parking", "biking"]
    assert node["lane_directions"][5:7] == ["backward", "forward"]
    assert len(node["lane_change"]) == 12


def test_lane_change_permissions_follow_the_road_marks(dbs: dict[str, MapDatabase]) -> None:
    lanes = {ln.id: ln for ln in dbs["straight_3x3.xodr"].segment("1").main_section.lanes}
    # Broken white lines between same-direction lanes; the double yellow centre line has oncoming traffic behind it.
    assert lanes[-1].change_right and not lanes[-1].change_left
    assert lanes[-2].change_left and lanes[-2].change_right
    assert lanes[-3].change_left and not lanes[-3].change_right
    assert lanes[2].change_left and lanes[2].change_right  # lane 2 drives -s: its left is lane 1
    assert not lanes[-4].change_left  # a bike lane is no lane to change from
    # In the junction map a solid line (laneChange="none") fences off the left-turn lane.
    j4 = {ln.id: ln for ln in dbs["junction4_signal.xodr"].segment("1").main_section.lanes}
    assert not j4[-2].change_left and not j4[-1].change_right
    assert j4[-2].change_right and j4[-3].change_left


def test_lane_changes_default_to_allowed_without_marks() -> None:
    net = load_network(bundled("junction4_signal.xodr"))
    db = build_map_database(net, use_marks=False)
    j4 = {ln.id: ln for ln in db.segment("1").main_section.lanes}
    assert j4[-2].change_left and j4[-1].change_right


def test_junction4_edges_have_turns_lanes_and_the_controlling_light(dbs: dict[str, MapDatabase]) -> None:
    db = dbs["junction4_signal.xodr"]
    assert len(db.edges) == 20
    net = load_network(bundled("junction4_signal.xodr"))
    for e in db.edges:
        assert e.junction_id == "100" and e.connecting_road is not None and e.to_lane is not None
        # The light is the one on the incoming road that governs the start lane.
        sig = net.signals[e.signal_id]
        assert sig.road_id == e.from_road and e.from_lane in sig.controlled_lanes
        assert e.traffic_light == (pytest.approx(sig.x, abs=1e-3), pytest.approx(sig.y, abs=1e-3))
        data = db.graph.edges[e.from_road, e.to_road, e.key]
        assert data["turn_type"] == e.turn.value and data["traffic_light_x"] == e.traffic_light[0]
        assert data["start_lane_id"] == e.from_lane and data["end_lane_id"] == e.to_lane
    by_turn = {t: [e for e in db.edges if e.turn is t] for t in Turn}
    assert {t: len(v) for t, v in by_turn.items()} == {Turn.STRAIGHT: 8, Turn.LEFT: 4, Turn.RIGHT: 4, Turn.UTURN: 4}
    assert all(e.from_lane == -1 for e in by_turn[Turn.LEFT] + by_turn[Turn.UTURN])
    assert all(e.from_lane == -3 for e in by_turn[Turn.RIGHT])
    assert all(e.to_road == e.from_road for e in by_turn[Turn.UTURN])


def test_junction4_approaches(dbs: dict[str, MapDatabase]) -> None:
    db = dbs["junction4_signal.xodr"]
    info = db.junction_infos["100"]
    assert info.layout is Layout.JUNCTION4 and info.control is Control.SIGNAL and info.legs == 4
    assert (info.x, info.y) == (pytest.approx(0.0), pytest.approx(0.0))
    for app in db.approaches("100"):
        assert [ln.lane_id for ln in app.lanes] == [-1, -2, -3]
        assert app.lanes[0].dedicated_left and app.lanes[0].turns == {Turn.LEFT, Turn.UTURN}
        assert app.lanes[2].turns == {Turn.STRAIGHT, Turn.RIGHT}
        assert app.control is Control.SIGNAL and app.exit_lanes == 2
        # The approach points at the centre of the junction.
        assert math.cos(app.heading - math.atan2(info.y - app.y, info.x - app.x)) > 0.999


def test_relative_approaches_agree_with_turn_geometry(dbs: dict[str, MapDatabase]) -> None:
    """A left turn leaves on the road the R1 traffic (crossing from the left) comes from; right on R3's; straight
    on R2's. Two independent computations: turn types from connecting-lane geometry, R1-R3 from leg headings."""
    for name in ("junction4_signal.xodr", "junction3_stop.xodr", "junction4_stop.xodr"):
        db = dbs[name]
        for jid in db.junction_infos:
            for app in db.approaches(jid):
                rel = db.relative_roads(jid, app.road_id)
                for lane in app.lanes:
                    for e in lane.edges:
                        key = {Turn.LEFT: "left", Turn.RIGHT: "right", Turn.STRAIGHT: "opposite"}.get(e.turn)
                        if key:
                            assert rel[key] == e.to_road, (name, e)


def test_relative_approaches_skip_exit_only_legs(dbs: dict[str, MapDatabase]) -> None:
    db = dbs["junction4_stop.xodr"]
    assert db.relative_roads("400", "1") == {"left": "4", "opposite": "2", "right": "3"}
    rel = db.relative_approaches("400", "1")
    assert rel["opposite"] is None and rel["left"].road_id == "4" and rel["right"].road_id == "3"


def test_t_junction_stop_control_on_the_minor_road_only(dbs: dict[str, MapDatabase]) -> None:
    db = dbs["junction3_stop.xodr"]
    info = db.junction_infos["200"]
    assert info.layout is Layout.JUNCTION3 and info.control is Control.STOP_SIGN and info.legs == 3
    controls = {a.road_id: a.control for a in db.approaches("200")}
    assert controls == {"1": Control.NONE, "2": Control.NONE, "3": Control.STOP_SIGN}
    assert db.approach("200", "3").turns == {Turn.LEFT, Turn.RIGHT}
    assert all(e.traffic_light is None for e in db.edges)


def test_roundabout_is_recognised_from_its_ring(dbs: dict[str, MapDatabase]) -> None:
    db = dbs["roundabout.xodr"]
    assert {j.layout for j in db.junction_infos.values()} == {Layout.ROUNDABOUT}
    ring = {rid for rid, seg in db.segments.items() if Layout.ROUNDABOUT in seg.layouts and not seg.is_connecting}
    assert ring == {"11", "12", "13", "14"}
    assert all(db.segment(r).one_way for r in ring)
    # Entering from a leg is a right turn; staying on the ring is straight.
    for jid in db.junction_infos:
        for app in db.approaches(jid):
            assert app.turns == ({Turn.RIGHT} if app.road_id in {"1", "2", "3", "4"} else {Turn.RIGHT, Turn.STRAIGHT})


def test_road_layout_tags(dbs: dict[str, MapDatabase]) -> None:
    def tags(name: str) -> frozenset[Layout]:
        return dbs[name].segment("1").layouts

    assert tags("straight_3x3.xodr") == {Layout.STRAIGHT}
    assert tags("curve.xodr") == {Layout.CURVE}
    assert tags("parking_lot.xodr") == {Layout.PARKING, Layout.STRAIGHT}
    assert dbs["one_way.xodr"].segment("1").one_way
    assert not dbs["straight_3x3.xodr"].segment("1").one_way
    # Connecting roads carry their junction's layout.
    assert dbs["junction4_signal.xodr"].segment("101").layouts == {Layout.JUNCTION4}


def test_build_is_deterministic() -> None:
    net = load_network(bundled("junction4_signal.xodr"))
    a, b = build_map_database(net), build_map_database(net)
    assert a == b and [e.key for e in a.edges] == [e.key for e in b.edges]
