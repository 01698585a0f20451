import math

import pytest

from standin_planner.route import off_route, plan_route
from txt2sce_ros.errors import InputError

from .helpers import goal_on_lane, net


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
