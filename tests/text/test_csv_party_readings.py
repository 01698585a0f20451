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


def _collision_party(report_id: str, text: str) -> tuple[str, str]:
    p = _partner(_read(report_id, text))
    return p.start, p.actions


def test_a_party_queued_behind_the_standing_av_that_moves_off_starts_from_a_standstill() -> None:
    # csvr-waymo-20220214-s134, source: _CSV.format(134)
    assert _collision_party("csvr-waymo-20220214-s134", (
        "On February 14, 2022 at 3:02 PM PST a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, "
        "California was in a collision involving a passenger vehicle on Kansas Street at 16th Street. The Waymo AV "
        "was stopped at a red light facing north on Kansas Street at the 16th Street intersection in autonomous "
        "mode. While the traffic light was still red, the vehicle immediately behind the Waymo AV began to accelerate "
        "and made contact with the rear bumper of the Waymo AV. At the time of the impact, the Waymo AV’s Level 4 ADS "
        "was engaged in autonomous mode, and a test driver was present (in the driver’s seating position). The Waymo "
        "AV sustained minor damage.")) == ("stopped", "i")
    # csvr-argo-20211019-s102, source: _CSV.format(102)
    assert _collision_party("csvr-argo-20211019-s102", (
        "An Argo AI Autonomous Vehicle (“Argo AV”) was involved in a rear-end collision on Grant Ave. The Argo AV came "
        "to a complete stop at the stop sign located at the intersection of Grant Ave. and El Camino Real. After the "
        "Argo AV began to initiate a right-hand turn, the Argo AV came to a stop in response to oncoming traffic. A "
        "vehicle trailing behind the Argo AV moved forward and contacted the Argo AV’s left rear bumper. The Argo AV "
        "sustained minor damage to its left rear bumper.")) == ("stopped", "i")
    # csvr-waymo-20211112-s108, source: _CSV.format(108)
    assert _collision_party("csvr-waymo-20211112-s108", (
        "On November 12, 2021 at 1:23 PM PST a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, CA "
        "was in a collision involving a passenger vehicle at Divisadero Street at Turk Street. The Waymo AV was "
        "stopped at a red light on Divisadero Street at Turk Street. When the traffic light turned green, the "
        "passenger vehicle behind the Waymo AV made contact with the rear of the Waymo AV. At the time of the impact, "
        "the Waymo AV’s Level 4 ADS was engaged in autonomous mode, and a test driver was present (in the driver’s "
        "seating position). The Waymo AV sustained minor damage, and the trailing passenger vehicle sustained minor "
        "damage.")) == ("stopped", "i")


def test_a_subjectless_opening_while_stopped_is_the_av_standing() -> None:
    # csvr-waymo-20220219-s135, source: _CSV.format(135): the vehicle approached from behind, on its way
    assert _collision_party("csvr-waymo-20220219-s135", (
        "On February 19, 2022 at 7:45 PM PST a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, "
        "California was in a collision involving a passenger vehicle at the northbound merge lane on the 100 block of "
        "Bayshore Boulevard. While attempting a merge onto northbound Bayshore Boulevard from southbound Bayshore "
        "Boulevard, the Waymo AV came to a stop to yield for approaching traffic on the right. While stopped, a "
        "vehicle approached from behind and made contact with the rear bumper of the Waymo AV. The other vehicle left "
        "the scene without exchanging information. At the time of the impact, the Waymo AV’s Level 4 ADS was engaged "
        "in autonomous mode, and a test driver was present (in the driver’s seating position). The Waymo AV sustained "
        "minor damage.")) == ("moving", "a")


def test_not_coming_to_a_complete_stop_is_a_slowing() -> None:
    # csvr-cruise-20190502-s8, source: _CSV.format(8)
    assert _collision_party("csvr-cruise-20190502-s8", (
        "A Cruise autonomous vehicle (“Cruise AV”), operating in autonomous mode, was stopped at a red light on "
        "eastbound 24th Street at the intersection with Potrero Avenue when another vehicle approaching from the rear "
        "did not come to a complete stop and made contact with the Cruise AV’s rear bumper. The driver of the other "
        "vehicle drove away without exchanging information. The Cruise AV tester sitting in the driver’s seat "
        "requested medical treatment and emergency services arrived on the scene. SFPD incident report number was not "
        "available at the time of filing of this report.")) == ("moving", "ac")


def test_a_follower_that_then_changes_lane_travelled_first() -> None:
    # csvr-cruise-20191017-s39, source: _CSV.format(39)
    assert _collision_party("csvr-cruise-20191017-s39", (
        "A Cruise autonomous vehicle (“Cruise AV”), operating in autonomous mode, was stopped at a red light on "
        "southbound Hyde Street at the intersection with Sutter Street when another vehicle behind the Cruise AV "
        "attempted to change into the right adjacent lane and made contact with the right rear corner of the Cruise "
        "AV, damaging the Cruise AV’s right rear radar and assembly. There were no injuries and police were not "
        "called.")) == ("moving", "ag")


