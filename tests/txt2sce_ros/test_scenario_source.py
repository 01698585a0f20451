"""Envelopes carry a scenario and its map; `write_envelope` lays them out again on another machine (issue 20)."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from txt2sce_ros.errors import InputError
from txt2sce_ros.paths import shared_dir
from txt2sce_ros.scenario_source import envelope_for, write_envelope

ESMINI = shared_dir() / "data" / "conformance" / "esmini"


def _scenario_with_map(tmp_path: Path, filepath: str) -> Path:
    """A real esmini map, named from a scenario by `filepath` (relative with `..`, or absolute)."""
    xodr = sorted((ESMINI / "xodr").glob("*.xodr"))[0]
    scen_dir = tmp_path / "driver" / "scenarios" / "deep"
    scen_dir.mkdir(parents=True)
    target = (scen_dir / filepath).resolve() if not Path(filepath).is_absolute() else Path(filepath)
    target.parent.mkdir(parents=True, exist_ok=True)
    shutil.copy(xodr, target)
    xosc = scen_dir / "s.xosc"
    xosc.write_text(f'<?xml version="1.0"?>\n<OpenSCENARIO><FileHeader revMajor="1" revMinor="0"/>'
                    f'<RoadNetwork><LogicFile filepath="{filepath}"/></RoadNetwork><Entities/><Storyboard/>'
                    f'</OpenSCENARIO>\n', encoding="utf-8")
    return xosc


@pytest.mark.parametrize("filepath", ["../../maps/road.xodr", "road.xodr", "ABS"])
def test_written_envelope_reads_back_the_same(tmp_path: Path, filepath: str) -> None:
    if filepath == "ABS":
        filepath = str(tmp_path / "elsewhere" / "road.xodr")
    env = envelope_for(_scenario_with_map(tmp_path, filepath), scenario_id="s1")
    assert env.map_xodr
    shutil.rmtree(tmp_path / "driver")                 # the worker has none of the driver's files
    if Path(filepath).is_absolute():
        shutil.rmtree(tmp_path / "elsewhere")
    out = write_envelope(env, tmp_path / "worker")
    assert out.is_relative_to(tmp_path / "worker") and out.name == "s.xosc"
    again = envelope_for(out, scenario_id="s1")
    assert again.map_xodr == env.map_xodr
    if Path(filepath).is_absolute():
        assert again.xosc == env.xosc.replace(filepath, "road.xodr")   # pointed at the copy beside it
    else:
        assert again.xosc == env.xosc                  # the scenario's bytes as shipped


def test_missing_map_is_an_input_error_naming_the_scenario(tmp_path: Path) -> None:
    xosc = _scenario_with_map(tmp_path, "road.xodr")
    (xosc.parent / "road.xodr").unlink()
    with pytest.raises(InputError, match="s.xosc"):
        envelope_for(xosc)
