"""ROS 2 launch file for a real ROS install: `ros2 launch txt2sce_ros txt2sce.launch.py scenarios:=/path/dir`.

The same graph `txt2sce_launch` starts on a plain machine: oracle monitor, stand-in planner (set
`planner:=none` to bring your own stack on the same topics), scenario player, generator.
"""

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import LaunchConfigurationEquals
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description() -> LaunchDescription:
    scenarios = LaunchConfiguration("scenarios")
    return LaunchDescription([
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
