"""Issue 13, who counts and of what kind: party categories and obstacles against parties, read from real narratives
of the studyable sets (dev.jsonl with its official gold, tests/text/csvr/study2.jsonl, tests/text/sgo/study3.jsonl;
each narrative quoted with its id and source). One test per reading; each asserts what sketch.md's rules and the
study sets' gold give.
"""

from __future__ import annotations

from txt2sce_ros.text.extractor import extract

from .quoted import QUOTED

_TEXTS = QUOTED  # report id -> (source, narrative): tests/text/quoted.py


def _sketch(rid: str):
    return extract(_TEXTS[rid][1], rid)


def test_a_scooterist_rides_a_motor_scooter_an_electric_scooterist_a_scooter() -> None:
    # "a scooterist approaching from the rear merged into the Cruise AV's lane", "a scooterist, attempting to pass the
    # Cruise AV on the left": a motor scooter's rider, a motorcycle (sketch.md: mopeds are motorcycles; gold of both);
    # "yielded to an electric scooterist traveling northbound": an e-scooter (gold: scooter).
    assert [p.category for p in _sketch("csvr-cruise-20230504-s240").npcs] == ["motorcycle"]
    assert [p.category for p in _sketch("dmvca-cruise-20190107-r0").npcs] == ["motorcycle"]
    assert [p.category for p in _sketch("dmvca-cruise-20191107-r89").npcs] == ["scooter"]


def test_what_another_party_ran_into_takes_part() -> None:
    # "A pickup truck ... made contact with a passenger car parked facing south at the curb ... then made contact with
    # the rear driver side of the Waymo AV": the parked car the truck struck first is an obstacle of the event (gold:
    # parked_vehicle); "As the SUV in the left lane was passing the Waymo AV, it maneuvered to the left in its lane,
    # and the driver side made contact with the center concrete median curb": the curb (gold: barrier).
    assert [o.category for o in _sketch("nhtsa-sgo-ads-30270-10668-v1").obstacles] == ["parked_vehicle"]
    assert [o.category for o in _sketch("nhtsa-sgo-ads-30270-9376-v1").obstacles] == ["barrier"]


def test_a_chain_across_a_lot_is_a_barrier() -> None:
    # "made contact with a hanging chain separating a section of the parking lot", "made contact with a chain hanging
    # at the entrance of the parking lot": a chain closing a way is a barrier, as a gate is (gold of both); the AV
    # struck an object, so the report is complete.
    for rid in ("nhtsa-sgo-ads-30270-7729-v1", "nhtsa-sgo-ads-30270-7936-v1"):
        sk = _sketch(rid)
        assert [o.category for o in sk.obstacles] == ["barrier"]
        assert (sk.collision.with_, sk.collision.type, sk.missing) == ("obs1", "hit_object", ())


def test_the_first_of_two_is_the_earlier_and_a_party_struck_in_the_chain_takes_part() -> None:
    # (dev.jsonl, official gold) "A passenger car then braked to a stop behind the Waymo and to the left of the SUV. A
    # second passenger car then made contact with the SUV and the first passenger car": "the first passenger car" is
    # the one named first (not the second, named last), and a party the chain's car struck takes part (gold: three
    # cars, the SUV, the first and the second passenger car).
    assert [p.category for p in _sketch("nhtsa-sgo-ads-30270-10695-v1").npcs] == ["car"] * 3


def test_the_operator_s_motor_vehicle_is_the_av() -> None:
    # "PACCAR, Inc. (Paccar) manufactured the Kodiak-operated motor vehicle involved in the incident summarized in the
    # Incident Report": the AV, named as the SGO form names vehicles, no other party; the narrative tells no event, so
    # the report is incomplete (gold: no party, missing npcs).
    sk = _sketch("nhtsa-sgo-ads-988-3684-v1")
    assert sk.npcs == () and "npcs" in sk.missing


def test_a_line_track_or_station_named_by_a_vehicle_noun_is_no_party() -> None:
    # "traffic pylons on the left edge of the leftmost lane that separate this lane from the municipal tram line that
    # operates in the median": a tram line is a place, not a tram; the parties are the city bus and the passenger
    # vehicle behind (gold).
    assert sorted(p.category for p in _sketch("csvr-waymo-20201229-s69").npcs) == ["bus", "car"]


