"""Start the txt2sce node graph as separate processes (no `ros2 launch` is installable from PyPI).

    txt2sce_launch --scenarios DIR_OR_FILES... [--bag-dir DIR] [--fault NAME]... [--planner none]

starts the oracle monitor, the planner under test (the stand-in by default; `--planner commonroad` for CommonRoad's
reactive planner in its own venv, see sut_adapters/commonroad; `--planner none` for a real ADS already running on
the same domain), the scenario player and the generator, each as its own process with the DDS settings of
`txt2sce_ros.ros_env`. It waits for the generator to finish the scenario list, then stops the others with SIGINT
(so the monitor closes its recording), escalating to SIGTERM/SIGKILL after a grace period. The same graph is
described for real ROS installs in `launch/txt2sce.launch.py`.
"""

from __future__ import annotations

import argparse
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from .lifeline import preexec
from .ros_env import pick_domain_id, ros_environment


def _executable(name: str) -> list[str]:
    """The node's console script beside this interpreter (a venv or a colcon install), else `python -m`."""
    here = Path(sys.executable).parent / name
    if here.exists():
        return [str(here)]
    found = shutil.which(name)
    if found:
        return [found]
    raise FileNotFoundError(f"node executable {name!r} not found next to {sys.executable} or on PATH")


def _param(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (list, tuple)):
        return "[" + ",".join(f"'{v}'" if isinstance(v, str) else str(v) for v in value) + "]"
    if value == "":
        return "''"  # `name:=` alone does not parse; an empty YAML string does
    return str(value)


def node_command(executable: str, params: dict[str, Any]) -> list[str]:
    cmd = _executable(executable)
    if params:
        cmd += ["--ros-args"]
        for key, value in params.items():
            cmd += ["-p", f"{key}:={_param(value)}"]
    return cmd


@dataclass
class GraphConfig:
    scenarios: list[str]
    bag_dir: str
    planner: str = "standin"            # 'standin', 'commonroad' (sut_adapters) or 'none' (an external stack)
    faults: list[str] = field(default_factory=list)
    lock_step: bool = True
    planner_timeout: float = 5.0        # wall-clock seconds the player waits for a command before 'error'
    run_timeout: float = 300.0          # wall-clock seconds per run
    domain_id: int | None = None
    log_dir: str | None = None
    time_limit: float | None = None     # simulated seconds per run (None: the scenario's / player's own limit)
    seed: int | None = None             # player seed (None: config/player.yaml)
    planner_settings: str = ""          # third-party adapter settings file ('' = its defaults)
    planner_stats: str = ""             # where a third-party adapter writes its per-run statistics ('' = nowhere)

#: Wall-clock seconds the player waits for a command, per planner: a sampling planner in Python on a loaded
#: 2-core machine takes up to ~10 s for its first cycle (map, road boundary, route) and ~1 s per cycle after.
PLANNER_TIMEOUTS = {"commonroad": 60.0}
#: Wall-clock seconds a whole campaign run may take, per planner (default 120 s; see campaign.ros_runs).
RUN_TIMEOUTS = {"commonroad": 900.0}

#: Planners the launcher can start: the stand-in, the adapters of sut_adapters/, or none (a user's stack).
PLANNERS = ("standin", "commonroad", "none")


def graph_commands(cfg: GraphConfig) -> dict[str, list[str]]:
    """The command line of every node of the graph, in start order (consumers before producers)."""
    cmds = {
        "oracle": node_command("oracle_monitor_node", {"bag_dir": cfg.bag_dir}),
    }
    if cfg.planner not in PLANNERS:
        raise ValueError(f"unknown planner {cfg.planner!r} (choose from {', '.join(PLANNERS)})")
    if cfg.planner == "standin":
        cmds["planner"] = node_command("planner_node", {"faults": cfg.faults or [""]})
    elif cfg.planner == "commonroad":
        from sut_adapters.commonroad.venv import adapter_command

        params = {"settings": cfg.planner_settings, "stats_file": cfg.planner_stats}
        cmds["planner"] = adapter_command() + ["--ros-args"] + [
            a for k, v in params.items() for a in ("-p", f"{k}:={_param(v)}")]
    player: dict[str, object] = {
        "lock_step": cfg.lock_step, "planner_timeout": cfg.planner_timeout, "run_timeout": cfg.run_timeout,
        # frames are volatile: a run starts only once the monitor listens, or its verdict misses the first frames
        "await_subscribers": ["oracle_monitor"],
    }
    if cfg.time_limit is not None:
        player["time_limit"] = float(cfg.time_limit)
    if cfg.seed is not None:
        player["seed"] = int(cfg.seed)
    cmds["player"] = node_command("scenario_player_node", player)
    cmds["generator"] = node_command("generator_node", {"scenarios": cfg.scenarios, "wait_for_result": True})
    return cmds


