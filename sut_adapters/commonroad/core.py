"""One planning step of CommonRoad's reactive planner, as a plain-Python core (no rclpy): frame in, command out.

Per run: the lanelet map (cached per map), a route and reference path from the goal (commonroad-route-planner, through
the reactive planner's own `create_initial_ref_path` / `create_coordinate_system` helpers; the coordinate system gets
explicit CLCS parameters, the workaround for `set_reference_path` failing with the resolved commonroad-clcs), and a
`ReactivePlanner` in one process, no worker pool. Per replanning cycle (every `replan_steps` planner steps): the
frame's objects become obstacles with the documented prediction (`prediction.py`), the ego becomes the planner's
initial state, a red or stoppable yellow stop line ahead switches the planner to its `stopping` mode with the stop
target short of the line, and `plan()` gives a trajectory. Between cycles the command follows that trajectory.

What the planner answers is recorded per cycle in `stats`: `planned`, `no_feasible_trajectory` (plan() returned
nothing) or `planner_exception` (it raised); the last two get a braking command (`fallback_decel`), marked as such.
"""

from __future__ import annotations

import logging
import math
import time
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from txt2sce_ros.contract import ControlCommand, Frame, Goal, SignalState, TrafficLightState
from txt2sce_ros.road import RoadNetwork

from .lanelets import lanelet_map
from .prediction import obstacle
from .settings import AdapterSettings

#: Outcomes of a planning cycle, as recorded in `stats['cycles']`.
PLANNED, NO_FEASIBLE, EXCEPTION = "planned", "no_feasible_trajectory", "planner_exception"


def planner_version() -> str:
    from importlib.metadata import version

    return version("commonroad-reactive-planner")


@dataclass
class PlannedTrajectory:
    t0: float                   # sim time of the plan's first state
    t: np.ndarray               # times of the states (sim s)
    x: np.ndarray
    y: np.ndarray
    v: np.ndarray
    heading: np.ndarray         # unwrapped


@dataclass
class Stats:
    cycles: dict[str, int] = field(default_factory=lambda: {PLANNED: 0, NO_FEASIBLE: 0, EXCEPTION: 0})
    plan_times: list[float] = field(default_factory=list)
    first_exception: str = ""
    braking_steps: int = 0
    stop_line_cycles: int = 0
    routes: int = 0
    setup_s: float = 0.0

    def to_dict(self) -> dict[str, Any]:
        pt = np.asarray(self.plan_times) if self.plan_times else np.zeros(1)
        return {"cycles": dict(self.cycles), "plan_time_mean_s": float(pt.mean()), "plan_time_max_s": float(pt.max()),
                "plan_time_p95_s": float(np.percentile(pt, 95)), "first_exception": self.first_exception,
                "braking_steps": self.braking_steps, "stop_line_cycles": self.stop_line_cycles,
                "routes": self.routes, "setup_s": self.setup_s}


#: Points of a reference path closer than this (m) are one point.
MIN_SPACING = 0.1


def clean_path(ref: np.ndarray) -> np.ndarray:
    """The route planner's reference path without repeated points and without the back-and-forth folds that
    appear where lanelet centre lines are joined (consecutive lanelets share their end points): the curvilinear
    frame rejects any step turning by more than 90° ("Reference path misaligned")."""
    pts = np.asarray(ref, dtype=float)
    keep = [pts[0]]
    for p in pts[1:]:
        step = p - keep[-1]
        if math.hypot(*step) < MIN_SPACING:
            continue
        if len(keep) >= 2:
            prev = keep[-1] - keep[-2]
            if float(step @ prev) <= 0.0:               # turns back: a fold, not a road
                continue
        keep.append(p)
    return np.asarray(keep)


