"""`txt2sce judge` on whole, damaged and unreadable recordings: output lines and exit status."""

from __future__ import annotations

import json
from pathlib import Path

from txt2sce_ros.cli.main import main
from txt2sce_ros.contract import RunStatus

from .oracle_runs import straight_run
from .test_recording import _frames, _record


def test_judge_prints_verdicts_errors_and_exit_status(tmp_path: Path, capsys) -> None:
    _record(tmp_path / "fail", _frames(), RunStatus("rt1", "finished", 8.0, "time_limit"))
    calm = straight_run(lambda t: 10.0, 12.0)                  # reaches the goal (x = 120) as the run ends
    _record(tmp_path / "pass", calm, RunStatus("rt1", "finished", 12.0, "goal_reached"))

    assert main(["judge", str(tmp_path / "pass")]) == 0
    out = capsys.readouterr().out
    assert "\trt1\tpass" in out and "live verdicts recorded: same" in out

    assert main(["judge", str(tmp_path / "fail"), str(tmp_path / "pass")]) == 1
    out = capsys.readouterr().out
    assert "fail Misinterp@4.65s(sig1)" in out

    mcap = tmp_path / "fail" / "fail.mcap"
    mcap.write_bytes(mcap.read_bytes()[:-3000])
    assert main(["judge", "--json", str(tmp_path / "fail")]) == 2
    captured = capsys.readouterr()
    assert "error:" in captured.err and "readable part" in captured.err
    (line,) = captured.out.splitlines()
    d = json.loads(line)
    assert d["complete"] is False and d["verdict"] == "fail" and d["categories"][0]["category"] == "Misinterp"

    assert main(["judge", str(tmp_path / "missing")]) == 2
    assert "no such bag" in capsys.readouterr().err
