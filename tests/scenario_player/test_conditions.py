"""Conditions and signal controllers the esmini examples leave out, on variants of a real file
(straight_500m.xosc: Ego and Target on a straight road)."""

from __future__ import annotations

import re
from pathlib import Path
from typing import Callable

from scenario_player import Simulation, SimulationConfig, load_scenario
from txt2sce_ros.contract import SignalState

from .conftest import xosc


Edit = tuple[str, "str | Callable[[re.Match[str]], str]"]


def _variant(esmini: Path, tmp_path: Path, name: str, edits: list[Edit]) -> Path:
    """A copy of a real example with regex edits (a literal replacement, or a function of the match)."""
    text = xosc(name).read_text(encoding="utf-8")
    for old, new in edits:
        assert re.search(old, text, flags=re.S), old
        text = re.sub(old, new if callable(new) else (lambda _m, _new=new: _new), text, count=1, flags=re.S)
    text = text.replace("../xodr/", f"{esmini}/xodr/").replace("../xosc/Catalogs", f"{esmini}/xosc/Catalogs")
    out = tmp_path / f"{name}_{len(list(tmp_path.iterdir()))}.xosc"
    out.write_text(text, encoding="utf-8")
    return out


def _stop_on(condition: str) -> str:
    """A StopTrigger holding one condition (replaces the file's own)."""
    return (f'<StopTrigger><ConditionGroup><Condition name="under_test" delay="0" conditionEdge="rising">'
            f"{condition}</Condition></ConditionGroup></StopTrigger>")


def _by_entity(entity: str, inner: str) -> str:
    return (f'<ByEntityCondition><TriggeringEntities triggeringEntitiesRule="any"><EntityRef entityRef="{entity}"/>'
            f"</TriggeringEntities><EntityCondition>{inner}</EntityCondition></ByEntityCondition>")


def _stop_time(esmini: Path, tmp_path: Path, condition: str, extra: list[Edit] | None = None) -> float:
    path = _variant(esmini, tmp_path, "straight_500m",
                    [(r"<StopTrigger>.*</StopTrigger>", _stop_on(condition))] + (extra or []))
    sim = Simulation(load_scenario(path), SimulationConfig(ego_mode="storyboard", time_limit=40.0))
    status = sim.run()
    assert status.end_reason == "stop_trigger", status
    return status.t


def test_traveled_distance_and_speed(esmini, tmp_path) -> None:
    sim = Simulation(load_scenario(xosc("straight_500m")), SimulationConfig(ego_mode="storyboard", time_limit=3))
    frame = sim.reset()
    v = frame.ego.speed
    assert v > 0
    t = _stop_time(esmini, tmp_path, _by_entity("Ego", '<TraveledDistanceCondition value="50"/>'))
    # Stops at the first evaluation after 50 m (evaluated on the state at t, shown one step later).
    assert abs(t - (50.0 / v + 0.05)) <= 0.051


def test_relative_distance_freespace_vs_reference_point(esmini, tmp_path) -> None:
    t_ref = _stop_time(esmini, tmp_path, _by_entity("Ego", (
        '<RelativeDistanceCondition entityRef="Target" relativeDistanceType="longitudinal" value="200" '
        'freespace="false" rule="lessThan" coordinateSystem="entity"/>')))
    t_free = _stop_time(esmini, tmp_path, _by_entity("Ego", (
        '<RelativeDistanceCondition entityRef="Target" relativeDistanceType="longitudinal" value="200" '
        'freespace="true" rule="lessThan" coordinateSystem="entity"/>')))
    # The gap between the boxes is a car length shorter than between reference points: it is reached earlier.
    assert t_free < t_ref


def test_parameter_condition_after_parameter_set_action(esmini, tmp_path) -> None:
    story = ('<Story name="setter"><Act name="setter_act"><ManeuverGroup name="setter_mg" maximumExecutionCount="1">'
             '<Actors selectTriggeringEntities="false"/><Maneuver name="setter_m"><Event name="set_go" '
             'priority="overwrite"><Action name="set_go_action"><GlobalAction><ParameterAction parameterRef="Phase">'
             '<SetAction value="go"/></ParameterAction></GlobalAction></Action><StartTrigger><ConditionGroup>'
             '<Condition name="at_2s" delay="0" conditionEdge="none"><ByValueCondition><SimulationTimeCondition '
             'value="2" rule="greaterOrEqual"/></ByValueCondition></Condition></ConditionGroup></StartTrigger>'
             '</Event></Maneuver></ManeuverGroup></Act></Story>')
    anchor = '<StopTrigger><ConditionGroup><Condition name="under_test"'
    extra = [("<ParameterDeclarations>", '<ParameterDeclarations><ParameterDeclaration name="Phase" '
              'parameterType="string" value="wait"/>'),
             (re.escape(anchor), story + anchor)]
    t = _stop_time(esmini, tmp_path, '<ByValueCondition><ParameterCondition parameterRef="Phase" value="go" '
                   'rule="equalTo"/></ByValueCondition>', extra)
    # Set in the step evaluated at t = 2.0; the stop trigger (evaluated first in each step) sees it at 2.05.
    assert abs(t - 2.05) < 1e-9


