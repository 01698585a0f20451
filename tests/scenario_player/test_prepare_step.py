"""`Simulation.prepare_step`: the command-independent half of a step, run by the lock-step node while the planner
works. Splitting a step there (and preparing twice) gives the bits of an unsplit step; the half moves the
storyboard's entities and leaves the planner's ego where it is."""

from __future__ import annotations

from scenario_player import Simulation, SimulationConfig, load_scenario

from .conftest import xosc
from .test_determinism import policy


def _run(name: str, split: bool) -> tuple[dict, list, str]:
    sim = Simulation(load_scenario(xosc(name)), SimulationConfig(ego_mode="planner", time_limit=8.0))
    frame = sim.reset()
    frames = [frame]
    while not sim.done:
        cmd = policy(frame)
        if split:
            ego_before = (sim.ego.x, sim.ego.y, sim.ego.h, sim.ego.speed)
            sim.prepare_step()
            sim.prepare_step()          # a second call before the step does nothing
            if not sim.done:
                assert (sim.ego.x, sim.ego.y, sim.ego.h, sim.ego.speed) == ego_before
        frame = sim.step(cmd)
        frames.append(frame)
    return sim.trajectory, frames, sim.end_reason


def test_split_steps_give_the_bits_of_whole_steps(esmini) -> None:
    for name in ("cut-in", "highway_merge", "traffic_lights", "pedestrian_collision"):
        whole, frames_whole, end_whole = _run(name, split=False)
        split, frames_split, end_split = _run(name, split=True)
        assert end_split == end_whole, name
        assert frames_split == frames_whole, name
        assert whole.keys() == split.keys()
        for ent in whole:
            assert whole[ent].tobytes() == split[ent].tobytes(), (name, ent)


def test_prepare_moves_the_storyboard_entities_only(esmini) -> None:
    sim = Simulation(load_scenario(xosc("cut-in")), SimulationConfig(ego_mode="planner", time_limit=8.0))
    sim.reset()
    sim.step(None)                      # the overtaker speeds up in the first steps
    sim.step(None)
    others = [e for e in sim.world.order if e is not sim.ego and e.present and e.speed > 0]
    assert others, "cut-in has a moving non-ego vehicle"
    before = [(e.x, e.y) for e in others]
    ego = (sim.ego.x, sim.ego.y)
    t = sim.world.t
    sim.prepare_step()
    assert [(e.x, e.y) for e in others] != before
    assert (sim.ego.x, sim.ego.y) == ego and sim.world.t == t     # time moves with the step's second half
    frame = sim.step(None)
    assert frame.t > t
