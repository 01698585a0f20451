"""Issue 13, the other parties (who counts, position, lane, start, actions), read from real NHTSA SGO narratives the
rules were not written from (tests/text/sgo/study3.jsonl; each entry's `source` beside its text). One test per
reading; each asserts what sketch.md's rules and the study set's gold give.
"""

from __future__ import annotations

from txt2sce_ros.sketch import Party, Sketch
from txt2sce_ros.text.extractor import extract

from .quoted import QUOTED

_SGO = QUOTED  # report id -> (source, narrative): tests/text/quoted.py


def _party(report_id: str, k: int = 0) -> Party:
    return extract(_SGO[report_id][1], report_id).npcs[k]


def test_a_party_heading_opposite_the_av_that_passes_it_is_oncoming() -> None:
    # "a pickup truck traveling southbound", the AV northbound: its pass is made from the front, in the oncoming
    # lane (R7, left), not from behind.
    p = _party("nhtsa-sgo-ads-30270-10684-v1")
    assert (p.position, p.lane, p.actions) == ("R7", "left", "a")
    # At a junction the oncoming party is on the opposite approach ("a cyclist traveling southbound against traffic
    # proceeded through the intersection, passing the Waymo AV on the left").
    sk = extract(_SGO["nhtsa-sgo-ads-30270-9654-v1"][1], "nhtsa-sgo-ads-30270-9654-v1")
    assert (sk.npcs[0].position, sk.npcs[0].lane) == ("R2", None)
    assert sk.collision.type == "side_swipe"  # a pass meets the AV along its side


def test_an_oncoming_party_passing_on_the_av_s_right_is_in_its_lane() -> None:
    # "A pickup truck traveling southeast ... began to maneuver past the Waymo AV on the right", the AV facing
    # northwest: the oncoming lane is on the AV's left, so one on its right is in its own lane (R7, same).
    p = _party("nhtsa-sgo-ads-30270-10725-v1")
    assert (p.position, p.lane) == ("R7", "same")


def test_coming_in_contact_and_coasting_into_the_av_are_contacts() -> None:
    # "The right side of the van came in contact with the rear left side of the Waymo AV" ("in", not "into").
    sk = extract(_SGO["nhtsa-sgo-ads-30270-7935-v1"][1], "nhtsa-sgo-ads-30270-7935-v1")
    assert (sk.collision.with_, sk.collision.type) == ("npc1", "side_swipe")
    # "A vehicle approaching from behind coasted into the ego vehicle."
    sk = extract(_SGO["nhtsa-sgo-ads-30413-10764-v1"][1], "nhtsa-sgo-ads-30413-10764-v1")
    assert (sk.collision.with_, sk.collision.type) == ("npc1", "rear_end")


def test_a_party_out_of_a_driveway_garage_or_parking_space_comes_from_the_curb_side() -> None:
    # "a passenger vehicle reversed out of a parking spot into a Pony.ai autonomous testing vehicle's rear bumper":
    # no side named; parking spots line the curb, on the AV's right.
    p = _party("csvr-pony.ai-20220517-s159")
    assert (p.position, p.lane, p.start, p.actions) == ("R6", "right", "stopped", "k")
    # "a passenger car began reversing out of the garage" (the AV at the curb beside it): on its right too.
    assert _party("nhtsa-sgo-ads-30270-9540-v1").lane == "right"


def test_an_av_named_only_as_an_autonomous_shuttle_is_the_av_not_a_bus() -> None:
    # "autonomous shuttle (MNCAV2, V005) for the Med City Mover was travelling southbound ... The vehicle behind the
    # shuttle ... hit the rear left corner of the shuttle": no operator's name for the AV (its driver, named, is no
    # name of the AV); the vehicle called autonomous is the AV, and the party is the vehicle behind it.
    sk = extract(_SGO["nhtsa-sgo-ads-30310-3698-v1"][1], "nhtsa-sgo-ads-30310-3698-v1")
    assert [(p.category, p.position) for p in sk.npcs] == [("car", "R6")]
    assert sk.collision.with_ == "npc1"


