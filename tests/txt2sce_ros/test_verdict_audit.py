"""Which failures say something about the planner: the attribution line, the report's column, the before/after
table of `txt2sce verdict-audit` and the hand classification it re-checks."""

from __future__ import annotations

from pathlib import Path

import pytest

from txt2sce_ros.analysis.behaviours import attribution
from txt2sce_ros.analysis.report import CampaignResults, write_report
from txt2sce_ros.campaign.audit import CLASSES, Side, classification_table, load_classification, rate_table
from txt2sce_ros.campaign.store import StoredRun
from txt2sce_ros.errors import InputError

CLASSIFICATION = Path(__file__).resolve().parents[2] / "docs" / "verdict_audit.jsonl"


def record(*labelled: str) -> dict:
    return {"details": {"unavoidable": [{"category": c, "entity": "npc1", "t": 1.0, "detail": f"{c} forced"}
                                        for c in labelled]}}


def run(sid: str, verdict: str, cats: tuple[str, ...] = (), labelled: tuple[str, ...] = ()) -> StoredRun:
    return StoredRun(sid, sid, "t", None, verdict, cats, record(*labelled))


def test_a_failure_says_something_about_the_planner_unless_every_category_was_forced() -> None:
    who = attribution([("fail", ("Collisions",), record("Collisions")),
                       ("fail", ("PlanFail", "Smooth"), record("Smooth")),     # PlanFail not forced
                       ("fail", ("Smooth",), {}),                              # a record older than the label
                       ("pass", (), {}), ("error", (), {})])
    assert (who.failed, who.planner) == (3, 2)
    assert who.unavoidable == {"Collisions": 1, "Smooth": 1}
    assert who.line() == ("3 failures: 1 unavoidable by scripted parties (every failing category labelled); "
                          "labels by category: Collisions 1, Smooth 1; 2 say something about the planner")


def test_the_report_shows_the_labels_beside_the_verdicts(tmp_path: Path) -> None:
    runs = [{"scenario_id": "n0", "tree": "t", "verdict": "fail", "categories": ["Collisions"],
             "record": record("Collisions")},
            {"scenario_id": "n1", "tree": "t", "verdict": "fail", "categories": ["Smooth"], "record": {}},
            {"scenario_id": "n2", "tree": "t", "verdict": "pass", "categories": [], "record": {}}]
    md, _ = write_report(CampaignResults(runs=runs), tmp_path)
    text = md.read_text(encoding="utf-8")
    assert "| unavoidable by scripted parties |" in text
    assert "| Collisions | 1 | 50.0% | 33.3% | 1 |" in text
    assert "2 failures: 1 unavoidable by scripted parties" in text and "1 say something about the planner" in text
    assert "| t n0 | fail Collisions | Collisions | Collisions forced |" in text


def test_before_after_rates_and_the_classified_runs_rechecked() -> None:
    before = Side({("t", "a"): run("a", "fail", ("Smooth",)), ("t", "b"): run("b", "fail", ("StartFail",)),
                   ("t", "c"): run("c", "pass"), ("t", "d"): run("d", "fail", ("Collisions",))})
    after = Side({("t", "a"): run("a", "pass"), ("t", "b"): run("b", "pass"),
                  ("t", "c"): run("c", "pass"), ("t", "d"): run("d", "fail", ("Collisions",), ("Collisions",))})
    rows = {r[0]: r[1:] for r in rate_table(before, after)}
    assert rows["any failure"] == ("3 (75.0 %)", "1 (25.0 %)", "1")
    assert rows["Smooth"] == ("1 (25.0 %)", "0 (0.0 %)", "0")
    assert rows["Collisions"] == ("1 (25.0 %)", "1 (25.0 %)", "1")
    assert rows["failures saying something about the planner"][1] == "0"
    classified = [{"tree": "t", "scenario_id": "a", "class": "stand-in deficiency"},
                  {"tree": "t", "scenario_id": "b", "class": "oracle false alarm"},
                  {"tree": "t", "scenario_id": "d", "class": "unavoidable by scripted parties"}]
    table = {r[0]: r[1:] for r in classification_table(classified, after)}
    assert table["stand-in deficiency"] == (1, 0, 0, 1)
    assert table["unavoidable by scripted parties"] == (1, 1, 1, 0)


def test_the_classification_covers_fifty_failing_runs_across_categories(tmp_path: Path) -> None:
    rows = load_classification(CLASSIFICATION)
    assert len(rows) >= 50 and len({(r["tree"], r["scenario_id"]) for r in rows}) == len(rows)
    assert {c for r in rows for c in r["before"]} >= {"StartFail", "Collisions", "PlanFail", "Smooth"}
    assert {r["class"] for r in rows} == set(CLASSES) and all(len(r["reason"]) > 20 for r in rows)
    bad = tmp_path / "bad.jsonl"
    bad.write_text('{"tree": "t", "scenario_id": "a", "before": [], "class": "bad luck", "reason": "x"}\n')
    with pytest.raises(InputError, match="class"):
        load_classification(bad)
