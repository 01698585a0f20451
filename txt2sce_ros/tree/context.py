"""What context-aware mutations need to know about a seed: its map (through the shared road model), where each
entity starts, the ego's path, and the positions each entity must still reach.

The road model is used through the API of `docs/road_api.md` (`load_network`, `lane_type`, `lane_width`,
`roads[id].length`); while the package does not export `load_network` yet, its parser
(`txt2sce_ros.road.parse.parse_network`) answers the same three questions.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from lxml import etree

from ..errors import InputError
from ..paths import BUNDLED_MAPS, shared_dir


@dataclass(frozen=True)
class LanePos:
    """An OpenSCENARIO LanePosition: road id, lane id, s along the road, offset (m, toward +t)."""

    road: str
    lane: int
    s: float
    offset: float = 0.0


class MapView:
    """The few road-model answers the mutators need, over whichever road-model entry point exists."""

    def __init__(self, path: Path) -> None:
        self.path = path
        self._net = None
        self._parsed = None
        try:
            from ..road import load_network  # type: ignore[attr-defined]

            self._net = load_network(str(path))
        except ImportError:
            from ..road.parse import parse_network

            self._parsed = parse_network(path.read_bytes(), str(path))

    def _road(self, road_id: str):
        roads = self._net.roads if self._net is not None else self._parsed.roads
        road = roads.get(str(road_id))
        if road is None:
            raise InputError(f"road {road_id} not in map", source=str(self.path), element=f"road[@id='{road_id}']")
        return road

    def has_road(self, road_id: str) -> bool:
        roads = self._net.roads if self._net is not None else self._parsed.roads
        return str(road_id) in roads

    def road_length(self, road_id: str) -> float:
        return float(self._road(road_id).length)

    def in_junction(self, road_id: str) -> bool:
        return str(self._road(road_id).junction) not in ("-1", "")

    def rule(self, road_id: str) -> str:
        return getattr(self._road(road_id), "rule", "RHT") or "RHT"

    def lane_type(self, road_id: str, lane_id: int, s: float) -> str | None:
        """Type of the lane at s, None when the lane does not exist there."""
        if self._net is not None:
            try:
                return self._net.lane_type(str(road_id), int(lane_id), float(s))
            except InputError:
                return None
        road = self._road(road_id)
        sec = road.sections[road.section_index(s)]
        lane = sec.lanes.get(int(lane_id))
        return lane.type if lane is not None else None

    def lane_width(self, road_id: str, lane_id: int, s: float) -> float:
        if self._net is not None:
            return float(self._net.lane_width(str(road_id), int(lane_id), float(s)))
        import numpy as np

        road = self._road(road_id)
        sec = road.sections[road.section_index(s)]
        lane = sec.lanes[int(lane_id)]
        return float(lane.width(np.array([s - sec.s]))[0])

    def signals_on(self, road_id: str, lane_id: int | None = None) -> list[str]:
        """Ids of the map's signals on `road_id` (those controlling `lane_id` first when given)."""
        if self._net is not None:
            sigs = [sg for sg in self._net.signals.values() if str(sg.road_id) == str(road_id)]
        else:
            sigs = list(self._road(road_id).signals)
        if lane_id is not None:
            sigs.sort(key=lambda sg: lane_id not in getattr(sg, "controlled_lanes", ()))
        return [str(sg.id) for sg in sigs]

    def direction(self, road_id: str, lane_id: int) -> int:
        """+1 when the lane drives toward increasing s, -1 otherwise (right-hand traffic: negative lane ids)."""
        rht = self.rule(road_id) != "LHT"
        return (1 if lane_id < 0 else -1) if rht else (1 if lane_id > 0 else -1)


def lane_pos(el: etree._Element) -> LanePos:
    return LanePos(road=el.get("roadId", ""), lane=int(float(el.get("laneId", "0"))), s=float(el.get("s", "0")),
                   offset=float(el.get("offset", "0") or 0))


def resolve_map(seed_path: Path | None, filepath: str) -> Path:
    """The map a seed names: relative to the seed (as esmini reads it), else by file name among the bundled maps and
    the shared esmini maps."""
    cand: list[Path] = []
    if seed_path is not None:
        cand.append((seed_path.parent / filepath).resolve())
    cand.append(Path(filepath))
    name = Path(filepath).name
    cand += [BUNDLED_MAPS / name, shared_dir() / "data" / "conformance" / "esmini" / "xodr" / name]
    for c in cand:
        if c.is_file():
            return c.resolve()
    raise InputError(f"map '{filepath}' not found (looked beside the seed, in bundled and shared maps)",
                     source=str(seed_path), element="RoadNetwork/LogicFile")


@dataclass
class SeedContext:
    """Facts about the seed that the context-aware operators read (never mutated by them)."""

    source: str
    map_path: Path | None
    map: MapView | None
    starts: dict[str, LanePos]          # entity -> Init TeleportAction LanePosition
    ego_route: list[LanePos]            # ego route waypoints (first = start, last = goal)
    must_reach: dict[str, list[LanePos]]  # entity -> positions it must still reach (routes, triggers)
    categories: dict[str, str]          # entity -> txt2sce:category
    ego_signals: tuple[str, ...] = ()   # signal ids facing the ego: its start lane's first, then its route's


def build_context(root: etree._Element, *, source: str, seed_path: Path | None) -> SeedContext:
    logic = root.find("RoadNetwork/LogicFile")
    map_path = resolve_map(seed_path, logic.get("filepath", "")) if logic is not None else None
    view = MapView(map_path) if map_path is not None else None
    starts: dict[str, LanePos] = {}
    for priv in root.iterfind("Storyboard/Init/Actions/Private"):
        lp = priv.find("PrivateAction/TeleportAction/Position/LanePosition")
        if lp is not None:
            starts[priv.get("entityRef", "")] = lane_pos(lp)
    ego_route = [lane_pos(lp) for lp in root.iterfind(
        "Storyboard/Init/Actions/Private[@entityRef='ego']/PrivateAction/RoutingAction/AssignRouteAction/Route/"
        "Waypoint/Position/LanePosition")]
    must: dict[str, list[LanePos]] = {name: [] for name in starts}
    must.setdefault("ego", [])
    must["ego"].extend(ego_route[1:])
    for mg in root.iterfind("Storyboard/Story/Act/ManeuverGroup"):
        actors = [e.get("entityRef", "") for e in mg.iterfind("Actors/EntityRef")]
        positions = [lane_pos(lp) for lp in mg.iter("LanePosition")]
        for a in actors:
            must.setdefault(a, []).extend(positions)
    for cond in root.iter("ByEntityCondition"):
        trig = [e.get("entityRef", "") for e in cond.iterfind("TriggeringEntities/EntityRef")]
        for lp in cond.iterfind("EntityCondition/ReachPositionCondition/Position/LanePosition"):
            for t in trig:
                must.setdefault(t, []).append(lane_pos(lp))
    cats = {}
    for obj in root.iterfind("Entities/ScenarioObject"):
        prop = obj.find("*/Properties/Property[@name='txt2sce:category']")
        cats[obj.get("name", "")] = prop.get("value", "") if prop is not None else ""
    ego_signals: list[str] = []
    ego = starts.get("ego")
    if view is not None and ego is not None:
        for pos in [ego] + ego_route[1:]:
            if view.has_road(pos.road):
                ego_signals += [sid for sid in view.signals_on(pos.road, pos.lane) if sid not in ego_signals]
    return SeedContext(source=source, map_path=map_path, map=view, starts=starts, ego_route=ego_route,
                       must_reach=must, categories=cats, ego_signals=tuple(ego_signals))
