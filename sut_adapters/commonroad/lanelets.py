"""The project's OpenDRIVE road model (`txt2sce_ros.road`) as a CommonRoad lanelet network, cached per map.

One lanelet per lane of a lane section (a `LaneRef`), its borders and centre line sampled from the road model in
the lane's driving direction; successors and predecessors from the road model's topology; left/right adjacency
from the neighbouring lane ids of the same section, in either direction of travel (so CommonRoad's road boundary
runs along the outer edges of a road, not between its carriageways). Only driving lanes become lanelets: what a
motion planner may drive on. Why not `commonroad-scenario-designer`'s OpenDRIVE converter: it pulls PyQt6 and SUMO
(1.2 GB), needs a geo-reference workaround and fails on 3 of the 20 shared maps, while this builder reuses the one
road model every other stage uses, so the planner's lanes are exactly the lanes the player and oracle use.
"""

from __future__ import annotations

import hashlib
import pickle
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from commonroad.scenario.lanelet import Lanelet, LaneletNetwork, LaneletType

from txt2sce_ros.paths import cache_dir
from txt2sce_ros.road import LaneRef, RoadNetwork

#: Border sample spacing (m): fine enough for the curvilinear frame on junction arcs.
DS = 1.0
#: Border points a straight chord passes within this distance (m) of are dropped: the planner's road boundary has
#: one rectangle per border segment and its collision checker copies all of them for every pose it checks, so a
#: 200 m straight sampled every metre made one planning cycle take seconds; arcs keep their points.
SIMPLIFY_TOL = 0.01
#: ... but never further apart than this (m), so that every lanelet keeps a centre line the route planner can
#: resample and locate positions on.
MAX_SPACING = 10.0
#: Lane ends closer than this (m) are one point: ends sampled from two roads' geometries differ by rounding, and the
#: union of the lanelets then keeps a slit at the seam that CommonRoad's road boundary turns into a wall across
#: the lane (the planner would not drive into a junction).
SNAP_TOL = 1e-3
#: Bump when the construction changes, so stale cached networks are not reused.
BUILD_VERSION = 3


@dataclass
class LaneletMap:
    """The lanelet network and the mapping between lanelet ids and the road model's lanes."""

    network: LaneletNetwork
    lanelet_of: dict[LaneRef, int]
    lane_of: dict[int, LaneRef]


def _driving_refs(net: RoadNetwork) -> list[LaneRef]:
    refs = []
    for rid, road in net.roads.items():
        for si, sec in enumerate(road.sections):
            for lid, lane in sec.lanes.items():
                if lid != 0 and lane.type == "driving":
                    refs.append(LaneRef(rid, si, lid))
    return refs


def _side_neighbour(net: RoadNetwork, ref: LaneRef, side: str, known: set[LaneRef]) -> tuple[LaneRef | None, bool]:
    """The driving lane beside `ref` on `side` of its driving direction, and whether it runs the same way."""
    road = net.roads[ref.road_id]
    sec_s = road.sections[ref.section].s
    forward = net.lane_forward(ref.road_id, ref.lane_id, sec_s)
    towards_plus_t = (side == "left") == forward
    lid = ref.lane_id + (1 if towards_plus_t else -1)
    if lid == 0:
        lid = 1 if towards_plus_t else -1
    other = LaneRef(ref.road_id, ref.section, lid)
    if other not in known:
        return None, False
    return other, net.lane_forward(ref.road_id, lid, sec_s) == forward


def _keep_points(left: np.ndarray, right: np.ndarray, tol: float) -> np.ndarray:
    """Indices of the border points to keep (Douglas-Peucker on both borders at once, so they stay paired)."""
    keep = np.zeros(len(left), dtype=bool)
    keep[0] = keep[-1] = True
    stack = [(0, len(left) - 1)]
    while stack:
        i, j = stack.pop()
        if j - i < 2:
            continue
        worst, k_worst = 0.0, -1
        for pts in (left, right):
            a, b = pts[i], pts[j]
            ab = b - a
            n = float(np.hypot(*ab))
            seg = pts[i + 1:j] - a
            d = np.abs(ab[0] * seg[:, 1] - ab[1] * seg[:, 0]) / n if n > 1e-9 else np.hypot(seg[:, 0], seg[:, 1])
            k = int(np.argmax(d))
            if d[k] > worst:
                worst, k_worst = float(d[k]), i + 1 + k
        if worst > tol or float(np.hypot(*(left[j] - left[i]))) > MAX_SPACING:
            k_worst = k_worst if worst > tol else (i + j) // 2
            keep[k_worst] = True
            stack += [(i, k_worst), (k_worst, j)]
    return np.flatnonzero(keep)


