"""Real studyable narratives with a clause of the same moment told after its main clause instead of before it ("As
the Waymo AV began to proceed, an SUV approached ..." -> "An SUV approached ... as the Waymo AV began to proceed"),
each read as the original is (session 22, tests/text/invariance.py's CLAUSE_ORDER family). Unseen reports order
their clauses every way: an extractor that reads "A as B" unlike "As B, A" reads word order, not the scene. Every
test here failed before the fix its comment names."""

from __future__ import annotations

from .invariance import _clause_after
from .quoted import QUOTED, assert_same_reading, quoted_sketch


def _same_reading(report_id: str, reworded: str) -> None:
    assert reworded != QUOTED[report_id][1], "the rewording no longer applies"
    assert_same_reading(report_id, reworded)


def test_the_av_s_move_told_after_the_party_s_clause_opens_the_interaction() -> None:
    # nhtsa-sgo-ads-30270-10078-v1 (study4 W): "The Waymo AV was traveling southbound ... and came to a stop for a
    # stop sign ... As the Waymo AV began to proceed straight through the intersection, an SUV approached the Waymo
    # AV from behind, and the front of the SUV made contact with the rear of the Waymo AV." Told "An SUV approached
    # ... as the Waymo AV began to proceed straight through the intersection.", the AV's move off came after the
    # party's first mention, so it followed the interaction instead of opening it: `ahi` moving instead of `i`
    # from its stop at the sign. (sequences.ego_sequence: the AV's moves told in a clause of the same moment after
    # the first party's clause are what it was doing when the party came in.)
    rid = "nhtsa-sgo-ads-30270-10078-v1"
    _same_reading(rid, _clause_after(QUOTED[rid][1]))
    assert (quoted_sketch(rid).ego.start, quoted_sketch(rid).ego.actions) == ("stopped", "i")
    # nhtsa-sgo-ads-30270-9905-v1 (dev gold W): "... and pulled over at the curb. As the Waymo AV came to a stop, the
    # passenger car in front of the Waymo AV reversed and ... made contact with the front bumper of the stopped
    # Waymo AV." Told "The passenger car ... reversed and ... made contact ... as the Waymo AV came to a stop.", the
    # AV's stop fell after the party's clause: stopped '' instead of `ah`.
    rid = "nhtsa-sgo-ads-30270-9905-v1"
    _same_reading(rid, _clause_after(QUOTED[rid][1]))


def test_the_av_s_move_retold_after_the_contact_ends_its_string() -> None:
    # nhtsa-sgo-ads-30270-6150-v1 (dev gold W): "... EGO attempted to merge into the left lane and make a left turn
    # onto westbound [XXX] ... As the Waymo AV moved into the left lane, the adjacent pickup truck began to proceed
    # forward and made contact with the drivers side of the Waymo AV." Told "The adjacent pickup truck ... made
    # contact with the drivers side of the Waymo AV as the Waymo AV moved into the left lane.", the lane change told
    # again after the contact was not read as the move the contact came in, so the turn it only meant to make next
    # joined the string: `ifdf` instead of `if`. (sequences._RETOLD: the clause of the same moment about the AV is
    # read wherever the sentence tells it.)
    rid = "nhtsa-sgo-ads-30270-6150-v1"
    _same_reading(rid, _clause_after(QUOTED[rid][1]))
    assert (quoted_sketch(rid).ego.start, quoted_sketch(rid).ego.actions) == ("stopped", "if")


def test_what_came_before_the_contact_told_after_it() -> None:
    # csvr-waymo-20220128-s127 (study2 W): "The Waymo AV was stopped at a red light ... After the traffic light turned
    # green and the Waymo AV had begun to accelerate, the passenger vehicle behind the Waymo AV struck the rear of the
    # Waymo AV." Told "The passenger vehicle behind the Waymo AV struck the rear of the Waymo AV after the traffic
    # light turned green and the Waymo AV had begun to accelerate.", the AV's move off was read as told after the
    # contact ("after" a word of what came next), so the AV stood throughout (stopped '' instead of `i`).
    # (story.before_contact: a clause opened by "after" with its own subject, told after the contact, tells what came
    # before it; "after the impact" still tells what came next.) The party behind read `a` instead of `i` too: see
    # the next test.
    rid = "csvr-waymo-20220128-s127"
    reworded = QUOTED[rid][1].replace(
        "After the traffic light turned green and the Waymo AV had begun to accelerate, the passenger vehicle behind "
        "the Waymo AV struck the rear of the Waymo AV.",
        "The passenger vehicle behind the Waymo AV struck the rear of the Waymo AV after the traffic light turned "
        "green and the Waymo AV had begun to accelerate.")
    _same_reading(rid, reworded)
    assert (quoted_sketch(rid).ego.start, quoted_sketch(rid).ego.actions) == ("stopped", "i")


def test_the_queue_behind_moves_off_on_a_green_told_after_the_contact() -> None:
    # csvr-waymo-20211112-s108 (study2 W): "The Waymo AV was stopped at a red light ... When the traffic light turned
    # green, the passenger vehicle behind the Waymo AV made contact with the rear of the Waymo AV." Told "The
    # passenger vehicle behind the Waymo AV made contact with the rear of the Waymo AV when the traffic light turned
    # green.", the green was looked for before the contact only, so the party behind read travelling (`a`) instead
    # of moving off with the queue (stopped, `i`). (sequences.queued_behind: the green told in a clause of the
    # contact's moment after it counts.) So with s127's "after the traffic light turned green".
    rid = "csvr-waymo-20211112-s108"
    _same_reading(rid, QUOTED[rid][1].replace(
        "When the traffic light turned green, the passenger vehicle behind the Waymo AV made contact with the rear of "
        "the Waymo AV.", "The passenger vehicle behind the Waymo AV made contact with the rear of the Waymo AV when "
        "the traffic light turned green."))
    assert [(n.start, n.actions) for n in quoted_sketch(rid).npcs] == [("stopped", "i")]


def test_a_contact_told_without_its_object_in_a_sentence_of_its_own() -> None:
    # csvr-zoox-20230211-s213 (study2 W): "A Zoox vehicle in autonomous mode was slowing to a stop with brake lights
    # illuminated behind traffic on northbound 5th Street near Jesse Street when a vehicle behind made contact at
    # approximately 10mph." Told as two sentences ("... near Jesse Street. Then a vehicle behind made contact at
    # approximately 10mph."), the contact's sentence names no AV, so no contact was found (collision `none`).
    # (story.find_contact: a contact that names no object, by a party subject right after a sentence about the AV, is
    # with the AV, as one told by a pronoun is.)
    rid = "csvr-zoox-20230211-s213"
    _same_reading(rid, QUOTED[rid][1].replace(" near Jesse Street when a vehicle", " near Jesse Street. Then a vehicle"))
    assert quoted_sketch(rid).collision.type == "rear_end"
