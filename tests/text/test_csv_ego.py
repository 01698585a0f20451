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
