"""Typed records of a planned seed: what the writer turns into OpenSCENARIO and the manifest records.

A `ScenarioPlan` is map-resolved and fully timed: every position is a lane position (road, lane, s, offset) or a
world point on the seed's OpenDRIVE map, every trigger a concrete condition. Nothing here touches XML.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Union


@dataclass(frozen=True, slots=True)
class LanePose:
    """`LanePosition`: lane centre + offset (OpenSCENARIO: positive toward +t of the road). x/y/h are the world pose
    (kept for the manifest, timing and the fidelity check; not written)."""

    road_id: str
    lane_id: int
    s: float
    offset: float = 0.0
    x: float = 0.0
    y: float = 0.0
    h: float = 0.0


@dataclass(frozen=True, slots=True)
class WorldPose:
    x: float
    y: float
    h: float


Pose = Union[LanePose, WorldPose]


@dataclass(frozen=True, slots=True)
class SpeedAct:
    target: float                  # m/s; negative = reverse (sketch action k)
    shape: str = "linear"
    dimension: str = "time"
    value: float = 1.0


@dataclass(frozen=True, slots=True)
class LaneChangeAct:
    relative: int                  # +1 = one lane to the left (OpenSCENARIO RelativeTargetLane sign), -1 right
    duration: float = 3.0
    reference: str = ""            # entityRef of RelativeTargetLane (the acting entity)


@dataclass(frozen=True, slots=True)
class LaneOffsetAct:
    offset: float                  # m, AbsoluteTargetLaneOffset (positive = left)
    max_lateral_acc: float = 0.5


@dataclass(frozen=True, slots=True)
class RouteAct:
    name: str
    waypoints: tuple[Pose, ...]
    strategy: str = "shortest"


@dataclass(frozen=True, slots=True)
class TrajectoryAct:
    name: str
    vertices: tuple[WorldPose, ...]   # followed at the entity's speed (TimeReference None)


Act = Union[SpeedAct, LaneChangeAct, LaneOffsetAct, RouteAct, TrajectoryAct]


@dataclass(frozen=True, slots=True)
class Trigger:
    """One start condition. kind: 'time' (SimulationTime ≥ value), 'distance' (RelativeDistance of `entity` to
    `ref` < value, cartesian), 'ttc' (TimeToCollision of `entity` to `ref` < value), 'event_end' (the event `ref`
    ends; value = delay)."""

    kind: str
    value: float
    entity: str = ""
    ref: str = ""


@dataclass(frozen=True, slots=True)
class EventPlan:
    name: str                      # <entity>_e<k>_<action name>
    code: str                      # sketch action code
    actions: tuple[Act, ...]
    trigger: Trigger
    planned_time: float            # s, when the plan expects it to start (manifest; fidelity diagnostics)
    #: (x, y, radius): the event starts only while its entity is within `radius` m of (x, y) (a lane change: the
    #: stretch of road with a lane beside it), whatever else its trigger says
    within: tuple[float, float, float] | None = None


@dataclass(frozen=True, slots=True)
class EntityPlan:
    name: str                      # ego, npc1, obs1
    kind: str                      # 'vehicle' | 'pedestrian' | 'misc'
    category: str                  # sketch category (or 'ego')
    xosc_category: str             # vehicleCategory / pedestrianCategory / miscObjectCategory
    dimensions: tuple[float, float, float]   # width, length, height
    start: Pose
    speed: float                   # initial speed, m/s
    events: tuple[EventPlan, ...] = ()
    route: RouteAct | None = None  # assigned at Init (the ego's mission)
    external: bool = False         # driven by the system under test in closed loop
    position: str | None = None    # the sketch's relative position R1-R7 (parties, obstacles), None for the ego
    lane: str | None = None        # the sketch's lane relative to the ego, for R5-R7 only


@dataclass(frozen=True, slots=True)
class SignalPhase:
    name: str
    duration: float
    states: tuple[tuple[str, str], ...]   # (OpenDRIVE signal id, state) pairs


@dataclass(frozen=True, slots=True)
class SignalPlan:
    name: str                      # signal_ctrl_<junction id>
    phases: tuple[SignalPhase, ...]


@dataclass(frozen=True, slots=True)
class EnvironmentPlan:
    date_time: str
    cloud_state: str
    sun_intensity: float
    sun_elevation: float
    sun_azimuth: float
    precipitation: str
    precipitation_intensity: float
    visual_range: float
    friction: float


@dataclass(frozen=True, slots=True)
class ScenarioPlan:
    report_id: str
    map_ref: str                   # LogicFile filepath as written (relative to the seed file)
    entities: tuple[EntityPlan, ...]
    environment: EnvironmentPlan
    goal: LanePose
    goal_tolerance: float
    time_limit: float
    signals: tuple[SignalPlan, ...] = ()
    choices: dict = field(default_factory=dict, hash=False, compare=False)   # manifest: every choice made

    def entity(self, name: str) -> EntityPlan:
        for e in self.entities:
            if e.name == name:
                return e
        raise KeyError(name)
