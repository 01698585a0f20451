"""The plain-dict lane graph and its search give what networkx gives on the same graph, ties included.

`route` (the player's routing actions) and the stand-in planner search `net.lane_graph` with
`topology.shortest_lane_path` instead of networkx, so that a cold process does not import networkx; every
trajectory depends on the lane sequence chosen, so the answer must be networkx's exactly, not merely as short."""

from __future__ import annotations

import random

import networkx as nx
import pytest

from txt2sce_ros.road import LaneRef

from txt2sce_ros.road.topology import (DRIVABLE_TYPES, LANE_CHANGE_COST, LaneGraph, lane_length,
                                      shortest_lane_path)

from .conftest import XODR, esmini_map

MAPS = sorted(p.stem for p in XODR.glob("*.xodr")) if XODR.is_dir() else []
#: Pairs searched per map and mode: all of them on small maps, an even spread on the large ones.
MAX_PAIRS = 2500


def _pairs(nodes: list) -> list[tuple]:
    every = [(a, b) for a in nodes for b in nodes]
    step = max(1, len(every) // MAX_PAIRS)
    return every[::step]


def _networkx_path(g: nx.DiGraph, a, b) -> list | None:
    try:
        return list(nx.shortest_path(g, a, b, weight="weight"))
    except (nx.NetworkXNoPath, nx.NodeNotFound):
        return None


def _reference_graph(net) -> nx.DiGraph:
    """The routing graph built straight into networkx by its rule (docs/road_api.md): every drivable lane, in the
    order of the network's lanes; per lane its 'follow' edges to its drivable successors, then its lane changes."""
    g = nx.DiGraph()
    for rid, road in net.roads.items():
        for si, sec in enumerate(road.sections):
            for lid, lane in sec.lanes.items():
                ref = LaneRef(rid, si, lid)
                if lid != 0 and lane.type in DRIVABLE_TYPES:
                    g.add_node(ref, length=lane_length(net, ref), road=rid, junction=road.junction, type=lane.type)
    for ref in list(g.nodes):
        for nxt in net.successors(ref):
            if nxt in g:
                g.add_edge(ref, nxt, kind="follow", weight=g.nodes[ref]["length"])
        for side in ("left", "right"):
            nb = net.neighbour(ref, side)
            if nb is not None and nb in g:
                g.add_edge(ref, nb, kind=f"change_{side}", weight=LANE_CHANGE_COST)
    return g


@pytest.mark.parametrize("name", MAPS)
def test_lane_graph_is_the_routing_graph_in_the_same_order(esmini_dir, name: str) -> None:
    net = esmini_map(name)
    g, lg = _reference_graph(net), net.lane_graph
    assert list(g.nodes(data=True)) == list(lg.nodes.items())
    built = net.routing_graph
    assert list(built.nodes(data=True)) == list(g.nodes(data=True))
    assert list(built.edges(data=True)) == list(g.edges(data=True))
    for ref in lg.nodes:
        # neighbour order is what decides between equal-length paths: both directions, in order
        assert [(b, (d["kind"], d["weight"])) for b, d in g._succ[ref].items()] == list(lg.succ[ref].items())
        assert [(a, (d["kind"], d["weight"])) for a, d in g._pred[ref].items()] == list(lg.pred[ref].items())


@pytest.mark.parametrize("name", MAPS)
def test_shortest_lane_path_is_networkx_path(esmini_dir, name: str) -> None:
    net = esmini_map(name)
    g, lg = net.routing_graph, net.lane_graph
    follow = nx.subgraph_view(g, filter_edge=lambda a, b: g[a][b]["kind"] == "follow")
    nodes = list(lg.nodes)
    found = missing = 0
    for a, b in _pairs(nodes):
        for view, follow_only in ((g, False), (follow, True)):
            want = _networkx_path(view, a, b)
            assert shortest_lane_path(lg, a, b, follow_only=follow_only) == want, (name, a, b, follow_only)
            found += want is not None
            missing += want is None
    assert found > 0
    # a lane outside the graph is no path, as networkx's NodeNotFound
    outside = next((r for r in net._topology_cache.get("succ", {}) if r not in lg.nodes), None)
    if outside is not None and nodes:
        assert shortest_lane_path(lg, outside, nodes[0]) is None


def test_equal_length_routes_pick_networkx_choice(esmini_dir) -> None:
    """two_plus_one holds equal-weight alternatives (lane changes on both sides): the searched pairs with two or
    more shortest paths get networkx's choice."""
    net = esmini_map("two_plus_one")
    g = net.routing_graph
    ties = 0
    for a in g.nodes:
        for b in g.nodes:
            if a != b and nx.has_path(g, a, b) and len(list(nx.all_shortest_paths(g, a, b, weight="weight"))) > 1:
                ties += 1
                assert shortest_lane_path(net.lane_graph, a, b) == _networkx_path(g, a, b), (a, b)
    assert ties >= 10


@pytest.mark.parametrize("seed", range(6))
def test_search_matches_networkx_on_tie_heavy_graphs(seed: int) -> None:
    """Random graphs with small integer and repeated weights (many equal-length paths), both edge kinds and some
    edges added twice (the second replaces the first's data in place, as networkx's add_edge does)."""
    rng = random.Random(seed)
    refs = [LaneRef(str(i), 0, -1) for i in range(40)]
    g = nx.DiGraph()
    nodes = {r: {"length": 1.0} for r in refs}
    succ: dict = {r: {} for r in refs}
    pred: dict = {r: {} for r in refs}
    for r in refs:
        g.add_node(r, length=1.0)
    for _ in range(140):
        a, b = rng.sample(refs, 2)
        kind = rng.choice(("follow", "follow", "change_left"))
        w = float(rng.choice((1, 2, 2, 3, 5)))
        g.add_edge(a, b, kind=kind, weight=w)
        succ[a][b] = pred[b][a] = (kind, w)
    lg = LaneGraph(nodes, succ, pred)
    follow = nx.subgraph_view(g, filter_edge=lambda a, b: g[a][b]["kind"] == "follow")
    ties = 0
    for a in refs:
        for b in refs:
            for view, follow_only in ((g, False), (follow, True)):
                want = _networkx_path(view, a, b)
                assert shortest_lane_path(lg, a, b, follow_only=follow_only) == want, (seed, a, b, follow_only)
                if want is not None and a != b and len(list(nx.all_shortest_paths(view, a, b, weight="weight"))) > 1:
                    ties += 1
    assert ties > 50
