"""Shared set-up for the planner tests: real esmini maps from the shared data, frames placed on their lanes."""

from __future__ import annotations

import math
from pathlib import Path

from txt2sce_ros.contract import EntityState, Frame, Goal, SignalState, TrafficLightState
from txt2sce_ros.paths import shared_dir
from txt2sce_ros.road import RoadNetwork, load_network

ESMINI_XODR = shared_dir() / "data" / "conformance" / "esmini" / "xodr"
FABRIKSGATAN = ESMINI_XODR / "fabriksgatan.xodr"     # a 4-way junction with 300 m and 100 m approaches
STRAIGHT = ESMINI_XODR / "straight_500m.xodr"


def net(path: Path = FABRIKSGATAN) -> RoadNetwork:
    return load_network(path)


def on_lane(network: RoadNetwork, name: str, road: str, lane: int, s: float, *, speed: float = 0.0,
            category: str = "car", t: float = 0.0, offset: float = 0.0, static: bool = False,
            heading_delta: float = 0.0, length: float = 4.5, width: float = 1.8, yaw_rate: float = 0.0
            ) -> EntityState:
    """An entity on a lane, facing its driving direction (+ heading_delta)."""
    x, y, h = network.lane_to_world(road, lane, s, offset)
    return EntityState(name=name, category=category, t=t, x=x, y=y, heading=h + heading_delta, speed=speed,
                       length=length, width=width, is_static=static, yaw_rate=yaw_rate,
                       center_x=1.4 if category not in ("pedestrian", "bicycle", "cone") else 0.0)


def goal_on_lane(network: RoadNetwork, road: str, lane: int, s: float) -> Goal:
    x, y, h = network.lane_to_world(road, lane, s)
    return Goal(x=x, y=y, heading=h)


def light_on_lane(network: RoadNetwork, road: str, lane: int, s: float, state: SignalState,
                  ident: str = "sig1") -> TrafficLightState:
    x, y, h = network.lane_to_world(road, lane, s)
    return TrafficLightState(id=ident, state=state, stop_x=x, stop_y=y, heading=h, road_id=road, lane_ids=(lane,))


def frame(t: float, ego: EntityState, *objects: EntityState, lights: tuple[TrafficLightState, ...] = ()) -> Frame:
    return Frame(t=t, ego=ego, objects=tuple(objects), lights=lights)


def heading_error(a: float, b: float) -> float:
    return abs(math.remainder(a - b, 2.0 * math.pi))
