"""Map database (paper §III-A.2): a networkx graph over the OpenDRIVE road model, road-matching queries, and the
generated bundled maps (`txt2sce mapdb build-maps`)."""

from .cache import load_map_database
from .database import MapDatabase, build_map_database
from .records import (Approach, ApproachLane, ConnectionEdge, Control, JunctionInfo, LaneInfo, Layout, RoadMatch,
                      SectionInfo, Segment, Turn)

__all__ = ["Approach", "ApproachLane", "ConnectionEdge", "Control", "JunctionInfo", "LaneInfo", "Layout",
           "MapDatabase", "RoadMatch", "SectionInfo", "Segment", "Turn", "build_map_database",
           "load_map_database"]
