"""Obstacles for the planner, from one frame of the player's ground truth, with the adapter's documented
prediction: every moving object keeps its speed and yaw rate (constant turn rate and velocity) over the planning
horizon; objects marked static (obstacles, parked vehicles) and objects standing still are static obstacles.
The ground truth is what the topics carry; the prediction is the adapter's (a real stack's perception and
prediction would sit here) and so part of what is tested.
"""

from __future__ import annotations

import math

import numpy as np
from commonroad.geometry.shape import Rectangle
from commonroad.prediction.prediction import TrajectoryPrediction
from commonroad.scenario.obstacle import DynamicObstacle, ObstacleType, StaticObstacle
from commonroad.scenario.state import CustomState, InitialState
from commonroad.scenario.trajectory import Trajectory

from txt2sce_ros.contract import EntityState

#: Marker categories (docs/ads_interface.md) -> CommonRoad obstacle types.
TYPES = {
    "car": ObstacleType.CAR, "van": ObstacleType.CAR, "truck": ObstacleType.TRUCK, "bus": ObstacleType.BUS,
    "motorbike": ObstacleType.MOTORCYCLE, "motorcycle": ObstacleType.MOTORCYCLE, "bicycle": ObstacleType.BICYCLE,
    "scooter": ObstacleType.BICYCLE, "pedestrian": ObstacleType.PEDESTRIAN,
    "parked_vehicle": ObstacleType.PARKED_VEHICLE, "cone": ObstacleType.CONSTRUCTION_ZONE,
}
#: Below this speed (m/s) an object counts as standing (its constant-velocity prediction is a standstill anyway).
STANDING = 0.05


def _centre(e: EntityState) -> tuple[float, float]:
    """Bounding-box centre (CommonRoad shapes are centred; our poses are reference points)."""
    return e.x + e.center_x * math.cos(e.heading), e.y + e.center_x * math.sin(e.heading)


def ctrv_path(e: EntityState, dt: float, steps: int) -> np.ndarray:
    """(steps, 3) reference-point x, y, heading at dt, 2dt, …: constant speed and yaw rate."""
    t = dt * np.arange(1, steps + 1)
    h = e.heading + e.yaw_rate * t
    if abs(e.yaw_rate) < 1e-4:
        x = e.x + e.speed * t * math.cos(e.heading)
        y = e.y + e.speed * t * math.sin(e.heading)
    else:
        r = e.speed / e.yaw_rate
        x = e.x + r * (np.sin(h) - math.sin(e.heading))
        y = e.y - r * (np.cos(h) - math.cos(e.heading))
    return np.column_stack([x, y, h])


def obstacle(e: EntityState, obstacle_id: int, dt: float, steps: int) -> StaticObstacle | DynamicObstacle:
    """One CommonRoad obstacle for entity `e` at time step 0 (the frame being answered)."""
    shape = Rectangle(length=max(e.length, 0.1), width=max(e.width, 0.1))
    kind = TYPES.get(e.category, ObstacleType.UNKNOWN)
    cx, cy = _centre(e)
    init = InitialState(time_step=0, position=np.array([cx, cy]), orientation=e.heading, velocity=e.speed,
                        acceleration=0.0, yaw_rate=e.yaw_rate, slip_angle=0.0)
    if e.is_static or abs(e.speed) < STANDING:
        return StaticObstacle(obstacle_id, kind, shape, init)
    states = [CustomState(time_step=k, position=np.array([x + e.center_x * math.cos(h), y + e.center_x * math.sin(h)]),
                          orientation=float(h), velocity=e.speed)
              for k, (x, y, h) in enumerate(ctrv_path(e, dt, steps), start=1)]
    pred = TrajectoryPrediction(Trajectory(1, states), shape)
    return DynamicObstacle(obstacle_id, kind, shape, init, pred)
