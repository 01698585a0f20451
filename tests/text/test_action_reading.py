"""Issue 13, the EVENTS slot: narratives -> action strings, one test per reading mechanism of `actions.py` and
`sequences.py` (the narratives are written for these tests, in the reports' styles; none is a gold or held-out text).
"""

from __future__ import annotations

import pytest

from txt2sce_ros.text.extractor import extract


def _party(text: str, k: int = 0) -> tuple[str, str]:
    sk = extract(text, "t")
    return sk.npcs[k].start, sk.npcs[k].actions


def _ego(text: str) -> tuple[str, str]:
    sk = extract(text, "t")
    return sk.ego.start, sk.ego.actions


def test_participle_right_after_a_noun_is_that_noun_s_move() -> None:
    # "seeing the oncoming car crossing the centerline": the car crossed, not the driver who saw it.
    text = ("A Cruise autonomous vehicle was traveling northbound on Valencia Street. The driver of the Cruise AV, "
            "seeing the oncoming car crossing the centerline, brought the Cruise AV to a stop. The oncoming car "
            "made contact with the front driver side of the Cruise AV.")
    assert _ego(text) == ("moving", "ah")
    assert _party(text) == ("moving", "af")


def test_relative_clause_after_a_make_and_model_is_the_party_s() -> None:
    text = ("The Waymo AV was traveling southbound on Hyde Street when it was struck by a 2015 Subaru Forester that "
            "crossed the double yellow line while driving northbound on Hyde Street.")
    assert _ego(text)[1] == "a"  # the AV kept its lane
    assert "f" in _party(text)[1]  # the Forester crossed into it


def test_reverse_lights_are_not_reversing_and_accelerating_in_reverse_is_backing() -> None:
    text = ("The Pony AV was stopped at a red light. The safety driver saw that the reverse lights of the vehicle "
            "directly in front of the Pony AV were on. Vehicle 2 accelerated while still in reverse toward the Pony "
            "AV and made contact with its front bumper.")
    assert _ego(text) == ("stopped", "")
    assert _party(text) == ("stopped", "k")


def test_a_turn_begun_without_a_side_takes_the_side_announced_before() -> None:
    text = ("The Waymo AV was traveling southbound on Folsom Street when it began to slow for a motorcyclist "
            "traveling on northbound Folsom Street signaling to make an unprotected left turn onto 24th Street. "
            "The motorcyclist attempted to turn behind the Waymo AV and made contact with its left rear corner.")
    assert _party(text)[1].endswith("d")
    # Without an announced side, an unnamed turn adds no letter.
    plain = text.replace("signaling to make an unprotected left turn onto 24th Street", "approaching")
    assert "d" not in _party(plain)[1] and "e" not in _party(plain)[1]


def test_entering_traffic_from_a_parked_position_starts_from_a_standstill() -> None:
    text = ("The Cruise AV was traveling westbound on Oak Street in the right lane when a sedan, entering traffic "
            "from a curbside parked position, made contact with the right side of the Cruise AV.")
    start, acts = _party(text)
    assert start == "stopped" and acts.startswith("i") and acts[1:2] in ("f", "g")


@pytest.mark.parametrize("verb, crosses", [("entered the crosswalk from the east sidewalk", True),
                                           ("entered the crosswalk", False)])
def test_entering_a_crosswalk_from_the_sidewalk_is_crossing(verb: str, crosses: bool) -> None:
    # A rider already travelling along (a sidewalk, a bike path) who goes on into the crosswalk is not crossing the
    # AV's path from the side; one entering it from the sidewalk is.
    text = (f"The Cruise AV was traveling northbound on Sanchez Street when a skateboarder {verb} and made contact "
            f"with the front right fender of the Cruise AV.")
    assert ("m" in _party(text)[1]) is crosses


def test_reversing_into_a_parking_space_ends_at_the_backing() -> None:
    # The parking would have come after the contact: the string ends at contact (sketch.md).
    text = ("The Waymo AV was slowly approaching stopped traffic when a vehicle in the right adjacent lane started "
            "reversing into a parallel parking space. The front left bumper of the vehicle scraped the right side "
            "of the Waymo AV.")
    assert _party(text)[1] == "k"
    ego = ("While the driver of the Cruise AV attempted to reverse into a parallel parking spot, the driver made "
           "contact with another parked vehicle's front bumper.")
    assert _ego(ego)[1] == "k"


