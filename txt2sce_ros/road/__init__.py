"""The OpenDRIVE road model shared by generator, player, planner and oracles (API: docs/road_api.md).

Modules, one concern each: `parse` (hardened XML -> records), `geometry` (planView primitives), `lanes` (sections,
widths, borders), `model` (records), `network` (RoadNetwork: geometry API), `lookup` ((x, y) -> lane),
`topology` (links, neighbours, routing), `lanepath` (LanePath for route following).
"""

from .lanepath import LanePath
from .lookup import LaneMatch, LanePoint
from .model import Connection, Controller, Junction, LaneRef, Road, RoadLink, Signal
from .network import RoadNetwork, load_network, load_network_text
from .topology import DRIVABLE_TYPES

__all__ = ["Connection", "Controller", "DRIVABLE_TYPES", "Junction", "LaneMatch", "LanePath", "LanePoint",
           "LaneRef", "Road", "RoadLink", "RoadNetwork", "Signal", "load_network", "load_network_text"]
