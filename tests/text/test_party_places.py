"""Issue 13, where the other parties were (position and lane, relations.place's tiers), read from real narratives of
the studyable sets (dev.jsonl with its official gold, tests/text/csvr/study2.jsonl, tests/text/sgo/study3.jsonl;
each narrative quoted with its id and source). One test per reading; each asserts what sketch.md's rules and the
studyable gold give, and fails when the reading is removed.
"""

from __future__ import annotations

from txt2sce_ros.sketch import Party
from txt2sce_ros.text.extractor import extract

from .invariance import _clause_after, _when_to_as
from .quoted import QUOTED

_TEXTS = QUOTED  # report id -> (source, narrative): tests/text/quoted.py


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


def test_a_party_that_rear_ended_the_av_was_behind_it_whatever_side_a_clause_about_the_av_names() -> None:
    # "The Waymo AV was yielding to approaching traffic from the left when a passenger vehicle rear-ended the Waymo
    # AV": told with the AV's clause after the party's (as another reporter writes it), the side "from the left" of
    # the traffic the AV yielded to comes into the party's words; the rear-end says where the party was (28 of the
    # 29 studyable reports telling a rear-end of the AV have the party behind it in the gold).
    text = _TEXTS["csvr-waymo-20190206-s2"][1].replace(
        "The Waymo AV was yielding to approaching traffic from the left when a passenger vehicle rear-ended the Waymo "
        "AV while travelling approximately 4 MPH.",
        "A passenger vehicle rear-ended the Waymo AV while travelling approximately 4 MPH as the Waymo AV was "
        "yielding to approaching traffic from the left.")
    assert text != _TEXTS["csvr-waymo-20190206-s2"][1]
    p = extract(text, "csvr-waymo-20190206-s2").npcs[0]
    assert (p.position, p.lane) == ("R6", "same")
    # The turn made first keeps the party on its own approach: "a Toyota Sedan on westbound Sacramento Street ...
    # was making an unprotected right turn on a red light onto northbound Van Ness Avenue behind the Cruise AV.
    # Shortly thereafter, the Toyota Sedan rear-ended the Cruise AV".
    p = _party("csvr-cruise-20220409-s148")
    assert p.position == "R3"


def test_a_clause_about_the_av_after_the_party_s_tells_the_av_s_place_not_the_party_s() -> None:
    # Told with the AV's clause after the party's (the clause order other reporters use): "A passenger car in front
    # of the Waymo AV began to reverse to parallel park as the Waymo AV was parked at the curb on the right side of
    # 29th Avenue": the curb and its side are where the AV stood; the party was ahead in its lane (the gold's R5/same).
    original = _TEXTS["csvr-waymo-20240605-s317"][1]
    text = _when_to_as(original)
    assert text != original and "as the Waymo AV was parked at the curb" in text
    p = extract(text, "csvr-waymo-20240605-s317").npcs[0]
    assert (p.position, p.lane) == ("R5", "same")
    # "An SUV reversed out of a driveway on the left side of the street as the Waymo AV was parked at the curb on the
    # right side of the street": out of a driveway on the AV's left (the gold's R5/left), not at its curb.
    original = _TEXTS["nhtsa-sgo-ads-30270-9435-v1"][1]
    text = _clause_after(original)
    assert text != original
    p = extract(text, "nhtsa-sgo-ads-30270-9435-v1").npcs[0]
    assert (p.position, p.lane) == ("R5", "left")


def _rewritten_place(report_id: str, old: str, new: str) -> tuple[str, str | None]:
    """(position, lane) of the first party of a quoted narrative told with `old` replaced by `new`."""
    original = _TEXTS[report_id][1]
    text = original.replace(old, new)
    assert text != original, (report_id, old)
    p = extract(text, report_id).npcs[0]
    return p.position, p.lane


