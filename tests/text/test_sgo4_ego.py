"""Issue 13, the AV's own start and action string and the road, read from the real NHTSA SGO narratives labelled
in session 19 before the extractor ran on them (tests/text/sgo4/study4.jsonl; each row's `source` beside its text
in tests/text/quoted.py). One test per reading; each asserts the reading sketch.md's rules and the official gold's
conventions give, and fails if the rule is removed.
"""

from __future__ import annotations

from .quoted import quoted_ego as _ego
from .quoted import quoted_sketch


def test_approaching_after_a_standing_places_it() -> None:
    # "A Zoox vehicle (Vehicle 1) in autonomy was stopped behind traffic in the left turn lane (lane 2) for a red
    # traffic signal on [XXX] approaching[XXX] in Las Vegas": "approaching" names the cross street ahead of where it
    # stood, not a move off; it stood throughout (stopped, '').
    assert _ego("nhtsa-sgo-ads-30610-10018-v2") == ("stopped", "")
    # In a clause of its own after the standing, "approaching" is told as a move again.
    moved = ("The Waymo AV was stopped at a red light on Mission Street, and then began approaching the intersection "
             "with 16th Street when a sedan traveling behind the Waymo AV made contact with its rear bumper.")
    assert _ego("t", moved) != ("stopped", "")


def test_stopped_before_a_traffic_noun_is_its_adjective() -> None:
    # "was traveling southbound on [XXX] in the center of three southbound lanes, passing a queue of stopped traffic
    # in the leftmost lane, when a domestic animal emerged": "stopped" tells the traffic the AV went by, not a stop
    # of the AV's (`a`, not `ahi`).
    assert _ego("nhtsa-sgo-ads-30270-9822-v1") == ("moving", "a")


def _layout(report_id: str, text: str | None = None) -> str:
    return quoted_sketch(report_id, text).road.layout


def test_an_intersection_the_av_had_crossed_is_behind_it() -> None:
    # "After the Waymo AV crossed the intersection with [XXX], an SUV in the leftmost lane initiated a right lane
    # change ...": the junction was left behind before the interaction; the summary's "on [XXX] at [XXX]" is where
    # the report was filed from (`straight`).
    assert _layout("nhtsa-sgo-ads-30270-7012-v1") == "straight"


def test_curvature_is_a_curve() -> None:
    # "The road was characterized by light traffic, with a slight curvature that transitioned from a gentle rightward
    # sway to a leftward sway" (`curve`).
    assert _layout("nhtsa-sgo-ads-30413-8861-v1") == "curve"


def test_a_party_that_moves_in_while_the_av_remains_stopped_meets_it_standing() -> None:
    # "It then slowed to a stop, with its hazards on due to a change in the traffic light configuration. While the
    # Waymo AV remained stopped, a passenger car traveling behind the Waymo AV maneuvered around the left side of the
    # Waymo AV and made contact with the rear driver side": the party's manoeuvre began with the AV standing.
    assert _ego("nhtsa-sgo-ads-30270-8851-v1") == ("stopped", "")
    # "came to a stop to yield for approaching traffic on the right. While stopped, a vehicle approached from behind
    # and made contact with the rear bumper" (study2): its approach began with the AV standing.
    assert _ego("csvr-waymo-20220219-s135") == ("stopped", "")
    # A follower already behind the AV that ran into its rear met it as it stopped: "stopped at a stop sign ... While
    # yielding to pedestrians crossing the street, a pickup truck traveling directly behind the Waymo AV made contact
    # with the rear of the Waymo AV" (study2): `ah`.
    assert _ego("csvr-waymo-20230629-s259") == ("moving", "ah")


def test_a_yield_sign_is_a_sign_control() -> None:
    # "The AV stopped at a yield sign in the right-turn only lane before merging onto [XXX] and a silver Toyota
    # rear-ended the AV": the sign control the schema's `stop_sign` stands for; no signal (`none`).
    sk = quoted_sketch("nhtsa-sgo-ads-669-8496-v2")
    assert (sk.road.control, sk.signal_state) == ("stop_sign", "none")


def test_a_turn_lane_near_a_cross_street_is_short_of_the_junction() -> None:
    # "... a collision involving a van on [XXX] near [XXX]. The Waymo AV was stopped in traffic in the dedicated right
    # turn lane of southwestbound [XXX]. While the Wamo AV remained stopped, a van traveling behind the Waymo AV
    # partially entered the left adjacent lane to maneuver around the Waymo AV": the summary places it near the cross
    # street; the turn lane is the approach to the junction, not in it (`straight`).
    assert _layout("nhtsa-sgo-ads-30270-8875-v1") == "straight"


def test_a_slowing_told_again_in_a_clause_of_the_same_moment_is_the_stop() -> None:
    # "The Waymo AV was traveling northwestbound on [XXX] and slowed to a stop in anticipation of turning right into a
    # driveway ... A passenger car ... made a U-turn in the near-side crosswalk just behind and to the left of the
    # Waymo AV as the AV was slowing": the slowing is the stop told again, the contact came while it stopped (`ah`,
    # not `ahc`).
    assert _ego("nhtsa-sgo-ads-30270-8631-v1") == ("moving", "ah")


def test_a_speed_told_after_a_turn_under_way_is_the_turn_s() -> None:
    # "The AV was making a right turn along the[XXX], traveling at 16 mph": the participle tells how fast it turned,
    # no run of its own after the turn (`e`, not `a`).
    assert _ego("nhtsa-sgo-ads-30791-10003-v1") == ("moving", "e")


def test_a_single_lane_road_has_one_lane_whatever_turn_lane_is_ahead() -> None:
    # "The Waymo AV was stopped in traffic in a one-lane section of northbound [XXX], just before the road widened to
    # include a dedicated left turn lane in the left adjacent lane ahead": one lane in the AV's direction (the turn
    # lane and "left adjacent lane" are where the road widens next).
    sk = quoted_sketch("nhtsa-sgo-ads-30270-8627-v1")
    assert sk.road.lanes == 1


def test_a_pull_over_finished_before_the_party_comes_in_is_where_the_av_stood() -> None:
    # "The Waymo AV was traveling east on [XXX], then pulled over at the curb for a passenger drop-off. The Waymo AV
    # passenger opened the rear driver side door ... An SUV ... attempted to pass the Waymo AV on the left, and the
    # passenger side of the SUV made contact with the open back driver side door of the stationary Waymo AV": the AV
    # stood when the interaction began (stopped, '', not `lh`).
    assert _ego("nhtsa-sgo-ads-30270-9910-v1") == ("stopped", "")


def test_a_yield_kept_up_while_moving_is_no_stop() -> None:
    # (study3) "After the light turned green, the Waymo AV began to slowly move ahead while continuing to yield to the
    # traffic ahead when the front of the pickup truck following behind the Waymo AV made contact": it moved off
    # from the red (`i`); the yield it kept up as it moved is no stop (not `ih`).
    assert _ego("nhtsa-sgo-ads-30270-7813-v1") == ("stopped", "i")


def test_a_collision_placed_inside_the_lot_the_av_was_exiting_is_in_the_lot() -> None:
    # "... was in a collision involving a passenger car in a parking lot at [XXX]. The Waymo AV was exiting a parking
    # lot at [XXX] when it slowed to a stop to yield for pedestrians entering the crosswalk ahead": the summary puts
    # the collision inside the lot, so the way out is the lot's aisle, not the driveway onto the road (gold parking).
    assert _layout("nhtsa-sgo-ads-30270-10184-v1") == "parking"
