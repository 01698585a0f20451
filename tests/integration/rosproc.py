"""Helpers for tests that start real ROS 2 processes over DDS (GUIDE.md settings)."""

from __future__ import annotations

import os
import subprocess
import sys
import time
from pathlib import Path
from typing import Callable

from txt2sce_ros.ros_env import pick_domain_id, ros_environment


def ros_test_env(tmp_path: Path) -> dict[str, str]:
    """A unique domain and a private log dir per test."""
    return ros_environment(domain_id=pick_domain_id(f"{tmp_path}:{os.getpid()}:{time.time_ns()}"),
                           log_dir=tmp_path / "ros_log")


def use_env_in_process(env: dict[str, str]) -> None:
    for key in ("ROS_AUTOMATIC_DISCOVERY_RANGE", "ROS_DOMAIN_ID", "ROS_LOG_DIR", "FASTRTPS_DEFAULT_PROFILES_FILE",
                "RMW_IMPLEMENTATION"):
        os.environ[key] = env[key]


def start(name: str, params: dict[str, object], env: dict[str, str], log: Path) -> subprocess.Popen[bytes]:
    from txt2sce_ros.launcher import node_command

    out = open(log, "wb")
    return subprocess.Popen(node_command(name, params), env=env, stdout=out, stderr=subprocess.STDOUT,
                            start_new_session=True)


def wait_until(cond: Callable[[], bool], timeout: float, spin: Callable[[], None] | None = None) -> bool:
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if cond():
            return True
        if spin:
            spin()
        else:
            time.sleep(0.05)
    return cond()


def python() -> str:
    return sys.executable