def test_the_same_scene_told_with_other_common_verbs_places_the_party_alike() -> None:
    # "the scooter's front tire made contact with the rear bumper of the Zoox vehicle", told "struck": the AV's part
    # is the words after the contact's verb (its rear), not the scooter's front as well; the rider ran into the
    # middle of the AV's rear, in line behind it (the gold's R6/same).
    assert _rewritten_place("csvr-zoox-20191011-s35", "made contact with", "struck") == ("R6", "same")
    # "A passenger car (Vehicle 2) was stopped directly behind the Zoox vehicle ... tried to pass the Zoox vehicle on
    # the right side", told "was stationary": it stood in the AV's queue, in its lane, and moved out to pass.
    assert _rewritten_place("csvr-zoox-20240716-s322", "was stopped", "was stationary") == ("R6", "same")
    # "The Waymo AV was stopped on the right side of southwestbound [XXX] for a passenger pick-up when an SUV
    # traveling in the rightmost lane ... passed", told "was stationary" or "had stopped": the AV at the right
    # edge, the rightmost lane on its left (the gold's R6/left).
    for told in ("was stationary", "had stopped"):
        assert _rewritten_place("nhtsa-sgo-ads-30270-9436-v1", "was stopped", told) == ("R6", "left")
    # "a white pickup truck traveling behind the Cruise AV rear-ended the Cruise AV, damaging the rear right bumper,
    # rear right quarter panel", told "traveling behind it": the pronoun is the AV, the truck in its lane (R6/same).
    assert _rewritten_place("csvr-cruise-20230728-s266", "traveling behind the Cruise AV",
                            "traveling behind it") == ("R6", "same")


def test_a_party_first_told_as_what_the_av_came_up_on_is_ahead_in_its_path() -> None:
    # "EGO approached a semi-trailer truck that was stopped in the left lane of traffic": what the AV came up on
    # stood in its path, whatever lane the road names it in (the gold's R5/same; 10 of 10 studyable parties first
    # told so are ahead in the AV's lane in the gold).
    p = _party("csvr-cruise-20220905-s189")
    assert (p.position, p.lane) == ("R5", "same")
    # "... when it approached a stopped pickup truck ... The pickup truck was stopped in the leftmost lane ... The
    # Waymo AV began changing lanes into the right lane ... to pass the stopped pickup truck": the pass is the AV's
    # (the truck is what it passed), no pass of the truck's.
    p = _party("nhtsa-sgo-ads-30270-7724-v1")
    assert (p.position, p.lane) == ("R5", "same")
    # "The Waymo AV was traveling southwest bound on [XXX] when it slowed to a stop as it approached an SUV reversing
    # in the roadway. ... The SUV continued reversing on the left side of the roadway": the AV named again by "it";
    # where the SUV went later is no place it began in (the gold's R5/same).
    p = _party("nhtsa-sgo-ads-30270-10672-v1")
    assert (p.position, p.lane) == ("R5", "same")


def _rewritten(report_id: str, *edits: tuple[str, str]) -> tuple[str, str | None]:
    """(position, lane) of the first party of a quoted narrative with each (old, new) edit made."""
    text = _TEXTS[report_id][1]
    for old, new in edits:
        assert old in text, (report_id, old)
        text = text.replace(old, new)
    p = extract(text, report_id).npcs[0]
    return p.position, p.lane


def test_a_party_told_crossing_the_av_s_way_at_a_junction_is_on_the_crossing_road_on_the_side_it_struck() -> None:
    # "the Cruise AV yielded to an electric scooterist traveling northbound on Mission Street and violating a red
    # light ... the electric scooterist made contact with the right rear corner of the Cruise AV" (the gold's R3),
    # told without its heading: running the light puts it on the crossing road, on the side of the AV it struck,
    # though it struck a rear corner (the tail of an AV crossing its way), not behind the AV.
    assert _rewritten("dmvca-cruise-20191107-r89", ("traveling northbound on Mission Street and violating",
                                                    "violating")) == ("R3", None)
    # "a passenger vehicle which had previously been stopped at a red light, proceeded through the red light. The
    # passenger vehicle approached from the left and made contact with the left rear bumper" (the gold's R1), told
    # without "from the left": the side of the AV it struck tells it.
    assert _rewritten("csvr-waymo-20230122-s209", ("approached from the left and made", "made")) == ("R1", None)


