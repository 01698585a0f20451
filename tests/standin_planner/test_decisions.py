"""The planner's decisions on constructed frames on a real map (fabriksgatan: road 2 lane -1 runs 304 m south
into a 4-way junction). Each fault flag is checked against the nominal planner on the same frame."""

import math

import pytest

from standin_planner import Faults, Planner, PlannerParams
from standin_planner.behaviour import Reason
from txt2sce_ros.contract import SignalState, TrafficLightState
from txt2sce_ros.paths import BUNDLED_MAPS
from txt2sce_ros.road import load_network

from .helpers import frame, goal_on_lane, light_on_lane, net, on_lane

N = net()
GOAL = goal_on_lane(N, "0", -1, 40.0)          # straight through the junction
STOP_LINE_S = 300.0                            # on road 2 lane -1, just before the junction


def planner(faults: Faults = Faults(), friction: float | None = None) -> Planner:
    return Planner(N, GOAL, PlannerParams.from_config(), faults=faults, road_friction=friction)


def reasons(p: Planner) -> set[Reason]:
    return {c.reason for c in p.decision.constraints}


def entities(p: Planner, reason: Reason) -> set[str]:
    return {c.entity for c in p.decision.constraints if c.reason is reason}


def test_free_road_from_standstill_accelerates_within_the_jerk_limit():
    p = planner()
    cmd = p.step(frame(0.0, on_lane(N, "ego", "2", -1, 100.0)))
    assert p.decision.reason is Reason.CRUISE
    assert 0.0 < cmd.speed <= p.params.comfort.max_jerk * 0.05 * 0.05 + 1e-9
    assert cmd.t == 0.0 and abs(cmd.yaw_rate) < 0.01


def test_red_light_ahead_is_a_stop_and_green_is_not():
    ego = on_lane(N, "ego", "2", -1, STOP_LINE_S - 32.0, speed=10.0)
    p = planner()
    p.step(frame(0.0, ego, lights=(light_on_lane(N, "2", -1, STOP_LINE_S, SignalState.RED),)))
    assert p.decision.reason is Reason.RED and p.decision.accel < 0.0
    p = planner()
    p.step(frame(0.0, ego, lights=(light_on_lane(N, "2", -1, STOP_LINE_S, SignalState.GREEN),)))
    assert Reason.RED not in reasons(p) and p.decision.accel >= 0.0


def test_yellow_stops_when_comfortable_clears_when_not_and_misread_ignores_it():
    light = (light_on_lane(N, "2", -1, STOP_LINE_S, SignalState.YELLOW),)
    far = on_lane(N, "ego", "2", -1, STOP_LINE_S - 55.0, speed=10.0)
    near = on_lane(N, "ego", "2", -1, STOP_LINE_S - 12.0, speed=10.0)
    p = planner()
    p.step(frame(0.0, far, lights=light))
    assert Reason.YELLOW in reasons(p)
    p = planner()
    p.step(frame(0.0, near, lights=light))
    assert Reason.YELLOW not in reasons(p)                 # would need > yellow_clear_decel: clear the junction
    p = planner(Faults(red_light_misread=True))
    p.step(frame(0.0, far, lights=light))
    assert Reason.YELLOW not in reasons(p)
    # The misread concerns yellow only: red is still a stop.
    p.step(frame(0.05, far, lights=(light_on_lane(N, "2", -1, STOP_LINE_S, SignalState.RED),)))
    assert Reason.RED in reasons(p)


def test_cyclist_ahead_is_followed_unless_cyclists_are_ignored():
    ego = on_lane(N, "ego", "2", -1, 150.0, speed=10.0)
    bike = on_lane(N, "bike1", "2", -1, 172.0, speed=3.0, category="bicycle", length=1.8, width=0.6)
    p = planner()
    p.step(frame(0.0, ego, bike))
    assert p.decision.reason is Reason.LEAD and p.decision.entity == "bike1"
    p = planner(Faults(ignore_cyclists=True))
    p.step(frame(0.0, ego, bike))
    assert "bike1" not in entities(p, Reason.LEAD) and p.decision.reason is Reason.CRUISE
    # A car in the same place is still followed by the faulty planner.
    car = on_lane(N, "car1", "2", -1, 172.0, speed=3.0)
    p.step(frame(0.05, ego, car))
    assert p.decision.reason is Reason.LEAD


