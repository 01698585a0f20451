"""Verdicts: pass / fail / error never mixed; Table VI's exclusivity; nothing observed is never a pass."""

from __future__ import annotations

import pytest

from oracle_monitor import Category, Oracle, OracleParams, Rule
from oracle_monitor.params import OracleParams as P
from txt2sce_ros.contract import Goal, RunStatus, SignalState, TrafficLightState, Verdict
from txt2sce_ros.errors import InputError

from .oracle_runs import car, finished, judge, straight_run

PARAMS = OracleParams.from_config()


def red(t: float) -> list[TrafficLightState]:
    return [TrafficLightState("sig1", SignalState.RED, 50.0, 0.0, 0.0)]


def test_red_light_then_crash_is_misinterp_only() -> None:
    # Runs the red at 4.65 s, then hits a car waiting 15 m past the line: the earliest misbehaviour decides.
    frames = straight_run(lambda t: 10.0, 8.0, lights=red, objects=lambda t: [car("crossing", t, 65.0)])
    verdict, online = judge(Oracle(None, Goal(200.0, 0.0, 0.0), PARAMS), frames, finished(8.0, "collision"))
    assert [v.rule for v in online][:2] == [Rule.RED_LIGHT, Rule.CONTACT]
    assert verdict.verdict is Verdict.FAIL and verdict.category_names() == ("Misinterp",)
    suppressed = {f.category for f in verdict.suppressed}
    assert suppressed == {Category.COLLISIONS, Category.PLAN_FAIL}
    assert next(f for f in verdict.suppressed if f.category is Category.COLLISIONS).entities == ("crossing",)


def test_crash_first_then_red_is_collisions() -> None:
    frames = straight_run(lambda t: 10.0, 8.0, lights=red, objects=lambda t: [car("lead", t, 30.0)])
    verdict, _ = judge(Oracle(None, None, PARAMS), frames)
    assert verdict.category_names() == ("Collisions",)


def test_planfail_and_smooth_overlap() -> None:
    # A jerky start (0 -> 2 m/s² at once) and a time out short of the goal.
    frames = straight_run(lambda t: 1.0 * t * t if t < 1.0 else 1.0 + 2.0 * (t - 1.0), 6.0)
    verdict, _ = judge(Oracle(None, Goal(500.0, 0.0, 0.0), PARAMS), frames, finished(6.0, "time_limit"))
    assert verdict.category_names() == ("PlanFail", "Smooth")


def test_error_runs_carry_no_categories() -> None:
    frames = straight_run(lambda t: 10.0, 8.0, objects=lambda t: [car("lead", t, 30.0)])
    status = RunStatus("s1", "finished", t=8.0, end_reason="planner_not_responding", verdict_hint="error")
    verdict, online = judge(Oracle(None, None, PARAMS), frames, status)
    assert online, "violations are still observed online"
    assert verdict.verdict is Verdict.ERROR and verdict.categories == () and verdict.suppressed == ()
    assert "planner_not_responding" in verdict.error and verdict.summary().startswith("error")


def test_nothing_observed_is_an_error_not_a_pass() -> None:
    verdict = Oracle(None, None, PARAMS).finish(finished(10.0))
    assert verdict.verdict is Verdict.ERROR and "nothing observed" in verdict.error


def test_a_run_without_an_end_is_an_error_even_when_calm() -> None:
    frames = straight_run(lambda t: 10.0, 3.0)
    verdict, _ = judge(Oracle(None, None, PARAMS), frames, None)
    assert verdict.verdict is Verdict.ERROR and "no final run status" in verdict.error


def test_verdict_serialises_and_is_stable() -> None:
    frames = straight_run(lambda t: 10.0, 8.0, lights=red)
    a, _ = judge(Oracle(None, None, PARAMS), frames)
    b, _ = judge(Oracle(None, None, PARAMS), frames)
    assert a == b and a.to_json() == b.to_json()
    assert '"Misinterp"' in a.to_json() and "Misinterp@4.65s(sig1)" in a.summary()


def test_config_rejects_unknown_keys_and_bad_rules(tmp_path) -> None:
    bad = tmp_path / "oracle.yaml"
    bad.write_text("safety:\n  jerk_treshold: 200\n")
    with pytest.raises(InputError, match="safety.jerk_treshold"):
        P.from_config(str(bad))
    bad.write_text("safety:\n  collision_rule: bump\n")
    with pytest.raises(InputError, match="collision_rule"):
        P.from_config(str(bad))
    assert PARAMS.safety.jerk_threshold == 300.0 and PARAMS.smoothness.jerk_high == 0.9
    assert PARAMS.smoothness.yaw_rate_limit_deg == 10.0 and PARAMS.smoothness.window == 1.0


def test_invalid_scenario_is_an_error_with_the_players_reason() -> None:
    status = RunStatus("bad", "finished", 0.0, "input_error: bad.xosc, line 3: <Storyboard> missing",
                       verdict_hint="error")
    verdict = Oracle(None, None, PARAMS).finish(status)
    assert verdict.verdict is Verdict.ERROR and "input_error" in verdict.error


def test_unsupported_elements_are_noted() -> None:
    frames = straight_run(lambda t: 10.0, 3.0)
    status = RunStatus("s", "finished", 3.0, "stop_trigger", unsupported=("unsupported: <SynchronizeAction> at line 40",))
    verdict, _ = judge(Oracle(None, None, PARAMS), frames, status)
    assert verdict.verdict is Verdict.PASS and any("SynchronizeAction" in n for n in verdict.notes)


def test_records_serialise_every_field() -> None:
    # Violation, Finding and RunStatus write their fields one by one (not `dataclasses.asdict`, whose deep copy was
    # most of a recorded verdict's cost): every field is there, with the values `asdict` gave (enums by value,
    # tuples as lists), so a field added later cannot go missing from the recordings.
    import dataclasses
    import json

    from oracle_monitor.records import Finding, Violation

    v = Violation(Rule.CONTACT, Category.COLLISIONS, 1.25, 0.5, 0.0, "m", ("a", "b"), "hit")
    f = Finding(Category.PLAN_FAIL, 2.5, Rule.GOAL_NOT_REACHED, 115.0, 3.0, "m", ("ego",), "far", 3)
    for rec in (v, f, Violation(Rule.SMOOTH_JERK, None, 0.1, 2.0, 0.9, "m/s³")):
        expected = dataclasses.asdict(rec)
        expected.update(rule=rec.rule.value, category=rec.category.value if rec.category else None,
                        entities=list(rec.entities))
        assert rec.to_dict() == expected and list(rec.to_dict()) == [x.name for x in dataclasses.fields(rec)]
    s = RunStatus("sid", "finished", 3.5, "goal_reached", "error", ("Trajectory", "Polyline"))
    assert s.to_json() == json.dumps(dataclasses.asdict(s), sort_keys=True)
    assert RunStatus.from_json(s.to_json()) == s