def test_a_side_of_the_av_named_after_it_and_a_broadside_are_read() -> None:
    # "... proceeded through the red light. The passenger vehicle approached from the left and made contact with the
    # left rear bumper of the Waymo AV", told "broadsided the Waymo AV on its driver side" / "on its passenger side":
    # a contact (the party is the collision's), and the part named after the AV's name is the side it struck (the
    # crossing road on that side).
    for side, leg in (("driver", "R1"), ("passenger", "R3")):
        text = _TEXTS["csvr-waymo-20230122-s209"][1].replace(
            "approached from the left and made contact with the left rear bumper of the Waymo AV",
            f"broadsided the Waymo AV on its {side} side")
        sk = extract(text, "csvr-waymo-20230122-s209")
        assert sk.collision.with_ == "npc1" and (sk.npcs[0].position, sk.npcs[0].lane) == (leg, None), side


def test_a_vehicle_the_av_gave_way_to_at_a_junction_is_on_the_crossing_road_from_the_left() -> None:
    # "The Waymo AV stopped to yield to another vehicle at the intersection" (a four-way stop, the AV going
    # straight): nothing else places it; a driver going straight yields to the crossing road from the left (R1).
    assert (_party("csvr-waymo-20190226-s3").position, _party("csvr-waymo-20190226-s3").lane) == ("R1", None)
    # "The first Waymo AV was preparing to make a right turn, while yielding to the other Waymo AV" (a T-junction
    # of a parking lot): the same, for an AV turning right.
    p = _party("dmvca-waymo-20241016-r620", 1)
    assert (p.position, p.lane) == ("R1", None)


def test_a_party_going_forward_into_the_front_of_a_standing_av_came_at_it_head_on() -> None:
    # "The Waymo AV remained stopped as the oncoming cyclists rode around both sides of the Waymo AV. One cyclist
    # then made contact with the front of the stationary Waymo AV": the cyclist named anew, nothing said of its
    # place, going forward into the middle of the front of an AV standing still: it came the other way, in the
    # AV's lane (the gold's R7/same), not ahead of the AV at the lane edge.
    p = _party("dmvca-waymo-20230507-r466")
    assert (p.position, p.lane) == ("R7", "same")
    # One that backed into the front of the standing AV was ahead of it: "a passenger car reversed into the vacant
    # parallel parking space in front of the Waymo AV. The rear of the passenger car made contact with the front of
    # the Waymo AV" (R5, in the AV's path).
    assert _party("nhtsa-sgo-ads-30270-10800-v1").position == "R5"


def test_a_rider_splitting_lanes_is_beside_the_av_coming_up_from_behind() -> None:
    # "While in traffic and stopped at 0mph in autonomy, a motorized scooter riding between the 2 lanes of traffic
    # clipped the May Mobility vehicle's mirror with their own mirror": riding the line between two lanes, it is in
    # no lane of the AV's and passes it from behind; no side of the AV named, on its left (the gold's R6/left), not
    # ahead at the curb edge.
    p = _party("nhtsa-sgo-ads-30413-7880-v1")
    assert (p.position, p.lane) == ("R6", "left")


def test_a_party_that_drove_into_an_av_standing_throughout_came_from_behind_when_nothing_else_is_told() -> None:
    # "A Zoox vehicle in autonomous mode was stopped at a traffic light on Brannan Street at 7th Street when a
    # passenger vehicle hit the Zoox vehicle from behind" (the gold's R6/same), told without "from behind" or with
    # "failed to stop in time and collided with": no part of the AV and no place told, but the AV stood still
    # throughout and the party drove into it: most often from behind (86 of the 119 studyable parties that touched
    # an AV standing throughout), not ahead of it. The place stays a default (`missing` keeps "position").
    for told in ("hit the Zoox vehicle", "failed to stop in time and collided with the Zoox vehicle"):
        text = _TEXTS["csvr-zoox-20220205-s130"][1].replace("hit the Zoox vehicle from behind", told)
        sk = extract(text, "csvr-zoox-20220205-s130")
        assert (sk.npcs[0].position, sk.npcs[0].lane) == ("R6", "same"), told
        assert "position" in sk.missing


