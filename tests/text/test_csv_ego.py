"""Issue 13, the AV's own start and action string, read from real narratives the rules were not written from:
California DMV collision reports transcribed in session 13 from a public CSV (each row's `source` beside its text).
One test per reading mechanism; each asserts the reading sketch.md's rules and the official gold's conventions give.
"""

from __future__ import annotations

from txt2sce_ros.text.extractor import extract

# id -> (source, narrative)
_CSV: dict[str, tuple[str, str]] = {
    'csvr-zoox-20230208-s212': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv'"
        " (serial 212, column 'Accident Detail Description'), transcribed",
        "A Zoox vehicle in autonomy was stopped with brake lights illuminated in traffic southbound on "
        "Embarcadero Street towards Folsom Street. When traffic ahead began to move the Zoox vehicle was "
        "appropriately following the car ahead at low speed when it was rear ended by Vehicle #2 at low speed. "
        "The other party did not stop to exchange information and left the scene. There were no injuries and "
        "police were not called."),
    'csvr-zoox-20240115-s294': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv'"
        " (serial 294, column 'Accident Detail Description'), transcribed",
        "A Zoox vehicle (Vehicle 1) in autonomy was traveling on southbound Stockton St near Union St in San "
        "Francisco. The Zoox vehicle slowed to a gradual stop with brake and hazard lights activated during a "
        "simulated pick up-drop off maneuver when it was rear-ended by a minivan (Vehicle 2). The rear bumper of "
        "the Zoox vehicle sustained minor damage. There were no reported injuries, and police were not called. "
        "Zoox vehicle camera footage shows that the driver of the minivan may not have been looking ahead at the "
        "roadway prior to and at the time of contact."),
    'csvr-zoox-20230517-s243': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv'"
        " (serial 243, column 'Accident Detail Description'), transcribed",
        "A Zoox vehicle in autonomous mode was traveling north on Harrison St. The Zoox vehicle began coming to a"
        " gradual stop for traffic ahead when it was rear ended by vehicle 2 at low speed. There was minor damage"
        " and police were not called. The Zoox operator reported a \"sore neck and back.\""),
    'csvr-waymo-20230320-s224': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv'"
        " (serial 224, column 'Accident Detail Description'), transcribed",
        "On March 20, 2023 at 10:43 AM PST a Waymo Autonomous Vehicle (“Waymo AV”) operating in Los Angeles, "
        "California was in a collision involving an SUV on Venice Boulevard at La Cienega. The Waymo AV was "
        "stopped in the center lane of a three-lane road behind a passenger vehicle for a red light facing "
        "southwest on Venice Boulevard at La Cienega in autonomous mode. The light turned green while cross-"
        "traffic remained backed up in the intersection. The Waymo AV nudged forward and slowed to a stop, "
        "yielding for the blocking cross traffic. A passenger vehicle that had been stopped behind the Waymo AV "
        "proceeded forward and made contact with the rear of the Waymo AV. At the time of the impact, the Waymo "
        "AV’s Level 4 ADS was engaged in autonomous mode, and a test driver was present (in the driver’s seating "
        "position). The Waymo AV sustained damage."),
    'csvr-zoox-20240716-s322': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv'"
        " (serial 322, column 'Accident Detail Description'), transcribed",
        "A Zoox vehicle (Vehicle 1) in autonomous mode was stopped at a stop sign waiting for traffic to clear to"
        " make a left turn from northeast bound King Street onto 7th Street in San Francisco. A passenger car "
        "(Vehicle 2) was stopped directly behind the Zoox vehicle apparently in the process of turning right onto"
        " 7th Street. As the Zoox vehicle advanced and then came to a stop as it yielded to cross traffic, the "
        "passenger car tried to pass the Zoox vehicle on the right side and contacted the Zoox vehicle. The front"
        " bumper on the passenger car and rear bumper on the Zoox vehicle sustained minor damage. There were no "
        "reported injuries and the police were not called."),
    'csvr-waymo-20220128-s127': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv'"
        " (serial 127, column 'Accident Detail Description'), transcribed",
        "On January 28, 2022 at 6:30 AM PST a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, "
        "California was in a collision involving a passenger vehicle on Franklin Street at Golden Gate Avenue. "
        "The Waymo AV was stopped at a red light on northbound Franklin Street at Golden Gate Avenue. After the "
        "traffic light turned green and the Waymo AV had begun to accelerate, the passenger vehicle behind the "
        "Waymo AV struck the rear of the Waymo AV. At the time of the impact, the Waymo AV’s Level 4 ADS was "
        "engaged in autonomous mode, and a test driver was present (in the driver’s seating position). The Waymo "
        "AV sustained minor damage, and the trailing passenger vehicle sustained minor damage."),
    'csvr-mercedes-benz-20220519-s161': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv'"
        " (serial 161, column 'Accident Detail Description'), transcribed",
        "While departing from a standstill in heavy traffic with L3 ADS engaged, the subject Mercedes-Benz "
        "vehicle was struck in the rear bumper by a large semi-truck. No injuries were reported. The contact from"
        " the truck resulted in two minor scratches and two indentations on the rear bumper of the subject "
        "Mercedes-Benz. The driver of the truck did not pull over after the collision and departed the scene. "
        "After a police report was initiated, the subject Mercedes-Benz drove away from the incident location. "
        "Further inspection of the vehicle revealed no additional damage beyond the cosmetic dents and surface "
        "scratches on the Mercedes-Benz."),
    'csvr-waymo-20220211-s132': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv'"
        " (serial 132, column 'Accident Detail Description'), transcribed",
        "On February 11, 2022 at 5:36 PM PST a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, "
        "California was in a collision involving a passenger vehicle on Market Street and Valencia Street. The "
        "Waymo AV was approaching stopped traffic in the left turn lane on Market Street at Valencia Street when "
        "a passenger vehicle approached from behind and made contact with the rear bumper of the Waymo AV. The "
        "other vehicle left the scene without exchanging information. At the time of the impact, the Waymo AV’s "
        "Level 4 ADS was engaged in autonomous mode, and a test driver was present (in the driver’s seating "
        "position). The Waymo AV sustained minor damage."),
    'csvr-argo-20211019-s102': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv'"
        " (serial 102, column 'Accident Detail Description'), transcribed",
        "An Argo AI Autonomous Vehicle (“Argo AV”) was involved in a rear-end collision on Grant Ave. The Argo AV"
        " came to a complete stop at the stop sign located at the intersection of Grant Ave. and El Camino Real. "
        "After the Argo AV began to initiate a right-hand turn, the Argo AV came to a stop in response to "
        "oncoming traffic. A vehicle trailing behind the Argo AV moved forward and contacted the Argo AV’s left "
        "rear bumper. The Argo AV sustained minor damage to its left rear bumper."),
    'csvr-cruise-20220409-s148': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv'"
        " (serial 148, column 'Accident Detail Description'), transcribed",
        "A Cruise autonomous vehicle (\"Cruise AV\"), operating in driverless autonomous mode, was stopped at a red"
        " light on northbound Van Ness Avenue at the intersection with Sacramento Street. The Cruise AV entered "
        "the intersection on a green light and continued straight through the intersection before braking and "
        "coming to a complete stop near the end of the intersection. At the same time, a Toyota Sedan on "
        "westbound Sacramento Street began was making an unprotected right turn on a red light onto northbound "
        "Van Ness Avenue behind the Cruise AV. Shortly thereafter, the Toyota Sedan rear-ended the Cruise AV and "
        "made contact with the Cruise AV's rear bumper, damaging the rear right bumper. The driver of the other "
        "vehicle left the scene without exchanging information. There were no injuries and a police report was "
        "later filed."),
    'csvr-cruise-20230422-s236': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv'"
        " (serial 236, column 'Accident Detail Description'), transcribed",
        "A Cruise autonomous vehicle (\"Cruise AV\"), operating in driverless autonomous mode, was at a complete "
        "stop in response to a red light on 10th Street at the intersection with Division Street. The Cruise AV "
        "began to make a right turn onto Division Street after the light turned green before yielding to a "
        "pedestrian in the crosswalk. Shortly thereafter, a silver Infiniti Sedan traveling behind the Cruise AV "
        "made contact with the Cruise AV’s rear bumper, causing damage to the Cruise AV’s rear fascia. The driver"
        " of the Infiniti Sedan left the scene without exchanging information. There were no reported injuries."),
    'csvr-zoox-20210511-s81': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv'"
        " (serial 81, column 'Accident Detail Description'), transcribed",
        "A Zoox vehicle in autonomous mode began to slow down during an unprotected left turn to yield for cross "
        "traffic entering the lane from the right. A passenger vehicle from behind did not slow and made contact "
        "with the rear sensors of the Zoox vehicle. There were no injuries and the police were not called."),
    'csvr-cruise-20190524-s14': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv'"
        " (serial 14, column 'Accident Detail Description'), transcribed",
        "A Cruise autonomous vehicle (“Cruise AV”), operating in autonomous mode, was changing lanes into the "
        "left turn lane on eastbound Geary Boulevard between 8th and 9th Avenues when the Cruise AV slowed down. "
        "The driver of the Cruise AV disengaged from autonomous mode and, shortly thereafter, another vehicle "
        "changing into the same lane made contact with the rear bumper of the Cruise AV, damaging the Cruise AV’s"
        " bumper. There were no injuries and police were not called."),
    'csvr-waymo-20210709-s89': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv'"
        " (serial 89, column 'Accident Detail Description'), transcribed",
        "A Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, California was in a collision "
        "involving a passenger vehicle at Bush Street and Grant Avenue. The Waymo AV was stopped in traffic while"
        " in autonomous mode when the passenger vehicle approached from behind while changing lanes. The "
        "passenger vehicle struck the rear of the stopped Waymo AV traveling at 5.5 miles per hour and left the "
        "scene. The left rear bumper of the Waymo AV sustained minor damage."),
    'csvr-waymo-20190529-s15': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv'"
        " (serial 15, column 'Accident Detail Description'), transcribed",
        "A Waymo Autonomous Vehicle (“Waymo AV”) in autonomous mode was stopped in traffic while in the leftmost "
        "lane on southbound San Antonio Road headed toward Charleston Road in Palo Alto when it was rear-ended by"
        " a passenger vehicle maneuvering into the Waymo AV’s lane at approximately less than 1 MPH. The Waymo AV"
        " sustained minor scratches to its rear sensor, and the passenger vehicle left the scene. There were no "
        "injuries reported at the scene."),
    'csvr-waymo-20220103-s122': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv'"
        " (serial 122, column 'Accident Detail Description'), transcribed",
        "On January 3, 2021 at 9:00 AM PST a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, "
        "California was in a collision involving a heavy truck at the northbound merge lane on the 100 block of "
        "Bayshore Boulevard. At the time of the impact, the Waymo AV’s Level 4 ADS was engaged in autonomous "
        "mode, and a test driver was present (in the driver’s seating position). While attempting a merge onto "
        "northbound Bayshore Boulevard from southbound Bayshore Boulevard, the Waymo AV came to a stop to yield "
        "for approaching traffic on the right. The Waymo AV was rear ended by the truck, causing minor damage to "
        "the right rear bumper of the Waymo AV. The truck sustained damage to the left front bumper."),
    'csvr-waymo-20230605-s246': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv'"
        " (serial 246, column 'Accident Detail Description'), transcribed",
        "On June 5, 2023 at 12:53 PM PT a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, "
        "California was in a collision involving a van in a parking lot at 3911 3rd Street. The Waymo AV came to "
        "a stop while yielding to a pickup truck which was reversing into a perpendicular parking space in front "
        "of the Waymo AV. While the Waymo AV was stopped, a van which was in a parking space immediately to the "
        "right of the Waymo AV began reversing out of the parking space. The rear of the van made contact with "
        "the right side of the Waymo AV. The Waymo AV sustained damage. At the time of the impact, the Waymo AV’s"
        " Level 4 ADS was engaged in autonomous mode."),
    'csvr-waymo-20190226-s3': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv'"
        " (serial 3, column 'Accident Detail Description'), transcribed",
        "A Waymo Autonomous Vehicle (“Waymo AV”) was stopped in autonomous mode at the intersection of Miramonte "
        "Avenue and Covington Road in Los Altos when it was involved in a collision. The Waymo AV was traveling "
        "northbound on Miramonte Avenue, when it reached a four-way stop sign intersection. The Waymo AV stopped "
        "to yield to another vehicle at the intersection, at which time a passenger vehicle rear-ended the Waymo "
        "AV at approximately 39 MPH. At the time of the collision the Waymo AV had been stopped for approximately"
        " 1.5 seconds. The Waymo AV sustained major damage to its rear bumper, rear hatch, and rear quarter "
        "panels, and the passenger vehicle sustained major damage to its front bumper, hood, and front quarter "
        "panels. First responders attended to the scene, but neither party reported injuries."),
    'csvr-waymo-20240330-s307': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv'"
        " (serial 307, column 'Accident Detail Description'), transcribed",
        "On March 30, 2024 at 1:33 AM PT, a Waymo Autonomous Vehicle (\"Waymo AV\") operating in San Francisco, "
        "California was in a collision involving an SUV on Jerrold Avenue at Barneveld Avenue. The Waymo AV was "
        "stopped at a stop sign on Jerrold Avenue and yielding to a pickup truck that was in the intersection "
        "making a left turn from Barneveld Avenue onto Jerrold Avenue when the front right corner of the SUV, "
        "which was traveling behind the Waymo AV, made contact with the rear left corner of the Waymo AV. At the "
        "time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles sustained "
        "damage."),
    'csvr-waymo-20241227-s358': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv'"
        " (serial 358, column 'Accident Detail Description'), transcribed",
        "On December 27, 2024 at 10:16 PM PT a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, "
        "California was in a collision involving a passenger car on Larkin Street at Olive Street. The Waymo AV "
        "was traveling northbound on Larkin Street when a passenger car traveling directly in front of the Waymo "
        "AV stopped in lane, and began to reverse to parallel park at the curb. While the passenger car was "
        "reversing, the rear driver side of the passenger car made contact with the front passenger side of the "
        "stationary Waymo AV. At the time of the impact, the Waymo AV’s Level 4 ADS was engaged in autonomous "
        "mode, and a test driver was present (in the driver’s seating position). Both vehicles sustained damage."),
    'csvr-cruise-20230615-s252': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv'"
        " (serial 252, column 'Accident Detail Description'), transcribed",
        "A Cruise autonomous vehicle (\"Cruise AV\"), operating in driverless autonomous mode, was traveling "
        "eastbound on Sacramento Street between Lyon Street and Baker Street. The Cruise AV approached a "
        "motorized articulating boom lift (“ABL”), which was stopped in the Cruise AV’s lane of travel. As the "
        "Cruise AV began to maneuver around and to the left of the ABL, the Cruise AV made contact with the arm "
        "of the ABL, which was elevated above the roadway. This caused damage to the Cruise AV’s roof Lidar "
        "assembly. There were no reported injuries."),
    'csvr-zoox-20230211-s213': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial"
        " 213, column 'Accident Detail Description'), transcribed",
        "A Zoox vehicle in autonomous mode was slowing to a stop with brake lights illuminated behind traffic on "
        "northbound 5th Street near Jesse Street when a vehicle behind made contact at approximately 10mph. There"
        " were no injuries and police were not called."),
    'csvr-waymo-20230506-s241': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial"
        " 241, column 'Accident Detail Description'), transcribed",
        "On May 6, 2023 at 8:48 PM PT a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, "
        "California was in a collision involving a passenger vehicle on Post Street at Webster Street. While "
        "traveling west on Post Street, the Waymo AV was executing a pullover maneuver in autonomous mode and "
        "made contact with the left rear bumper of a parked vehicle. At the time of the impact, the Waymo AV’s "
        "Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage."),
    'csvr-cruise-20230609-s250': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial"
        " 250, column 'Accident Detail Description'), transcribed",
        "A Cruise autonomous vehicle (“Cruise AV”), operating in driverless autonomous mode, was traveling "
        "northbound on Harrison St. between 18th Street and 19th Street. As the Cruise AV was coming to a stop "
        "for a stop sign at the intersection with 18th Street, a van approaching from the rear failed to stop "
        "behind the Cruise AV and made contact with the Cruise AV's rear bumper, damaging the rear bumper of the "
        "Cruise AV. Police and Emergency Medical Services were called and the Cruise AV was towed from the scene."
        " The driver of the van was transported by Emergency Medical Services for further evaluation."),
    'dmvca-zoox-20220823-r376': (
        "github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 376, column "
        "\"Accident Detail Description\")",
        "A Zoox vehicle in autonomy had made a right turn from Oakdell Rd. onto Santa Cruz Ave. in Menlo Park, CA"
        " and was preparing to make an immediate, unprotected left turn onto Sharon Road. The Zoox vehicle was "
        "slowing and moving at approximately 2 mph with its brake lamps and left turn indicator illuminated, "
        "yielding to an oncoming vehicle with the right of way. A following vehicle - traveling at approximately "
        "24 mph - then struck the Zoox vehicle's right rear bumper, and that vehicle's driver airbag appeared to "
        "have deployed on impact. The Zoox operator disengaged autonomy, proceeded with the left turn, and pulled"
        " over. The following vehicle continued its path of travel, veered out of the lane, and collided with a "
        "tree on the left side of the road. The Menlo Park Police Department was called to the scene. Two Zoox "
        "operators sustained minor injuries and it is unknown if the driver of the other vehicle sustained "
        "injuries."),
    'csvr-waymo-20190515-s11': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial"
        " 11, column 'Accident Detail Description'), transcribed",
        "A Waymo Autonomous Vehicle (“Waymo AV”) in autonomous mode was yielding to check for cross traffic while "
        "in the slip lane to turn from southbound Shoreline Boulevard to westbound El Camino Real in Mountain "
        "View when it was rear-ended by a passenger vehicle at approximately 5 MPH. The Waymo AV sustained minor "
        "damage to its rear bumper, and the passenger vehicle had minor damage to its front bumper. The two Waymo "
        "AV operators reported neck/back pain but declined medical attention at the scene."),
    'dmvca-waymo-20220511-r333': (
        "github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 333, column "
        "\"Accident Detail Description\")",
        "On May 11, 2022 at 9:19 AM PST a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, "
        "California was in a collision involving a SUV on 24th Street and Capp Street. The Waymo AV was "
        "attempting to make a right turn from 24th Street onto Capp Street while yielding to a pedestrian in the "
        "adjacent crosswalk in autonomous mode. A SUV approaching from behind the Waymo AV passed on the left "
        "side, making contact with the Waymo AV’s rear left sensor housing. The Waymo AV operator transitioned "
        "the system from autonomous to manual mode just before the moment of impact. The SUV immediately left the "
        "scene. At the time of the impact, the Waymo AV’s Level 4 ADS was not engaged and a test driver was "
        "operating the Waymo AV in manual mode. The Waymo AV sustained minor damage."),
}


