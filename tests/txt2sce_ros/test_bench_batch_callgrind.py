"""`bench._batch_callgrind split` (the batch player's set-up and steps apart, for callgrind): run natively on a job
of two esmini examples it steps every run to the job's end time and reports the steps taken."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from txt2sce_ros.bench import _batch_callgrind
from txt2sce_ros.paths import shared_dir

XOSC = shared_dir() / "data" / "conformance" / "esmini" / "xosc"


def test_split_steps_every_run_to_its_end_time(tmp_path: Path, capsys) -> None:
    if not XOSC.is_dir():
        pytest.skip("shared esmini conformance data not present")
    job = tmp_path / "job.json"
    job.write_text(json.dumps([[str(XOSC / "cut-in.xosc"), 2.0], [str(XOSC / "straight_500m.xosc"), 1.5]]))
    assert _batch_callgrind.main(["split", str(job)]) == 0
    steps, ends = capsys.readouterr().out.split(" ", 1)
    assert int(steps) == 40 + 30
    assert json.loads(ends) == [2.0, 1.5]


def test_unknown_use_prints_the_usage(capsys) -> None:
    assert _batch_callgrind.main(["nothing"]) == 2
    assert "callgrind" in capsys.readouterr().out