def test_npc_close_behind_blocks_the_start_only_under_no_start_when_close():
    ego = on_lane(N, "ego", "2", -1, 100.0)
    behind = on_lane(N, "npc1", "2", -1, 93.0)            # front bumper ~1 m behind the ego's rear
    p = planner()
    cmd = p.step(frame(0.0, ego, behind))
    assert cmd.speed > 0.0
    p = planner(Faults(no_start_when_close=True))
    for k in range(40):
        cmd = p.step(frame(0.05 * k, ego, behind))
        assert cmd.speed == 0.0 and p.decision.reason is Reason.HOLD
    # With the NPC gone, the faulty planner starts too.
    cmd = p.step(frame(2.0, ego))
    assert cmd.speed > 0.0


def test_aggressive_start_commands_throttle_beyond_low_friction():
    ego = on_lane(N, "ego", "2", -1, 100.0)
    p = planner(friction=0.3)
    cmd = p.step(frame(0.0, ego))
    assert (cmd.speed - 0.0) / 0.05 < 0.3 * 9.81
    p = planner(Faults(aggressive_start=True), friction=0.3)
    cmd = p.step(frame(0.0, ego))
    assert (cmd.speed - 0.0) / 0.05 > 0.3 * 9.81
    assert abs(cmd.yaw_rate) >= p.params.faults.aggressive_start_yaw_rate


def test_low_friction_starts_the_stop_earlier_unless_braking_ignores_friction():
    ego = on_lane(N, "ego", "2", -1, STOP_LINE_S - 60.0, speed=10.0)
    red = (light_on_lane(N, "2", -1, STOP_LINE_S, SignalState.RED),)
    dry = planner(friction=1.0)
    dry.step(frame(0.0, ego, lights=red))
    wet = planner(friction=0.2)
    wet.step(frame(0.0, ego, lights=red))
    late = planner(Faults(late_braking_low_friction=True), friction=0.2)
    late.step(frame(0.0, ego, lights=red))
    assert wet.decision.reason is Reason.RED
    assert dry.decision.reason is not Reason.RED and late.decision.reason is not Reason.RED


def test_stale_tracking_sees_objects_a_second_late():
    ego = on_lane(N, "ego", "2", -1, 100.0, speed=8.0)
    nominal, stale = planner(), planner(Faults(stale_tracking=True))
    lead_far = on_lane(N, "lead", "2", -1, 140.0, speed=8.0)
    lead_near = on_lane(N, "lead", "2", -1, 112.0, speed=0.0)   # the lead has braked to a stop
    for k in range(20):                                          # 1 s of the lead far ahead
        nominal.step(frame(0.05 * k, ego, lead_far))
        stale.step(frame(0.05 * k, ego, lead_far))
    for k in range(20, 30):                                      # then 0.5 s of it stopped close
        nominal.step(frame(0.05 * k, ego, lead_near))
        stale.step(frame(0.05 * k, ego, lead_near))
    near_d = {c.distance for c in nominal.decision.constraints if c.entity == "lead"}
    stale_d = {c.distance for c in stale.decision.constraints if c.entity == "lead"}
    assert min(near_d) < 10.0
    assert min(stale_d) > 30.0


def test_parked_car_in_lane_is_a_stop_and_a_cone_at_the_edge_is_passed():
    ego = on_lane(N, "ego", "2", -1, 150.0, speed=8.0)
    parked = on_lane(N, "obs1", "2", -1, 185.0, category="parked_vehicle", static=True)
    p = planner()
    p.step(frame(0.0, ego, parked))
    assert "obs1" in entities(p, Reason.OBSTACLE)
    width = N.lane_width("2", -1, 185.0)
    side = 1.0 if N.lane_forward("2", -1) else -1.0
    # A cone on the right edge of the lane (the left of the driving direction is +t for a forward lane).
    cone = on_lane(N, "obs2", "2", -1, 185.0, category="cone", static=True, length=0.4, width=0.4,
                   offset=-side * (0.5 * width - 0.4))
    p = planner()
    for k in range(40):
        p.step(frame(0.05 * k, ego, cone))
    assert p.decision.offset > 0.2                    # shifting left, away from the cone, just enough


