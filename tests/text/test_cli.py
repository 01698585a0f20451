"""`txt2sce extract` and `txt2sce eval-extract` end to end on the real dev set, through the CLI entry point."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from txt2sce_ros.cli.main import main
from txt2sce_ros.paths import BUNDLED_REPORTS, shared_dir
from txt2sce_ros.sketch import Sketch, load_sketches, validate_sketch_dict

REPORTS = shared_dir() / "data" / "reports"


def test_extract_dev_writes_180_schema_valid_lines(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "dev_pred.jsonl"
    assert main(["extract", str(REPORTS / "dev.jsonl"), "--out", str(out)]) == 0
    lines = out.read_text(encoding="utf-8").splitlines()
    assert len(lines) == 180
    ids = [json.loads(x)["report_id"] for x in lines]
    assert len(set(ids)) == 180
    assert all(validate_sketch_dict(json.loads(x)) == [] for x in lines)
    err = capsys.readouterr().err
    assert "180 reports" in err and "0 errors" in err

    assert main(["eval-extract", "--gold", str(REPORTS / "dev_gold.jsonl"), "--pred", str(out),
                 "--form-labels", str(REPORTS / "dev_form_labels.jsonl"), "--check-targets"]) == 0
    text = capsys.readouterr().out
    for slot in ("npc_quantity", "npc_type", "npc_position", "npc_events", "obstacle_quantity", "obstacle_type",
                 "obstacle_position", "weather", "collision_type", "completeness", "Worst slots",
                 "Agreement with company-filed form labels", "party_category", "av_movement"):
        assert slot in text
    assert "over 60 gold reports" in text and "BELOW" not in text.split("Extra slots")[0]


def test_eval_extract_counts_a_wrong_prediction(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    gold = [s for s in load_sketches(REPORTS / "dev_gold.jsonl") if isinstance(s, Sketch)]
    # Predictions = gold, except one report whose NPC is given the wrong category.
    first = next(g for g in gold if g.npcs)
    lines = []
    for g in gold:
        d = g.to_dict()
        if g.report_id == first.report_id:
            d["npcs"][0]["category"] = "bus" if d["npcs"][0]["category"] != "bus" else "car"
        lines.append(json.dumps(d))
    pred = tmp_path / "pred.jsonl"
    pred.write_text("\n".join(lines) + "\n", encoding="utf-8")
    assert main(["eval-extract", "--gold", str(REPORTS / "dev_gold.jsonl"), "--pred", str(pred)]) == 0
    out = capsys.readouterr().out
    n_npcs = sum(len(g.npcs) for g in gold)
    row = next(x for x in out.splitlines() if x.startswith("npc_type"))
    assert row.split()[2:4] == [str(n_npcs - 1), str(n_npcs)]
    assert next(x for x in out.splitlines() if x.startswith("npc_position")).split()[1] == "100.0%"
    assert first.report_id in out  # the confusion listing names the report


def test_bundled_demo_reports_are_real_dev_rows_with_complete_gold() -> None:
    demo = BUNDLED_REPORTS / "demo.jsonl"
    rows = [json.loads(x) for x in demo.read_text(encoding="utf-8").splitlines() if x.strip()]
    assert 6 <= len(rows) <= 10
    dev = {json.loads(x)["id"]: json.loads(x)["text"] for x in
           (REPORTS / "dev.jsonl").read_text(encoding="utf-8").splitlines()}
    gold = {g.report_id: g for g in load_sketches(REPORTS / "dev_gold.jsonl") if isinstance(g, Sketch)}
    for r in rows:
        assert dev[r["id"]] == r["text"] and gold[r["id"]].is_buildable
    cats = {n.category for r in rows for n in gold[r["id"]].npcs} | {o.category for r in rows
                                                                      for o in gold[r["id"]].obstacles}
    assert {"bicycle", "pedestrian", "door"} <= cats


def test_extract_prints_the_reason_of_a_missing_input(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    missing = tmp_path / "no_such_report.txt"
    assert main(["extract", str(missing), "--out", str(tmp_path / "o.jsonl")]) == 2   # nothing usable (README)
    err = capsys.readouterr().err
    # the reason is on the console, not only in the output file
    assert "no_such_report" in err and "file not found" in err and "1 errors" in err


def test_extract_names_an_oversized_report_once_and_goes_on(tmp_path: Path,
                                                            capsys: pytest.CaptureFixture[str]) -> None:
    # A narrative past the limit is refused with its size and the limit, the report named once; the batch goes on.
    rows = [{"id": "huge", "text": "The AV was rear-ended. " * 6000}, {"id": "fine", "text": "The AV was rear-ended."}]
    src = tmp_path / "in.jsonl"
    src.write_text("".join(json.dumps(r) + "\n" for r in rows))
    assert main(["extract", str(src), "--out", str(tmp_path / "o.jsonl")]) == 1
    err = capsys.readouterr().err
    assert "txt2sce extract: error: huge: narrative is 138,000 characters, over the limit of 100,000" in err
    assert "huge: huge" not in err and "1 errors" in err
    out = (tmp_path / "o.jsonl").read_text().splitlines()
    assert [json.loads(line)["report_id"] for line in out] == ["huge", "fine"]
