"""Smartness: failure to start, failure to reach the goal, misinterpretation of signals and obstacles."""

from __future__ import annotations

import math
from dataclasses import replace

import pytest

from oracle_monitor import Category, Oracle, OracleParams, Rule
from txt2sce_ros.contract import EntityState, Frame, Goal, SignalState, TrafficLightState, Verdict
from txt2sce_ros.road import load_network

from .oracle_runs import DT, car, ego, esmini_map, finished, judge, straight_run

PARAMS = OracleParams.from_config()


def light(state: SignalState, x: float = 50.0, heading: float = 0.0, y: float = 0.0) -> TrafficLightState:
    return TrafficLightState("sig1", state, x, y, heading, road_id="1", lane_ids=(-1,))


def stop_at(t_stop: float, v0: float = 10.0, decel: float = 2.5, t_go: float | None = None, a_go: float = 1.0):
    """Cruise at v0, brake at `decel` from t_stop to standstill, go again at `t_go`."""
    def v(t: float) -> float:
        if t_go is not None and t >= t_go:
            return min(v0, a_go * (t - t_go))
        return max(0.0, v0 - decel * max(0.0, t - t_stop))
    return v


# --- failure to start -------------------------------------------------------------------------------------------

def test_standing_at_the_start_with_a_clear_path_is_startfail() -> None:
    frames = straight_run(lambda t: 0.0, 8.0)
    verdict, online = judge(Oracle(None, None, PARAMS), frames)
    ev = [v for v in online if v.rule is Rule.NO_START]
    assert len(ev) == 1 and ev[0].t == pytest.approx(5.0) and ev[0].units == "s"
    assert verdict.category_names() == ("StartFail",)


def test_waiting_behind_a_car_that_then_leaves_is_not_startfail() -> None:
    lead = lambda t: [car("lead", t, 8.0 + max(0.0, t - 7.0) * 8.0, speed=8.0 if t > 7.0 else 0.0)]
    frames = straight_run(lambda t: 0.0 if t < 7.5 else min(6.0, 1.0 * (t - 7.5)), 12.0, objects=lead)
    verdict, online = judge(Oracle(None, None, PARAMS), frames)
    assert not [v for v in online if v.category is Category.START_FAIL]
    assert verdict.finding(Category.START_FAIL) is None


def test_waiting_at_red_is_not_startfail_but_staying_after_green_is() -> None:
    lights = lambda t: [light(SignalState.RED if t < 6.0 else SignalState.GREEN, x=10.0)]
    frames = straight_run(lambda t: 0.0, 14.0, lights=lights)
    verdict, online = judge(Oracle(None, None, PARAMS), frames)
    ev = [v for v in online if v.rule is Rule.NO_START]
    assert len(ev) == 1 and ev[0].t == pytest.approx(11.0)        # 5 s of clear path after the green at 6 s


def test_never_moving_behind_a_blocker_that_stays_is_not_startfail() -> None:
    frames = straight_run(lambda t: 0.0, 10.0, objects=lambda t: [car("lead", t, 9.0)])
    verdict, _ = judge(Oracle(None, Goal(200.0, 0.0, 0.0), PARAMS), frames, finished(10.0, "time_limit"))
    assert verdict.category_names() == ("PlanFail",)                 # the goal is not reached: a planning failure
    assert verdict.categories[0].rule is Rule.GOAL_NOT_REACHED
    assert "time out" in verdict.categories[0].detail


