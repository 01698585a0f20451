"""CPU time per lock-step step of the ROS player node, to compare two checkouts side by side.

`txt2sce bench player` gives the lock-step rate in wall time beside a DDS ping-pong cap; on a loaded machine both
are dominated by scheduling and the ratio says nothing. This measures what the player itself spends per step:
the player node runs in this process (the checkout on PYTHONPATH), a trivial planner (answers each ego frame with
its speed, zero yaw rate) in a child process, over DDS with the project's settings. `time.process_time` (every
thread of the process: rclpy and the DDS threads included) is taken around a short and a long run of the same
scenario in the same node; the difference over the difference in steps is the CPU per step, without start-up
(CPU time still swings by a third with a shared machine's load: caches, sibling threads); the main thread's share alone (`time.thread_time`) beside it. `--parts` also times the node's
`publish_frame`, `Simulation.step` and `Simulation.prepare_step` (main-thread CPU, same runs).

`txt2sce bench lockstep_cpu` measures this checkout. Run the file to measure the checkout on PYTHONPATH instead
(another worktree, main before a change), side by side in the same minutes:
    PYTHONPATH=/path/to/other/checkout python txt2sce_ros/bench/lockstep_cpu.py --parts --rounds 5
Under callgrind (`--separate-threads=yes`), a run with `--long 30` minus one with `--long 2.05` gives the main
thread's instructions per step without the load's noise (docs/performance.md).
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import textwrap
import time
from pathlib import Path

DESCRIPTION = "ROS lock-step player: CPU per step (process, main thread, parts), load-robust; any checkout"

# The planner: echoes the ego's speed for the frame's stamp, as `bench player`'s planner does.
_PLANNER = textwrap.dedent("""
    import rclpy
    from rclpy.node import Node
    from rclpy.qos import QoSProfile, ReliabilityPolicy
    from nav_msgs.msg import Odometry
    from geometry_msgs.msg import TwistStamped
    rclpy.init()
    n = Node("lockstep_cpu_planner")
    q = QoSProfile(depth=100, reliability=ReliabilityPolicy.RELIABLE)
    pub = n.create_publisher(TwistStamped, "/control/command", q)
    out = TwistStamped()
    out.header.frame_id = "ego"
    def on_ego(msg):
        out.header.stamp = msg.header.stamp
        out.twist.linear.x = msg.twist.twist.linear.x
        pub.publish(out)
    n.create_subscription(Odometry, "/sim/ego/odom", on_ego, q)
    try:
        rclpy.spin(n)
    except BaseException:
        pass