def test_a_model_named_between_make_and_noun_and_a_rider_s_wheelchair_are_one_party() -> None:
    # "A passenger car approached the Waymo AV from behind" (nhtsa-sgo-ads-30270-9347-v1), told with a make, its
    # model and the noun ("a Ford Transit van"), or as a person in a wheelchair: one party of the noun's kind.
    text = _TEXTS["nhtsa-sgo-ads-30270-9347-v1"][1]
    assert "a passenger car approached" in text and "the passenger car" in text
    for name, kind in (("Ford Transit van", "van"), ("white Honda Odyssey minivan", "van"),
                       ("person in a wheelchair", "pedestrian")):
        sk = extract(text.replace("a passenger car", f"a {name}").replace("the passenger car", f"the {name}"),
                     "rewritten")
        assert [p.category for p in sk.npcs] == [kind], name


def test_a_row_of_pylons_the_av_braked_for_is_one_obstacle() -> None:
    # "there are traffic pylons on the left edge of the leftmost lane ... Due to the encroaching city bus and the
    # pylons on the left edge of the Waymo AV's lane, the Waymo AV began to brake": the AV acted for the row (the
    # second of the two things "due to" names); one cone obstacle, on its left (gold).
    sk = _sketch("csvr-waymo-20201229-s69")
    assert [(o.category, o.position, o.lane) for o in sk.obstacles] == [("cone", "R5", "left")]


def test_a_possessive_printed_without_its_apostrophe_names_the_same_owner() -> None:
    # Redacted NHTSA narratives print possessives without the apostrophe ("the Waymo AVs Level 4 ADS", "the heavy
    # trucks trailer"). Told so, these read as with it: "The edge of the taxi cab's door made contact" (a door, gold),
    # "colliding with a bicyclist's back tire" (the cyclist), "the unoccupied parked passenger vehicle's driver side
    # view mirror" (the parked vehicle struck).
    for rid in ("dmvca-waymo-20220208-r284", "nhtsa-sgo-ads-30413-4170-v1", "dmvca-waymo-20210404-r172"):
        text = _TEXTS[rid][1]
        bare = text.replace("’s ", "s ").replace("'s ", "s ")
        assert bare != text, rid
        told, other = extract(text, rid), extract(bare, rid)
        assert [p.category for p in other.npcs] == [p.category for p in told.npcs], rid
        assert [o.category for o in other.obstacles] == [o.category for o in told.obstacles], rid
        assert other.collision == told.collision, rid


def test_a_cord_across_the_road_is_an_object_of_its_own_kind() -> None:
    # "the front of the Waymo AV made contact with a cord that was draped across the roadway and attached to a
    # plastic chair in the opposing lane": the cord is what the AV met, an `other` object like a fallen cable (gold);
    # the chair it was tied to is no second obstacle.
    sk = _sketch("nhtsa-sgo-ads-30270-10602-v1")
    assert [o.category for o in sk.obstacles] == ["other"]
    assert (sk.collision.with_, sk.collision.type) == ("obs1", "hit_object")


def test_what_lay_in_the_lane_named_by_more_nouns_is_the_object_met() -> None:
    # "the front passenger side of the Waymo AV made contact with a piece of debris that was in the lane of travel"
    # (gold: one debris, R5 same), told with what the debris was: the same object, of its kind.
    text = _TEXTS["nhtsa-sgo-ads-30270-9355-v1"][1]
    assert text.count("a piece of debris") == 2
    for name, kind in (("a cooler", "debris"), ("a bumper cover", "debris"), ("a cinder block", "debris"),
                       ("a puppy", "animal"), ("a suitcase", "debris")):
        sk = extract(text.replace("a piece of debris", name), "rewritten")
        assert [(o.category, o.position, o.lane) for o in sk.obstacles] == [(kind, "R5", "same")], name
        assert (sk.collision.with_, len(sk.npcs)) == ("obs1", 0), name


def test_the_vehicle_after_a_summary_s_vehicle_that_then_meets_the_av_is_that_party() -> None:
    # "was in a collision involving a passenger vehicle ... when the passenger vehicle approached from behind while
    # changing lanes. The passenger vehicle struck the rear of the stopped Waymo AV", told with the bare noun ("a
    # vehicle ... the vehicle approached ... The vehicle struck the rear of the stopped Waymo AV"): "the vehicle",
    # the subject of a sentence that names the AV after it, is the summary's party, not the AV.
    text = _TEXTS["csvr-waymo-20210709-s89"][1]
    bare = text.replace("passenger vehicle", "vehicle")
    assert bare != text
    told, other = extract(text, "s89"), extract(bare, "s89")
    assert [p.category for p in other.npcs] == [p.category for p in told.npcs] == ["car"]
    assert other.collision.with_ == told.collision.with_ == "npc1"
