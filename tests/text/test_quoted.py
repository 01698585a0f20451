"""The narratives the extraction tests quote (tests/text/quoted.py) are real studyable ones, word for word: a rule
is tested on the text it was written from, never on text kept back for scoring."""

from __future__ import annotations

from .invariance import every_studyable
from .quoted import QUOTED


def test_every_quote_is_a_studyable_narrative_word_for_word() -> None:
    # (every_studyable: the dev texts with a studyable gold sketch, not the check set's, and study2 .. study6: the
    # one list of what may be read)
    studyable = every_studyable()
    assert len(QUOTED) >= 100
    for rid, (source, text) in QUOTED.items():
        assert rid in studyable, rid
        assert text == studyable[rid], rid
        assert source.strip(), rid
