"""The OpenDRIVE road model shared by generator, player, planner and oracles (API: docs/road_api.md).

Modules, one concern each: `parse` (hardened XML -> records), `geometry` (planView primitives), `lanes` (sections,
widths, borders), `model` (records), `network` (RoadNetwork: geometry API), `lookup` ((x, y) -> lane),
`topology` (links, neighbours, routing), `lanepath` (LanePath for route following).
"""

from ..lazy import lazy_exports

# Lazy: a module that needs the network alone does not load the spatial index, route paths and topology with it.
__getattr__, __dir__ = lazy_exports(__name__, {
    "LanePath": ".lanepath", "LaneMatch": ".lookup", "LanePoint": ".lookup",
    **{name: ".model" for name in ("Connection", "Controller", "Junction", "LaneRef", "Road", "RoadLink", "Signal")},
    "RoadNetwork": ".network", "load_network": ".network", "load_network_text": ".network",
    "DRIVABLE_TYPES": ".topology"})

__all__ = ["Connection", "Controller", "DRIVABLE_TYPES", "Junction", "LaneMatch", "LanePath", "LanePoint",
           "LaneRef", "Road", "RoadLink", "RoadNetwork", "Signal", "load_network", "load_network_text"]