def test_a_lane_entered_right_after_a_turn_is_where_the_turn_ends() -> None:
    text = ("The Zoox vehicle was stopped at a red light on westbound Flamingo Road. When the light turned green, the "
            "Zoox vehicle began to proceed straight. A pickup truck approaching from the Zoox vehicle's right made a "
            "right turn onto westbound Flamingo Road and entered the right lane, and its left side made contact with "
            "the front right corner of the Zoox vehicle.")
    assert _party(text)[1].endswith("e")
    cut = ("The Zoox vehicle was proceeding southbound in the right lane of Fourth Street. A box truck in the left "
           "adjacent lane abruptly turned right and cut in front of the Zoox vehicle, making contact with its left "
           "front sensor.")
    assert _party(cut)[1].endswith("e")


def test_entering_the_adjacent_lane_is_a_lane_change() -> None:
    text = ("The Waymo AV was traveling north in the rightmost of two lanes on Polk Street when it partially entered "
            "the left adjacent lane to make room for a cyclist. A box truck behind in the left adjacent lane proceeded "
            "forward and made contact with the rear driver side of the Waymo AV.")
    assert _ego(text) == ("moving", "af")


def test_back_into_the_driving_lane_from_a_pull_over_is_a_pull_out() -> None:
    text = ("The Waymo AV was stopped at the curb of 24th Street after a pull-over, when the test driver took manual "
            "control and proceeded into the driving lane. The Waymo AV then made contact with a sedan passing it on "
            "the left side.")
    assert _ego(text) == ("stopped", "if")


def test_a_parking_maneuver_is_pulling_over() -> None:
    text = "A Woven Planet vehicle in manual mode contacted the curb while making a parking maneuver on Fell Street."
    assert _ego(text)[1] == "l"


def test_every_object_joined_to_the_struck_one_is_struck() -> None:
    text = ("After turning right onto Mission Blvd, the Pony.ai AV performed a left lane change. While performing the "
            "lane change, the Pony.ai AV came into contact with a center divider on Mission Blvd. and the traffic "
            "sign that was posted on the divider.")
    sk = extract(text, "t")
    assert [o.category for o in sk.obstacles] == ["barrier", "pole"]


def test_a_quoted_name_given_to_the_av_is_the_av() -> None:
    text = ("A Toyota Research Institute vehicle (the 'TRI Vehicle\") was travelling in the #1 lane of I-80. A "
            "sedan changed lanes into the #1 lane, where it struck the TRI Vehicle. The TRI Vehicle then struck the "
            "center barrier.")
    sk = extract(text, "t")
    assert len(sk.npcs) == 1 and sk.npcs[0].category == "car"
    assert any(o.category == "barrier" for o in sk.obstacles)  # the AV's own contact, not the sedan's


def test_both_vehicles_moving_off_is_the_av_s_move_too() -> None:
    text = ("A Zoox vehicle was stopped for a red light on northbound Van Ness Avenue. A passenger car was stopped in "
            "the adjacent lane to the right of the Zoox vehicle. As the signal turned green, both vehicles proceeded "
            "forward and shortly after that the car suddenly veered left into the Zoox vehicle's lane. The car made "
            "contact with the passenger side fender of the Zoox vehicle.")
    assert _ego(text) == ("stopped", "i")


def test_begin_to_inside_a_purpose_is_an_intention() -> None:
    text = ("The AV was moving at 9 mph in the right lane and slowing to begin to execute a right turn, when a sedan "
            "side-swiped the AV while overtaking from the left adjacent lane.")
    assert _ego(text) == ("moving", "ac")


def test_a_numbered_group_is_that_many_parties() -> None:
    text = ("A Cruise AV was traveling northbound on 36th Avenue. While proceeding straight, the driver of the Cruise "
            "AV made contact with two unoccupied vehicles parked on the other side of 36th Avenue.")
    sk = extract(text, "t")
    assert [o.category for o in sk.obstacles] == ["parked_vehicle", "parked_vehicle"]
    assert sk.collision.with_ == "obs1"
    riders = ("The May Mobility shuttle was driving northbound in autonomous mode and was followed by 2 people riding "
              "on scooters. The scooter rider contacted the rear bumper of the May Mobility shuttle.")
    assert [n.category for n in extract(riders, "t").npcs] == ["scooter", "scooter"]
    # Unnumbered, or the AV and the party together, a group names no party.
    assert not extract("The AV was traveling north when both vehicles stopped. The AV struck a pole.", "t").npcs


