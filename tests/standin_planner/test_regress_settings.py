"""`python -m standin_planner.regress settings` prices a result-changing setting: both runs of each file, the step
counts of each, and the verdicts that differ. Checked on two example scenarios: a coarser step halves the steps,
and the planner held between plans is really held (its runs differ from the defaults' in trajectory)."""

from __future__ import annotations

import re
from pathlib import Path

from standin_planner import regress
from standin_planner.planner import Planner

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "scenarios"
FILES = [EXAMPLES / "benign_straight.xosc", EXAMPLES / "benign_parked_car.xosc"]


def _steps(out: str, label: str) -> int:
    return int(re.search(rf"^{label}: 2 runs, (\d+) steps", out, re.M).group(1))


def test_a_coarser_step_is_priced_in_steps_and_verdicts(capsys) -> None:
    regress.compare_settings(FILES, dt=0.1)
    out = capsys.readouterr().out
    defaults, coarse = _steps(out, "defaults"), _steps(out, "settings")
    assert abs(coarse - defaults / 2) <= 2                   # 20 Hz -> 10 Hz, the same simulated time
    assert re.search(r"verdict differs in \d of 2 runs", out)


def test_planning_every_other_frame_holds_the_command_and_is_undone() -> None:
    from txt2sce_ros.closed_loop import run_closed_loop

    plain = run_closed_loop(FILES[1], keep_trajectory=True)[1]
    original = regress._hold_between_plans(2)
    try:
        held = run_closed_loop(FILES[1], keep_trajectory=True)[1]
    finally:
        Planner.step = original
    again = run_closed_loop(FILES[1], keep_trajectory=True)[1]
    assert held["ego"].tobytes() != plain["ego"].tobytes()
    assert again["ego"].tobytes() == plain["ego"].tobytes()   # the planner is itself again