def test_standstill_after_braking(esmini, tmp_path) -> None:
    brake = ('<PrivateAction><LongitudinalAction><SpeedAction><SpeedActionDynamics dynamicsShape="linear" '
             'value="-8" dynamicsDimension="rate"/><SpeedActionTarget><AbsoluteTargetSpeed value="0"/>'
             '</SpeedActionTarget></SpeedAction></LongitudinalAction></PrivateAction>')
    sim0 = Simulation(load_scenario(xosc("straight_500m")), SimulationConfig(ego_mode="storyboard", time_limit=1))
    v0 = sim0.reset().ego.speed
    # After Ego's Init speed, a braking transition from that speed: it stops after v0/8 s, then stands 1 s.
    t = _stop_time(esmini, tmp_path, _by_entity("Ego", '<StandStillCondition duration="1.0"/>'),
                   [(r'(<Private entityRef="Ego">.*?)</Private>', lambda m: m.group(1) + brake + "</Private>")])
    assert abs(t - (v0 / 8.0 + 1.0)) < 0.2


def test_signal_controller_cycles_its_phases(esmini, tmp_path) -> None:
    ctrl = ('<TrafficSignals><TrafficSignalController name="ctrl" delay="0">'
            '<Phase name="go" duration="4"><TrafficSignalState trafficSignalId="1" state="off;off;on"/></Phase>'
            '<Phase name="caution" duration="2"><TrafficSignalState trafficSignalId="1" state="off;on;off"/></Phase>'
            '<Phase name="stop" duration="6"><TrafficSignalState trafficSignalId="1" state="on;off;off"/></Phase>'
            "</TrafficSignalController></TrafficSignals></RoadNetwork>")
    path = _variant(esmini, tmp_path, "traffic_lights", [("</RoadNetwork>", ctrl),
                                                         (r"<Story .*</Story>", "")])
    sim = Simulation(load_scenario(path), SimulationConfig(ego_mode="storyboard", time_limit=24.0))
    frame = sim.reset()
    states = [(frame.t, {lt.id: lt.state for lt in frame.lights}["1"])]
    while not sim.done:
        frame = sim.step()
        states.append((frame.t, {lt.id: lt.state for lt in frame.lights}["1"]))
    changes = [(t, s) for (t, s), (_, prev) in zip(states[1:], states) if s != prev]
    # Init sets green (TrafficSignalStateAction); the controller then cycles 4 s green, 2 s yellow, 6 s red.
    assert [s for _, s in changes][:4] == [SignalState.YELLOW, SignalState.RED, SignalState.GREEN,
                                           SignalState.YELLOW]
    assert [round(t, 2) for t, _ in changes][:4] == [4.0, 6.0, 12.0, 16.0]


def test_field_less_subclasses_keep_the_records_behaviour() -> None:
    # Subclasses that add no fields reuse their base's generated dataclass methods (not re-decorated, to save
    # start-up time): they must still compare, hash, print and refuse writes as frozen records of their own class.
    import dataclasses
    import pickle

    import pytest

    from scenario_player.conditions.base import Rule
    from scenario_player.conditions.by_entity import AccelerationCondition, SpeedCondition, StandStillCondition
    from txt2sce_ros.road.geometry import Line

    rule = Rule("greaterThan")
    a, b = SpeedCondition(3.0, rule), SpeedCondition(3.0, rule)
    assert a == b and hash(a) == hash(b) and a != SpeedCondition(4.0, rule)
    assert a != AccelerationCondition(3.0, rule)            # same fields, another class
    assert repr(a).startswith("SpeedCondition(value=3.0")
    assert dataclasses.is_dataclass(a) and [f.name for f in dataclasses.fields(a)] == ["value", "rule"]
    assert dataclasses.replace(a, value=5.0) == SpeedCondition(5.0, rule)
    with pytest.raises(dataclasses.FrozenInstanceError):
        a.value = 1.0  # type: ignore[misc]
    with pytest.raises(TypeError):      # as for the base itself (Python 3.11's frozen + slots __setattr__)
        a.other = 1.0  # type: ignore[attr-defined]
    assert StandStillCondition(2.0) == StandStillCondition(2.0) != StandStillCondition(3.0)
    line = Line(s=0.0, x=1.0, y=2.0, hdg=0.5, length=10.0)
    assert pickle.loads(pickle.dumps(line)) == line and line.at(2.0) == pytest.approx((1.0 + 2.0 * 0.8775825618903728,
                                                                                      2.0 + 2.0 * 0.479425538604203,
                                                                                      0.5))