def _ego(report_id: str, text: str | None = None) -> tuple[str, str]:
    sk = extract(text if text is not None else _CSV[report_id][1], report_id)
    return sk.ego.start, sk.ego.actions


def test_brake_lights_are_lamps_not_braking() -> None:
    # Stopped with its brake lights on, then following the car ahead when traffic moved: it moved off (`i`).
    assert _ego("csvr-zoox-20230208-s212") == ("stopped", "i")
    # "slowed to a gradual stop with brake and hazard lights activated": a run, then the stop; no slowing told.
    assert _ego("csvr-zoox-20240115-s294") == ("moving", "ah")
    # The lamps alone tell no manoeuvre: a travelling AV with its brake lights on still only kept its lane.
    plain = ("A Zoox vehicle in autonomous mode was traveling north on Harrison St with its brake lights illuminated "
             "when it was rear-ended by a sedan.")
    assert _ego("t", plain) == ("moving", "a")


def test_a_stop_with_any_adjective_is_a_stop() -> None:
    # "began coming to a gradual stop" after travelling: `ah` (sketch.md: slowing to a standstill is `h`).
    assert _ego("csvr-zoox-20230517-s243") == ("moving", "ah")
    for adj in ("controlled", "slow", "smooth"):
        text = _CSV["csvr-zoox-20230517-s243"][1].replace("gradual", adj)
        assert _ego("csvr-zoox-20230517-s243", text) == ("moving", "ah"), adj