def test_a_participle_joined_by_and_to_a_party_s_participle_is_the_party_s() -> None:
    # "it detected a vehicle traveling west on [XXX] and crossing into the opposing lane": the crossing is the
    # vehicle's (a run, then a move to its left), not the AV's, the clause's subject.
    sk = extract(_SGO["nhtsa-sgo-ads-30270-8061-v1"][1], "nhtsa-sgo-ads-30270-8061-v1")
    assert (sk.npcs[0].position, sk.npcs[0].actions) == ("R2", "af")
    assert "f" not in sk.ego.actions


def test_a_party_backing_into_a_front_corner_of_the_av_came_straight_back_in_its_lane() -> None:
    # "another vehicle (Car 2) began reversing in front of the vehicle in question. The reversing vehicle (Car 2)
    # ultimately collided with the front left corner of the WeRide vehicle": the corner its rear met tells no lane.
    sk = extract(_SGO["nhtsa-sgo-ads-30792-6114-v1"][1], "nhtsa-sgo-ads-30792-6114-v1")
    p = sk.npcs[0]
    assert (p.position, p.lane, p.actions, sk.collision.type) == ("R5", "same", "k", "rear_end")


def test_the_av_described_again_in_parentheses_is_no_party() -> None:
    # "The subject vehicle (autonomous vehicle - AV) was stopped at a red traffic light ... struck from behind by an
    # SUV": the parenthesis says what the AV is; the one other party is the SUV.
    sk = extract(_SGO["nhtsa-sgo-ads-1420-7995-v1"][1], "nhtsa-sgo-ads-1420-7995-v1")
    assert [(p.category, p.position, p.lane) for p in sk.npcs] == [("car", "R6", "same")]


def test_a_pick_up_truck_and_the_pickup_truck_are_one_party() -> None:
    # "A pick-up truck traveling in the right most lane ... the driver side of the pickup truck made contact": one
    # truck, spelled two ways.
    sk = extract(_SGO["nhtsa-sgo-ads-30270-9507-v1"][1], "nhtsa-sgo-ads-30270-9507-v1")
    assert len(sk.npcs) == 1


def test_what_follows_after_the_initial_contact_is_after_the_conflict() -> None:
    # "After this initial contact, the pick-up truck maneuvered to the front of the Waymo AV ... reversed, and the
    # rear of the pickup truck made contact with the front": the conflict is the first contact; the string ends there.
    sk = extract(_SGO["nhtsa-sgo-ads-30270-9507-v1"][1], "nhtsa-sgo-ads-30270-9507-v1")
    assert (sk.npcs[0].position, sk.npcs[0].lane, sk.npcs[0].actions, sk.collision.type) == \
        ("R5", "right", "af", "side_swipe")
    # "... made contact with the rear bumper of the Waymo AV. After this initial contact, the pickup truck reversed":
    # the reversing is no part of it.
    p = _party("nhtsa-sgo-ads-30270-9414-v1")
    assert (p.position, p.lane, p.actions) == ("R6", "same", "l")


def test_a_second_contact_after_the_party_moved_on_again_is_after_the_conflict() -> None:
    # "... made contact with the rear of the Waymo AV ... before the passenger car slowed down and separated from the
    # AV. ... The passenger car then accelerated and ... made contact with the rear left corner": the conflict is the
    # first contact, the party's string ends there.
    p = _party("csvr-waymo-20240319-s304")
    assert (p.position, p.lane, p.actions) == ("R6", "same", "a")


