"""`txt2sce bench batch_cpu` on a few files: the rounds run, both checkouts given reach the same end times, and a
directory that is not a checkout is refused."""

from __future__ import annotations

from pathlib import Path

import pytest

from txt2sce_ros.bench import batch_cpu
from txt2sce_ros.bench._vs_esmini import available

HERE = Path(batch_cpu.__file__).resolve().parents[2]


@pytest.mark.skipif(not available(), reason="shared esmini not found")
def test_two_rounds_over_every_25th_file(capsys) -> None:
    assert batch_cpu.main(["--rounds", "2", "--every", "25", "--checkouts", str(HERE), str(HERE)]) == 0
    out = capsys.readouterr().out
    assert out.count("round ") == 2
    assert "end times reached: the same in every checkout" in out
    assert out.count("speed-up over esmini median") == 2


def test_a_directory_without_the_player_is_refused(tmp_path: Path) -> None:
    if not available():
        pytest.skip("shared esmini not found")
    with pytest.raises(SystemExit, match="not a checkout"):
        batch_cpu.main(["--rounds", "1", "--checkouts", str(tmp_path)])


def test_a_checkouts_child_runs_that_checkouts_player_from_any_directory(tmp_path: Path, monkeypatch) -> None:
    """Started inside another tree, the child must not import that tree's packages (`python -c` puts the current
    directory first on sys.path): here the current directory holds a `txt2sce_ros` that cannot be imported."""
    shadow = tmp_path / "txt2sce_ros"
    shadow.mkdir()
    (shadow / "__init__.py").write_text("raise ImportError('the current directory was imported')\n")
    monkeypatch.chdir(tmp_path)
    from txt2sce_ros.paths import shared_dir

    xosc = shared_dir() / "data" / "conformance" / "esmini" / "xosc" / "straight_500m.xosc"
    if not xosc.is_file():
        pytest.skip("shared esmini conformance data not present")
    _cpu, _wall, reached = batch_cpu._child(HERE, f'[["{xosc}", 1.0]]')
    assert reached == [1.0]