def _snap_ends(borders: dict[LaneRef, tuple[np.ndarray, np.ndarray]], tol: float) -> None:
    """Make lane ends that coincide within `tol` the same point (in place), the first one seen standing for all."""
    seen: list[np.ndarray] = []
    for left, right in borders.values():
        for pts in (left, right):
            for idx in (0, -1):
                p = pts[idx]
                for q in seen:
                    if abs(p[0] - q[0]) <= tol and abs(p[1] - q[1]) <= tol:
                        pts[idx] = q
                        break
                else:
                    seen.append(p.copy())


def build_lanelet_map(net: RoadNetwork) -> LaneletMap:
    """Build the lanelet network of `net` (no cache; see `lanelet_map`)."""
    refs = _driving_refs(net)
    known = set(refs)
    ids = {ref: i + 1 for i, ref in enumerate(refs)}
    borders = {}
    for ref in refs:
        left, right = net.lane_borders(ref.road_id, ref.lane_id, DS, section=ref.section)
        n = min(len(left), len(right))
        if n < 2:
            continue
        left, right = np.asarray(left[:n], dtype=float), np.asarray(right[:n], dtype=float)
        idx = _keep_points(left, right, SIMPLIFY_TOL)
        borders[ref] = (left[idx], right[idx])
    _snap_ends(borders, SNAP_TOL)
    lanelets = []
    for ref, (left, right) in borders.items():
        centre = 0.5 * (left + right)
        succ = [ids[s] for s in net.successors(ref) if s in ids]
        pred = [ids[p] for p in net.predecessors(ref) if p in ids]
        adj = {}
        for side in ("left", "right"):
            other, same = _side_neighbour(net, ref, side, known)
            adj[side] = (ids[other], same) if other is not None else (None, None)
        junction = net.roads[ref.road_id].junction not in ("-1", "")
        lanelets.append(Lanelet(
            left_vertices=left, center_vertices=centre, right_vertices=right, lanelet_id=ids[ref],
            predecessor=pred, successor=succ,
            adjacent_left=adj["left"][0], adjacent_left_same_direction=adj["left"][1],
            adjacent_right=adj["right"][0], adjacent_right_same_direction=adj["right"][1],
            lanelet_type={LaneletType.INTERSECTION if junction else LaneletType.URBAN}))
    network = LaneletNetwork.create_from_lanelet_list(lanelets, cleanup_ids=False)
    return LaneletMap(network, ids, {v: k for k, v in ids.items()})


_MEMO: dict[str, LaneletMap] = {}


def lanelet_map(net: RoadNetwork, xodr_text: str | bytes | None = None) -> LaneletMap:
    """The lanelet map of `net`, cached in memory and on disk (`$TXT2SCE_CACHE/commonroad/`) by the hash of the
    OpenDRIVE text (when given) so that every run on the same map after the first skips the build."""
    if xodr_text is None:
        return build_lanelet_map(net)
    data = xodr_text.encode() if isinstance(xodr_text, str) else xodr_text
    key = hashlib.sha256(data + f":v{BUILD_VERSION}:ds{DS}".encode()).hexdigest()[:24]
    if key in _MEMO:
        return _MEMO[key]
    path = Path(cache_dir()) / "commonroad" / f"{key}.pickle"
    lmap = None
    if path.is_file():
        try:
            lmap = pickle.loads(path.read_bytes())
        except Exception:           # a corrupt or incompatible cache entry is rebuilt, never trusted
            lmap = None
    if lmap is None:
        lmap = build_lanelet_map(net)
        path.parent.mkdir(parents=True, exist_ok=True)
        tmp = path.with_suffix(".tmp")
        tmp.write_bytes(pickle.dumps(lmap))
        tmp.replace(path)           # atomic: parallel adapters never read half a file
    _MEMO[key] = lmap
    return lmap
