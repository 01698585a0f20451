"""Issue 13, the AV's own start and action string and the road, read from the real NHTSA SGO narratives labelled in
session 20 (tests/text/sgo6/study6.jsonl, its W half; each row's `source` beside its text in tests/text/quoted.py).
One test per reading; each asserts the reading sketch.md's rules and the gold's conventions give, and fails if the
rule is removed.
"""

from __future__ import annotations

from .quoted import quoted_ego as _ego
from .quoted import quoted_sketch


def test_a_backing_told_between_a_stop_and_a_move_forward_keeps_both() -> None:
    # "The Waymo AV was proceeding through a parking lot ... The AV came to a stop, and shortly thereafter the test
    # driver assumed manual control of the AV. The test driver reversed slightly and then proceeded through a vacant
    # marked parking space ... it made contact with a raised concrete curb": the run, the stop, the backing and the
    # move forward again (`ahki`), not a backing from a standstill.
    assert _ego("nhtsa-sgo-ads-30531-9244-v1") == ("moving", "ahki")
    # A party that backs and then goes forward again moves off (`ki`), as after a stop.
    text = ("A Zoox vehicle was stopped in the right lane of [XXX]. A pickup truck parked at the curb ahead of the "
            "Zoox vehicle backed up and then pulled forward, and the pickup truck made contact with the front of the "
            "Zoox vehicle.")
    assert [(n.start, n.actions) for n in quoted_sketch("t", text).npcs] == [("stopped", "ki")]

def test_another_stop_after_a_backing_is_a_stop() -> None:
    # "As the passenger car was reversing at a high rate of speed, the Waymo AV briefly reversed before coming to
    # another complete stop. The rear of the passenger car then made contact with the front of the stopped Waymo AV"
    assert _ego("nhtsa-sgo-ads-30270-9183-v1") == ("moving", "ahkh")
