"""`txt2sce play`: ego modes named for what they do, contacts reported in every mode (issue 18)."""

from __future__ import annotations

import itertools
from pathlib import Path

import pytest

from txt2sce_ros.cli.main import main
from txt2sce_ros.paths import shared_dir
from txt2sce_ros.sketch import Sketch, load_sketches

DEV_GOLD = shared_dir() / "data" / "reports" / "dev_gold.jsonl"
#: A real report: the AV side-swipes a double-parked vehicle (obs1) while driving its reported manoeuvre.
REPORT = "dmvca-apollobaid-20230906-r524"


@pytest.fixture(scope="module")
def seed_file(tmp_path_factory: pytest.TempPathFactory) -> Path:
    from txt2sce_ros.seed import write_seeds

    out = tmp_path_factory.mktemp("play")
    sketch = next(s for s in load_sketches(DEV_GOLD) if isinstance(s, Sketch) and s.report_id == REPORT)
    write_seeds(itertools.islice([sketch], 1), out, seed=0)
    return out / f"{REPORT}.xosc"


def _contacts(out: str) -> str:
    return next(line for line in out.splitlines() if line.startswith("contacts"))


def test_storyboard_mode_reports_the_contact(seed_file: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["play", str(seed_file), "--ego-mode", "storyboard"]) == 0
    out = capsys.readouterr().out
    assert "driven by the scenario's storyboard" in out
    line = _contacts(out)
    assert "ego - obs1 at t=" in line
    t = float(line.split("t=")[1].split()[0])
    assert 3.0 < t < 10.0


def test_planner_is_a_deprecated_alias_of_keep_speed(seed_file: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["play", str(seed_file), "--ego-mode", "keep-speed"]) == 0
    keep = capsys.readouterr()
    assert main(["play", str(seed_file), "--ego-mode", "planner"]) == 0
    old = capsys.readouterr()
    assert "deprecated" in old.err and "keep-speed" in old.err and "deprecated" not in keep.err
    strip = [ln for ln in keep.out.splitlines() if not ln.startswith("speed")]
    assert strip == [ln for ln in old.out.splitlines() if not ln.startswith("speed")]
    assert "holds its initial speed and heading" in keep.out


def test_standin_mode_drives_the_ego_and_is_judged(seed_file: Path, capsys: pytest.CaptureFixture[str],
                                                   tmp_path: Path) -> None:
    assert main(["play", str(seed_file), "--ego-mode", "standin", "--time-limit", "12",
                 "--csv", str(tmp_path / "t.csv")]) == 0
    out = capsys.readouterr().out
    assert "driven by the stand-in planner" in out and "verdict    " in out and _contacts(out)
    # the planner does not drive into the parked car, as keep-speed and the reported manoeuvre do
    assert "ego - obs1" not in _contacts(out)
    assert (tmp_path / "t.csv").read_text(encoding="utf-8").startswith("time,name,x,y,heading,speed")


def test_fault_outside_standin_is_a_one_line_error(seed_file: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["play", str(seed_file), "--fault", "stale_tracking"]) == 2
    assert main(["play", str(seed_file), "--ego-mode", "standin", "--fault", "no_such_fault"]) == 2
    err = capsys.readouterr().err
    assert "--fault needs --ego-mode standin" in err and "unknown fault mode" in err and "Traceback" not in err
