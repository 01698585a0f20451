"""Issue 13, who counts and of what kind: party categories and obstacles against parties, read from real narratives
of the studyable sets (dev.jsonl with its official gold, tests/text/csvr/study2.jsonl, tests/text/sgo/study3.jsonl;
each narrative quoted with its id and source). One test per reading; each asserts what sketch.md's rules and the
study sets' gold give.
"""

from __future__ import annotations

from txt2sce_ros.text.extractor import extract

# id -> (source, narrative)
_TEXTS: dict[str, tuple[str, str]] = {
    'csvr-cruise-20230504-s240': (
        "github:galravid/Autonomous-Vehicle-Accidents@9e2ce07 'CA_AV_Collision_2019-2024 Reduced.csv' (serial"
        " 240, column 'Accident Detail Description'), transcribed"
        ,
        'A Cruise autonomous vehicle ("Cruise AV"), operating in driverless autonomous mode, was traveling '
        'northbound on Franklin Street between Clay Street and Sacramento Street. As the Cruise AV passed '
        'through the intersection with Sacramento Street, a scooterist approaching from the rear merged into '
        "the Cruise AV's lane behind the Cruise AV. The Cruise AV began to brake, and the scooterist made "
        'contact with the rear window and rear bumper of the Cruise AV. This caused damage to the rear '
        'window, rear bumper and driver side rear headlight of the Cruise AV. The parties exchanged '
        'information. There were no injuries reported at the scene and police were not called. The scooterist'
        ' later reported injuries.'
    ),
    'dmvca-cruise-20190107-r0': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 0, column '
        '"Accident Detail Description")'
        ,
        'A Cruise autonomous vehicle (“Cruise AV”), operating in conventional mode, was making a left turn '
        'from northeast bound Folsom Street onto northwest bound 11th Street when a scooterist, attempting to'
        ' pass the Cruise AV on the left, made contact with the front left side of the Cruise AV, damaging '
        'the front left fender, radar, and wheel well of the Cruise AV. The scooterist reported injuries and '
        'emergency services and the police arrived at the scene, but the scooterist declined medical '
        'treatment. No police report was available at the time of the filing of this report.'
    ),
    'dmvca-cruise-20191107-r89': (
        'github:galravid/Autonomous-Vehicle-Accidents@1547d38 CA_AV_Collision_2019-2024.csv (row 89, column '
        '"Accident Detail Description")'
        ,
        'A Cruise autonomous vehicle (“Cruise AV”), operating in autonomous mode, was traveling eastbound on '
        '24th Street at the intersection with Mission Street when the Cruise AV yielded to an electric '
        'scooterist traveling northbound on Mission Street and violating a red light. The driver of the '
        'Cruise AV disengaged from autonomous mode and, shortly thereafter, the electric scooterist made '
        'contact with the right rear corner of the Cruise AV, damaging the Cruise AV’s right rear fascia and '
        'brake light. The electric scooterist left the scene without exchanging information. There were no '
        'injuries and police were not called.'
    ),
    'nhtsa-sgo-ads-30270-9376-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9376,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data'
        ,
        'On November [XXX], 2024 at 10:36 AM PT, a Waymo Autonomous Vehicle ("Waymo AV") operating in San '
        'Francisco, California was alleged to have contributed to a collision between an SUV and a concrete '
        'median curb on [XXX] at [XXX]. The Waymo AV was traveling southbound on [XXX] in the right of two '
        'travel lanes with its left turn signal activated, and traversed through the intersection with [XXX] '
        'with an SUV following slightly behind and to the left of the Waymo AV in the adjacent travel lane. '
        'As the Waymo AV exited the intersection with its left turn signal still activated, it slowed and '
        'moved slightly to the left within its lane, preparing to change lanes due to a stopped truck ahead '
        'within the right lane. As the SUV in the left lane was passing the Waymo AV, it maneuvered to the '
        'left in its lane, and the driver side made contact with the center concrete median curb. At the time'
        " of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. The SUV sustained a flat "
        'tire, and the driver alleged an injury. Waymo is reporting this crash under Request No. 2 of '
        'Standing General Order 2021-01. Waymo may supplement or correct its reporting with additional '
        'information as it may become available.'
    ),
    'nhtsa-sgo-ads-30270-10668-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID '
        '30270-10668, version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data'
        ,
        'On April [XXX], 2025 at 10:41 AM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San '
        'Francisco, California was in a collision involving a pickup truck on [XXX] at [XXX]. The Waymo AV '
        'was stopped facing north at a red light on [XXX] with the left turn signal activated, preparing to '
        'make an unprotected left turn onto [XXX]. A pickup truck traveling eastbound on [XXX] made a right '
        'turn onto [XXX] and made contact with a passenger car parked facing south at the curb near the '
        'intersection with [XXX]. As the pickup truck maneuvered away from the passenger car and continued to'
        ' proceed southbound on [XXX], the driver side of the pickup truck then made contact with the rear '
        "driver side of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in "
        'autonomous mode. The pickup truck sustained damage. Waymo is reporting this crash under Request No. '
        '2 of Standing General Order 2021-01. Waymo may supplement or correct its reporting with additional '
        'information as it may become available.'
    ),
    'nhtsa-sgo-ads-30270-7936-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-7936,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data'
        ,
        'On May [XXX], 2024 at 8:25 AM MT a Waymo Autonomous Vehicle ("Waymo AV") operating in Tempe, Arizona'
        ' was in a collision involving a chain at the entrance of a parking lot at Arizona State University '
        'on [XXX] near [XXX]. The Waymo AV was traveling north on [XXX] when it made a left turn into a '
        'parking lot near [XXX]. As the Waymo AV was entering the parking lot, it made contact with a chain '
        "hanging at the entrance of the parking lot. At the time of the impact, the Waymo AV's Level 4 ADS "
        'was engaged in autonomous mode. The chain sustained damage. Waymo is reporting this crash under '
        'Request No. 2 of Standing General Order 2021-01. Waymo may supplement or correct its reporting with '
        'additional information as it may become available.'
    ),
    'nhtsa-sgo-ads-30270-7729-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-7729,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data'
        ,
        'On April [XXX], 2024 at 11:07 PM PT a Waymo Autonomous Vehicle (Waymo AV) operating in Santa Monica,'
        ' California was in a collision involving a chain in a parking lot at [XXX]. The Waymo AV was '
        'traveling northwest on [XXX] when it made a left turn into a parking lot at [XXX]. As the Waymo AV '
        'was turning into the section of the parking lot directly to its left, the Waymo AV made contact with'
        ' a hanging chain separating a section of the parking lot. At the time of the impact, the Waymo AVs '
        'Level 4 ADS was engaged in autonomous mode. The Waymo AV and the chain sustained damage. Waymo is '
        'reporting this crash under Request No. 2 of Standing General Order 2021-01. Waymo may supplement or '
        'correct its reporting with additional information as it may become available.'
    ),
    'nhtsa-sgo-ads-30270-10695-v1': (
        'github:vanshagg233/Risk_Function SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-10695, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data'
        ,
        'On May [XXX], 2025 at 8:50 AM MT a Waymo Autonomous Vehicle ("Waymo AV") operating in Paradise '
        'Valley, Arizona was in a collision involving an animal and subsequently an SUV on [XXX] at [XXX]. '
        'The Waymo AV was traveling southbound on [XXX] in the leftmost lane, proceeding through a green '
        'light at the intersection with [XXX]. As the Waymo AV exited the intersection, a cat crossed [XXX] '
        "from the east side of the street, and began to enter the Waymo AV's lane of travel. As the Waymo AV "
        'braked, the front of the Waymo AV made contact with the cat, which subsequently ran away, and the '
        'Waymo AV came to a stop. The front of an SUV traveling directly behind the Waymo AV then made '
        'contact with the right rear of the stationary Waymo AV. A passenger car then braked to a stop behind'
        ' the Waymo and to the left of the SUV. A second passenger car then made contact with the SUV and the'
        " first passenger car. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in "
        'autonomous mode. All involved vehicles sustained damage. Waymo is reporting this crash under Request'
        ' No. 1 of Standing General Order 2021-01 because a vehicle involved was towed away and because of '
        'airbag deployment. Waymo may supplement or correct its reporting with additional information as it '
        'may become available.'
    ),
    'nhtsa-sgo-ads-988-3684-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 988-3684, '
        'version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data'
        ,
        'On August [XXX], 2022, Kodiak Robotics, Inc. ("Kodiak") filed an Incident Report (the "Report") '
        'under the Standing General Order 2021-01 (the "Order"). PACCAR, Inc. (Paccar) manufactured the '
        'Kodiak-operated motor vehicle involved in the incident summarized in the Incident Report. Because '
        'Paccar is also a Reporting Entity under the Order, Paccar is submitting a duplicate of the redacted '
        'public copy of the Report. Paccar has selected "Unknown" in the "ADS version" field solely to avoid '
        "the second submission of nonpublic Kodiak CBI. Paccar is in possession of Kodiak's response to this "
        "field and incorporates Kodiak's response into this submission by reference. Paccar's submission is "
        'based on facts supplied to Paccar by Kodiak. Paccar has not investigated the alleged incident and '
        'has no independent knowledge of the facts in the Report.'
    ),
}


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