def test_the_driver_of_a_party_named_by_its_vehicle_acts_for_it() -> None:
    text = ("A Zoox vehicle was traveling west and turning right onto Main Street. As the Zoox vehicle was slowing, the "
            "motorcycle operator accelerated in an apparent attempt to overtake the Zoox vehicle. The motorcycle then "
            "struck the driver's side rear bumper of the Zoox vehicle.")
    assert "b" in _party(text)[1]  # the motorcycle sped up ...
    assert "b" not in _ego(text)[1]  # ... not the AV


def test_an_av_slowing_in_a_turn_it_was_making_starts_with_the_turn() -> None:
    text = ("A Zoox vehicle in autonomy was traveling west on Main Street and turning right onto 5th Street. While "
            "executing a low-speed turn, the Zoox vehicle braked. As the Zoox vehicle was slowing, a motorcycle "
            "struck the rear bumper of the Zoox vehicle.")
    assert _ego(text) == ("moving", "ec")
    straight = text.replace(" and turning right onto 5th Street", "").replace("executing a low-speed turn", "in traffic")
    assert _ego(straight) == ("moving", "ac")


@pytest.mark.parametrize("state, as_party", [("was stopped", True), ("was parked", False)])
def test_a_vehicle_stopped_in_the_lane_that_the_av_went_around_is_a_party(state: str, as_party: bool) -> None:
    # sketch.md: a vehicle stopped in traffic is an NPC; a parked, unattended one an obstacle.
    text = (f"The Cruise AV was traveling southbound in the right lane of Divisadero Street. The Cruise AV approached "
            f"a box truck that {state} in the right lane. The Cruise AV began to navigate around the box truck. "
            f"Shortly thereafter, a sedan attempted to pass the Cruise AV on the left and made contact with its front "
            f"left fender.")
    sk = extract(text, "t")
    trucks = [n for n in sk.npcs if n.category == "truck"]
    assert bool(trucks) is as_party
    if as_party:
        assert (trucks[0].start, trucks[0].actions) == ("stopped", "")
    else:
        assert [o.category for o in sk.obstacles] == ["parked_vehicle"]


def test_swerving_into_the_av_s_door_is_a_contact_but_into_its_lane_is_not() -> None:
    text = ("The test driver of the Waymo AV pulled over to the right shoulder of Silver Avenue. A moment later, a "
            "passenger vehicle turned right onto Silver Avenue and swerved into the driver door of the Waymo AV.")
    sk = extract(text, "t")
    assert sk.collision.with_ == "npc1"
    lane = text.replace("the driver door of the Waymo AV", "the Waymo AV's lane")
    assert extract(lane, "t").collision.with_ is None


@pytest.mark.parametrize(("text", "want"), [
    # A turn in progress when the story takes the party up: the string opens with it, no run along the lane before.
    ("The AV was driving west on Folsom Street toward 7th Street. A sedan ahead of it in the same lane was making "
     "a left turn onto 7th Street when it stopped for a cyclist, and the AV's front bumper touched its rear.",
     ("moving", "dh")),
    # A participle right after the party: merging was what it was doing.
    ("Our autonomous vehicle was traveling in the right lane of northbound Interstate 680. A cement truck merging "
     "onto the freeway from the on-ramp on our right moved into our lane and scraped our passenger side.",
     ("moving", "f")),
    # Told travelling first in a sentence of its own, then turning: a run along the lane, then the turn.
    ("The AV was traveling south on Market Street. A sedan was driving ahead of the AV in the same lane. As the AV "
     "approached Valencia Street, the sedan turned right and stopped for a pedestrian, and the AV struck its rear.",
     ("moving", "aeh")),
])
def test_a_manoeuvre_told_in_progress_opens_the_string(text: str, want: tuple[str, str]) -> None:
    assert _party(text) == want


