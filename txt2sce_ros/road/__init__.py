"""The OpenDRIVE road model shared by generator, player, planner and oracles (API: docs/road_api.md)."""

from .model import Connection, Controller, Junction, LaneRef, Road, RoadLink, Signal
from .network import RoadNetwork, load_network

__all__ = ["Connection", "Controller", "Junction", "LaneRef", "Road", "RoadLink", "RoadNetwork", "Signal",
           "load_network"]
