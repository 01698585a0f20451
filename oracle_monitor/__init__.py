"""Oracle monitor: the paper's bug-detection oracles (safety, smoothness, smartness), the five behaviour categories
and run verdicts (core, no rclpy), plus MCAP recording, offline judging, replay and the ROS 2 monitor node."""

import txt2sce_ros  # noqa: F401  (first: it installs the compiled build's import hook, txt2sce_ros.accel)
from .oracle import Oracle
from .params import OracleParams, SafetyParams, SmartnessParams, SmoothnessParams
from .records import Category, Finding, Rule, RunVerdict, Violation

__all__ = ["Oracle", "OracleParams", "SafetyParams", "SmartnessParams", "SmoothnessParams", "Category", "Finding",
           "Rule", "RunVerdict", "Violation"]
