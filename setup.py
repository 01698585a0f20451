"""ament_python package: `colcon build` + `ros2 run txt2sce_ros <node>` on a ROS 2 install, `pip install -e .` elsewhere."""
from glob import glob
import os

from setuptools import find_packages, setup

PACKAGE = "txt2sce_ros"

# One console script per node (named after it, as ros2/examples do) plus the `txt2sce` command-line tool.
NODES = {
    "txt2sce": "txt2sce_ros.cli.main:main",
    "generator_node": "txt2sce_ros.nodes.generator_node:main",
    "scenario_player_node": "scenario_player.node:main",
    "planner_node": "standin_planner.node:main",
    "oracle_monitor_node": "oracle_monitor.node:main",
    "txt2sce_launch": "txt2sce_ros.launcher:main",
}

DATA_PACKAGES = ["txt2sce_ros.data", "txt2sce_ros.data.maps", "txt2sce_ros.data.reports"]


def _tree(src: str, dst: str) -> list[tuple[str, list[str]]]:
    """data_files entries that mirror the files under `src` into share/<pkg>/`dst`."""
    out = []
    for root, _dirs, files in os.walk(src):
        if files:
            rel = os.path.relpath(root, src)
            target = os.path.normpath(os.path.join("share", PACKAGE, dst, rel))
            out.append((target, [os.path.join(root, f) for f in files]))
    return out


setup(
    name=PACKAGE,
    version="0.1.0",
    # The bundled data directories hold no code (no __init__.py) but are importable as namespace packages; naming
    # them here is what setuptools asks for, instead of warning at every `pip install -e .` that they are absent.
    packages=find_packages(exclude=["tests", "tests.*", "bench", "bench.*"]) + DATA_PACKAGES,
    package_data={
        "txt2sce_ros.data": ["*.json"],
        "txt2sce_ros.data.reports": ["*.jsonl"],
        "txt2sce_ros.data.maps": ["*.xodr", "*.md"],
        "": ["*.yaml", "*.json", "*.jsonl", "*.xodr", "*.xosc", "*.txt", "*.md"],
    },
    include_package_data=True,
    data_files=[
        ("share/ament_index/resource_index/packages", [f"resource/{PACKAGE}"]),
        (f"share/{PACKAGE}", ["package.xml"]),
        (f"share/{PACKAGE}/launch", glob("launch/*.launch.py")),
        *_tree("config", "config"),
    ],
    install_requires=["setuptools"],
    zip_safe=False,
    maintainer="txt2sce developers",
    maintainer_email="dev@txt2sce.invalid",
    description="Accident reports to OpenSCENARIO scenario trees, closed-loop ADS testing on ROS 2.",
    license="Apache-2.0",
    entry_points={"console_scripts": [f"{name} = {target}" for name, target in NODES.items()]},
)