def test_a_party_striking_one_told_behind_the_av_came_from_further_behind_whichever_is_named_first() -> None:
    # "... with an SUV stopped directly behind the Waymo AV. Moments later, a passenger car traveling at a high rate
    # of speed approached the stopped SUV from behind and made contact with the rear of the SUV" (the gold's two
    # R6/same), told with the striker first: "a passenger car traveling at a high rate of speed made contact with the
    # rear of an SUV that was stopped directly behind the Waymo AV". The chain puts it behind the SUV, so behind
    # the AV, though the SUV is placed after it.
    text = _TEXTS["csvr-waymo-20241104-s345"][1].replace(
        " with an SUV stopped directly behind the Waymo AV. Moments later, a passenger car traveling at a high rate of "
        "speed approached the stopped SUV from behind and made contact with the rear of the SUV.",
        ". Moments later, a passenger car traveling at a high rate of speed made contact with the rear of an SUV that "
        "was stopped directly behind the Waymo AV.")
    sk = extract(text, "csvr-waymo-20241104-s345")
    assert [(p.position, p.lane) for p in sk.npcs] == [("R6", "same"), ("R6", "same")]


def test_a_party_coming_the_other_way_in_the_lanes_of_the_av_s_direction_is_the_wrong_way_in_its_lane() -> None:
    # "an SUV that was traveling westbound on [XXX] in the middle shared turn lane, directly in front of the Waymo
    # AV" (the AV eastbound; the gold's R7/same), told "in the eastbound lanes": a lane named by the direction it
    # carries, the AV's, holds a party going the other way in the AV's lane, head-on, also at the junction.
    for told in ("in the eastbound lanes", "within the eastbound travel lane"):
        text = _TEXTS["nhtsa-sgo-ads-30270-10726-v1"][1].replace(
            "in the middle shared turn lane, directly in front of the Waymo AV", told)
        p = extract(text, "nhtsa-sgo-ads-30270-10726-v1").npcs[0]
        assert (p.position, p.lane) == ("R7", "same"), told


def test_a_party_behind_moving_over_toward_the_av_came_from_the_side_of_the_rear_corner_it_struck() -> None:
    # "A white Honda SUV approaching from the rear in the lane to the left of the Cruise AV changed into the Cruise
    # AV's lane ... and then proceeded forward to make contact with the rear driver side bumper of the Cruise AV"
    # (the gold's R6/left), told "approaching from the rear changed lanes to the right": no lane named, but a move
    # to the right ending at the AV's rear left came from the left lane.
    old = "approaching from the rear in the lane to the left of the Cruise AV changed into the Cruise AV’s lane"
    for told in ("approaching from the rear changed lanes to the right", "approaching from the rear moved over to the "
                 "right"):
        p = extract(_TEXTS["dmvca-cruise-20220816-r374"][1].replace(old, told), "dmvca-cruise-20220816-r374").npcs[0]
        assert (p.position, p.lane) == ("R6", "left"), told
    # A move out toward the side struck left the AV's lane: "a vehicle behind the Cruise AV attempted to change into
    # the right adjacent lane and made contact with the right rear corner" (csvr-cruise-20191017-s39: R6/same).
    p = _party("csvr-cruise-20191017-s39")
    assert (p.position, p.lane) == ("R6", "same")


def test_a_verb_made_of_a_part_after_the_av_s_name_is_what_the_av_did_not_a_part_of_it() -> None:
    # "a white pickup truck traveling behind the Cruise AV rear-ended the Cruise AV" and "Then the AV side-swiped the
    # double-parked vehicle": the AV's name before "rear-ended" / "side-swiped" is no possessive ("EGO's rear"), so
    # no part of the AV is read from the verb.
    from txt2sce_ros.text.mentions import normalise
    t = normalise(_TEXTS["csvr-cruise-20230728-s266"][1])
    assert "behind EGO rear-ended EGO" in t and "EGO's rear-ended" not in t
    t = normalise(_TEXTS["dmvca-apollobaid-20230906-r524"][1])
    assert "EGO side-swiped" in t
    # So the AV rear-ending the car ahead of it keeps that car ahead (R5/same), not behind it.
    sk = extract("The Waymo AV was traveling northbound on Main Street. A sedan ahead slammed on its brakes and the "
                 "Waymo AV rear-ended the sedan.", "t")
    assert (sk.npcs[0].position, sk.npcs[0].lane) == ("R5", "same")


