"""Issue 13, the road (`road.layout`, `road.control`) and the AV's signal (`signal_state`), read from real narratives
the rules were not written from: California DMV reports (tests/text/csvr/study2.jsonl) and NHTSA SGO reports
(tests/text/sgo/study3.jsonl), each row's `source` beside its text. Each test fails if its rule is removed.
"""

from __future__ import annotations

from txt2sce_ros.text.extractor import extract

from .quoted import QUOTED

_TEXTS = QUOTED  # report id -> (source, narrative): tests/text/quoted.py


def _signal(report_id: str) -> tuple[str, str]:
    sk = extract(_TEXTS[report_id][1], report_id)
    return sk.road.control, sk.signal_state


def _layout(report_id: str) -> str:
    return extract(_TEXTS[report_id][1], report_id).road.layout


def test_a_standing_av_in_a_story_of_a_red_light_stood_at_red() -> None:
    # "was at a complete stop in response to a red light ... The Cruise AV entered the intersection on a green
    # light": the AV's signal when its actions began was the red it stood at (sketch.md), though green is named.
    assert _signal("csvr-cruise-20211211-s119") == ("signal", "red")
    # "was stopped at a traffic light" with no colour told: a light the AV stands at is red (the annotators' reading
    # in both study sets).
    assert _signal("csvr-zoox-20220205-s130") == ("signal", "red")
    assert _signal("nhtsa-sgo-ads-30413-10764-v1") == ("signal", "red")


def test_a_right_on_red_is_a_signal_and_a_red() -> None:
    # "was preparing to make a right-on-red ... and was yielding to cross-traffic": a signalised approach, at red.
    assert _signal("csvr-waymo-20191014-s37") == ("signal", "red")
    assert _signal("csvr-waymo-20191016-s38") == ("signal", "red")


def test_a_block_between_two_cross_streets_and_a_rail_crossing_are_a_road() -> None:
    # "was parked at a [XXX] parking meter - between [XXX] and [XXX]": mid-block on a street (no junction named),
    # where no other road word survives the redaction; not an unknown place (which would refuse the sketch).
    assert _layout("nhtsa-sgo-ads-30792-6114-v1") == "straight"
    # "came to a gentle stop at the railroad crossing": a level crossing of rails is on a road, no junction of roads.
    assert _layout("nhtsa-sgo-ads-30413-6032-v1") == "straight"


def test_no_place_told_is_no_signal_told() -> None:
    # The official gold's 30530-7892: "an Aurora truck struck a small animal on [XXX] near Corsicana, TX": the layout
    # is unknown, so whether the AV was at a junction (and had a light) is unknown too, not `none`.
    assert _signal("nhtsa-sgo-ads-30530-7892-v1") == ("unknown", "unknown")


def test_a_ramp_the_junction_meets_is_a_leg_of_a_crossing() -> None:
    # "on [XXX] at the [XXX] onramp. While the Waymo AV was stopped at a red light on southbound [XXX] in the
    # rightmost through lane": the AV is at a crossing one of whose legs is the ramp (junction4), not on a ramp that
    # merges (junction3).
    assert _layout("nhtsa-sgo-ads-30270-3057-v2") == "junction4"
    assert _layout("nhtsa-sgo-ads-30270-9545-v1") == "junction4"
    # On the ramp itself it is a T: "was stopped in autonomous mode on the off-ramp from westbound Alma Street to
    # southbound Oregon Expressway".
    assert _layout("csvr-waymo-20190616-s18") == "junction3"


def test_opposite_headings_on_the_first_road_make_it_two_way() -> None:
    # "was traveling southbound on Albion Street ... a Ford pickup truck was traveling northbound on Albion Street":
    # the AV's road carries both directions (the official gold's r511: one_way false), though no "oncoming" is said.
    sk = extract(_TEXTS["dmvca-cruise-20230814-r511"][1], "r511")
    assert sk.road.one_way is False
    # The redacted NHTSA street is one name: "traveling east on [XXX] ... a vehicle traveling west on [XXX]".
    assert extract(_TEXTS["nhtsa-sgo-ads-30270-8141-v1"][1], "8141").road.one_way is False
    # Headings on two different streets say nothing of either.
    crossing = ("A Waymo AV was traveling northbound on Mission Street when a sedan traveling southbound on Valencia "
                "Street ran a red light and struck it.")
    assert extract(crossing, "x").road.one_way is None


