"""Issue 13: a party named loosely first ("another vehicle", "a motorist") and then by a more precise definite noun
("the passenger vehicle", "the passenger car") is one party, as it is when both name it "passenger vehicle". Found by
rewording real studyable narratives (tests/text/invariance.py, session 21); each test fails without the fix.
"""

from __future__ import annotations

from .quoted import QUOTED
from .quoted import quoted_sketch as _sketch


def _parties(report_id: str, text: str | None = None) -> list[tuple[str, str | None, str, str | None]]:
    return [(p.position, p.lane, p.actions, p.category) for p in _sketch(report_id, text).npcs]


def test_the_passenger_vehicle_after_a_summary_naming_another_vehicle() -> None:
    # csvr-waymo-20210709-s89, "was in a collision involving a passenger vehicle ... when the passenger vehicle
    # approached from behind ... struck the rear of the stopped Waymo AV" (gold R6/same `af`): told "involving another
    # vehicle", "the passenger vehicle" named no party (it was read as the AV) and the sketch lost its only party.
    rid = "csvr-waymo-20210709-s89"
    want = _parties(rid)
    assert want == [("R6", "same", "af", "car")]
    loose = QUOTED[rid][1].replace("involving a passenger vehicle", "involving another vehicle", 1)
    assert loose != QUOTED[rid][1] and _parties(rid, loose) == want
    assert _sketch(rid, loose).collision.with_ == _sketch(rid).collision.with_


def test_the_passenger_car_after_a_motorist_is_not_the_pickup_named_between() -> None:
    # dmvca-waymo-20241014-r619, "a passenger car entered the center southeast lane from a driveway to the right of
    # the pickup truck. As the passenger car entered ...": told "a motorist entered", "the passenger car" was taken
    # for the pickup truck named in between (the latest vehicle), and the pickup lost its swerve.
    rid = "dmvca-waymo-20241014-r619"
    want = _parties(rid)
    loose = QUOTED[rid][1].replace("when a passenger car entered", "when a motorist entered", 1)
    assert loose != QUOTED[rid][1] and _parties(rid, loose) == want
