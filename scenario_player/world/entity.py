"""Runtime state of one scenario object. Mutable on purpose (the world steps it in place); everything the outside
sees is copied into frozen `EntityState` records."""

from __future__ import annotations

import math
from dataclasses import fields
from typing import TYPE_CHECKING

from txt2sce_ros.contract import EntityState

from .lanes import LaneTrack
from .spec import EntitySpec

if TYPE_CHECKING:
    from .protocols import Run


class Entity:
    __slots__ = ("spec", "name", "x", "y", "h", "speed", "accel", "yaw_rate", "track", "s", "offset",
                 "runs", "route_lanes", "odometer", "standstill_time", "end_of_road_time", "offroad_time",
                 "colliding", "planner", "present", "lane_locked", "_prev_speed", "_prev_h", "_road",
                 "road_stale", "locator", "heading_override", "corner_cache", "reverse", "placed", "_static", "radius", "reach", "still")

    def __init__(self, spec: EntitySpec) -> None:
        self.spec = spec
        self.name = spec.name
        self._static = spec.is_static             # a property of the (immutable) spec; read for every frame
        self.radius = 0.5 * math.hypot(spec.length, spec.width)   # of the footprint's enclosing circle (contacts)
        # How far from the reference point the footprint can reach, with 0.5 m to spare (the contact scan's
        # first, trigonometry-free test)
        self.reach = self.radius + math.hypot(spec.center_x, spec.center_y) + 0.5
        self.x = self.y = self.h = 0.0
        self.speed = self.accel = self.yaw_rate = 0.0
        self.track: LaneTrack | None = None       # lane the entity follows (None: free motion)
        self.s = 0.0                              # road s on `track`
        self.offset = 0.0                         # from the lane centre toward +t
        self.runs: dict[str, "Run"] = {}    # control domain -> run holding it
        self.route_lanes: set = set()             # LaneRefs of an assigned route (junction choices)
        self.odometer = 0.0
        self.standstill_time = 0.0
        self.end_of_road_time: float | None = None
        self.offroad_time: float | None = None
        self.colliding: set[str] = set()
        self.planner = False                      # driven by the planner under test
        self.present = False                      # placed by a teleport (or the planner's start)
        self.lane_locked = True                   # motion follows the lane (False: free kinematics)
        self._prev_speed = 0.0
        self._prev_h = 0.0
        # Road coordinates (road id, lane id, s, t). Lane-following entities keep them exact as they move;
        # free-moving ones are located lazily, only when a condition or action asks (locating costs ~0.1 ms).
        self._road: tuple[str | None, int | None, float, float] = (None, None, 0.0, 0.0)
        self.road_stale = False
        self.locator = None                       # callable(x, y, h) -> LanePoint | None, set by the World
        self.heading_override: float | None = None
        self.corner_cache = None
        self.placed = False                       # teleported during this step's triggers/actions
        self.reverse = False                      # moves against its lane's driving direction (heading says so)
        # The last standing step on a lane, for `motion.move_storyboard` to repeat while its inputs stay the same
        # objects: (track, s, offset, heading override, reverse, ok, x, y, h, road); None: none to repeat.
        self.still: tuple | None = None

    # -- placement ------------------------------------------------------------------------------------------------
    def place_on_lane(self, track: LaneTrack, s: float, offset: float, heading: float | None = None) -> None:
        self.track, self.s, self.offset = track, s, offset
        self.lane_locked = True
        x, y, h = track.pose(s, offset)
        self.x, self.y = x, y
        self.h = h if heading is None else heading
        # An entity placed facing against its lane drives against it (esmini: motion follows the heading).
        self.reverse = heading is not None and abs(_wrap(heading - h)) > math.pi / 2
        lane_h = h + math.pi if self.reverse else h
        self.heading_override = None if heading is None or abs(_wrap(heading - lane_h)) < 1e-9 else heading
        self.present = True
        self._sync_road()

    def place_free(self, x: float, y: float, h: float) -> None:
        self.track = None
        self.x, self.y, self.h = x, y, h
        self.lane_locked = False
        self.present = True

    def _sync_road(self) -> None:
        tr = self.track
        if tr is not None:
            self._road = (tr.ref.road_id, tr.ref.lane_id, self.s, tr.center_t(self.s) + self.offset)
            self.road_stale = False

    def _fresh(self) -> tuple[str | None, int | None, float, float]:
        if self.road_stale:
            self.road_stale = False
            lp = self.locator(self.x, self.y, self.h) if self.locator is not None else None
            if lp is not None:
                self._road = (lp.road_id, lp.lane_id, lp.s, lp.t)
                return self._road
            self._road = (None, None, 0.0, 0.0)
        return self._road

    def road(self) -> tuple[str | None, int | None, float, float]:
        """(road id, lane id, road s, road t), located first when stale: the four properties below in one call."""
        return self._road if not self.road_stale else self._fresh()

    def set_road(self, road_id: str | None, lane_id: int | None, s: float, t: float) -> None:
        self._road = (road_id, lane_id, s, t)
        self.road_stale = False

    @property
    def road_id(self) -> str | None:
        return self._fresh()[0]

    @property
    def lane_id(self) -> int | None:
        return self._fresh()[1]

    @property
    def road_s(self) -> float:
        return self._fresh()[2]

    @property
    def road_t(self) -> float:
        return self._fresh()[3]

    def state(self, t: float) -> EntityState:
        sp = self.spec
        # Positional, in EntityState's field order: built for every entity every step, and keywords cost more.
        return EntityState(self.name, sp.category, t, self.x, self.y, (self.h + _PI) % _TWO_PI - _PI,
                           self.speed, self.accel, self.yaw_rate, sp.length, sp.width, sp.height, sp.center_x,
                           self._static)


_PI = math.pi
_TWO_PI = 2.0 * math.pi

# `Entity.state` passes EntityState's fields positionally: fail at import, not silently, if the contract reorders.
if tuple(f.name for f in fields(EntityState)) != (
        "name", "category", "t", "x", "y", "heading", "speed", "accel", "yaw_rate", "length", "width", "height",
        "center_x", "is_static"):
    raise ImportError("txt2sce_ros.contract.EntityState fields changed: update scenario_player Entity.state")


def _wrap(a: float) -> float:
    return (a + _PI) % _TWO_PI - _PI
