"""Issue 13: what the extractor strips from a sentence before reading it (the AV's driving mode, a turn's noun
phrase) leaves the rest of the sentence reading as it would without it. Both faults were found by rewording real
studyable narratives (probes and invariance rewrites, session 21) and fail without their fix.
"""

from __future__ import annotations

from txt2sce_ros.text.extractor import extract

from .quoted import QUOTED
from .quoted import quoted_sketch as _sketch


def _parties(report_id: str, text: str | None = None) -> list[tuple[str, str | None, str]]:
    return [(p.position, p.lane, p.actions) for p in _sketch(report_id, text).npcs]


def test_a_place_to_the_left_before_a_turn_is_no_intention() -> None:
    # "to the left" before "made a right turn" is where the party was; only the turn's own article and words are
    # its noun phrase, so no "to" is left to read as an intention ("preparing to make a left turn").
    text = ("The Cruise AV was traveling northbound on Mission Street when a vehicle in the adjacent lane to the left "
            "made a right turn and made contact with the front of the Cruise AV.")
    assert [(p.position, p.lane, p.actions) for p in extract(text, "t").npcs] == [("R5", "left", "ae")]
    # An intention told with "to" is still one: the AV stood, preparing its turn.
    text = ("The Cruise AV was stopped at the intersection, preparing to make an unprotected left turn, when a vehicle "
            "made contact with the rear of the Cruise AV.")
    assert extract(text, "t").ego.actions == ""


def test_an_emptied_mode_aside_after_the_avs_name_parts_nothing() -> None:
    # nhtsa-sgo-ads-30270-9736-v1, "The Waymo AV was stopped at a stop sign facing east in the rightmost of two
    # lanes", told "The Waymo AV, in autonomous mode, was stopped": the mode dropped left "EGO,, was"; the AV's lane
    # (and so the party's beside it, gold R6/left) reads as without the aside.
    rid = "nhtsa-sgo-ads-30270-9736-v1"
    want = _parties(rid)
    assert want[0][:2] == ("R6", "left")
    aside = QUOTED[rid][1].replace("The Waymo AV was stopped", "The Waymo AV, in autonomous mode, was stopped", 1)
    assert aside != QUOTED[rid][1] and _parties(rid, aside) == want
