"""Third-party maps (esmini's conformance set): every one builds; junctions are found with plausible turns."""

from __future__ import annotations

import math

import pytest

from txt2sce_ros.mapdb import Control, Layout, MapDatabase, Turn, load_map_database
from txt2sce_ros.road import load_network

from .conftest import ESMINI_XODR

ALL = sorted(p.name for p in ESMINI_XODR.glob("*.xodr"))


def test_the_conformance_set_is_there() -> None:
    assert len(ALL) == 20


@pytest.mark.parametrize("name", ALL)
def test_every_esmini_map_builds(name: str) -> None:
    db = load_map_database(ESMINI_XODR / name, cache=False)
    net = load_network(ESMINI_XODR / name)
    assert set(db.segments) == set(net.roads)
    assert set(db.graph.nodes) == {r for r, road in net.roads.items() if not road.in_junction}
    assert set(db.junction_infos) == set(net.junctions)
    for e in db.edges:
        assert e.from_road in db.graph and e.to_road in db.graph
        assert e.junction_id == "-1" or e.junction_id in net.junctions
    assert db.summary().startswith("map ")


def _exit_heading(net, e) -> float:  # noqa: ANN001
    """Heading of travel leaving the junction on the edge's outgoing lane (independent of the turn classifier)."""
    road = net.roads[e.to_road]
    leaves_at_start = road.predecessor is not None and road.predecessor.element_id == e.junction_id
    s = 0.0 if leaves_at_start else road.length
    _, _, h = net.road_to_world(road.id, s)
    return h if leaves_at_start else h + math.pi


def _entry_heading(net, e) -> float:  # noqa: ANN001
    road = net.roads[e.from_road]
    arrives_at_end = road.successor is not None and road.successor.element_id == e.junction_id
    _, _, h = net.road_to_world(road.id, road.length if arrives_at_end else 0.0)
    return h if arrives_at_end else h + math.pi


@pytest.mark.parametrize("name", ["fabriksgatan.xodr", "fabriksgatan_traffic_lights.xodr",
                                  "multi_intersections.xodr"])
def test_junction_turn_types_match_road_headings(name: str) -> None:
    db: MapDatabase = load_map_database(ESMINI_XODR / name, cache=False)
    net = load_network(ESMINI_XODR / name)
    junction_edges = [e for e in db.edges if e.junction_id != "-1"]
    assert junction_edges
    for e in junction_edges:
        d = _exit_heading(net, e) - _entry_heading(net, e)
        d = math.degrees(math.atan2(math.sin(d), math.cos(d)))
        expected = Turn.STRAIGHT if abs(d) < 45 else Turn.UTURN if abs(d) > 135 else (
            Turn.LEFT if d > 0 else Turn.RIGHT)
        assert e.turn is expected, (e, d)


def test_fabriksgatan_is_a_four_way_junction_with_every_turn_from_every_approach() -> None:
    db = load_map_database(ESMINI_XODR / "fabriksgatan.xodr", cache=False)
    (info,) = db.junctions()
    assert info.layout is Layout.JUNCTION4 and info.legs == 4 and info.control is Control.NONE
    apps = db.approaches(info.id)
    assert len(apps) == 4
    for app in apps:
        assert app.turns == {Turn.LEFT, Turn.STRAIGHT, Turn.RIGHT}
        rel = db.relative_roads(info.id, app.road_id)
        for lane in app.lanes:
            for e in lane.edges:
                assert rel[{Turn.LEFT: "left", Turn.RIGHT: "right", Turn.STRAIGHT: "opposite"}[e.turn]] == e.to_road


def test_fabriksgatan_traffic_lights_put_a_light_on_the_controlled_approach() -> None:
    db = load_map_database(ESMINI_XODR / "fabriksgatan_traffic_lights.xodr", cache=False)
    (info,) = db.junctions(control="signal")
    lit = [e for e in db.edges if e.traffic_light]
    assert lit and {e.from_road for e in lit} == {a.road_id for a in db.approaches(info.id, control="signal")}
    for e in lit:  # the light stands near the junction
        assert math.hypot(e.traffic_light[0] - info.x, e.traffic_light[1] - info.y) < 40


def test_multi_intersections_layouts_and_signals() -> None:
    db = load_map_database(ESMINI_XODR / "multi_intersections.xodr", cache=False)
    layouts = sorted(j.layout.value for j in db.junction_infos.values())
    assert layouts == ["junction3", "junction3", "junction3", "junction4", "junction4"]
    for info in db.junction_infos.values():
        apps = db.approaches(info.id)
        assert len(apps) == info.legs
        assert all(a.control is Control.SIGNAL for a in apps)
        if info.layout is Layout.JUNCTION3:
            # At a T, one approach has no straight-on, the other two lack one turn each.
            assert sorted(len(a.turns) for a in apps) == [2, 2, 2]
            assert sum(Turn.STRAIGHT not in a.turns for a in apps) == 1
        else:
            assert all({Turn.LEFT, Turn.RIGHT} <= a.turns for a in apps)
    assert db.junctions("junction4", control="signal", turns={"left"})
