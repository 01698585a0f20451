"""The ASAM life cycle on real files: transitions, priorities, maximumExecutionCount, edges and delays."""

from __future__ import annotations

from scenario_player import Simulation, SimulationConfig, load_scenario

from .conftest import xosc


def _run(name: str, **kw: object) -> Simulation:
    sim = Simulation(load_scenario(xosc(name)), SimulationConfig(ego_mode="storyboard", **kw))  # type: ignore[arg-type]
    sim.run()
    return sim


def _events(sim: Simulation, kind: str, name: str) -> list[tuple[float, str]]:
    return [(t, tr) for t, k, n, tr in sim.world.transitions if k == kind and n == name]


def test_overwrite_priority_stops_the_running_event(esmini) -> None:
    sim = _run("cut-in")
    # The continuous relative speed event runs until CutInEvent (priority overwrite) starts and stops it.
    start = _events(sim, "event", "OverTakerStartSpeedEvent")
    cut_in = _events(sim, "event", "CutInEvent")
    assert start[0][1] == "start" and start[-1][1] == "stop"
    assert cut_in[0] == (start[-1][0], "start")
    # The stop trigger waits 5 s after the maneuver's end transition.
    maneuver_end = [t for t, tr in _events(sim, "maneuver", "CutInManeuver") if tr == "end"][0]
    assert sim.status.end_reason == "stop_trigger"
    assert abs(sim.t - (maneuver_end + 5.0)) < 0.051


def test_maximum_execution_count_repeats_events(esmini) -> None:
    sim = _run("lane_change_simple")
    teleports = [tr for _, tr in _events(sim, "event", "End Of Road teleport event")]
    speeds = [tr for _, tr in _events(sim, "event", "End Of Road speed event")]
    # maximumExecutionCount 3 and 2: started (and ended) exactly that often, then complete.
    assert teleports.count("start") == 3 and teleports.count("end") == 3
    assert speeds.count("start") == 2
    act_states = [tr for _, tr in _events(sim, "act", "Lane change act")]
    assert act_states == ["start", "end"]


def test_transitions_follow_start_then_end_order(esmini) -> None:
    sim = _run("highway_merge")
    for (kind, name), element in sim.world.elements.items():
        seq = [tr for t, k, n, tr in sim.world.transitions if k == kind and n == name]
        for a, b in zip(seq, seq[1:]):
            assert (a, b) in {("start", "end"), ("end", "start"), ("start", "stop"), ("end", "stop"),
                              ("skip", "start"), ("skip", "skip"), ("start", "skip")}, (kind, name, seq)


def test_rising_edge_is_not_fired_by_a_condition_already_true(esmini) -> None:
    # traffic_lights.xosc: DriveOnGreenEvent waits for a *rising* green; green is set in Init, so the event only
    # fires after red -> green, more than 10 s later (firing at once would make the car miss the red light).
    sim = _run("traffic_lights")
    starts = [t for t, tr in _events(sim, "event", "DriveOnGreenEvent") if tr == "start"]
    assert len(starts) == 1 and starts[0] > 15.0


def test_delay_shifts_a_condition(esmini) -> None:
    sim = _run("traffic_lights")
    red = [t for t, tr in _events(sim, "event", "StopLightEvent2") if tr == "start"][0]
    green = [t for t, tr in _events(sim, "event", "StopLightEvent3") if tr == "start"][0]
    # StopLightEvent3: red for 10 s (delay 10) -> green.
    assert abs((green - red) - 10.0) < 0.11
