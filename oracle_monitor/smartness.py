"""Smartness oracles (paper §III-D.2): failure to start, failure to reach the goal, misinterpretation.

- Failure to start (StartFail): the ego has not left its start (by `start_distance`) after standing still for
  `start_timeout` seconds *with a clear path*; or it never moved at all in a run at least that long and its path
  is clear at the end (a blocker that stays to the end makes it a failure to reach the goal instead).
- Failure to reach the goal (PlanFail): it stands still mid-route with a clear path for `stop_timeout`; it stands
  (`park_time`) with part of its footprint outside the allowed lanes; or the run ends (time out, end of the story)
  with the goal not reached.
- Misinterpretation (Misinterp): its front bumper crosses a stop line whose signal shows red (the state of the
  last frame before the crossing: what the stack saw when it decided); it hits a static object that had been in
  view (within `sensor_range`) for `visible_time` seconds. Occlusion is not modelled.

"Clear path" (`wait_reason`): no entity's footprint in the corridor `clear_distance` metres along the ego's path
ahead of the front bumper (ego width plus `clear_margin` each side), no mover about to cross that path (within
`conflict_distance` m and `conflict_horizon` s: the ego is yielding), and no red/yellow signal governing the ego
whose stop line lies within `clear_distance` ahead. The path is the road model's route to the goal (`egopath.py`).

A signal governs the ego when the ego heads the signal's way (within `light_heading_tolerance_deg`) and, with a road
network and a signal that names its lanes, when the ego is in one of those lanes on the signal's road; otherwise
(no network, no lanes, ego not on that road) when it is within `light_half_width` of the stop point laterally.
Waiting behind a car or at a red light is therefore never a failure to start.
"""

from __future__ import annotations

import math
from typing import Any

from txt2sce_ros.contract import EntityState, Frame, Goal, SignalState, TrafficLightState

from .egopath import EgoPath
from .geometry import footprint
from .params import SmartnessParams
from .records import Category, Rule, Violation
from .signals import Sample


def front_point(e: EntityState) -> tuple[float, float]:
    """Centre of the front bumper."""
    d = e.center_x + 0.5 * e.length
    return e.x + d * math.cos(e.heading), e.y + d * math.sin(e.heading)