class GraphCodes(dict):
    """Each process's exit code, plus what ended the graph: `early` the nodes that exited before the generator
    was done (name -> exit code), `timed_out` whether the generator outlived the timeout, and then `stuck`: each
    process still running at the timeout -> what it was doing (`describe_live`), so an error can name it."""

    def __init__(self) -> None:
        super().__init__()
        self.early: dict[str, int] = {}
        self.timed_out = False
        self.stuck: dict[str, str] = {}


_STATES = {"R": "running", "S": "waiting", "D": "blocked on I/O", "T": "stopped by a signal", "t": "stopped by a tracer",
           "Z": "exited, not reaped"}


def describe_live(pid: int, log: Path | None = None) -> str:
    """What a live process is doing, from /proc and its log: 'waiting, 1.2 s CPU, last log 40 s ago: "..."'.
    A stopped or spinning process is the one to look at; one that has been waiting while its log went quiet
    waits on another."""
    parts = []
    try:
        stat = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
        ticks = os.sysconf("SC_CLK_TCK")
        parts += [_STATES.get(stat[0], stat[0]), f"{(int(stat[11]) + int(stat[12])) / ticks:.1f} s CPU"]
    except (OSError, IndexError, ValueError):
        parts.append("state unknown")
    if log is not None and log.is_file():
        lines = _log_lines(log)
        age = time.time() - log.stat().st_mtime
        parts.append(f'last log {age:.0f} s ago: "{lines[-1][:120]}"' if lines else "no log output")
    return ", ".join(parts)


def _log_lines(log: Path) -> list[str]:
    """A node's log, its non-empty lines stripped."""
    return [ln.strip() for ln in log.read_text(encoding="utf-8", errors="replace").splitlines() if ln.strip()]


def last_error(log: Path) -> str:
    """The line of a node's log that says why it stopped: its last error line, else its last line."""
    try:
        lines = _log_lines(log)
    except OSError:
        return f"(no log at {log})"
    errors = [ln for ln in lines if "error" in ln.lower() or "exception" in ln.lower()]
    return (errors or lines or ["(empty log)"])[-1][:300]


def describe_exit(code: int) -> str:
    """'exit status 3' or 'killed by SIGKILL'."""
    if code < 0:
        try:
            return f"killed by {signal.Signals(-code).name}"
        except ValueError:
            return f"killed by signal {-code}"
    return f"exit status {code}"


