"""Lane topology on real maps: successors across junctions, neighbours, routing, turn types."""

from __future__ import annotations

import math
from collections import Counter

import pytest

from txt2sce_ros.errors import InputError
from txt2sce_ros.road import LaneRef

from .conftest import esmini_map


def test_successors_cross_the_junction_and_predecessors_invert_them(esmini_dir) -> None:
    net = esmini_map("fabriksgatan")
    start = LaneRef("0", 0, 1)                      # lane 1 drives along -s, into junction 4 at the road start
    succ = net.successors(start)
    assert {r.road_id for r in succ} == {"8", "9", "10"}
    assert all(net.roads[r.road_id].junction == "4" for r in succ)
    for nxt in succ:
        assert start in net.predecessors(nxt)
        # geometric continuity: the lane ends where its successor begins
        a = net.lane_centerline(start.road_id, start.lane_id, section=start.section)[-1]
        b = net.lane_centerline(nxt.road_id, nxt.lane_id, section=nxt.section)[0]
        assert abs(a[0] - b[0]) + abs(a[1] - b[1]) < 0.1


def test_every_successor_is_geometrically_continuous(esmini_dir) -> None:
    for name in ("multi_intersections", "soderleden", "two_plus_one", "parking_demo"):
        net = esmini_map(name)
        for ref in net.routing_graph.nodes:
            end = net.lane_centerline(ref.road_id, ref.lane_id, section=ref.section)[-1]
            for nxt in net.successors(ref):
                beg = net.lane_centerline(nxt.road_id, nxt.lane_id, section=nxt.section)[0]
                # A merging lane (width -> 0) ends on its successor's border, not on its centre.
                half = 0.5 * net.lane_width(nxt.road_id, nxt.lane_id, float(beg[2]))
                assert math.hypot(end[0] - beg[0], end[1] - beg[1]) < half + 0.1, (name, ref, nxt)


def test_four_way_junction_turn_types(esmini_dir) -> None:
    """Each arm of fabriksgatan's 4-way junction has one left, one straight and one right driving connection."""
    net = esmini_map("fabriksgatan")
    per_arm: dict[str, Counter] = {}
    for conn in net.junctions["4"].connections:
        for frm, to in conn.lane_links:
            inc = net.lane_ref(conn.incoming_road, frm, 1.0)
            if net.lane_type(inc.road_id, frm, 1.0) != "driving":
                continue
            cr = net.roads[conn.connecting_road]
            ref = net.lane_ref(cr.id, to, 0.0 if conn.contact_point == "start" else cr.length)
            per_arm.setdefault(conn.incoming_road, Counter())[net.turn_type(inc, ref)] += 1
    assert len(per_arm) == 4
    assert all(c == Counter(left=1, straight=1, right=1) for c in per_arm.values()), per_arm


def test_neighbours_in_right_and_left_hand_traffic(esmini_dir) -> None:
    rht, lht = esmini_map("e6mini"), esmini_map("e6mini-lht")
    assert rht.neighbour(LaneRef("0", 0, -3), "left") == LaneRef("0", 0, -2)
    assert rht.neighbour(LaneRef("0", 0, -3), "right") == LaneRef("0", 0, -4)
    assert rht.neighbour(LaneRef("0", 0, -2), "left") is None          # lane -1 is a border
    assert rht.neighbour(LaneRef("0", 0, 3), "left") == LaneRef("0", 0, 2)   # drives along -s: left is -t
    # LHT: positive lanes drive along +s, so their left is +t (outwards)
    assert lht.neighbour(LaneRef("0", 0, 3), "left") == LaneRef("0", 0, 4)
    assert lht.neighbour(LaneRef("0", 0, 3), "right") == LaneRef("0", 0, 2)
    # opposite-direction lanes are never neighbours
    two = esmini_map("straight_500m")
    assert two.neighbour(LaneRef("1", 0, -1), "left") is None


def test_route_through_junctions_and_lane_changes(esmini_dir) -> None:
    net = esmini_map("multi_intersections")
    g = net.routing_graph
    assert all(d["kind"] in ("follow", "change_left", "change_right") for *_, d in g.edges(data=True))
    start = LaneRef("196", 0, -1) if LaneRef("196", 0, -1) in g else next(iter(g.nodes))
    far = max(g.nodes, key=lambda r: len(__import__("networkx").shortest_path(g, start, r))
              if __import__("networkx").has_path(g, start, r) else 0)
    path = net.route(start, far)
    assert path[0] == start and path[-1] == far
    for a, b in zip(path, path[1:]):
        assert b in net.successors(a) or b in (net.neighbour(a, "left"), net.neighbour(a, "right"))
    assert any(net.roads[r.road_id].in_junction for r in path)


def test_route_without_path_is_input_error(esmini_dir) -> None:
    net = esmini_map("straight_500m")
    with pytest.raises(InputError, match="no route"):
        net.route(LaneRef("1", 0, -1), LaneRef("1", 0, 1))
