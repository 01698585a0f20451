"""Issue 13, where the other parties were (position and lane, relations.place's tiers), read from real narratives of
the studyable sets (dev.jsonl with its official gold, tests/text/csvr/study2.jsonl, tests/text/sgo/study3.jsonl;
each narrative quoted with its id and source). One test per reading; each asserts what sketch.md's rules and the
studyable gold give, and fails when the reading is removed.
"""

from __future__ import annotations

from txt2sce_ros.sketch import Party
from txt2sce_ros.text.extractor import extract

# id -> (source, narrative)
_TEXTS: dict[str, tuple[str, str]] = {
    'nhtsa-sgo-ads-30291-7981-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30291-7981, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'At approximately 5:10pm CDT, a passenger vehicle collided with a Nuro Prius operating in manual mode in '
        'Houston, Texas. Prior to the collision, the Nuro Prius operating autonomously came to a stop at the '
        'intersection of [XXX] and [XXX]. The Nuro operator disengaged autonomy, switched to manual, and proceeded '
        'to make a left turn. A passenger vehicle collided with the Nuro Prius before the driver completed the '
        'turn. No injuries were reported. Both vehicles sustained damage. Law enforcement was not involved.'),
    'dmvca-waymo-20210712-r196': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 196, column '
        '"Accident Detail Description")',
        'On July 12, 2021 at 3:10 PM PDT, a Waymo Autonomous Vehicle (\u201cWaymo AV\u201d) was in a collision '
        'involving a van at Broadway and Gough Street in San Francisco. The Waymo AV, while in autonomous mode, '
        'was waiting to make a left turn and yielding to oncoming traffic, when the test driver (in the driver\u2019s '
        'seating position) transitioned to manual mode and proceeded with a left turn manually. During the left '
        'turn, an approaching van struck the right side of the Waymo AV. At the time of the impact, the Waymo AV '
        'was in manual mode.'),
    'csvr-cruise-20190524-s14': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial 14, "
        "column 'Accident Detail Description'), transcribed",
        'A Cruise autonomous vehicle (\u201cCruise AV\u201d), operating in autonomous mode, was changing lanes into '
        'the left turn lane on eastbound Geary Boulevard between 8th and 9th Avenues when the Cruise AV slowed '
        'down. The driver of the Cruise AV disengaged from autonomous mode and, shortly thereafter, another '
        'vehicle changing into the same lane made contact with the rear bumper of the Cruise AV, damaging the '
        'Cruise AV\u2019s bumper. There were no injuries and police were not called.'),
    'nhtsa-sgo-ads-30270-10673-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID '
        '30270-10673, version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report '
        'data',
        'On May [XXX], 2025 at 9:59 AM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Los Angeles, '
        'California was in a collision involving a box truck and trailer on [XXX] at [XXX]. The Waymo AV was '
        'traveling southeastbound on [XXX] in the leftmost lane when it stopped at the intersection of [XXX] '
        'to yield to a box truck hauling a trailer within the intersection. The heavy truck was facing '
        'southwest, apparently attempting a multi-point turn. The truck stopped and the Waymo AV began to '
        'pass the truck on the left. The truck began reversing as the Waymo AV was passing and the Waymo AV '
        'came to a stop to yield to the truck. While the Waymo AV remained stopped, the truck continued to '
        'reverse, and the rear passenger side of the trailer made contact with the front passenger side of '
        "the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. "
        'The Waymo AV sustained damage. Waymo is reporting this crash under Request No. 1 of Standing '
        'General Order 2021-01 because a vehicle involved was towed away. Waymo may supplement or correct '
        'its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-9436-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID '
        '30270-9436, version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On November [XXX], 2024 at 12:56 PM PT a Waymo Autonomous Vehicle (Waymo AV) operating in Beverly '
        'Hills, California was in a collision involving an SUV on [XXX] at [XXX]. The Waymo AV was stopped '
        'on the right side of southwestbound [XXX] for a passenger pick-up when an SUV traveling in the '
        'rightmost lane of southwestbound [XXX] passed the Waymo AV. As the SUV passed the stopped Waymo AV, '
        'the passenger side of the SUV made contact with the driver side of the Waymo AV. At the time of the '
        'impact, the Waymo AVs Level 4 ADS was engaged in autonomous mode. The Waymo AV sustained damage. '
        'Waymo is reporting this crash under Request No. 2 of Standing General Order 2021-01. Waymo may '
        'supplement or correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-10726-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID '
        '30270-10726, version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report '
        'data',
        'On April [XXX], 2025 at 9:07 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Los '
        'Angeles, California was in a collision involving an SUV on [XXX] at [XXX]. The Waymo AV was '
        'traveling eastbound on [XXX] and stopped in the dedicated left turn lane, preparing to make an '
        'unprotected left turn onto [XXX]. As the Waymo AV remained stopped, an SUV that was traveling '
        'westbound on [XXX] in the middle shared turn lane, directly in front of the Waymo AV, maneuvered '
        'from the middle lane to the second from the left lane and the driver side of the SUV made contact '
        "with the rear driver side of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS "
        'was engaged in autonomous mode. The SUV sustained damage. Waymo is reporting this crash under '
        'Request No. 2 of Standing General Order 2021-01. Waymo may supplement or correct its reporting with '
        'additional information as it may become available.'),
    'dmvca-waymo-20230507-r466': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 466, '
        'column "Accident Detail Description")',
        'On May 7, 2023 at 3:27 PM PDT a Waymo Autonomous Vehicle (“Waymo AV”) operating in San Francisco, '
        'California was in a collision involving a cyclist on Bay Street near Mason Street. The Waymo AV was '
        'traveling westbound in the left lane on Bay Street and had just passed Mason Street when it '
        'detected an oncoming pickup truck traveling eastbound in the Waymo AV’s lane. The Waymo AV stopped '
        'and the pickup truck re-entered the correct lane for eastbound traffic and passed the Waymo AV. The '
        'pickup truck was immediately followed by a large group of cyclists traveling eastbound in multiple '
        'lanes of the roadway, including the right lanes and on the wrong side of the double-yellow '
        'centerline. The Waymo AV remained stopped as the oncoming cyclists rode around both sides of the '
        'Waymo AV. One cyclist then made contact with the front of the stationary Waymo AV, and then '
        'immediately left the scene. At the time of the impact, the Waymo AV’s Level 4 ADS was engaged in '
        'autonomous mode. The Waymo AV sustained damage.'),
    'dmvca-cruise-20230817-r515': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 515, '
        'column "Accident Detail Description")',
        'A Cruise autonomous vehicle ("AV"), operating in driverless autonomous mode, was at a complete stop '
        'in response to a stop sign on eastbound 17th Street at the intersection with Vermont Street. As the '
        'AV began to proceed straight, a gray Honda Odyssey traveling westbound on 17th Street on the '
        'opposite side of the intersection from the AV entered the intersection and veered into the AV’s '
        'lane of travel. The AV stopped in response as the Honda Odyssey continued traveling in the AV’s '
        'lane of travel through the intersection and, shortly thereafter, the Honda Odyssey made contact '
        'with the AV, damaging the front and rear driver side doors, front driver side radar assembly and '
        'rear driver side tire of the AV. The parties exchanged information. There were no reported injuries '
        'and the AV was towed from the scene.'),
    'nhtsa-sgo-ads-30270-9376-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID '
        '30270-9376, version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On November [XXX], 2024 at 10:36 AM PT, a Waymo Autonomous Vehicle ("Waymo AV") operating in San '
        'Francisco, California was alleged to have contributed to a collision between an SUV and a concrete '
        'median curb on [XXX] at [XXX]. The Waymo AV was traveling southbound on [XXX] in the right of two '
        'travel lanes with its left turn signal activated, and traversed through the intersection with [XXX] '
        'with an SUV following slightly behind and to the left of the Waymo AV in the adjacent travel lane. '
        'As the Waymo AV exited the intersection with its left turn signal still activated, it slowed and '
        'moved slightly to the left within its lane, preparing to change lanes due to a stopped truck ahead '
        'within the right lane. As the SUV in the left lane was passing the Waymo AV, it maneuvered to the '
        'left in its lane, and the driver side made contact with the center concrete median curb. At the '
        "time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. The SUV sustained a "
        'flat tire, and the driver alleged an injury. Waymo is reporting this crash under Request No. 2 of '
        'Standing General Order 2021-01. Waymo may supplement or correct its reporting with additional '
        'information as it may become available.'),
    'nhtsa-sgo-ads-30270-9333-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID '
        '30270-9333, version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On December [XXX], 2024 at 10:19 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San '
        'Francisco, California was in a collision involving a mini coach bus on [XXX] at [XXX]. The Waymo AV '
        'was stopped facing south in the rightmost lane of [XXX] after a passenger dropoff when a mini coach '
        'bus initiated a wide right turn from eastbound [XXX] into the left lane of southbound [XXX]. As the '
        'bus passed the stopped Waymo AV, the passenger side of the bus made contact with the rear driver '
        "side of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in "
        'autonomous mode. Both vehicles sustained damage. Waymo is reporting this crash under Request No. 1 '
        'of Standing General Order 2021-01 because a vehicle involved was towed away. Waymo may supplement '
        'or correct its reporting with additional information as it may become available.'),
    'nhtsa-sgo-ads-30413-6032-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID '
        '30413-6032, version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'The May vehicle came to a gentle stop at the railroad crossing (about -0.8 m/s2 deceleration) as '
        'designed, but the agent behind did not come to a stop and made contact with the AV. The May shuttle '
        'behaved as expected and slowed down to a stop in a safe manner. The collision was unavoidable from '
        'the shuttle side.'),
    'nhtsa-sgo-ads-30270-9631-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID '
        '30270-9631, version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On January [XXX], 2025 at 2:55 PM MT a Waymo Autonomous Vehicle (Waymo AV) operating in Phoenix, '
        'Arizona was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV was traveling '
        'north on [XXX] when it approached the intersection with [XXX]. As the Waymo AV approached the '
        'intersection, it slowed to yield to a pedestrian who was traveling south on the sidewalk of [XXX] '
        'and had just entered the intersection to cross [XXX]. As the Waymo AV continued to slow, a '
        'passenger car traveling directly behind the Waymo AV approached the Waymo AV from behind. The front '
        'of the passenger car made contact with the rear of the Waymo AV. At the time of the impact, the '
        'Waymo AVs Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage. The passenger '
        'in the Waymo AV reported a minor injury. Waymo is reporting this crash under Request No. 1 of '
        'Standing General Order 2021-01 because a vulnerable road user influenced the driving task of a '
        'vehicle involved and because vehicles involved were towed away. Waymo may supplement or correct its '
        'reporting with additional information as it may become available.'),
    'csvr-waymo-20211207-s118': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' "
        "(serial 118, column 'Accident Detail Description'), transcribed",
        'On December 7, 2021 at 10:47 AM PST a Waymo Autonomous Vehicle (“Waymo AV”) operating in San '
        'Francisco, CA was in a collision involving an SUV at Oak Street at Stanyan Street. While in '
        'autonomous mode, the Waymo AV came to a stop at a stop sign on Oak Street. While the ADV was '
        'stopped, waiting for a pedestrian to cross and for traffic on Stanyan Street to clear, an SUV '
        'approached the Waymo AV from behind and made contact with the rear of the Waymo AV. At the time of '
        'the impact, the Waymo AV’s Level 4 ADS was engaged in autonomous mode, and a test driver was '
        'present (in the driver’s seating position). The Waymo AV sustained minor damage to the rear bumper.'),
    'nhtsa-sgo-ads-30270-10630-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID '
        '30270-10630, version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report '
        'data',
        'On April [XXX], 2025 at 9:10 AM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San '
        'Francisco, California was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV '
        'was traveling northbound on [XXX] and came to a stop, allowing for a passenger car to exit a '
        'parking lot on the east side of the roadway. As the passenger car turned left onto [XXX] and '
        'attempted to pass the Waymo AV, the driver side of the passenger car made contact with the rear '
        "driver side of the stationary Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was "
        'engaged in autonomous mode. The passenger car sustained damage. Waymo is reporting this crash under '
        'Request No. 2 of Standing General Order 2021-01. Waymo may supplement or correct its reporting with '
        'additional information as it may become available.'),
    'nhtsa-sgo-ads-30270-9540-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID '
        '30270-9540, version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On December[XXX], 2024 at 8:21 AM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San '
        'Francisco, California was in a collision involving a passenger car on [XXX] near [XXX]. The Waymo '
        'AV had pulled up to the curb facing northbound on [XXX] for a requested passenger pickup. While '
        'awaiting the passenger, the Waymo AV was partially obstructing access to a residential garage and a '
        'passenger car began reversing out of the garage and the rear driver side of the passenger car made '
        "contact with the rear passenger side of the Waymo AV. At the time of the impact, the Waymo AV's "
        'Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage. Waymo is reporting this '
        'crash under Request No. 2 of Standing General Order 2021-01. Waymo may supplement or correct its '
        'reporting with additional information as it may become available.'),
    'csvr-pony.ai-20220517-s159': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' "
        "(serial 159, column 'Accident Detail Description'), transcribed",
        'On May 17, 2022, a passenger vehicle reversed out of a parking spot into a Pony.ai autonomous '
        'testing vehicle’s rear bumper. At the time of the collision, the Pony.ai vehicle was operating in '
        'autonomous mode with a safety operator in the driver’s seat and was moving at a low speed. The '
        'Pony.ai vehicle did not sustain any damage. There were no injuries or property damage, the police '
        'were not called to the scene, and a Pony.ai employee drove the Pony.ai vehicle back to Pony.ai’s '
        'Irvine facility.'),
    'nhtsa-sgo-ads-30270-9544-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID '
        '30270-9544, version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On December [XXX], 2024 at 6:09 PM MT a Waymo Autonomous Vehicle (Waymo AV) operating in Phoenix, '
        'Arizona was in a collision involving an SUV on [XXX] near [XXX]. The Waymo AV was travelling '
        'southbound on the single lane on [XXX], preparing to enter the dedicated left turn lane at the '
        'intersection with [XXX], when an SUV was exiting a shopping center driveway making a right turn '
        'onto southbound [XXX]. As the SUV turned, the front driver side of the SUV made contact with the '
        'passenger side of the Waymo AV. At the time of the impact, the Waymo AVs Level 4 ADS was engaged in '
        'autonomous mode. Both vehicles sustained damage. Waymo is reporting this crash under Request No. 2 '
        'of Standing General Order 2021-01. Waymo may supplement or correct its reporting with additional '
        'information as it may become available.'),
    'dmvca-waymo-20241202-r634': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 634, '
        'column "Accident Detail Description")',
        'On December 2, 2024 at 10:54 AM PT a Waymo Autonomous Vehicle (“Waymo AV”) operating in Los '
        'Angeles, California was in a collision involving a plastic crate on East 3rd Street at South '
        'Central Avenue. The Waymo AV was traveling westbound in the center lane on East 3rd Street, '
        'crossing the intersection with South Central Avenue when the front passenger side of the Waymo AV '
        'made contact with a plastic crate that was in the roadway within the Waymo AV’s lane of travel. The '
        'contact with the Waymo AV caused the crate to move into the adjacent right lane, which was occupied '
        'by a scooterist. The front tire of the scooter made contact with the crate and the scooter and '
        'scooterist fell. At the time of the impact, the Waymo AV’s Level 4 ADS was engaged in autonomous '
        'mode. Given the speed at which the scooter was traveling at the time of the contact, the scooter '
        'may have sustained damage.'),
    'csvr-zoox-20230208-s212': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' "
        "(serial 212, column 'Accident Detail Description'), transcribed",
        'A Zoox vehicle in autonomy was stopped with brake lights illuminated in traffic southbound on '
        'Embarcadero Street towards Folsom Street. When traffic ahead began to move the Zoox vehicle was '
        'appropriately following the car ahead at low speed when it was rear ended by Vehicle #2 at low '
        'speed. The other party did not stop to exchange information and left the scene. There were no '
        'injuries and police were not called.'),
}


