"""`python -m tests.text.eval_sets`: every gold set in one table, pooled by role, on the real sets."""

from __future__ import annotations

import re
from dataclasses import replace
from pathlib import Path

import pytest

from tests.text.eval_sets import gold_sets, main
from tests.text.test_llm import REPORTS, ChatServer, _gold, server  # noqa: F401 (server: the loopback fixture)
from txt2sce_ros.sketch import Sketch, load_sketches
from txt2sce_ros.text.evaluate import conflict_exact


def _row(out: str, name: str) -> list[str]:
    return next(x for x in out.splitlines() if x.startswith(name + " ")).split()


def test_every_set_is_on_disk_and_each_role_is_named() -> None:
    sets = gold_sets()
    assert all(s.narratives.is_file() and s.gold.is_file() for s in sets)
    assert {s.name for s in sets if not s.studyable} == {"dev_gold_check"} | {f"check{n}" for n in range(2, 7)}


def test_rows_pool_by_role_and_the_ceiling_is_never_below_the_rules(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["--sets", "dev_gold,dev_gold_check,check2", "--hybrid-ceiling"]) == 0
    out = capsys.readouterr().out
    check, check2, dev = _row(out, "dev_gold_check"), _row(out, "check2"), _row(out, "dev_gold")
    assert check[1] == "*" and dev[1] != "*"  # scored-only sets are marked
    pooled = _row(out, "scored only")  # "scored", "only", "*", nine slots, conflict, ceiling

    def frac(cell: str) -> tuple[int, int]:
        a, b = cell.split("/")
        return int(a), int(b)

    (a1, b1), (a2, b2) = frac(check[-2]), frac(check2[-2])
    assert frac(pooled[-2]) == (a1 + a2, b1 + b2)
    for row in (check, check2, dev):
        assert frac(row[-1])[0] >= frac(row[-2])[0] and frac(row[-1])[1] == frac(row[-2])[1]
    assert _row(out, "studyable")[-2] == dev[-2]  # one studyable set: its own figure
    assert re.search(r"backend: offline; 3 sets in", out)


def test_bad_requests_get_one_line(capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch) -> None:
    assert main(["--sets", "dev_gold,check9"]) == 2
    assert "unknown set(s) check9" in capsys.readouterr().err
    for name in ("TXT2SCE_LLM_API_KEY", "DEEPSEEK_API_KEY", "TXT2SCE_LLM_BASE_URL"):
        monkeypatch.delenv(name, raising=False)
    assert main(["--backend", "llm", "--sets", "dev_gold"]) == 2
    assert "no API key for https://api.deepseek.com" in capsys.readouterr().err


def test_a_model_server_is_scored_through_the_same_table(server: ChatServer, tmp_path: Path,
                                                         monkeypatch: pytest.MonkeyPatch,
                                                         capsys: pytest.CaptureFixture[str]) -> None:
    # The loopback server answers every narrative with one dev report's gold, cut into the dialogue's five steps:
    # the table must score exactly the reports whose gold conflict that sketch reproduces.
    monkeypatch.setenv("TXT2SCE_CACHE", str(tmp_path / "cache"))
    assert main(["--backend", "llm", "--base-url", server.url, "--model", "recorded-model",
                 "--sets", "dev_gold"]) == 0
    out = capsys.readouterr().out
    answered = _gold()
    gold = [g for g in load_sketches(REPORTS / "dev_gold.jsonl") if isinstance(g, Sketch)]
    complete = [g for g in gold if not g.missing]
    hits = sum(conflict_exact(g, replace(answered, report_id=g.report_id)) for g in complete)
    assert hits >= 1 and _row(out, "dev_gold")[-1] == f"{hits}/{len(complete)}"
    assert "backend: llm" in out and len(server.log) == 5 * 180  # every dev narrative, each asked once


def test_reports_the_server_never_answered_are_counted_wrong_and_said(
        server: ChatServer, tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]) -> None:
    # A step-2 answer that is never valid (a position that does not exist): every report becomes an error record.
    server.answers["STEP 2"] = '{"positions": [{"id": "npc1", "position": "R9", "lane": null}]}'
    monkeypatch.setenv("TXT2SCE_CACHE", str(tmp_path / "cache"))
    assert main(["--backend", "llm", "--base-url", server.url, "--model", "recorded-model",
                 "--sets", "dev_gold_check"]) == 0
    captured = capsys.readouterr()
    assert _row(captured.out, "dev_gold_check")[-1].startswith("0/")
    assert "180 report(s) got no sketch" in captured.err and "R9" in captured.err