def test_a_move_the_av_was_made_to_make_is_the_av_s() -> None:
    # "forcing the AV to steer to the left": an event, not an intention, and the AV's (the object of "forcing").
    text = ("The AV was traveling east on Alameda Street in the middle lane. A pickup in the lane to the right of the "
            "AV swerved toward a pile of cones, forcing the AV to veer to the left, and the pickup's mirror touched "
            "the AV's right side.")
    assert _ego(text) == ("moving", "af")
    text = ("While the AV was driving on Lincoln Avenue, a ball rolling into the street caused the AV to brake hard. "
            "A hatchback behind the AV then rear-ended it.")
    assert _ego(text) == ("moving", "ac")


def test_a_repeated_contact_ends_the_string_at_the_first() -> None:
    text = ("The AV was stopped at a red light on northbound Broadway. A grey SUV pulled up behind the AV, stopped, "
            "then crept forward and bumped the rear of the AV. Its driver backed up and bumped the AV again.")
    assert _party(text) == ("moving", "ahi")


@pytest.mark.parametrize(("text", "want"), [
    ("The AV was driving south on Ocean Avenue in the left lane. A coupe in the right lane changed into the AV's "
     "lane a few feet ahead and the AV's front bumper struck the coupe.", "af"),
    ("The AV was traveling east on Central Expressway in the center lane. A pickup truck in the left lane moved "
     "over into the center lane directly in front of the AV, and the AV's front made contact with its rear bumper.",
     "ag"),
])
def test_a_move_into_the_lane_ahead_of_the_av_is_a_lane_change(text: str, want: str) -> None:
    assert _party(text)[1] == want


def test_a_party_named_by_its_manoeuvre_did_it() -> None:
    # "yielded to a parallel parking vehicle": "to a" is an object, not an infinitive of intention.
    text = ("The AV was traveling north on Guerrero Street when it yielded to a parallel parking sedan ahead on the "
            "right. The sedan's rear bumper then touched the AV's front right corner.")
    assert _party(text) == ("moving", "l")
    # "a lane-splitting motorcyclist": travelling between the lanes before the lane change.
    text = ("The AV was stopped in traffic on Interstate 80. A lane-splitting motorcyclist attempting to change "
            "lanes made contact with the AV's left mirror.")
    assert _party(text)[1][:1] == "a"


def test_the_party_named_again_by_its_move_makes_no_new_move() -> None:
    # "due to the encroaching van": a party named again by what it did, travelling along its lane (R7).
    text = ("The AV was traveling west on Clay Street. A van was traveling east on Clay Street partly in the AV's "
            "lane. The AV stopped due to the encroaching van, and the van made contact with the AV's left side.")
    assert _party(text) == ("moving", "a")


def test_a_slow_moving_truck_is_not_slowing() -> None:
    text = ("The AV was traveling north in the right lane of Interstate 280 when it approached a slow-moving heavy "
            "truck ahead in the same lane. The AV changed lanes to the left, and a sedan passing in the left lane "
            "made contact with the AV's front left.")
    sk = extract(text, "t")
    assert [(n.category, n.actions) for n in sk.npcs] == [("truck", "a"), ("car", "a")]


def test_debris_thrown_onto_the_av_is_an_obstacle_it_touched() -> None:
    text = ("The AV was traveling west on Highway 92 when a gravel truck ahead of it in the same lane launched "
            "a rock onto the AV, chipping its windshield.")
    sk = extract(text, "t")
    assert [o.category for o in sk.obstacles] == ["debris"]
    # (a thing thrown at the AV is no object the AV hit: the form's "other", as the studyable gold of
    # dmvca-apple-20221220-r411 and nhtsa-sgo-ads-30530-6125-v1 gives it; tests/text/test_who_counts.py)
    assert sk.collision.with_ == "obs1" and sk.collision.type == "other"