def test_traffic_backed_up_is_a_queue_and_nudging_forward_is_moving_off() -> None:
    # "cross-traffic remained backed up in the intersection" is no reversing of the AV; "nudged forward and slowed
    # to a stop" is a start and a stop.
    assert _ego("csvr-waymo-20230320-s224") == ("stopped", "ih")


def test_advancing_from_a_stop_is_moving_off() -> None:
    assert _ego("csvr-zoox-20240716-s322") == ("stopped", "ih")


def test_had_begun_to_accelerate_is_a_start() -> None:
    # "had begun" (not "began"): the AV stopped at the red light had moved off when it was struck.
    assert _ego("csvr-waymo-20220128-s127") == ("stopped", "i")


def test_departing_from_a_standstill_starts_stopped() -> None:
    # A participle told in progress is a run along the lane, unless it names the standstill it began from; "the
    # subject Mercedes-Benz vehicle" is the AV, and the clause's subject.
    assert _ego("csvr-mercedes-benz-20220519-s161") == ("stopped", "i")


def test_approaching_stopped_traffic_is_no_stopped_state() -> None:
    # "was approaching stopped traffic": the AV was moving ("was ... stopped" is not its state), and the queue it
    # met stopped it (the annotators' `ah`).
    assert _ego("csvr-waymo-20220211-s132") == ("moving", "ah")


