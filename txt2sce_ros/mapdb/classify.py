"""Segment-level classification: road layout tags, junction legs, roundabouts, traffic control from signals."""

from __future__ import annotations

import math
from typing import Iterable

import networkx as nx
import numpy as np

from ..road import Road, RoadNetwork, Signal
from .records import Control, Layout, SectionInfo

#: A road counts as a curve when its reference line bends at least this much in total with a radius under this.
CURVE_MIN_TURN = math.radians(10.0)
CURVE_MAX_RADIUS = 500.0
#: Road directions within this angle of each other at a junction are one leg (e.g. the two halves of a dual road).
LEG_MERGE_ANGLE = math.radians(35.0)
#: Signals further than this from the junction do not control its approach.
CONTROL_RANGE = 60.0
#: Stop-sign types across the signal catalogues seen in maps (DE StVO 206, US MUTCD R1-1, OpenDRIVE generic).
STOP_TYPES = {"206", "R1-1", "r1-1", "stop"}
#: Parking stalls of a lot (perpendicular or angled) are wider than kerb-side parallel parking lanes.
STALL_MIN_WIDTH = 4.5


def curvature_profile(road: Road) -> tuple[float, float, float]:
    """(max |curvature| 1/m, signed heading change rad, total absolute turning rad) of a road's reference line."""
    n = max(3, int(road.length / 1.0) + 1)
    s = np.linspace(0.0, road.length, n)
    k = road.plan_view.curvature(s)
    if n < 2 or road.length <= 0:
        return 0.0, 0.0, 0.0
    return float(np.max(np.abs(k))), float(np.trapezoid(k, s)), float(np.trapezoid(np.abs(k), s))


def road_layouts(road: Road, main: SectionInfo, max_curv: float, abs_turn: float) -> set[Layout]:
    """Layout tags of a road outside junctions: straight or curve, plus parking for lot-like roads."""
    tags = {Layout.CURVE if (abs_turn >= CURVE_MIN_TURN and max_curv >= 1.0 / CURVE_MAX_RADIUS)
            else Layout.STRAIGHT}
    parking = [ln for ln in main.lanes if ln.type == "parking"]
    lot_like = (road.road_type in ("lowSpeed", "parking") or "parking" in road.name.lower()
                or any(ln.width >= STALL_MIN_WIDTH for ln in parking))
    if parking and lot_like:
        tags.add(Layout.PARKING)
    return tags


def count_legs(bearings: Iterable[float]) -> int:
    """Number of distinct directions among bearings (rad), merging those within `LEG_MERGE_ANGLE`."""
    angles = sorted(a % (2 * math.pi) for a in bearings)
    if not angles:
        return 0
    groups = 1
    for prev, cur in zip(angles, angles[1:]):
        if cur - prev > LEG_MERGE_ANGLE:
            groups += 1
    if groups > 1 and (angles[0] + 2 * math.pi - angles[-1]) <= LEG_MERGE_ANGLE:
        groups -= 1  # the first and last group wrap around 0
    return groups


def roundabout_roads(graph: nx.MultiDiGraph, ring_like: set[str], turning: dict[str, float]) -> set[str]:
    """Roads on a directed cycle of one-way, consistently bending roads whose turning, connecting roads included,
    adds up to a full circle. `turning` maps road ids (segments and connecting roads) to their heading change."""
    sub = nx.DiGraph()
    sub.add_nodes_from(ring_like)
    via: dict[tuple[str, str], float] = {}
    for a, b, data in graph.edges(data=True):
        if a in ring_like and b in ring_like:
            sub.add_edge(a, b)
            via[(a, b)] = turning.get(data.get("connecting_road") or "", 0.0)
    found: set[str] = set()
    for cycle in nx.simple_cycles(sub, length_bound=12):
        turn = sum(turning[r] + via[(r, cycle[(k + 1) % len(cycle)])] for k, r in enumerate(cycle))
        if abs(abs(turn) - 2 * math.pi) < math.radians(45):
            found.update(cycle)
    return found


def signal_control(signals: Iterable[Signal]) -> Control:
    """The control a set of signals puts on an approach: a light beats a stop sign beats nothing."""
    sigs = list(signals)
    if any(s.is_traffic_light for s in sigs):
        return Control.SIGNAL
    if any(is_stop_sign(s) for s in sigs):
        return Control.STOP_SIGN
    return Control.NONE


def is_stop_sign(sig: Signal) -> bool:
    return not sig.dynamic and (sig.type in STOP_TYPES or "stop" in sig.name.lower() and sig.type != "294")


def approach_signals(net: RoadNetwork, road: Road, at_end: bool, lanes: Iterable[int]) -> list[Signal]:
    """Traffic lights and stop signs on `road` near its junction end that apply to any of `lanes`."""
    wanted = set(lanes)
    end_s = road.length if at_end else 0.0
    out = []
    for sig in road.signals:
        if abs(sig.s - end_s) > CONTROL_RANGE:
            continue
        if not (sig.is_traffic_light or is_stop_sign(sig)):
            continue
        if sig.controlled_lanes and not wanted & set(sig.controlled_lanes):
            continue
        if not sig.controlled_lanes and sig.orientation in ("+", "-") and (sig.orientation == "+") != at_end:
            continue
        out.append(net.signals.get(sig.id, sig) if not sig.is_reference else sig)
    return out
