"""Issue 13, the AV's own start and action string and the road, read from the real NHTSA SGO narratives labelled
in session 19 and kept from every rule writer until session 20 (tests/text/sgo5/study5.jsonl; each row's `source`
beside its text in tests/text/quoted.py). One test per reading; each asserts the reading sketch.md's rules and the
gold's conventions give (sgo5/README.md: an AV stopped for a light, sign or queue before the other party acted is
`stopped` with ''), and fails if the rule is removed.
"""

from __future__ import annotations

from .quoted import quoted_ego as _ego
from .quoted import quoted_sketch


def test_a_standing_told_as_lasting_is_the_start_even_for_a_follower() -> None:
    # "... when it slowed to a stop to yield to traffic ahead of it in the same lane. While the Waymo AV remained
    # stopped, a passenger car traveling directly behind the Waymo AV approached the Waymo AV from behind": the AV
    # stood on while the follower came in (stopped, '').
    assert _ego("nhtsa-sgo-ads-30270-9635-v1") == ("stopped", "")
    # "... came to a stop, yielding to high speed traffic in the oncoming lane. The passenger car that was following
    # closely behind the Waymo AV then entered the intersection while the Waymo AV continued to yield": the same.
    assert _ego("nhtsa-sgo-ads-30270-8617-v1") == ("stopped", "")
    # Without the lasting state, the follower met the AV as it stopped (`ah`, the follower rule).
    text = ("The Waymo AV was traveling in the leftmost lane of westbound [XXX] when it slowed to a stop to yield to "
            "traffic ahead of it in the same lane. As the Waymo AV was stopped, a passenger car traveling directly "
            "behind the Waymo AV made contact with the rear passenger side of the Waymo AV.")
    assert _ego("t", text) == ("moving", "ah")


def test_a_slowing_told_in_progress_with_a_manner_adverb_is_under_way() -> None:
    # "A Zoox vehicle (Vehicle 1) in autonomy was gradually slowing to a stop in the right travel lane (lane 5) for a
    # red traffic signal ... the motorcycle made contact with the Zoox vehicle's rear bumper": the stop was under way
    # at the contact, so the AV was moving (gold `moving`; "was slowly slowing" read so before, "gradually" not).
    assert _ego("nhtsa-sgo-ads-30610-8290-v2")[0] == "moving"


def test_a_queues_standing_in_a_relative_clause_is_not_the_avs() -> None:
    # "The Waymo AV was traveling west on [XXX] in the leftmost through lane when it began to slow as it approached a
    # cue of traffic that was stopped for a red light": "was stopped" tells the queue's state (the relative clause of
    # "traffic"), not the AV's; the AV was slowing when the passing car struck it (gold moving `ac`).
    assert _ego("nhtsa-sgo-ads-30270-8383-v1") == ("moving", "ac")


def test_a_slowing_told_with_the_stop_it_prepared_for_is_a_stop() -> None:
    # "The Waymo AV slowed, preparing to stop, and a van traveling directly behind the Waymo AV then made contact
    # with the rear of the Waymo AV": the slowing was to a standstill (sketch.md: slowing to a standstill is `h`).
    assert _ego("nhtsa-sgo-ads-30270-5591-v1") == ("moving", "ah")


def test_a_turn_the_av_was_attempting_is_at_the_junction() -> None:
    # "While attempting a right turn in autonomous mode from westbound [XXX] onto northbound [XXX], the Waymo AV was
    # yielding to traffic approaching from the left": the turn was under way when the follower struck it (gold
    # junction4); the driving mode inside the clause does not part the turn from its roads.
    assert quoted_sketch("nhtsa-sgo-ads-30531-5336-v1").road.layout == "junction4"