def test_a_stop_after_moving_off_from_where_it_waited_is_an_event() -> None:
    # Stopped at the stop sign, began a right turn, stopped again for oncoming traffic: `ieh` from a standstill.
    assert _ego("csvr-argo-20211019-s102") == ("stopped", "ieh")


def test_a_stop_told_after_before_is_the_next_thing_done() -> None:
    # "continued straight through the intersection before braking and coming to a complete stop"
    assert _ego("csvr-cruise-20220409-s148") == ("stopped", "ih")
    # "began to make a right turn ... before yielding to a pedestrian in the crosswalk"
    assert _ego("csvr-cruise-20230422-s236") == ("stopped", "ieh")


def test_a_manoeuvre_under_way_comes_before_the_slowing_within_it() -> None:
    # "began to slow down during an unprotected left turn": the turn was under way (`dc`).
    assert _ego("csvr-zoox-20210511-s81") == ("moving", "dc")
    # "was changing lanes into the left turn lane ... when the Cruise AV slowed down" (`fc`).
    assert _ego("csvr-cruise-20190524-s14") == ("moving", "fc")


def test_a_participle_after_the_stopped_av_is_the_striker_s() -> None:
    # "struck the rear of the stopped Waymo AV traveling at 5.5 miles per hour": the AV stood throughout.
    assert _ego("csvr-waymo-20210709-s89") == ("stopped", "")