def test_the_lane_a_party_came_out_of_is_where_it_was() -> None:
    # "a passenger car that was traveling behind the Waymo AV at a high rate of speed began to change lanes from the
    # rightmost lane to the leftmost lane. As the Waymo AV entered the leftmost lane, the passenger car passed the
    # Waymo AV in the leftmost lane" (the AV "in the center lane of three lanes"): it was in the lane to the AV's
    # right when the interaction began, not in the AV's lane ("traveling behind") nor in the leftmost lane it
    # passed in (relations.place: the lane it came out of first).
    p = _party("nhtsa-sgo-ads-30270-8121-v1")
    assert (p.position, p.lane) == ("R6", "right")


def test_a_party_the_av_follows_behind_is_ahead_of_it() -> None:
    # "The Waymo AV was traveling westbound on [XXX] following behind a heavy truck. ... the heavy truck began to
    # reverse again and made contact with the front of the Waymo AV" (nhtsa-sgo-ads-30270-7007-v1, study4): "following
    # behind" with the truck named after it is the AV's place behind the truck, so the truck is ahead (R5, same).
    p = _party("nhtsa-sgo-ads-30270-7007-v1")
    assert (p.position, p.lane) == ("R5", "same")


def test_an_oncoming_party_turning_into_a_lot_or_crossing_the_median_is_on_the_av_s_road_not_the_opposite_approach() -> None:
    # "The Waymo AV was stopped in a queue of westbound traffic for a red traffic light on [XXX]. An SUV traveling
    # eastbound on W Monroe Street attempted to make a left turn across the stationary Waymo AV's lane of travel to
    # the entrance of a parking lot on the right of the Waymo AV" (nhtsa-sgo-ads-30270-10175-v1, study4): it turns
    # off mid-block, oncoming on the AV's own road (R7, left), not on the junction's opposite approach (R2).
    p = _party("nhtsa-sgo-ads-30270-10175-v1")
    assert (p.position, p.lane) == ("R7", "left")
    # "a pickup truck was traveling southeast on El Camino Real in the center of three lanes ... the pickup truck
    # swerved to the left, crossing the curbed median" (dmvca-waymo-20241014-r619, dev, official gold R7/left), the
    # AV stopped behind a queue in a left turn lane at the intersection.
    p = _party("dmvca-waymo-20241014-r619")
    assert (p.position, p.lane) == ("R7", "left")


def _said(report_id: str, old: str, new: str, k: int = 0) -> tuple[str, str | None]:
    """The place of party `k` in the real narrative with one wording replaced (each occurrence) by another of the
    same fact."""
    text = _TEXTS[report_id][1]
    assert old in text
    p = extract(text.replace(old, new), report_id).npcs[k]
    return p.position, p.lane


def test_a_heading_told_in_the_simple_past_places_the_party_as_the_progressive_does() -> None:
    # "The Waymo AV was traveling east on [XXX] ... A pickup truck traveling west on [XXX] approached the Waymo AV"
    # (nhtsa-sgo-ads-30270-8141-v1, study3: R7/left), told "traveled east", "traveled west" as police write it.
    assert _said("nhtsa-sgo-ads-30270-8141-v1", "traveling", "traveled") == ("R7", "left")
    assert _said("nhtsa-sgo-ads-30270-8141-v1", "was traveling", "drove") == ("R7", "left")


def test_an_av_standing_at_the_right_edge_in_other_words_puts_the_road_s_lanes_on_its_left() -> None:
    # "The Waymo AV was stopped on the right side of southwestbound [XXX] for a passenger pick-up when an SUV
    # traveling in the rightmost lane ... passed the Waymo AV" (nhtsa-sgo-ads-30270-9436-v1, study3: R6/left), the
    # standing told as the road reading's other words tell it.
    for standing in ("was at a standstill", "was sitting", "had come to a stop", "was at a stop"):
        assert _said("nhtsa-sgo-ads-30270-9436-v1", "was stopped", standing) == ("R6", "left")