def _party(report_id: str, k: int = 0) -> Party:
    return extract(_TEXTS[report_id][1], report_id).npcs[k]


def test_a_vehicle_met_by_an_av_turning_left_with_nothing_told_of_its_place_came_from_the_opposite_approach() -> None:
    # "proceeded to make a left turn. A passenger vehicle collided with the Nuro Prius before the driver completed
    # the turn": no heading, side, lane or end of the AV told; a left turn across the path of oncoming traffic.
    p = _party("nhtsa-sgo-ads-30291-7981-v1")
    assert (p.position, p.lane) == ("R2", None)
    # "During the left turn, an approaching van struck the right side of the Waymo AV": the side it struck is where
    # the oncoming lane crosses a left-turning AV, no lane beside it.
    p = _party("dmvca-waymo-20210712-r196")
    assert (p.position, p.lane) == ("R2", None)


def test_a_party_behind_that_changes_lanes_with_the_av_stays_behind_it_in_its_lane() -> None:
    # "was changing lanes into the left turn lane ... another vehicle changing into the same lane made contact with
    # the rear bumper": both moved over from one lane, the party behind the AV in it (R6, same), not waiting in the
    # lane the AV moved into (the AV's move puts a party on that side only when the party kept its lane).
    p = _party("csvr-cruise-20190524-s14")
    assert (p.position, p.lane) == ("R6", "same")


