"""Issue 13, the AV's own start and action string, read from real NHTSA SGO narratives the rules were not written
from (tests/text/sgo/study3.jsonl, session 14; each row's `source` beside its text). One test per reading; each
asserts the reading sketch.md's rules and the official gold's conventions give, and fails if the rule is removed.
"""

from __future__ import annotations

from txt2sce_ros.text.extractor import extract

from .quoted import QUOTED
from .quoted import quoted_ego as _ego

_SGO = QUOTED  # report id -> (source, narrative): tests/text/quoted.py


def test_a_stop_told_under_way_opens_the_string() -> None:
    # "The Nuro Prius was coming to a stop as the traffic signal changed": the stop was under way when the
    # interaction began (`h`, not `ah`).
    assert _ego("nhtsa-sgo-ads-30291-7677-v1") == ("moving", "h")
    # So after a run told in the same sentence: "was traveling southbound on a narrow portion of [XXX] and was
    # slowing to a stop for a passenger drop-off when a passenger car ... began passing" (`h`).
    assert _ego("nhtsa-sgo-ads-30270-10649-v1") == ("moving", "h")


def test_a_participle_after_traffic_is_the_traffic_s_move() -> None:
    # "came to a stop to gain visibility of oncoming traffic traveling southbound": the travelling is the traffic's,
    # not the AV's; the AV moved off from the red and stopped again (`ih`).
    assert _ego("nhtsa-sgo-ads-30270-10598-v1") == ("stopped", "ih")


def test_slowed_down_to_a_stop_is_a_stop() -> None:
    # "was traveling on northbound [XXX] and slowed down to a stop for a queue of traffic": a run, then the stop
    # (`ah`), as "slowed to a stop" is.
    assert _ego("nhtsa-sgo-ads-30270-9486-v1") == ("moving", "ah")


def test_a_lane_change_told_again_without_its_side_is_the_one_told() -> None:
    # "began a lane change into the right thru lane where there was a gap in a slow-moving traffic stack. The
    # passenger car ... accelerated as the Waymo AV began merging": "slow-moving" is the traffic stack's adjective
    # (no run of the AV's after the lane change), and "began merging" is the lane change to the right told again
    # (`ag`, not `af`).
    assert _ego("nhtsa-sgo-ads-30270-8130-v1") == ("moving", "ag")


def test_a_turn_named_by_a_longer_noun_phrase_after_an_intention_is_a_plan() -> None:
    # "was stopped facing north at a red light ... preparing to make an unprotected left turn onto [XXX]": the turn
    # is planned, not made; the AV stood throughout (the article and modifiers of "an unprotected left turn" do not
    # put it out of the intention's reach).
    assert _ego("nhtsa-sgo-ads-30270-10668-v1") == ("stopped", "")


def test_an_e_stop_is_a_stop() -> None:
    # "the shuttle entered the intersection ... The shuttle experienced an unknown e-stop. The vehicle behind the
    # shuttle ... hit the rear left corner of the shuttle": a run, then the (emergency) stop (`ah`).
    assert _ego("nhtsa-sgo-ads-30310-3698-v1") == ("moving", "ah")


def test_following_an_event_is_after_it() -> None:
    # "was parked at the curb facing west following a passenger drop-off ... While the Waymo AV remained
    # stationary": "following" tells when, not a vehicle followed; the parked AV stood throughout.
    assert _ego("nhtsa-sgo-ads-30270-10666-v1") == ("stopped", "")


def test_accelerating_after_a_slowing_is_a_speed_up() -> None:
    # Stopped at a red light, then "initiated a right turn ... The Waymo AV slowed to yield to the U-turning
    # passenger car and had begun to accelerate again to complete the right turn when" it was struck: moving off,
    # the turn, the slowing, then the speed-up (`iecb`), not a second start.
    assert _ego("nhtsa-sgo-ads-30270-7734-v1") == ("stopped", "iecb")


def test_a_turn_lane_named_before_onto_is_no_turn() -> None:
    # "came to a stop for a red traffic light in the dedicated left turn lane, preparing to make a left turn onto
    # northbound [XXX]": "turn" of "left turn lane" is the lane's name, not a turn onto the road named after it (the
    # turn itself is a plan); rear-ended there after the stop told as an event of its run (`ah`, not `dh`).
    assert "d" not in _ego("nhtsa-sgo-ads-30270-9371-v1")[1]


def test_the_part_of_the_stationary_av_is_the_avs_part() -> None:
    # "made contact with the rear passenger side of the stationary Waymo AV": the part of "the stationary EGO" is
    # the AV's part as much as that of "EGO" (33 of the studyable narratives write "of the stationary Waymo AV", 6
    # "of the stopped", 2 "of the parked"); here it tells the AV was struck from behind, so its stop is told (`ah`).
    from txt2sce_ros.text import story

    sk = extract(_SGO["nhtsa-sgo-ads-30270-9371-v1"][1], "nhtsa-sgo-ads-30270-9371-v1")
    assert (sk.ego.start, sk.ego.actions) == ("moving", "ah")
    assert story._ego_parts("A car made contact with the rear of the stationary EGO.")[0].split()[-1] == "rear"


def test_began_to_pass_is_a_start_after_a_stop() -> None:
    # "stopped at the intersection ... to yield to a box truck ... The truck stopped and the Waymo AV began to pass
    # the truck on the left. ... the Waymo AV came to a stop to yield to the truck": moving off past it after the
    # stop, then the second stop (`ahih`).
    assert _ego("nhtsa-sgo-ads-30270-10673-v1") == ("moving", "ahih")