@pytest.mark.parametrize(("text", "want"), [
    # Stopped, then itself struck an object standing still: it moved off first.
    ("The AV stopped on Mission Street behind a delivery truck that was double-parked in its lane. A minute "
     "later the AV side-swiped the delivery truck.", ("moving", "ahi")),
    # A stop and a start told before the object comes in are part of the story that ends at it.
    ("While turning right from 9th Avenue onto Irving Street, the AV slowed to a stop for a pedestrian. As the AV "
     "began to move forward, the test driver took over and drove forward, making contact with a parked sedan.",
     ("moving", "ehi")),
    # "entered the intersection" after a stop moves the AV off; a lane change after a stop too.
    ("The AV was traveling south on Gough Street. As it approached Geary Boulevard, a bus ahead of it turned "
     "right. The AV came to a stop at the crosswalk. The AV then entered the intersection but came to a stop again "
     "as the bus began backing up, and the bus's rear touched the AV's front.", ("moving", "ahih")),
    ("The AV was traveling in the right lane of El Camino Real and stopped behind a stalled car. The AV then "
     "changed lanes to the left, and a pickup traveling behind in the left lane struck the AV's left rear.",
     ("moving", "ahif")),
])
def test_a_stop_then_a_move_off_before_the_contact(text: str, want: tuple[str, str]) -> None:
    assert _ego(text) == want


def test_a_vehicle_stopped_in_the_lane_is_its_state_not_the_av_s_stop() -> None:
    text = ("While traveling north on Valencia Street, the AV went around a delivery van stopped in the right lane. "
            "After re-entering the right lane, the AV came to a stop behind a sedan, which then reversed into it.")
    assert _ego(text) == ("moving", "afgh")


def test_what_a_sign_says_traffic_should_do_is_no_one_s_move() -> None:
    # "indicating that traffic should merge to the left": a modal is no event; then the AV slowed, stopped and moved
    # off into its lane change.
    text = ("The AV was traveling in the right lane of Interstate 5 when it approached a work truck with an arrow "
            "board indicating that traffic should merge to the left. The AV slowed down behind the work truck and "
            "stopped. The AV then began a lane change to the left, and a sedan passing on the left struck its front "
            "left corner.")
    assert _ego(text) == ("moving", "ahif")


def test_an_unnumbered_group_s_move_is_no_party_s() -> None:
    text = ("The AV was stopped in the right lane of Market Street behind a stalled bus. Several cars passed the AV "
            "on the left. The AV then changed lanes to the left and a cyclist riding in the left lane struck the AV's "
            "left mirror.")
    assert _ego(text) == ("stopped", "if")


@pytest.mark.parametrize(("text", "want"), [
    ("The AV moved off on a green light from the left lane of southbound Mission Street. A sedan in the lane to its "
     "right partly entered the left lane ahead of the AV and the AV's front bumper touched the sedan.",
     ("stopped", "i")),
    # A stop at a light before the party comes in is where the AV waited: it starts stopped.
    ("The AV was traveling north on Rengstorff Avenue and stopped at a red light at Middlefield Road. When the light "
     "turned green, the AV turned left, and an oncoming pickup truck struck its right side.", ("stopped", "id")),
])
def test_moving_off_from_where_the_av_stood(text: str, want: tuple[str, str]) -> None:
    assert _ego(text) == want


@pytest.mark.parametrize(("text", "category"), [
    ("The AV was traveling south on Page Mill Road when a rabbit darted into the road and the AV's front bumper "
     "struck it.", "animal"),
    ("The AV was driving in the right lane of US-101 and ran over a tire tread lying in its lane.", "debris"),
    # A make before a street word after a preposition of place is a street ("on Lincoln Way"), not a party.
    ("While traveling east on Lincoln Way, the AV struck a fallen tree limb that was lying across its lane.", "other"),
])
def test_an_object_the_av_struck_is_its_only_counterpart(text: str, category: str) -> None:
    sk = extract(text, "t")
    assert not sk.npcs
    assert [o.category for o in sk.obstacles] == [category]
    assert sk.collision.with_ == "obs1"


def test_a_party_slowing_when_the_story_takes_it_up_opens_with_c() -> None:
    text = ("The AV was stopped in the left turn lane of eastbound Tropicana Avenue, waiting to turn left. A pickup "
            "approaching from the right of the AV was slowing with its turn signal on. The AV began its left turn "
            "and the pickup continued straight, and the AV's front struck the pickup's left side.")
    assert _party(text)[1].startswith("c")


def test_numbered_parties_are_told_apart() -> None:
    text = ("The AV was traveling south on Potrero Avenue and braked for Cyclist 1 and Cyclist 2 in the bike lane "
            "ahead. Cyclist 3, riding behind the AV, swerved left around a car door. Cyclist 3 then made contact "
            "with the right rear bumper of the AV.")
    sk = extract(text, "t")
    assert [n.category for n in sk.npcs] == ["bicycle"] * 3
    assert sk.collision.with_ == "npc3"


