"""The stand-in planner: route + perception + behaviour rules + IDM / stop control + pure pursuit + comfort
limits, composed (no inheritance), one `step(frame) -> ControlCommand` per lock-step frame.

Command encoding (contract.ControlCommand): speed to reach by the next step, v + a·dt, and a yaw rate; the stamp is
the frame's time. The step is a deterministic function of the frames seen so far.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from txt2sce_ros.contract import ControlCommand, EntityState, Frame, Goal
from txt2sce_ros.errors import InputError
from txt2sce_ros.quick_init import quick_init
from txt2sce_ros.road import RoadNetwork

from .behaviour import (Constraint, EgoOnPath, PathObject, Reason, StopPlan, lead_constraint, measure,
                        is_static, obstacle_rules, signal_constraints, start_clear, yield_constraints)
from .faults import Faults
from .idm import braking_decel, free_road_accel, slow_down_accel, stop_accel
from .params import PlannerParams
from .perception import Perception
from .pure_pursuit import curve_targets, pursuit_curvature
from .route import Route, off_route, plan_route

#: Time step assumed for the first frame (the player's default lock-step dt), s.
DEFAULT_DT = 0.05
#: Objects farther than this from the ego are not considered at all (m).
PERCEPTION_RANGE = 150.0
#: Lateral speed at which the lane offset for passing an obstacle is taken up or given back (m/s).
OFFSET_RATE = 0.6


@quick_init
@dataclass(frozen=True, slots=True)
class _Braking:
    """Decelerations (m/s², positive) the stack counts on this step."""

    stop: StopPlan           # how planned stops are made
    goal_decel: float        # the goal stop (planned, never "hard")
    idm_decel: float         # IDM's comfortable deceleration b
    max_decel: float         # the hardest braking it commands


@quick_init
@dataclass(frozen=True, slots=True)
class Decision:
    """Why the planner commanded what it did at time t (for tests, logs and the planner-check table)."""

    t: float
    accel: float
    yaw_rate: float
    reason: Reason
    entity: str
    offset: float
    constraints: tuple[Constraint, ...]
    route_ok: bool


class Planner:
    """The system under test. `road_friction` is the road's friction coefficient as the stack knows it (a real
    stack gets it from its road-condition / weather input; in our runs from the scenario's EnvironmentAction, see
    `friction_from_xosc`); None means dry (1.0)."""

    def __init__(self, network: RoadNetwork, goal: Goal | None, params: PlannerParams | None = None, *,
                 faults: Faults | None = None, road_friction: float | None = None) -> None:
        self.network = network
        self.goal = goal
        self.params = params or PlannerParams.from_config()
        self.faults = faults or Faults()
        self.road_friction = 1.0 if road_friction is None else float(road_friction)
        self.perception = Perception(self.params.perception, self.faults, self.params.faults)
        self.route: Route | None = None
        self.route_error: str = ""
        self.replans = 0
        self.decision: Decision | None = None
        self._s = 0.0
        self._accel = 0.0
        self._offset = 0.0
        self._last_t: float | None = None
        self._yellow_stops: set[str] = set()       # lights it decided to stop for at yellow onset

    # --- public -------------------------------------------------------------------------------------------------

    def set_goal(self, goal: Goal) -> None:
        if goal != self.goal:
            self.goal = goal
            self.route = None

    def step(self, frame: Frame) -> ControlCommand:
        ego = frame.ego
        # (min/max in the step are written as the builtins' comparisons: max(a, b) is `b if b > a else a`,
        # min(a, b) `b if b < a else a`, min(xs, key=k) the first x with the smallest k(x); see `_limit`)
        if self._last_t is None:
            dt = DEFAULT_DT
        else:
            dt = frame.t - self._last_t
            dt = 1e-3 if 1e-3 > dt else dt
        self._last_t = frame.t
        objects = self.perception.objects(frame)      # every frame, so latency buffers stay filled
        if self.goal is None or not self._ensure_route(ego):
            accel = self._hold(ego, dt)
            return self._command(frame, accel, 0.0, Reason.HOLD, "", (), speed=max(0.0, ego.speed + accel * dt))
        assert self.route is not None
        pp = self.route.line.project(ego.x, ego.y, near_s=self._s)
        self._s = pp.s
        v = ego.speed
        me = EgoOnPath(s=pp.s, s_front=pp.s + ego.center_x + 0.5 * ego.length, offset=pp.offset,
                       speed=0.0 if 0.0 > v else v, half_width=0.5 * ego.width)
        braking = self._braking_model(me.speed)
        constraints, target_offset = self._constraints(frame, objects, me, braking)
        binding = constraints[0]
        for c in constraints:
            if c.accel < binding.accel:
                binding = c
        accel = self._limit(binding.accel, me.speed, dt, urgent=binding.urgent, max_decel=braking.max_decel)
        self._offset = _approach(self._offset, target_offset, OFFSET_RATE * dt)
        speed, yaw = self._lateral(ego, me, accel, dt, starting=binding.accel > 0.0)
        return self._command(frame, (speed - me.speed) / dt, yaw, binding.reason, binding.entity,
                             tuple(constraints), speed=speed)

    def _braking_model(self, v: float) -> "_Braking":
        """The decelerations the stack plans with on this road (or, under `late_braking_low_friction`, on a dry
        one whatever the road) and how stops are planned this step."""
        lp, fp = self.params.longitudinal, self.params.faults
        friction = fp.dry_friction if self.faults.late_braking_low_friction else self.road_friction
        cruise = free_road_accel(v, lp.desired_speed, lp)
        braking = self._accel < -0.05
        if self.faults.late_braking_low_friction:
            # Tuned on dry roads: stops start late, at a deceleration only a dry road gives, and brake hard.
            # (stop_accel starts a stop at stop_onset_ratio x the planned deceleration: scale so that is the onset)
            plan = fp.late_brake_decel / lp.stop_onset_ratio
            # Its dry-road tuning does know its own brake build-up (at the emergency jerk): without it the stop
            # overruns on any road, and the fault would no longer depend on friction (its ground truth).
            lag = self._build_up(v, fp.late_brake_decel, self.params.comfort.emergency_jerk)
            stop = StopPlan(decel=plan, cruise=cruise, lag=lag, hard=True, braking=braking)
        else:
            plan = braking_decel(lp, friction)
            # Distance the jerk-limited build-up of braking to the planned deceleration still costs (from the
            # current acceleration: while still accelerating the build-up is longer).
            lag = self._build_up(v, plan, self.params.comfort.max_jerk)
            stop = StopPlan(decel=plan, cruise=cruise, lag=lag, braking=braking)
        # min(a, b) as the builtin compares: `b if b < a else a` (see `_limit`)
        tyres, dry = lp.friction_safety * friction * lp.gravity, friction * lp.gravity
        return _Braking(stop=stop, goal_decel=braking_decel(lp, friction),
                        idm_decel=tyres if tyres < lp.comfort_decel else lp.comfort_decel,
                        max_decel=dry if dry < lp.max_decel else lp.max_decel)

    def _build_up(self, v: float, decel: float, jerk: float) -> float:
        """m travelled while braking builds up from the current acceleration to `decel` at `jerk`."""
        d = decel + self._accel
        return 0.5 * v * (d if d > 0.0 else 0.0) / jerk          # max(0.0, d), as the builtin compares

    def _constraints(self, frame: Frame, objects: tuple[EntityState, ...], me: EgoOnPath, br: "_Braking"
                     ) -> tuple[list[Constraint], float]:
        """Every rule's demand this step, and the lateral offset to drive at (passing a static obstacle)."""
        assert self.route is not None
        line, lp, bp, sp = self.route.line, self.params.longitudinal, self.params.behaviour, br.stop
        v, v0 = me.speed, lp.desired_speed
        out: list[Constraint] = [Constraint(Reason.CRUISE, sp.cruise)]
        for dist, v_curve in curve_targets(line, me.s, v, v0, self.params.lateral, sp.decel):
            a = slow_down_accel(v, v_curve, dist, lp, plan_decel=sp.decel, lag=sp.lag, cruise=sp.cruise)
            # A late, hard plan (fault late_braking_low_friction) brakes at the emergency jerk its lag allows for.
            out.append(Constraint(Reason.CURVE, a, "", dist, urgent=sp.hard and a < 0.0))
        ego = frame.ego
        measured = [measure(o, line, me.s) for o in objects
                    if math.hypot(o.x - ego.x, o.y - ego.y) < PERCEPTION_RANGE]
        stops, target_offset = obstacle_rules(measured, me, line, lp, bp, sp)
        out += stops
        lead = lead_constraint(measured, me, self._offset, v0, lp, bp, br.idm_decel, br.max_decel)
        if lead is not None:
            out.append(lead)
        out += yield_constraints(measured, me, line, lp, bp, sp, v0)
        out += signal_constraints(frame.lights, me, line, lp, bp, sp, br.max_decel,
                                  misread_yellow=self.faults.red_light_misread, yellow_stops=self._yellow_stops)
        goal_d = self.route.goal_s + bp.goal_overshoot - me.s
        out.append(Constraint(Reason.GOAL, stop_accel(v, goal_d, lp, plan_decel=br.goal_decel, cruise=sp.cruise,
                                                      lag=sp.lag, braking=sp.braking, hold=False), "goal", goal_d))
        wait = start_clear(measured, me, self._offset, bp)
        if wait is not None:
            out.append(wait)
        if self.faults.no_start_when_close and v < 0.1 and self._npc_close(measured, me):
            out.append(Constraint(Reason.HOLD, -lp.max_decel, "npc_close"))
        return out, target_offset

    def _lateral(self, ego: EntityState, me: EgoOnPath, accel: float, dt: float, *, starting: bool
                 ) -> tuple[float, float]:
        """(speed command, yaw rate): pure pursuit on the line at the current offset, yaw rate within its limit;
        under `aggressive_start`, a pull-away with full throttle and a large steering input instead."""
        assert self.route is not None
        fp, lat = self.params.faults, self.params.lateral
        kappa = pursuit_curvature(ego.x, ego.y, ego.heading, me.s, me.speed, self.route.line, lat,
                                  offset=self._offset)
        if self.faults.aggressive_start and me.speed < fp.aggressive_start_speed and starting:
            # Autoware's start on low adhesion (paper §V-C): throttle and steering together.
            self._accel = fp.aggressive_start_accel
            return me.speed + fp.aggressive_start_accel * dt, math.copysign(fp.aggressive_start_yaw_rate,
                                                                           kappa if kappa != 0.0 else 1.0)
        speed = max(self.params.comfort.min_speed_command, me.speed + accel * dt)
        return speed, max(-lat.max_yaw_rate, min(lat.max_yaw_rate, kappa * speed))

    # --- internals ----------------------------------------------------------------------------------------------

    def _ensure_route(self, ego: EntityState) -> bool:
        assert self.goal is not None
        if self.route is not None and not off_route(self.route.line, ego.x, ego.y, ego.heading, self._s,
                                                    self.params.lateral.replan_offset):
            return True
        try:
            self.route = plan_route(self.network, ego.x, ego.y, ego.heading, self.goal)
        except InputError as exc:
            self.route, self.route_error = None, str(exc)
            return False
        self.replans += 1
        self._s = self.route.line.project(ego.x, ego.y).s
        self.route_error = ""
        return True

    def _npc_close(self, measured: list[PathObject], me: EgoOnPath) -> bool:
        radius = self.params.faults.close_start_radius
        for po in measured:
            if is_static(po.state):
                continue
            ahead = po.s_min - me.s_front
            behind = me.s - po.s_max
            if max(ahead, behind) < radius and abs(po.offset - me.offset) < 2.5:
                return True
        return False

    def _limit(self, a_des: float, v: float, dt: float, *, urgent: bool, max_decel: float) -> float:
        """Comfort limits: acceleration bounds, jerk (emergency jerk only when urgent), and a decel taper to zero
        at the moment of stopping so a stop does not end with a jolt."""
        c, lp = self.params.comfort, self.params.longitudinal
        if v < 0.05 and self._accel < 0.0:
            self._accel = 0.0                          # standing: the brake force is not an acceleration
        jerk = c.emergency_jerk if urgent else c.max_jerk
        # min/max written as the builtins' comparisons (max(a, b): `b if b > a else a`; min(a, b): `b if b < a
        # else a`), the same values at a fifth of the cost.
        lo, hi = self._accel - jerk * dt, self._accel + c.max_jerk * dt
        a = lo if lo > a_des else a_des
        a = hi if hi < a else a
        lo, hi = -max_decel, lp.max_accel
        a = lo if lo > a else a
        a = hi if hi < a else a
        if a < 0.0 and not urgent:
            lo = -math.sqrt(2.0 * c.max_jerk * (0.0 if 0.0 > v else v)) - c.max_jerk * dt
            a = lo if lo > a else a
        if v + a * dt < 0.0:
            a = -v / dt
        self._accel = a
        return a

    def _hold(self, ego: EntityState, dt: float) -> float:
        """No route or no goal: stop as comfortably as possible."""
        return self._limit(-self.params.longitudinal.comfort_decel, max(ego.speed, 0.0), dt, urgent=False,
                           max_decel=self.params.longitudinal.max_decel)

    def _command(self, frame: Frame, accel: float, yaw: float, reason: Reason, entity: str,
                 constraints: tuple[Constraint, ...], *, speed: float) -> ControlCommand:
        self.decision = Decision(t=frame.t, accel=accel, yaw_rate=yaw, reason=reason, entity=entity,
                                 offset=self._offset, constraints=constraints, route_ok=self.route is not None)
        return ControlCommand(t=frame.t, speed=speed, yaw_rate=yaw)


def _approach(x: float, target: float, step: float) -> float:
    return target if abs(target - x) <= step else x + math.copysign(step, target - x)