def test_crossing_car_near_the_junction_is_yielded_to():
    ego = on_lane(N, "ego", "2", -1, STOP_LINE_S - 20.0, speed=8.0)
    cross = on_lane(N, "npc1", "3", -1, 100.0, speed=8.0)   # road 3 comes in from the west
    p = planner()
    p.step(frame(0.0, ego, cross))
    assert "npc1" in entities(p, Reason.YIELD)
    assert p.decision.accel < 0.0
    # The same car driving away from the junction is no conflict.
    away = on_lane(N, "npc1", "3", 1, 100.0, speed=8.0)
    p = planner()
    p.step(frame(0.0, ego, away))
    assert "npc1" not in entities(p, Reason.YIELD)


@pytest.mark.parametrize("latency", [0.0, 0.5])
def test_same_frames_same_commands(latency):
    params = PlannerParams.from_config().replace(perception={"latency": latency, "position_noise": 0.3,
                                                             "speed_noise": 0.2, "seed": 7})
    ego = on_lane(N, "ego", "2", -1, 150.0, speed=8.0)
    npc = on_lane(N, "npc1", "2", -1, 175.0, speed=6.0)
    out = []
    for _ in range(2):
        p = Planner(N, GOAL, params)
        out.append([p.step(frame(0.05 * k, ego, npc)) for k in range(30)])
    assert out[0] == out[1]


def test_standing_behind_something_close_waits_and_starts_once_clear():
    ego = on_lane(N, "ego", "2", -1, 100.0)
    close = on_lane(N, "npc1", "2", -1, 108.0)          # ~2 m from bumper to bumper, standing
    p = planner()
    cmd = p.step(frame(0.0, ego, close))
    assert cmd.speed == 0.0 and Reason.WAIT in reasons(p)
    away = on_lane(N, "npc1", "2", -1, 125.0, speed=3.0)
    cmd = p.step(frame(0.05, ego, away))
    assert cmd.speed > 0.0


def test_off_route_pose_triggers_a_replan_from_where_the_ego_is():
    p = planner()
    p.step(frame(0.0, on_lane(N, "ego", "2", -1, 150.0, speed=5.0)))
    assert p.replans == 1 and p.route.lanes[0].road_id == "2"
    p.step(frame(0.05, on_lane(N, "ego", "2", -1, 150.2, speed=5.0)))
    assert p.replans == 1                                  # still on its route: no replanning
    # Displaced onto the road coming in from the west (e.g. a lane it was pushed into): a new route from there.
    p.step(frame(0.10, on_lane(N, "ego", "3", -1, 60.0, speed=5.0)))
    assert p.replans == 2 and p.route.lanes[0].road_id == "3" and p.route.lanes[-1].road_id == "0"


def test_pedestrian_about_to_cross_ahead_is_yielded_to():
    ego = on_lane(N, "ego", "2", -1, 150.0, speed=8.0)
    # 25 m ahead, 4 m to the right of the ego's lane centre, walking across it at 1.4 m/s.
    side = -4.0 if N.lane_forward("2", -1) else 4.0
    ped = on_lane(N, "ped1", "2", -1, 175.0, speed=1.4, category="pedestrian", offset=side, length=0.5,
                  width=0.6, heading_delta=math.copysign(math.pi / 2, -side))
    p = planner()
    p.step(frame(0.0, ego, ped))
    assert "ped1" in entities(p, Reason.YIELD)
    # Walking away from the road instead: no yield.
    away = on_lane(N, "ped1", "2", -1, 175.0, speed=1.4, category="pedestrian", offset=side, length=0.5,
                   width=0.6, heading_delta=math.copysign(math.pi / 2, side))
    p = planner()
    p.step(frame(0.0, ego, away))
    assert "ped1" not in entities(p, Reason.YIELD)


