"""A node of the graph that cannot start (a bad parameter, a missing input, a directory it cannot write) ends with
one line naming the cause and exit status 2, never a traceback; `txt2sce_launch` quotes that line. Real processes."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest

from txt2sce_ros.launcher import _executable, node_command
from txt2sce_ros.paths import shared_dir

from .rosproc import ros_test_env

XOSC = shared_dir() / "data" / "conformance" / "esmini" / "xosc"


def _run(cmd: list[str], env: dict[str, str], timeout: float = 60.0) -> subprocess.CompletedProcess[str]:
    return subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=timeout)


@pytest.mark.timeout(180)
@pytest.mark.parametrize("node,params,message", [
    ("generator_node", {"scenarios": ["/no/such/dir"]}, r"generator_node: error: /no/such/dir: no such scenario"),
    ("generator_node", {"scenarios": 5}, r"generator_node: error: parameter scenarios: expected a path"),
    ("oracle_monitor_node", {"bag_dir": "/proc/no_bags_here"}, r"oracle_monitor_node: error: /proc/no_bags_here"),
    ("planner_node", {"faults": "ignore_cyclists"}, r"planner_node: error: .*'faults'.*STRING_ARRAY"),
    ("scenario_player_node", {"dt": "fast"}, r"scenario_player_node: error: .*'dt'.*DOUBLE"),
])
def test_a_node_that_cannot_start_says_why_in_one_line(node: str, params: dict, message: str,
                                                        tmp_path: Path) -> None:
    import re

    res = _run(node_command(node, params), ros_test_env(tmp_path))
    assert res.returncode == 2, (res.stdout, res.stderr)
    assert "Traceback" not in res.stderr + res.stdout
    assert re.search(message, res.stderr), res.stderr


@pytest.mark.timeout(120)
def test_the_generator_takes_one_path_as_a_string(tmp_path: Path) -> None:
    # `-p scenarios:=cut-in.xosc`: what a user types first; no player listens, so it gives up after 1 s.
    cmd = node_command("generator_node", {"subscriber_timeout": 1.0})
    cmd += ["-p", f"scenarios:={XOSC / 'cut-in.xosc'}"]
    res = _run(cmd, ros_test_env(tmp_path))
    assert res.returncode == 0, res.stderr
    assert "1 scenario(s) to publish" in res.stdout + res.stderr


@pytest.mark.timeout(180)
def test_the_launcher_quotes_the_failing_node(tmp_path: Path) -> None:
    env = ros_test_env(tmp_path)
    cmd = _executable("txt2sce_launch") + ["--scenarios", str(tmp_path / "nothing"), "--log-dir",
                                           str(tmp_path / "logs"), "--bag-dir", str(tmp_path / "bags")]
    res = _run(cmd, env, timeout=150)
    assert res.returncode == 1
    assert f"generator failed (exit status 2): generator_node: error: {tmp_path / 'nothing'}" in res.stderr, \
        res.stderr
    assert "player failed" not in res.stderr and "Traceback" not in res.stderr
