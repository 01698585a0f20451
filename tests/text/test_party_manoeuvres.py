"""Issue 13, the other parties' start and action strings, read from real narratives of the studyable sets (quoted in
tests/text/quoted.py with their sources). One test per reading (session 18); each asserts what sketch.md's rules and
the official gold's conventions give, on the narrative as written and, where the reading is one of grammar, on the
same narrative told in another common wording.
"""

from __future__ import annotations

from txt2sce_ros.sketch import Party
from txt2sce_ros.text.extractor import extract

from .quoted import QUOTED


def _party(report_id: str, text: str | None = None, k: int = 0) -> Party:
    return extract(text if text is not None else QUOTED[report_id][1], report_id).npcs[k]


def test_a_turn_named_after_the_party_s_participle_is_under_way() -> None:
    # "a passenger car turning left in the leftmost dedicated left turn lane ... crossed into the lane of the Waymo
    # AV": the turn was under way when the story takes the car up (`d`, then the move into the AV's lane, `g`; the
    # gold `dg`). "a passenger car making a left turn in ..." tells the same: the noun of the manoeuvre after the
    # subject's participle is under way as the participle itself is, so no run (`a`) opens the string.
    rid = "nhtsa-sgo-ads-30270-10717-v1"
    assert _party(rid).actions == "dg"
    told = QUOTED[rid][1].replace("a passenger car turning left", "a passenger car making a left turn")
    assert _party(rid, told).actions == "dg"


def test_a_backing_or_speed_up_after_a_contact_begins_another_episode_with_or_without_then() -> None:
    # "The heavy truck then reversed and proceeded eastbound. As the heavy truck passed the stationary Waymo AV, it
    # made contact with the driver side ...": the conflict is the first contact, so the truck's string ends there
    # (`af`, the gold), without the backing. Told without "then" the backing still follows the first contact.
    rid = "nhtsa-sgo-ads-30270-10776-v1"
    assert _party(rid).actions == "af"
    assert _party(rid, QUOTED[rid][1].replace("The heavy truck then reversed", "The heavy truck reversed")).actions \
        == "af"
    # "The passenger car then accelerated and the front right corner of the passenger car made contact with the rear
    # left corner of the stationary Waymo AV": the second contact, after the first ("made continuous contact ...
    # before the passenger car slowed down and separated"); the car's string is its approach from behind (`a`).
    rid = "csvr-waymo-20240319-s304"
    assert _party(rid).actions == "a"
    assert _party(rid, QUOTED[rid][1].replace("The passenger car then accelerated", "The passenger car accelerated")) \
        .actions == "a"


def test_a_stop_told_as_the_party_s_first_state_is_where_it_stood() -> None:
    # "a passenger car traveling westbound on [XXX] initially stopped behind the Waymo AV, then proceeded to pass to
    # Waymo AV on the left": it stood behind the parked AV when the story begins (`stopped`), then moved off and
    # passed (`if`, the gold), not a run that stopped (`ahif`).
    assert (_party("nhtsa-sgo-ads-30270-10666-v1").start, _party("nhtsa-sgo-ads-30270-10666-v1").actions) == \
        ("stopped", "if")
    # "A passenger car travelling directly behind the Waymo AV initially came to a stop in the queue of traffic, then
    # began to proceed forward": `stopped`, `i` (the gold), told "initially", "at first" or "first".
    rid = "nhtsa-sgo-ads-30270-10718-v1"
    for first in ("initially", "at first", "first"):
        p = _party(rid, QUOTED[rid][1].replace("initially came", f"{first} came"))
        assert (p.start, p.actions) == ("stopped", "i"), first


def test_the_vehicle_the_av_stood_behind_stood_too_by_any_word_of_standing() -> None:
    # "it came to a stop behind its lead vehicle": the lead vehicle, of which no move is told, stood (`stopped`, no
    # actions; the gold). So whatever word tells the AV's standing behind it.
    rid = "csvr-waymo-20240131-s297"
    lead = next(p for p in extract(QUOTED[rid][1], rid).npcs if p.position == "R5")
    assert (lead.start, lead.actions) == ("stopped", "")
    for told in ("came to rest behind", "halted behind", "paused behind", "was stopping behind",
                 "stopped completely behind"):
        sk = extract(QUOTED[rid][1].replace("came to a stop behind", told), rid)
        lead = next(p for p in sk.npcs if p.position == "R5")
        assert (lead.start, lead.actions) == ("stopped", ""), told