def test_began_to_proceed_around_is_the_going_around() -> None:
    # "came to a stop behind a box truck that was stopped in-lane. The Waymo AV began to proceed around the left of
    # the stopped box truck and came to a stop": the move around it to the left after the stop (`ahifh`), not only a
    # start.
    assert _ego("nhtsa-sgo-ads-30270-10757-v1") == ("moving", "ahifh")


def test_a_pull_over_told_in_the_pluperfect_is_where_the_av_stood() -> None:
    # "The Waymo AV had pulled up to the curb facing northbound on [XXX] for a requested passenger pickup. While
    # awaiting the passenger, ... a passenger car began reversing out of the garage": the pull-over was done before
    # the story (as "had come to a stop" is); the AV stood throughout (`stopped`, empty), not `l`.
    assert _ego("nhtsa-sgo-ads-30270-9540-v1") == ("stopped", "")


def test_proceeding_to_after_before_is_still_a_plan() -> None:
    # "waiting for eastbound traffic to clear before proceeding to merge right onto [XXX]": the merge is what the AV
    # waited to do ("proceeding to" after "before" is no manoeuvre made, as "to begin to" is not); it moved forward
    # and stopped, with no lane change to the right (gold `ih`).
    assert "g" not in _ego("nhtsa-sgo-ads-30270-10639-v1")[1]


def test_an_opening_clause_of_standing_still_tells_of_the_av_when_the_narrative_opens_with_it() -> None:
    # "While in traffic and stopped at 0mph in autonomy, a motorized scooter riding between the 2 lanes of traffic
    # clipped the May Mobility vehicle's mirror": the subjectless clause tells of the AV the report is about (as
    # "While stopped, ..." later in a narrative does), not of the scooter named after it.
    assert _ego("nhtsa-sgo-ads-30413-7880-v1") == ("stopped", "")
    sk = extract(_SGO["nhtsa-sgo-ads-30413-7880-v1"][1], "nhtsa-sgo-ads-30413-7880-v1")
    assert (sk.npcs[0].start, sk.npcs[0].actions) == ("moving", "a")


def test_a_contact_a_third_time_is_a_repeat_after_the_conflict() -> None:
    # "... the front of the SUV made contact with the front of the Waymo AV. The Waymo AV then reversed and the SUV
    # proceeded forward to make contact with the front of the Waymo AV a second time. ... the front of the SUV made
    # contact with the front of the Waymo AV a third time": the conflict ends at the first contact (sketch.md), so
    # the AV's reversing after it is no part of its string.
    assert "k" not in _ego("nhtsa-sgo-ads-30270-10756-v1")[1]


def test_a_move_into_the_avs_own_lane_is_not_the_avs() -> None:
    # "The Waymo AV was traveling northbound ... in the middle lane when the left front wheel from an SUV traveling in
    # the right most lane ... separated from the SUV and rolled into the Waymo AV's lane of travel": the AV does not
    # move into its own lane; it kept to it (`a`, not `af`).
    assert _ego("nhtsa-sgo-ads-30270-10674-v1") == ("moving", "a")


def test_reversing_to_exit_a_space_is_the_backing_out() -> None:
    # "The Waymo AV was parked facing south in a parking stall ... The Waymo AV proceeded to reverse to exit the
    # parking stall, and came to a stop to yield to an SUV": out of the stall in reverse is the backing itself, then
    # the stop (`kh`), not a pull-out forward into a lane (`if`).
    assert _ego("nhtsa-sgo-ads-30270-10640-v1") == ("stopped", "kh")


def test_returning_to_the_left_lane_is_a_lane_change_to_the_left() -> None:
    # "The Waymo AV began changing lanes into the right lane, which is a dedicated bus lane ... and the Waymo AV
    # started to return to the left lane behind the pickup truck. The pickup truck came to a stop, and the Waymo AV
    # also came to a stop": out to the right, back to the left, then the stop (`agfh`).
    assert _ego("nhtsa-sgo-ads-30270-7724-v1") == ("moving", "agfh")


def test_entering_the_leftmost_lane_is_a_lane_change_to_the_left() -> None:
    # "The Waymo AV was traveling northeast on [XXX] in the center lane of three lanes when it activated its left turn
    # signal. ... As the Waymo AV entered the leftmost lane, the passenger car passed the Waymo AV": its run, then
    # the move left (`af`).
    assert _ego("nhtsa-sgo-ads-30270-8121-v1") == ("moving", "af")


def test_a_stop_in_a_queue_is_where_the_av_stood() -> None:
    # "The Waymo AV was traveling southeastbound on [XXX] and came to a stop in a queue of traffic for a red light
    # ... An SUV traveling southeastbound on [XXX] approached the Waymo AV from behind, and the front of the SUV made
    # contact with the rear of the stationary Waymo AV": the stop names the queue the AV then stood in (5 of 5
    # studyable reports with the AV stopping "in a queue" are gold `stopped`), not a stop made as the SUV came.
    assert _ego("nhtsa-sgo-ads-30270-10685-v1") == ("stopped", "")


def test_merging_back_into_a_lane_is_the_return() -> None:
    # "The Waymo AV began passing the double-parked vehicles on the left ... The Waymo AV began to merge back into the
    # northbound lane": the return to the lane it left, as "re-enter" is (`g` after passing on the left; gold
    # `afgkh`). 2 of 2 studyable reports with "merg* back into" the AV's lane have gold's letter for it (9409 `g`;
    # s189 "merging back into the left lane", `f`). The passing itself is not yet read as a move left.
    assert "g" in _ego("nhtsa-sgo-ads-30270-9409-v1")[1]
