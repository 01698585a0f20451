"""The stand-in Autoware-like planner: the system under test of the closed loop, kept apart from the harness so
swapping in a real ADS is visibly a swap. Core (no rclpy): `Planner(network, goal, params, faults=...)`,
`planner.step(frame) -> ControlCommand`; the ROS 2 node is `standin_planner.node`."""

import txt2sce_ros  # noqa: F401  (first: it installs the compiled build's import hook, txt2sce_ros.accel)
from txt2sce_ros.lazy import lazy_exports

# Lazy: `txt2sce play` needs only the fault names; the planner (road model, numpy) loads when it is used.
__getattr__, __dir__ = lazy_exports(__name__, {"friction_from_xosc": ".environment", "Faults": ".faults",
                                               "PlannerParams": ".params", "Decision": ".planner",
                                               "Planner": ".planner"})

__all__ = ["Decision", "Faults", "Planner", "PlannerParams", "friction_from_xosc"]
