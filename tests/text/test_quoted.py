"""The narratives the extraction tests quote (tests/text/quoted.py) are real studyable ones, word for word: a rule
is tested on the text it was written from, never on text kept back for scoring."""

from __future__ import annotations

import json
from pathlib import Path

from txt2sce_ros.paths import shared_dir

from .quoted import QUOTED

HERE = Path(__file__).parent


def _ids(path: Path) -> set[str]:
    return {json.loads(line)["report_id"] for line in path.read_text(encoding="utf-8").splitlines() if line.strip()}


def _texts(path: Path) -> dict[str, str]:
    return {d["id"]: d["text"] for d in map(json.loads, path.read_text(encoding="utf-8").splitlines()) if d}


def test_every_quote_is_a_studyable_narrative_word_for_word() -> None:
    reports = shared_dir() / "data" / "reports"
    # The dev texts hold the check set's too: only the ids with a studyable gold sketch count.
    gold = _ids(reports / "dev_gold.jsonl") | _ids(reports / "dev_gold_study.jsonl")
    studyable = {rid: text for rid, text in _texts(reports / "dev.jsonl").items() if rid in gold}
    studyable.update(_texts(HERE / "csvr" / "study2.jsonl"))
    studyable.update(_texts(HERE / "sgo" / "study3.jsonl"))
    studyable.update(_texts(HERE / "sgo4" / "study4.jsonl"))
    studyable.update(_texts(HERE / "sgo5" / "study5.jsonl"))
    studyable.update(_texts(HERE / "sgo6" / "study6.jsonl"))
    assert len(QUOTED) >= 100
    for rid, (source, text) in QUOTED.items():
        assert rid in studyable, rid
        assert text == studyable[rid], rid
        assert source.strip(), rid