def test_a_pass_told_of_the_av_in_its_own_clause_is_not_the_party_s() -> None:
    # "The truck began reversing as the Waymo AV was passing and the Waymo AV came to a stop to yield to the truck":
    # the AV passed the truck; the truck, facing southwest in the intersection while the AV went southeast, is on
    # the crossing road to the AV's left (R1), not behind it.
    p = _party("nhtsa-sgo-ads-30270-10673-v1")
    assert (p.position, p.lane) == ("R1", None)


def test_a_lane_named_on_the_road_is_on_the_left_of_an_av_standing_at_the_right_edge() -> None:
    # "The Waymo AV was stopped on the right side of southwestbound [XXX] for a passenger pick-up when an SUV
    # traveling in the rightmost lane of southwestbound [XXX] passed the Waymo AV": at the curb the AV is in no
    # travel lane, so the rightmost one is on its left (R6, left), not to its right.
    p = _party("nhtsa-sgo-ads-30270-9436-v1")
    assert (p.position, p.lane) == ("R6", "left")


def test_a_party_coming_the_other_way_in_the_av_s_lane_is_head_on_in_it_also_at_a_junction() -> None:
    # "an SUV that was traveling westbound on [XXX] in the middle shared turn lane, directly in front of the Waymo
    # AV" (the AV eastbound, stopped in the left turn lane at the junction): on the AV's own road, in its lane.
    p = _party("nhtsa-sgo-ads-30270-10726-v1")
    assert (p.position, p.lane) == ("R7", "same")
    # "an oncoming pickup truck traveling eastbound in the Waymo AV's lane"
    p = _party("dmvca-waymo-20230507-r466", 1)
    assert (p.category, p.position, p.lane) == ("car", "R7", "same")
    # "traveling westbound on 17th Street on the opposite side of the intersection from the AV entered the
    # intersection and veered into the AV's lane of travel": it got there; it came from the opposite approach.
    p = _party("dmvca-cruise-20230817-r515")
    assert (p.position, p.lane) == ("R2", None)


