"""The road in the bag: a recorded run holds the road markers once, in the map frame, on the scenario's lanes (checked
against the road model); the goal and light markers follow the lights; `txt2sce bag-plot` draws the run from the
bag alone; a replay offers the same bytes, latched, to a viewer that joins late."""

from __future__ import annotations

import math
import time
from pathlib import Path

import numpy as np
import pytest

rclpy = pytest.importorskip("rclpy")

from oracle_monitor.bagread import read_bag  # noqa: E402
from oracle_monitor.recorder import typestore  # noqa: E402
from oracle_monitor.runwriter import RunWriter  # noqa: E402
from scenario_player import Simulation, SimulationConfig, load_scenario  # noqa: E402
from standin_planner import Faults, Planner, PlannerParams  # noqa: E402
from txt2sce_ros import contract as c  # noqa: E402
from txt2sce_ros.cli.main import main  # noqa: E402
from txt2sce_ros.road.outline import road_outline, thin  # noqa: E402
from txt2sce_ros.ros_io import road_markers_bytes  # noqa: E402

from .oracle_runs import ESMINI  # noqa: E402
from .replaying import viewer_and_replayer  # noqa: E402

MARKER_ARRAY = "visualization_msgs/msg/MarkerArray"


def record_run(name: str, bag: Path) -> Simulation:
    """One closed-loop run of an esmini example (player + stand-in planner), recorded in-process."""
    sim = Simulation(load_scenario(str(ESMINI / "xosc" / f"{name}.xosc")), SimulationConfig(ego_mode="planner"))
    frame = sim.reset()
    planner = Planner(sim.network, sim.goal, PlannerParams.from_config(), faults=Faults())
    with RunWriter(bag) as w:
        w.begin(None, sim.goal, name, network=sim.network, lights=frame.lights)
        while not sim.done:
            cmd = planner.step(frame)
            w.frame(frame, cmd)
            frame = sim.step(cmd)
        w.frame(frame)
        w.end(sim.status)
    return sim


@pytest.fixture(scope="module")
def lights_run(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, Simulation]:
    bag = tmp_path_factory.mktemp("road") / "traffic_lights"
    return bag, record_run("traffic_lights", bag)


def _decoded(bag: Path, topic: str) -> list:
    ts = typestore()
    return [ts.deserialize_cdr(bytes(m.data), MARKER_ARRAY) for m in read_bag(bag).messages(frozenset({topic}))]


def test_bag_holds_the_road_once_in_the_map_frame_on_the_lanes(lights_run: tuple[Path, Simulation]) -> None:
    bag, sim = lights_run
    net = sim.network
    (road,) = _decoded(bag, c.TOPIC_MAP_MARKERS)                  # once per run
    assert road.markers[0].action == 3                            # DELETEALL: a viewer drops the previous road
    lines = road.markers[1:]
    assert {m.header.frame_id for m in road.markers} == {c.MAP_FRAME}
    assert {m.ns for m in lines} == {"border", "centre", "stop_line"}
    assert all(m.type == 4 and len(m.points) >= 2 for m in lines)  # LINE_STRIP

    for m in lines:
        road_id, lane_id = m.text.split()[1], int(m.text.split()[3])
        xy = np.array([(p.x, p.y) for p in m.points])
        if m.ns == "centre":
            # Every point on the centre of the lane the marker names.
            match = net.world_to_lane(xy[:, 0], xy[:, 1], lane_types=None)
            assert np.all(match.distance < 0.05), (m.text, match.distance.max())
            assert np.all(np.abs(match.offset) < 0.05), (m.text, np.abs(match.offset).max())
        elif m.ns == "border":
            # A border point lies half a lane width from the centre of the lane it bounds.
            match = net.world_to_lane(xy[:, 0], xy[:, 1], lane_types=None)
            for rid, lid, s, off in zip(match.road_id, match.lane_id, match.s, match.offset):
                half = net.lane_width(rid, int(lid), float(s)) / 2.0
                assert abs(abs(off) - half) < 0.05, (m.text, rid, lid, s, off, half)
        else:
            # A stop line crosses the lane its light controls, at the light's s: midpoint in that lane.
            mid = xy.mean(axis=0)
            match = net.world_to_lane(np.array([mid[0]]), np.array([mid[1]]))
            assert (str(match.road_id[0]), int(match.lane_id[0])) == (road_id, lane_id)
            assert bool(match.inside[0])
            width = float(np.hypot(*(xy[-1] - xy[0])))
            assert width == pytest.approx(net.lane_width(road_id, lane_id, float(match.s[0])), abs=0.05)
    stops = {(m.text.split()[1], int(m.text.split()[3])) for m in lines if m.ns == "stop_line"}
    lights = {(sig.road_id, lane) for sig in net.signals.values() if sig.is_traffic_light
              for lane in sig.controlled_lanes}
    assert stops == lights and stops