def test_numbered_individuals_are_people_on_foot() -> None:
    # "it was struck on its right front fender by two individuals involved in an altercation who had darted out from
    # the side of the roadway": people on foot (not a group of traffic), the AV touched by one of them.
    sk = extract(_SGO["nhtsa-sgo-ads-30610-3719-v2"][1], "nhtsa-sgo-ads-30610-3719-v2")
    assert sk.npcs and sk.npcs[0].category == "pedestrian"
    assert (sk.collision.with_, sk.collision.type) == ("npc1", "pedestrian")


def test_a_numbered_group_told_only_in_the_opening_sentence_is_that_many_parties() -> None:
    # The opening sentence tells the contact ("struck ... by two individuals"), so it reads as a summary; but no later
    # sentence names the two one by one ("The two individuals fled the scene"): the count is the opening's (gold:
    # two pedestrians, R5 right, `m` each).
    sk = extract(_SGO["nhtsa-sgo-ads-30610-3719-v2"][1], "nhtsa-sgo-ads-30610-3719-v2")
    assert [(p.category, p.position, p.lane) for p in sk.npcs] == [("pedestrian", "R5", "right")] * 2


def test_a_party_in_the_adjacent_lane_is_on_the_side_of_the_av_it_touched() -> None:
    # "A passenger car approached the stationary Waymo AV from behind in the adjacent straight lane, and crossed into
    # the lane that the Waymo AV was occupying. The front driver side of the passenger car made contact with the rear
    # passenger side": the adjacent lane, its side told by the contact (right), not the AV's own lane.
    p = _party("nhtsa-sgo-ads-30270-9371-v1")
    assert (p.position, p.lane, p.actions) == ("R6", "right", "af")


def test_debris_a_party_threw_at_the_av_came_from_where_that_party_was() -> None:
    # (dev.jsonl, official gold) "a nearby semi-trailer truck merging from Interstate 238 generated a draft that
    # projected road debris onto the test vehicle": the truck merged in from the right; the debris came from there.
    sk = extract(_SGO["dmvca-apple-20240126-r555"][1], "dmvca-apple-20240126-r555")
    assert (sk.npcs[0].position, sk.npcs[0].lane) == ("R5", "right")
    assert (sk.obstacles[0].category, sk.obstacles[0].position, sk.obstacles[0].lane) == ("debris", "R5", "right")


def test_the_av_s_street_is_read_in_its_own_clause_not_a_turning_party_s() -> None:
    # "The Waymo AV was stopped at a stop sign on Jerrold Avenue and yielding to a pickup truck that was in the
    # intersection making a left turn from Barneveld Avenue onto Jerrold Avenue": the AV is on Jerrold (the stop sign
    # is where it stopped, not another party's clause), and the turn from Barneveld is the truck's; so the truck
    # turned left onto the AV's street, coming from its right (R3).
    sk = extract(_SGO["csvr-waymo-20240330-s307"][1], "csvr-waymo-20240330-s307")
    assert sorted((p.position, p.actions) for p in sk.npcs) == [("R3", "d"), ("R6", "a")]


def test_a_party_the_av_stopped_behind_is_ahead_in_its_lane() -> None:
    # "The Waymo AV ... came to a stop behind a passenger car that had stopped for a closed traffic control gate arm.
    # ... the gate arm rose to allow the passenger car to pass through": ahead of the AV in its lane (its later
    # mention is no test of the first's words), and passing through the gate is no pass of the AV.
    p = _party("nhtsa-sgo-ads-30270-10561-v1")
    assert (p.position, p.lane, p.start, p.actions) == ("R5", "same", "stopped", "i")


def test_stopped_for_a_pickup_facing_north_is_an_errand_not_a_truck() -> None:
    # "The Waymo AV was stopped curbside for a pickup facing north": a passenger pickup; the one party is the SUV.
    sk = extract(_SGO["nhtsa-sgo-ads-30270-8150-v1"][1], "nhtsa-sgo-ads-30270-8150-v1")
    assert len(sk.npcs) == 1


