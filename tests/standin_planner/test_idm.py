import pytest

from standin_planner.idm import braking_decel, free_road_accel, idm_accel, stop_accel
from standin_planner.params import LongitudinalParams

P = LongitudinalParams()


def test_free_road_accelerates_below_and_brakes_above_desired_speed():
    assert free_road_accel(0.0, 10.0, P) == pytest.approx(P.max_accel)
    assert free_road_accel(10.0, 10.0, P) == pytest.approx(0.0)
    assert free_road_accel(12.0, 10.0, P) < 0.0


def test_idm_equilibrium_gap_behind_a_lead_at_the_same_speed():
    v = 8.0
    # At the IDM equilibrium gap the acceleration vanishes: s_e = s* / sqrt(1 - (v/v0)^delta).
    s_star = P.min_gap + v * P.time_headway
    s_eq = s_star / (1.0 - (v / 10.0) ** P.accel_exponent) ** 0.5
    assert idm_accel(v, 10.0, s_eq, v, P) == pytest.approx(0.0, abs=1e-9)
    assert idm_accel(v, 10.0, 0.5 * s_eq, v, P) < -P.comfort_decel / 2
    assert idm_accel(v, 10.0, 2.0 * s_eq, v, P) > 0.0


def test_stop_accel_integrated_stops_before_the_point():
    v, x, dt, target = 12.0, 0.0, 0.01, 80.0
    while v > 0.0:
        a = stop_accel(v, target - x, P, plan_decel=2.5, cruise=free_road_accel(v, 12.0, P))
        v = max(0.0, v + a * dt)
        x += v * dt
    assert 0.0 <= target - x < 1.0


def test_braking_decel_respects_friction():
    assert braking_decel(P, 1.0) == P.planned_stop_decel
    assert braking_decel(P, 0.2) == pytest.approx(P.friction_safety * 0.2 * P.gravity)
