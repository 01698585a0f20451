"""Issue 13, session 18: the AV's own story read the same whatever verbs tell it (the AV's start, actions and road).

Each test takes a real studyable narrative (tests/text/quoted.py gives its source), tells one fact of it in another
reporter's words, and asserts the reading the official gold's conventions give; it fails if the rule is removed.
"""

from __future__ import annotations

import pytest

from txt2sce_ros.text.extractor import extract

from .quoted import QUOTED


def _ego(report_id: str, text: str) -> tuple[str, str]:
    sk = extract(text, report_id)
    return sk.ego.start, sk.ego.actions


#: Other verbs of the AV's run along its road, put for "was traveling" (the official gold: a run, then the stop or
#: the lane change, `ah`, `af`).
_RUN_WORDS = ("was operating", "was en route", "was in motion", "was being driven", "was navigating", "was")


@pytest.mark.parametrize("run", _RUN_WORDS)
def test_a_run_told_by_other_verbs_of_going_opens_the_string(run: str) -> None:
    # nhtsa-sgo-ads-30270-9371-v1: "The Waymo AV was traveling eastbound on [XXX] and came to a stop for a red traffic
    # light in the dedicated left turn lane ... A passenger car approached the stationary Waymo AV from behind":
    # the AV on its way stopped, and was struck stopped (`ah`), however its run is told ("was operating
    # eastbound", "was en route eastbound", "was eastbound on [XXX]").
    text = QUOTED["nhtsa-sgo-ads-30270-9371-v1"][1]
    assert _ego("nhtsa-sgo-ads-30270-9371-v1", text.replace("was traveling", run, 1)) == ("moving", "ah")
    # nhtsa-sgo-ads-30270-8121-v1: "The Waymo AV was traveling northeast on [XXX] in the center lane of three lanes
    # when it activated its left turn signal ... As the Waymo AV entered the leftmost lane": the run, then the lane
    # change (`af`).
    text = QUOTED["nhtsa-sgo-ads-30270-8121-v1"][1]
    if run == "was":
        text = text.replace("northeast on", "northeastbound on", 1)
    assert _ego("nhtsa-sgo-ads-30270-8121-v1", text.replace("was traveling", run, 1)) == ("moving", "af")


def test_a_run_named_as_a_mode_is_no_run() -> None:
    # dmvca-cruise-20200725-r132: "A Cruise autonomous vehicle ("Cruise AV") being driven in conventional mode was
    # involved in a single-car collision ... After completing a right turn onto Taraval from 21st, the driver of the
    # Cruise AV turned into a parallel parking space": "being driven in conventional mode" tells how it was driven,
    # no run; the string is the pull into the space (`l`).
    text = QUOTED["dmvca-cruise-20200725-r132"][1]
    assert _ego("dmvca-cruise-20200725-r132", text) == ("moving", "l")