def test_the_av_s_lane_told_as_one_of_a_count_places_the_lanes_named_on_the_road() -> None:
    # "The Waymo AV was traveling southbound on [XXX] in the right of two travel lanes ... due to a stopped truck
    # ahead within the right lane": the AV is in the right lane, so the truck ahead in it is in the AV's lane (R5,
    # same), and "the SUV in the left lane" passing it is on its left.
    sk = extract(_TEXTS["nhtsa-sgo-ads-30270-9376-v1"][1], "nhtsa-sgo-ads-30270-9376-v1")
    truck = next(p for p in sk.npcs if p.category == "truck")
    assert (truck.position, truck.lane) == ("R5", "same")
    assert all(p.lane == "left" for p in sk.npcs if p.category == "car")


def test_a_party_heading_across_the_av_s_way_at_a_junction_came_from_the_crossing_road_whatever_it_passed() -> None:
    # "The Waymo AV was stopped facing south ... when a mini coach bus initiated a wide right turn from eastbound
    # [XXX] into the left lane of southbound [XXX]. As the bus passed the stopped Waymo AV, ...": eastbound, across
    # the southbound AV's way, it came from the AV's right (R3); its pass came after.
    p = _party("nhtsa-sgo-ads-30270-9333-v1")
    assert (p.position, p.lane) == ("R3", None)


