"""Oracle monitor: the paper's bug-detection oracles (safety, smoothness, smartness), the five behaviour categories
and run verdicts (core, no rclpy), plus MCAP recording, offline judging, replay and the ROS 2 monitor node."""

from .oracle import Oracle
from .params import OracleParams, SafetyParams, SmartnessParams, SmoothnessParams
from .records import Category, Finding, Rule, RunVerdict, Violation

__all__ = ["Oracle", "OracleParams", "SafetyParams", "SmartnessParams", "SmoothnessParams", "Category", "Finding",
           "Rule", "RunVerdict", "Violation"]
