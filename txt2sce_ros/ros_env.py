"""The DDS environment every txt2sce process runs in (GUIDE.md: verified settings for this kind of machine).

Without a `ros2 launch` on PyPI, the launcher and the integration tests start each node as its own process with
this environment: discovery kept on localhost, a domain id of its own so parallel runs never see each other,
logs in a directory of the run's, and the Fast DDS profile that shortens participant announcements.
"""

from __future__ import annotations

import os
import zlib
from pathlib import Path

from .paths import config_dir


def fastdds_profile() -> Path:
    return config_dir() / "fastdds_profile.xml"


def pick_domain_id(tag: str) -> int:
    """A domain id in [1, 100] derived from `tag` (e.g. a run directory and pid): distinct runs, distinct domains.
    (Fast DDS maps domains to UDP ports; ids above ~101 overflow the port range on Linux.)"""
    return 1 + zlib.crc32(tag.encode()) % 100


def ros_environment(*, domain_id: int, log_dir: str | Path, base: dict[str, str] | None = None) -> dict[str, str]:
    """Environment for a child process: inherits everything (the wheels' .pth hook needs LD_LIBRARY_PATH)."""
    env = dict(os.environ if base is None else base)
    env["ROS_AUTOMATIC_DISCOVERY_RANGE"] = "LOCALHOST"
    env["ROS_DOMAIN_ID"] = str(domain_id)
    env["ROS_LOG_DIR"] = str(log_dir)
    env["FASTRTPS_DEFAULT_PROFILES_FILE"] = str(fastdds_profile())
    env.setdefault("RMW_IMPLEMENTATION", "rmw_fastrtps_cpp")
    env["PYTHONUNBUFFERED"] = "1"
    Path(log_dir).mkdir(parents=True, exist_ok=True)
    return env


def apply_to_current_process(*, domain_id: int, log_dir: str | Path) -> None:
    """Set the same variables in this process (before rclpy.init), e.g. for an in-test node."""
    os.environ.update(ros_environment(domain_id=domain_id, log_dir=log_dir, base={}))