def test_a_party_behind_the_standing_av_that_passes_it_changed_lane_from_its_lane() -> None:
    # "a cyclist that had been traveling behind the Waymo AV passed the Waymo AV on the left" (the AV stopped in
    # traffic): it was in the AV's lane behind it and moved out to pass (R6/same, `af`: the official gold), as one
    # that had stood behind it does ("had been stopped behind the Waymo AV passed ... on the left": `if`).
    p = _party("dmvca-waymo-20230820-r519")
    assert (p.position, p.lane, p.actions) == ("R6", "same", "af")
    # "An SUV traveling southeast on [XXX] directly behind the Waymo AV passed the Waymo AV on the left"; so when
    # it "went by" or "drove by" the Waymo AV on the left.
    rid = "nhtsa-sgo-ads-30270-10758-v1"
    for verb in ("passed", "went by", "drove by"):
        p = _party(rid, QUOTED[rid][1].replace("Waymo AV passed the Waymo AV", f"Waymo AV {verb} the Waymo AV"))
        assert (p.position, p.lane, p.actions) == ("R6", "same", "af"), verb
    # A follower of the AV on its way is not placed so ("a SUV following closely behind the Waymo AV passed the
    # Waymo AV on the left side" as the AV pulled up behind a double-parked car: R6/left, `a`, the official gold).
    p = _party("dmvca-waymo-20220411-r318")
    assert (p.position, p.lane, p.actions) == ("R6", "left", "a")


def test_a_space_off_the_road_is_left_across_the_way_a_curbside_one_into_a_lane() -> None:
    # "an SUV parked in a carport to the right of the Waymo AV began to exit its parking stall and proceed into the
    # alley": the stall is off the roadway, so the SUV moved off across the AV's path (`im`, the gold), not from the
    # curb into a lane (`if`).
    p = _party("nhtsa-sgo-ads-30270-10570-v1")
    assert (p.start, p.actions) == ("stopped", "im")
    # "another vehicle pulling out of a curbside parking spot": from the curb into the lane (`if`, the official gold).
    p = next(x for x in extract(QUOTED["dmvca-cruise-20220129-r278"][1], "r278").npcs if x.start == "stopped")
    assert p.actions == "if"


def test_the_way_out_of_a_driveway_told_with_its_turn_is_the_turn() -> None:
    # "an SUV was exiting a shopping center driveway making a right turn onto southbound [XXX]": the exit is the
    # turn onto the AV's road (`e`, the gold), not a crossing and then a turn (`me`); so when told "exited ... and
    # turned right onto".
    rid = "nhtsa-sgo-ads-30270-9544-v1"
    assert _party(rid).actions == "e"
    told = QUOTED[rid][1].replace("was exiting a shopping center driveway making a right turn onto",
                                  "exited a shopping center driveway and turned right onto")
    assert _party(rid, told).actions == "e"


def test_a_lane_entered_by_any_name_is_a_lane_change() -> None:
    # "The passenger car partially entered the number 2 lane as the front right corner of the passenger car made
    # contact with the rear left corner of the Waymo AV": the car behind the AV moved out of its lane (`af`, the
    # gold), as "moved into the number 2 lane" reads; so whatever names the lane.
    rid = "csvr-waymo-20240513-s311"
    assert _party(rid).actions == "af"
    for name in ("lane 2", "the #2 lane", "the No. 2 lane", "the center lane", "the adjacent lane"):
        told = QUOTED[rid][1].replace("partially entered the number 2 lane", f"partially entered {name}")
        assert _party(rid, told).actions == "af", name
    # "a pedestrian on a scooter who entered the lane of traffic in front of the AV": a walker or rider into the
    # traffic lane is crossing (`m`, the official gold), not changing lanes.
    assert _party("dmvca-cruise-20230617-r484").actions == "m"


def test_a_standing_party_that_passes_moved_off_first_whatever_its_verb() -> None:
    # "an SUV that had been stopped partially in-lane behind the Waymo AV passed the Waymo AV on the left": it stood,
    # moved off and moved out to pass (`stopped`, `if`: the gold). A verb of passing that tells no move of its own
    # ("overtook", "got around", "pulled around") still begins with the move off, never a run (`af`) from a stand.
    rid = "nhtsa-sgo-ads-30270-8150-v1"
    assert (_party(rid).start, _party(rid).actions) == ("stopped", "if")
    for verb in ("overtook", "got around", "pulled around"):
        p = _party(rid, QUOTED[rid][1].replace("behind the Waymo AV passed the Waymo AV", f"behind the Waymo AV {verb} "
                                                                                      "the Waymo AV"))
        assert (p.start, p.actions) == ("stopped", "if"), verb