def test_an_agent_is_another_road_user() -> None:
    # "but the agent behind did not come to a stop and made contact with the AV": the AV industry's word for
    # another road user names the party that struck the AV from behind, so the report is complete.
    sk = extract(_TEXTS["nhtsa-sgo-ads-30413-6032-v1"][1], "nhtsa-sgo-ads-30413-6032-v1")
    assert [(p.category, p.position, p.lane) for p in sk.npcs] == [("car", "R6", "same")]
    assert (sk.collision.with_, sk.missing) == ("npc1", ())


def test_a_summary_of_a_collision_between_two_parties_announces_the_telling_s() -> None:
    # "The Waymo AV ... was alleged to have contributed to a collision between an SUV and a concrete median curb on
    # [XXX]. ... with an SUV following slightly behind and to the left of the Waymo AV": the opening sentence
    # announces the SUV the telling names; it is one party, not two.
    sk = extract(_TEXTS["nhtsa-sgo-ads-30270-9376-v1"][1], "nhtsa-sgo-ads-30270-9376-v1")
    assert sorted((p.category, p.position, p.lane) for p in sk.npcs) == [("car", "R6", "left"), ("truck", "R5", "same")]


def test_a_walker_the_av_waits_for_at_a_junction_crosses_on_the_leg_ahead() -> None:
    # "it slowed to yield to a pedestrian who was traveling south on the sidewalk of [XXX] and had just entered the
    # intersection to cross [XXX]" (the AV northbound): a walker's heading is no opposite approach (R2).
    sk = extract(_TEXTS["nhtsa-sgo-ads-30270-9631-v1"][1], "nhtsa-sgo-ads-30270-9631-v1")
    assert [(p.position, p.lane) for p in sk.npcs if p.category == "pedestrian"] == [("R4", None)]
    # "came to a stop at a stop sign on Oak Street. While the ADV was stopped, waiting for a pedestrian to cross":
    # not ahead in the AV's lane either.
    sk = extract(_TEXTS["csvr-waymo-20211207-s118"][1], "csvr-waymo-20211207-s118")
    assert [(p.position, p.lane) for p in sk.npcs if p.category == "pedestrian"] == [("R4", None)]