def test_the_direction_a_standing_av_faced_is_no_move() -> None:
    # "was stopped in traffic ... on southbound San Antonio Road headed toward Charleston Road"
    assert _ego("csvr-waymo-20190529-s15") == ("stopped", "")


def test_a_stop_told_as_an_event_away_from_a_light_or_sign_is_made_on_the_way() -> None:
    # The official gold's reading ("came to a stop in the parking lot while yielding ... While the Waymo AV was
    # stopped", `ah`): a stop made for traffic, not at a light or a sign, is an event of a moving AV.
    assert _ego("csvr-waymo-20220103-s122") == ("moving", "ah")
    # "came to a stop while yielding to a pickup truck ... While the Waymo AV was stopped, a van ...": the stop is
    # not swallowed by the state beside it, and the state told after it is its result.
    assert _ego("csvr-waymo-20230605-s246") == ("moving", "ah")
    # At a stop sign it is where the AV waited (official gold: "came to a stop at a stop sign", `stopped`).
    at_sign = _CSV["csvr-waymo-20220103-s122"][1].replace("came to a stop to yield",
                                                           "came to a stop at a stop sign to yield")
    assert _ego("csvr-waymo-20220103-s122", at_sign)[0] == "stopped"


def test_a_summary_state_is_the_av_s_at_the_contact_when_the_telling_goes_back() -> None:
    # "was stopped ... when it was involved in a collision. The Waymo AV was traveling northbound ... when it
    # reached a four-way stop sign intersection. The Waymo AV stopped to yield ...": it did not move off (`ih`);
    # it stopped on its way, or stood where it waited.
    assert _ego("csvr-waymo-20190226-s3") in (("moving", "ah"), ("stopped", ""))


