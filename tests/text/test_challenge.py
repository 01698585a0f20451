"""The hand-written challenge set (tests/text/challenge.py) holds at what the extractor reaches: a rule change that
loses a pattern shows here even when the gold sets do not move."""

from .challenge import POSITIONS, score


def test_challenge_set_holds() -> None:
    sc = score()
    assert sc.reports == 235 and sc.parties == 234
    assert sc.position >= 227, sc.misses
    assert sc.events >= 206, sc.misses
    assert sc.ego >= 233, sc.misses


# The batches written beside the events work (challenge_positions.jsonl), held apart so both files can grow at once.
def test_challenge_positions_file_holds() -> None:
    sc = score(POSITIONS)
    assert sc.reports == 128 and sc.parties == 135
    assert sc.position >= 128, sc.misses
    assert sc.events >= 114, sc.misses
    assert sc.ego >= 128, sc.misses
