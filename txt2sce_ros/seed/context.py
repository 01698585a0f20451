"""Context of a written seed, for the tree's context-aware mutations (paper Table III: WPM initialisation location,
OIM obstacle position): where an entity may start and still be on a drivable lane that leads to where it met the AV.

    from txt2sce_ros.seed.context import SeedContext
    ctx = SeedContext.from_file("out/dmvca-....xosc")     # map from RoadNetwork/LogicFile (relative to the file)
    ctx.start("npc1")                                     # LanePose (or WorldPose for off-lane starts)
    ctx.reachable_lanes("npc1", max_back=100.0)           # lanes from which npc1's start lane is reachable
    ctx.shift_start("npc1", -12.0)                        # LanePose 12 m further back along its lanes
    ctx.is_drivable("1", -2, 35.0)                        # a driving lane exists there

Only the seed and its map are read: a mutant (a seed whose Init was edited) gives its own context the same way.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import networkx as nx
from lxml import etree

from ..errors import InputError
from ..road import LaneRef, RoadNetwork, load_network
from ..xosc.schema import safe_parser
from .model import LanePose, WorldPose


@dataclass(frozen=True, slots=True)
class ReachableLane:
    ref: LaneRef
    distance: float        # m of lane-following (and lane changes) from the start of `ref` to the entity's lane


class SeedContext:
    def __init__(self, root: etree._Element, network: RoadNetwork, *, source: str = "<seed>") -> None:
        self.root = root
        self.network = network
        self.source = source
        self._starts: dict[str, LanePose | WorldPose] = {}
        for priv in root.iterfind("Storyboard/Init/Actions/Private"):
            name = priv.get("entityRef")
            pos = priv.find("PrivateAction/TeleportAction/Position")
            if name is None or pos is None:
                continue
            lp, wp = pos.find("LanePosition"), pos.find("WorldPosition")
            if lp is not None:
                road, lane, s = lp.get("roadId"), int(lp.get("laneId")), float(lp.get("s"))
                off = float(lp.get("offset", "0") or 0)
                x, y, h = network.lane_to_world(road, lane, s, off)
                self._starts[name] = LanePose(road, lane, s, off, x, y, h)
            elif wp is not None:
                self._starts[name] = WorldPose(float(wp.get("x")), float(wp.get("y")), float(wp.get("h", "0") or 0))

    @classmethod
    def from_file(cls, path: str | Path) -> "SeedContext":
        p = Path(path)
        try:
            root = etree.parse(str(p), safe_parser()).getroot()
        except (OSError, etree.XMLSyntaxError) as exc:
            raise InputError(f"cannot read seed: {exc}", source=str(p)) from exc
        return cls.from_root(root, base_dir=p.resolve().parent, source=str(p))

    @classmethod
    def from_text(cls, xosc: str | bytes, *, base_dir: str | Path = ".", source: str = "<seed>") -> "SeedContext":
        data = xosc.encode("utf-8") if isinstance(xosc, str) else xosc
        return cls.from_root(etree.fromstring(data, safe_parser()), base_dir=Path(base_dir), source=source)

    @classmethod
    def from_root(cls, root: etree._Element, *, base_dir: Path, source: str) -> "SeedContext":
        lf = root.find("RoadNetwork/LogicFile")
        if lf is None or not lf.get("filepath"):
            raise InputError("seed has no RoadNetwork/LogicFile", source=source, element="LogicFile")
        map_path = Path(lf.get("filepath"))
        if not map_path.is_absolute():
            map_path = base_dir / map_path
        return cls(root, load_network(map_path), source=source)

    # ------------------------------------------------------------------------------------------------ queries
    @property
    def entities(self) -> list[str]:
        return list(self._starts)

    def start(self, name: str) -> LanePose | WorldPose:
        try:
            return self._starts[name]
        except KeyError:
            raise InputError(f"no initial position for '{name}'", source=self.source, element="Private") from None

    def start_lane(self, name: str) -> LaneRef | None:
        st = self.start(name)
        if isinstance(st, LanePose):
            return self.network.lane_ref(st.road_id, st.lane_id, st.s)
        loc = self.network.locate(st.x, st.y, st.h)
        return None if loc is None else self.network.lane_ref(loc.road_id, loc.lane_id, loc.s)

    def is_drivable(self, road_id: str, lane_id: int, s: float) -> bool:
        try:
            road = self.network.roads[str(road_id)]
        except KeyError:
            return False
        if not 0.0 <= s <= road.length or lane_id == 0:
            return False
        return int(lane_id) in self.network.lane_ids(str(road_id), s)

    def reachable_lanes(self, name: str, *, max_back: float = 150.0, lane_changes: bool = True
                        ) -> list[ReachableLane]:
        """Lanes from which the entity's start lane can be reached by following lanes (and changing lanes when
        `lane_changes`) within `max_back` m: the places a mutated start may move to and still lead into the same
        conflict. Sorted by distance, the start lane first."""
        ref = self.start_lane(name)
        if ref is None:
            return []
        g = self.network.routing_graph
        if ref not in g:
            return [ReachableLane(ref, 0.0)]
        view = g if lane_changes else nx.subgraph_view(g, filter_edge=lambda u, v: g[u][v]["kind"] == "follow")
        dist = nx.single_source_dijkstra_path_length(view.reverse(copy=False), ref, cutoff=max_back,
                                                     weight="weight")
        return sorted((ReachableLane(r, round(float(d), 3)) for r, d in dist.items()),
                      key=lambda x: (x.distance, x.ref))

    def shift_start(self, name: str, ds: float) -> LanePose:
        """The start moved `ds` m along its lane (negative = back), continuing into the unique predecessor /
        successor lane when it runs off the lane's end; keeps the lateral offset. InputError when the lanes
        branch or end before `ds` is used up."""
        st = self.start(name)
        if not isinstance(st, LanePose):
            raise InputError(f"'{name}' does not start on a lane", source=self.source, element="TeleportAction")
        net = self.network
        ref = net.lane_ref(st.road_id, st.lane_id, st.s)
        s, left = st.s, float(ds)
        for _ in range(32):
            road = net.roads[ref.road_id]
            sec = road.sections[ref.section]
            lo, hi = sec.s, min(sec.end, road.length)
            forward = net.lane_forward(ref.road_id, ref.lane_id, s)
            step = left if forward else -left      # distance along the lane -> along road s
            target = s + step
            if lo - 1e-9 <= target <= hi + 1e-9:
                x, y, h = net.lane_to_world(ref.road_id, ref.lane_id, target, st.offset)
                return LanePose(ref.road_id, ref.lane_id, round(target, 3), st.offset, x, y, h)
            edge = hi if target > hi else lo
            used = abs(edge - s)
            left = left - used if left > 0 else left + used
            nxt = net.successors(ref) if left > 0 else net.predecessors(ref)
            if len(nxt) != 1:
                raise InputError(f"lane {ref} {'branches' if nxt else 'ends'} before {ds:+.1f} m",
                                 source=self.source, element="TeleportAction")
            ref = nxt[0]
            road = net.roads[ref.road_id]
            sec = road.sections[ref.section]
            fwd = net.lane_forward(ref.road_id, ref.lane_id, sec.s)
            # entering the next lane at its start (moving ahead) or its end (moving back), in driving direction
            at_start = (left > 0) == fwd
            s = sec.s if at_start else min(sec.end, road.length)
        raise InputError("shift crosses too many lanes", source=self.source, element="TeleportAction")