def test_goal_and_light_markers_follow_the_lights(lights_run: tuple[Path, Simulation]) -> None:
    bag, sim = lights_run
    scenes = _decoded(bag, c.TOPIC_SCENARIO_MARKERS)
    assert len(scenes) >= 2                                       # the start, and each change of a light
    stamps = [m.markers[0].header.stamp.sec + m.markers[0].header.stamp.nanosec * 1e-9 for m in scenes]
    assert stamps[0] == 0.0 and stamps == sorted(set(stamps))
    states = [tuple(sorted(x.text for x in s.markers if x.ns == "traffic_light")) for s in scenes]
    assert all(a != b for a, b in zip(states, states[1:]))       # a message only when something changed
    goal = [x for x in scenes[0].markers if x.ns == "goal" and x.type == 0][0]
    assert (goal.pose.position.x, goal.pose.position.y) == pytest.approx((sim.goal.x, sim.goal.y))
    # The markers' colours are the states they name.
    for x in scenes[-1].markers:
        if x.ns == "traffic_light":
            state = x.text.split()[-1]
            assert {"red": x.color.r > 0.9 and x.color.g < 0.2, "green": x.color.g > 0.8 and x.color.r < 0.2,
                    "yellow": x.color.r > 0.9 and x.color.g > 0.8}.get(state, True), x.text


def test_road_bytes_are_built_once_per_network_and_are_what_is_recorded(lights_run) -> None:
    bag, sim = lights_run
    (raw,) = list(read_bag(bag).messages(frozenset({c.TOPIC_MAP_MARKERS})))
    assert bytes(raw.data) == road_markers_bytes(sim.network)
    assert road_markers_bytes(sim.network) is road_markers_bytes(sim.network)


def test_thin_keeps_shape_within_tolerance() -> None:
    s = np.linspace(0.0, 100.0, 201)
    straight = np.column_stack((s, 0.5 * s))
    assert len(thin(straight)) == 2
    r = 60.0                                                      # an arc: dense samples, thinned, stay close
    a = s / r
    arc = np.column_stack((r * np.sin(a), r * (1 - np.cos(a))))
    kept = thin(arc, tolerance=0.02)
    assert 2 < len(kept) < len(arc)
    dense = np.linspace(0.0, a[-1], 2000)
    for px, py in zip(r * np.sin(dense), r * (1 - np.cos(dense))):
        d = np.min([_seg_dist(px, py, kept[i], kept[i + 1]) for i in range(len(kept) - 1)])
        assert d < 0.03


def _seg_dist(px: float, py: float, a: np.ndarray, b: np.ndarray) -> float:
    ab = b - a
    u = max(0.0, min(1.0, ((px - a[0]) * ab[0] + (py - a[1]) * ab[1]) / float(ab @ ab)))
    return math.hypot(px - a[0] - u * ab[0], py - a[1] - u * ab[1])


def test_outline_skips_borders_inside_junctions() -> None:
    from txt2sce_ros.road import load_network

    net = load_network(ESMINI / "xodr" / "fabriksgatan.xodr")
    lines = road_outline(net)
    junction_roads = {r.id for r in net.roads.values() if r.junction not in ("", "-1")}
    assert junction_roads
    assert not any(ln.kind == "border" and ln.road_id in junction_roads for ln in lines)
    assert any(ln.kind == "centre" and ln.road_id in junction_roads for ln in lines)


def test_bag_plot_draws_the_run_from_the_bag_alone(lights_run, tmp_path: Path, capsys) -> None:
    import matplotlib.image

    bag, _ = lights_run
    out = tmp_path / "run.png"
    assert main(["bag-plot", str(bag), "--out", str(out), "--t", "5"]) == 0
    assert "run 1 of 1 at t = 5.00 s" in capsys.readouterr().out
    img = matplotlib.image.imread(out)
    # Light-grey border lines and the ego's box in the car colour the bag gives it (orange) are in the picture.
    rgb = img[..., :3]
    grey = np.all(np.abs(rgb - 0.85) < 0.08, axis=-1).sum()
    orange = ((rgb[..., 0] > 0.7) & (rgb[..., 1] > 0.3) & (rgb[..., 1] < 0.55) & (rgb[..., 2] < 0.3)).sum()
    assert grey > 500 and orange > 20, (grey, orange)

    assert main(["bag-plot", str(bag), "--out", str(out), "--run", "2"]) == 2
    assert "holds 1 run(s)" in capsys.readouterr().err


def test_bag_plot_refuses_a_bag_without_road(tmp_path: Path, capsys) -> None:
    with RunWriter(tmp_path / "old") as w:                         # a recording made without the road
        w.begin(None, None, "x")
    assert main(["bag-plot", str(tmp_path / "old"), "--out", str(tmp_path / "x.png")]) == 2
    err = capsys.readouterr().err
    assert "no road markers" in err and "Traceback" not in err and len(err.strip().splitlines()) == 1


