"""Road-matching queries: every sketch layout finds a bundled match; filters cut what they should."""

from __future__ import annotations

import json

import pytest

from txt2sce_ros.errors import InputError
from txt2sce_ros.mapdb import MapDatabase, Turn
from txt2sce_ros.paths import shared_dir


def test_roads_with_bike_and_parking_lanes_and_oncoming_traffic(dbs: dict[str, MapDatabase]) -> None:
    db = dbs["straight_3x3.xodr"]
    matches = db.roads("straight", min_lanes=3, one_way=False,
                       needs={"left_neighbour", "oncoming", "bike_lane", "parking_lane"})
    assert [(m.road_id, m.forward) for m in matches] == [("1", True), ("1", False)]
    fwd = matches[0]
    assert fwd.lanes == (-1, -2, -3) and fwd.oncoming == (1, 2, 3)
    assert fwd.right_side == ("biking", "parking", "sidewalk")
    assert matches[1].lanes == (1, 2, 3)  # left to right when driving along -s
    assert db.roads("straight", min_lanes=4) == []
    assert db.roads("curve") == []


def test_one_way_filter_and_its_sides(dbs: dict[str, MapDatabase]) -> None:
    db = dbs["one_way.xodr"]
    (only,) = db.roads(one_way=True, needs={"parking_lane", "lane_change_right"})
    assert only.lanes == (-1, -2) and only.oncoming == () and only.left_side == ("sidewalk",)
    assert db.roads(one_way=False) == []
    assert db.roads(needs={"oncoming"}) == []


def test_junction_queries_filter_by_layout_control_turns_and_needs(dbs: dict[str, MapDatabase]) -> None:
    j4, j3 = dbs["junction4_signal.xodr"], dbs["junction3_stop.xodr"]
    assert [j.id for j in j4.junctions("junction4", control="signal", min_lanes=3, turns={"left", "uturn"},
                                       needs={"dedicated_left"})] == ["100"]
    assert j4.junctions("junction3") == [] and j4.junctions(control="stop_sign") == []
    # A left turn from a lane with a same-direction lane on its left ("afd") is not offered: -1 is leftmost.
    assert j4.junctions(needs={"left_with_left_neighbour"}) == []
    assert [a.road_id for a in j3.approaches("200", control="stop_sign")] == ["3"]
    assert [a.road_id for a in j3.approaches("200", control="none", turns={Turn.LEFT})] == ["1"]
    assert [a.road_id for a in j3.approaches("200", needs={"right_with_right_neighbour"})] == []
    assert [j.id for j in j3.junctions("junction3", control="none", min_lanes=2)] == ["200"]


def test_bad_query_arguments_raise_input_errors(dbs: dict[str, MapDatabase]) -> None:
    db = dbs["junction4_signal.xodr"]
    with pytest.raises(InputError, match="unknown road need"):
        db.roads(needs={"helipad"})
    with pytest.raises(InputError, match="unknown layout"):
        db.roads("motorway")
    with pytest.raises(InputError, match="unknown control"):
        db.junctions(control="police")
    with pytest.raises(InputError, match="no junction"):
        db.approaches("999")


def _candidates(dbs: dict[str, MapDatabase], road: dict) -> list[str]:
    """Bundled maps offering a place for a sketch's `road` block, as road matching would look for it."""
    layout, control = road["layout"], road.get("control")
    found = []
    for name, db in dbs.items():
        if layout in ("junction4", "junction3", "roundabout"):
            ctrl = control if control in ("signal", "stop_sign", "none") else None
            if db.junctions(layout, control=ctrl, min_lanes=road.get("lanes"), one_way=road.get("one_way")):
                found.append(name)
        elif db.roads(layout, min_lanes=road.get("lanes"), one_way=road.get("one_way")):
            found.append(name)
    return found


def test_every_sketch_layout_finds_a_bundled_map(dbs: dict[str, MapDatabase]) -> None:
    layouts = ["straight", "curve", "junction4", "junction3", "roundabout", "parking"]
    for layout in layouts:
        assert _candidates(dbs, {"layout": layout}), layout
    assert _candidates(dbs, {"layout": "junction4", "control": "signal"}) == ["junction4_signal.xodr"]
    assert _candidates(dbs, {"layout": "junction3", "control": "stop_sign"}) == ["junction3_stop.xodr"]
    assert _candidates(dbs, {"layout": "junction4", "control": "stop_sign"}) == ["junction4_stop.xodr"]
    assert _candidates(dbs, {"layout": "junction4", "one_way": True, "lanes": 2}) == ["junction4_stop.xodr"]
    one_way = _candidates(dbs, {"layout": "straight", "one_way": True})
    assert "one_way.xodr" in one_way and "straight_3x3.xodr" not in one_way


def test_dev_set_sketches_find_bundled_roads(dbs: dict[str, MapDatabase]) -> None:
    """The hand-labelled dev sketches (dev set only): each complete one with a known layout has a match
    when its lane count is honoured, and a junction match with its control when that is signal or stop sign."""
    path = shared_dir() / "data" / "reports" / "dev_gold.jsonl"
    roads = []
    for line in path.read_text(encoding="utf-8").splitlines():
        sketch = json.loads(line)
        if not sketch["missing"] and sketch["road"]["layout"] != "unknown":
            roads.append(sketch["road"])
    assert len(roads) >= 50
    missing = [r for r in roads if not _candidates(dbs, r)]
    assert missing == []