""")


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--scenario", default="", help="xosc file (default: the shared straight_500m.xosc)")
    ap.add_argument("--short", type=float, default=2.0, help="sim seconds of the short run")
    ap.add_argument("--long", type=float, default=30.0, help="sim seconds of the long run")
    ap.add_argument("--rounds", type=int, default=3, help="short/long pairs; the median is printed")
    ap.add_argument("--parts", action="store_true", help="also time publish_frame and Simulation.step")
    args = ap.parse_args(argv)
    if not 0 < args.short < args.long or args.rounds < 1:
        ap.error("needs 0 < --short < --long and --rounds >= 1 (the figure is the difference of the two runs)")

    from txt2sce_ros.paths import shared_dir
    from txt2sce_ros.ros_env import pick_domain_id, ros_environment

    xosc = Path(args.scenario) if args.scenario else \
        shared_dir() / "data" / "conformance" / "esmini" / "xosc" / "straight_500m.xosc"
    with tempfile.TemporaryDirectory(prefix="lockstep_cpu_") as tmp:
        env = ros_environment(domain_id=pick_domain_id(f"{tmp}:{os.getpid()}:{time.time_ns()}"),
                              log_dir=Path(tmp) / "ros_log")
        for key in ("ROS_AUTOMATIC_DISCOVERY_RANGE", "ROS_DOMAIN_ID", "ROS_LOG_DIR",
                    "FASTRTPS_DEFAULT_PROFILES_FILE", "RMW_IMPLEMENTATION"):
            if key in env:
                os.environ[key] = env[key]
        planner = subprocess.Popen([sys.executable, "-c", _PLANNER], env=env, stdout=subprocess.DEVNULL,
                                   stderr=subprocess.DEVNULL, start_new_session=True)
        try:
            return _measure(xosc, args)
        finally:
            planner.terminate()
            try:
                planner.wait(timeout=5)
            except subprocess.TimeoutExpired:
                planner.kill()


def _measure(xosc: Path, args: argparse.Namespace) -> int:
    import rclpy
    from rclpy.executors import SingleThreadedExecutor

    from scenario_player import node as player_node
    from scenario_player.simulation import Simulation
    from txt2sce_ros.contract import ScenarioEnvelope

    # Parts in the main thread's CPU time (the DDS threads' work is not theirs): the frame's publication, the
    # step after the command, and (where the checkout has it) the step's part done while the planner works.
    parts = {"publish_frame": 0.0, "sim.step": 0.0, "prepare_step": 0.0}
    if args.parts:
        def timed(name: str, fn):   # noqa: ANN001, ANN202 - a wrapper for the measurement only
            def wrapper(*a, **k):   # noqa: ANN002, ANN003, ANN202
                t0 = time.thread_time()
                try:
                    return fn(*a, **k)
                finally:
                    parts[name] += time.thread_time() - t0
            return wrapper
        player_node.PlayerNode.publish_frame = timed("publish_frame", player_node.PlayerNode.publish_frame)
        Simulation.step = timed("sim.step", Simulation.step)
        if hasattr(Simulation, "prepare_step"):
            Simulation.prepare_step = timed("prepare_step", Simulation.prepare_step)

    rclpy.init(args=["--ros-args", "-p", "planner_timeout:=5.0", "-p", "startup_timeout:=20.0"])
    node = player_node.PlayerNode()
    ex = SingleThreadedExecutor()
    ex.add_node(node)
    env = ScenarioEnvelope(id=str(xosc), xosc="", map_path="", meta={"file": str(xosc)})

    def one(limit: float) -> tuple[float, float, int, dict[str, float]]:
        node.time_limit = limit
        for k in parts:
            parts[k] = 0.0
        c0, m0 = time.process_time(), time.thread_time()
        status = node.run_one(env, ex)
        cpu, main_cpu = time.process_time() - c0, time.thread_time() - m0
        if status.verdict_hint == "error":
            raise SystemExit(f"run ended in error: {status.end_reason}")
        return cpu, main_cpu, round(status.t / node.base_config.dt), dict(parts)

    try:
        one(args.short)             # warm-up: discovery, caches, first-use imports
        rows: dict[str, list[float]] = {"process": [], "main thread": [], **{k: [] for k in parts}}
        for _ in range(args.rounds):
            c_s, m_s, n_s, p_s = one(args.short)
            c_l, m_l, n_l, p_l = one(args.long)
            dn = n_l - n_s
            rows["process"].append((c_l - c_s) / dn * 1e6)
            rows["main thread"].append((m_l - m_s) / dn * 1e6)
            for k in parts:
                rows[k].append((p_l[k] - p_s[k]) / dn * 1e6)
    finally:
        ex.remove_node(node)
        node.destroy_node()
        rclpy.shutdown()
    print(f"player CPU per lock-step step ({xosc.name}, runs of {args.short:g} and {args.long:g} sim s, "
          f"{args.rounds} rounds; median, then every round, in us):")
    shown = list(rows) if args.parts else ["process", "main thread"]
    for k in shown:
        print(f"  {k:14s} {statistics.median(rows[k]):7.1f}   ({', '.join(f'{v:.1f}' for v in rows[k])})")
    if args.parts:
        crit = [rows["main thread"][i] - rows["prepare_step"][i] for i in range(args.rounds)]
        print(f"  {'main - prepare':14s} {statistics.median(crit):7.1f}   (the main thread's CPU per step "
              f"outside the part done while the planner works)")
    return 0


def run(args: argparse.Namespace) -> int:
    """`txt2sce bench lockstep_cpu`: this checkout, with the parts (`--quick`: one round)."""
    return main(["--parts", "--rounds", "1" if args.quick else "5"])


if __name__ == "__main__":
    sys.exit(main())