def test_a_turn_from_one_road_into_a_lane_of_another_is_at_a_junction() -> None:
    # "a mini coach bus initiated a wide right turn from eastbound [XXX] into the left lane of southbound [XXX]",
    # "was making a left turn from the rightmost dedicated left turn lane on Admiralty Way into lane two of three
    # lanes in the eastbound direction of Bali Way": a turn from one road into another told by its heading is made
    # where they meet (2 of 2 studyable reports with this construction; both gold junction4).
    assert _layout("nhtsa-sgo-ads-30270-9333-v1") == "junction4"
    assert _layout("csvr-waymo-20240603-s315") == "junction4"


def test_a_red_another_party_ran_is_not_the_avs() -> None:
    # "upon entering the intersection at Jerrold Avenue, a passenger vehicle which had previously been stopped at a
    # red light, proceeded through the red light": the red is the other car's; the AV had green.
    assert _signal("csvr-waymo-20230122-s209") == ("signal", "green")


def test_the_av_slowing_for_a_red_light_has_red() -> None:
    # "As the Cruise AV was slowing for a red light at the intersection with Polk Street, an Infiniti Q60 ... failed
    # to stop for the red light": the AV's own light was red (2 of 2 studyable reports with the AV "slowing for a red
    # light", gold red in both), whatever red the other party ran.
    assert _signal("csvr-cruise-20230721-s263") == ("signal", "red")


def test_an_intersection_the_av_is_approaching_is_a_junction() -> None:
    # "was traveling northwest bound on Columbus Street approaching the intersection with Jones Street when the
    # Cruise AV slowed down ... another vehicle, changing into the Cruise AV's lane from the left adjacent lane, made
    # contact": sketch.md puts R1-R4 "at a junction the AV is in or approaching" (10 of the 11 studyable reports
    # saying "approaching/toward(s) the intersection" are gold junction4).
    assert _layout("csvr-cruise-20200129-s50") == "junction4"


def test_a_driveway_exit_is_where_they_met_not_the_junction_ahead() -> None:
    # The 11th (dev, official gold straight): "As the AV was approaching the intersection with Stillman Street, a blue
    # Model 3 Tesla exited out of a parking garage into the AV's lane of travel"; and "allowing for a passenger car
    # to exit a parking lot ... As the passenger car turned left onto [XXX]": the turn out of the lot is no junction's
    # (10 of the 11 studyable reports with someone leaving a driveway, lot or garage are gold straight; the 11th
    # stood at a red light at the intersection).
    assert _layout("dmvca-cruise-20230927-r531") == "straight"
    assert _layout("nhtsa-sgo-ads-30270-10630-v1") == "straight"


def test_a_turn_the_av_approached_is_at_the_junction_it_approached() -> None:
    # "As the Waymo AV approached a right turn from Cesar Chavez onto Evans Avenue, it braked behind stopped traffic.
    # An SUV following behind the Waymo AV made contact with the rear": the turn ahead is the junction it was
    # approaching (sketch.md), though told before the SUV comes in (1 of 1 studyable report; gold junction4).
    assert _layout("csvr-waymo-20211018-s101") == "junction4"


def test_a_queue_at_the_cross_street_the_summary_names_is_at_the_junction() -> None:
    # "was in a collision involving a passenger car on 2nd Street at Minna Street. The Waymo AV was stopped in traffic
    # on northbound 2nd Street"; "on Bush Street and Gough Street. The Waymo AV was stopped ... behind stopped
    # traffic": a queue stands at the junction the summary names (17 of 17 studyable reports with the AV in a queue
    # and the collision placed at a cross street are gold junction4, 4 of them read straight before the rule).
    assert _layout("csvr-waymo-20221108-s197") == "junction4"
    assert _layout("dmvca-waymo-20220605-r349") == "junction4"
    # "on W. Jefferson Boulevard near La Brea Avenue ... was stopped in traffic": near a cross street is no junction.
    assert _layout("csvr-waymo-20240801-s325") == "straight"


def test_a_junction_told_only_after_the_contact_is_not_the_scene() -> None:
    # dmvca-cruise-20230321-r442 (official dev gold `straight`): "Shortly before the intersection with Leavenworth
    # Street, the Cruise AV made contact with a downed power cable on Clay Street and came to a stop." Mid-block.
    report = "dmvca-cruise-20230321-r442"
    assert _layout(report) == "straight"
    # Where the AV went after the contact (moved on through the junction, pulled over at a corner) does not move
    # the place of the interaction: the layout is read from the story up to the contact, as the road's other facts.
    for told_after in ("The Cruise AV was then moved through the intersection with Leavenworth Street to the curb.",
                       "The Cruise AV then pulled over at the corner of Clay Street and Leavenworth Street.",
                       "Police later met the test driver at the traffic light at Leavenworth Street."):
        after = _TEXTS[report][1].replace("came to a stop. ", f"came to a stop. {told_after} ")
        assert extract(after, report).road.layout == "straight", told_after