@pytest.mark.parametrize(("text", "want"), [
    # Into a turn lane is a move to its side, here told in progress: the string opens with it.
    ("The AV was entering the left turn lane of westbound Camelback Road when its front struck a piece of "
     "debris lying in the lane.", ("moving", "f")),
    # Waited at a light, moved off, then stopped again before the party struck it: it starts stopped.
    ("The AV was stopped at a red light on eastbound Main Street. When the light turned green, the AV proceeded "
     "through the intersection, and as it was slowing to a stop beyond it, a pickup truck following it struck "
     "its rear bumper.", ("stopped", "ih")),
])
def test_a_turn_lane_entered_and_a_start_from_where_it_waited(text: str, want: tuple[str, str]) -> None:
    assert _ego(text) == want


@pytest.mark.parametrize(("text", "want"), [
    # A sideways move told without "changed lanes": its side from the words, else from where the party was.
    ("The Waymo AV was traveling in the left lane of Market Street. A sedan in the right lane shifted over toward "
     "the left lane and struck the passenger side of the Waymo AV.", ("moving", "af")),
    ("The Zoox vehicle was stopped at a red light. A delivery truck stopped to our right inched left as the light "
     "turned green and touched the Zoox vehicle's front passenger side.", ("stopped", "if")),
    ("Our vehicle was traveling in the center lane when a sedan in the lane to our left moved toward our lane and "
     "made contact with our driver side mirror.", ("moving", "ag")),
    # A clause set off by commas is an aside: the verb after it is the subject's before it.
    ("The Cruise AV was stopped at a red light on Post Street. A cyclist in the bike lane to the right of the AV, "
     "while the AV waited for pedestrians to clear, moved left and struck the AV's right mirror.", ("moving", "af")),
    # Out of a driveway into the AV's lane is the crossing itself, not a lane change after it.
    ("The AV was traveling north on Pine Street when a pickup truck leaving a driveway on the right crossed into "
     "the AV's lane and struck its front bumper.", ("moving", "m")),
])
def test_sideways_moves_without_a_lane_change_word(text: str, want: tuple[str, str]) -> None:
    assert _party(text) == want


@pytest.mark.parametrize(("text", "want"), [
    # A state told by a participle or a verb of breaking down: it stood when the story took it up.
    ("The Zoox vehicle was traveling on Howard Street when a delivery van stalled in the lane ahead. The Zoox "
     "vehicle slowed and its front bumper touched the rear of the van.", ("stopped", "")),
    ("The Cruise AV was traveling in the right lane of Geary Boulevard when a sedan parked at the curb ahead pulled "
     "into the lane in front of it and the Cruise AV struck its rear bumper.", ("stopped", "if")),
    # Out of the roadway's edge in front of the AV: a crossing, from a standstill.
    ("The Waymo AV was traveling south on Valencia Street when a scooter rider who had been stopped on the sidewalk "
     "entered the roadway from the right curb directly in front of the Waymo AV.", ("stopped", "im")),
])
def test_a_state_told_by_a_participle(text: str, want: tuple[str, str]) -> None:
    assert _party(text) == want


def test_a_move_told_in_the_pluperfect_is_the_avs() -> None:
    text = ("The Waymo AV was stopped behind a box truck on Folsom Street. The truck backed up, and the Waymo AV, "
            "which had begun to move forward, made contact with the rear of the truck.")
    assert _ego(text) == ("stopped", "i")


@pytest.mark.parametrize(("text", "want"), [
    # Straying into the AV's lane during a turn is a move of its own; ending a turn in front of the AV is not.
    ("The Zoox vehicle was turning right from Folsom Street onto 2nd Street. A sedan in the lane to its right also "
     "turned right and drifted into the Zoox vehicle's lane during the turn, striking its passenger side.",
     ("moving", "aef")),
    # "Pulled out": out of a parking spot when it was parked, a start from where it stood otherwise.
    ("The Cruise AV was traveling in the left lane of Bush Street when a sedan that had been parked along the right "
     "curb pulled out and struck the Cruise AV's passenger side.", ("stopped", "if")),
    ("The Cruise AV was traveling in the left lane of Bush Street when a sedan that had been stopped in the right "
     "lane pulled out and struck the Cruise AV's passenger side.", ("stopped", "i")),
])
def test_a_turn_strayed_from_and_pulling_out(text: str, want: tuple[str, str]) -> None:
    assert _party(text) == want


