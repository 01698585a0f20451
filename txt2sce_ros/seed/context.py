"""Context of a written seed (or of a mutant: a seed whose Init was edited): its map, where each entity starts, the
ego's route and the positions each entity must still reach — what the tree's context-aware mutations need (paper
Table III: WPM initialisation location, OIM obstacle position, TLS signal facing the AV). The one context module:
the seed stage's tests and the tree both read seeds through it.

    from txt2sce_ros.seed.context import SeedContext
    ctx = SeedContext.from_file("out/dmvca-....xosc")     # map from RoadNetwork/LogicFile (see `resolve_map`)
    ctx.start("npc1")                                     # LanePose (or WorldPose for off-lane starts)
    ctx.starts["npc1"]                                    # LanePos as written (lane starts only)
    ctx.reachable_lanes("npc1", max_back=100.0)           # lanes from which npc1's start lane is reachable
    ctx.shift_start("npc1", -12.0)                        # LanePose 12 m further back along its lanes
    ctx.is_drivable("1", -2, 35.0)                        # a driving lane exists there
    ctx.map.lane_width("1", -2, 35.0)                     # MapView: the few road-model answers mutators read

Only the seed and its map are read. A seed without a LogicFile still gives a context (`map` is None); the queries
that need the map raise InputError then.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import networkx as nx
from lxml import etree

from ..errors import InputError
from ..paths import BUNDLED_MAPS, shared_dir
from ..road import LaneRef, RoadNetwork, load_network
from ..xosc.schema import parse_document, safe_parser
from .model import LanePose, WorldPose


@dataclass(frozen=True)
class LanePos:
    """An OpenSCENARIO LanePosition as written: road id, lane id, s along the road, offset (m, toward +t)."""

    road: str
    lane: int
    s: float
    offset: float = 0.0


def lane_pos(el: etree._Element) -> LanePos:
    """The LanePos of a `LanePosition` element (a missing attribute reads as 0 / empty)."""
    return LanePos(road=el.get("roadId", ""), lane=int(float(el.get("laneId", "0"))), s=float(el.get("s", "0")),
                   offset=float(el.get("offset", "0") or 0))


@dataclass(frozen=True, slots=True)
class ReachableLane:
    ref: LaneRef
    distance: float        # m of lane-following (and lane changes) from the start of `ref` to the entity's lane


def resolve_map(base_dir: Path | None, filepath: str, *, source: str | None = None) -> Path:
    """The map a seed names: relative to the seed's directory (as esmini reads it), else by file name among the
    bundled maps and the shared esmini maps (a seed copied away from its maps still opens)."""
    cand: list[Path] = []
    if base_dir is not None:
        cand.append((base_dir / filepath).resolve())
    cand.append(Path(filepath))
    name = Path(filepath).name
    cand += [BUNDLED_MAPS / name, shared_dir() / "data" / "conformance" / "esmini" / "xodr" / name]
    for c in cand:
        if c.is_file():
            return c.resolve()
    raise InputError(f"map '{filepath}' not found (looked beside the seed, in bundled and shared maps)",
                     source=source, element="RoadNetwork/LogicFile")


class MapView:
    """The few road-model answers the mutators read, each tolerant where a mutant may point off the map."""

    def __init__(self, network: RoadNetwork, path: Path) -> None:
        self.network = network
        self.path = path

    def _road(self, road_id: str):
        road = self.network.roads.get(str(road_id))
        if road is None:
            raise InputError(f"road {road_id} not in map", source=str(self.path), element=f"road[@id='{road_id}']")
        return road

    def has_road(self, road_id: str) -> bool:
        return str(road_id) in self.network.roads

    def road_length(self, road_id: str) -> float:
        return float(self._road(road_id).length)

    def in_junction(self, road_id: str) -> bool:
        return self._road(road_id).in_junction

    def lane_type(self, road_id: str, lane_id: int, s: float) -> str | None:
        """Type of the lane at s, None when the lane does not exist there."""
        try:
            return self.network.lane_type(str(road_id), int(lane_id), float(s))
        except InputError:
            return None

    def lane_width(self, road_id: str, lane_id: int, s: float) -> float:
        return float(self.network.lane_width(str(road_id), int(lane_id), float(s)))

    def signals_on(self, road_id: str, lane_id: int | None = None) -> list[str]:
        """Ids of the map's signals on `road_id` (those controlling `lane_id` first when given)."""
        sigs = [sg for sg in self.network.signals.values() if str(sg.road_id) == str(road_id)]
        if lane_id is not None:
            sigs.sort(key=lambda sg: lane_id not in getattr(sg, "controlled_lanes", ()))
        return [str(sg.id) for sg in sigs]

    def direction(self, road_id: str, lane_id: int) -> int:
        """+1 when the lane drives toward increasing s, -1 otherwise (by the road's traffic rule and the lane id's
        side; a lane's own `direction="reversed"` is not consulted, as the OpenSCENARIO s of a start is not)."""
        return 1 if self.network.lane_forward(self._road(road_id).id, int(lane_id)) else -1