def test_a_party_out_of_a_roadside_place_was_beside_or_ahead_of_the_av_whatever_it_passed_then() -> None:
    # "came to a stop, allowing for a passenger car to exit a parking lot on the east side of the roadway. As the
    # passenger car turned left onto [XXX] and attempted to pass the Waymo AV, ...": beside the AV on the right (R5),
    # its turn out of the lot not preceded by a run along the AV's road.
    p = _party("nhtsa-sgo-ads-30270-10630-v1")
    assert (p.position, p.lane, p.actions) == ("R5", "right", "d")
    # "a passenger car began reversing out of the garage and the rear driver side of the passenger car made contact
    # with the rear passenger side of the Waymo AV": beside it, though it met the AV's rear half.
    p = _party("nhtsa-sgo-ads-30270-9540-v1")
    assert (p.position, p.lane) == ("R5", "right")
    # "a passenger vehicle reversed out of a parking spot into a Pony.ai autonomous testing vehicle's rear bumper":
    # the rear end, no side of it: it came out behind the AV.
    p = _party("csvr-pony.ai-20220517-s159")
    assert (p.position, p.lane) == ("R6", "right")


def test_another_party_s_turn_is_no_turn_of_the_av() -> None:
    # "The Waymo AV was traveling northbound on [XXX] approaching the intersection with [XXX], when an SUV was
    # exiting a shopping center driveway making a right turn onto southbound [XXX]": the turn is the SUV's; the AV
    # goes straight, so the driveway beside it is no leg it exits onto (R4): the SUV is at its right (R5).
    p = _party("nhtsa-sgo-ads-30270-9544-v1")
    assert (p.position, p.lane) == ("R5", "right")


def test_a_party_the_object_struck_by_the_av_then_struck_takes_part() -> None:
    # "The contact with the Waymo AV caused the crate to move into the adjacent right lane, which was occupied by a
    # scooterist. The front tire of the scooter made contact with the crate": the scooterist's contact is told in
    # the sentence after the one that names it; a chain collision's party takes part (sketch.md).
    sk = extract(_TEXTS["dmvca-waymo-20241202-r634"][1], "dmvca-waymo-20241202-r634")
    assert [(p.category, p.position, p.lane) for p in sk.npcs] == [("scooter", "R5", "right")]
    assert [o.category for o in sk.obstacles] == ["debris"] and sk.collision.with_ == "obs1"


def test_rear_ended_by_belongs_to_the_party_named_after_by() -> None:
    # "the Zoox vehicle was appropriately following the car ahead at low speed when it was rear ended by Vehicle #2":
    # the car ahead is ahead (R5); Vehicle #2 came from behind (R6).
    sk = extract(_TEXTS["csvr-zoox-20230208-s212"][1], "csvr-zoox-20230208-s212")
    assert sorted((p.position, p.lane) for p in sk.npcs) == [("R5", "same"), ("R6", "same")]