def run_graph(cfg: GraphConfig, *, timeout: float = 600.0, quiet: bool = False) -> GraphCodes:
    """Run the graph until the generator exits (or `timeout`), stop the rest, return each process's exit code."""
    log_dir = Path(cfg.log_dir or tempfile.mkdtemp(prefix="txt2sce_ros_log_"))
    domain = cfg.domain_id if cfg.domain_id is not None else pick_domain_id(f"{log_dir}:{os.getpid()}")
    env = ros_environment(domain_id=domain, log_dir=log_dir)
    procs: dict[str, subprocess.Popen[bytes]] = {}
    codes = GraphCodes()
    try:
        for name, cmd in graph_commands(cfg).items():
            out = open(log_dir / f"{name}.log", "wb")
            child_env = env
            if name == "planner" and cfg.planner == "commonroad":
                from sut_adapters.commonroad.venv import adapter_environment

                child_env = adapter_environment(env)
            # Own session (so a stop reaches the node's whole group) but tied to this process: if it dies, so
            # does the node.
            procs[name] = subprocess.Popen(cmd, env=child_env, stdout=out, stderr=subprocess.STDOUT,
                                           start_new_session=True, preexec_fn=preexec())
            if not quiet:
                print(f"[launch] {name}: pid {procs[name].pid}, log {log_dir / (name + '.log')}", file=sys.stderr)
        deadline = time.monotonic() + timeout
        gen = procs["generator"]
        while gen.poll() is None:
            if time.monotonic() >= deadline:
                codes.timed_out = True
                codes.stuck = {n: describe_live(p.pid, log_dir / f"{n}.log") for n, p in procs.items()
                               if p.poll() is None}
                break
            dead = [n for n, p in procs.items() if n != "generator" and p.poll() is not None]
            if dead:
                codes.early = {n: int(procs[n].returncode) for n in dead}
                if not quiet:
                    print(f"[launch] {', '.join(dead)} exited early; stopping the graph", file=sys.stderr)
                break
            time.sleep(0.1)
    finally:
        # The player stops last: what it published and a reader has not yet received (a sample the transport
        # dropped under load is sent again when the reader asks) is lost once it exits, so the monitor drains
        # first, while the player can still answer.
        for name in sorted(reversed(list(procs)), key=lambda n: n == "player"):
            codes[name] = _stop(procs[name])
    return codes


def _stop(proc: subprocess.Popen[bytes], grace: float = 10.0) -> int:
    """SIGINT first so nodes shut down cleanly (the monitor finalises its bag), then harder."""
    if proc.poll() is not None:
        return proc.returncode
    for sig, wait in ((signal.SIGINT, grace), (signal.SIGTERM, 3.0), (signal.SIGKILL, 3.0)):
        try:
            os.killpg(proc.pid, sig)
        except ProcessLookupError:
            break
        try:
            return proc.wait(timeout=wait)
        except subprocess.TimeoutExpired:
            continue
    return proc.wait()


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="txt2sce_launch", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--scenarios", nargs="+", required=True, help=".xosc files, directories, or tree directories")
    ap.add_argument("--bag-dir", default="txt2sce_bags", help="where the monitor writes its recordings")
    ap.add_argument("--planner", choices=PLANNERS, default="standin",
                    help="'commonroad' runs CommonRoad's reactive planner (make sut-commonroad); "
                         "'none' leaves /control/command to your own stack")
    ap.add_argument("--planner-settings", default="", help="settings YAML of a third-party planner adapter")
    ap.add_argument("--fault", action="append", default=[], help="stand-in planner fault mode (repeatable)")
    ap.add_argument("--real-time", action="store_true", help="real-time mode instead of lock-step")
    ap.add_argument("--timeout", type=float, default=600.0, help="wall-clock limit for the whole graph (s)")
    ap.add_argument("--domain-id", type=int, default=None)
    ap.add_argument("--log-dir", default=None)
    a = ap.parse_args(argv)
    log_dir = Path(a.log_dir or tempfile.mkdtemp(prefix="txt2sce_ros_log_"))   # named here: failures quote it
    cfg = GraphConfig(scenarios=a.scenarios, bag_dir=a.bag_dir, planner=a.planner, faults=a.fault,
                      lock_step=not a.real_time, domain_id=a.domain_id, log_dir=str(log_dir),
                      planner_timeout=PLANNER_TIMEOUTS.get(a.planner, 5.0), planner_settings=a.planner_settings)
    codes = run_graph(cfg, timeout=a.timeout)
    print("[launch] exit codes: " + ", ".join(f"{k}={v}" for k, v in codes.items()), file=sys.stderr)
    for name, code in codes.items():
        if code > 0:        # a node that failed on its own (negative: stopped by the launcher's signal)
            print(f"[launch] {name} failed ({describe_exit(code)}): {last_error(log_dir / f'{name}.log')}",
                  file=sys.stderr)
    return 0 if codes.get("generator") == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
