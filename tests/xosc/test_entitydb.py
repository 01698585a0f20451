"""The entity database against facts of the OpenSCENARIO 1.0 schema."""

from __future__ import annotations

import pytest

from txt2sce_ros.errors import InputError
from txt2sce_ros.xosc.entitydb import UNBOUNDED, entity_db


@pytest.fixture(scope="module")
def db():
    return entity_db("1.0")


def test_enumerations(db) -> None:
    assert db.allowed_values("TransitionDynamics", "dynamicsShape") == ["cubic", "linear", "sinusoidal", "step"]
    assert db.allowed_values("Precipitation", "precipitationType") == ["dry", "rain", "snow"]
    assert db.allowed_values("SpeedActionDynamics", "dynamicsDimension") == ["distance", "rate", "time"]
    assert set(db.allowed_values("Vehicle", "vehicleCategory")) >= {"car", "van", "truck", "bus", "motorbike",
                                                                    "bicycle"}
    assert db.allowed_values("Precipitation", "intensity") is None
    assert db.allowed_values("DynamicsShape") == ["cubic", "linear", "sinusoidal", "step"]


def test_structure(db) -> None:
    tags = [c.tag for c in db.children("SpeedAction")]
    assert tags == ["SpeedActionDynamics", "SpeedActionTarget"]
    assert {"LongitudinalAction", "LateralAction", "RoutingAction", "TeleportAction"} <= set(
        db.alternatives("PrivateAction"))
    assert "SpeedAction" in db.alternatives("LongitudinalAction")
    events = next(c for c in db.children("Maneuver") if c.tag == "Event")
    assert events.min_occurs == 1 and events.max_occurs == UNBOUNDED
    assert db.resolve("StartTrigger") == "Trigger"
    assert db.resolve("CollisionCondition/ByType") == "ByObjectType"
    assert "CollisionCondition" in db.parents("ByObjectType")
    assert db.bases("CustomCommandAction") == ["xsd:string"]
    names = {a.name: a for a in db.attributes("Phase")}
    assert names["duration"].required and names["duration"].type == "Double"


def test_ranges_and_checks(db) -> None:
    assert db.numeric_range("Precipitation", "intensity") == (0.0, 1.0)
    assert db.numeric_range("Event", "maximumExecutionCount") == (0.0, 4294967295.0)
    assert db.check_value("Precipitation", "precipitationType", "rain") == "rain"
    assert db.check_value("Phase", "duration", 2.5) == "2.5"
    assert db.check_value("Phase", "duration", "$dur") == "$dur"
    with pytest.raises(InputError, match="precipitationType"):
        db.check_value("Precipitation", "precipitationType", "hail")
    with pytest.raises(InputError, match="intensity"):
        db.check_value("Precipitation", "intensity", 1.5)
    with pytest.raises(InputError, match="maximumExecutionCount"):
        db.check_value("Event", "maximumExecutionCount", 1.5)
    with pytest.raises(InputError, match="not a number"):
        db.check_value("Dimensions", "width", "wide")
    with pytest.raises(InputError, match="no attribute"):
        db.check_value("Dimensions", "depth", 1.0)
    with pytest.raises(InputError, match="not an OpenSCENARIO"):
        db.children("Spaceship")


def test_other_versions_build(db) -> None:
    db13 = entity_db("1.3")
    assert "TrafficSwarmAction" in db13.elements()
    assert "RandomRouteAction" in db13.elements() and "RandomRouteAction" not in db.elements()


def test_enumerated_domains(db) -> None:
    weather = db.enumerations("Weather")
    assert weather == {("Weather", "cloudState"): ["cloudy", "free", "overcast", "rainy", "skyOff"]}
    every = db.enumerations()
    assert ("TransitionDynamics", "dynamicsShape") in every and ("Vehicle", "vehicleCategory") in every
    assert all(vals == sorted(vals) and vals for vals in every.values())
