"""CommonRoad's reactive planner (TUM, `commonroad-reactive-planner`) on the txt2sce topics; see README.md here.

Modules: `lanelets` (the road model as a CommonRoad lanelet network, cached per map), `prediction` (obstacles and
their documented prediction), `settings` (the adapter's settings, named in every result), `core` (one planning
step: frame in, command out, no rclpy), `node` (the ROS 2 node), `venv` (where its environment lives).
"""

#: Name the harness uses for this planner (`--planner commonroad`).
PLANNER_NAME = "commonroad"