def test_a_relative_clause_with_a_place_and_making_a_turn_is_its_noun_s() -> None:
    # "was stopped at a stop sign ... and yielding to a pickup truck that was in the intersection making a left
    # turn": the turn is the pickup's; the AV stood throughout ("and yielding" is its state, not a stop).
    assert _ego("csvr-waymo-20240330-s307") == ("stopped", "")


def test_the_contact_naming_the_av_standing_ends_its_run_stopped() -> None:
    # "was traveling northbound ... made contact with the front passenger side of the stationary Waymo AV": `ah`.
    assert _ego("csvr-waymo-20241227-s358") == ("moving", "ah")
    # Without "stationary", nothing says it stopped.
    text = _CSV["csvr-waymo-20241227-s358"][1].replace("of the stationary Waymo AV", "of the Waymo AV")
    assert _ego("csvr-waymo-20241227-s358", text) == ("moving", "a")


def test_a_relative_clause_after_the_av_s_object_is_not_the_av_s() -> None:
    # "The Cruise AV approached a motorized articulating boom lift ("ABL"), which was stopped in the Cruise AV's
    # lane of travel": the lift stood, not the AV (`af`, not `ahf`).
    assert _ego("csvr-cruise-20230615-s252") == ("moving", "af")
    # Right after the AV's own name the clause is the AV's.
    text = ("The Cruise AV, which was stopped at a red light on Sacramento Street, was struck from behind by a "
            "sedan.")
    assert _ego("t", text) == ("stopped", "")


