"""The Simulation: one run of a Scenario in the deterministic 2D world.

One documented step function (`Simulation.step`), in this order:

1. triggers   — the storyboard is evaluated on the state at t_k (StopTrigger, Acts, Events); actions that start
                take effect (teleports, step speeds) and take their control domains;
2. actions    — every running action advances one step (longitudinal first, then lateral/trajectory);
3. command    — the planner's ControlCommand for t_k is applied to the ego (planner mode);
4. kinematics — every entity moves dt (lane following, free motion, bicycle model for the ego);
5. derived    — t_{k+1}; accelerations, yaw rates, odometers, stand-still/end-of-road/off-road timers, signals;
6. collisions — oriented-box overlap of every pair of footprints;
7. record     — the trajectory row of t_{k+1} and the Frame returned.

An action triggered at step k therefore first shows at t_{k+1}, as in esmini's recordings.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from txt2sce_ros.contract import EGO_NAME, ControlCommand, Frame, Goal, RunStatus
from txt2sce_ros.errors import InputError
from txt2sce_ros.road import RoadNetwork

from .actions.longitudinal import SpeedAction
from .actions.teleport import TeleportAction
from .conditions.by_entity import ByEntityCondition, ReachPositionCondition
from .storyboard.build import build_storyboard
from .storyboard.element import all_complete
from .storyboard.tree import index_elements
from .syntax.scenario import Scenario
from .syntax.xml import ParseContext
from .world import collision
from .world.entity import Entity
from .world.motion import derive, move_planner, move_storyboard
from .world.world import World

if TYPE_CHECKING:
    from .actions.routing import AssignRouteAction


@dataclass(frozen=True, slots=True)
class SimulationConfig:
    dt: float = 0.05
    ego_mode: str = "planner"              # 'planner': the ego follows ControlCommands; 'storyboard': its actions
    seed: int = 0
    time_limit: float | None = None        # s of simulation time; None: config/player.yaml default
    ego_name: str | None = None            # default: 'ego' (contract), else 'Ego', else the first entity
    stop_on_ego_collision: bool = True     # planner mode: a crash ends the run (the oracle judges it)
    default_time_limit: float = 120.0
    scenario_id: str = ""
    locate_free: bool | None = None        # locate free-moving entities every step (None: only if the
                                           # scenario has an OffroadCondition; otherwise on demand)
    max_steps: int = 200_000               # bound on time_limit / dt: memory and time stay bounded
    max_entities: int = 256                # bound on entities per scenario (the step is O(n^2) in collisions)

    def __post_init__(self) -> None:
        # Refuse settings that would hang (dt <= 0), blow up (NaN positions read as a collision) or run for days,
        # before anything runs: a bad setting is the user's input error, never a verdict against the stack.
        where = "simulation settings"
        if not (isinstance(self.dt, (int, float)) and math.isfinite(self.dt) and 0.0 < self.dt <= 1.0):
            raise InputError(f"dt must be a finite step in (0, 1] s, got {self.dt!r}", source=where, element="dt")
        for name in ("time_limit", "default_time_limit"):
            value = getattr(self, name)
            if value is None and name == "time_limit":
                continue
            if not (isinstance(value, (int, float)) and math.isfinite(value) and value > 0.0):
                raise InputError(f"{name.replace('_', ' ')} must be a finite number of seconds > 0, got {value!r}",
                                 source=where, element=name)
            if value / self.dt > self.max_steps:
                raise InputError(f"{name.replace('_', ' ')} {value:g} s at dt {self.dt:g} s is "
                                 f"{value / self.dt:.3g} steps, more than the limit of {self.max_steps} "
                                 f"(config/player.yaml simulation.max_steps)", source=where, element=name)
        if self.ego_mode not in ("planner", "storyboard"):
            raise InputError(f"ego mode must be 'planner' or 'storyboard', got {self.ego_mode!r}", source=where,
                             element="ego_mode")

    @classmethod
    def from_config(cls, **overrides: object) -> "SimulationConfig":
        from dataclasses import fields

        from txt2sce_ros.config import load_config
        from txt2sce_ros.paths import config_dir

        cfg = dict(load_config("player").get("simulation", {}) or {})
        known = {f.name for f in fields(cls)}
        unknown = sorted(set(cfg) - known)
        if unknown:
            raise InputError(f"unknown key {unknown[0]!r} (known: {', '.join(sorted(known))})",
                             source=str(config_dir() / "player.yaml"), element=f"simulation.{unknown[0]}")
        cfg.update({k: v for k, v in overrides.items() if v is not None})
        return cls(**cfg)  # type: ignore[arg-type]


@dataclass
class _Recorder:
    rows: dict[str, list[tuple[float, float, float, float, float]]] = field(default_factory=dict)

    def add(self, t: float, entities: list[Entity]) -> None:
        rows = self.rows
        for e in entities:
            if e.present:
                r = rows.get(e.name)
                if r is None:
                    r = rows[e.name] = []
                r.append((t, e.x, e.y, e.h, e.speed))


#: The time of step k, `round(k * dt, 9)`, by dt: rounding to 9 digits goes through a decimal conversion
#: (~0.5 us, once per step), and every run at one dt asks the same values. Kept up to this many steps per dt.
_STEP_TIMES: dict[float, list[float]] = {}
_TIMES_KEPT = 200_000


def _step_times(dt: float) -> list[float]:
    times = _STEP_TIMES.get(dt)
    if times is None:
        if len(_STEP_TIMES) >= 16:       # a few step sizes per process; a stream of others is not kept
            _STEP_TIMES.clear()
        times = _STEP_TIMES[dt] = [round(0 * dt, 9)]
    return times


def _pick_ego(names: list[str], wanted: str | None) -> str:
    if wanted:
        return wanted
    for cand in (EGO_NAME, "Ego", "EGO", "hero"):
        if cand in names:
            return cand
    return names[0]


class Simulation:
    """One run. `reset()` executes Init; `step(command)` advances one dt; see the module docstring."""

    def __init__(self, scenario: Scenario, config: SimulationConfig | None = None) -> None:
        self.scenario = scenario
        self.config = config or SimulationConfig()
        if len(scenario.entity_names) > self.config.max_entities:
            raise InputError(f"{len(scenario.entity_names)} entities, more than the limit of "
                             f"{self.config.max_entities} (config/player.yaml simulation.max_entities)",
                             source=scenario.source, element="Entities")
        self.network: RoadNetwork = scenario.network
        self.ego_name = _pick_ego(scenario.entity_names, self.config.ego_name)
        self.goal: Goal | None = None
        self.done = False
        self.end_reason = ""
        self.verdict_hint = ""
        self.slip_steps = 0
        self._end_time = self.time_limit - 1e-9
        self._times = _step_times(self.config.dt)
        self._build()

    # -- life cycle -----------------------------------------------------------------------------------------------
    def _build(self) -> None:
        sc = self.scenario
        if sc.prebuilt:
            self.storyboard = sc.prebuilt.pop()      # load_scenario's own, never run: fresh
        else:
            self.storyboard = build_storyboard(ParseContext(sc.source), sc.root)
        entities = {spec.name: Entity(spec) for spec in sc.entities}
        self.world = World(sc.network, entities, dt=self.config.dt, seed=self.config.seed,
                           parameters=sc.doc.parameters, source=sc.source)
        for ctrl in sc.controllers:
            self.world.signals.add_controller(ctrl)
        self.world.elements = index_elements(self.storyboard.stories)
        self.ego = entities[self.ego_name]
        self.ego.planner = self.config.ego_mode == "planner"
        self.locate_free = (self.config.locate_free if self.config.locate_free is not None
                            else any(True for _ in sc.root.iter("OffroadCondition")))
        self.recorder = _Recorder()
        self.done = False
        self.end_reason = self.verdict_hint = ""
        self._started = False
        self._before: list | None = None    # positions at t_k of a step prepare_step began (None: none begun)
        # The constructor builds the world so that `network`, `world` and `ego` exist at once; the first reset()
        # uses that untouched build instead of building it again (the storyboard build is ~1 ms, a tenth of a
        # typical closed-loop run's player time).
        self._pristine = True

    def reset(self) -> Frame:
        """Build a fresh world and storyboard, execute Init (t = 0) and return the first frame."""
        if not self._pristine:
            self._build()
        self._pristine = False
        w = self.world
        planner = self.ego.planner
        if planner:     # routes matter to a planner-driven ego only (a storyboard run need not import routing)
            from .actions.routing import AssignRouteAction
        for ent_name, spec, _line in self.storyboard.init:
            if ent_name is None:
                run = spec.start(w, None)
                if run is not None and not run.done:
                    w.global_runs.append(run)
                continue
            ent = w.entity(ent_name)
            if planner and ent is self.ego and not isinstance(spec, (TeleportAction, SpeedAction, AssignRouteAction)):
                w.note(f"ignored: Init action {type(spec).__name__} on planner-driven '{ent.name}'")
                continue
            if planner and ent is self.ego and isinstance(spec, SpeedAction):
                # The initial speed only (a step sets it; a transition would start from standing still): the
                # planner drives from here.
                if spec.dynamics.shape == "step" or spec.dynamics.value == 0.0:
                    ent.speed = spec.target.speed(w)
                continue
            run = spec.start(w, ent)
            if run is not None:
                w.take(ent, run)
            if planner and ent is self.ego and isinstance(spec, AssignRouteAction):
                self.goal = self._goal_from_route(spec)
        if planner:
            self.ego.track = None
            self.ego.lane_locked = False
        for ent in w.order:
            ent.placed = False          # Init placements are the t = 0 state; everyone moves from step 1
            ent._prev_speed, ent._prev_h = ent.speed, ent.h
            if ent.track is None:
                derive(w, ent, self.config.dt, ent.x, ent.y, self.locate_free)
                ent.accel = ent.yaw_rate = 0.0
        for story in self.storyboard.stories:
            story.start(w)
        self._started = True
        self.recorder.add(0.0, w.order)
        return self.frame()

    def _goal_from_route(self, spec: AssignRouteAction) -> Goal:
        pose = self.world.resolve_cached(spec.route.waypoints[-1].position)
        tol = 3.0
        stop = self.storyboard.stop_trigger
        if stop is not None:
            for group in stop.groups:
                for cond in group.conditions:
                    chk = cond.check
                    if isinstance(chk, ByEntityCondition) and isinstance(chk.check, ReachPositionCondition):
                        tol = chk.check.tolerance
        return Goal(x=pose.x, y=pose.y, heading=pose.h, tolerance=tol)

    @property
    def time_limit(self) -> float:
        return self.config.time_limit if self.config.time_limit is not None else self.config.default_time_limit

    # -- the step -------------------------------------------------------------------------------------------------
    def step(self, command: ControlCommand | None = None) -> Frame:
        """Advance one dt (the documented step function) and return the new frame. A step begun by
        `prepare_step` is completed with `command` (the frame is the current one when the run ended there)."""
        self.advance(command)
        return self.frame()

    def advance(self, command: ControlCommand | None = None) -> None:
        """`step` without building the Frame (batch runs that only need the trajectory)."""
        self.prepare_step()
        self._complete_step(command)

    def prepare_step(self) -> None:
        """The part of the next step that does not depend on the planner's command (1. triggers, 2. actions, and
        the kinematics and derived states of every entity the planner does not drive): a lock-step node runs it while the planner
        works on the frame just published, so that only the rest of `step` lies between the command and the next
        frame. Each entity's motion reads only its own state, the road and the world's friction, so moving the
        planner-driven ego after the others gives the same bits as moving everyone in list order (the
        regress fingerprints check this). Calling it again before `step` does nothing."""
        if not self._started:
            self.reset()
        if self.done or self._before is not None:
            return
        w, dt = self.world, self.config.dt
        # 1. triggers
        stop = self.storyboard.stop_trigger
        if stop is not None and stop.evaluate(w):
            fired = [c.name for g in stop.groups for c in g.conditions if c.last_value]
            self._finish("goal_reached" if any("goal" in n for n in fired) else "stop_trigger")
            return
        for story in self.storyboard.stories:
            story.tick(w)
        # 2. actions
        order = w.order
        before = []
        for e in order:
            if e.track is None:
                before.append((e.x, e.y, 0.0, None))
            else:
                road = e.road()
                before.append((e.x, e.y, road[3], road[0]))
        w.step_runs(dt)
        # 4. kinematics of everyone the storyboard drives, and 5. their derived states (each reads only the
        # entity's own motion and the road, not the time or the other entities, so one entity's motion and
        # derived state may come before the next entity's motion)
        locate_free = self.locate_free
        for ent, (px, py, pt, proad) in zip(order, before):
            if ent.present and not ent.planner:
                move_storyboard(w, ent, dt, pt, proad)
                derive(w, ent, dt, px, py, locate_free)
                ent._prev_speed, ent._prev_h = ent.speed, ent.h
        self._before = before

    def _complete_step(self, command: ControlCommand | None) -> None:
        before = self._before
        if before is None:
            return                      # the run ended in prepare_step (or was never prepared: done)
        self._before = None
        w, dt = self.world, self.config.dt
        order = w.order
        # 3 + 4. planner command and kinematics of the planner-driven ego
        for ent in order:
            if ent.planner and ent.present:
                if move_planner(w, ent, command, dt):
                    self.slip_steps += 1
        # 5. derived states
        k = w.step_index + 1
        times = self._times
        if k < len(times):
            t = times[k]
        else:
            t = round(k * dt, 9)
            if k == len(times) and k <= _TIMES_KEPT:
                times.append(t)
        w.t = t
        w.step_index = k
        w.signals.step(t)
        locate_free = self.locate_free
        for ent, (px, py, _pt, _pr) in zip(order, before):
            if ent.present and ent.planner:
                derive(w, ent, dt, px, py, locate_free)
                ent._prev_speed, ent._prev_h = ent.speed, ent.h
            if ent.colliding:
                ent.colliding.clear()       # 6. starts from no contact (sets are rarely non-empty: test first)
        # 6. collisions
        for a, b in collision.detect(order):
            w.entities[a].colliding.add(b)
            w.entities[b].colliding.add(a)
        # 7. record
        self.recorder.add(t, order)
        ego = self.ego
        stop = self.storyboard.stop_trigger
        stories = self.storyboard.stories
        if stop is None and stories and all_complete(stories):
            self._finish("storyboard_complete")
        elif ego.planner and self.config.stop_on_ego_collision and ego.colliding:
            self._finish("collision")
        elif ego.planner and self.goal is not None and math.hypot(
                ego.x - self.goal.x, ego.y - self.goal.y) <= self.goal.tolerance:
            self._finish("goal_reached")
        elif t >= self._end_time:
            self._finish("time_limit")

    def _finish(self, reason: str, verdict_hint: str = "") -> None:
        self.done = True
        self.end_reason = reason
        self.verdict_hint = verdict_hint

    def abort(self, reason: str) -> None:
        """End the run from outside (e.g. the node: planner not responding) as an error of the run itself."""
        self._finish(reason, "error")

    # -- outputs --------------------------------------------------------------------------------------------------
    def frame(self) -> Frame:
        w = self.world
        t = w.t
        ego = self.ego
        objects = tuple([e.state(t) for e in w.order if e.present and e is not ego])
        return Frame(t=t, ego=ego.state(t), objects=objects, lights=w.signals.lights())

    @property
    def t(self) -> float:
        return self.world.t

    @property
    def unsupported(self) -> list[str]:
        return list(self.scenario.unsupported)

    @property
    def notes(self) -> list[str]:
        return list(self.world.notes)

    @property
    def status(self) -> RunStatus:
        notes = list(self.scenario.unsupported) + [n for n in self.world.notes if n not in self.scenario.unsupported]
        if self.slip_steps:
            notes.append(f"note: ego wheels slipped in {self.slip_steps} steps (friction {self.world.friction:g})")
        return RunStatus(scenario_id=self.config.scenario_id or self.scenario.source,
                         state="finished" if self.done else ("started" if self._started else "pending"),
                         t=self.world.t, end_reason=self.end_reason, verdict_hint=self.verdict_hint,
                         unsupported=tuple(notes))

    @property
    def trajectory(self) -> dict[str, np.ndarray]:
        """Per entity: rows of t, x, y, heading, speed (float64)."""
        return {name: np.array(rows, dtype=float) for name, rows in self.recorder.rows.items()}

    def run(self, *, max_steps: int | None = None) -> RunStatus:
        """Batch: run to the end with no planner commands (storyboard mode, or a planner-less smoke run)."""
        self.reset()
        n = 0
        while not self.done and (max_steps is None or n < max_steps):
            self.advance(None)
            n += 1
        return self.status
