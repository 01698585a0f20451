import math

import numpy as np
import pytest

from standin_planner.route import off_route, plan_route
from txt2sce_ros.errors import InputError
from txt2sce_ros.paths import BUNDLED_MAPS
from txt2sce_ros.road import load_network

from .helpers import ESMINI_XODR, goal_on_lane, net


def test_route_through_the_junction_turns_onto_the_goal_road():
    n = net()
    x, y, h = n.lane_to_world("2", -1, 200.0)
    goal = goal_on_lane(n, "1", -1, 12.0)
    route = plan_route(n, x, y, h, goal)
    roads = [ref.road_id for ref in route.lanes]
    assert roads[0] == "2" and roads[-1] == "1"
    assert any(n.roads[r].junction != "-1" for r in roads[1:-1])
    line = route.line
    # The line starts just behind the ego and passes through the goal.
    assert line.project(x, y).s == pytest.approx(10.0, abs=1.0)
    gx, gy, _ = line.position(route.goal_s)
    assert math.hypot(gx - goal.x, gy - goal.y) < 0.5
    assert line.in_junction.any() and not line.in_junction[0]
    assert line.length >= route.goal_s   # road 1 ends at the map edge: nothing to extend into


def test_unreachable_goal_is_an_input_error():
    n = net()
    x, y, h = n.lane_to_world("2", -1, 200.0)
    # Road 2 lane 1 drives away from the junction towards the map edge: no way back from lane -1.
    with pytest.raises(InputError, match="no route"):
        plan_route(n, x, y, h, goal_on_lane(n, "2", 1, 100.0))


def test_off_route_by_offset_and_by_heading():
    n = net()
    x, y, h = n.lane_to_world("2", -1, 200.0)
    route = plan_route(n, x, y, h, goal_on_lane(n, "0", -1, 40.0))
    s = route.line.project(x, y).s
    assert not off_route(route.line, x, y, h, s, 3.0)
    xo, yo, _ = n.lane_to_world("2", -1, 200.0, 4.0 if n.lane_forward("2", -1) else -4.0)
    assert off_route(route.line, xo, yo, h, s, 3.0)
    assert off_route(route.line, x, y, h + math.pi, s, 3.0)


def test_lane_changes_in_the_route_are_blended_into_the_line():
    n = load_network(BUNDLED_MAPS / "straight_3x3.xodr")
    x, y, h = n.lane_to_world("1", -1, 20.0)
    goal = goal_on_lane(n, "1", -3, 300.0)
    route = plan_route(n, x, y, h, goal)
    assert [ref.lane_id for ref in route.lanes] == [-1, -2, -3]
    line = route.line
    gx, gy, _ = line.position(route.goal_s)
    assert math.hypot(gx - goal.x, gy - goal.y) < 0.5
    # Starts in the ego's lane, is in the goal lane well before the goal, and is smooth in between.
    assert line.project(x, y).offset == pytest.approx(0.0, abs=0.1)
    w3 = n.lane_to_world("1", -3, 150.0)
    assert line.project(w3[0], w3[1]).offset == pytest.approx(0.0, abs=0.1)
    assert np.hypot(*np.diff(line.xy, axis=0).T).max() < 1.0
    assert np.abs(line.curvature).max() < 0.05


def test_goal_behind_the_ego_on_a_ring_road_goes_round():
    n = load_network(ESMINI_XODR / "circle_300m.xodr")
    x, y, h = n.lane_to_world("1", -1, 100.0)
    behind = plan_route(n, x, y, h, goal_on_lane(n, "1", -1, 50.0))
    ahead = plan_route(n, x, y, h, goal_on_lane(n, "1", -1, 150.0))
    assert len(behind.lanes) == 2 and len(ahead.lanes) == 1
    # Round the ring (~250 m of lane) versus 50 m straight on, both measured from 10 m behind the ego.
    assert behind.goal_s > 4.0 * (ahead.goal_s - 10.0)
    # 250 m of reference line round the ring; the lane centre's ring is a few per cent longer or shorter.
    assert behind.goal_s == pytest.approx(10.0 + 250.0, rel=0.06)


def test_a_route_planned_again_is_the_remembered_one_and_equals_a_fresh_plan():
    from standin_planner import route as route_mod

    n = net()
    x, y, h = n.lane_to_world("2", -1, 200.0)
    goal = goal_on_lane(n, "1", -1, 12.0)
    first = plan_route(n, x, y, h, goal)
    assert plan_route(n, x, y, h, goal) is first
    fresh = route_mod._plan_route(n, x, y, h, goal)
    assert fresh.lanes == first.lanes and fresh.goal_s == first.goal_s
    assert np.array_equal(fresh.line.xy, first.line.xy)
    # another pose, or the same numbers with another sign of zero, is planned on its own
    assert plan_route(n, x + 1.0, y, h, goal) is not first
    zero = goal_on_lane(n, "1", -1, 12.0)
    a = plan_route(n, x, y, 0.0, zero)
    assert plan_route(n, x, y, -0.0, zero) is not a
