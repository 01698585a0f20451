"""A campaign from a seed directory writes its report: report.md, a self-contained report.html, analysis.json."""

from __future__ import annotations

import base64
import json
import re
from pathlib import Path

from txt2sce_ros.campaign.pipeline import CampaignConfig, run_campaign
from txt2sce_ros.campaign.store import ResultStore

from .conftest import TIME_LIMIT

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


def test_seed_directory_campaign_writes_the_report(seed_dir: Path, tmp_path: Path) -> None:
    out = tmp_path / "c"
    cfg = CampaignConfig(out=out, executor="pool", workers=2, progress=False, mutations=1, max_nodes=10,
                         max_seeds=1, time_limit=TIME_LIMIT)
    summary = run_campaign([seed_dir], cfg)
    assert summary.start_stage == "seeds" and summary.trees == 1
    assert summary.report == out / "report" / "report.md"
    with ResultStore(out / "results.sqlite") as store:
        runs = list(store.runs())
    assert len(runs) == summary.scenarios > 1
    assert (out / ".trees.done").exists()

    md = (out / "report" / "report.md").read_text(encoding="utf-8")
    verdicts = {v: sum(r.verdict == v for r in runs) for v in ("pass", "fail", "error")}
    assert f"{len(runs)} runs: {verdicts['pass']} pass, {verdicts['fail']} fail, {verdicts['error']} error" in md
    for heading in ("## Unexpected behaviours (paper Table VI)", "## Trigger conditions by lift",
                    "## Derivation triggers", "## Diversity (paper Table V)"):
        assert heading in md
    # every figure the Markdown names exists beside it as a PNG
    figs = re.findall(r"!\[[^\]]*\]\(([^)]+)\)", md)
    assert any("categories" in f for f in figs) and any("tree" in f for f in figs)
    for f in figs:
        assert (out / "report" / f).read_bytes().startswith(PNG_MAGIC)

    # every Markdown table row has its header's column count (no stray '|' in a cell)
    table: list[str] = []
    for line in md.splitlines() + [""]:
        if line.startswith("|"):
            table.append(line)
        elif table:
            assert len({row.count("|") for row in table}) == 1, table
            table = []

    page = (out / "report" / "report.html").read_text(encoding="utf-8")
    uris = re.findall(r'src="data:image/png;base64,([^"]+)"', page)
    assert len(uris) == len(figs)                       # every image inlined, none linked
    assert all(base64.b64decode(u).startswith(PNG_MAGIC) for u in uris)
    assert not re.search(r'src="(?!data:)', page)       # self-contained: no external references
    assert "**" not in page and "<strong>" in page      # Markdown emphasis rendered, not shown as asterisks

    analysis = json.loads((out / "report" / "analysis.json").read_text(encoding="utf-8"))
    assert analysis["verdicts"] == {k: v for k, v in verdicts.items() if v}
    fails = [r for r in runs if r.verdict == "fail"]
    by_cat = {b["category"]: b["count"] for b in analysis["behaviours"]}
    for cat in by_cat:
        assert by_cat[cat] == sum(cat in r.categories for r in fails)

    # rerunning the finished campaign runs nothing and rewrites the same analysis
    again = run_campaign([seed_dir], cfg)
    assert again.runs is not None and again.runs.ran == 0
    assert json.loads((out / "report" / "analysis.json").read_text(encoding="utf-8")) == analysis


def test_report_says_what_was_tested_explains_codes_and_marks_a_partial_campaign(seed_dir: Path,
                                                                                 tmp_path: Path) -> None:
    out = tmp_path / "c"
    cfg = dict(out=out, executor="serial", progress=False, mutations=1, max_nodes=6, max_seeds=1,
               time_limit=TIME_LIMIT, faults=("stale_tracking",), seed=7)
    first = run_campaign([seed_dir], CampaignConfig(limit=2, **cfg))
    assert first.runs is not None and first.runs.ran == 2 and first.runs.left > 0
    md = (out / "report" / "report.md").read_text(encoding="utf-8")     # --limit writes a report too ...
    assert f"partial campaign: 2 of {2 + first.runs.left} distinct scenarios judged" in md   # ... marked partial
    page = (out / "report" / "report.html").read_text(encoding="utf-8")
    assert "class='banner'" in page
    tested = md.split("## What was tested")[1].split("\n## ")[0]
    for what in ("stand-in planner", "faults switched on | stale_tracking", "RNG seed 7", "node budget 6",
                 f"simulated time limit {TIME_LIMIT}", "txt2sce 0.1.0 (git ", "Python 3.", "1: "):
        assert what in tested, what
    legend = md.split("## Legend: the codes in this report")[1]
    for code in ("R5+ag", "| R1 | junction, crossing road to the AV's left |", "| g | change lane to the right |"):
        assert code in legend
    done = run_campaign([seed_dir], CampaignConfig(**cfg))
    assert done.runs is not None and done.runs.left == 0
    md = (out / "report" / "report.md").read_text(encoding="utf-8")
    assert "partial campaign" not in md
    assert "## Scenario trees" in md and "### Tree " in md
    # every lift row carries its element in words
    for line in md.split("## Trigger conditions by lift")[1].split("## Derivation")[0].splitlines():
        if line.startswith("| ") and not line.startswith("| element"):
            element, meaning = [c.strip() for c in line.strip("|").split("|")][:2]
            assert meaning and (meaning != element or ":" not in element), line


def test_campaign_summary_tells_the_runs_once_and_the_baseline_apart(capsys) -> None:
    from txt2sce_ros.campaign.pipeline import CampaignSummary
    from txt2sce_ros.campaign.runs import RunsSummary
    from txt2sce_ros.cli.cmd_campaign import print_summary

    summary = CampaignSummary(start_stage="scenarios", scenarios=5,
                              runs=RunsSummary(total=5, skipped=1, ran=4, verdicts={"fail": 3, "pass": 1}),
                              baseline_runs=RunsSummary(total=5, skipped=0, ran=5, verdicts={"pass": 5}),
                              planner={"name": "standin", "version": "0.1.0", "settings": {}})
    print_summary(summary)
    out = capsys.readouterr().out
    assert out.count("4 new (fail 3, pass 1)") == 1
    assert "baseline:   5 new (pass 5), 0 already done" in out
