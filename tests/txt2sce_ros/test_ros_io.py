"""Round trips between contract records and the standard messages they ride on."""

import math

import pytest
from rclpy.serialization import deserialize_message, serialize_message

from nav_msgs.msg import Odometry
from visualization_msgs.msg import MarkerArray

from txt2sce_ros import ros_io
from txt2sce_ros.contract import ControlCommand, EntityState, Frame, Goal, SignalState, TrafficLightState


def _frame(t: float = 1.25) -> Frame:
    ego = EntityState("ego", "car", t, 10.0, -3.5, 0.3, 7.5, accel=-1.25, yaw_rate=0.05, center_x=1.4)
    bike = EntityState("npc1", "bicycle", t, 30.0, 2.0, -math.pi / 2, 3.0, length=1.8, width=0.6, height=1.7,
                       center_x=0.0)
    cone = EntityState("obs1", "cone", t, 50.0, 0.0, 0.0, 0.0, length=0.4, width=0.4, height=0.7, center_x=0.0,
                       is_static=True)
    light = TrafficLightState("sig3", SignalState.YELLOW, 40.0, -2.0, 0.0, road_id="7", lane_ids=(-1, -2))
    return Frame(t=t, ego=ego, objects=(bike, cone), lights=(light,))


def test_frame_survives_serialisation_in_any_message_order() -> None:
    frame = _frame()
    odoms = [ros_io.entity_to_odometry(e) for e in (frame.ego, *frame.objects)]
    markers = ros_io.frame_to_markers(frame)
    lights = ros_io.lights_to_diagnostics(frame.lights, frame.t)
    # Through CDR bytes, as a bag or DDS would carry them.
    odoms = [deserialize_message(serialize_message(m), Odometry) for m in odoms]
    markers = deserialize_message(serialize_message(markers), MarkerArray)

    asm = ros_io.FrameAssembler()
    asm.add_lights(lights)
    assert asm.add_odometry(odoms[0]) is None          # ego first: objects still missing
    assert asm.add_odometry(odoms[2]) is None
    assert asm.add_markers(markers) is None            # manifest lists npc1, not yet received
    rebuilt = asm.add_odometry(odoms[1])
    assert rebuilt is not None
    assert rebuilt.t == pytest.approx(frame.t)
    for got, want in zip((rebuilt.ego, *rebuilt.objects), (frame.ego, *frame.objects)):
        assert got.name == want.name and got.category == want.category
        assert (got.x, got.y, got.speed, got.accel) == pytest.approx((want.x, want.y, want.speed, want.accel))
        assert got.heading == pytest.approx(want.heading)
        assert (got.length, got.width, got.center_x) == pytest.approx((want.length, want.width, want.center_x))
        assert got.is_static == want.is_static
    assert rebuilt.lights == frame.lights
    # A late duplicate of the finished step is ignored.
    assert asm.add_odometry(odoms[1]) is None


def test_command_goal_and_stamps_round_trip() -> None:
    cmd = ControlCommand(t=3.05, speed=4.2, yaw_rate=-0.1)
    assert ros_io.twist_to_command(ros_io.command_to_twist(cmd)) == pytest.approx(cmd)
    goal = Goal(100.0, 5.0, 1.0)
    back = ros_io.pose_to_goal(ros_io.goal_to_pose(goal))
    assert (back.x, back.y, back.heading) == pytest.approx((goal.x, goal.y, goal.heading))
    # 0.05 s steps stay exactly distinguishable as integer nanoseconds.
    keys = {ros_io.stamp_key(ros_io.to_stamp(k * 0.05)) for k in range(10_000)}
    assert len(keys) == 10_000


def test_frames_through_the_fast_decoders_follow_each_light_change() -> None:
    # The assembler reuses the lights it converted while the decoder hands it the same statuses (a signal holding
    # its state); every change must show in the frame of its own step, and every frame must equal the one
    # rebuilt from rosbags' decoding of the same bytes.
    from oracle_monitor import cdr
    from oracle_monitor.recorder import typestore

    ts = typestore()
    states = [SignalState.RED] * 3 + [SignalState.GREEN] * 2 + [SignalState.YELLOW] + [SignalState.RED] * 2
    fast, slow = ros_io.FrameAssembler(), ros_io.FrameAssembler()
    got = []
    for k, state in enumerate(states):
        base = _frame(1.0 + 0.05 * k)
        light = TrafficLightState("sig3", state, 40.0, -2.0, 0.0, road_id="7", lane_ids=(-1, -2))
        frame = Frame(t=base.t, ego=base.ego, objects=base.objects, lights=(light,))
        messages = [("lights", cdr.encode_lights(frame.lights, frame.t), "diagnostic_msgs/msg/DiagnosticArray"),
                    ("markers", cdr.encode_markers(frame), "visualization_msgs/msg/MarkerArray")]
        messages += [("odom", cdr.encode_odometry(e), "nav_msgs/msg/Odometry") for e in (frame.ego, *frame.objects)]
        out = {}
        for asm, decode in ((fast, lambda d, t: cdr.decode(d, t, ts)), (slow, ts.deserialize_cdr)):
            for kind, data, msgtype in messages:
                msg = decode(data, msgtype)
                done = {"lights": asm.add_lights, "markers": asm.add_markers, "odom": asm.add_odometry}[kind](msg)
            out[asm] = done
        assert out[fast] == out[slow] and out[fast] is not None
        got.append(out[fast].lights[0].state)
    assert got == states


def test_scenario_marker_bytes_are_the_messages_serialised() -> None:
    # The kept bytes must be what serialising the markers gives for these very inputs: a changed light, goal or
    # time must not be answered from the cache.
    from oracle_monitor.cdr import encode_marker_array

    goal = Goal(10.0, -2.5, 0.3, 2.0)
    red = (TrafficLightState("L1", SignalState.RED, 5.0, 1.0, 0.0, "1", (-1,)),)
    green = (TrafficLightState("L1", SignalState.GREEN, 5.0, 1.0, 0.0, "1", (-1,)),)
    seen = set()
    for g, lights, t in ((goal, red, 0.0), (goal, green, 0.0), (goal, red, 1.5), (None, red, 0.0),
                         (Goal(10.0, -2.5, 0.3, 3.0), red, 0.0), (goal, (), 0.0)):
        for _ in range(2):                        # the second call is answered from the cache
            got = ros_io.scenario_markers_bytes(g, lights, t)
            assert got == encode_marker_array(ros_io.scenario_markers(g, lights, t))
        markers = deserialize_message(got, MarkerArray).markers
        assert [m.text for m in markers[1:]] == (["goal", "goal"] if g else []) + [
            f"L1 {light.state.value}" for light in lights]
        seen.add(got)
    assert len(seen) == 6
    # A light built with a list for its lanes cannot be a cache key: the bytes are made all the same.
    listed = (TrafficLightState("L1", SignalState.RED, 5.0, 1.0, 0.0, "1", [-1]),)
    assert ros_io.scenario_markers_bytes(goal, listed, 0.0) == ros_io.scenario_markers_bytes(goal, red, 0.0)