def test_blocking_parked_car_is_passed_in_the_free_lane_beside_or_waited_for():
    n = load_network(BUNDLED_MAPS / "straight_3x3.xodr")       # three lanes each way: lane -2 is right of -1
    goal = goal_on_lane(n, "1", -1, 300.0)
    ego = on_lane(n, "ego", "1", -1, 50.0, speed=8.0)
    parked = on_lane(n, "obs1", "1", -1, 90.0, category="parked_vehicle")
    p = Planner(n, goal, PlannerParams.from_config())
    for k in range(20):
        p.step(frame(0.05 * k, ego, parked))
    assert p.decision.offset < -0.5                          # moving over to the right (closed loop: the
                                                             # benign_parked_car scenario passes it)
    # A car coming up in that lane: line up and wait short of the parked car instead.
    passing = on_lane(n, "npc1", "1", -2, 45.0, speed=10.0)
    p = Planner(n, goal, PlannerParams.from_config())
    p.step(frame(0.0, ego, parked, passing))
    waits = [c for c in p.decision.constraints if c.reason is Reason.OBSTACLE and c.entity == "obs1"]
    assert waits and waits[0].accel < 0.0
    assert abs(p.decision.offset) < 0.05


def test_red_light_marked_on_a_neighbour_lane_it_governs_still_stops_the_ego():
    # A signal's stop point sits on one of the lanes it governs (the player picks one); an ego in another lane of
    # that set must stop for it even 3.5 m to the side. Without lane information only its own lane's point counts.
    ego = on_lane(N, "ego", "2", -1, STOP_LINE_S - 60.0, speed=8.0)
    x, y, h = N.lane_to_world("2", -1, STOP_LINE_S)
    side_x, side_y = x - 3.5 * math.sin(h), y + 3.5 * math.cos(h)      # 3.5 m to the left of the ego's lane
    governed = TrafficLightState(id="sig", state=SignalState.RED, stop_x=side_x, stop_y=side_y, heading=h,
                                 road_id="2", lane_ids=(-1, 1))
    unknown = TrafficLightState(id="sig", state=SignalState.RED, stop_x=side_x, stop_y=side_y, heading=h)
    p = planner()
    p.step(frame(0.0, ego, lights=(governed,)))
    assert Reason.RED in reasons(p)
    q = planner()
    q.step(frame(0.0, ego, lights=(unknown,)))
    assert Reason.RED not in reasons(q)


def test_a_stop_decided_at_yellow_onset_is_kept_through_the_yellow():
    # Yellow appears 60 m out: a comfortable stop, so the planner stops. Later in the same yellow the remaining stop
    # is no longer "comfortable" (it braked gently, the line came closer): it must not change its mind and run into
    # the red; a planner that first sees the yellow that close clears the junction instead.
    yellow = (light_on_lane(N, "2", -1, STOP_LINE_S, SignalState.YELLOW),)
    far = on_lane(N, "ego", "2", -1, STOP_LINE_S - 60.0, speed=10.0)
    near = on_lane(N, "ego", "2", -1, STOP_LINE_S - 19.0, speed=10.0, t=0.05)
    p = planner()
    p.step(frame(0.0, far, lights=yellow))
    assert Reason.YELLOW in reasons(p)
    p.step(frame(0.05, near, lights=yellow))
    assert Reason.YELLOW in reasons(p)
    fresh = planner()
    fresh.step(frame(0.05, near, lights=yellow))
    assert Reason.YELLOW not in reasons(fresh)


def test_right_turn_yields_to_a_cyclist_riding_on_beside_unless_cyclists_are_ignored():
    # a right turn (south on road 2, west onto road 3) across a cyclist riding straight on at the lane's right
    # edge, just ahead of or behind the ego: the route turns across its course, so it is a crossing
    right_turn = goal_on_lane(N, "3", 1, 60.0)
    for s_cyc in (292.0, 286.0):
        ego = on_lane(N, "ego", "2", -1, 290.0, speed=4.0)
        bike = on_lane(N, "bike", "2", -1, s_cyc, speed=5.0, category="bicycle", offset=-1.7, length=1.8, width=0.6)
        p = Planner(N, right_turn, PlannerParams.from_config())
        p.step(frame(0.0, ego, bike))
        assert "bike" in entities(p, Reason.YIELD)
        p = Planner(N, right_turn, PlannerParams.from_config(), faults=Faults(ignore_cyclists=True))
        p.step(frame(0.0, ego, bike))
        assert "bike" not in entities(p, Reason.YIELD)
        # going straight on beside it is no crossing
        p = planner()
        p.step(frame(0.0, ego, bike))
        assert "bike" not in entities(p, Reason.YIELD)
