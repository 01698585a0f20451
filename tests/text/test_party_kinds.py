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
