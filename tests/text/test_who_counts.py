"""Issue 13, who counts and what the AV struck: the party the AV touched found by the verbs that tell it, one party
named by the rider and by the ride, a door opened into the AV's path, a vehicle struck before the story, held on real
narratives of the studyable sets (study5's and study6's W halves; each entry's source in tests/text/quoted.py). One
test per reading; each asserts what the set's gold gives and fails without the rule.
"""

from __future__ import annotations

from .quoted import QUOTED, quoted_sketch as _read


def test_a_summary_s_ride_and_the_telling_s_rider_are_one_party() -> None:
    # "was in a collision involving a motorcycle ... A motorcyclist then approached from behind the stopped Waymo AV
    # ... As the motorcyclist passed, the motorcycle made contact with the rear passenger side corner" (study6
    # nhtsa-sgo-ads-30270-7639-v1; gold: one motorcycle).
    assert [p.category for p in _read("nhtsa-sgo-ads-30270-7639-v1").npcs] == ["motorcycle"]


def test_what_the_other_vehicle_struck_is_a_third_vehicle() -> None:
    # "a passenger vehicle in the right adjacent lane swerved into the Zoox vehicles lane and made contact with the
    # right passenger side door. The other vehicle also made contact with the vehicle in front of them after
    # contacting the Zoox vehicle" (study5 nhtsa-sgo-ads-30610-4814-v2): "the other vehicle" is the swerving one,
    # what it struck another (gold: two cars, the AV touched by the first).
    sk = _read("nhtsa-sgo-ads-30610-4814-v2")
    assert [p.category for p in sk.npcs] == ["car", "car"]
    assert sk.collision.with_ == "npc1"


def test_a_move_that_ends_in_the_av_is_its_contact() -> None:
    # "a car in a parking space in front of the stop backed up into the May vehicle at 2mph" (study6
    # nhtsa-sgo-ads-30413-9109-v1; gold: collision with the car, rear_end).
    sk = _read("nhtsa-sgo-ads-30413-9109-v1")
    assert (sk.collision.with_, sk.collision.type) == ("npc1", "rear_end")
    # "The pickup truck then slowly pushed into the rear of the Waymo AV" (study6 nhtsa-sgo-ads-30270-6337-v1).
    sk = _read("nhtsa-sgo-ads-30270-6337-v1")
    assert (sk.collision.with_, sk.collision.type) == ("npc1", "rear_end")


def test_crashing_into_an_object_is_a_contact_with_it() -> None:
    # "resulting in the vehicle crashing into a road sign/ pole" (study6 nhtsa-sgo-ads-669-1762-v3; gold: a pole, hit;
    # "Hyundai notes that ...", told after the crash, is the maker, no party).
    sk = _read("nhtsa-sgo-ads-669-1762-v3")
    assert ([o.category for o in sk.obstacles], sk.npcs, sk.collision.with_) == (["pole"], (), "obs1")


def test_a_door_opened_after_its_owner_is_named_is_the_obstacle() -> None:
    # "the driver's side door of a stopped passenger vehicle in the right adjacent lane opened, and made contact with
    # the front right sensor of the Zoox vehicle" (study6 nhtsa-sgo-ads-30610-2151-v1; gold: a door, no party: its
    # vehicle never moved).
    sk = _read("nhtsa-sgo-ads-30610-2151-v1")
    assert ([o.category for o in sk.obstacles], sk.npcs, sk.collision.with_) == (["door"], (), "obs1")


def test_a_vehicle_that_struck_the_object_before_the_story_takes_no_part() -> None:
    # "it made contact with a small dog that had apparently been previously struck by a preceding vehicle and was
    # laying in the roadway" (study6 nhtsa-sgo-ads-30270-9177-v1; gold: the dog only, hit).
    sk = _read("nhtsa-sgo-ads-30270-9177-v1")
    assert ([o.category for o in sk.obstacles], sk.npcs, sk.collision.with_) == (["animal"], (), "obs1")


def test_a_road_works_machine_is_a_truck() -> None:
    # "an asphalt roller vehicle passed the Waymo AV multiple times" (study6 nhtsa-sgo-ads-30270-9285-v1; gold: truck).
    assert [p.category for p in _read("nhtsa-sgo-ads-30270-9285-v1").npcs] == ["truck"]


def test_a_truck_s_cab_is_no_taxi() -> None:
    # "made contact with the driver side of the Waymo AV cab" (study6 nhtsa-sgo-ads-30531-2902-v2; gold: one truck).
    assert [p.category for p in _read("nhtsa-sgo-ads-30531-2902-v2").npcs] == ["truck"]


def test_a_thing_struck_that_no_word_list_names_is_an_object() -> None:
    # study6 nhtsa-sgo-ads-669-1762-v3 ("resulting in the vehicle crashing into a road sign/ pole") with the thing
    # struck named by a word no list holds: it is still the thing struck, an object "other", and the report is no
    # empty one (sketch.md: `npcs` is missing only when no party and no object is described).
    rid = "nhtsa-sgo-ads-669-1762-v3"
    sk = _read(rid, QUOTED[rid][1].replace("a road sign/ pole", "a carport"))
    assert ([o.category for o in sk.obstacles], sk.collision.with_, "npcs" in sk.missing) == (["other"], "obs1", False)
    # The ground met stays contact with nothing: "the Waymo AVs undercarriage then made contact with a speed bump"
    # (study5 nhtsa-sgo-ads-30270-5611-v1; gold: no object, `missing` npcs).
    sk = _read("nhtsa-sgo-ads-30270-5611-v1")
    assert (sk.obstacles, sk.collision.with_, "npcs" in sk.missing) == ((), None, True)


def test_a_thing_thrown_at_the_av_is_no_object_hit() -> None:
    # "a nearby Subaru Outback ran over road debris, which was projected onto the test vehicle" (dev_gold_study
    # dmvca-apple-20221220-r411) and "the front windshield was struck by an unknown object" (study3
    # nhtsa-sgo-ads-30530-6125-v1): the AV did not hit an object, a thing came at it (gold: collision type "other").
    for rid in ("dmvca-apple-20221220-r411", "nhtsa-sgo-ads-30530-6125-v1"):
        sk = _read(rid)
        assert (sk.obstacles[0].category, sk.collision.with_, sk.collision.type) == ("debris", "obs1", "other"), rid
