"""Scenario elements read from a scenario file: the vocabulary of trigger conditions (paper Table VI).

Elements are short strings, e.g. `position:R7`, `category:bicycle`, `npcs:2`, `events:ah`, `weather:rain`,
`signal:red`, `obstacle:yes`, and pairs such as `R7+ah` (a party's position with its event sequence), so a lift
ranking can name what the paper's table names ("R7, ah", "R7, km, 2", bicycle, fog).

They are read from the file itself (names per docs/seed_format.md, properties `txt2sce:category` and
`txt2sce:position` on the ScenarioObjects), so any scenario the tree wrote can be analysed without its history.

Positions: seeds write `txt2sce:position` (the report's reading); for files without it (third-party scenarios)
and for closeness at the start (mutations move parties), when the scenario's map is at hand each party's position
is *derived* from the Init teleports in
the ego's frame (`derived_position`), by the sketch spec's definitions of R1-R7; plus `near_start:yes` when a party
starts within `NEAR_START_GAP` metres (bumper to bumper) ahead of or behind a standing ego in its lane (what a "too close to start"
fault depends on). A written `txt2sce:position` wins over the derived one.
"""

from __future__ import annotations

import math
import os
import re
from functools import lru_cache
from pathlib import Path
from typing import Any

from lxml import etree

from ..tree.trajectory import footprint_extent
from ..xosc.schema import parse_document


#: Event-name suffix -> sketch action code (docs/seed_format.md).
ACTION_NAMES = {
    "go_straight": "a", "accelerate": "b", "decelerate": "c", "turn_left": "d", "turn_right": "e",
    "lane_change_left": "f", "lane_change_right": "g", "stop": "h", "start": "i", "u_turn": "j",
    "reverse": "k", "pull_over": "l", "cross": "m",
}
_EVENT = re.compile(r"^(?P<entity>[a-z]+\d*)_e(?P<k>\d+)_(?P<action>[a-z_]+)$")


def _props(obj: etree._Element) -> dict[str, str]:
    return {p.get("name", ""): p.get("value", "") for p in obj.iter("Property")}


#: The analysis's names for the WM weather types (tree.environment.weather_type, the one classifier).
WEATHER_LABELS = {"sunny": "clear", "cloudy": "cloudy", "rainy": "rain", "snowy": "snow", "foggy": "fog"}


def weather_label(root: etree._Element) -> str:
    """clear / cloudy / rain / snow / fog from the Init environment (the weather block); 'default' without one."""
    from ..tree.environment import weather_type

    env = root.find(".//EnvironmentAction/Environment")
    if env is None:
        return "default"
    return WEATHER_LABELS[weather_type(env)]


def signal_label(root: etree._Element, facing: tuple[str, ...] = ()) -> str:
    """The state the ego's signal shows in the phase the scenario is labelled by (the first of its signal Story:
    `seed.signal_story`), 'none' without one: the signal `tree.environment.primary_signal` picks, the one the
    tree's TLS mutation changes. A scenario in the older form (a RoadNetwork TrafficSignalController) is labelled
    by its controller's first phase."""
    from ..seed.signal_story import colour_of, plan_of
    from ..tree.environment import primary_signal

    decoded = plan_of(root)
    if decoded is not None:
        states = decoded.tested
    else:
        phase = root.find(".//TrafficSignalController/Phase")
        states = tuple((s.get("trafficSignalId", ""), s.get("state", ""))
                       for s in (phase.iterfind("TrafficSignalState") if phase is not None else ()))
    primary = primary_signal(states, facing)
    if primary is None:
        return "none"
    value = colour_of(primary[1]).lower()
    for colour in ("red", "yellow", "green"):
        if colour in value:
            return colour
    return value or "none"


#: m of bumper-to-bumper gap: a party in the ego's lane this close ahead of or behind it at the start counts as
#: `near_start:yes`. Closer than the tree keeps ordinary starts apart in a lane (config/mutation.yaml
#: `trajectory.init_location.min_gap`, 6 m): a party this close was put there on purpose (WPM-near, NCM-new
#: close_behind) or stood so in the report (a queue). Measured between footprints, not centres, so a bus and a
#: bicycle at the same gap are equally close.
NEAR_START_GAP = 6.0
_SAME_DIR = math.radians(45.0)     # heading difference below this: same direction of travel
_LANE_HALF = 1.8                   # m: lateral offset within which a party is in the ego's lane
_ROAD_HALF = 12.0                  # m: lateral offset within which a party is on the ego's road (R5-R7)


