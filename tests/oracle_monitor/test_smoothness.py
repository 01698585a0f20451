"""Smoothness: 1 s moving averages of longitudinal jerk (|avg| <= 0.9 m/s³) and yaw rate (±10 °/s)."""

from __future__ import annotations

import math

import pytest

from oracle_monitor import Category, Oracle, OracleParams, Rule
from oracle_monitor.smoothness import MovingAverage

from .oracle_runs import finished, judge, straight_run, turning_run

PARAMS = OracleParams.from_config()


def _speed_from_jerk(jerk: float, t_on: float, t_off: float):
    """Speed law of a ramp: acceleration grows at `jerk` m/s³ from t_on to t_off, then holds."""
    def v(t: float) -> float:
        if t <= t_on:
            return 5.0
        tau = min(t, t_off) - t_on
        a_end = jerk * tau
        return 5.0 + 0.5 * jerk * tau * tau + a_end * max(0.0, t - t_off)
    return v


def test_moving_average_is_the_mean_of_the_last_second() -> None:
    avg = MovingAverage(1.0)
    out = [avg.push(round(k * 0.05, 9), float(k), 0.05) for k in range(1, 41)]
    assert all(o is None for o in out[:19])              # fewer samples than one second covers
    assert out[19] == pytest.approx(sum(range(1, 21)) / 20)
    assert out[39] == pytest.approx(sum(range(21, 41)) / 20)


@pytest.mark.parametrize("jerk, fires", [(0.5, False), (0.85, False), (1.5, True), (-1.5, True)])
def test_jerk_band_fires_only_outside_0_9(jerk: float, fires: bool) -> None:
    frames = straight_run(_speed_from_jerk(jerk, 1.0, 3.0), 5.0)
    verdict, online = judge(Oracle(None, None, PARAMS), frames)
    events = [v for v in online if v.rule is Rule.SMOOTH_JERK]
    assert bool(events) is fires
    if fires:
        e = events[0]
        assert e.category is Category.SMOOTH and e.units == "m/s³"
        # Raised when the 1 s mean first passes 0.9: after 0.9/|jerk| s of ramp (the mean grows linearly as
        # the window fills with the ramp's samples), with the ramp's sign.
        assert 0.9 < abs(e.observed) < 1.0 and math.copysign(1.0, e.observed) == math.copysign(1.0, jerk)
        assert e.t == pytest.approx(1.0 + 0.9 / abs(jerk), abs=0.06)
        assert verdict.category_names() == ("Smooth",)


def test_signed_reading_flags_gentle_braking_the_magnitude_reading_accepts() -> None:
    frames = straight_run(_speed_from_jerk(-0.5, 1.0, 3.0), 5.0)
    _, online = judge(Oracle(None, None, PARAMS), frames)
    assert not [v for v in online if v.rule is Rule.SMOOTH_JERK]
    signed = PARAMS.with_overrides(smoothness={"jerk_mode": "signed"})
    _, online = judge(Oracle(None, None, signed), frames)
    ev = [v for v in online if v.rule is Rule.SMOOTH_JERK]
    assert ev and ev[0].observed < 0.0 and ev[0].threshold == 0.0
    assert ev[0].t == pytest.approx(1.05)                # the first braking sample already leaves [0, 0.9]


def test_one_event_per_excursion() -> None:
    # Acceleration 0 -> 1 m/s² over [1, 1.5] s, back to 0 over [4, 4.5] s, up again over [8, 8.5] s: three
    # excursions of the 1 s mean jerk (+, -, +), each reported once however long it stays out.
    def accel(t: float) -> float:
        ramp = lambda t0: min(1.0, max(0.0, (t - t0) / 0.5))
        return ramp(1.0) - ramp(4.0) + ramp(8.0)

    speeds, v = {}, 5.0
    for k in range(241):
        t = round(k * 0.05, 9)
        if k:
            v += 0.5 * (accel(t) + accel(t - 0.05)) * 0.05
        speeds[t] = v
    frames = straight_run(lambda t: speeds[round(t, 9)], 12.0)
    _, online = judge(Oracle(None, None, PARAMS), frames)
    events = [e for e in online if e.rule is Rule.SMOOTH_JERK]
    assert [math.copysign(1, e.observed) for e in events] == [1, -1, 1]
    assert [int(e.t) for e in events] == [1, 4, 8]


@pytest.mark.parametrize("deg, fires", [(5.0, False), (9.5, False), (15.0, True), (-15.0, True)])
def test_yaw_rate_band(deg: float, fires: bool) -> None:
    frames = turning_run(8.0, lambda t: math.radians(deg) if t >= 1.0 else 0.0, 4.0)
    verdict, online = judge(Oracle(None, None, PARAMS), frames)
    events = [v for v in online if v.rule is Rule.SMOOTH_YAW_RATE]
    assert bool(events) is fires
    if fires:
        assert events[0].units == "deg/s"
        assert abs(events[0].observed) > 10.0 and abs(events[0].threshold) == 10.0
        assert verdict.finding(Category.SMOOTH) is not None


def test_a_short_swerve_averages_out() -> None:
    # 20 °/s for 0.3 s: a spike, but its 1 s average (6 °/s) stays inside the band, as the paper intends.
    frames = turning_run(8.0, lambda t: math.radians(20.0) if 2.0 <= t < 2.3 else 0.0, 5.0)
    _, online = judge(Oracle(None, None, PARAMS), frames)
    assert not [v for v in online if v.rule is Rule.SMOOTH_YAW_RATE]


def test_steady_cruise_passes() -> None:
    frames = straight_run(lambda t: 10.0, 6.0)
    verdict, online = judge(Oracle(None, None, PARAMS), frames, finished(6.0))
    assert online == [] and verdict.verdict.value == "pass"
