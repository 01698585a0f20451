"""The closed loop's contract: topic names and the typed records that flow between player, planner and oracle.

Plain Python (no rclpy): the in-process campaign path passes these records directly; the ROS nodes convert them
to and from standard messages in `txt2sce_ros.ros_io`. Units are SI; angles in radians; positions in the map
frame of the scenario's OpenDRIVE file (x east, y north, heading counter-clockwise from +x).

Lock-step protocol (documented in the README topic table):
1. The player publishes, for step k at sim time t_k: `/clock`, `/sim/traffic_lights`, one `/sim/objects/odom` per
   entity, `/sim/objects/markers` (the manifest of step k: one marker per entity present), then `/sim/ego/odom`.
2. The planner, once it holds the ego odometry, the markers and every listed entity's odometry stamped t_k,
   answers with `/control/command` stamped t_k.
3. The player applies the command and steps to k+1. No answer within the wall-clock limit ends the run as an
   *error* ("planner not responding"), never as a failure of the stack.
"""

from __future__ import annotations

import enum
import functools
import json
from dataclasses import dataclass, field, fields
from typing import Any

from .quick_init import quick_init

# --- topics --------------------------------------------------------------------------------------------------------

TOPIC_SCENARIO = "/txt2sce/scenario"          # std_msgs/String, JSON ScenarioEnvelope; generator -> player
TOPIC_RUN_STATUS = "/txt2sce/run_status"      # std_msgs/String, JSON RunStatus; player -> oracle, generator
TOPIC_CLOCK = "/clock"                        # rosgraph_msgs/Clock; player
TOPIC_EGO_ODOM = "/sim/ego/odom"              # nav_msgs/Odometry, frame map, child ego
TOPIC_OBJECTS_ODOM = "/sim/objects/odom"      # nav_msgs/Odometry, one per entity per step, child = entity name
TOPIC_OBJECTS_MARKERS = "/sim/objects/markers"  # visualization_msgs/MarkerArray, footprints + categories
TOPIC_TRAFFIC_LIGHTS = "/sim/traffic_lights"  # diagnostic_msgs/DiagnosticArray, one status per signal
TOPIC_GOAL = "/planning/goal"                 # geometry_msgs/PoseStamped
TOPIC_COMMAND = "/control/command"            # geometry_msgs/TwistStamped (linear.x speed, angular.z yaw rate)
TOPIC_VIOLATIONS = "/oracle/violations"       # diagnostic_msgs/DiagnosticArray
TOPIC_MAP_MARKERS = "/sim/map/markers"        # visualization_msgs/MarkerArray, the road; latched, once per scenario
TOPIC_SCENARIO_MARKERS = "/sim/scenario/markers"  # visualization_msgs/MarkerArray, goal + light states; latched

MAP_FRAME = "map"
EGO_NAME = "ego"

#: Topics an oracle needs to judge a run; a bag with these can be re-judged offline.
CONTRACT_TOPICS = (
    TOPIC_SCENARIO, TOPIC_RUN_STATUS, TOPIC_CLOCK, TOPIC_EGO_ODOM, TOPIC_OBJECTS_ODOM, TOPIC_OBJECTS_MARKERS,
    TOPIC_TRAFFIC_LIGHTS, TOPIC_GOAL, TOPIC_COMMAND,
)

#: Topics for people watching (Foxglove, RViz): recorded and replayed, never needed to judge a run.
VIEW_TOPICS = (TOPIC_MAP_MARKERS, TOPIC_SCENARIO_MARKERS)

#: Categories of traffic participants (sketch vocabulary) and of static objects.
PARTY_CATEGORIES = ("car", "van", "truck", "bus", "motorcycle", "bicycle", "scooter", "pedestrian")
OBSTACLE_CATEGORIES = ("parked_vehicle", "door", "debris", "cone", "barrier", "pole", "animal", "other")


class Verdict(str, enum.Enum):
    """Outcome of one closed-loop run. Never mixed: an error is not a failure."""

    PASS = "pass"
    FAIL = "fail"
    ERROR = "error"


class SignalState(str, enum.Enum):
    RED = "red"
    YELLOW = "yellow"
    GREEN = "green"
    OFF = "off"


