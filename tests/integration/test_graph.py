"""The node graph as separate processes over DDS: generator -> player <-> stand-in planner, oracle monitor recording.

Checks what a user of `txt2sce_launch` relies on: the ego moves under the planner's commands, the recording is a
rosbag2 directory whose MCAP holds the contract topics, and the verdict judged from the recording equals the one
the in-process cores give for the same seed (the ROS path adds transport, not behaviour).
"""

import json
from pathlib import Path

import pytest

from txt2sce_ros.closed_loop import run_closed_loop
from txt2sce_ros.contract import TOPIC_COMMAND, TOPIC_EGO_ODOM, TOPIC_OBJECTS_MARKERS, TOPIC_OBJECTS_ODOM, TOPIC_SCENARIO
from txt2sce_ros.launcher import GraphConfig, run_graph
from txt2sce_ros.paths import shared_dir
from txt2sce_ros.seed import write_seeds
from txt2sce_ros.sketch import load_sketches

from .rosproc import ros_test_env

GOLD = shared_dir() / "data" / "reports" / "dev_gold.jsonl"
# A junction conflict whose seed the nominal planner drives through in ~10 s of sim time.
REPORT = "dmvca-apple-20211111-r241"


@pytest.fixture(scope="module")
def seed_file(tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("seeds")
    sketches = [s for s in load_sketches(GOLD) if getattr(s, "report_id", None) == REPORT]
    manifest = write_seeds(sketches, out, seed=0)
    assert manifest["built"], manifest["refused"]
    return out / manifest["built"][0]["file"]


@pytest.mark.timeout(240)
def test_graph_over_dds_moves_the_ego_records_and_judges_like_batch(seed_file: Path, tmp_path: Path) -> None:
    from rosbags.highlevel import AnyReader
    from rosbags.typesys import Stores, get_typestore

    env = ros_test_env(tmp_path)
    bags = tmp_path / "bags"
    codes = run_graph(GraphConfig(scenarios=[str(seed_file)], bag_dir=str(bags), log_dir=env["ROS_LOG_DIR"],
                                  domain_id=int(env["ROS_DOMAIN_ID"])), timeout=180, quiet=True)
    logs = "\n".join(f"--- {p.name}\n{p.read_text(errors='replace')[-3000:]}"
                     for p in sorted(Path(env["ROS_LOG_DIR"]).glob("*.log")))
    assert codes["generator"] == 0, logs
    metas = sorted(bags.rglob("metadata.yaml"))
    assert metas, f"no rosbag2 directory under {bags}\n{logs}"
    bag = metas[0].parent
    assert list(bag.glob("*.mcap"))

    ego_xy = []
    counts: dict[str, int] = {}
    with AnyReader([bag], default_typestore=get_typestore(Stores.ROS2_JAZZY)) as reader:
        for conn, _t, raw in reader.messages():
            counts[conn.topic] = counts.get(conn.topic, 0) + 1
            if conn.topic == TOPIC_EGO_ODOM:
                msg = reader.deserialize(raw, conn.msgtype)
                ego_xy.append((msg.pose.pose.position.x, msg.pose.pose.position.y))
    for topic in (TOPIC_SCENARIO, TOPIC_EGO_ODOM, TOPIC_OBJECTS_ODOM, TOPIC_OBJECTS_MARKERS, TOPIC_COMMAND):
        assert counts.get(topic, 0) > 0, f"{topic} not recorded: {counts}"
    assert counts[TOPIC_EGO_ODOM] > 20
    (x0, y0), (x1, y1) = ego_xy[0], ego_xy[-1]
    assert ((x1 - x0) ** 2 + (y1 - y0) ** 2) ** 0.5 > 5.0, "the ego did not move under the planner's commands"

    # The recording judged offline gives the in-process verdict for the same seed.
    from oracle_monitor.judge import judge_bag

    judged = judge_bag(bag)
    assert judged.complete, judged.issues
    assert len(judged.verdicts) == 1
    offline = judged.verdicts[0]
    assert judged.agrees_with_live() is True, (judged.live, offline.to_dict())
    batch, _ = run_closed_loop(seed_file)
    assert offline.verdict.value == batch.verdict.value, (offline.summary(), batch.to_dict())
    assert set(offline.category_names()) == set(batch.categories)


@pytest.mark.timeout(120)
def test_a_stuck_node_is_named_with_what_it_was_doing(seed_file: Path, tmp_path: Path) -> None:
    """A node that hangs (here the player, frozen with SIGSTOP once it is up) stalls the graph until the timeout;
    the graph's codes then name every process still running and its state, so the stored error says which one
    to look at."""
    import os
    import signal
    import threading
    import time

    env = ros_test_env(tmp_path)
    log_dir = Path(env["ROS_LOG_DIR"])
    frozen: list[int] = []

    def freeze_player() -> None:
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline and not frozen:
            for entry in os.listdir("/proc"):
                if entry.isdigit():
                    try:
                        cmd = Path(f"/proc/{entry}/cmdline").read_bytes()
                        environ = Path(f"/proc/{entry}/environ").read_bytes()
                    except OSError:
                        continue
                    if b"scenario_player_node" in cmd and f"ROS_LOG_DIR={log_dir}".encode() in environ:
                        time.sleep(0.5)  # let it start; a frozen player stalls the graph whenever it stops
                        os.kill(int(entry), signal.SIGSTOP)
                        frozen.append(int(entry))
                        break
            time.sleep(0.2)

    t = threading.Thread(target=freeze_player, daemon=True)
    t.start()
    codes = run_graph(GraphConfig(scenarios=[str(seed_file)], bag_dir=str(tmp_path / "bags"), log_dir=str(log_dir),
                                  domain_id=int(env["ROS_DOMAIN_ID"])), timeout=25, quiet=True)
    t.join(5)
    assert frozen, "the player process was never seen"
    assert codes.timed_out
    assert "stopped by a signal" in codes.stuck.get("player", ""), codes.stuck
    assert all(not what.startswith("stopped") for name, what in codes.stuck.items() if name != "player"), codes.stuck
