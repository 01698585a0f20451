"""`txt2sce planner-check` on the benign scenarios: every goal reached, no oracle violation (the acceptance of
issue 7), and the table printed."""

from txt2sce_ros.cli.cmd_planner_check import DEFAULT_DIR, scenario_files
from txt2sce_ros.cli.main import main


def test_benign_set_passes_and_the_table_says_so(capsys):
    files = scenario_files(None)
    assert len(files) >= 8 and all(f.name.startswith("benign_") for f in files)
    code = main(["planner-check"])
    out = capsys.readouterr().out
    assert f"goals reached {len(files)}/{len(files)}" in out
    assert "runs with violations 0" in out and "errors 0" in out
    assert code == 0


def test_a_fault_makes_the_check_fail(capsys):
    code = main(["planner-check", "--scenarios", str(DEFAULT_DIR / "fault_aggressive_start.xosc"),
                 "--faults", "aggressive_start"])
    out = capsys.readouterr().out
    assert code == 1 and "StartFail" in out and "goals reached 0/1" in out


def test_unknown_fault_is_a_clear_error(capsys):
    code = main(["planner-check", "--faults", "brakes_off"])
    assert code == 2 and "brakes_off" in capsys.readouterr().err