@quick_init
@dataclass(frozen=True, slots=True)
class EntityState:
    """One entity at one instant. (x, y) is the reference point (rear axle centre for vehicles, as OpenSCENARIO);
    the footprint is the bounding box of `length` × `width` centred `center_x` metres ahead of it."""

    name: str
    category: str
    t: float
    x: float
    y: float
    heading: float
    speed: float                 # signed along heading, m/s
    accel: float = 0.0           # longitudinal, m/s²
    yaw_rate: float = 0.0        # rad/s
    length: float = 4.5
    width: float = 1.8
    height: float = 1.5
    center_x: float = 1.4        # bounding-box centre ahead of the reference point, m
    is_static: bool = False      # MiscObject / obstacle


@quick_init
@dataclass(frozen=True, slots=True)
class TrafficLightState:
    """A signal head as the planner sees it: its state and the stop line it governs."""

    id: str
    state: SignalState
    stop_x: float
    stop_y: float
    heading: float               # travel direction of the lane(s) it controls
    road_id: str = ""
    lane_ids: tuple[int, ...] = ()


@quick_init
@dataclass(frozen=True, slots=True)
class ControlCommand:
    """The planner's answer for step `t`: speed to reach by the next step and yaw rate. With lock-step at dt, a
    planner that wants acceleration a sends speed = v + a·dt; the player applies it within the vehicle's limits."""

    t: float
    speed: float
    yaw_rate: float


@dataclass(frozen=True, slots=True)
class Goal:
    """The ego's mission: reach (x, y) within `tolerance` metres."""

    x: float
    y: float
    heading: float
    tolerance: float = 3.0


@quick_init
@dataclass(frozen=True, slots=True)
class Frame:
    """Everything observable at one step: what the planner perceives and the oracle judges."""

    t: float
    ego: EntityState
    objects: tuple[EntityState, ...] = ()
    lights: tuple[TrafficLightState, ...] = ()


@functools.lru_cache(maxsize=32)
def _json_text(text: str) -> str:
    """A string as JSON. An envelope's scenario and map texts are tens of KB, escaped character by character
    (~0.2 ms an envelope, a twentieth of recording a short run); a campaign sends the same map with every
    scenario and a recorder writes each envelope again, so the escaped forms are kept (a repeat costs a hash and
    one comparison)."""
    return json.dumps(text)


@dataclass(frozen=True, slots=True)
class ScenarioEnvelope:
    """What the generator publishes on `/txt2sce/scenario`: one scenario file and where it sits in its tree."""

    id: str
    xosc: str                              # the OpenSCENARIO XML text
    map_path: str = ""                     # path of the OpenDRIVE file on the generator's machine
    map_xodr: str = ""                     # the OpenDRIVE text, so a remote player needs no shared disk
    parent: str | None = None
    tree: str | None = None
    meta: dict[str, Any] = field(default_factory=dict)

    def to_json(self) -> str:
        """`json.dumps(asdict(self), sort_keys=True)`, with the texts' escaped forms kept (`_json_text`)."""
        return "{" + ", ".join(f'"{f}": ' + (_json_text(v) if isinstance(v, str) else json.dumps(v, sort_keys=True))
                               for f, v in sorted((f.name, getattr(self, f.name)) for f in fields(self))) + "}"

    @classmethod
    def from_json(cls, text: str) -> "ScenarioEnvelope":
        from .errors import InputError

        try:
            data = json.loads(text)
            return cls(**data)
        except (ValueError, TypeError) as exc:
            raise InputError(f"not a scenario envelope: {exc}", source=TOPIC_SCENARIO) from exc


@dataclass(frozen=True, slots=True)
class RunStatus:
    """Player's run life cycle on `/txt2sce/run_status`: state is 'started' or 'finished'."""

    scenario_id: str
    state: str
    t: float = 0.0
    end_reason: str = ""          # e.g. 'goal_reached', 'stop_trigger', 'time_limit', 'planner_not_responding'
    verdict_hint: str = ""        # 'error' when the run itself broke; the oracle decides pass/fail
    unsupported: tuple[str, ...] = ()

    def to_json(self) -> str:
        # Field by field rather than `asdict` (a deep copy; a status is written twice per recorded run).
        return json.dumps({"scenario_id": self.scenario_id, "state": self.state, "t": self.t,
                           "end_reason": self.end_reason, "verdict_hint": self.verdict_hint,
                           "unsupported": list(self.unsupported)}, sort_keys=True)

    @classmethod
    def from_json(cls, text: str) -> "RunStatus":
        data = json.loads(text)
        data["unsupported"] = tuple(data.get("unsupported", ()))
        return cls(**data)
