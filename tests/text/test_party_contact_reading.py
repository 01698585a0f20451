"""Issue 13, the other parties: readings of the AV's touched part and of a party's manoeuvre that says where it was,
held on real narratives of the studyable sets (dev_gold_study, study2, study3; each entry's source beside its text).
One test per reading; each asserts what the set's gold gives and fails without the rule.
"""

from __future__ import annotations

from txt2sce_ros.sketch import Sketch
from txt2sce_ros.text.extractor import extract

# id -> (source, narrative)
_REAL: dict[str, tuple[str, str]] = {
    'dmvca-waymo-20230507-r466': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 466, column '
        '"Accident Detail Description")',
        'On May 7, 2023 at 3:27 PM PDT a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, '
        'California was in a collision involving a cyclist on Bay Street near Mason Street. The Waymo AV was '
        'traveling westbound in the left lane on Bay Street and had just passed Mason Street when it detected'
        ' an oncoming pickup truck traveling eastbound in the Waymo AV’s lane. The Waymo AV stopped and the '
        'pickup truck re-entered the correct lane for eastbound traffic and passed the Waymo AV. The pickup '
        'truck was immediately followed by a large group of cyclists traveling eastbound in multiple lanes of'
        ' the roadway, including the right lanes and on the wrong side of the double-yellow centerline. The '
        'Waymo AV remained stopped as the oncoming cyclists rode around both sides of the Waymo AV. One '
        'cyclist then made contact with the front of the stationary Waymo AV, and then immediately left the '
        'scene. At the time of the impact, the Waymo AV’s Level 4 ADS was engaged in autonomous mode. The '
        'Waymo AV sustained damage.'),
    'csvr-waymo-20240605-s317': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial"
        " 317, column 'Accident Detail Description'), transcribed",
        'On June 5, 2024 at 1:12 PM PT a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, '
        'California was in a collision involving a passenger car on 29th Avenue near Lawton Street. The Waymo'
        ' AV was parked at the curb on the right side of 29th Avenue when a passenger car in front of the '
        'Waymo AV began to reverse to parallel park. The passenger car’s rear driver side corner made contact'
        ' with the front driver side corner of the parked Waymo AV. At the time of the impact, the Waymo AV’s'
        ' Level 4 ADS was engaged in autonomous mode. The Waymo AV sustained damage.'),
    'nhtsa-sgo-ads-30270-10742-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID '
        '30270-10742, version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On April [XXX], 2025 at 3:29 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San '
        'Francisco, CA was in a collision involving a pickup truck on [XXX] near [XXX]. The Waymo AV was '
        'traveling northbound on [XXX] in the rightmost lane and slowed to a stop for an SUV that was '
        'parallel parking in front of the Waymo AV. While the Waymo AV was stopped, a pickup truck traveling '
        'directly behind the Waymo AV approached the Waymo AV from behind, and the front of the pickup truck '
        "made contact with the rear of the stationary Waymo AV. At the time of the impact, the Waymo AV's "
        'Level 4 ADS was engaged in autonomous mode. The pickup truck sustained damage. Waymo is reporting '
        'this crash under Request No. 2 of Standing General Order 2021-01. Waymo may supplement or correct '
        'its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-9350-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9350,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On November [XXX], 2024 at 8:03 AM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San '
        'Francisco, California was in a collision involving a SUV on [XXX] near [XXX]. The Waymo AV was '
        'parked at the curb in the northbound direction of [XXX] when an SUV began to parallel park behind '
        'the Waymo AV. While parking, the SUV moved forward from the curb into the roadway, maneuvering to '
        'the left of the Waymo AV, and the passenger side of the SUV made contact with the rear driver side '
        "of the stationary Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in "
        'autonomous mode. The SUV sustained damage. Waymo is reporting this crash under Request No. 2 of '
        'Standing General Order 2021-01. Waymo may supplement or correct its reporting with additional '
        'information as it may become available.'),
    'csvr-waymo-20240513-s311': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial"
        " 311, column 'Accident Detail Description'), transcribed",
        'On May 13, 2024 at 12:58 AM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Los Angeles, CA '
        'was in a collision involving a passenger car on eastbound Interstate 10 between Exit 2 and Exit 3A. '
        'The Waymo AV was traveling with a test driver present behind a box truck in the number 3 lane of '
        'eastbound Interstate 10 near the Bundy Drive overpass when a passenger car traveling at a high rate '
        'of speed approached the Waymo AV from behind. The passenger car partially entered the number 2 lane '
        'as the front right corner of the passenger car made contact with the rear left corner of the Waymo '
        'AV. The passenger car then made contact with the center median and came to a stop. The Waymo AV was '
        'transitioned into manual mode, and the test driver stopped the Waymo AV to the right-hand shoulder. '
        "At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode, and a test "
        'driver was present (in the driver’s seating position). Both vehicles sustained damage.'),
    'nhtsa-sgo-ads-30270-10599-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID '
        '30270-10599, version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On April [XXX], 2025 at 12:41 AM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Venice, '
        'California was in a collision involving a van on [XXX] near [XXX]. The Waymo AV was parked in-lane '
        'for a passenger drop-off facing southwest on [XXX] with hazard lights activated. A van that was '
        'stopped directly behind the Waymo AV began to maneuver around the stationary Waymo by crossing the '
        'yellow center line, entering the opposing lane of travel. As the van proceeded to the left of the '
        'stationary Waymo AV, the Waymo AV passenger opened the driver side rear door and the passenger side '
        'of the van made contact with the open driver side rear door of the Waymo AV. At the time of the '
        "impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. The passengers who were seated in"
        ' the rear of the Waymo AV and the front passenger seat were not belted at the time of the collision,'
        ' as they were likely preparing to exit the Waymo AV. Both vehicles sustained damage. Waymo is '
        'reporting this crash under Request No. 1 of Standing General Order 2021-01 because a vehicle '
        'involved was towed away. Waymo may supplement or correct its reporting with additional information '
        'as it may become available.'),
    'dmvca-waymo-20241016-r620': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 620, column '
        '"Accident Detail Description")',
        'On October 16, 2024 at 5:27 AM PT a Waymo Autonomous Vehicle (“Waymo AV”) operating in San '
        'Francisco, California was in a collision involving a van in an underground parking lot at 1160 '
        'Mission Street. Two Waymo AVs were stopped at neighboring junctures of a tight T-instersection of '
        'the lot. The first Waymo AV was preparing to make a right turn, while yielding to the other Waymo '
        'AV. While the Waymo AVs remained stopped, a van that had been traveling behind the first Waymo AV '
        'entered the oncoming lane to maneuver around the left side of the Waymo AV. The passenger side of '
        'the van then made contact with the rear driver side of the stopped Waymo AV. At the time of the '
        'impact, the Waymo AV’s Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage.'),
}


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
