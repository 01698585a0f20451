"""Parties, their categories, actions and the contact, read from real California DMV narratives the rules were not
written from (session 13's study set, transcribed from a public CSV; each row's `source` is kept beside it). Each
test holds one reading mechanism; the narrative is the case that showed it missing."""

from __future__ import annotations

from txt2sce_ros.sketch import Sketch
from txt2sce_ros.text.extractor import extract

_CSV = "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial {}, " \
       "column 'Accident Detail Description'), transcribed"


def _read(report_id: str, text: str) -> Sketch:
    return extract(text, report_id)


def _partner(sk: Sketch):
    return next((p for p in sk.npcs + sk.obstacles if p.id == sk.collision.with_), None)


def test_a_lane_named_for_two_kinds_of_traffic_is_no_party() -> None:
    # csvr-cruise-20220905-s189, source: _CSV.format(189)
    sk = _read("csvr-cruise-20220905-s189", (
        'A Cruise autonomous vehicle ("Cruise AV"), operating in driverless autonomous mode, was traveling eastbound '
        'on Sacramento Street between Van Ness Avenue and Polk Street. The Cruise AV approached a semi-trailer truck '
        'that was stopped in the left lane of traffic. The Cruise AV stopped before maneuvering into the bus and taxi '
        'lane to pass the semi-trailer truck. As the Cruise AV was slowly maneuvering around the semi-trailer truck '
        'and merging back into the left lane of traffic, a Honda Accord traveling behind the Cruise AV attempted to '
        'pass the Cruise AV and made contact with the Cruise AV, damaging the rear passenger side bumper of the '
        'Cruise AV. The driver of the Honda Accord left the scene without exchanging information. There were no '
        'reported injuries.'))
    assert sorted(p.category for p in sk.npcs) == ["car", "truck"]  # no bus: "the bus and taxi lane" is a lane


def test_a_stop_sign_in_the_clause_after_a_contact_phrase_is_not_struck() -> None:
    # csvr-zoox-20191011-s35, source: _CSV.format(35)
    sk = _read("csvr-zoox-20191011-s35", (
        "The stationary Zoox vehicle was in autonomous mode heading northbound on Union St. Contact occurred when the "
        "Zoox vehicle was stopped at a stop sign at the intersection of Union St. and Grant St., when it was "
        "rear-ended by an electric scooter. The scooter was following closely behind the Zoox vehicle and the "
        "scooter driver was not focused on the Zoox vehicle in front of it, when the scooter's front tire made "
        "contact with the rear bumper of the Zoox vehicle. There were no injuries."))
    assert sk.obstacles == ()
    assert [p.category for p in sk.npcs] == ["scooter"] and _partner(sk).category == "scooter"


def test_the_last_word_of_a_party_s_name_refers_back_to_it() -> None:
    # csvr-waymo-20220209-s131, source: _CSV.format(131)
    sk = _read("csvr-waymo-20220209-s131", (
        "On February 9, 2022 at 3:05 PM PST a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, "
        "California was in a collision involving a pick-up truck on Coral Road at Wisconsin Street. The Waymo AV was "
        "traveling westbound on Coral Road in autonomous mode and came to a stop while yielding to an oncoming "
        "pick-up truck in a narrow roadway. The oncoming truck continued proceeding straight and made contact with "
        "the rear left sensor of the Waymo AV. At the time of the impact, the Waymo AV’s Level 4 ADS was engaged in "
        "autonomous mode, and a test driver was present (in the driver’s seating position). Both vehicles sustained "
        "minor damage."))
    assert [(p.category, p.position) for p in sk.npcs] == [("car", "R7")]  # one party; a pickup is a car
    assert sk.collision.with_ == "npc1"


def test_an_av_named_a_testing_vehicle_is_the_one_backed_into() -> None:
    # csvr-pony.ai-20220517-s159, source: _CSV.format(159)
    sk = _read("csvr-pony.ai-20220517-s159", (
        "On May 17, 2022, a passenger vehicle reversed out of a parking spot into a Pony.ai autonomous testing "
        "vehicle’s rear bumper. At the time of the collision, the Pony.ai vehicle was operating in autonomous mode "
        "with a safety operator in the driver’s seat and was moving at a low speed. The Pony.ai vehicle did not "
        "sustain any damage. There were no injuries or property damage, the police were not called to the scene, and "
        "a Pony.ai employee drove the Pony.ai vehicle back to Pony.ai’s Irvine facility."))
    assert len(sk.npcs) == 1 and sk.collision.with_ == "npc1"
    assert (sk.npcs[0].start, sk.npcs[0].actions) == ("stopped", "k")


def test_the_adv_is_the_av() -> None:
    # csvr-waymo-20211207-s118, source: _CSV.format(118)
    sk = _read("csvr-waymo-20211207-s118", (
        "On December 7, 2021 at 10:47 AM PST a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, CA "
        "was in a collision involving an SUV at Oak Street at Stanyan Street. While in autonomous mode, the Waymo AV "
        "came to a stop at a stop sign on Oak Street. While the ADV was stopped, waiting for a pedestrian to cross "
        "and for traffic on Stanyan Street to clear, an SUV approached the Waymo AV from behind and made contact "
        "with the rear of the Waymo AV. At the time of the impact, the Waymo AV’s Level 4 ADS was engaged in "
        "autonomous mode, and a test driver was present (in the driver’s seating position). The Waymo AV sustained "
        "minor damage to the rear bumper."))
    suv = _partner(sk)
    assert (suv.position, suv.lane, suv.start, suv.actions) == ("R6", "same", "moving", "a")  # it was the AV stopped