def test_a_side_of_the_av_s_body_is_no_lane_beside_it() -> None:
    # "The Waymo AV was rear ended by the truck, causing minor damage to the right rear bumper of the Waymo AV"
    # (csvr-waymo-20220103-s122, study2: R6/same), told "to the Waymo AV's right rear bumper": a part of the AV, not
    # a place to its right.
    assert _said("csvr-waymo-20220103-s122", "the right rear bumper of the Waymo AV",
                 "the Waymo AV's right rear bumper") == ("R6", "same")


def test_the_party_s_own_flank_after_its_pass_is_no_side_it_passed_on() -> None:
    # "As the heavy truck was passing the stopped Waymo AV, the passenger side of the heavy truck made contact with
    # the rear driver side corner of the Waymo AV" (csvr-waymo-20241214-s355, study2: R6/same after stopping behind
    # it), told "the right side of the heavy truck": the truck's own side, not the AV's side it passed on.
    assert _said("csvr-waymo-20241214-s355", "the passenger side of the heavy truck",
                 "the right side of the heavy truck") == ("R6", "same")


def test_the_side_a_pass_was_made_on_is_the_pass_s_whatever_its_pronoun() -> None:
    # "an SUV that had been stopped partially in-lane behind the Waymo AV passed the Waymo AV on the left"
    # (nhtsa-sgo-ads-30270-8150-v1, study3: R6/same, it stood in the AV's lane and moved out), told "on its left":
    # the side of the pass, read as "on the left" is, not a lane the SUV was in.
    assert _said("nhtsa-sgo-ads-30270-8150-v1", "on the left", "on its left") == ("R6", "same")
    # "a heavy truck traveling southeastbound on [XXX] passed the Waymo AV on the right"
    # (nhtsa-sgo-ads-30270-10689-v1, study3, the AV northwest): the oncoming pass on the AV's right puts it in the AV's lane, told either way.
    assert _said("nhtsa-sgo-ads-30270-10689-v1", "on the right", "on its right") == \
        _said("nhtsa-sgo-ads-30270-10689-v1", "on the right", "on the right") == ("R7", "same")


def test_an_oncoming_party_directly_ahead_of_the_av_is_in_its_lane_however_ahead_is_said() -> None:
    # "an SUV that was traveling westbound on [XXX] in the middle shared turn lane, directly in front of the Waymo AV"
    # (nhtsa-sgo-ads-30270-10726-v1, study3: R7/same), told "directly ahead of the Waymo AV".
    assert _said("nhtsa-sgo-ads-30270-10726-v1", "directly in front of", "directly ahead of") == ("R7", "same")


def test_a_party_on_the_compass_side_of_the_street_opposite_the_av_s_is_across_the_street() -> None:
    # "The Waymo AV was parked at the curb facing westbound on the north side of [XXX]when a pickup truck reversed
    # out of a driveway on the south side of [XXX] into the Waymo AV" (nhtsa-sgo-ads-30270-9881-v1, study4, gold
    # R7/left): the two compass sides are opposite, so the truck came from across the street, as "across the street
    # from the Waymo AV" says (beyond the oncoming lane).
    p = _party("nhtsa-sgo-ads-30270-9881-v1")
    assert (p.position, p.lane) == ("R7", "left")
    # With the AV's own side untold, the south side of a redacted street is the left of an AV facing west.
    assert _said("nhtsa-sgo-ads-30270-9881-v1", "westbound on the north side of [XXX]", "westbound on [XXX] ") == \
        ("R5", "left")


def test_an_animal_that_ran_into_the_av_s_path_from_one_side_is_beside_its_lane_on_that_side() -> None:
    # "The Waymo AV was traveling eastbound on [XXX] at the intersection of [XXX] when a dog ran from the north side
    # of [XXX] towards the path of the Waymo AV ... the rear driver side of the Waymo AV made contact with the dog. The
    # dog then crossed behind the Waymo AV" (nhtsa-sgo-ads-30270-8612-v1, study4, gold R5/left): north is the left of
    # an eastbound AV; where the dog went after the contact is not where it was.
    sk = extract(_TEXTS["nhtsa-sgo-ads-30270-8612-v1"][1], "nhtsa-sgo-ads-30270-8612-v1")
    assert [(o.category, o.position, o.lane) for o in sk.obstacles] == [("animal", "R5", "left")]