def test_backing_is_one_move_wherever_and_whyever_it_goes() -> None:
    # csvr-cruise-20230608-s248, source: _CSV.format(248): "reversing further into EGO's lane" is no lane change
    assert _collision_party("csvr-cruise-20230608-s248", (
        "A Cruise autonomous vehicle (“Cruise AV”), operating in driverless autonomous mode, was traveling southbound "
        "on Revere Avenue between Industrial Street and Selby Street. The Cruise AV came to a stop behind a GMC Yukon "
        "that was stopped diagonally in the Cruise AV’s lane of travel. After the Cruise AV came to a complete stop, "
        "the GMC Yukon began reversing further into the Cruise AV’s lane and made contact with the Cruise AV, "
        "damaging the front bumper fascia of the Cruise AV. The parties exchanged information and there were no "
        "reported injuries.")) == ("stopped", "k")
    # csvr-waymo-20240605-s317, source: _CSV.format(317): "began to reverse to parallel park" ends at the contact
    assert _collision_party("csvr-waymo-20240605-s317", (
        "On June 5, 2024 at 1:12 PM PT a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, "
        "California was in a collision involving a passenger car on 29th Avenue near Lawton Street. The Waymo AV was "
        "parked at the curb on the right side of 29th Avenue when a passenger car in front of the Waymo AV began to "
        "reverse to parallel park. The passenger car’s rear driver side corner made contact with the front driver "
        "side corner of the parked Waymo AV. At the time of the impact, the Waymo AV’s Level 4 ADS was engaged in "
        "autonomous mode. The Waymo AV sustained damage.")) == ("stopped", "k")
    # csvr-weride-20230608-s249, source: _CSV.format(249): "proceeded to reverse" is no run along the lane
    assert _collision_party("csvr-weride-20230608-s249", (
        "At 2:06pm a WeRide driverless vehicle (car 1) was stopped behind a big rig truck (vehicle 2). As our vehicle "
        "(car 1) was stopped behind the big rig truck, the big rig truck proceeded to reverse backwards and eventually "
        "collided into the WeRide vehicle (car 1). Both parties pulled over both involved vehicles and cooperated to "
        "exchange information. The damage sustained to the WeRide vehicle was moderate and the big rig truck did not "
        "have any damage.")) == ("stopped", "k")


def test_a_repeated_noun_refers_to_the_party_it_named_and_a_lead_vehicle_stood() -> None:
    # csvr-waymo-20240131-s297, source: _CSV.format(297): "the passenger vehicle" is the summary's passenger
    # vehicle, not "its lead vehicle" named in between; the lead vehicle the AV stopped behind stood there
    sk = _read("csvr-waymo-20240131-s297", (
        "On January 31, 2024 at 5:15 PM PT a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, "
        "California was in a collision involving a passenger vehicle on Potrero Avenue near 22nd Street. The Waymo AV "
        "was traveling southbound on Potrero Avenue in the leftmost thru lane, adjacent to a dedicated left turn lane "
        "on its left. As the Waymo AV approached the intersection with 22nd Street, it came to a stop behind its lead "
        "vehicle. The passenger vehicle behind the Waymo AV then attempted to change lanes into the dedicated left "
        "turn lane, and made contact with the rear driver side corner of the Waymo AV. At the time of the impact, the "
        "Waymo AV’s Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage."))
    assert len(sk.npcs) == 2
    hit = _partner(sk)
    lead = next(p for p in sk.npcs if p is not hit)
    assert (hit.position, hit.actions) == ("R6", "af")
    assert (lead.position, lead.lane, lead.start, lead.actions) == ("R5", "same", "stopped", "")


def test_a_party_the_av_yielded_to_is_not_the_summary_s_party_of_another_noun() -> None:
    # csvr-waymo-20240330-s307, source: _CSV.format(307): the pickup truck turning in the intersection is a second
    # party, and its left turn (told in a relative clause after where it was) is its own, not the AV's
    sk = _read("csvr-waymo-20240330-s307", (
        'On March 30, 2024 at 1:33 AM PT, a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
        'California was in a collision involving an SUV on Jerrold Avenue at Barneveld Avenue. The Waymo AV was '
        'stopped at a stop sign on Jerrold Avenue and yielding to a pickup truck that was in the intersection making '
        'a left turn from Barneveld Avenue onto Jerrold Avenue when the front right corner of the SUV, which was '
        'traveling behind the Waymo AV, made contact with the rear left corner of the Waymo AV. At the time of the '
        "impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage."))
    assert len(sk.npcs) == 2
    hit = _partner(sk)
    other = next(p for p in sk.npcs if p is not hit)
    assert (hit.position, hit.actions) == ("R6", "a") and other.actions == "d"
    assert (sk.ego.start, sk.ego.actions) == ("stopped", "")