class SmartnessOracle:
    def __init__(self, params: SmartnessParams, goal: Goal | None, network: Any | None = None) -> None:
        self.params = params
        self.goal = goal
        self.network = network
        self._start: tuple[float, float] | None = None
        self._t0 = 0.0
        self.moved = False
        self.goal_reached = False
        self.min_goal_distance = math.inf
        self._still = 0.0                    # s standing still in the current stop
        self._still_clear = 0.0              # s of it with a clear path
        self._stop_reported = False
        self._park_reported = False
        self._start_reported = False
        self._prev_front: tuple[float, float] | None = None
        self._prev_lights: dict[str, TrafficLightState] = {}
        self._in_view_since: dict[str, float] = {}
        self._located: dict[tuple[float, float, float], Any] = {}
        self.last_frame: Frame | None = None
        self._path: EgoPath | None = None          # planned when the ego first stands (route to the goal)
        self._cos_tol = math.cos(math.radians(params.light_heading_tolerance_deg))
        self._light_axes: dict[float, tuple[float, float]] = {}   # cos, sin of a signal's heading, by heading

    def set_network(self, network: Any | None) -> None:
        """The road network arrived late: lane checks and the way ahead use it from now on."""
        self.network = network
        self._path = None

    # --- per frame ---------------------------------------------------------------------------------------------

    def observe(self, frame: Frame, s: Sample) -> list[Violation]:
        p = self.params
        ego = frame.ego
        out: list[Violation] = []
        if self._start is None:
            self._start, self._t0 = (ego.x, ego.y), frame.t
        self._track_view(frame)
        if self.goal is not None:
            d = math.hypot(ego.x - self.goal.x, ego.y - self.goal.y)
            self.min_goal_distance = min(self.min_goal_distance, d)
            if d <= self.goal.tolerance:
                self.goal_reached = True
        if not self.moved and math.hypot(ego.x - self._start[0], ego.y - self._start[1]) > p.start_distance:
            self.moved = True
            self._still = self._still_clear = 0.0
        v = self._red_light(frame)
        if v:
            out.append(v)
        out.extend(self._standing(frame, s))
        self.last_frame = frame
        return out

    def _standing(self, frame: Frame, s: Sample) -> list[Violation]:
        p = self.params
        ego = frame.ego
        if abs(ego.speed) >= p.stop_speed:
            self._still = self._still_clear = 0.0
            self._stop_reported = self._park_reported = False
            return []
        self._still += s.dt
        if self._stop_reported if self.moved else self._start_reported:
            # This stop's failure is reported already and the clear-path time counts for nothing more until the
            # ego moves (which resets it): only the path's state (planned once, located near the last answer) is
            # kept as the full check would leave it.
            self._follow_path(frame)
        elif self.path_clear(frame):
            self._still_clear += s.dt
        out = []
        if not self.moved:
            if self._still_clear >= p.start_timeout and not self._start_reported:
                self._start_reported = True
                out.append(Violation(Rule.NO_START, Category.START_FAIL, frame.t, self._still_clear, p.start_timeout,
                                     "s", (), "standing at the start with a clear path"))
            return out
        at_goal = self.goal is not None and math.hypot(ego.x - self.goal.x, ego.y - self.goal.y) <= self.goal.tolerance
        if self._still_clear >= p.stop_timeout and not at_goal and not self._stop_reported:
            self._stop_reported = True
            out.append(Violation(Rule.STOPPED_MID_ROUTE, Category.PLAN_FAIL, frame.t, self._still_clear,
                                 p.stop_timeout, "s", (), "standing mid-route with a clear path"))
        if self._still >= p.park_time and not self._park_reported and self.network is not None:
            # Checked once per stop (standing still, the footprint does not move; the lookup costs ~1 ms).
            self._park_reported = True
            outside = self.outside_lane(ego)
            if outside:
                out.append(Violation(Rule.PARKED_OUTSIDE_LANE, Category.PLAN_FAIL, frame.t, outside, 0.0,
                                     "corners", (), f"{outside:.0f} of 4 footprint corners outside "
                                                    f"{'/'.join(p.lane_types)} lanes"))
        return out

    # --- red lights ----------------------------------------------------------------------------------------------

    def stop_line_position(self, light: TrafficLightState, heading: float,
                           point: tuple[float, float]) -> tuple[float, float] | None:
        """(longitudinal, lateral) position of `point` relative to the light's stop line (longitudinal > 0: past
        it), or None when the ego heads another way than the signal's lanes (cheap: no map lookup)."""
        return self._stop_line_position(light, math.cos(heading), math.sin(heading), point)

    def _stop_line_position(self, light: TrafficLightState, ch: float, sh: float,
                            point: tuple[float, float]) -> tuple[float, float] | None:
        """`stop_line_position` with the heading's cosine and sine given (the same for every light of a frame)."""
        cs = self._light_axes.get(light.heading)
        if cs is None:
            cs = (math.cos(light.heading), math.sin(light.heading))
            if light.heading != 0.0:          # 0.0 and -0.0 are one key but have sines of either sign
                self._light_axes[light.heading] = cs
        c, s = cs
        if ch * c + sh * s < self._cos_tol:
            return None
        dx, dy = point[0] - light.stop_x, point[1] - light.stop_y
        return dx * c + dy * s, -dx * s + dy * c

    def governs(self, light: TrafficLightState, heading: float, point: tuple[float, float], lat: float) -> bool:
        """Whether the signal is the ego's at `point` (lateral offset `lat` from its stop point): by its controlled
        lanes when the map can tell, else by `light_half_width`."""
        lane = self._in_controlled_lane(light, point, heading)
        return lane is True or (lane is None and abs(lat) <= self.params.light_half_width)

    def _in_controlled_lane(self, light: TrafficLightState, point: tuple[float, float],
                            heading: float) -> bool | None:
        """Whether `point` lies in one of the lanes the signal controls, from the road network; None when that
        cannot be told (no network, a signal without lanes, a point off the road or past the signal's road)."""
        if self.network is None or not light.road_id or not light.lane_ids:
            return None
        lp = self._locate(point, heading)
        if lp is None or not lp.inside or lp.road_id != light.road_id:
            return None
        return lp.ref.lane_id in light.lane_ids

    def _locate(self, point: tuple[float, float], heading: float) -> Any:
        """`network.locate`, remembered for the last few points: a crossing asks about this frame's and the
        previous frame's bumper, for every signal."""
        key = (point[0], point[1], heading)
        cache = self._located
        if key not in cache:
            if len(cache) > 8:
                cache.clear()
            try:
                cache[key] = self.network.locate(point[0], point[1], heading)
            except Exception:               # a map the lookup cannot serve here: fall back to the lateral test
                cache[key] = None
        return cache[key]

    def _red_light(self, frame: Frame) -> Violation | None:
        ego = frame.ego
        front = front_point(ego)
        prev_front, prev_lights = self._prev_front, self._prev_lights
        self._prev_front = front
        self._prev_lights = {light.id: light for light in frame.lights}
        if prev_front is None:
            return None
        ch, sh = math.cos(ego.heading), math.sin(ego.heading)
        for light in frame.lights:
            before = prev_lights.get(light.id, light)
            p0 = self._stop_line_position(before, ch, sh, prev_front)
            if p0 is None or not p0[0] < 0.0:
                continue                            # not heading its way, or past the line already
            p1 = self._stop_line_position(light, ch, sh, front)
            if p1 is None or not 0.0 <= p1[0]:
                continue                            # not heading its way, or no crossing in this step
            red = before.state is SignalState.RED or (
                self.params.yellow_is_violation and before.state is SignalState.YELLOW)
            if red and self.governs(before, ego.heading, prev_front, p0[1]):
                return Violation(Rule.RED_LIGHT, Category.MISINTERP, frame.t, ego.speed, 0.0, "m/s",
                                 (light.id,), f"crossed the stop line of signal {light.id} on {before.state.value} "
                                              f"at {ego.speed:.2f} m/s (lateral {p1[1]:+.2f} m)")
        return None

    # --- clear path, visibility, lanes ---------------------------------------------------------------------------

    def path_clear(self, frame: Frame) -> bool:
        return not self.wait_reason(frame)

    def blocker_ahead(self, frame: Frame) -> str:
        """The entity in the corridor along the ego's path ahead ('' when none)."""
        if self._path is None:
            self._path = EgoPath.plan(self.network, frame.ego, self.goal)
        return self._path.blocker(frame.ego, front_point(frame.ego), frame.objects,
                                  clear_distance=self.params.clear_distance, margin=self.params.clear_margin)

    def _follow_path(self, frame: Frame) -> None:
        """What `wait_reason` leaves behind in the path (its plan, its last located point), without judging: the
        corridor test, whose answer decides whether the crossing test locates the bumper once more."""
        p = self.params
        if self._path is None:
            self._path = EgoPath.plan(self.network, frame.ego, self.goal)
        front = front_point(frame.ego)
        if not self._path.blocker(frame.ego, front, frame.objects, clear_distance=p.clear_distance,
                                  margin=p.clear_margin):
            self._path.locate(*front)

    def wait_reason(self, frame: Frame) -> str:
        """Why a standing ego may wait ('' when nothing gives it a reason): an entity in the corridor along its
        path, a mover about to cross the path ahead (`egopath`), or a red/yellow signal governing it whose stop
        line is close ahead."""
        p = self.params
        ego = frame.ego
        if self._path is None:
            self._path = EgoPath.plan(self.network, ego, self.goal)
        fx, fy = front_point(ego)
        name = self._path.blocker(ego, (fx, fy), frame.objects, clear_distance=p.clear_distance,
                                  margin=p.clear_margin)
        if name:
            return f"{name} in the path"
        name = self._path.crossing(ego, (fx, fy), frame.objects, distance=p.conflict_distance,
                                   horizon=p.conflict_horizon, margin=p.conflict_margin, min_speed=p.stop_speed)
        if name:
            return f"{name} about to cross the path"
        for light in frame.lights:
            if light.state is SignalState.RED or light.state is SignalState.YELLOW:
                pos = self.stop_line_position(light, ego.heading, (fx, fy))
                # lon < 0: the line is ahead of the bumper; a bumper just over it (1 m) still waits for it.
                if pos is not None and -p.clear_distance <= pos[0] <= 1.0 and \
                        self.governs(light, ego.heading, (fx, fy), pos[1]):
                    return f"signal {light.id} {light.state.value}"
        return ""

    def _track_view(self, frame: Frame) -> None:
        ex, ey = frame.ego.x, frame.ego.y
        r2 = self.params.sensor_range ** 2
        seen = self._in_view_since
        for obj in frame.objects:
            if (obj.x - ex) ** 2 + (obj.y - ey) ** 2 <= r2:
                seen.setdefault(obj.name, frame.t)
            else:
                seen.pop(obj.name, None)

    def visible_for(self, name: str, t: float) -> float:
        """Seconds the entity has been in view (continuously) up to `t`; 0 if it is not in view."""
        since = self._in_view_since.get(name)
        return 0.0 if since is None else t - since

    def outside_lane(self, ego: EntityState) -> int:
        """How many of the footprint's corners lie outside every lane of the allowed types (0 when inside)."""
        corners = footprint(ego).corners()
        xs = [c[0] for c in corners]
        ys = [c[1] for c in corners]
        match = self.network.world_to_lane(xs, ys, lane_types=tuple(self.params.lane_types))
        return int(sum(1 for inside in match.inside if not bool(inside)))

    # --- end of run ----------------------------------------------------------------------------------------------

    def finish(self, t_end: float, end_reason: str) -> list[Violation]:
        p = self.params
        out: list[Violation] = []
        frame = self.last_frame
        if frame is None:
            return out
        # Never moved over a run long enough to have started, and nothing blocks it at the end: the blocker (if
        # any) went away and the ego still did not go. A blocker present to the end is a planning matter instead.
        if (not self.moved and not self._start_reported and t_end - self._t0 >= p.start_timeout
                and self.path_clear(frame)):
            d = math.hypot(frame.ego.x - self._start[0], frame.ego.y - self._start[1])  # type: ignore[index]
            out.append(Violation(Rule.NO_START, Category.START_FAIL, t_end, d, p.start_distance, "m", (),
                                 f"never moved in {t_end - self._t0:.1f} s"))
        if self.goal is not None and not self.goal_reached:
            d = math.hypot(frame.ego.x - self.goal.x, frame.ego.y - self.goal.y)
            why = "time out" if end_reason == "time_limit" else f"run ended ({end_reason or 'no reason given'})"
            out.append(Violation(Rule.GOAL_NOT_REACHED, Category.PLAN_FAIL, t_end, d, self.goal.tolerance, "m", (),
                                 f"{why} {d:.1f} m from the goal (closest {min(d, self.min_goal_distance):.1f} m)"))
        return out
