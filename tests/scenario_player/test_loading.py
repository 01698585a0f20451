"""Bad input is reported by file, element and line; unsupported elements are listed, never silently skipped."""

from __future__ import annotations

from pathlib import Path

import pytest

from scenario_player import Simulation, SimulationConfig, load_scenario
from txt2sce_ros.errors import InputError

from .conftest import xosc


def _variant(esmini: Path, tmp_path: Path, name: str, old: str, new: str) -> Path:
    """A copy of a real example with one edit, placed beside the original so its relative paths still resolve."""
    text = xosc(name).read_text(encoding="utf-8")
    assert old in text
    out = tmp_path / f"{name}_variant.xosc"
    out.write_text(text.replace(old, new, 1).replace("../xodr/", f"{esmini}/xodr/").replace(
        "../xosc/Catalogs", f"{esmini}/xosc/Catalogs"), encoding="utf-8")
    return out


def test_every_example_loads(esmini: Path) -> None:
    for path in sorted((esmini / "xosc").glob("*.xosc")):
        sc = load_scenario(path)
        assert sc.entities, path.name
        assert sc.network.roads, path.name


def test_malformed_xml_names_file_and_line(esmini: Path, tmp_path: Path) -> None:
    bad = _variant(esmini, tmp_path, "cut-in", "</Entities>", "</Entitie>")
    with pytest.raises(InputError) as info:
        load_scenario(bad)
    assert info.value.source == str(bad)
    assert info.value.line is not None and info.value.line > 30
    assert "malformed XML" in str(info.value)


def test_unknown_entity_reference_is_rejected_at_load(esmini: Path, tmp_path: Path) -> None:
    bad = _variant(esmini, tmp_path, "cut-in", '<Private entityRef="OverTaker">', '<Private entityRef="Ghost">')
    with pytest.raises(InputError, match="unknown entity reference 'Ghost'") as info:
        load_scenario(bad)
    assert info.value.element == "Private" and info.value.line is not None


def test_unknown_catalog_entry_is_rejected(esmini: Path, tmp_path: Path) -> None:
    bad = _variant(esmini, tmp_path, "cut-in", 'value="car_red"', 'value="no_such_car"')
    with pytest.raises(InputError, match="no_such_car"):
        load_scenario(bad)


def test_unsupported_action_is_listed_with_its_line_and_the_run_goes_on(esmini: Path, tmp_path: Path) -> None:
    # Replace the lane change by a VisibilityAction (valid OpenSCENARIO, not implemented by this player).
    text = xosc("cut-in").read_text(encoding="utf-8")
    start = text.index("<LateralAction>")
    end = text.index("</LateralAction>") + len("</LateralAction>")
    line = text[:start].count("\n") + 1
    out = tmp_path / "cut-in_visibility.xosc"
    out.write_text((text[:start] + '<VisibilityAction graphics="true" traffic="false" sensors="false"/>'
                    + text[end:]).replace("../xodr/", f"{esmini}/xodr/").replace(
        "../xosc/Catalogs", f"{esmini}/xosc/Catalogs"), encoding="utf-8")
    sc = load_scenario(out)
    assert sc.unsupported == (f"unsupported: VisibilityAction at line {line}",)
    sim = Simulation(sc, SimulationConfig(ego_mode="storyboard", time_limit=8.0))
    status = sim.run()
    assert status.end_reason == "time_limit"
    assert f"unsupported: VisibilityAction at line {line}" in status.unsupported


def test_missing_map_is_an_input_error(esmini: Path, tmp_path: Path) -> None:
    bad = _variant(esmini, tmp_path, "cut-in", "e6mini.xodr", "nowhere.xodr")
    with pytest.raises(InputError, match="nowhere.xodr") as info:
        load_scenario(bad)
    assert info.value.element == "LogicFile"


def test_runtime_reference_to_missing_lane_is_an_input_error(esmini: Path, tmp_path: Path) -> None:
    bad = _variant(esmini, tmp_path, "cut-in", 'laneId="-3" offset="0" s="$EgoStartS"',
                   'laneId="-9" offset="0" s="$EgoStartS"')
    sim = Simulation(load_scenario(bad), SimulationConfig(ego_mode="storyboard"))
    with pytest.raises(InputError, match="lane -9"):
        sim.reset()
