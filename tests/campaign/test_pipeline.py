"""Where a campaign starts (stage detection from the inputs' content) and how bad inputs are refused."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from txt2sce_ros.campaign.pipeline import CampaignConfig, detect_stage, run_campaign
from txt2sce_ros.cli.main import main as cli_main
from txt2sce_ros.errors import InputError
from txt2sce_ros.paths import shared_dir

from .conftest import DEV_GOLD, TIME_LIMIT

DEV = shared_dir() / "data" / "reports" / "dev.jsonl"


def test_stage_is_read_from_the_inputs(seed_dir: Path, seed_files: list[Path], tmp_path: Path) -> None:
    assert detect_stage([DEV]) == "reports"           # {id, text} lines
    assert detect_stage([DEV_GOLD]) == "sketches"     # txt2sce.sketch/1 lines
    assert detect_stage([seed_dir]) == "seeds"        # a seed manifest (built / refused)
    assert detect_stage(seed_files[:2]) == "scenarios"
    plain = tmp_path / "plain"
    plain.mkdir()
    shutil.copy(seed_files[0], plain / seed_files[0].name)
    assert detect_stage([plain]) == "scenarios"       # a directory of .xosc without a manifest
    narratives = tmp_path / "narratives"
    narratives.mkdir()
    (narratives / "r1.txt").write_text("The AV was rear-ended while stopped at a red light.", encoding="utf-8")
    assert detect_stage([narratives]) == "reports"


def test_tree_directories_are_detected(seed_files: list[Path], tmp_path: Path) -> None:
    from txt2sce_ros.tree.build import build_trees, tree_config

    build_trees(seed_files[:1], tmp_path / "trees", cfg=tree_config(mutations=1, max_nodes=6, validate=False))
    tree = next((tmp_path / "trees").iterdir())
    assert detect_stage([tree]) == "trees"            # one tree: manifest with nodes
    assert detect_stage([tmp_path / "trees"]) == "trees"   # a directory of trees


@pytest.mark.parametrize("content, message", [
    ("", "empty JSON Lines file"),
    ("{not json\n", "first line is not JSON"),
])
def test_bad_jsonl_is_refused_naming_the_file(tmp_path: Path, content: str, message: str) -> None:
    bad = tmp_path / "bad.jsonl"
    bad.write_text(content, encoding="utf-8")
    with pytest.raises(InputError, match=message) as err:
        detect_stage([bad])
    assert str(bad) in str(err.value)


def test_missing_and_mixed_inputs_are_refused(seed_files: list[Path], tmp_path: Path) -> None:
    with pytest.raises(InputError, match="no such file or directory") as err:
        detect_stage([tmp_path / "nope.xosc"])
    assert "nope.xosc" in str(err.value)
    with pytest.raises(InputError, match="inputs mix stages"):
        detect_stage([DEV_GOLD, seed_files[0]])


def test_unknown_fault_fails_before_any_run(seed_files: list[Path], tmp_path: Path) -> None:
    cfg = CampaignConfig(out=tmp_path / "c", faults=("ignore_trucks",), progress=False, report=False)
    with pytest.raises(InputError, match="unknown fault mode 'ignore_trucks'"):
        run_campaign(seed_files[:1], cfg)
    assert not (tmp_path / "c").exists()     # nothing started


def test_cli_prints_one_line_errors(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code = cli_main(["campaign", str(tmp_path / "missing.jsonl"), "--out", str(tmp_path / "c")])
    err = capsys.readouterr().err
    assert code == 2
    assert "missing.jsonl" in err and "Traceback" not in err


def test_scenario_stage_campaign_stores_a_verdict_per_file(seed_files: list[Path], tmp_path: Path) -> None:
    cfg = CampaignConfig(out=tmp_path / "c", executor="serial", progress=False, report=False,
                         time_limit=TIME_LIMIT)
    summary = run_campaign(seed_files[:2], cfg)
    assert summary.start_stage == "scenarios"
    assert summary.runs is not None and summary.runs.ran == 2 and summary.scenarios == 2
    # the verdicts are the closed loop's own: re-running one file gives the stored record
    from txt2sce_ros.campaign.store import ResultStore
    from txt2sce_ros.closed_loop import run_closed_loop

    with ResultStore(tmp_path / "c" / "results.sqlite") as store:
        stored = {r.scenario_id: r for r in store.runs()}
    rec, _ = run_closed_loop(seed_files[0], time_limit=TIME_LIMIT)
    assert stored[seed_files[0].stem].verdict == rec.verdict.value
    assert stored[seed_files[0].stem].categories == rec.categories
    assert json.dumps(stored[seed_files[0].stem].record["details"], sort_keys=True) == \
        json.dumps(rec.details, sort_keys=True)


def test_campaign_extraction_prints_why_a_report_gave_no_sketch(tmp_path: Path,
                                                                capsys: pytest.CaptureFixture[str]) -> None:
    from txt2sce_ros.campaign.pipeline import extract_stage

    good = json.loads(DEV.open(encoding="utf-8").readline())
    reports = tmp_path / "reports.jsonl"
    reports.write_text(json.dumps(good) + "\n" + json.dumps({"id": "empty-one", "text": ""}) + "\n",
                       encoding="utf-8")
    (tmp_path / "c").mkdir()
    _, count = extract_stage([reports], CampaignConfig(out=tmp_path / "c", progress=False))
    assert count == 1
    err = capsys.readouterr().err
    assert "txt2sce campaign: error: empty-one:" in err and "missing or empty narrative" in err


def test_reports_that_build_no_seed_stop_with_the_cause(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    # Reports that are read but give no buildable sketch: the campaign stops at the seed stage and says why,
    # instead of failing later on the empty tree directory.
    reports = tmp_path / "reports.jsonl"
    reports.write_text(json.dumps({"id": "no-story", "text": "There were no injuries and police were not called."})
                       + "\n", encoding="utf-8")
    code = cli_main(["campaign", str(reports), "--out", str(tmp_path / "c"), "--no-progress"])
    err = capsys.readouterr().err
    assert code == 2 and "Traceback" not in err
    assert "no seed could be built from the 1 sketch(es)" in err and "seeds/manifest.json" in err
    assert not (tmp_path / "c" / "trees").exists()