def test_things_on_the_road_the_av_turned_onto_told_by_its_heading_are_on_the_exit_leg() -> None:
    # "As the Waymo AV made a right turn onto southwestbound {XXX], it pushed the barrier along with it and the
    # rightmost edge of the barrier made contact with the rear driver side of a postal van parked at the curb of
    # southwestbound [XXX] ... two other postal vans and two passenger cars that were also parked at the curb of
    # southwestbound [XXX]" (nhtsa-sgo-ads-30270-8152-v1, study3, gold R4/shoulder for the five): the heading the AV
    # turned to names the road of its exit leg; the vans, first named after the first contact, stood there.
    sk = extract(_TEXTS["nhtsa-sgo-ads-30270-8152-v1"][1], "nhtsa-sgo-ads-30270-8152-v1")
    assert [(o.position, o.lane) for o in sk.obstacles if o.category == "parked_vehicle"] == [("R4", "shoulder")] * 5


def test_a_barrier_that_closes_the_way_stands_in_the_av_s_lane() -> None:
    # "the front of the Waymo AV made contact with a portable metal barrier at the intersection with [XXX]"
    # (nhtsa-sgo-ads-30270-8152-v1, study3, gold R5/same): a portable barrier stands across the way, not at the curb.
    sk = extract(_TEXTS["nhtsa-sgo-ads-30270-8152-v1"][1], "nhtsa-sgo-ads-30270-8152-v1")
    assert [(o.position, o.lane) for o in sk.obstacles if o.category == "barrier"] == [("R5", "same")]


def test_a_thing_that_came_into_the_av_s_path_from_a_lane_named_on_the_road_is_placed_against_the_av_s_lane() -> None:
    # "The Waymo AV was traveling southbound on [XXX]in the center of three southbound lanes, passing a queue of
    # stopped traffic in the leftmost lane, when a domestic animal emerged from a gap between vehicles in the leftmost
    # lane and crossed the path of the Waymo AV" (nhtsa-sgo-ads-30270-9822-v1, study4, gold R5/left): the AV's lane is
    # the centre of three, the animal came from the leftmost.
    def animal(text: str) -> list[tuple[str, str, str]]:
        return [(o.category, o.position, o.lane) for o in extract(text, "nhtsa-sgo-ads-30270-9822-v1").obstacles]
    text = _TEXTS["nhtsa-sgo-ads-30270-9822-v1"][1]
    assert animal(text) == [("animal", "R5", "left")]
    # ... told "left most", the word split as some operators write it
    assert animal(text.replace("leftmost", "left most")) == [("animal", "R5", "left")]


def test_a_median_named_as_the_curb_s_modifier_is_on_the_av_s_left() -> None:
    # "the Waymo AV's front driver's side tire drove over the curb of a traffic island median" (dmvca-waymo-20201218-r146,
    # official dev gold: the barrier R5/left), told "a median curb": the modifier opens the object's words.
    sk = extract(_TEXTS["dmvca-waymo-20201218-r146"][1].replace("the curb of a traffic island median", "a median curb"),
                 "dmvca-waymo-20201218-r146")
    assert [(o.position, o.lane) for o in sk.obstacles if o.category == "barrier"] == [("R5", "left")]


def test_a_party_backing_out_of_a_space_into_the_av_s_front_stood_in_its_path() -> None:
    # "a parked SUV began reversing out of a diagonal parking stall. The rear driver side of the SUV made contact with
    # the front of the Waymo AV": the AV's front, no side of it, met the backing SUV's rear corner: it was in the
    # AV's path (R5/same), not at the curb on the right, and its "rear driver side" is a corner, no flank that faced
    # the AV (a flank met by the AV's front tells the side a party came from only for one going forward).
    p = _party("nhtsa-sgo-ads-30270-8608-v1")
    assert (p.position, p.lane, p.actions) == ("R5", "same", "k")


