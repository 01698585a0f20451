"""The hand-written CDR codec equals rclpy's serialisation byte for byte, and decodes what rosbags decodes."""

from __future__ import annotations

import math
from struct import error as struct_error

import pytest
from rclpy.serialization import serialize_message

from oracle_monitor import cdr
from oracle_monitor.recorder import typestore
from txt2sce_ros import ros_io
from txt2sce_ros.contract import ControlCommand, EntityState, Frame, Goal, SignalState, TrafficLightState

ENTS = [
    EntityState("Ego", "car", 12.35, 101.25, -7.5, 2.9, 8.25, accel=-1.5, yaw_rate=0.07),
    EntityState("pedestrian_adult", "pedestrian", 12.35, 3.0, 4.0, -1.2, 1.1, length=0.6, width=0.5, center_x=0.06),
    EntityState("box1", "debris", 0.0, -5.0, 1e-3, 0.0, 0.0, length=1.0, width=1.0, center_x=0.0, is_static=True),
    EntityState("Ünïcode-npc", "bicycle", 1e6 + 0.123456789, 0.1, 0.2, math.pi, -2.0),
]
LIGHTS = (TrafficLightState("sig1", SignalState.RED, 50.0, 1.75, 0.0, "12", (-1, -2)),
          TrafficLightState("s2", SignalState.GREEN, -3.5, 0.25, 3.14159, "", ()))


@pytest.mark.parametrize("e", ENTS, ids=lambda e: e.name)
def test_odometry_equals_rclpy(e: EntityState) -> None:
    # rclpy leaves alignment padding uninitialised, so bytes are compared outside the padding (ours is zero)
    # and contents through rclpy's own deserialiser.
    from nav_msgs.msg import Odometry
    from rclpy.serialization import deserialize_message

    ours, theirs = cdr.encode_odometry(e), serialize_message(ros_io.entity_to_odometry(e))
    assert len(ours) == len(theirs)
    child_end = 4 + 16 + 4 + len(e.name.encode()) + 1
    pad = (-(child_end - 4)) % 8
    assert ours[:child_end] == theirs[:child_end] and ours[child_end + pad:] == theirs[child_end + pad:]
    assert ours[child_end:child_end + pad] == bytes(pad)
    assert deserialize_message(ours, Odometry) == ros_io.entity_to_odometry(e)


@pytest.mark.parametrize("n", [0, 1, 3])
def test_markers_and_lights_equal_rclpy(n: int) -> None:
    # rclpy leaves alignment padding uninitialised (we saw 0x56 bytes there), so MarkerArrays are compared by
    # content after a round trip through rclpy's own deserialiser; every field, float32 colours included.
    from diagnostic_msgs.msg import DiagnosticArray
    from rclpy.serialization import deserialize_message
    from visualization_msgs.msg import MarkerArray

    frame = Frame(12.35, ENTS[0], tuple(ENTS[1:1 + n]), LIGHTS[:n])
    ours = deserialize_message(cdr.encode_markers(frame), MarkerArray)
    theirs = deserialize_message(serialize_message(ros_io.frame_to_markers(frame)), MarkerArray)
    assert ours == theirs and len(ours.markers) == n + 1
    assert len(cdr.encode_markers(frame)) == len(serialize_message(ros_io.frame_to_markers(frame)))
    ours = deserialize_message(cdr.encode_lights(frame.lights, frame.t), DiagnosticArray)
    assert ours == ros_io.lights_to_diagnostics(frame.lights, frame.t)


def test_clock_and_command_bytes_equal_rclpy() -> None:
    assert cdr.encode_clock(12.35) == serialize_message(ros_io.clock_msg(12.35))
    goal = Goal(x=-12.5, y=301.25, heading=2.7, tolerance=3.0)
    assert cdr.encode_goal(goal, 7.05) == serialize_message(ros_io.goal_to_pose(goal, 7.05))
    assert cdr.encode_goal(goal, 7.05) != cdr.encode_goal(goal, 7.1)
    cmd = ControlCommand(12.35, 8.4, -0.03)
    assert cdr.encode_command(cmd) == serialize_message(ros_io.command_to_twist(cmd))


