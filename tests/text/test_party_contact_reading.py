"""Issue 13, the other parties: readings of the AV's touched part and of a party's manoeuvre that says where it was,
held on real narratives of the studyable sets (dev_gold_study, study2, study3; each entry's source beside its text).
One test per reading; each asserts what the set's gold gives and fails without the rule.
"""

from __future__ import annotations

from txt2sce_ros.sketch import Sketch
from txt2sce_ros.text.extractor import extract

from .quoted import QUOTED

_REAL = QUOTED  # report id -> (source, narrative): tests/text/quoted.py


def _read(report_id: str) -> Sketch:
    return extract(_REAL[report_id][1], report_id)


def test_the_av_s_part_is_read_when_the_av_is_named_with_its_state() -> None:
    # "One cyclist then made contact with the front of the stationary Waymo AV": the part of the AV touched is told
    # ("the front of the stationary EGO"), so the party's place is told and the report is complete (gold: no
    # `missing`).
    assert _read("dmvca-waymo-20230507-r466").missing == ()


def test_a_party_parallel_parking_is_in_the_av_s_lane_not_beside_it() -> None:
    # "a passenger car in front of the Waymo AV began to reverse to parallel park": parking is its manoeuvre, not a
    # place parallel to the AV; it is ahead, in the AV's lane (gold R5, same, k).
    p = _read("csvr-waymo-20240605-s317").npcs[0]
    assert (p.position, p.lane, p.actions) == ("R5", "same", "k")
    # "slowed to a stop for an SUV that was parallel parking in front of the Waymo AV" (gold R5, same, l).
    suv = next(p for p in _read("nhtsa-sgo-ads-30270-10742-v1").npcs if p.actions == "l")
    assert (suv.position, suv.lane) == ("R5", "same")


def test_a_side_the_party_maneuvers_to_is_where_it_went() -> None:
    # "an SUV began to parallel park behind the Waymo AV. While parking, the SUV moved forward from the curb into the
    # roadway, maneuvering to the left of the Waymo AV": the left is where it went, not where it was; it began behind
    # the AV in its lane (gold R6, same).
    p = _read("nhtsa-sgo-ads-30270-9350-v1").npcs[0]
    assert (p.position, p.lane) == ("R6", "same")


def test_what_a_party_did_after_the_contact_does_not_place_it() -> None:
    # "a passenger car traveling at a high rate of speed approached the Waymo AV from behind ... the front right
    # corner of the passenger car made contact with the rear left corner of the Waymo AV. The passenger car then made
    # contact with the center median": the median is where it went afterwards; it was behind the AV (gold R6, same).
    p = _read("csvr-waymo-20240513-s311").npcs[0]
    assert (p.position, p.lane) == ("R6", "same")


def test_a_party_named_after_an_open_door_as_the_doer_of_the_contact_touched_the_av() -> None:
    # "the Waymo AV passenger opened the driver side rear door and the passenger side of the van made contact with
    # the open driver side rear door of the Waymo AV": the van touched the AV (gold: collision with the van, R6, same,
    # stopped behind it, then around it: "if").
    sk = _read("nhtsa-sgo-ads-30270-10599-v1")
    van = next(p for p in sk.npcs if p.id == sk.collision.with_)
    assert (van.category, van.position, van.lane, van.start, van.actions) == ("van", "R6", "same", "stopped", "if")


def test_another_av_of_the_fleet_is_a_party() -> None:
    # "The first Waymo AV was preparing to make a right turn, while yielding to the other Waymo AV": the other AV is
    # a party the AV yielded to, a car (official gold: the van, and the other AV as a car).
    sk = _read("dmvca-waymo-20241016-r620")
    assert sorted(p.category for p in sk.npcs) == ["car", "van"]
    assert next(p for p in sk.npcs if p.id == sk.collision.with_).category == "van"
