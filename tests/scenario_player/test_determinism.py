"""Same file, same seed -> bit-identical trajectories (storyboard and planner modes)."""

from __future__ import annotations

import math

import numpy as np

from scenario_player import Simulation, SimulationConfig, load_scenario
from txt2sce_ros.contract import ControlCommand, Frame

from .conftest import xosc


def policy(frame: Frame) -> ControlCommand:
    """A deterministic toy planner: speed up to 12 m/s, weave gently."""
    k = round(frame.t / 0.05)
    return ControlCommand(t=frame.t, speed=min(frame.ego.speed + 0.1, 12.0), yaw_rate=0.03 * math.sin(0.05 * k))


def _planner_run(path, seed: int) -> dict[str, np.ndarray]:
    sim = Simulation(load_scenario(path), SimulationConfig(ego_mode="planner", seed=seed, time_limit=6.0))
    frame = sim.reset()
    while not sim.done:
        frame = sim.step(policy(frame))
    return sim.trajectory


def test_storyboard_runs_are_bit_identical(esmini) -> None:
    runs = []
    for _ in range(2):
        sim = Simulation(load_scenario(xosc("highway_merge")), SimulationConfig(ego_mode="storyboard", seed=3))
        sim.run()
        runs.append(sim.trajectory)
    assert runs[0].keys() == runs[1].keys()
    for name in runs[0]:
        assert runs[0][name].tobytes() == runs[1][name].tobytes()


def test_planner_runs_are_bit_identical_and_reset_restarts(esmini) -> None:
    a = _planner_run(xosc("cut-in"), 0)
    b = _planner_run(xosc("cut-in"), 0)
    for name in a:
        assert a[name].tobytes() == b[name].tobytes()
    # The ego really was driven by the policy (not by its storyboard): it ends near 12 m/s, not 30.
    assert abs(a["Ego"][-1, 4] - 12.0) < 1e-9
    # reset() starts over from Init: the same Simulation object gives the same run again.
    sim = Simulation(load_scenario(xosc("cut-in")), SimulationConfig(ego_mode="planner", time_limit=6.0))
    for _ in range(2):
        frame = sim.reset()
        while not sim.done:
            frame = sim.step(policy(frame))
        assert sim.trajectory["Ego"].tobytes() == a["Ego"].tobytes()


def test_simulations_sharing_one_scenario_agree(esmini) -> None:
    # The first Simulation of a Scenario runs the storyboard load_scenario built; later ones build their own; all
    # share the map's route paths. None of that may show in the trajectories.
    scen = load_scenario(xosc("traffic_lights"))
    assert len(scen.prebuilt) == 1
    runs = []
    for _ in range(3):
        sim = Simulation(scen, SimulationConfig(ego_mode="storyboard", time_limit=20.0))
        sim.run()
        runs.append(sim.trajectory)
    assert not scen.prebuilt
    from scenario_player.world.lanes import TrackCache

    assert TrackCache.of(scen.network).paths        # the routes went through the shared path cache
    for other in runs[1:]:
        assert other.keys() == runs[0].keys()
        for name in runs[0]:
            assert other[name].tobytes() == runs[0][name].tobytes()