@pytest.mark.parametrize("text", ["", "started", '{"id": "Ölgrund – ✓", "xosc": "<a/>"}', "x" * 100_003])
def test_string_bytes_equal_rclpy(text: str) -> None:
    # A run's envelope and status messages: any length, any Unicode.
    assert cdr.encode_string(text) == serialize_message(ros_io.string_msg(text))


def test_decoders_agree_with_rosbags_through_ros_io() -> None:
    ts = typestore()
    frame = Frame(12.35, ENTS[0], tuple(ENTS[1:]), LIGHTS)
    for e in ENTS:
        data = cdr.encode_odometry(e)
        fast = ros_io.odometry_to_entity(cdr.decode_odometry(data))
        slow = ros_io.odometry_to_entity(ts.deserialize_cdr(data, "nav_msgs/msg/Odometry"))
        assert fast == slow
    data = cdr.encode_markers(frame)
    fast = [ros_io.marker_dims(m) for m in cdr.decode_markers(data).markers]
    slow = [ros_io.marker_dims(m) for m in ts.deserialize_cdr(data, "visualization_msgs/msg/MarkerArray").markers]
    assert fast == slow and [d["name"] for d in fast] == [e.name for e in ENTS]
    data = cdr.encode_lights(LIGHTS, 1.0)
    assert ros_io.diagnostics_to_lights(cdr.decode_diagnostics(data)) == LIGHTS
    assert ros_io.diagnostics_to_lights(ts.deserialize_cdr(data, "diagnostic_msgs/msg/DiagnosticArray")) == LIGHTS


def test_markers_with_points_and_mesh_data_decode() -> None:
    # Markers written by other tools carry points, colours, textures and meshes: the decoder must walk them.
    from geometry_msgs.msg import Point
    from std_msgs.msg import ColorRGBA
    from visualization_msgs.msg import MarkerArray, UVCoordinate

    arr = ros_io.frame_to_markers(Frame(1.0, ENTS[0], (ENTS[1],)))
    m = arr.markers[0]
    m.points = [Point(x=1.0, y=2.0, z=3.0), Point(x=4.0, y=5.0, z=6.0)]
    m.colors = [ColorRGBA(r=1.0, g=0.0, b=0.0, a=1.0)]
    m.texture_resource = "embedded://x"
    m.texture.format = "png"
    m.texture.data = [1, 2, 3]
    m.uv_coordinates = [UVCoordinate(u=0.5, v=0.25)]
    m.mesh_resource = "package://a/b.dae"
    m.mesh_file.filename = "b.dae"
    m.mesh_file.data = [7] * 5
    data = serialize_message(MarkerArray(markers=[m, arr.markers[1]]))
    fast = [ros_io.marker_dims(x) for x in cdr.decode_markers(data).markers]
    slow = [ros_io.marker_dims(x) for x in typestore().deserialize_cdr(data, "visualization_msgs/msg/MarkerArray").markers]
    assert fast == slow


def test_truncated_message_is_an_error() -> None:
    data = cdr.encode_odometry(ENTS[0])
    with pytest.raises((ValueError, Exception)):
        cdr.decode_odometry(data[:100])
    data = cdr.encode_markers(Frame(1.0, ENTS[0], (ENTS[1],)))
    with pytest.raises(Exception):
        cdr.decode_markers(data[: len(data) - 40])


def test_the_ego_goes_out_under_its_wire_name() -> None:
    # The player node names the ego 'ego' on the wire by the encoders' name arguments instead of a renamed copy of
    # the frame: the same bytes as encoding the renamed frame.
    from dataclasses import replace

    frame = Frame(12.35, ENTS[0], tuple(ENTS[1:3]), ())
    renamed = replace(frame, ego=replace(frame.ego, name="ego"))
    assert cdr.encode_markers(frame, ego_name="ego") == cdr.encode_markers(renamed)
    assert cdr.encode_markers(frame, ego_name="ego") != cdr.encode_markers(frame)
    assert cdr.encode_odometry(frame.ego, name="ego") == cdr.encode_odometry(renamed.ego)
    assert cdr.encode_odometry(frame.objects[0], name=None) == cdr.encode_odometry(frame.objects[0])


