"""`--planner` / `--baseline`: runs keyed by planner set-up, a missing planner environment is a one-line error,
the differential sorts scenarios by who fails them, and the adapter's settings file is checked."""

from __future__ import annotations

from pathlib import Path

import pytest

from sut_adapters.commonroad.settings import AdapterSettings
from txt2sce_ros.campaign.pipeline import CampaignConfig, planner_info, run_campaign
from txt2sce_ros.campaign.reporting import differential
from txt2sce_ros.campaign.runs import make_tasks
from txt2sce_ros.errors import InputError


def test_runs_of_different_planners_never_share_a_key(seed_files: list[Path]) -> None:
    standin = make_tasks(seed_files[:2])
    cr = make_tasks(seed_files[:2], planner="commonroad", planner_settings=AdapterSettings().to_dict())
    slower = make_tasks(seed_files[:2], planner="commonroad",
                        planner_settings={**AdapterSettings().to_dict(), "desired_speed": 8.0})
    assert {t.key for t in standin}.isdisjoint({t.key for t in cr})
    assert {t.key for t in cr}.isdisjoint({t.key for t in slower})
    assert all(t.ros and t.planner == "commonroad" for t in cr)      # a third-party planner runs over ROS
    assert make_tasks(seed_files[:2]) == standin                      # the stand-in's keys are unchanged


def test_a_missing_planner_environment_is_one_clear_line(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                                          seed_files: list[Path]) -> None:
    monkeypatch.setenv("TXT2SCE_COMMONROAD_VENV", str(tmp_path / "nowhere"))
    with pytest.raises(InputError, match="make sut-commonroad"):
        planner_info("commonroad")
    with pytest.raises(InputError, match="make sut-commonroad"):
        run_campaign(seed_files[:1], CampaignConfig(out=tmp_path / "c", planner="commonroad", progress=False))
    with pytest.raises(InputError, match="cannot be combined"):
        run_campaign(seed_files[:1], CampaignConfig(out=tmp_path / "d", planner="commonroad",
                                                    faults=("ignore_cyclists",), progress=False))


def test_the_standin_is_described_with_its_faults() -> None:
    info = planner_info("standin", faults=("stale_tracking",))
    assert info["name"] == "standin" and info["settings"]["faults"] == ["stale_tracking"]


def _run(sid: str, verdict: str, cats: tuple[str, ...] = ()) -> dict:
    return {"tree": "t", "scenario_id": sid, "verdict": verdict, "categories": list(cats)}


def test_differential_separates_own_failures_from_shared_ones() -> None:
    runs = [_run("a", "fail", ("Collision",)), _run("b", "fail", ("Smooth",)), _run("c", "pass"),
            _run("d", "pass"), _run("e", "error"), _run("f", "fail")]
    base = [_run("a", "pass"), _run("b", "fail", ("Collision",)), _run("c", "fail", ("StartFail",)),
            _run("d", "pass"), _run("e", "pass")]
    d = differential(runs, base)
    assert [r["scenario_id"] for r in d["own"]] == ["a"]
    assert [r["scenario_id"] for r in d["both"]] == ["b"] and d["both"][0]["baseline_categories"] == ["Collision"]
    assert [r["scenario_id"] for r in d["baseline_only"]] == ["c"]
    assert [r["scenario_id"] for r in d["both_pass"]] == ["d"]
    assert [r["scenario_id"] for r in d["error"]] == ["e"]
    assert [r["scenario_id"] for r in d["unmatched"]] == ["f"]


def test_adapter_settings_file_is_checked(tmp_path: Path) -> None:
    good = tmp_path / "s.yaml"
    good.write_text("desired_speed: 8\nreplan_steps: 2\n", encoding="utf-8")
    s = AdapterSettings.from_yaml(good)
    assert s.desired_speed == 8.0 and s.replan_steps == 2 and s.horizon_steps == 30
    bad = tmp_path / "bad.yaml"
    bad.write_text("desired_sped: 8\n", encoding="utf-8")
    with pytest.raises(InputError, match="desired_sped"):
        AdapterSettings.from_yaml(bad)
