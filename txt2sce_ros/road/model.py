"""Typed records of an OpenDRIVE network: roads, links, junctions, signals, controllers."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import NamedTuple

from .geometry import PlanView
from .lanes import Cubic, LaneSection


class LaneRef(NamedTuple):
    """A lane of one lane section: the node type of the routing graph."""

    road_id: str
    section: int
    lane_id: int


@dataclass(frozen=True, slots=True)
class RoadLink:
    """A road's predecessor or successor: another road (with contact point) or a junction."""

    element_type: str          # 'road' | 'junction'
    element_id: str
    contact_point: str = ""    # 'start' | 'end' (roads only)


@dataclass(frozen=True, slots=True)
class SignalValidity:
    from_lane: int
    to_lane: int


@dataclass(frozen=True, slots=True)
class Signal:
    """A `<signal>` (or `<signalReference>` resolved to its road): placed with road s/t, plus its world pose."""

    id: str
    road_id: str
    s: float
    t: float
    orientation: str           # '+' (valid for traffic along +s), '-' (along -s), 'none' (both)
    dynamic: bool
    type: str
    subtype: str = ""
    name: str = ""
    country: str = ""
    value: float | None = None
    h_offset: float = 0.0
    x: float = 0.0
    y: float = 0.0
    heading: float = 0.0       # direction the signal faces travel: the heading of the traffic it controls
    validity: tuple[SignalValidity, ...] = ()
    controlled_lanes: tuple[int, ...] = ()   # lane ids of `road_id` the signal applies to
    is_reference: bool = False

    @property
    def is_traffic_light(self) -> bool:
        # Type codes are country-specific (in esmini's maps 1000001 is a vehicle light but 1000003 a crosswalk
        # marking), so the one portable mark of a light is a signal whose state changes: dynamic="yes".
        return self.dynamic


@dataclass(frozen=True, slots=True)
class Controller:
    id: str
    name: str = ""
    sequence: int | None = None
    signal_ids: tuple[str, ...] = ()


@dataclass(frozen=True, slots=True)
class JunctionLaneLink:
    from_lane: int
    to_lane: int


@dataclass(frozen=True, slots=True)
class Connection:
    id: str
    incoming_road: str
    connecting_road: str
    contact_point: str            # where the connecting road is entered: 'start' | 'end'
    lane_links: tuple[tuple[int, int], ...] = ()

    def __iter__(self):  # noqa: ANN204 - lets `incoming, connecting, contact, links = conn` work as in road_api.md
        return iter((self.incoming_road, self.connecting_road, self.contact_point, self.lane_links))


@dataclass(frozen=True, slots=True)
class Junction:
    id: str
    name: str = ""
    type: str = "default"
    connections: tuple[Connection, ...] = ()
    controllers: tuple[str, ...] = ()


@dataclass(frozen=True, slots=True)
class Road:
    """One `<road>`. Frozen; only its `signals` list is filled in place once, when the network places them."""

    id: str
    name: str
    length: float
    junction: str                 # "-1" if not part of a junction
    plan_view: PlanView
    sections: list[LaneSection]
    lane_offsets: tuple[Cubic, ...] = ()
    predecessor: RoadLink | None = None
    successor: RoadLink | None = None
    rule: str = "RHT"             # 'RHT' | 'LHT'
    signals: list[Signal] = field(default_factory=list)
    speed_limit: float | None = None   # m/s, from <type><speed>, first one
    road_type: str = ""

    @property
    def links(self) -> dict[str, RoadLink | None]:
        return {"predecessor": self.predecessor, "successor": self.successor}

    @property
    def in_junction(self) -> bool:
        return self.junction not in ("-1", "")

    def section_index(self, s: float) -> int:
        """Index of the lane section holding s (the last one starting at or before s)."""
        idx = 0
        for i, sec in enumerate(self.sections):
            if sec.s <= s + 1e-9:
                idx = i
            else:
                break
        return idx
