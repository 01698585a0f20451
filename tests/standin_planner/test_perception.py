import numpy as np
import pytest

from standin_planner.faults import Faults
from standin_planner.params import FaultParams, PerceptionParams
from standin_planner.perception import Perception
from txt2sce_ros.contract import EntityState, Frame

EGO = EntityState("ego", "car", 0.0, 0.0, 0.0, 0.0, 0.0)


def _obj(t: float, x: float, speed: float, category: str = "car", name: str = "npc1") -> EntityState:
    return EntityState(name, category, t, x, 0.0, 0.0, speed)


def _frames(xs_speeds, dt=0.05):
    return [Frame(t=k * dt, ego=EGO, objects=(_obj(k * dt, x, v),)) for k, (x, v) in enumerate(xs_speeds)]


def test_latency_reports_the_state_of_that_many_seconds_ago():
    p = Perception(PerceptionParams(latency=0.5), Faults(), FaultParams())
    frames = _frames([(10.0 + k, 1.0) for k in range(40)])
    seen = [p.objects(f)[0] for f in frames]
    assert seen[30].t == pytest.approx(frames[20].t) and seen[30].x == pytest.approx(30.0)
    assert seen[5].t == 0.0                       # before 0.5 s have passed: the oldest state held


def test_stale_tracking_is_exact_at_constant_speed_and_behind_reality_when_braking():
    p = Perception(PerceptionParams(), Faults(stale_tracking=True), FaultParams(stale_tracking_delay=1.0))
    # 2 s at 10 m/s, then braking at 5 m/s² for 1 s.
    states, x, v = [], 0.0, 10.0
    for k in range(60):
        if k >= 40:
            v = max(0.0, v - 5.0 * 0.05)
        states.append((x, v))
        x += v * 0.05
    frames = _frames(states)
    seen = [p.objects(f)[0] for f in frames]
    assert seen[39].x == pytest.approx(frames[39].objects[0].x, abs=1e-6)     # constant speed: no error
    assert seen[59].x > frames[59].objects[0].x + 1.0                          # braking lead: seen too far ahead
    assert seen[59].speed == pytest.approx(10.0)                               # ...and a second-old speed


def test_noise_is_seeded_and_has_the_configured_spread():
    params = PerceptionParams(position_noise=0.5, speed_noise=0.2, seed=3)
    frames = _frames([(50.0, 5.0)] * 400)
    a = [Perception(params, Faults(), FaultParams()).objects(f)[0] for f in frames[:1]]
    b = [Perception(params, Faults(), FaultParams()).objects(f)[0] for f in frames[:1]]
    assert a == b
    p = Perception(params, Faults(), FaultParams())
    xs = np.array([p.objects(f)[0].x for f in frames])
    assert np.std(xs) == pytest.approx(0.5, rel=0.2) and abs(np.mean(xs) - 50.0) < 0.1


def test_ignore_cyclists_drops_bicycles_and_scooters_only():
    objs = (_obj(0.0, 5.0, 3.0, "bicycle", "b"), _obj(0.0, 9.0, 3.0, "scooter", "s"),
            _obj(0.0, 20.0, 3.0, "car", "c"), _obj(0.0, 30.0, 1.4, "pedestrian", "p"))
    f = Frame(t=0.0, ego=EGO, objects=objs)
    seen = Perception(PerceptionParams(), Faults(ignore_cyclists=True), FaultParams()).objects(f)
    assert [o.name for o in seen] == ["c", "p"]
    assert len(Perception(PerceptionParams(), Faults(), FaultParams()).objects(f)) == 4
