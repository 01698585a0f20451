"""Failures the scripted parties made unavoidable: labelled beside the verdict, never hiding one braking avoids."""

from __future__ import annotations

import math

import numpy as np
import pytest

from oracle_monitor import Category, Oracle, OracleParams
from oracle_monitor.unavoidable import emergency_stop, smooth_stop
from txt2sce_ros.contract import Goal

from .oracle_runs import DT, car, finished, judge, straight_run

PARAMS = OracleParams.from_config()


def test_the_smoothest_stop_keeps_every_one_second_mean_jerk_in_the_band() -> None:
    v0, jerk = 10.0, 0.9
    d = smooth_stop(v0, jerk)
    t = np.arange(0.0, 12.0, 0.01)
    x = np.array([d(ti) for ti in t])
    v = np.gradient(x, t)
    a = np.gradient(v, t)
    assert x[-1] == pytest.approx(v0 * math.sqrt(v0 / jerk), rel=1e-3)        # v0·T/2
    assert v[0] == pytest.approx(v0, abs=0.05) and abs(v[-1]) < 1e-3
    mean_jerk = (a[100:] - a[:-100]) / 1.0                                     # 1 s means
    assert np.abs(mean_jerk).max() <= jerk + 0.02
    assert emergency_stop(10.0, 8.0)(5.0) == pytest.approx(100.0 / 16.0)


def crossing(x: float, y0: float, speed: float = 10.0):
    """A car driving north across the ego's lane at x, from y0 (south of it)."""
    return lambda t: [car("crosser", t, x, y0 + speed * t, heading=math.pi / 2, speed=speed)]


def test_a_party_that_reaches_the_ego_before_it_could_stop_is_labelled() -> None:
    # Ego at 10 m/s; the crosser reaches its lane at 1.2 s, 10 m ahead: braking at 8 m/s² from the start the ego
    # still stops with its front at ~9.9 m, inside the crosser's path.
    frames = straight_run(lambda t: 10.0, 1.6, objects=crossing(10.0, -12.0))
    verdict, _ = judge(Oracle(None, None, PARAMS), frames, finished(1.6, "collision"))
    assert verdict.category_names() == ("Collisions",)
    assert [u.category for u in verdict.unavoidable] == [Category.COLLISIONS]
    assert verdict.unavoidable[0].entity == "crosser" and not verdict.planner_relevant()
    assert "unavoidable by scripted parties" in verdict.summary()
    assert verdict.to_dict()["unavoidable"][0]["category"] == "Collisions"


def test_a_crash_braking_could_have_avoided_is_not_labelled() -> None:
    # The same crossing 30 m ahead at 3 s: in view and on course from the start, a stop was possible.
    frames = straight_run(lambda t: 10.0, 3.4, objects=crossing(30.0, -30.0))
    verdict, _ = judge(Oracle(None, None, PARAMS), frames, finished(3.4, "collision"))
    assert verdict.category_names() == ("Collisions",)
    assert verdict.unavoidable == () and verdict.planner_relevant()


def test_a_cut_in_too_late_to_stop_for_is_labelled() -> None:
    # A car alongside in the next lane swerves into the ego 0.4 s before the contact: its course met the ego's path
    # only then, and no stop from then avoids it.
    def cutter(t: float):
        y = 3.5 if t < 2.0 else max(0.0, 3.5 - 6.0 * (t - 2.0))
        return [car("cutter", t, 3.0 + 10.0 * t, y, heading=0.0 if t < 2.0 else -0.5, speed=10.0)]
    frames = straight_run(lambda t: 10.0, 2.6, objects=cutter)
    verdict, _ = judge(Oracle(None, None, PARAMS), frames, finished(2.6, "collision"))
    assert verdict.category_names() == ("Collisions",)
    [label] = verdict.unavoidable
    assert label.entity == "cutter" and "when the party's course first met its path" in label.detail


def test_a_goal_missed_behind_a_slow_party_is_labelled_but_not_behind_a_parked_car() -> None:
    slow = lambda t: [car("walker", t, 20.0 + 1.0 * t, speed=1.0, category="pedestrian", length=0.6, width=0.6,
                          center_x=0.0)]
    frames = straight_run(lambda t: 1.0, 20.0, objects=slow)              # follows it at walking pace
    goal = Goal(200.0, 0.0, 0.0)
    verdict, _ = judge(Oracle(None, goal, PARAMS), frames, finished(20.0, "time_limit"))
    assert verdict.category_names() == ("PlanFail",)
    assert [u.entity for u in verdict.unavoidable] == ["walker"]
    parked = lambda t: [car("parked", t, 30.0, is_static=True)]
    frames = straight_run(lambda t: max(0.0, 5.0 - 1.0 * t), 20.0, objects=parked)
    verdict, _ = judge(Oracle(None, goal, PARAMS), frames, finished(20.0, "time_limit"))
    assert verdict.finding(Category.PLAN_FAIL) is not None
    assert Category.PLAN_FAIL not in {u.category for u in verdict.unavoidable}