def _init_poses(root: etree._Element, net: Any) -> dict[str, tuple[float, float, float]]:
    """World (x, y, heading) of each entity's Init teleport (LanePosition or WorldPosition)."""
    poses: dict[str, tuple[float, float, float]] = {}
    for priv in root.iterfind("Storyboard/Init/Actions/Private"):
        pos = priv.find("PrivateAction/TeleportAction/Position")
        if pos is None or len(pos) == 0:
            continue
        p = pos[0]
        try:
            if p.tag == "WorldPosition":
                poses[priv.get("entityRef", "")] = (float(p.get("x", 0)), float(p.get("y", 0)), float(p.get("h", 0)))
            elif p.tag == "LanePosition" and net is not None:
                poses[priv.get("entityRef", "")] = net.lane_to_world(p.get("roadId"), int(p.get("laneId", 0)),
                                                                     float(p.get("s", 0)),
                                                                     float(p.get("offset", 0) or 0))
        except Exception:   # a position the map cannot place: no derived position for that party
            continue
    return poses


def derived_position(ego: tuple[float, float, float], other: tuple[float, float, float]) -> tuple[str, str | None]:
    """(R-code, lane) of `other` in the ego's frame (sketch spec: R1-R4 at a junction, R5-R7 on the ego's road)."""
    ex, ey, eh = ego
    dx, dy = other[0] - ex, other[1] - ey
    lon = dx * math.cos(eh) + dy * math.sin(eh)           # ahead +
    lat = -dx * math.sin(eh) + dy * math.cos(eh)          # left +
    dh = math.atan2(math.sin(other[2] - eh), math.cos(other[2] - eh))
    lane = "same" if abs(lat) <= _LANE_HALF else ("left" if lat > 0 else "right")
    if abs(dh) < _SAME_DIR and abs(lat) <= _ROAD_HALF:
        return ("R5" if lon >= 0 else "R6"), lane
    if abs(dh) > math.pi - _SAME_DIR:
        return ("R7", lane) if abs(lat) <= _ROAD_HALF and lon > 0 else ("R2", None)
    if abs(dh) < _SAME_DIR:
        return "R4", None                                  # same heading but off the ego's road: beyond a turn
    # crossing traffic: heading left-to-right across the ego's path comes from its left
    return ("R1" if dh < 0 else "R3"), None


def _ego_standing(root: etree._Element) -> bool:
    """Whether the ego's Init speed is 0 (no Init SpeedAction: it stands, as a player starts it)."""
    target = root.find("Storyboard/Init/Actions/Private[@entityRef='ego']/PrivateAction/LongitudinalAction/"
                       "SpeedAction/SpeedActionTarget/AbsoluteTargetSpeed")
    try:
        return target is None or float(target.get("value", "0")) <= 0.0
    except ValueError:
        return False


def start_gap(ego: tuple[float, float, float], ego_extent: tuple[float, float], other: tuple[float, float, float],
              other_extent: tuple[float, float]) -> float:
    """Bumper-to-bumper gap (m) along the ego's heading between the ego and a party travelling its way; extents are
    (rear, front) of each footprint from its reference point (`tree.trajectory.footprint_extent`). Negative when
    the footprints overlap along the lane."""
    lon = (other[0] - ego[0]) * math.cos(ego[2]) + (other[1] - ego[1]) * math.sin(ego[2])
    ahead = lon + other_extent[0] - ego_extent[1]
    behind = ego_extent[0] - (lon + other_extent[1])
    return max(ahead, behind)


