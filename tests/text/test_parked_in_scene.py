"""Issue 13, parked vehicles in the scene, read from real NHTSA SGO narratives (tests/text/sgo6/study6.jsonl, W half;
quoted word for word in tests/text/quoted.py with their sources). sketch.md: "A parked, unattended vehicle is an
obstacle `parked_vehicle`". Each test asserts what the set's gold gives and fails without the rule.
"""

from __future__ import annotations

from .quoted import QUOTED, quoted_sketch


def _kinds(report_id: str, text: str | None = None) -> tuple[list[str], list[str], str | None]:
    s = quoted_sketch(report_id, text)
    return [n.category for n in s.npcs], [o.category for o in s.obstacles], s.collision.with_


def test_parked_vehicles_the_telling_names_before_the_contact_are_obstacles() -> None:
    # sgo6 4484: "stopped, unable to proceed past the garbage truck and an SUV parked parallel to the curb. The
    # garbage truck then attempted to pass between the Waymo AV and a parked passenger vehicle to the right of the
    # garbage truck": gold, the truck and two parked vehicles.
    assert _kinds("nhtsa-sgo-ads-30270-4484-v1") == (["truck"], ["parked_vehicle", "parked_vehicle"], "npc1")


def test_the_parked_car_is_the_one_told_parked_after_its_noun() -> None:
    # sgo6 9244: "a passenger car parked outside the marked parking spaces ... to pass around the parked passenger
    # car": one parked car, not two.
    assert _kinds("nhtsa-sgo-ads-30531-9244-v1")[1] == ["barrier", "parked_vehicle"]


def test_a_vehicle_told_parked_is_not_the_moving_party_of_the_same_noun() -> None:
    # sgo6 9214: "a black passenger car traveling north ... made contact with the rear driver side corner of the
    # Waymo AV. The impact caused the front of the Waymo AV to make contact with the rear bumper of the passenger car
    # parked in front of the Waymo AV": the parked car is an obstacle of its own, and the conflict is the first
    # contact (the one the impact caused is its effect).
    assert _kinds("nhtsa-sgo-ads-30270-9214-v1") == (["car"], ["parked_vehicle"], "npc1")


def test_a_contact_told_as_the_effect_of_the_first_is_not_the_conflict() -> None:
    text = QUOTED["nhtsa-sgo-ads-30270-9214-v1"][1]
    for opener in ("As a result, the front of the Waymo AV made", "The force of the impact caused the front of the "
                   "Waymo AV to make", "As a result of the collision, the front of the Waymo AV made",
                   "In a secondary impact, the front of the Waymo AV made", "The collision then caused the front of "
                   "the Waymo AV to make"):
        t = text.replace("The impact caused the front of the Waymo AV to make", opener)
        assert _kinds("nhtsa-sgo-ads-30270-9214-v1", t)[2] == "npc1", opener
