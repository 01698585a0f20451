"""The hybrid ceiling: `hybrid` run with a perfect model (answers from gold) in the server's place, through the real
pipeline and the real slot merge; and `eval-extract --hybrid-ceiling` on the real dev gold."""

from __future__ import annotations

import re
from dataclasses import replace
from pathlib import Path

import pytest

from txt2sce_ros.cli.main import main
from txt2sce_ros.paths import shared_dir
from txt2sce_ros.sketch import Sketch
from txt2sce_ros.text.ceiling import PerfectModel
from txt2sce_ros.text.extractor import extract_weighed
from txt2sce_ros.text.pipeline import sketch_report
from txt2sce_ros.text.readers import ReportInput

REPORTS = shared_dir() / "data" / "reports"
# Two lanes said of one car: the rules place it, but flag the place weak (the conflicting evidence); its
# manoeuvre is told.
WEAK = "The AV was traveling northbound on Main Street when a car in the left lane, then in the right lane, " \
       "changed lanes and struck the AV."


def _gold_from(rules: Sketch, **npc: object) -> Sketch:
    return replace(rules, npcs=(replace(rules.npcs[0], **npc),) + rules.npcs[1:])


def test_a_perfect_model_fixes_the_flagged_slots_and_only_those() -> None:
    rules, weak = extract_weighed(WEAK, "weak-1")
    assert "npcs[0].position" in weak and "npcs[0].actions" not in weak
    # The gold puts the car behind in the AV's lane and gives it another manoeuvre: the place is asked, the
    # manoeuvre (told, so not flagged) is not.
    gold = _gold_from(rules, position="R6", lane="same", actions="af")
    model = PerfectModel({"weak-1": gold})
    out = sketch_report(ReportInput("weak-1", WEAK, "mem"), backend="hybrid", llm=model)
    assert isinstance(out, Sketch)
    assert (out.npcs[0].position, out.npcs[0].lane, out.npcs[0].actions) == ("R6", "same", rules.npcs[0].actions)
    assert (model.slot_questions, model.slots_asked, model.dialogues) == (1, len(weak), 0)
    f = model.flags
    assert (f.flagged_wrong, f.unflagged_wrong) == (2, 1) and f.recall == pytest.approx(2 / 3)
    # A report with no gold sketch, or whose sketch has nothing flagged, keeps the rules' reading.
    assert sketch_report(ReportInput("other", WEAK, "mem"), backend="hybrid", llm=model) == \
        extract_weighed(WEAK, "other")[0]
    assert model.slot_questions == 1


def test_an_incomplete_sketch_takes_the_whole_dialogue_only_when_its_answer_is_complete() -> None:
    vague = "The AV was damaged. No injuries were reported."
    rules, _ = extract_weighed(vague, "v")
    assert not rules.is_buildable
    assert sketch_report(ReportInput("v", vague, "mem"), backend="hybrid", llm=PerfectModel({})) == rules
    whole = extract_weighed(WEAK, "v")[0]
    model = PerfectModel({"v": whole})
    assert sketch_report(ReportInput("v", vague, "mem"), backend="hybrid", llm=model) == whole
    assert model.dialogues == 1
    still = PerfectModel({"v": rules})  # gold incomplete too: nothing better to take
    assert sketch_report(ReportInput("v", vague, "mem"), backend="hybrid", llm=still) == rules


def test_eval_extract_prints_the_hybrid_ceiling_beside_the_rules(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["eval-extract", "--gold", str(REPORTS / "dev_gold.jsonl"), "--input", str(REPORTS / "dev.jsonl"),
                 "--hybrid-ceiling"]) == 0
    out = capsys.readouterr().out
    main_figure = re.search(r"Conflict reproduced exactly .*: (\d+)/(\d+) complete", out)
    ceiling = re.search(r"user's figure: rules (\d+)/(\d+) \([\d.]+%\) -> ceiling (\d+)/(\d+)", out)
    assert main_figure and ceiling
    assert ceiling.group(1, 2) == main_figure.group(1, 2)  # the rules' figure is the table's
    assert ceiling.group(4) == ceiling.group(2) and int(ceiling.group(1)) <= int(ceiling.group(3))
    flags = re.search(r"(\d+) flagged \((\d+) wrong\), (\d+) not flagged \((\d+) wrong\)", out)
    assert flags and int(flags.group(2)) <= int(flags.group(1)) and int(flags.group(4)) <= int(flags.group(3))


def test_hybrid_ceiling_needs_the_narratives(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    pred = tmp_path / "p.jsonl"
    pred.write_text("", encoding="utf-8")
    assert main(["eval-extract", "--gold", str(REPORTS / "dev_gold.jsonl"), "--pred", str(pred),
                 "--hybrid-ceiling"]) == 2
    assert "--hybrid-ceiling needs --gold and --input" in capsys.readouterr().err
