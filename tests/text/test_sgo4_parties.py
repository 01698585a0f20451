"""Issue 13, who counts and what the other parties do, read from real NHTSA SGO narratives labelled before the
extractor ran on them (tests/text/sgo4/study4.jsonl; each entry's `source` beside its text in tests/text/quoted.py).
One test per reading mechanism; each asserts what sketch.md's rules and the official gold's conventions give.
"""

from __future__ import annotations

from .quoted import QUOTED
from .quoted import quoted_sketch as _sketch


def test_a_vehicle_noun_naming_the_damage_is_no_party() -> None:
    # "then struck the curb, resulting in minor vehicle damage": "vehicle" names the damage, not a vehicle; the AV
    # struck the curb alone ("no third parties were impacted").
    sk = _sketch("nhtsa-sgo-ads-30413-6684-v1")
    assert (len(sk.npcs), [o.category for o in sk.obstacles]) == (0, ["barrier"])
    for words in ("vehicle camera footage", "car damage", "vehicle owner"):
        text = QUOTED["nhtsa-sgo-ads-30413-6684-v1"][1].replace("minor vehicle damage", f"minor {words}")
        assert not _sketch("t", text).npcs, words


def test_the_av_s_own_door_is_no_obstacle_wherever_it_is_named() -> None:
    # "the passenger side of the SUV made contact with the open back driver side door of the stationary Waymo AV":
    # the AV's own door (a word of its state between "of" and the AV's name); the SUV is the party touched.
    sk = _sketch("nhtsa-sgo-ads-30270-9910-v1")
    assert (sk.obstacles, sk.collision.with_) == ((), "npc1")


def test_the_door_of_a_vehicle_that_moved_into_the_av_is_no_obstacle() -> None:
    # "as they did so with the door open, the passenger car started to proceed straight and made contact with the
    # rear of the Waymo AV": the car moved and touched the AV; its open door took no part of its own.
    sk = _sketch("nhtsa-sgo-ads-30270-7726-v1")
    assert (sk.obstacles, sk.collision.with_, sk.npcs[0].actions) == ((), "npc1", "i")


def test_a_redaction_that_swallowed_the_period_still_ends_the_sentence() -> None:
    # "... involving a passenger car on [XXX] The Waymo AV was stopped at the curb ...": the opening summary ends at
    # the redacted street; the telling after it is read as told (the party's approach and stop are no summary).
    sk = _sketch("nhtsa-sgo-ads-30270-9853-v1")
    assert sk.npcs[0].actions.startswith("ah")


def test_a_move_made_to_pass_after_a_stop_of_its_own_moves_the_party_off() -> None:
    # "approached the Waymo AV from behind, and came to a stop. The passenger car then maneuvered to pass the Waymo
    # AV on the left": approach, stop, move off (`ahi`); the pass is the purpose the move achieved.
    sk = _sketch("nhtsa-sgo-ads-30270-9853-v1")
    assert (sk.npcs[0].start, sk.npcs[0].actions) == ("moving", "ahi")


def test_a_toy_vehicle_is_an_object() -> None:
    # "a remote controlled toy car that was crossing the intersection": a thing the AV struck (obstacle `other`),
    # no traffic participant, though it moved.
    sk = _sketch("nhtsa-sgo-ads-30270-9823-v1")
    assert (sk.npcs, [o.category for o in sk.obstacles], sk.collision.with_) == ((), ["other"], "obs1")


def test_a_misspelt_operator_s_name_still_names_the_av() -> None:
    # "While the Wamo AV remained stopped, a van traveling behind the Waymo AV partially entered the left adjacent
    # lane": the standing is the AV's; the van was on its way (`af`, not a start from a standstill).
    p = _sketch("nhtsa-sgo-ads-30270-8875-v1").npcs[0]
    assert (p.start, p.actions) == ("moving", "af")


def test_the_vehicle_the_av_stopped_behind_stood_though_the_av_s_place_is_told_between() -> None:
    # "came to a stop in the rightmost travel lane heading south on [XXX] at [XXX], behind a van that was unloading
    # passengers and cargo in the travel lane": the van stood throughout (stopped, no action).
    sk = _sketch("nhtsa-sgo-ads-30270-6662-v1")
    assert [(p.start, p.actions) for p in sk.npcs if p.category == "van"] == [("stopped", "")]


def test_a_chain_party_named_after_the_contact_is_read_in_its_own_sentence() -> None:
    # (official gold, dev_gold_study) "The front of an SUV traveling directly behind the Waymo AV then made contact
    # with the right rear of the stationary Waymo AV. A passenger car then braked to a stop behind the Waymo and to
    # the left of the SUV. A second passenger car then made contact with the SUV and the first passenger car.":
    # the first passenger car travelled and stopped (`ah`), the second travelled (`a`).
    sk = _sketch("nhtsa-sgo-ads-30270-10695-v1")
    assert [p.actions for p in sk.npcs] == ["a", "ah", "a"]


def test_the_party_the_av_acted_for_counts_though_named_after_the_contact() -> None:
    # "the May vehicle made contact with the curb ... The May vehicle chose to maneuver at the curb due to perceived
    # risk from a car in an adjacent lane": the car the AV reacted to took part (sketch.md: a party the AV acted for,
    # singled out); the curb is the object struck.
    sk = _sketch("nhtsa-sgo-ads-30413-8861-v1")
    assert ([p.category for p in sk.npcs], [o.category for o in sk.obstacles], sk.collision.with_) == \
        (["car"], ["barrier"], "obs1")


def test_a_second_notice_of_an_allegation_tells_the_event() -> None:
    # (official gold, dev_gold) "On May 28, 2024, Waymo received notice of an allegation that a Waymo Autonomous
    # Vehicle ... may have contributed to a low-speed collision between a fire engine and an SUV ... Waymo received
    # notice of an allegation that as the fire engine proceeded straight, it made contact with the driver side of an
    # SUV that was parked at the curb": the first notice announces, the second tells; the parked SUV the fire engine
    # struck takes part (obstacle `parked_vehicle`).
    sk = _sketch("nhtsa-sgo-ads-30270-7938-v1")
    assert ([p.category for p in sk.npcs], [o.category for o in sk.obstacles]) == (["truck"], ["parked_vehicle"])


def test_a_turn_that_crosses_the_centre_line_is_no_lane_change() -> None:
    # "As the truck turned left, it partially crossed the centerline of [XXX]": the turn swung wide (`d`).
    assert _sketch("nhtsa-sgo-ads-30270-7882-v1").npcs[0].actions == "d"