class CommonRoadPlanner:
    """The reactive planner behind the `ControlCommand` interface of the closed loop (one instance per run)."""

    def __init__(self, network: RoadNetwork, goal: Goal, settings: AdapterSettings | None = None, *,
                 xodr_text: str | bytes | None = None) -> None:
        self.net = network
        self.goal = goal
        self.s = settings or AdapterSettings()
        self.lmap = lanelet_map(network, xodr_text)
        self.stats = Stats()
        self.plan: PlannedTrajectory | None = None
        self.next_replan = -math.inf
        self.braking = False
        self._planner = None
        self._co = None
        self._scenario = None
        self._road_boundary = None
        self._boundary_shapes: list = []
        self._boundary_centres = np.zeros((0, 2))
        self._boundary_extents = np.zeros(0)
        self._pp = None
        self._last_t: float | None = None
        self._dt = 0.05                                  # until two frames show the player's step
        for name in ("RP_LOGGER", "commonroad_route_planner"):
            logging.getLogger(name).setLevel(logging.ERROR)

    # --- set-up (first frame) ----------------------------------------------------------------------------------

    def _setup(self, frame: Frame) -> None:
        from commonroad.scenario.scenario import Scenario
        from commonroad_dc.boundary.boundary import create_road_boundary_obstacle
        from commonroad_rp.reactive_planner import ReactivePlanner
        from commonroad_rp.utility.config import ReactivePlannerConfiguration

        ego = frame.ego
        self._scenario = Scenario(dt=self.s.planner_dt)
        self._scenario.add_objects(self.lmap.network)
        cfg = ReactivePlannerConfiguration()
        cfg.planning.dt = self.s.planner_dt
        cfg.planning.time_steps_computation = self.s.horizon_steps
        cfg.planning.planning_horizon = self.s.planner_dt * self.s.horizon_steps
        cfg.planning.replanning_frequency = self.s.replan_steps
        cfg.sampling.num_sampling_levels = self.s.sampling_levels
        cfg.debug.multiproc = False          # 2 cores shared with the player and the monitor: no worker pool
        cfg.debug.logging_level = "ERROR"
        # the ego's footprint as the player has it, so the planner's collision check is the oracle's geometry
        wheelbase = cfg.vehicle.wheelbase
        cfg.vehicle.length, cfg.vehicle.width = ego.length, ego.width
        cfg.vehicle.wb_rear_axle = ego.center_x
        cfg.vehicle.wb_front_axle = max(0.1, wheelbase - ego.center_x)
        cfg.vehicle._update_computed_params()
        self._pp = self._planning_problem(frame)
        cfg.update(scenario=self._scenario, planning_problem=self._pp)
        self._planner = ReactivePlanner(cfg)
        _, self._road_boundary = create_road_boundary_obstacle(self._scenario, method="obb_rectangles")
        shapes = self._road_boundary.unpack()
        if all(hasattr(sh, "r_x") for sh in shapes):
            self._boundary_shapes = shapes
            self._boundary_centres = np.array([sh.center() for sh in shapes], dtype=float).reshape(-1, 2)
            self._boundary_extents = np.array([math.hypot(sh.r_x(), sh.r_y()) for sh in shapes], dtype=float)
        self._route(frame)

    def _planning_problem(self, frame: Frame):
        from commonroad.common.util import Interval
        from commonroad.geometry.shape import Circle
        from commonroad.planning.goal import GoalRegion
        from commonroad.planning.planning_problem import PlanningProblem
        from commonroad.scenario.state import CustomState, InitialState

        ego = frame.ego
        cx = ego.x + ego.center_x * math.cos(ego.heading)
        cy = ego.y + ego.center_x * math.sin(ego.heading)
        init = InitialState(time_step=0, position=np.array([cx, cy]), orientation=ego.heading,
                            velocity=max(ego.speed, 0.0), yaw_rate=ego.yaw_rate, slip_angle=0.0, acceleration=0.0)
        # the goal's velocity interval is how the planner learns its desired speed when starting from standstill
        # (retrieve_desired_velocity_from_pp takes its midpoint)
        area = CustomState(time_step=Interval(0, 100000),
                           position=Circle(self.goal.tolerance, np.array([self.goal.x, self.goal.y])),
                           velocity=Interval(0.0, 2.0 * self.s.desired_speed))
        return PlanningProblem(1, init, GoalRegion([area]))

    def _route(self, frame: Frame) -> None:
        """Route and reference path from the ego's current position to the goal, and the planner's frame on it."""
        from commonroad_rp.utility.utils_coordinate_system import create_coordinate_system, create_initial_ref_path

        self._pp = self._planning_problem(frame)
        self._planner.config.planning_problem = self._pp
        ref = clean_path(create_initial_ref_path(self.lmap.network, self._pp))
        self._co = create_coordinate_system(ref)
        self._planner.set_reference_path(coordinate_system=self._co)
        self.stats.routes += 1

    # --- stepping ----------------------------------------------------------------------------------------------

    def step(self, frame: Frame) -> ControlCommand:
        """The command for `frame`: replan when due, else follow the current trajectory."""
        if self._last_t is not None and frame.t > self._last_t:
            self._dt = frame.t - self._last_t          # the player's step, learnt from the frames
        self._last_t = frame.t
        if frame.t >= self.next_replan - 1e-9:
            self._replan(frame)
            self.next_replan = frame.t + self.s.replan_steps * self.s.planner_dt
        return self._command(frame, self._dt)

    def _replan(self, frame: Frame) -> None:
        if self._planner is None:
            t_setup = time.perf_counter()
            try:
                self._setup(frame)
            except Exception as exc:                # the planner stack cannot plan this map/mission: brake
                self._record_exception(frame, exc)
                self.stats.setup_s = time.perf_counter() - t_setup
                return
            self.stats.setup_s = time.perf_counter() - t_setup
        t0 = time.perf_counter()
        try:
            result = self._plan_once(frame)
        except Exception as exc:                    # the planner's answer, recorded; never the adapter's crash
            self._record_exception(frame, exc)
            return
        finally:
            self.stats.plan_times.append(time.perf_counter() - t0)
        if result is None:
            self.stats.cycles[NO_FEASIBLE] += 1
            self.plan, self.braking = None, True
            return
        self.stats.cycles[PLANNED] += 1
        self.plan, self.braking = result, False

    def _record_exception(self, frame: Frame, exc: Exception) -> None:
        self.stats.cycles[EXCEPTION] += 1
        if not self.stats.first_exception:
            self.stats.first_exception = f"t={frame.t:.2f}: {type(exc).__name__}: {exc}"[:300]
        self.plan, self.braking = None, True

    def _boundary_near(self, frame: Frame):
        """The road boundary's rectangles that a trajectory of this cycle can reach: the planner checks every pose
        against a copy of the whole boundary (`time_slice`, linear in its rectangles), which made a cycle take
        seconds on a junction map. Nothing beyond the reach can collide, so the answer is the same."""
        import commonroad_dc.pycrcc as pycrcc

        if not self._boundary_shapes:
            return self._road_boundary
        ego = frame.ego
        horizon = self.s.planner_dt * self.s.horizon_steps
        a_max = self._planner.vehicle_params.a_max          # trajectories above it fail the kinematic check first
        reach = max(ego.speed, 0.0) * horizon + 0.5 * a_max * horizon ** 2 + ego.length + 1.0
        dist = np.hypot(self._boundary_centres[:, 0] - ego.x, self._boundary_centres[:, 1] - ego.y)
        group = pycrcc.ShapeGroup()
        for i in np.flatnonzero(dist <= reach + self._boundary_extents):
            group.add_shape(self._boundary_shapes[i])
        return group

    def _ego_state(self, frame: Frame):
        from commonroad_rp.state import ReactivePlannerState

        ego = frame.ego
        vp = self._planner.vehicle_params
        v = max(ego.speed, 0.0)
        steer = math.atan(ego.yaw_rate * vp.wheelbase / v) if v > 0.1 else 0.0
        steer = min(max(steer, vp.delta_min), vp.delta_max)
        return ReactivePlannerState(time_step=0, position=np.array([ego.x, ego.y]), velocity=v,
                                    orientation=ego.heading, acceleration=ego.accel, yaw_rate=ego.yaw_rate,
                                    steering_angle=steer)

    def _plan_once(self, frame: Frame) -> PlannedTrajectory | None:
        p = self._planner
        sc = self._scenario
        for o in list(sc.obstacles):
            sc.remove_obstacle(o)
        for i, e in enumerate(frame.objects):
            sc.add_objects(obstacle(e, 100000 + i, self.s.planner_dt, self.s.horizon_steps))
        p.set_collision_checker(scenario=sc, road_boundary_obstacle=self._boundary_near(frame))
        x0 = self._ego_state(frame)
        s_d = self._co.convert_to_curvilinear_coords(frame.ego.x, frame.ego.y)
        if abs(s_d[1]) > self.s.reroute_offset:
            self._route(frame)
        p.reset(initial_state_cart=x0, collision_checker=p.collision_checker, coordinate_system=self._co)
        stop_s = self._stop_target(frame)
        if stop_s is not None:
            self.stats.stop_line_cycles += 1
            p.config.sampling.longitudinal_mode = "stopping"
            p.set_desired_lon_position(stop_s)
        else:
            p.config.sampling.longitudinal_mode = "velocity_keeping"
            p.set_desired_velocity(self.s.desired_speed, current_speed=x0.velocity)
        out = p.plan()
        if out is None:
            return None
        states = out[0].state_list
        ts = frame.t + self.s.planner_dt * np.array([st.time_step - x0.time_step for st in states], dtype=float)
        return PlannedTrajectory(
            t0=frame.t, t=ts, x=np.array([st.position[0] for st in states]),
            y=np.array([st.position[1] for st in states]), v=np.array([st.velocity for st in states]),
            heading=np.unwrap(np.array([st.orientation for st in states])))

    def _stop_target(self, frame: Frame) -> float | None:
        """Curvilinear s (rear axle) to stop at for the nearest red, or stoppable yellow, stop line ahead on the
        reference path; None when none governs the ego."""
        ego = frame.ego
        s_ego, _ = self._co.convert_to_curvilinear_coords(ego.x, ego.y)
        front = ego.center_x + 0.5 * ego.length          # rear axle -> front bumper
        best = None
        for light in frame.lights:
            if light.state not in (SignalState.RED, SignalState.YELLOW):
                continue
            s_line = self._governing_line(light, s_ego)
            if s_line is None:
                continue
            gap = s_line - (s_ego + front)
            if gap < 0.0:
                continue                                 # already at or past the line
            if light.state is SignalState.YELLOW and ego.speed ** 2 > 2 * self.s.yellow_comfort_decel * gap:
                continue                                 # cannot stop comfortably: clear the yellow
            target = s_line - front - self.s.stop_margin
            best = target if best is None else min(best, target)
        return best

    def _governing_line(self, light: TrafficLightState, s_ego: float) -> float | None:
        try:
            s_line, d_line = self._co.convert_to_curvilinear_coords(light.stop_x, light.stop_y)
        except Exception:                               # the line is off this reference path
            return None
        if abs(d_line) > self.s.signal_lateral_window or s_line < s_ego:
            return None
        # the signal must face the direction of travel along the path at the line
        i = int(np.clip(np.searchsorted(self._co.ref_pos, s_line), 0, len(self._co.ref_theta) - 1))
        diff = math.remainder(light.heading - float(self._co.ref_theta[i]), math.tau)
        return s_line if abs(diff) < math.pi / 3 else None

    def _command(self, frame: Frame, dt: float) -> ControlCommand:
        ego = frame.ego
        if self.braking or self.plan is None:
            self.stats.braking_steps += 1
            return ControlCommand(frame.t, max(0.0, ego.speed - self.s.fallback_decel * dt), 0.0)
        tr = self.plan
        t_next = frame.t + dt
        v_next = float(np.interp(t_next, tr.t, tr.v))
        # heading the trajectory has at the next step, reached from the ego's actual heading (feed-forward plus
        # correction: on the trajectory this is exactly its yaw rate)
        h_next = float(np.interp(t_next, tr.t, tr.heading))
        yaw_rate = math.remainder(h_next - ego.heading, math.tau) / dt
        return ControlCommand(frame.t, max(0.0, v_next), yaw_rate)
