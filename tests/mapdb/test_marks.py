"""Road marks read from real files and the lane changes they permit."""

from __future__ import annotations

import pytest

from txt2sce_ros.errors import InputError
from txt2sce_ros.mapdb import load_map_database
from txt2sce_ros.mapdb.marks import Mark, crossing_allowed, read_marks

from .conftest import ESMINI_XODR, bundled


def test_explicit_lane_change_attribute_overrides_the_line_type() -> None:
    path = ESMINI_XODR / "straight_500m_roadmarks.xodr"
    table = read_marks(path.read_bytes(), str(path))
    centre = table[("0", 0, 0)] if ("0", 0, 0) in table else next(v for k, v in table.items() if k[2] == 0)
    assert {m.type for m in centre} >= {"solid", "solid solid", "broken"}
    assert all(m.lane_change == "both" for m in centre)
    assert all(m.allows(True) and m.allows(False) for m in centre)  # laneChange="both" even on solid lines


def test_line_types_and_directions_without_the_attribute() -> None:
    assert not Mark("solid", None).allows(True) and Mark("broken", None).allows(False)
    assert Mark("solid", "increase").allows(True) and not Mark("solid", "increase").allows(False)
    assert Mark("broken", "decrease").allows(False) and not Mark("broken", "none").allows(False)


def test_border_ownership_between_lanes() -> None:
    # Lane -2 -> -1 crosses the outer border of -1; lane 1 -> -1 crosses the centre lane's mark.
    table = {("r", 0, -1): (Mark("solid", None),), ("r", 0, 0): (Mark("broken", None),)}
    assert crossing_allowed(table, "r", 0, -2, True) is False
    assert crossing_allowed(table, "r", 0, -1, False) is False
    assert crossing_allowed(table, "r", 0, 1, False) is True
    assert crossing_allowed(table, "r", 0, -3, False) is None  # no mark known there


def test_two_plus_one_road_permits_changes_across_its_broken_lines() -> None:
    db = load_map_database(ESMINI_XODR / "two_plus_one.xodr", cache=False)
    (seg,) = [s for s in db.segments.values() if not s.is_connecting]
    four = next(sec for sec in seg.sections if len([ln for ln in sec.lanes if ln.type == "driving"]) == 4)
    lanes = {ln.id: ln for ln in four.lanes}
    assert lanes[-1].change_right and lanes[-2].change_left      # same direction, broken line
    assert not lanes[-1].change_left and not lanes[1].change_left  # the centre line: oncoming traffic beyond
    assert lanes[1].change_right and lanes[2].change_left          # lane 1 drives -s: its right is lane 2
    assert db.roads(needs={"lane_change_right"})


def test_malformed_file_names_the_source() -> None:
    data = bundled("one_way.xodr").read_bytes()[:300]
    with pytest.raises(InputError, match="broken.xodr"):
        read_marks(data, "broken.xodr")