def test_command_decodes_as_ros_io_reads_it() -> None:
    # The player takes /control/command raw: the decoder must give what twist_to_command and stamp_key give for
    # rclpy's bytes, whatever frame id (padding) the planner used.
    from geometry_msgs.msg import TwistStamped

    for cmd, frame_id in ((ControlCommand(t=12.35, speed=3.5, yaw_rate=-0.2), "ego"),
                          (ControlCommand(t=1e6 + 0.123456789, speed=-1.0, yaw_rate=0.07), "base_link_x")):
        msg = ros_io.command_to_twist(cmd)
        msg.header.frame_id = frame_id
        msg.twist.linear.y, msg.twist.angular.x = 9.0, 8.0        # fields the contract ignores
        key, got = cdr.decode_command(serialize_message(msg))
        assert key == ros_io.stamp_key(msg.header.stamp) and got == ros_io.twist_to_command(msg)
    # Every padding before the twist (frame ids of 0..8 characters).
    for n in range(9):
        msg = ros_io.command_to_twist(ControlCommand(t=0.05 * n, speed=1.5 + n, yaw_rate=0.01 * n))
        msg.header.frame_id = "f" * n
        key, got = cdr.decode_command(serialize_message(msg))
        assert key == ros_io.stamp_key(msg.header.stamp) and got == ros_io.twist_to_command(msg), n
    with pytest.raises((ValueError, struct_error)):
        cdr.decode_command(serialize_message(TwistStamped())[:20])


def _marker_view(m) -> tuple:
    """Every field the fast decoder carries, from its objects or rosbags'."""
    h, p, o, s = m.header, m.pose.position, m.pose.orientation, m.scale
    return (h.stamp.sec, h.stamp.nanosec, h.frame_id, m.ns, m.id, m.type, m.action, m.text,
            p.x, p.y, p.z, o.x, o.y, o.z, o.w, s.x, s.y, s.z)


def _odometry_view(m) -> tuple:
    h, p, o, tl, ta = m.header, m.pose.pose.position, m.pose.pose.orientation, m.twist.twist.linear, m.twist.twist.angular
    return (h.stamp.sec, h.stamp.nanosec, h.frame_id, m.child_frame_id, p.x, p.y, p.z, o.x, o.y, o.z, o.w,
            tl.x, tl.y, tl.z, ta.x, ta.y, ta.z)


def _odd_markers():
    """Marker arrays of the usual shape and of every other one the fast layout has to hand over: each optional
    field set on its own, in the first, middle or last marker, names of every length modulo 8."""
    from geometry_msgs.msg import Point
    from std_msgs.msg import ColorRGBA
    from visualization_msgs.msg import UVCoordinate

    changes = {
        "usual": lambda m: None,
        "points": lambda m: setattr(m, "points", [Point(x=1.0, y=2.0, z=3.0)]),
        "colors": lambda m: setattr(m, "colors", [ColorRGBA(r=1.0, g=0.5, b=0.0, a=1.0)]),
        "texture_resource": lambda m: setattr(m, "texture_resource", "embedded://t"),
        "texture_frame": lambda m: setattr(m.texture.header, "frame_id", "cam"),
        "texture_format": lambda m: setattr(m.texture, "format", "png"),
        "texture_data": lambda m: setattr(m.texture, "data", [1, 2, 3]),
        "uv": lambda m: setattr(m, "uv_coordinates", [UVCoordinate(u=0.5, v=0.25)]),
        "mesh_resource": lambda m: setattr(m, "mesh_resource", "package://a/b.dae"),
        "mesh_file": lambda m: setattr(m.mesh_file, "filename", "b.dae"),
        "mesh_data": lambda m: setattr(m.mesh_file, "data", [7] * 5),
        "empty_text": lambda m: setattr(m, "text", ""),
        "frame_id": lambda m: setattr(m.header, "frame_id", "odom_long_frame"),
    }
    for name, change in changes.items():
        for which in (0, 1, 2):
            for k in range(8):
                ents = [ENTS[0], ENTS[1], ENTS[2]]
                ents[1] = EntityState("n" * (k + 1), "car" if k % 2 else "pedestrian", 3.0, 1.0, 2.0, 0.5, 1.0)
                arr = ros_io.frame_to_markers(Frame(ents[0].t, ents[0], tuple(ents[1:])))
                change(arr.markers[which])
                yield f"{name}-{which}-{k}", arr