def test_a_party_stopped_behind_the_av_that_passes_it_began_in_its_lane() -> None:
    # "an SUV that had been stopped partially in-lane behind the Waymo AV passed the Waymo AV on the left": it stood
    # in the AV's queue, in its lane, and moved out to the left to pass (R6, same; start, lane change left).
    p = _party("nhtsa-sgo-ads-30270-8150-v1")
    assert (p.position, p.lane, p.start, p.actions) == ("R6", "same", "stopped", "if")


def test_a_party_that_backs_up_began_standing() -> None:
    # "A passenger car traveling directly in front of the Waymo AV started to reverse backwards towards the Waymo
    # AV": it backs only from a standstill; "traveling" describes where it was (gold: stopped, k).
    p = _party("nhtsa-sgo-ads-30270-9552-v1")
    assert (p.position, p.lane, p.start, p.actions) == ("R5", "same", "stopped", "k")


def test_an_oncoming_party_crossing_into_the_av_s_lane_travelled_first() -> None:
    # "an oncoming passenger car crossed into the Waymo AVs lane, toward the Waymo AV": the possessive written
    # without its apostrophe is the AV's lane; the party came along its own lane, then moved over into the AV's
    # (gold R7, left, "af").
    p = _party("nhtsa-sgo-ads-30270-5896-v1")
    assert (p.position, p.lane, p.start, p.actions) == ("R7", "left", "moving", "af")


def test_a_make_and_model_digit_written_as_one_word_is_a_car() -> None:
    # "subject vehicle was lightly struck from behind by a white Mazda3": the party that struck it, behind in its
    # lane (gold: a car, R6 same, `a`).
    sk = extract(_SGO["nhtsa-sgo-ads-30590-3431-v1"][1], "nhtsa-sgo-ads-30590-3431-v1")
    assert [(p.category, p.position, p.lane, p.actions) for p in sk.npcs] == [("car", "R6", "same", "a")]


def test_any_verb_of_motion_with_a_side_into_a_place_is_a_lane_change() -> None:
    # "The heavy truck traveling eastbound ... began maneuvering left into the path of the Waymo AV": oncoming, it
    # moved left into the AV's lane before the contact (gold: R7 left, `af`), as "moved left into", "merging left
    # into" and "veered left into" already read.
    p = _party("nhtsa-sgo-ads-30270-10776-v1")
    assert (p.position, p.lane, p.actions) == ("R7", "left", "af")


def test_a_party_told_leaving_its_lane_changed_lane() -> None:
    # "a passenger car traveling southeast in the center lane ... entered the intersection and departed its lane into
    # the path of left-turning traffic": the opposite approach's car left its lane toward the turning AV (gold: R2,
    # `af`), as "drifted out of its lane" already read.
    p = _party("nhtsa-sgo-ads-30270-9330-v1")
    assert (p.position, p.actions) == ("R2", "af")


def test_a_party_backing_out_from_across_the_street_is_oncoming_and_meets_the_av_broadside() -> None:
    # "The Waymo AV was parallel parked along the right-hand curb ... when a passenger car reversed out of a driveway
    # across the street from the Waymo AV and made contact with the driver side rear bumper": the far side of the
    # AV's road is the oncoming side (R7, left), and a party backing into the AV's side meets it broadside (gold).
    sk = extract(_SGO["nhtsa-sgo-ads-30270-6131-v1"][1], "nhtsa-sgo-ads-30270-6131-v1")
    p = sk.npcs[0]
    assert (p.position, p.lane, p.start, p.actions) == ("R7", "left", "stopped", "k")
    assert (sk.collision.with_, sk.collision.type) == ("npc1", "broadside")


def test_a_party_passing_in_front_of_the_av_crosses_its_path_ahead_of_it() -> None:
    # "it stopped for a cyclist who was approaching from the left. The Waymo AV remained stationary as the cyclist
    # passed in front of the vehicle, slowed, and appeared to begin to dismount": a crossing (`m`) ahead of the AV,
    # not a pass from behind along its side (gold: R5 left, `mc`).
    p = _party("nhtsa-sgo-ads-30270-8039-v1")
    assert (p.position, p.lane, p.actions) == ("R5", "left", "mc")


