"""An entity's static description (what a ScenarioObject says: kind, category, bounding box, performance, axles,
controller), as the world needs it. `syntax/entities.py` reads it from the XML."""

from __future__ import annotations

from dataclasses import dataclass, field

from txt2sce_ros.contract import OBSTACLE_CATEGORIES


@dataclass(frozen=True, slots=True)
class EntitySpec:
    """A scenario object's static description. Lengths in m, speeds m/s, accelerations m/s², angles rad."""

    name: str
    kind: str                     # 'vehicle' | 'pedestrian' | 'misc'
    category: str                 # contract category ('car', 'bicycle', 'pedestrian', 'parked_vehicle', ...)
    length: float
    width: float
    height: float
    center_x: float               # bounding-box centre ahead of the reference point
    center_y: float
    max_speed: float
    max_accel: float
    max_decel: float
    wheelbase: float
    max_steering: float
    external: bool = False        # the ego's controller is the planner under test (seed_format.md)
    properties: dict[str, str] = field(default_factory=dict)
    line: int | None = None

    @property
    def is_static(self) -> bool:
        # A parked vehicle written as a Vehicle is still an obstacle: same rule as ros_io, so in-process and ROS
        # frames agree.
        return self.kind == "misc" or self.category in OBSTACLE_CATEGORIES