def test_a_relative_clause_after_a_possessed_place_is_the_party_s() -> None:
    # "... in the lane to the AV's right, which was attempting to merge left": the vehicle merged, not the AV.
    text = ("A Cruise AV traveling westbound on Eddy Street was struck on the right rear quarter panel by a vehicle "
            "traveling westbound in the lane to the Cruise AV's right, which was attempting to merge left.")
    assert _ego(text) == ("moving", "a")
    assert _party(text) == ("moving", "af")


@pytest.mark.parametrize("move, code", [("drifted over the lane line", "g"),
                                        ("swung out into the oncoming lane", "f")])
def test_a_sideways_move_told_without_lane_change_words(move: str, code: str) -> None:
    # Over the line between two lanes, or out into the opposing lane: a lane change, its side from where it went.
    text = (f"A Zoox vehicle was traveling eastbound on Tropicana Avenue in the middle lane. A sedan traveling "
            f"eastbound in the lane to the left of the Zoox vehicle {move} and made contact with the Zoox vehicle.")
    assert _party(text)[1].endswith(code)


@pytest.mark.parametrize("move", ["switched lanes", "entered the Zoox vehicle's lane", "cut off the Zoox vehicle",
                                  "crossed the lane line into the Zoox vehicle's lane",
                                  "began to encroach into the Zoox vehicle's lane", "changed lanes"])
def test_a_lane_change_however_told_keeps_the_party_in_its_lane(move: str) -> None:
    # The move into the AV's lane from the right is to the left; "in the right lane changed lanes" keeps its lane
    # cue (a verb "changed" after "right lane" is no "right lane change").
    text = (f"A Zoox vehicle was traveling northbound on Koval Lane in the left lane. A sedan traveling northbound in "
            f"the right lane {move} and made contact with the Zoox vehicle.")
    p = extract(text, "t").npcs[0]
    assert (p.position, p.lane, p.actions) == ("R5", "right", "af")


def test_a_turn_told_as_making_one_is_under_way_when_the_av_slows_in_it() -> None:
    text = ("A Zoox vehicle was traveling west on Main Street and making a right turn onto 1st Street. While "
            "executing the turn, the Zoox vehicle braked. A motorcycle then struck the rear bumper of the Zoox "
            "vehicle.")
    assert _ego(text) == ("moving", "ec")


def test_a_participle_after_a_short_phrase_of_means_is_the_party_s() -> None:
    # "bumped a person on foot crossing the street": the person crossed, not the operator who bumped them.
    text = ("The Nuro vehicle was stopped at a stop sign on Webster Street. When reversing, the operator bumped a "
            "person on foot crossing the street behind the Nuro vehicle.")
    assert _ego(text) == ("stopped", "k")
    assert _party(text) == ("moving", "m")


@pytest.mark.parametrize("stop", ["halted", "was brought to a stop", "made a sudden stop", "came to rest",
                                  "pulled to a stop"])
def test_a_stop_however_told(stop: str) -> None:
    text = (f"A Zoox vehicle was traveling northbound on Koval Lane. The Zoox vehicle {stop} for a pedestrian and a "
            f"sedan traveling behind it struck its rear bumper.")
    assert _ego(text) == ("moving", "ah")


@pytest.mark.parametrize("start", ["pulled away from the stop line", "resumed travel"])
def test_a_start_however_told(start: str) -> None:
    # "pulled away from the stop line" moves off from a stop, it leaves no parking space.
    text = (f"A Zoox vehicle was stopped at a red light on Koval Lane. When the light turned green, the Zoox vehicle "
            f"{start} and a sedan traveling behind it struck its rear bumper.")
    assert _ego(text) == ("stopped", "i")


def test_travel_as_a_noun_is_no_run_along_the_lane() -> None:
    # "stopped in its lane of travel": "travel" names the lane, it tells no movement (a run `a` after a standstill
    # would be read as moving off). 21 of the 379 studyable reports say "lane/direction/path of travel".
    text = ("The Waymo AV was stopped in its lane of travel on Main Street when a cyclist made contact with its front "
            "bumper.")
    assert _ego(text) == ("stopped", "")