def test_a_party_astride_the_av_s_lane_and_the_next_is_on_the_next_lane_s_side() -> None:
    # "a passenger car traveling partially in the rightmost lane and partially in the left-adjacent dedicated left
    # turn lane approached the Waymo AV from behind. As the passenger car was passing the stopped Waymo AV, the
    # passenger side of the passenger car made contact with the rear driver side": the AV in the rightmost lane, the
    # lane the car shared with it is not its side; it passed on the left (R6/left), keeping its way (`a`).
    p = _party("nhtsa-sgo-ads-30270-9736-v1")
    assert (p.position, p.lane, p.actions) == ("R6", "left", "a")


def test_the_adjacent_lane_beside_an_av_in_the_right_lane_is_on_its_left() -> None:
    # "A May autonomous vehicle was traveling in the right lane of a two-lane road ... the May vehicle made contact
    # with the curb ... The May vehicle chose to maneuver at the curb due to perceived risk from a car in an adjacent
    # lane": the only lane beside an AV in the right lane of two is on its left; the car, told only after the
    # contact, is read at its first mention.
    p = _party("nhtsa-sgo-ads-30413-8861-v1")
    assert (p.position, p.lane) == ("R5", "left")


def test_a_numbered_lane_is_read_against_the_av_s_numbered_lane() -> None:
    # "The AV was eastbound on [XXX], approaching the intersection with [XXX], in the furthest left of five lanes
    # (lane one) ... Another vehicle, originally traveling in a middle through-traffic lane (lane three), had entered
    # lane two": lanes count from the left, so lanes two and three are on the right of the AV's lane one.
    p = _party("nhtsa-sgo-ads-669-8495-v1")
    assert (p.position, p.lane) == ("R5", "right")


def test_a_party_that_struck_the_av_again_is_placed_at_its_first_contact() -> None:
    # "... when a passenger vehicle struck the Waymo AV from behind two times. The passenger vehicle then struck the
    # Waymo AV a third time, on the left side of the Waymo AV, as it passed on the left": the conflict is the first
    # contact, told in the opening sentence; the pass after it is where the party went then (R6/same, not left).
    p = _party("csvr-waymo-20210714-s91")
    assert (p.position, p.lane, p.actions) == ("R6", "same", "a")


def test_a_party_passing_from_behind_on_no_named_side_passed_on_the_side_it_struck() -> None:
    # "a Honda Accord traveling behind the Cruise AV attempted to pass the Cruise AV and made contact with the Cruise
    # AV, damaging the rear passenger side bumper": no side of the pass named, no lane change told; the side of the
    # AV it struck is the side it passed on (sketch.md: R6 on the side it passed, `a`).
    p = _party("csvr-cruise-20220905-s189", 1)
    assert (p.position, p.lane, p.actions) == ("R6", "right", "a")


def test_a_party_that_touched_the_av_backing_up_was_ahead_or_alongside_not_behind() -> None:
    # sgo6 nhtsa-sgo-ads-30270-9285-v1 (study6 W): "an asphalt roller vehicle passed the Waymo AV multiple times. On
    # one such pass while the asphalt roller was reversing, the rear driver side of the asphalt roller vehicle made
    # contact with the rear passenger side of the stationary Waymo AV". A vehicle going the AV's way that backs into
    # it backs from ahead or alongside: R5, on the side it was read on (gold R5/right, `k`).
    p = _party("nhtsa-sgo-ads-30270-9285-v1")
    assert (p.position, p.lane, p.actions) == ("R5", "right", "k")
    # The backing told by any of its verbs reads the same: the rule reads the string, not the words.
    for verb in ("began backing up", "reversed", "rolled backward", "was reversing"):
        text = (f"The Waymo AV was stopped in traffic. A box truck in the adjacent right lane {verb} and made contact "
                "with the rear passenger side of the Waymo AV.")
        p = extract(text, "t").npcs[0]
        assert (p.position, p.lane, p.actions) == ("R5", "right", "k"), verb
    # A party behind that moves forward again before the contact stays behind ("reversed briefly and then drove
    # around EGO on the left": R6).
    text = ("The Waymo AV was stopped in a parking lot for a passenger drop off when a passenger car immediately behind "
            "the Waymo AV reversed briefly and then drove around the Waymo AV on the left. As the passenger car was "
            "passing the stopped Waymo AV, the passenger side of the passenger car made contact with the rear driver "
            "side corner of the Waymo AV.")
    assert extract(text, "t").npcs[0].position == "R6"
