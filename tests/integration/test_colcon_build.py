"""The ament_python layout builds with colcon (from PyPI) so `ros2 run txt2sce_ros <node>` works on a ROS install."""

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
NODES = ("generator_node", "scenario_player_node", "planner_node", "oracle_monitor_node", "txt2sce")


@pytest.mark.timeout(300)
def test_colcon_build_installs_node_executables(tmp_path: Path) -> None:
    colcon = Path(sys.executable).parent / "colcon"
    if not colcon.exists():
        pytest.fail("colcon is not installed in the test environment (requirements-dev.txt)")
    src = tmp_path / "src" / "txt2sce_ros"
    files = subprocess.run(["git", "ls-files", "-co", "--exclude-standard"], cwd=REPO, capture_output=True,
                           text=True, check=True).stdout.split()
    for rel in files:
        if (REPO / rel).is_file():
            (src / rel).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(REPO / rel, src / rel)
    proc = subprocess.run([str(colcon), "build", "--base-paths", "src", "--build-base", "build",
                           "--install-base", "install"], cwd=tmp_path, capture_output=True, text=True)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    lib = tmp_path / "install" / "txt2sce_ros" / "lib" / "txt2sce_ros"
    for node in NODES:
        assert (lib / node).is_file(), f"{node} missing from {lib}"
    share = tmp_path / "install" / "txt2sce_ros" / "share"
    assert (share / "ament_index" / "resource_index" / "packages" / "txt2sce_ros").is_file()
    assert (share / "txt2sce_ros" / "package.xml").is_file()
    assert (share / "txt2sce_ros" / "launch" / "txt2sce.launch.py").is_file()
    assert (share / "txt2sce_ros" / "config" / "fastdds_profile.xml").is_file()
    # Bundled data travels inside the Python package (maps, demo narratives, the sketch schema).
    site = list((tmp_path / "install" / "txt2sce_ros" / "lib").glob("python3*/site-packages/txt2sce_ros"))
    assert site, "txt2sce_ros not installed as a Python package"
    data = site[0] / "data"
    assert list((data / "maps").glob("*.xodr")), "bundled maps missing from the install"
    assert list((data / "reports").glob("*.jsonl")), "bundled narratives missing from the install"
    assert (data / "sketch.schema.json").is_file()
