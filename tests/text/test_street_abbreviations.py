"""Issue 13: a street's name abbreviated inside a sentence ("Alma St. merging onto", "Market St. onto Haight St.
at") reads as the name spelled out: the rules that scan a clause stop at a period. Found by rewording real
studyable narratives (tests/text/invariance.py, session 21); fails without the period dropped in `mentions.normalise`.
"""

from __future__ import annotations

from txt2sce_ros.text.mentions import normalise

from .quoted import QUOTED
from .quoted import quoted_sketch as _sketch


def test_an_abbreviated_street_reads_as_the_street_spelled_out() -> None:
    # csvr-waymo-20191018-s40, "on the interchange from eastbound Alma Street merging onto southbound Oregon
    # Expressway": told "Alma St. merging onto", the layout was read as a four-way junction.
    rid = "csvr-waymo-20191018-s40"
    short = QUOTED[rid][1].replace("Alma Street", "Alma St.", 1)
    assert short != QUOTED[rid][1]
    assert _sketch(rid, short).to_dict() | {"evidence": None} == _sketch(rid).to_dict() | {"evidence": None}


def test_only_a_street_inside_a_sentence_is_spelled_out() -> None:
    t = normalise("It turned from Market St. onto Haight St., near 10th St. and St. Francis Blvd. The end.")
    assert "Market St onto Haight St, near 10th St and St. Francis Blvd. The end." in t