class SeedContext:
    """Facts about one seed that the context-aware operators read (never mutated by them)."""

    def __init__(self, root: etree._Element, *, source: str, map_path: Path | None) -> None:
        self.root = root
        self.source = source
        self.map_path = map_path
        self.network: RoadNetwork | None = load_network(map_path) if map_path is not None else None
        self.map: MapView | None = MapView(self.network, map_path) if self.network is not None else None
        self._positions: dict[str, LanePos | WorldPose] = {}
        for priv in root.iterfind("Storyboard/Init/Actions/Private"):
            name = priv.get("entityRef")
            pos = priv.find("PrivateAction/TeleportAction/Position")
            if name is None or pos is None:
                continue
            lp, wp = pos.find("LanePosition"), pos.find("WorldPosition")
            if lp is not None:
                self._positions[name] = lane_pos(lp)
            elif wp is not None:
                self._positions[name] = WorldPose(float(wp.get("x")), float(wp.get("y")),
                                                  float(wp.get("h", "0") or 0))
        #: entity -> Init TeleportAction LanePosition (lane starts only)
        self.starts: dict[str, LanePos] = {n: p for n, p in self._positions.items() if isinstance(p, LanePos)}
        #: ego route waypoints (first = start, last = goal)
        self.ego_route: list[LanePos] = [lane_pos(lp) for lp in root.iterfind(
            "Storyboard/Init/Actions/Private[@entityRef='ego']/PrivateAction/RoutingAction/AssignRouteAction/Route/"
            "Waypoint/Position/LanePosition")]
        #: entity -> positions it must still reach (routes, its manoeuvres, reach-position triggers)
        self.must_reach: dict[str, list[LanePos]] = self._must_reach()
        #: entity -> txt2sce:category
        self.categories: dict[str, str] = {}
        for obj in root.iterfind("Entities/ScenarioObject"):
            prop = obj.find("*/Properties/Property[@name='txt2sce:category']")
            self.categories[obj.get("name", "")] = prop.get("value", "") if prop is not None else ""
        #: signal ids facing the ego: its start lane's first, then its route's
        self.ego_signals: tuple[str, ...] = self._ego_signals()

    # ------------------------------------------------------------------------------------------------ building
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
        return cls.from_root(parse_document(xosc, source=source), base_dir=Path(base_dir), source=source)

    @classmethod
    def from_root(cls, root: etree._Element, *, base_dir: Path | None, source: str) -> "SeedContext":
        lf = root.find("RoadNetwork/LogicFile")
        map_path = resolve_map(base_dir, lf.get("filepath", ""), source=source) if lf is not None else None
        return cls(root, source=source, map_path=map_path)

    def _must_reach(self) -> dict[str, list[LanePos]]:
        must: dict[str, list[LanePos]] = {name: [] for name in self.starts}
        must.setdefault("ego", [])
        must["ego"].extend(self.ego_route[1:])
        for mg in self.root.iterfind("Storyboard/Story/Act/ManeuverGroup"):
            actors = [e.get("entityRef", "") for e in mg.iterfind("Actors/EntityRef")]
            positions = [lane_pos(lp) for lp in mg.iter("LanePosition")]
            for a in actors:
                must.setdefault(a, []).extend(positions)
        for cond in self.root.iter("ByEntityCondition"):
            trig = [e.get("entityRef", "") for e in cond.iterfind("TriggeringEntities/EntityRef")]
            for lp in cond.iterfind("EntityCondition/ReachPositionCondition/Position/LanePosition"):
                for t in trig:
                    must.setdefault(t, []).append(lane_pos(lp))
        return must

    def _ego_signals(self) -> tuple[str, ...]:
        out: list[str] = []
        ego = self.starts.get("ego")
        if self.map is None or self.network is None or ego is None:
            return ()
        lanes = [(p.road, p.lane) for p in [ego] + self.ego_route[1:]]
        if self.map.has_road(ego.road) and self.map.in_junction(ego.road):
            # an AV standing past the stop line, inside the junction, still faces its approach's lights (the
            # route's later roads carry the lights facing the other way)
            ref = self.network.lane_ref(ego.road, ego.lane, ego.s)
            lanes = [(p.road_id, p.lane_id) for p in self.network.predecessors(ref)] + lanes
        for road, lane in lanes:
            if self.map.has_road(road):
                out += [sid for sid in self.map.signals_on(road, lane) if sid not in out]
        return tuple(out)

    # ------------------------------------------------------------------------------------------------ queries
    def _net(self, element: str) -> RoadNetwork:
        if self.network is None:
            raise InputError("seed has no RoadNetwork/LogicFile", source=self.source, element=element)
        return self.network

    @property
    def entities(self) -> list[str]:
        return list(self._positions)

    def start(self, name: str) -> LanePose | WorldPose:
        """The entity's initial pose: a LanePose with its world pose, or the WorldPose it was written as."""
        try:
            pos = self._positions[name]
        except KeyError:
            raise InputError(f"no initial position for '{name}'", source=self.source, element="Private") from None
        if isinstance(pos, WorldPose):
            return pos
        x, y, h = self._net("LogicFile").lane_to_world(pos.road, pos.lane, pos.s, pos.offset)
        return LanePose(pos.road, pos.lane, pos.s, pos.offset, x, y, h)

    def start_lane(self, name: str) -> LaneRef | None:
        st = self.start(name)
        net = self._net("LogicFile")
        if isinstance(st, LanePose):
            return net.lane_ref(st.road_id, st.lane_id, st.s)
        loc = net.locate(st.x, st.y, st.h)
        return None if loc is None else net.lane_ref(loc.road_id, loc.lane_id, loc.s)

    def is_drivable(self, road_id: str, lane_id: int, s: float) -> bool:
        net = self._net("LogicFile")
        try:
            road = net.roads[str(road_id)]
        except KeyError:
            return False
        if not 0.0 <= s <= road.length or lane_id == 0:
            return False
        return int(lane_id) in net.lane_ids(str(road_id), s)

    def reachable_lanes(self, name: str, *, max_back: float = 150.0, lane_changes: bool = True
                        ) -> list[ReachableLane]:
        """Lanes from which the entity's start lane can be reached by following lanes (and changing lanes when
        `lane_changes`) within `max_back` m: the places a mutated start may move to and still lead into the same
        conflict. Sorted by distance, the start lane first."""
        ref = self.start_lane(name)
        if ref is None:
            return []
        g = self._net("LogicFile").routing_graph
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
        net = self._net("TeleportAction")
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


def build_context(root: etree._Element, *, source: str, seed_path: Path | None) -> SeedContext:
    """The context of a parsed seed read from `seed_path` (its map resolved beside it, see `resolve_map`)."""
    return SeedContext.from_root(root, base_dir=seed_path.parent if seed_path is not None else None, source=source)
