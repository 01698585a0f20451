"""ROS 2 launch file for a real ROS install: `ros2 launch txt2sce_ros txt2sce.launch.py scenarios:=/path/dir`.

The same graph `txt2sce_launch` starts on a plain machine: oracle monitor, stand-in planner (set
`planner:=none` to bring your own stack on the same topics), scenario player, generator. Unless
FASTRTPS_DEFAULT_PROFILES_FILE already names a profile, the nodes load the package's `config/fastdds_profile.xml`
(as `txt2sce_launch` does): with Fast DDS's 3 s default heartbeat, samples dropped under load reached the
monitor too late or never.
"""

import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, SetEnvironmentVariable
from launch.conditions import LaunchConfigurationEquals
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description() -> LaunchDescription:
    scenarios = LaunchConfiguration("scenarios")
    profile = os.environ.get("FASTRTPS_DEFAULT_PROFILES_FILE") or os.path.join(
        get_package_share_directory("txt2sce_ros"), "config", "fastdds_profile.xml")
    return LaunchDescription([
        SetEnvironmentVariable("FASTRTPS_DEFAULT_PROFILES_FILE", profile),
        DeclareLaunchArgument("scenarios", description="scenario file or directory"),
        DeclareLaunchArgument("bag_dir", default_value="txt2sce_bags"),
        DeclareLaunchArgument("planner", default_value="standin", description="standin | none"),
        Node(package="txt2sce_ros", executable="oracle_monitor_node", name="oracle_monitor",
             parameters=[{"bag_dir": LaunchConfiguration("bag_dir")}]),
        Node(package="txt2sce_ros", executable="planner_node", name="standin_planner",
             condition=LaunchConfigurationEquals("planner", "standin")),
        Node(package="txt2sce_ros", executable="scenario_player_node", name="scenario_player",
             # frames are volatile: a run starts only once the monitor listens (else its verdict misses frames)
             parameters=[{"lock_step": True, "await_subscribers": ["oracle_monitor"]}]),
        Node(package="txt2sce_ros", executable="generator_node", name="txt2sce_generator",
             parameters=[{"scenarios": [scenarios]}]),
    ])