def scenario_elements(xml: bytes, net: Any = None, facing: tuple[str, ...] = (), *,
                      root: etree._Element | None = None) -> frozenset[str]:
    """Elements of one scenario; `net` (its RoadNetwork) lets positions be derived from the Init teleports,
    `facing` names the signals facing the ego (see `signal_label`); `root`: `xml` already parsed (read only)."""
    if root is None:
        root = parse_document(xml)
    out: set[str] = set()
    npcs: dict[str, dict[str, str]] = {}
    extents: dict[str, tuple[float, float]] = {}
    obstacles = 0
    for obj in root.iterfind("Entities/ScenarioObject"):
        name = obj.get("name", "")
        props = _props(obj)
        extents[name] = footprint_extent(obj)
        if name.startswith("npc"):
            npcs[name] = props
        elif name.startswith("obs"):
            obstacles += 1
            out.add(f"obstacle:{props.get('txt2sce:category', 'other')}")
    events: dict[str, list[tuple[int, str]]] = {}
    for ev in root.iter("Event"):
        m = _EVENT.match(ev.get("name", ""))
        if m and m["entity"].startswith("npc") and m["action"] in ACTION_NAMES:
            events.setdefault(m["entity"], []).append((int(m["k"]), ACTION_NAMES[m["action"]]))
    poses = _init_poses(root, net) if npcs else {}
    ego_pose = poses.get("ego")
    # a party close to the AV matters at *its start*: an AV that drives off at speed has no start to refuse, and a
    # car standing a few metres behind it is left behind (`near_start` needs the ego standing at t = 0)
    standing = _ego_standing(root)
    if ego_pose is not None:
        for name, props in npcs.items():
            if name not in poses:
                continue
            # Derived from the (possibly mutated) start poses: closeness at the start is a fact of this file,
            # while a written position (the report's reading) wins as the party's R1-R7 label.
            code, lane = derived_position(ego_pose, poses[name])
            if standing and code in ("R5", "R6") and lane == "same" and \
                    start_gap(ego_pose, extents["ego"], poses[name], extents[name]) <= NEAR_START_GAP:
                out.add("near_start:yes")
            if not props.get("txt2sce:position"):
                props["txt2sce:position"] = code
                if lane:
                    props["txt2sce:lane"] = lane
    out.add(f"npcs:{len(npcs)}")
    out.add("obstacle:yes" if obstacles else "obstacle:no")
    for name, props in npcs.items():
        pos = props.get("txt2sce:position", "")
        cat = props.get("txt2sce:category", "")
        codes = "".join(code for _, code in sorted(events.get(name, [])))
        if pos:
            out.add(f"position:{pos}")
            if props.get("txt2sce:lane"):
                out.add(f"position:{pos}/{props['txt2sce:lane']}")
        if cat:
            out.add(f"category:{cat}")
        if codes:
            out.add(f"events:{codes}")
            if pos:
                out.add(f"{pos}+{codes}")
    out.add(f"weather:{weather_label(root)}")
    out.add(f"signal:{signal_label(root, facing)}")
    return frozenset(out)


@lru_cache(maxsize=65536)
def elements_of_file(path: str) -> frozenset[str]:
    """Elements of a scenario file, positions derived on the map it names (when that map loads)."""
    from ..road import load_network
    from ..scenario_source import logic_file, logic_file_of

    data = Path(path).read_bytes()
    try:
        # parsed once for the map's name, the signals and the elements (none of them changes the tree)
        root = parse_document(data, source=path)
    except Exception:   # not well-formed: the steps below say so as they always did
        root = None
    net, facing = None, ()
    try:
        xodr = logic_file(Path(path), data) if root is None else logic_file_of(root, Path(path))
        if xodr is not None and xodr.is_file():
            net = load_network(str(xodr))
            if b"TrafficSignalController" in data or b"TrafficSignalStateAction" in data:
                from ..seed.context import build_context

                facing = build_context(root if root is not None else parse_document(data, source=path),
                                       source=path, seed_path=Path(path)).ego_signals
    except Exception:   # the elements that need no map are still worth having
        pass
    return scenario_elements(data, net, facing, root=root)


#: Below this many files `elements_of_files` reads them in this process (a pool's start-up would cost more).
PARALLEL_FILES = 400


def elements_of_files(paths: list[str], workers: int | None = None) -> dict[str, frozenset[str]]:
    """`elements_of_file` of each of `paths`, by path: read on `workers` forked processes (default: the cores) when
    there are many (a campaign's report reads thousands of scenarios, ~0.75 ms each, while the other core idles).
    Each file's elements are the same whichever process reads them."""
    with ElementsReading(paths, workers) as reading:
        return reading.result()


class ElementsReading:
    """`elements_of_files(paths)` begun now on forked workers, answered by `result()`: a report starts it before
    the work it does alone (trees, failure plots), so that work runs beside the reading instead of before it.
    Few files: read in `result()`, in this process. A context manager: leaving it stops the workers."""

    def __init__(self, paths: list[str], workers: int | None = None) -> None:
        self._unique = list(dict.fromkeys(paths))
        workers = (os.cpu_count() or 1) if workers is None else workers
        self._pool = None
        self._answers = None
        self._done: dict[str, frozenset[str]] | None = None
        if workers >= 2 and len(self._unique) >= PARALLEL_FILES:
            import multiprocessing as mp
            from concurrent.futures import ProcessPoolExecutor

            self._pool = ProcessPoolExecutor(max_workers=workers, mp_context=mp.get_context("fork"))
            chunk = max(1, len(self._unique) // (workers * 8))
            self._answers = self._pool.map(elements_of_file, self._unique, chunksize=chunk)

    def result(self) -> dict[str, frozenset[str]]:
        if self._done is None:
            if self._answers is None:
                self._done = {p: elements_of_file(p) for p in self._unique}
            else:
                try:
                    self._done = dict(zip(self._unique, self._answers))
                finally:
                    self.close()
        return self._done

    def close(self) -> None:
        if self._pool is not None:
            self._pool.shutdown(wait=True, cancel_futures=True)
            self._pool = None

    def __enter__(self) -> "ElementsReading":
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
