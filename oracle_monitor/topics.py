"""The message type of every topic the monitor records (ROS 2 names, as rosbag2 metadata spells them)."""

from __future__ import annotations

from txt2sce_ros import contract as c

TOPIC_TYPES: dict[str, str] = {
    c.TOPIC_SCENARIO: "std_msgs/msg/String",
    c.TOPIC_RUN_STATUS: "std_msgs/msg/String",
    c.TOPIC_CLOCK: "rosgraph_msgs/msg/Clock",
    c.TOPIC_EGO_ODOM: "nav_msgs/msg/Odometry",
    c.TOPIC_OBJECTS_ODOM: "nav_msgs/msg/Odometry",
    c.TOPIC_OBJECTS_MARKERS: "visualization_msgs/msg/MarkerArray",
    c.TOPIC_TRAFFIC_LIGHTS: "diagnostic_msgs/msg/DiagnosticArray",
    c.TOPIC_GOAL: "geometry_msgs/msg/PoseStamped",
    c.TOPIC_COMMAND: "geometry_msgs/msg/TwistStamped",
    c.TOPIC_VIOLATIONS: "diagnostic_msgs/msg/DiagnosticArray",
    c.TOPIC_MAP_MARKERS: "visualization_msgs/msg/MarkerArray",
    c.TOPIC_SCENARIO_MARKERS: "visualization_msgs/msg/MarkerArray",
}

#: What the oracle reads to judge; the others (/clock, /control/command, /oracle/violations, the view topics) are
#: recorded only.
JUDGED_TOPICS = frozenset({c.TOPIC_SCENARIO, c.TOPIC_RUN_STATUS, c.TOPIC_EGO_ODOM, c.TOPIC_OBJECTS_ODOM,
                           c.TOPIC_OBJECTS_MARKERS, c.TOPIC_TRAFFIC_LIGHTS, c.TOPIC_GOAL})