def test_replay_offers_the_recorded_road_latched_to_a_late_viewer(lights_run, tmp_path: Path, monkeypatch) -> None:
    from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
    from visualization_msgs.msg import MarkerArray

    from oracle_monitor.replay import replay_bag

    bag, _ = lights_run
    recorded = {t: [bytes(m.data) for m in read_bag(bag).messages(frozenset({t}))] for t in c.VIEW_TOPICS}
    latched = QoSProfile(depth=1, reliability=ReliabilityPolicy.RELIABLE, durability=DurabilityPolicy.TRANSIENT_LOCAL)
    keep = QoSProfile(depth=100, reliability=ReliabilityPolicy.RELIABLE, durability=DurabilityPolicy.TRANSIENT_LOCAL)
    got: dict[str, list[bytes]] = {t: [] for t in c.VIEW_TOPICS}
    late: list[bytes] = []
    with viewer_and_replayer(tmp_path, monkeypatch) as (node, pub_node):
        for t in c.VIEW_TOPICS:
            node.create_subscription(MarkerArray, t, lambda data, t=t: got[t].append(bytes(data)), keep, raw=True)
        count, issues = replay_bag(bag, rate=50.0, node=pub_node, topics=frozenset(c.VIEW_TOPICS),
                                   discovery_timeout=10.0)
        deadline = time.monotonic() + 5.0
        while len(got[c.TOPIC_SCENARIO_MARKERS]) < len(recorded[c.TOPIC_SCENARIO_MARKERS]) \
                and time.monotonic() < deadline:
            time.sleep(0.01)
        # A viewer that joins after the replay published the road still gets it (latched).
        node.create_subscription(MarkerArray, c.TOPIC_MAP_MARKERS, lambda data: late.append(bytes(data)),
                                 latched, raw=True)
        deadline = time.monotonic() + 5.0
        while not late and time.monotonic() < deadline:
            time.sleep(0.01)
    assert issues == [] and count == sum(len(v) for v in recorded.values())
    # Replayed == recorded, byte for byte (DDS may pad a payload to a multiple of 4 bytes on the wire).
    unpadded = {t: [d[:len(r)] for d, r in zip(got[t], recorded[t])] for t in got}
    assert unpadded == recorded, {t: (len(got[t]), len(recorded[t])) for t in got}
    assert [d[:len(r)] for d, r in zip(late, recorded[c.TOPIC_MAP_MARKERS])] == recorded[c.TOPIC_MAP_MARKERS]
    assert len(late) == 1


def test_marker_array_encoder_matches_rclpy_and_zeroes_padding(lights_run) -> None:
    from rclpy.serialization import deserialize_message, serialize_message
    from visualization_msgs.msg import MarkerArray

    from oracle_monitor.cdr import encode_marker_array
    from txt2sce_ros.contract import Goal, SignalState, TrafficLightState
    from txt2sce_ros.ros_io import road_markers, scenario_markers

    _, sim = lights_run
    light = TrafficLightState("7", SignalState.YELLOW, 3.0, -4.0, 0.5, "1", (-1,))
    for msg in (road_markers(road_outline(sim.network)), scenario_markers(Goal(1.0, 2.0, 0.3), [light], 2.5),
                scenario_markers(None, [], 0.0)):
        data = encode_marker_array(msg)
        assert data == encode_marker_array(msg)                    # same message, same bytes
        assert len(data) == len(serialize_message(msg))
        assert deserialize_message(data, MarkerArray) == deserialize_message(serialize_message(msg), MarkerArray)


def test_foxglove_layout_names_topics_and_fields_the_bag_has(lights_run) -> None:
    import json

    from oracle_monitor.topics import TOPIC_TYPES

    layout = json.loads((Path(__file__).parents[2] / "docs" / "foxglove_layout.json").read_text())
    panels = layout["configById"]
    three_d = next(v for k, v in panels.items() if k.startswith("3D!"))
    assert three_d["followTf"] == c.MAP_FRAME
    assert set(c.VIEW_TOPICS) | {c.TOPIC_OBJECTS_MARKERS} <= {t for t, s in three_d["topics"].items() if s["visible"]}
    # Every topic a panel reads is one the recorder writes, and the plotted fields exist in the recorded messages.
    ts = typestore()
    bag, _ = lights_run
    first = {}
    for m in read_bag(bag).messages():
        first.setdefault(m.topic, ts.deserialize_cdr(bytes(m.data), m.msgtype))
    plot = next(v for k, v in panels.items() if k.startswith("Plot!"))
    for path in [p["value"] for p in plot["paths"]] + [v["topicPath"] for k, v in panels.items()
                                                       if k.startswith("Table!")]:
        topic, _, fields = path.partition(".")
        assert topic in TOPIC_TYPES, path
        if topic in first:
            value = first[topic]
            for f in fields.split("."):
                value = getattr(value, f)              # raises if the layout names a field the type lacks
    assert set(three_d["topics"]) <= set(TOPIC_TYPES)
