"""A node process's end (`txt2sce_ros.nodes.lifetime`): a stop signal that shuts the context down under a running
spin ends the process quietly, however rclpy reports it; an error while the context is up is still an error."""

from __future__ import annotations

import os
import subprocess
import sys
import time
from pathlib import Path

import pytest

pytest.importorskip("rclpy")

from txt2sce_ros.ros_env import pick_domain_id, ros_environment  # noqa: E402

_SCRIPT = """
import rclpy
from rclpy._rclpy_pybind11 import RCLError
from txt2sce_ros.nodes.lifetime import node_lifetime

rclpy.init()
node = rclpy.create_node("lifetime_probe")
with node_lifetime(node):
    if {stop}:
        rclpy.shutdown()      # what rclpy's SIGINT handler does, between the spin's check and its wait set
    # ... and what the spin then raises (seen from planner_node under load), instead of ExternalShutdownException
    raise RCLError("failed to initialize wait set: the given context is not valid")
print("ended quietly")
"""


def _run(tmp_path: Path, stop: bool) -> subprocess.CompletedProcess[str]:
    env = ros_environment(domain_id=pick_domain_id(f"{tmp_path}:{os.getpid()}:{time.time_ns()}"),
                          log_dir=tmp_path / "log")
    env["PYTHONPATH"] = os.pathsep.join([str(Path(__file__).resolve().parents[2]), env.get("PYTHONPATH", "")])
    return subprocess.run([sys.executable, "-c", _SCRIPT.format(stop=stop)], env=env, capture_output=True,
                          text=True, timeout=60)


def test_a_stop_under_the_spin_ends_quietly(tmp_path: Path) -> None:
    done = _run(tmp_path, stop=True)
    assert (done.returncode, done.stdout.strip()) == (0, "ended quietly"), done.stderr


def test_an_error_while_the_context_is_up_is_not_swallowed(tmp_path: Path) -> None:
    done = _run(tmp_path, stop=False)
    assert done.returncode == 1 and "RCLError" in done.stderr and "ended quietly" not in done.stdout