def test_a_slowing_stop_or_pull_over_told_under_way_opens_the_string() -> None:
    # "was slowing to a stop ... when a vehicle behind made contact": what the AV was doing when the interaction
    # began, as a party's manoeuvre told under way is (sketch.md); no run before it (the annotators' `h`).
    assert _ego("csvr-zoox-20230211-s213") == ("moving", "h")
    # "While traveling west on Post Street, the Waymo AV was executing a pullover maneuver": the participle of the
    # same sentence only describes it (`l`).
    assert _ego("csvr-waymo-20230506-s241") == ("moving", "l")
    # A run told first in a sentence of its own is kept: "was traveling eastbound ... As the Cruise AV was coming
    # to a stop" (`ah`).
    assert _ego("csvr-cruise-20230609-s250") == ("moving", "ah")


def test_a_slowing_told_under_way_with_its_description_opens_the_string() -> None:
    # The official gold's r376: "was preparing to make an immediate, unprotected left turn" (planned), then "The
    # Zoox vehicle was slowing and moving at approximately 2 mph ..., yielding to an oncoming vehicle": the slowing
    # opens the string; "moving at 2 mph" only describes it (`c`).
    assert _ego("dmvca-zoox-20220823-r376") == ("moving", "c")


def test_yielding_told_in_the_present_is_where_the_av_waited() -> None:
    # "A Waymo Autonomous Vehicle ("Waymo AV") in autonomous mode was yielding to check for cross traffic while in the
    # slip lane ... when it was rear-ended": the AV stood where it waited (9 of 11 studyable reports with the AV "was
    # yielding" are gold `stopped` at the start). Told in the present, as some reporters write, it reads the same.
    text = _CSV["csvr-waymo-20190515-s11"][1]
    assert _ego("csvr-waymo-20190515-s11") == ("stopped", "")
    present = text.replace("was yielding", "is yielding")
    assert present != text
    assert _ego("csvr-waymo-20190515-s11", present) == ("stopped", "")


def test_the_present_tense_reads_as_the_past() -> None:
    # "When traffic ahead began to move the Zoox vehicle was appropriately following the car ahead ... when it was
    # rear ended": told "begins ... is appropriately following", the AV named before the progressive is still its
    # subject (`i`, moved off with the queue). "The Waymo AV was attempting to make a right turn ... while yielding
    # to a pedestrian": told "is attempting", the attempt still waits (stopped, no turn made).
    for rid, told in (("csvr-zoox-20230208-s212", ("stopped", "i")), ("dmvca-waymo-20220511-r333", ("stopped", ""))):
        text = _CSV[rid][1]
        present = text.replace("began", "begins").replace("was ", "is ")
        assert present != text
        assert _ego(rid) == told
        assert _ego(rid, present) == told, rid
