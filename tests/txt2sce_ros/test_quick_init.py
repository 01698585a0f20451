"""`quick_init` replaces only the `__init__` of the closed loop's per-step records: every decorated class must build
the same instance from the same arguments as the dataclass's own `__init__`, with the same signature, and stay
frozen, comparable, hashable and picklable."""

from __future__ import annotations

import dataclasses
import inspect
import math
import pickle

import pytest

from standin_planner.behaviour import Constraint, EgoOnPath, PathObject, Reason, StopPlan
from standin_planner.planner import Decision, _Braking
from standin_planner.refline import PathPoint
from txt2sce_ros.contract import ControlCommand, EntityState, Frame, SignalState, TrafficLightState
from txt2sce_ros.quick_init import quick_init

DECORATED = (EntityState, TrafficLightState, ControlCommand, Frame, Constraint, StopPlan, PathObject, EgoOnPath,
             Decision, _Braking, PathPoint)


def _twin(cls: type) -> type:
    """The same dataclass with the generated `__init__` (built afresh from the decorated class's fields)."""
    spec = [(f.name, f.type, dataclasses.field(default=f.default)) if f.default is not dataclasses.MISSING
            else (f.name, f.type) for f in dataclasses.fields(cls)]
    return dataclasses.make_dataclass(cls.__name__, spec, frozen=True, slots=True)


def _state(name: str = "npc1") -> EntityState:
    return EntityState(name, "car", 1.5, 10.0, -2.0, 0.3, 4.0, yaw_rate=0.01, center_x=1.2)


SAMPLES = {
    EntityState: (("ego", "car", 0.05, 1.0, 2.0, 0.1, 3.0), {"accel": -1.0, "is_static": True}),
    TrafficLightState: (("tl1", SignalState.RED, 5.0, 6.0, 0.5), {"road_id": "3", "lane_ids": (-1, -2)}),
    ControlCommand: ((0.1, 4.2, -0.02), {}),
    Frame: ((0.1, _state("ego")), {"objects": (_state(),)}),
    Constraint: ((Reason.YIELD, -1.5), {"entity": "npc1", "urgent": True}),
    StopPlan: ((2.5, 0.4), {"lag": 1.2}),
    PathObject: ((_state(), 1.0, 5.5, -0.3, 1.1, 3.9, 0.05), {}),
    EgoOnPath: ((12.0, 15.8, 0.1, 7.0, 0.95), {}),
    Decision: ((0.1, 0.5, 0.0, Reason.CRUISE, "", 0.0, (), True), {}),
    _Braking: ((StopPlan(2.5, 0.4), 2.5, 2.0, 7.0), {}),
    PathPoint: ((1.0, -0.5, math.pi / 4), {}),
}


@pytest.mark.parametrize("cls", DECORATED, ids=lambda c: c.__name__)
def test_the_same_instance_as_the_dataclass_init(cls: type) -> None:
    args, kwargs = SAMPLES[cls]
    twin = _twin(cls)
    assert inspect.signature(cls.__init__) == inspect.signature(twin.__init__)
    got, want = cls(*args, **kwargs), twin(*args, **kwargs)
    names = [f.name for f in dataclasses.fields(cls)]
    assert [getattr(got, n) for n in names] == [getattr(want, n) for n in names]
    assert got == cls(*args, **kwargs) and hash(got) == hash(cls(*args, **kwargs))
    assert pickle.loads(pickle.dumps(got)) == got
    # every field also by keyword, and the defaults are the dataclass's own objects
    by_name = cls(**{n: getattr(got, n) for n in names})
    assert by_name == got
    with pytest.raises(dataclasses.FrozenInstanceError):
        setattr(got, names[0], None)
    with pytest.raises(TypeError):
        cls()                                     # required fields stay required
    with pytest.raises(TypeError):
        cls(*args, nonsense=1, **kwargs)


def test_only_frozen_slotted_plain_dataclasses_are_taken() -> None:
    @dataclasses.dataclass(frozen=True)
    class NoSlots:
        a: int

    @dataclasses.dataclass(slots=True)
    class NotFrozen:
        a: int

    @dataclasses.dataclass(frozen=True, slots=True)
    class Factory:
        a: list = dataclasses.field(default_factory=list)

    @dataclasses.dataclass(frozen=True, slots=True)
    class PostInit:
        a: int

        def __post_init__(self) -> None:
            pass

    for cls in (NoSlots, NotFrozen, Factory, PostInit):
        with pytest.raises(TypeError):
            quick_init(cls)