def test_the_av_s_own_open_door_is_no_obstacle() -> None:
    # "the Waymo AV passenger opened the driver side rear door and the passenger side of the van made contact with
    # the open driver side rear door of the Waymo AV": a door the AV's rider opened is a part of the AV, not an
    # object in its path (sketch.md: a door opened into the AV's path); the van that met it is the party.
    sk = extract(_SGO["nhtsa-sgo-ads-30270-10599-v1"][1], "nhtsa-sgo-ads-30270-10599-v1")
    assert ([o.category for o in sk.obstacles], [p.category for p in sk.npcs]) == ([], ["van"])
    assert sk.collision.with_ == "npc1"


def _told_as(report_id: str, *pairs: tuple[str, str]) -> tuple[Sketch, Sketch]:
    """The sketch of a real narrative and of the same narrative with its words replaced as another reporter writes
    them (each replacement must change the text)."""
    text = other = _SGO[report_id][1]
    for old, new in pairs:
        assert old in other, old
        other = other.replace(old, new)
    return extract(text, report_id), extract(other, report_id)


def test_the_sgo_form_s_role_names_name_the_other_party() -> None:
    # "a passenger car approached the Waymo AV from behind and the front of the passenger car made contact with the
    # rear of the Waymo AV", told with the form's role name ("the Crash Partner (CP) ... the CP"), another numbering
    # ("Unit 2") or a third-party vehicle: one car, the one that struck the AV.
    rid = "nhtsa-sgo-ads-30270-9347-v1"
    for name, again in (("the Crash Partner (CP)", "the CP"), ("a third-party vehicle (TPV)", "the TPV"),
                        ("the other vehicle (OV)", "the OV"), ("Unit 2", "Unit 2"), ("a CP vehicle", "the CP")):
        told, other = _told_as(rid, ("a passenger car approached", f"{name} approached"),
                               ("the front of the passenger car", f"the front of {again}"))
        assert [(p.category, p.position, p.lane) for p in other.npcs] == [("car", "R6", "same")], name
        assert other.collision == told.collision, name


def test_a_contact_told_in_brief_after_a_note_about_the_report_is_the_summary() -> None:
    # "This report is mean to correct monthly report 30270-7719-1 ... On April [XXX], 2024 ... a Waymo Autonomous
    # Vehicle ... was in a collision involving a passenger car ... a passenger car traveling directly behind the
    # Waymo AV made contact": told "was struck by a passenger car" in the opening story sentence, the car of the
    # telling is the same car (the note about the report is no part of the story).
    told, other = _told_as("nhtsa-sgo-ads-30270-7719-v2", ("was in a collision involving", "was struck by"))
    assert [p.category for p in told.npcs] == [p.category for p in other.npcs] == ["car"]


def test_a_vehicle_the_contact_pushed_the_av_into_takes_part() -> None:
    # "an SUV approached the Waymo AV from behind. The front of the SUV made contact with the rear of the Waymo AV",
    # told on with the AV pushed into a car ahead: that car is a party of its own (not the SUV, which no studyable
    # narrative calls "the passenger car"), and the conflict is still the SUV's contact.
    told, other = _told_as("nhtsa-sgo-ads-30270-9433-v1", (
        "made contact with the rear of the Waymo AV.",
        "made contact with the rear of the Waymo AV, pushing the Waymo AV into the passenger car stopped ahead."))
    assert [p.category for p in told.npcs] == ["car"]
    assert [p.category for p in other.npcs] == ["car", "car"]
    assert other.collision == told.collision


