"""Parameters and expressions (OpenSCENARIO 1.1 §9), on their own and as resolved in real files."""

from __future__ import annotations

import pytest

from scenario_player import load_scenario
from scenario_player.syntax.params import ParameterScope
from txt2sce_ros.errors import InputError

from .conftest import xosc


def test_references_and_expressions() -> None:
    scope = ParameterScope({"EgoSpeed": "108", "F": "1.2", "Name": "car_white"})
    assert scope.resolve("$Name") == "car_white"
    assert float(scope.resolve("${$EgoSpeed / 3.6}")) == pytest.approx(30.0)
    assert scope.resolve("${2 * ($F + 0.8)}") == "4"
    assert scope.resolve("${sqrt(16) + round(1.5)}") == "6"
    assert scope.resolve("plain") == "plain"


def test_inner_scope_shadows_outer() -> None:
    outer = ParameterScope({"owner": "Ego"})
    inner = outer.child()
    inner.values["owner"] = "OverTaker"
    assert inner.resolve("$owner") == "OverTaker"
    assert outer.resolve("$owner") == "Ego"


def test_string_concatenation_names_as_esmini() -> None:
    # cut-in.xosc names a condition "${BrakeCondition_HWT + _ + $HeadwayTime_Brake}".
    scope = ParameterScope({"HeadwayTime_Brake": "0.7"})
    assert scope.resolve("${BrakeCondition_HWT + _ + $HeadwayTime_Brake}") == "BrakeCondition_HWT_0.7"


def test_undeclared_parameter_is_an_input_error() -> None:
    with pytest.raises(InputError, match=r"\$nope"):
        ParameterScope().resolve("$nope", source="f.xosc", element="X", line=3)


def test_catalog_entry_parameters_and_global_expression_resolved(esmini) -> None:
    sc = load_scenario(xosc("cut-in"))
    ego = next(e for e in sc.entities if e.name == "Ego")
    # car_white from the VehicleCatalog: MaxSpeed declared as ${250/3.6}, axles give the wheelbase.
    assert ego.max_speed == pytest.approx(250 / 3.6)
    assert ego.max_accel == 5.0 and ego.max_decel == 10.0
    assert ego.wheelbase == pytest.approx(2.98)
    assert ego.length == pytest.approx(5.04) and ego.center_x == pytest.approx(1.4)
    assert float(sc.doc.parameters["EgoSpeed"]) == 108.0
