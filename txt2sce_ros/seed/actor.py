"""An entity while it is being planned: its path, start, profiles and events (frozen into an EntityPlan), and the
predicted closest approach between two of them."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .kinematics import LateralStep, SpeedStep, box_corners, boxes_gap, lateral_profile, speed_profile
from .linetrack import LineTrack
from .model import EntityPlan, EventPlan, LanePose, RouteAct, WorldPose
from .track import Track


def center_x(kind: str, length: float) -> float:
    return round(0.311 * length, 2) if kind == "vehicle" else 0.0


@dataclass
class Actor:
    """One moving or standing entity while it is being planned (mutable builder, frozen into an EntityPlan)."""

    name: str
    kind: str
    category: str
    xosc_category: str
    dims: tuple[float, float, float]
    track: Track | LineTrack
    d0: float = 0.0
    lat0: float = 0.0
    v0: float = 0.0
    speed_steps: list[SpeedStep] = field(default_factory=list)
    lat_steps: list[LateralStep] = field(default_factory=list)
    events: list[EventPlan] = field(default_factory=list)
    route: RouteAct | None = None
    external: bool = False
    world_start: bool = False         # start written as WorldPosition (off-lane paths, wrong-way driving)
    notes: list[str] = field(default_factory=list)

    @property
    def length(self) -> float:
        return self.dims[1]

    @property
    def width(self) -> float:
        return self.dims[0]

    @property
    def cx(self) -> float:
        return center_x(self.kind, self.length)

    def profile(self, horizon: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        return speed_profile(self.v0, self.speed_steps, horizon)

    def states(self, horizon: float) -> tuple[np.ndarray, np.ndarray]:
        """(t, poses (N,3)) of the planned motion."""
        t, _, d = self.profile(horizon)
        lat = lateral_profile(self.lat0, self.lat_steps, t)
        return t, self.track.world_array(self.d0 + d, lat)

    def start_pose(self) -> LanePose | WorldPose:
        if self.world_start or isinstance(self.track, LineTrack):
            return self.track.world(self.d0, self.lat0)
        return self.track.lane_pose(self.d0, self.lat0)

    def freeze(self) -> EntityPlan:
        return EntityPlan(self.name, self.kind, self.category, self.xosc_category, self.dims, self.start_pose(),
                          round(self.v0, 3), tuple(self.events), self.route, self.external)


def predicted_gap(actors: list[Actor], target: str, horizon: float) -> tuple[float, float]:
    """(smallest box gap in m between the ego and `target` over the planned motion, time of it)."""
    ego = next(a for a in actors if a.name == "ego")
    other = next(a for a in actors if a.name == target)
    t, pe = ego.states(horizon)
    _, po = other.states(horizon)
    best, when = math.inf, 0.0
    # A step whose gap cannot beat the best so far is skipped without the (numpy, slow) box test: the separating
    # gap along the normal of one box closest to the line of centres is at least |d|/sqrt(2) minus that box's
    # larger half side minus the other's circumradius (1e-6 m of slack for rounding). Same result, same time.
    reach = min(0.5 * max(ego.length, ego.width) + 0.5 * math.hypot(other.length, other.width),
                0.5 * max(other.length, other.width) + 0.5 * math.hypot(ego.length, ego.width)) + 1e-6
    ego_cx, other_cx = ego.cx, other.cx
    for k in range(0, len(t), 2):
        if best < math.inf:
            ex, ey, eh = pe[k, 0], pe[k, 1], pe[k, 2]
            ox, oy, oh = po[k, 0], po[k, 1], po[k, 2]
            dx = ex + ego_cx * math.cos(eh) - ox - other_cx * math.cos(oh)
            dy = ey + ego_cx * math.sin(eh) - oy - other_cx * math.sin(oh)
            if math.hypot(dx, dy) / math.sqrt(2.0) - reach >= best:
                continue
        a = box_corners(pe[k, 0], pe[k, 1], pe[k, 2], ego.length, ego.width, ego.cx)
        b = box_corners(po[k, 0], po[k, 1], po[k, 2], other.length, other.width, other.cx)
        g = boxes_gap(a, b)
        if g < best:
            best, when = g, float(t[k])
        if g <= 0:
            break
    return best, when
