"""The stand-in Autoware-like planner: the system under test of the closed loop, kept apart from the harness so
swapping in a real ADS is visibly a swap. Core (no rclpy): `Planner(network, goal, params, faults=...)`,
`planner.step(frame) -> ControlCommand`; the ROS 2 node is `standin_planner.node`."""

from .environment import friction_from_xosc
from .faults import Faults
from .params import PlannerParams
from .planner import Decision, Planner

__all__ = ["Decision", "Faults", "Planner", "PlannerParams", "friction_from_xosc"]