def test_a_contact_told_as_an_event_by_the_av_s_operator_named_by_abbreviation() -> None:
    # "the Autonomous Vehicle Operator (AVO) disengages and proceeds in manual. The AVO overcorrects to the right
    # slightly and a minor contact with the parked car's mirror occurs": the AVO drives the AV, and "a minor contact
    # with" is the contact; the parked car is the obstacle struck (gold), the oncoming vehicle a party.
    sk = extract(_SGO["nhtsa-sgo-ads-30413-10763-v1"][1], "nhtsa-sgo-ads-30413-10763-v1")
    assert [o.category for o in sk.obstacles] == ["parked_vehicle"]
    assert (sk.collision.with_, sk.collision.type) == ("obs1", "hit_object")
    assert [p.category for p in sk.npcs] == ["car"]


def test_an_av_named_only_as_the_truck_of_a_named_operator_and_its_own_parts_are_no_party() -> None:
    # "TuSimple's position is ... As the truck was being operated on the highway ... the uninitialized vehicle control
    # unit rotated the steering to the left, causing the truck to veer left ... the left front truck tire and left
    # front quarter panel came into contact with the concrete barrier": the report names no AV but "the truck" (its
    # operator named), which is the AV; "vehicle control unit" and "truck tire" are its parts. One barrier (gold).
    sk = extract(_SGO["nhtsa-sgo-ads-10003-3210-v1"][1], "nhtsa-sgo-ads-10003-3210-v1")
    assert (len(sk.npcs), [o.category for o in sk.obstacles]) == (0, ["barrier"])
    assert (sk.collision.with_, sk.collision.type) == ("obs1", "hit_object")


def test_a_contact_between_another_party_and_an_object_or_believed_is_not_the_av_s() -> None:
    # "As the SUV in the left lane was passing the Waymo AV, it maneuvered to the left in its lane, and the driver side
    # made contact with the center concrete median curb": the SUV met the curb, the AV met nothing (gold: no contact).
    sk = extract(_SGO["nhtsa-sgo-ads-30270-9376-v1"][1], "nhtsa-sgo-ads-30270-9376-v1")
    assert (sk.collision.with_, sk.collision.type) == (None, "none")
    # "subject vehicle was lightly struck from behind by a white Mazda3. Having seen debris on the roadway, the driver
    # and operator believed they had run over a rock": the rock is a belief; the Mazda struck the AV (gold).
    sk = extract(_SGO["nhtsa-sgo-ads-30590-3431-v1"][1], "nhtsa-sgo-ads-30590-3431-v1")
    assert ([p.category for p in sk.npcs], [o.category for o in sk.obstacles]) == (["car"], [])
    assert (sk.collision.with_, sk.collision.type) == ("npc1", "rear_end")
    # "an Infiniti Q60 ... made contact with a black sedan ... The Infiniti Q60 spun after contact and continued into
    # the Cruise AV": the Infiniti's contact with the sedan is theirs; its move into the AV is the AV's (gold: npc1).
    sk = extract(_SGO["csvr-cruise-20230721-s263"][1], "csvr-cruise-20230721-s263")
    assert (len(sk.npcs), sk.collision.with_) == (2, "npc1")


def test_an_object_the_av_pushed_into_parked_vehicles_struck_them_too() -> None:
    # "the front of the Waymo AV made contact with a portable metal barrier ... it pushed the barrier along with it and
    # the rightmost edge of the barrier made contact with the rear driver side of a postal van parked at the curb ...
    # the rightmost edge of the barrier made contact with the driver side of two other postal vans and two passenger
    # cars that were also parked": the AV met the barrier; the barrier met five parked vehicles (the numbered plurals
    # counted, "that were also parked" said of both); no moving party (gold).
    sk = extract(_SGO["nhtsa-sgo-ads-30270-8152-v1"][1], "nhtsa-sgo-ads-30270-8152-v1")
    assert sk.npcs == ()
    assert sorted(o.category for o in sk.obstacles) == ["barrier"] + ["parked_vehicle"] * 5
    assert (sk.collision.with_, sk.collision.type) == ("obs1", "hit_object")
