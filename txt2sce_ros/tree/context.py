"""Re-export of the seed context for callers outside the tree package that import it from here
(`txt2sce_ros.analysis.features`, `txt2sce_ros.bench.tree`). The implementation is `txt2sce_ros.seed.context`;
tree modules import it from there."""

from ..seed.context import LanePos, MapView, SeedContext, build_context, lane_pos, resolve_map

__all__ = ["LanePos", "MapView", "SeedContext", "build_context", "lane_pos", "resolve_map"]