def test_a_bare_backed_is_a_backing_and_a_listed_verb_after_the_contact_comes_after_it() -> None:
    # "a passenger car in a parking spot to the left of the Waymo AV reversed and the rear of the passenger car made
    # contact": `stopped`, `k` (the gold); told "backed" (no particle) it is the same backing.
    rid = "nhtsa-sgo-ads-30270-10669-v1"
    for told in (QUOTED[rid][1], QUOTED[rid][1].replace("Waymo AV reversed and", "Waymo AV backed and")):
        p = _party(rid, told)
        assert (p.start, p.actions) == ("stopped", "k")
    # "The cyclist then reached out a hand and made contact with the front passenger side of the stationary Waymo AV,
    # backed the bicycle up slightly, dropped the bicycle, then fell": what the list tells after the contact came
    # after it (`mc`, the gold; no backing).
    assert _party("nhtsa-sgo-ads-30270-8039-v1").actions == "mc"


def test_a_party_named_on_its_way_by_any_participle_of_going_ran_along_its_lane_first() -> None:
    # "seeing the oncoming vehicle crossing the centerline": on its way (`a`), then across the centre line (`f`;
    # the official gold `af`). "the opposing vehicle", "the advancing vehicle" tell the same run.
    rid = "dmvca-cruise-20201024-r143"
    assert _party(rid).actions == "af"
    for word in ("opposing", "on-coming", "advancing"):
        told = QUOTED[rid][1].replace("oncoming", word)
        assert _party(rid, told).actions == "af", word


def test_a_party_s_sideless_lane_change_right_after_one_with_a_side_is_the_same_move() -> None:
    # "A passenger vehicle stopped behind the Waymo AV then attempted to go around the Waymo AV, attempting to merge
    # with traffic in the center lane": the merge is the going around told by its purpose, to the left (`if`, the
    # gold), not a move back to the right (`ifg`).
    p = _party("dmvca-waymo-20220206-r282")
    assert (p.position, p.lane, p.start, p.actions) == ("R6", "same", "stopped", "if")


def test_a_participle_that_places_the_party_behind_the_standing_av_is_no_run() -> None:
    # "The driver of a passenger car traveling directly behind the Waymo AV began to exit their vehicle, and as they
    # did so with the door open, the passenger car started to proceed straight": the car stood in the queue behind
    # the AV stopped at the red light and moved off (`stopped`, `i`: the gold), as told "a passenger car directly
    # behind the Waymo AV"; "traveling" only places it.
    rid = "nhtsa-sgo-ads-30270-7726-v1"
    for told in (QUOTED[rid][1], QUOTED[rid][1].replace("traveling directly behind", "directly behind")):
        p = _party(rid, told)
        assert (p.start, p.actions) == ("stopped", "i")


def test_a_pass_told_with_went_by_is_a_run_along_the_av() -> None:
    # "a passenger car passed the Waymo AV on the right" before turning: a run (`a`), then its turn and stop (`adh`,
    # the gold); "went by the Waymo AV" or "drove by the Waymo AV" tell the same run.
    rid = "nhtsa-sgo-ads-30270-8139-v1"
    for verb in ("passed", "went by", "drove by"):
        told = QUOTED[rid][1].replace("passenger car passed the Waymo AV", f"passenger car {verb} the Waymo AV")
        assert _party(rid, told).actions == "adh", verb


def test_a_parked_party_pulling_out_straight_into_a_u_turn_changes_no_lane_first() -> None:
    # "a passenger car (Vehicle 2) which had been parallel parked in the adjacent right curb lane, pulled out of the
    # parking spot and began attempting a multi-point U-turn ahead of the Zoox vehicle": it moved off (`i`) and its
    # way out of the space was the U-turn itself (`j`), no lane change before it (the gold `ij`; studyable parties
    # moving off into a turn: `id` 2, `ie` 1, `ij` 1).
    p = _party("nhtsa-sgo-ads-30610-9963-v1")
    assert (p.start, p.actions) == ("stopped", "ij")


def test_a_lane_change_from_one_outer_lane_of_three_to_the_other_is_two_changes() -> None:
    # "an SUV also proceeding westbound on Winston Drive made a continuous right lane change from the far left lane,
    # through the middle lane, and entered the far right lane in front of the Waymo AV": two changes to the right
    # (the official gold's `agg`).
    p = _party("dmvca-waymo-20211204-r256")
    assert (p.position, p.lane, p.actions) == ("R5", "left", "agg")