def test_waiting_for_a_party_about_to_cross_the_path_is_not_startfail() -> None:
    # A car from the right crosses the ego's lane 15 m ahead at 6 m/s, reaching it at ~8.3 s: within the 8 s
    # conflict horizon almost from the start, so the wait counts from when it has crossed (~8.8 s), not from 0.
    cross = lambda t: [car("crosser", t, 15.0, -50.0 + 6.0 * t, heading=math.pi / 2, speed=6.0)]
    frames = straight_run(lambda t: 0.0, 20.0, objects=cross)
    verdict, online = judge(Oracle(None, None, PARAMS), frames)
    ev = [v for v in online if v.rule is Rule.NO_START]
    assert len(ev) == 1 and ev[0].t == pytest.approx(13.8, abs=0.5)
    # A party coming up behind in the ego's lane is no reason to wait: its course runs along the path, not across.
    behind = lambda t: [car("follower", t, -40.0 + 2.0 * t, speed=2.0)]
    verdict, online = judge(Oracle(None, None, PARAMS), straight_run(lambda t: 0.0, 8.0, objects=behind))
    assert [v.t for v in online if v.rule is Rule.NO_START] == [pytest.approx(5.0)]


def test_the_corridor_follows_the_route_into_a_turn() -> None:
    # On a real junction map, an ego standing before a right turn with a car parked across the exit it turns
    # into: the straight corridor ahead is empty, the corridor along its route is not.
    from oracle_monitor.egopath import EgoPath
    from txt2sce_ros.road import RoadNetwork

    net = load_network(esmini_map("fabriksgatan.xodr"))
    starts = [(r, l) for r in net.roads.values() if r.junction in ("-1", "") for l in (-1, 1)
              if l in r.sections[0].lanes]
    assert starts
    found = 0
    for road, lane in starts:
        ref = net.lane_ref(road.id, lane, 0.0)
        nxt = [c for c in net.successors(ref) if net.roads[c.road_id].junction not in ("-1", "")]
        for conn in nxt:
            if net.turn_type(ref, conn) not in ("left", "right"):
                continue
            pts = net.lane_centerline(ref.road_id, ref.lane_id, 0.5, section=ref.section)
            x, y = pts[-12, 0], pts[-12, 1]                  # ~6 m before the junction
            h = math.atan2(pts[-11, 1] - pts[-12, 1], pts[-11, 0] - pts[-12, 0])
            exit_lane = net.successors(conn)[0]
            ex = net.lane_centerline(exit_lane.road_id, exit_lane.lane_id, 0.5, section=exit_lane.section)
            goal = Goal(float(ex[-1, 0]), float(ex[-1, 1]), 0.0)
            e = ego(0.0, float(x), float(y), h)
            routed = EgoPath.plan(net, e, goal)
            assert routed.routed
            cn = net.lane_centerline(conn.road_id, conn.lane_id, 0.5, section=conn.section)
            mx, my = cn[len(cn) // 2, 0], cn[len(cn) // 2, 1]
            parked = car("parked", 0.0, float(mx), float(my), heading=h + math.pi / 2)
            straight = EgoPath.straight(e)
            front = (e.x + 0.5 * e.length * math.cos(h), e.y + 0.5 * e.length * math.sin(h))
            if straight.blocker(e, front, (parked,), clear_distance=20.0, margin=0.5):
                continue                                     # this turn is too tight to tell the two apart
            assert routed.blocker(e, front, (parked,), clear_distance=20.0, margin=0.5) == "parked"
            found += 1
    assert found >= 1


# --- failure to reach the goal ----------------------------------------------------------------------------------

def test_stopping_mid_route_on_a_clear_road_is_planfail() -> None:
    frames = straight_run(stop_at(3.0), 16.0)
    verdict, online = judge(Oracle(None, None, PARAMS), frames)
    ev = [v for v in online if v.rule is Rule.STOPPED_MID_ROUTE]
    assert len(ev) == 1 and ev[0].t == pytest.approx(7.0 + 5.0, abs=2 * DT)   # standstill at 7 s, + 5 s
    assert verdict.finding(Category.PLAN_FAIL) is not None


def test_stopping_behind_a_stopped_car_is_not_planfail() -> None:
    frames = straight_run(stop_at(3.0), 16.0, objects=lambda t: [car("lead", t, 58.0)])
    verdict, online = judge(Oracle(None, None, PARAMS), frames)
    assert not [v for v in online if v.rule is Rule.STOPPED_MID_ROUTE]
    assert not [v for v in online if v.rule is Rule.CONTACT]


def test_goal_reached_passes_and_time_out_fails() -> None:
    frames = straight_run(lambda t: 10.0, 10.0)                     # ends at x = 100
    verdict, _ = judge(Oracle(None, Goal(99.0, 0.0, 0.0), PARAMS), frames, finished(10.0, "goal_reached"))
    assert verdict.verdict is Verdict.PASS and verdict.categories == ()
    verdict, _ = judge(Oracle(None, Goal(150.0, 0.0, 0.0), PARAMS), frames, finished(10.0, "time_limit"))
    f = verdict.finding(Category.PLAN_FAIL)
    assert f is not None and f.rule is Rule.GOAL_NOT_REACHED and f.observed == pytest.approx(50.0)
    assert f.threshold == 3.0 and f.units == "m"


def test_parking_outside_the_lane_on_a_real_map() -> None:
    net = load_network(esmini_map("straight_500m.xodr"))           # road "1": lanes 1 / -1 each ~3 m wide
    # Drive along lane -1 (y = -1.5), pull over to y = -5.5 (beyond the driving lanes) and stop there.
    frames = []
    for k in range(int(12.0 / DT) + 1):
        t = round(k * DT, 9)
        x = 50.0 + min(t, 4.0) * 8.0
        y = -1.5 - 4.0 * min(1.0, max(0.0, (t - 2.0) / 2.0))
        frames.append(Frame(t, ego(t, x, y, 0.0, 8.0 if t < 4.0 else 0.0)))
    verdict, online = judge(Oracle(net, None, PARAMS), frames)
    ev = [v for v in online if v.rule is Rule.PARKED_OUTSIDE_LANE]
    assert len(ev) == 1 and ev[0].observed >= 2 and ev[0].t == pytest.approx(6.0, abs=2 * DT)
    # The same stop inside lane -1 is not parking outside it.
    inside = [replace(f, ego=replace(f.ego, y=-1.5)) for f in frames]
    _, online = judge(Oracle(net, None, PARAMS), inside)
    assert not [v for v in online if v.rule is Rule.PARKED_OUTSIDE_LANE]


# --- misinterpretation ------------------------------------------------------------------------------------------

@pytest.mark.parametrize("state, fires", [(SignalState.RED, True), (SignalState.GREEN, False),
                                          (SignalState.YELLOW, False)])
def test_crossing_a_stop_line(state: SignalState, fires: bool) -> None:
    frames = straight_run(lambda t: 10.0, 8.0, lights=lambda t: [light(state)])
    verdict, online = judge(Oracle(None, None, PARAMS), frames)
    ev = [v for v in online if v.rule is Rule.RED_LIGHT]
    assert bool(ev) is fires
    if fires:
        # front bumper (3.65 m ahead of the rear axle) reaches x = 50 at t = 4.635 s: the first frame past it.
        assert ev[0].t == pytest.approx(4.65) and ev[0].entities == ("sig1",)
        assert verdict.category_names() == ("Misinterp",)


def test_red_after_crossing_and_oncoming_signals_are_not_violations() -> None:
    late = lambda t: [light(SignalState.RED if t > 4.7 else SignalState.GREEN)]
    _, online = judge(Oracle(None, None, PARAMS), straight_run(lambda t: 10.0, 8.0, lights=late))
    assert not [v for v in online if v.rule is Rule.RED_LIGHT]
    oncoming = lambda t: [light(SignalState.RED, heading=math.pi)]
    _, online = judge(Oracle(None, None, PARAMS), straight_run(lambda t: 10.0, 8.0, lights=oncoming))
    assert not [v for v in online if v.rule is Rule.RED_LIGHT]
    beside = lambda t: [light(SignalState.RED, y=12.0)]                  # a signal for a parallel road
    _, online = judge(Oracle(None, None, PARAMS), straight_run(lambda t: 10.0, 8.0, lights=beside))
    assert not [v for v in online if v.rule is Rule.RED_LIGHT]


def test_stopping_at_red_then_going_on_green_passes() -> None:
    lights = lambda t: [light(SignalState.RED if t < 9.0 else SignalState.GREEN)]
    # 10 m/s braking at 2.5 m/s² from t = 2.3 s stops 20 m on, at x = 43: front bumper 3.35 m before the line.
    frames = straight_run(stop_at(2.3, t_go=9.5), 16.0, lights=lights)
    x_stop = max(f.ego.x for f in frames if f.t < 9.0)
    assert x_stop + 3.65 < 50.0, "the constructed run must stop before the line"
    verdict, online = judge(Oracle(None, None, PARAMS), frames)
    assert online == [] or all(v.category is Category.SMOOTH for v in online)
    assert verdict.finding(Category.MISINTERP) is None and verdict.finding(Category.START_FAIL) is None


def _obstacle(t: float, appear_at: float = 0.0) -> list[EntityState]:
    if t < appear_at:
        return []
    return [EntityState("box1", "debris", t, 40.0, 0.0, 0.0, 0.0, length=1.0, width=1.0, center_x=0.0,
                        is_static=True)]


def test_hitting_a_visible_static_obstacle_is_misinterp() -> None:
    frames = straight_run(lambda t: 10.0, 5.0, objects=_obstacle)
    verdict, online = judge(Oracle(None, None, PARAMS), frames)
    ev = [v for v in online if v.rule is Rule.STATIC_OBSTACLE_HIT]
    assert len(ev) == 1 and ev[0].entities == ("box1",) and ev[0].observed > 3.0
    assert verdict.category_names() == ("Misinterp",)


def test_an_obstacle_dropped_in_front_of_the_ego_is_a_collision() -> None:
    frames = straight_run(lambda t: 10.0, 5.0, objects=lambda t: _obstacle(t, appear_at=3.6))
    verdict, online = judge(Oracle(None, None, PARAMS), frames)
    assert [v.rule for v in online if v.entities == ("box1",)] == [Rule.CONTACT]
    assert verdict.category_names() == ("Collisions",)


def test_signal_lanes_decide_on_a_real_map() -> None:
    # straight_500m.xodr, road "1": lane -1 drives +x (y in [-3.07, 0]), lane 1 drives -x. A red signal
    # controlling lane -1, stop point on lane -1's centre at s = 100: an ego driving lane -1 runs it.
    net = load_network(esmini_map("straight_500m.xodr"))
    x, y, h = net.lane_to_world("1", -1, 100.0)
    mine = lambda t: [TrafficLightState("s1", SignalState.RED, x, y, h, "1", (-1,))]
    frames = straight_run(lambda t: 10.0, 12.0, x0=50.0, lights=mine)
    frames = [replace(f, ego=replace(f.ego, y=y)) for f in frames]
    _, online = judge(Oracle(net, None, PARAMS), frames)
    assert [v.rule for v in online if v.rule is Rule.RED_LIGHT] == [Rule.RED_LIGHT]
    # The same stop point and heading, but the signal controls lane 1, not the ego's lane: not the ego's signal.
    other = lambda t: [TrafficLightState("s2", SignalState.RED, x, y, h, "1", (1,))]
    frames2 = straight_run(lambda t: 10.0, 12.0, x0=50.0, lights=other)
    frames2 = [replace(f, ego=replace(f.ego, y=y)) for f in frames2]
    _, online = judge(Oracle(net, None, PARAMS), frames2)
    assert not [v for v in online if v.rule is Rule.RED_LIGHT]
    # Without the map the lateral test applies and (wrongly, but knowingly) counts it.
    _, online = judge(Oracle(None, None, PARAMS), frames2)
    assert [v.rule for v in online if v.rule is Rule.RED_LIGHT] == [Rule.RED_LIGHT]