def test_a_relative_clause_after_a_place_told_against_the_av_is_the_party_s() -> None:
    # csvr-waymo-20220424-s154, source: _CSV.format(154): "the vehicle directly in front of the Waymo AV, which
    # stopped" stopped on its way (the AV did not); "westbound Lincoln Way" is a street, not a Lincoln
    sk = _read("csvr-waymo-20220424-s154", (
        "On April 24, 2022 at 4:36 PM PST a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, "
        "California was in a collision involving an SUV on Lincoln Way at 17th Avenue. The Waymo AV was in "
        "autonomous mode and traveling on westbound Lincoln Way, when it slowed for the vehicle directly in front of "
        "the Waymo AV, which stopped shortly after passing 17th Avenue. Shortly after the Waymo AV came to a stop, the "
        "SUV behind the Waymo AV was rear-ended by a pickup truck, and the SUV then made contact with the rear of the "
        "Waymo AV. At the time of the impact, the Waymo AV’s Level 4 ADS was engaged in autonomous mode, and a test "
        "driver was present (in the driver’s seating position). Both vehicles sustained minor damage."))
    ahead = [p for p in sk.npcs if p.position == "R5"]
    assert len(sk.npcs) == 3 and [(p.lane, p.start, p.actions) for p in ahead] == [("same", "moving", "ah")]


def test_a_model_named_by_a_common_word_is_a_car_only_when_capitalised() -> None:
    sk = _read("matrix", "The AV slowed behind a heavy truck with a truck-mounted light matrix when a "
                         "Toyota Matrix struck its rear bumper.")
    assert [p.category for p in sk.npcs if p.id == sk.collision.with_] == ["car"]
    assert len(sk.npcs) == 2  # the truck and the Toyota, not the light matrix


def test_a_vehicle_the_av_only_travelled_behind_is_named_in_passing() -> None:
    # csvr-waymo-20240513-s311, source: _CSV.format(311): the box truck did nothing and the AV did nothing for it
    sk = _read("csvr-waymo-20240513-s311", (
        'On May 13, 2024 at 12:58 AM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Los Angeles, CA was in a '
        'collision involving a passenger car on eastbound Interstate 10 between Exit 2 and Exit 3A. The Waymo AV was '
        'traveling with a test driver present behind a box truck in the number 3 lane of eastbound Interstate 10 near '
        'the Bundy Drive overpass when a passenger car traveling at a high rate of speed approached the Waymo AV from '
        'behind. The passenger car partially entered the number 2 lane as the front right corner of the passenger car '
        'made contact with the rear left corner of the Waymo AV. The passenger car then made contact with the center '
        'median and came to a stop. The Waymo AV was transitioned into manual mode, and the test driver stopped the '
        "Waymo AV to the right-hand shoulder. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in "
        "autonomous mode, and a test driver was present (in the driver’s seating position). Both vehicles sustained "
        "damage."))
    assert [p.category for p in sk.npcs] == ["car"] and sk.collision.with_ == "npc1"
    # ... but one it slowed or stopped behind takes part (csvr-waymo-20240131-s297 above)


def test_a_number_given_first_beside_another_party_of_its_sentence_names_a_party_of_its_own() -> None:
    # csvr-zoox-20220830-s186, source: _CSV.format(186): "Vehicle Two" is not "a vehicle ahead" (one named in an
    # earlier sentence may be the party numbered: test_action_reading's reverse lights)
    sk = _read("csvr-zoox-20220830-s186", (
        "A Zoox vehicle in autonomy was proceeding straight on Kearney Street in San Francisco, CA, in stop-and-go "
        "traffic. The Zoox vehicle came to a stop for a vehicle ahead when Vehicle Two made light contact with the Zoox "
        "vehicle's rear bumper from behind. There were no injuries and the police were not called."))
    assert sorted(p.position for p in sk.npcs) == ["R5", "R6"] and _partner(sk).position == "R6"
    # ... and a sentence that opens with the number still opens a sentence (the AV's stop is not the party's)
    sk = _read("label", "The SV was stopped at a stop sign at the intersection. V2, approaching from the left on "
                        "the cross street, failed to stop and struck the front left corner of the SV.")
    assert (sk.ego.start, sk.ego.actions) == ("stopped", "") and len(sk.npcs) == 1


def test_before_then_a_sequence_adverb_tells_the_next_step_done() -> None:
    # csvr-waymo-20221229-s207, source: _CSV.format(207)
    assert _collision_party("csvr-waymo-20221229-s207", (
        "On December 29, 2022 at 3:15 AM PST a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, "
        "California was in a collision involving a passenger vehicle on 3rd Street and Mariposa Street. The Waymo AV "
        "was stopped facing north on 3rd Street for a red light in the right lane of the three-lane street while in "
        "autonomous mode. A passenger vehicle approached from behind and stopped behind the Waymo AV before "
        "eventually proceeding forward and making contact with the rear of the Waymo AV while the AV was still "
        "stopped at the red light. At the time of the impact, the Waymo AV’s Level 4 ADS was engaged in autonomous "
        "mode, and a test driver was present (in the driver’s seating position). The Waymo sustained damage.")) == \
        ("moving", "ahi")


def test_a_number_in_apposition_names_the_party_before_it() -> None:
    sk = _read("apposition", "The AV was stopped at a red light when a white SUV, Vehicle 2, struck its rear bumper.")
    assert len(sk.npcs) == 1 and sk.collision.with_ == "npc1"
