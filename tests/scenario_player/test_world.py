"""World pieces on real maps: lane tracks, collisions, signals, measurements."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from scenario_player import Simulation, SimulationConfig, load_scenario
from scenario_player.world.collision import obb_overlap
from scenario_player.world.lanes import TrackCache
from scenario_player.world.signals import state_of
from txt2sce_ros.contract import SignalState
from txt2sce_ros.road import load_network

from .conftest import xosc

CURVE_MAP = Path(__file__).with_name("conformance_cases") / "xodr" / "curve_r100.xodr"


def test_lane_track_matches_the_road_model(esmini) -> None:
    sc = load_scenario(xosc("lane_change_crest"))          # curved road (crest-curve.xodr)
    net = sc.network
    cache = TrackCache.of(net)
    track = cache.at("0", -1, 100.0)
    for s in (3.3, 100.0, 171.7, track.s1 - 0.5):
        x, y, h = track.pose(s, 0.4)
        rx, ry, rh = net.lane_to_world("0", -1, s, 0.4)
        assert math.hypot(x - rx, y - ry) < 2e-3
        assert abs(math.remainder(h - rh, 2 * math.pi)) < 1e-3
    # Steps of 0.1 m, each turned into road s where it starts, cover 10 m of the lane centre (the curve's
    # 1/(1 - k·t) scale: without it the path would be 10·(1 - k·t) m long). Radius 100 m from s = 500.
    track = TrackCache.of(load_network(CURVE_MAP)).at("0", -1, 550.0)
    s, path = 550.0, 0.0
    px, py, _ = track.pose(s)
    for _ in range(100):
        s, left = track.advance(s, 0.1 * track.ds_per_metre(s))
        assert left == 0.0
        x, y, _ = track.pose(s)
        path += math.hypot(x - px, y - py)
        px, py = x, y
    assert path == pytest.approx(10.0, abs=2e-3)
    assert abs(s - 560.0) > 0.1             # the curve does scale: road s is not the lane's length
    # At the track's end the rest is returned in road s, for the next lane.
    assert track.advance(track.s1 - 1.0, 3.0) == (track.s1, pytest.approx(2.0))


def test_collision_condition_fires_when_footprints_overlap(esmini) -> None:
    sim = Simulation(load_scenario(xosc("pedestrian_collision")), SimulationConfig(ego_mode="storyboard"))
    sim.reset()
    hit_at = None
    while not sim.done:
        sim.step()
        if "pedestrian_adult" in sim.world.entities["Ego"].colliding and hit_at is None:
            hit_at = sim.t
    starts = [t for t, k, n, tr in sim.world.transitions if n == "ped_collide_event" and tr == "start"]
    assert hit_at is not None and starts
    # The event is triggered by the first overlapping step (evaluated at the start of the next one).
    assert starts[0] == pytest.approx(hit_at, abs=1e-9)


def _diamond(cx: float, cy: float) -> list[tuple[float, float]]:
    return [(cx + math.cos(t), cy + math.sin(t)) for t in (0.0, math.pi / 2, math.pi, 3 * math.pi / 2)]


def test_oriented_box_overlap() -> None:
    square = [(1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0), (1.0, -1.0)]
    assert not obb_overlap(square, _diamond(2.1, 0.0))       # left tip at x = 1.1
    assert obb_overlap(square, _diamond(1.9, 0.0))           # left tip at x = 0.9
    # Axis-aligned bounds overlap near the corner, the rotated box does not: only a separating axis shows it.
    assert not obb_overlap(square, _diamond(1.8, 1.8))
    assert obb_overlap(square, _diamond(1.4, 1.4))


def test_signal_states_and_lights_in_frames(esmini) -> None:
    assert state_of("off;on;off") is SignalState.YELLOW
    assert state_of("on;off") is SignalState.RED
    assert state_of("green") is SignalState.GREEN
    sim = Simulation(load_scenario(xosc("traffic_lights")), SimulationConfig(ego_mode="storyboard"))
    frame = sim.reset()
    lights = {lt.id: lt for lt in frame.lights}
    assert lights["1"].state is SignalState.GREEN          # set by Init
    seen = set()
    while not sim.done:
        frame = sim.step()
        seen.add({lt.id: lt for lt in frame.lights}["1"].state)
    assert {SignalState.GREEN, SignalState.YELLOW, SignalState.RED} <= seen
    assert math.isfinite(lights["1"].stop_x) and lights["1"].road_id
