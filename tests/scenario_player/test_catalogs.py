"""Maneuver catalogs with parameter assignments, and storyboard references checked at load."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from scenario_player import Simulation, SimulationConfig, load_scenario
from scenario_player.actions.synchronize import SynchronizeAction
from txt2sce_ros.errors import InputError

from .conftest import xosc


def _cut_in_with_catalog_maneuver(esmini: Path, tmp_path: Path, stop_ref: str) -> Path:
    """cut-in.xosc whose maneuver is HWManeuvers/Synchronize_NPC from the catalog, MS1NPC assigned 150."""
    text = xosc("cut-in").read_text(encoding="utf-8")
    # The catalog maneuver reads $AccRate from the scenario's own declarations (as esmini allows).
    text = text.replace("<ParameterDeclarations>", '<ParameterDeclarations><ParameterDeclaration name="AccRate" '
                        'parameterType="double" value="4"/>', 1)
    text = text.replace("</VehicleCatalog>", "</VehicleCatalog><ManeuverCatalog><Directory "
                        'path="../xosc/Catalogs/Maneuvers"/></ManeuverCatalog>', 1)
    ref = ('<CatalogReference catalogName="HWManeuvers" entryName="Synchronize_NPC"><ParameterAssignments>'
           '<ParameterAssignment parameterRef="MS1NPC" value="${100 + 50}"/></ParameterAssignments>'
           '</CatalogReference>')
    text = re.sub(r'<Maneuver name="CutInManeuver">.*?</Maneuver>', ref, text, count=1, flags=re.S)
    text = text.replace('storyboardElementRef="CutInManeuver"', f'storyboardElementRef="{stop_ref}"')
    text = text.replace('name="CutInAndBrakeAct"', 'name="Synchronize_Act"')    # the catalog's events wait for it
    text = text.replace("../xodr/", f"{esmini}/xodr/").replace("../xosc/Catalogs", f"{esmini}/xosc/Catalogs")
    out = tmp_path / f"cut-in_catalog_{stop_ref}.xosc"
    out.write_text(text, encoding="utf-8")
    return out


def test_maneuver_from_catalog_takes_assigned_parameters(esmini: Path, tmp_path: Path) -> None:
    sc = load_scenario(_cut_in_with_catalog_maneuver(esmini, tmp_path, "Synchronize_NPC"))
    sim = Simulation(sc, SimulationConfig(ego_mode="storyboard", time_limit=5.0))
    maneuver = sim.world.elements[("maneuver", "Synchronize_NPC")]
    events = {e.name: e for e in maneuver.children}
    assert set(events) == {"Synchronize_NPC_Event", "Keep_Relative_Speed_Event_NPC", "Free_Speed_Event_NPC"}
    spec = events["Synchronize_NPC_Event"].children[0].spec
    assert isinstance(spec, SynchronizeAction)
    assert spec.target.s == 150.0            # assigned through ParameterAssignment (an expression)
    assert spec.master_target.s == 300.0     # the catalog's default for MS1EgoS
    assert spec.target.lane_id == -2
    status = sim.run()
    assert status.end_reason == "time_limit"


def test_unknown_storyboard_element_reference_is_rejected_at_load(esmini: Path, tmp_path: Path) -> None:
    with pytest.raises(InputError, match="no maneuver named 'CutInManeuver'") as info:
        load_scenario(_cut_in_with_catalog_maneuver(esmini, tmp_path, "CutInManeuver"))
    assert info.value.line is not None
