"""`txt2sce play` and `txt2sce conformance` end to end (in-process through the CLI entry point)."""

from __future__ import annotations

import csv

from txt2sce_ros.cli.main import main

from .conftest import xosc


def test_play_writes_the_trajectory_csv(esmini, tmp_path, capsys) -> None:
    out = tmp_path / "cut-in.csv"
    assert main(["play", str(xosc("cut-in")), "--ego-mode", "storyboard", "--csv", str(out)]) == 0
    text = capsys.readouterr().out
    assert "end reason: stop_trigger" in text and "OverTaker" in text
    rows = list(csv.DictReader(open(out, encoding="utf-8")))
    names = {r["name"] for r in rows}
    assert names == {"Ego", "OverTaker"}
    ego = [r for r in rows if r["name"] == "Ego"]
    assert float(ego[0]["time"]) == 0.0 and float(ego[0]["speed"]) == 30.0
    assert float(ego[-1]["time"]) > 20.0


def test_play_reports_bad_input_as_one_line(esmini, tmp_path, capsys) -> None:
    bad = tmp_path / "broken.xosc"
    bad.write_text("<OpenSCENARIO><FileHeader/>", encoding="utf-8")
    assert main(["play", str(bad)]) == 2
    err = capsys.readouterr().err
    assert "broken.xosc" in err and "malformed XML" in err and "Traceback" not in err


def test_conformance_prints_per_entity_errors(esmini, capsys) -> None:
    assert main(["conformance", str(esmini / "xosc"), "--reference", str(esmini / "reference"),
                 "--only", "cut-in", "speed-profile"]) == 0
    text = capsys.readouterr().out
    assert "OverTaker" in text and "Car1" in text and "Car2" in text
    assert "ran 2/2; RMS < 0.5 m: 2/2" in text


def test_esmini_check_prints_errors_and_agreement(tmp_path, capsys) -> None:
    import pytest

    from scenario_player.esmini import available
    from txt2sce_ros.paths import REPO_ROOT

    if not available():
        pytest.skip("the shared esmini is not present")
    good = REPO_ROOT / "examples" / "scenarios" / "benign_straight.xosc"
    assert main(["esmini-check", str(good)]) == 0
    out = capsys.readouterr().out
    assert "benign_straight.xosc" in out and "1/1 files: no esmini [error]" in out
    # The ego's controller without the esminiController property: esmini logs an [error], the check fails.
    old = tmp_path / "old.xosc"
    old.write_text(good.read_text(encoding="utf-8").replace(
        '<Property name="esminiController" value="ExternalController"/>', "").replace(
        'filepath="', f'filepath="{good.parent}/'), encoding="utf-8")
    assert main(["esmini-check", str(old)]) == 1
    assert "Unsupported controller type" in capsys.readouterr().out
    assert main(["esmini-check", str(tmp_path / "missing.xosc")]) == 2
    err = capsys.readouterr().err
    assert "missing.xosc" in err and "Traceback" not in err
