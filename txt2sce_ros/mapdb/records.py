"""Typed records of the map database: segments (roads), lanes, connections, junctions and their approaches.

Directions: a lane "forward" drives along +s of its road. "Left"/"right" of a lane are taken in its own driving
direction. Turn types come from geometry (the road model's `turn_type`).
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum


class Layout(str, Enum):
    """Where an interaction happens; the first six are the sketch's `road.layout` values."""

    STRAIGHT = "straight"
    CURVE = "curve"
    JUNCTION4 = "junction4"
    JUNCTION3 = "junction3"
    ROUNDABOUT = "roundabout"
    PARKING = "parking"
    JUNCTION = "junction"  # a junction with 2 or 5+ legs


class Control(str, Enum):
    """Traffic control of a junction approach (the sketch's `road.control`)."""

    SIGNAL = "signal"
    STOP_SIGN = "stop_sign"
    NONE = "none"


class Turn(str, Enum):
    STRAIGHT = "straight"
    LEFT = "left"
    RIGHT = "right"
    UTURN = "uturn"


#: Road-level features a caller may require of one driving direction (`MapDatabase.roads(needs=...)`).
ROAD_NEEDS = frozenset({"left_neighbour", "right_neighbour", "oncoming", "bike_lane", "parking_lane", "sidewalk",
                        "shoulder", "lane_change_left", "lane_change_right"})


@dataclass(frozen=True)
class LaneInfo:
    """One lane of one lane section."""

    id: int
    type: str
    width: float            # m, at the section's middle
    forward: bool           # drives along +s (meaningful for driving-type lanes)
    change_left: bool       # a lane change to the left neighbour is allowed (same direction, marks permit it)
    change_right: bool

    @property
    def direction(self) -> str:
        return "forward" if self.forward else "backward"


@dataclass(frozen=True)
class SectionInfo:
    index: int
    s_start: float
    s_end: float
    lanes: tuple[LaneInfo, ...]  # left to right across the road (descending id), centre lane excluded

    @property
    def length(self) -> float:
        return self.s_end - self.s_start

    def driving(self, forward: bool) -> tuple[LaneInfo, ...]:
        """Driving lanes of one direction, ordered left to right in that direction of travel."""
        lanes = [ln for ln in self.lanes if ln.type == "driving" and ln.forward == forward]
        # Across the road the tuple runs +t to -t, i.e. left to right for forward travel.
        return tuple(lanes if forward else reversed(lanes))

    def beside(self, forward: bool, side: str) -> tuple[LaneInfo, ...]:
        """Non-driving lanes beyond the outermost driving lane of a direction, on its `side` ('left'|'right'),
        nearest first (e.g. the bike lane, then the parking lane, then the sidewalk on the right)."""
        drive = self.driving(forward)
        if not drive:
            return ()
        ordered = list(self.lanes) if forward else list(reversed(self.lanes))  # left to right in travel direction
        edge = ordered.index(drive[-1] if side == "right" else drive[0])
        rest = ordered[edge + 1:] if side == "right" else list(reversed(ordered[:edge]))
        out = []
        for lane in rest:
            if lane.type == "driving":
                break
            out.append(lane)
        return tuple(out)


@dataclass(frozen=True)
class Segment:
    """A node of the map graph: one OpenDRIVE road (junction connecting roads included, flagged)."""

    road_id: str
    name: str
    length: float
    junction_id: str                 # "-1" for a road outside junctions
    sections: tuple[SectionInfo, ...]
    layouts: frozenset[Layout]
    one_way: bool
    lanes_forward: int               # driving lanes along +s in the main (longest) section
    lanes_backward: int
    max_curvature: float             # 1/m, largest |curvature| of the reference line
    heading_change: float            # rad, signed, start to end of the reference line
    predecessor_junction: str | None
    successor_junction: str | None
    speed_limit: float | None        # m/s

    @property
    def is_connecting(self) -> bool:
        return self.junction_id != "-1"

    @property
    def main_section(self) -> SectionInfo:
        return max(self.sections, key=lambda sec: (sec.length, -sec.index))

    def lane_ids(self) -> list[int]:
        return [ln.id for ln in self.main_section.lanes]


@dataclass(frozen=True)
class ConnectionEdge:
    """A directed lane-level connection from one road to another through a junction (or a direct road link)."""

    from_road: str
    to_road: str
    from_lane: int                   # lane of `from_road` (its last/first section in the driving direction)
    to_lane: int | None              # lane of `to_road`; None if the map gives no link
    connecting_road: str | None      # None for a direct road-to-road link
    connecting_lane: int | None
    junction_id: str                 # "-1" for a direct link
    turn: Turn
    traffic_light: tuple[float, float] | None  # world x, y of the light controlling this movement
    signal_id: str | None

    @property
    def key(self) -> str:
        return f"{self.connecting_road or '-'}:{self.from_lane}:{self.connecting_lane}"


@dataclass(frozen=True)
class ApproachLane:
    lane_id: int
    index_from_left: int             # 0 = leftmost driving lane of the approach
    turns: frozenset[Turn]
    edges: tuple[ConnectionEdge, ...]
    has_left_neighbour: bool
    has_right_neighbour: bool

    @property
    def dedicated_left(self) -> bool:
        """Only left turns (and U-turns) start from this lane: a left-turn lane."""
        return bool(self.turns) and self.turns <= {Turn.LEFT, Turn.UTURN}


@dataclass(frozen=True)
class Approach:
    """An incoming road of a junction: the lanes that drive into it and where each can go."""

    junction_id: str
    road_id: str
    at_end: bool                     # the junction is at the road's end (traffic drives along +s into it)
    s_stop: float                    # road s where the approach meets the junction
    x: float                         # world position of the reference line there
    y: float
    heading: float                   # rad, direction of travel into the junction
    lanes: tuple[ApproachLane, ...]  # left to right in the direction of travel
    control: Control
    signal_ids: tuple[str, ...]      # traffic lights and stop signs controlling the approach
    exit_lanes: int                  # driving lanes of the same road leaving the junction

    @property
    def turns(self) -> frozenset[Turn]:
        out: set[Turn] = set()
        for lane in self.lanes:
            out |= lane.turns
        return frozenset(out)

    def lanes_with(self, turn: Turn | str) -> tuple[ApproachLane, ...]:
        t = Turn(turn)
        return tuple(lane for lane in self.lanes if t in lane.turns)


@dataclass(frozen=True)
class JunctionInfo:
    id: str
    name: str
    layout: Layout
    control: Control                 # strongest control over its approaches (signal > stop sign > none)
    legs: int                        # distinct directions roads leave it in
    leg_roads: tuple[str, ...]       # non-junction roads touching it
    leg_headings: tuple[tuple[str, float], ...]  # (road id, heading of travel toward the junction along it)
    approaches: tuple[str, ...]      # road ids with lanes driving into it
    connecting_roads: tuple[str, ...]
    controllers: tuple[str, ...]
    x: float                         # centre (mean of the approach points)
    y: float


@dataclass(frozen=True)
class RoadMatch:
    """A candidate for a road-layout sketch: one road in one direction of travel."""

    segment: Segment
    forward: bool                    # travel along +s
    section: int                     # lane section index the counts refer to
    lanes: tuple[int, ...]           # driving lane ids, left to right in the direction of travel
    oncoming: tuple[int, ...]        # driving lanes of the other direction, nearest first
    right_side: tuple[str, ...]      # lane types beyond the rightmost driving lane, nearest first
    left_side: tuple[str, ...]       # lane types beyond the leftmost driving lane (one-way roads), nearest first

    @property
    def road_id(self) -> str:
        return self.segment.road_id
