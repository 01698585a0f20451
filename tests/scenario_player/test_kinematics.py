"""The planner-driven ego: performance limits, steering limits, friction and wheel slip."""

from __future__ import annotations

import math

import pytest

from scenario_player import Simulation, SimulationConfig, load_scenario
from scenario_player.world.kinematics import G, bicycle_command
from txt2sce_ros.contract import ControlCommand

from .conftest import xosc

CAR = dict(wheelbase=2.98, max_steer=0.5236, max_accel=5.0, max_decel=10.0, max_speed=69.4)


def test_acceleration_and_braking_within_performance() -> None:
    r = bicycle_command(10.0, 30.0, 0.0, 0.05, friction=1.0, **CAR)
    assert r.accel == pytest.approx(5.0) and not r.slipping
    r = bicycle_command(10.0, 0.0, 0.0, 0.05, friction=1.0, **CAR)
    assert r.accel == pytest.approx(-min(10.0, G))       # performance 10 m/s², friction μg = 9.81 m/s²


def test_low_friction_caps_braking() -> None:
    r = bicycle_command(20.0, 0.0, 0.0, 0.05, friction=0.3, **CAR)
    assert r.accel == pytest.approx(-0.3 * G)


def test_steering_limit_caps_yaw_rate() -> None:
    r = bicycle_command(5.0, 5.0, 3.0, 0.05, friction=1.0, **CAR)
    assert r.yaw_rate == pytest.approx(5.0 * math.tan(0.5236) / 2.98)


def test_high_throttle_and_steering_on_low_friction_slips_and_does_not_start() -> None:
    r = bicycle_command(0.0, 0.25, 0.8, 0.05, friction=0.1, **CAR)   # asks 5 m/s² while steering hard, μ = 0.1
    assert r.slipping and r.speed == 0.0
    gentle = bicycle_command(0.0, 0.02, 0.0, 0.05, friction=0.1, **CAR)   # 0.4 m/s² straight: within μg
    assert not gentle.slipping and gentle.speed == pytest.approx(0.02)


def test_planner_ego_in_a_real_scenario_follows_commands(esmini) -> None:
    sim = Simulation(load_scenario(xosc("cut-in")), SimulationConfig(ego_mode="planner", time_limit=2.0))
    frame = sim.reset()
    start = frame.ego
    assert start.speed == pytest.approx(30.0)            # Init speed applies; then the planner drives
    while not sim.done:
        frame = sim.step(ControlCommand(t=frame.t, speed=frame.ego.speed - 0.25, yaw_rate=0.0))   # -5 m/s²
    ego = sim.trajectory["Ego"]
    assert ego[-1, 4] == pytest.approx(30.0 - 5.0 * 2.0)
    travelled = math.hypot(ego[-1, 1] - ego[0, 1], ego[-1, 2] - ego[0, 2])
    assert travelled == pytest.approx(0.5 * (30.0 + 20.0) * 2.0, rel=1e-6)


def _with_friction(esmini, tmp_path, friction: float):
    """lane_change_simple.xosc (ego starts standing) with an Init EnvironmentAction setting the road friction."""
    text = xosc("lane_change_simple").read_text(encoding="utf-8")
    env = (f'<GlobalAction><EnvironmentAction><Environment name="env"><TimeOfDay animation="false" '
           f'dateTime="2020-01-01T12:00:00"/><Weather cloudState="free"/><RoadCondition '
           f'frictionScaleFactor="{friction}"/></Environment></EnvironmentAction></GlobalAction>')
    text = text.replace("<Actions>", "<Actions>" + env, 1)
    text = text.replace("../xodr/", f"{esmini}/xodr/").replace("../xosc/Catalogs", f"{esmini}/xosc/Catalogs")
    path = tmp_path / f"friction_{friction}.xosc"
    path.write_text(text, encoding="utf-8")
    return path


def test_full_throttle_and_steering_on_ice_does_not_start(esmini, tmp_path) -> None:
    moved = {}
    for mu in (0.1, 1.0):
        sim = Simulation(load_scenario(_with_friction(esmini, tmp_path, mu)),
                         SimulationConfig(ego_mode="planner", time_limit=2.0))
        frame = sim.reset()
        assert frame.ego.speed == 0.0 and sim.world.friction == pytest.approx(mu)
        while not sim.done:
            frame = sim.step(ControlCommand(t=frame.t, speed=frame.ego.speed + 0.25, yaw_rate=0.5))
        ego = sim.trajectory["Ego"]
        moved[mu] = math.hypot(ego[-1, 1] - ego[0, 1], ego[-1, 2] - ego[0, 2])
        slip_notes = [n for n in sim.status.unsupported if "slipped" in n]
        assert bool(slip_notes) == (mu == 0.1)
    assert moved[0.1] == 0.0          # wheels spin, no start
    assert moved[1.0] > 5.0           # on a dry road the same commands pull away