def test_fast_marker_layout_reads_what_rosbags_reads() -> None:
    from visualization_msgs.msg import MarkerArray

    ts = typestore()
    seen = 0
    for label, arr in _odd_markers():
        data = serialize_message(MarkerArray(markers=arr.markers))
        ours = [_marker_view(m) for m in cdr.decode_markers(data).markers]
        theirs = [_marker_view(m) for m in ts.deserialize_cdr(data, "visualization_msgs/msg/MarkerArray").markers]
        assert ours == theirs, label
        seen += 1
    assert seen == 13 * 3 * 8
    frame = Frame(12.35, ENTS[0], tuple(ENTS[1:]), LIGHTS)
    data = cdr.encode_markers(frame)
    assert [_marker_view(m) for m in cdr.decode_markers(data).markers] == [
        _marker_view(m) for m in ts.deserialize_cdr(data, "visualization_msgs/msg/MarkerArray").markers]


@pytest.mark.parametrize("e", ENTS, ids=lambda e: e.name)
def test_odometry_decoder_reads_what_rosbags_reads(e: EntityState) -> None:
    ts = typestore()
    for data in (cdr.encode_odometry(e), serialize_message(ros_io.entity_to_odometry(e))):
        assert _odometry_view(cdr.decode_odometry(data)) == _odometry_view(
            ts.deserialize_cdr(data, "nav_msgs/msg/Odometry"))
    with pytest.raises(Exception):
        cdr.decode_odometry(cdr.encode_odometry(e)[:-8])


def test_violations_and_verdicts_equal_rclpy_and_are_deterministic() -> None:
    # What a recorder writes on /oracle/violations: rclpy's message content, in bytes that do not depend on the
    # run (rclpy's own serialisation leaves its padding uninitialised).
    from diagnostic_msgs.msg import DiagnosticArray
    from rclpy.serialization import deserialize_message

    from oracle_monitor.messages import verdict_cdr, verdict_to_diagnostics, violations_cdr, violations_to_diagnostics
    from oracle_monitor.records import Category, Rule, RunVerdict, Violation
    from txt2sce_ros.contract import Verdict

    vs = [Violation(Rule.CONTACT, Category.COLLISIONS, 3.17, 0.74, 0.0, "m", ("Ego", "lead"), "rear-end"),
          Violation(Rule.JERK_COLLISION, None, 3.2, -412.5, 300.0, "m/s³", (), "Ünïcode detail")]
    verdict = RunVerdict(verdict=Verdict.FAIL, scenario_id="cut-in", t_end=6.05, frames=122)
    for ours, msg in ((violations_cdr(3.2, vs), violations_to_diagnostics(3.2, vs)),
                      (violations_cdr(0.0, vs[:1]), violations_to_diagnostics(0.0, vs[:1])),
                      (verdict_cdr(verdict), verdict_to_diagnostics(verdict))):
        assert deserialize_message(ours, DiagnosticArray) == msg
        assert len(ours) == len(serialize_message(msg))
        decoded = typestore().deserialize_cdr(ours, "diagnostic_msgs/msg/DiagnosticArray")
        assert [s.name for s in decoded.status] == [s.name for s in msg.status]
    assert violations_cdr(3.2, vs) == violations_cdr(3.2, list(vs))
