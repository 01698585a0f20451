"""Realising a party's action string as OpenSCENARIO events (sketch.md's guide), with the speed and lateral
profiles they produce so the planner can time the meeting: `EventRealiser.schedule` spreads the actions over the
run-up to the conflict, `apply` turns them into EventPlans, `check_lane_changes` keeps lane changes where a lane
exists beside, `trim_trajectories` starts trajectories where the actor is when they fire."""

from __future__ import annotations

import dataclasses

import numpy as np

from ..road import RoadNetwork
from ..sketch import action_names
from .actor import Actor
from .defaults import SeedDefaults
from .kinematics import LateralStep, SpeedStep, transition_time
from .linetrack import LineTrack
from .model import EventPlan, LaneChangeAct, LaneOffsetAct, RouteAct, SpeedAct, TrajectoryAct, Trigger
from .track import Track

TURN_CODES = {"d": "left", "e": "right", "j": "uturn"}
#: The AV's turn events reuse its mission route, known only once every party is placed.
EGO_ROUTE_PLACEHOLDER = "__ego_route__"


class EventRealiser:
    """Event realisation for one scenario: the defaults, the map, the lane width at the AV and the horizon."""

    def __init__(self, defaults: SeedDefaults, net: RoadNetwork, lane_w: float, horizon: float) -> None:
        self.D = defaults
        self.net = net
        self.lane_w = lane_w
        self.horizon = horizon

    def schedule(self, actor: Actor, codes: str, *, t_first: float, t_critical: float) -> list[tuple[str, float]]:
        """Event times: the first action at `t_first`; the last lateral/speed action so that it bites at
        `t_critical`; the ones between spread evenly. Turns (route assignments) go with the event before them."""
        n = len(codes)
        if n == 0:
            return []
        lead = {"f": 0.5 * self.D.lane_change_time, "g": 0.5 * self.D.lane_change_time, "h": 3.0, "c": 2.5,
                "k": 2.5, "l": 3.0, "i": 3.0, "b": 2.0, "m": 0.0}
        if actor.name == "ego":
            # the AV's reported stop comes too late to avoid the contact: it is still braking at the conflict
            lead["h"] = 1.0
        times = [t_first]
        if n == 1 and codes in lead and codes != "m":
            # a single lateral/stop/start action is the critical one: it bites at the conflict
            times = [max(t_first, t_critical - lead[codes])]
        if n > 1:
            last = max(t_critical - lead.get(codes[-1], 0.0), t_first + 0.5 * (n - 1))
            for k in range(1, n):
                times.append(t_first + (last - t_first) * k / (n - 1))
        # route assignments early: the path through the junction must be known before the junction
        for k, c in enumerate(codes):
            if c in TURN_CODES and k > 0:
                times[k] = times[k - 1] + 0.1 if times[k - 1] + 0.1 < times[k] else times[k]
        return [(c, round(t, 2)) for c, t in zip(codes, times)]

    def apply(self, actor: Actor, schedule: list[tuple[str, float]], *, cruise: float,
              route_for: dict[str, RouteAct] | None = None, crossing: TrajectoryAct | None = None,
              lane_change_ref: str | None = None) -> None:
        """Turn (code, time) pairs into events and the matching speed/lateral steps."""
        v = actor.v0
        names = action_names("".join(c for c, _ in schedule))
        shape, dim = self.D.shape, self.D.dimension
        floor = 0.0
        for k, ((code, t), name) in enumerate(zip(schedule, names)):
            prev = actor.events[-1] if actor.events else None
            if prev is not None and prev.code == "h" and code in "ik":
                # a stop is completed before moving off again (0.5 s at standstill)
                stop_end = prev.planned_time + next((a.value for a in prev.actions if isinstance(a, SpeedAct)), 0.0)
                floor = max(floor, round(stop_end + 0.5, 2))
            t = max(t, floor)
            acts: list = []
            if code in "ai":
                target = cruise if code == "i" or v == 0.0 else v if v > 0 else cruise
            elif code == "b":
                target = max(v, cruise) * self.D.accelerate_factor
            elif code == "c":
                target = max(v, cruise) * self.D.decelerate_factor
            elif code == "h":
                target = 0.0
            elif code == "k":
                target = self.D.reverse_speed if actor.kind != "pedestrian" else -0.8
            elif code == "l":
                target = 0.0
            elif code == "m":
                target = cruise
            else:  # d e j f g: keep the speed (or start moving if standing)
                target = v if v != 0 else cruise
            dur = transition_time(v, target)
            if code == "l":
                dur = max(dur, 3.0)
            if code in TURN_CODES:
                # the AV's turn reuses its mission route (filled in by _ego_mission); a party's its own route
                acts.append(route_for[code] if route_for and code in route_for else  # type: ignore[arg-type]
                            RouteAct(EGO_ROUTE_PLACEHOLDER, ()) if actor.name == "ego" else None)
                if acts[-1] is None:
                    acts.pop()
            if code == "m" and crossing is not None:
                acts.append(crossing)
            if code in "fg" and isinstance(actor.track, LineTrack):
                # off the lane network (after a crossing): no lane to change from; keep going
                actor.notes.append(f"{name} after leaving the lanes realised as keeping speed")
            elif code in "fg":
                rel = 1 if code == "f" else -1
                acts.append(LaneChangeAct(rel, self.D.lane_change_time, lane_change_ref or actor.name))
                actor.lat_steps.append(LateralStep(t, rel * self.lane_w, self.D.lane_change_time))
            if code == "l":
                off = -(self.lane_w / 2 - actor.width / 2 - 0.2)
                acts.append(LaneOffsetAct(round(self.offset_t(actor, off), 3), self.D.lane_offset_max_lat_acc))
                actor.lat_steps.append(LateralStep(t, off - actor.lat0, 3.0))
            if target != v or not acts:
                acts.insert(0, SpeedAct(round(target, 3), shape, dim, dur))
                actor.speed_steps.append(SpeedStep(t, target, dur))
            v = target
            ev_name = f"{actor.name}_e{k + 1}_{name}"
            trigger = Trigger("time", t)
            prev = actor.events[-1] if actor.events else None
            if prev is not None and prev.code == "h" and code in "ik":
                # moving off again after a stop: chained to the end of the stop (the standstill is reached), so
                # the pause survives mutations of speed and dynamics
                stop_end = prev.planned_time + next((a.value for a in prev.actions if isinstance(a, SpeedAct)), 0.0)
                trigger = Trigger("event_end", round(max(t - stop_end, 0.0), 2), ref=prev.name)
            actor.events.append(EventPlan(ev_name, code, tuple(acts), trigger, t))

    def offset_t(self, actor: Actor, lateral: float) -> float:
        """Lateral (left of travel) -> OpenSCENARIO lane offset sign (toward +t) at the actor's start lane."""
        if isinstance(actor.track, LineTrack):
            return lateral
        pose = actor.track.lane_pose(actor.d0)
        forward = self.net.lane_forward(pose.road_id, pose.lane_id, pose.s)
        return lateral if forward != actor.track.reverse else -lateral

    def check_lane_changes(self, actor: Actor) -> None:
        """A lane change must start on a lane that has a neighbour on that side (not inside a one-lane junction
        connector) and be driven fast enough for its sideways motion. It moves to the nearest planned instant
        where both hold, no earlier than the action reported before it, else the lane is kept (noted).

        Moved ahead of earlier actions, a change would contradict them (a change left before a reported right
        turn leaves the party on a lane its route cannot start from). Sideways faster than the party drives is no
        lane change a vehicle can make, and the standard does not say what a player does then: esmini stops the
        forward motion and slides the entity sideways at its speed, ours keeps the shape's timing, so the two
        disagree by metres (waymo r247: a change left while braking to a stop, or while reversing at 1.5 m/s)."""
        if not isinstance(actor.track, Track):
            return
        t, v, d = actor.profile(self.horizon)
        duration = self.D.lane_change_time
        # peak lateral speed of the sinusoidal change (the shape the seeds write), with a margin of a quarter
        fast_enough = 1.25 * np.pi * self.lane_w / (2.0 * duration)

        def ok(at: float, rel: int) -> bool:
            # with a margin of ±0.5 s: the player's position may differ from the plan's by a few centimetres at a
            # lane's end, and a lane change is resolved against the lane the entity is on when it starts
            for dt in (-0.5, 0.0, 0.5):
                ref = actor.track.lane_at(actor.d0 + float(np.interp(at + dt, t, d)))
                if self.net.neighbour(ref, "left" if rel > 0 else "right") is None:
                    return False
            during = (t >= at - 1e-9) & (t <= at + duration + 1e-9)
            speeds = np.abs(v[during]) if during.any() else np.abs(np.interp([at], t, v))
            return bool(speeds.min() >= fast_enough)

        for k, ev in enumerate(actor.events):
            lc = next((a for a in ev.actions if isinstance(a, LaneChangeAct)), None)
            if lc is None or ok(ev.planned_time, lc.relative):
                if lc is not None:
                    actor.events[k] = self._guarded(actor, ev, lc.relative, t, d)
                continue
            earliest = actor.events[k - 1].planned_time if k > 0 else 0.0
            cands = sorted((abs(c - ev.planned_time), c) for c in np.arange(0.0, self.horizon - 5.0, 0.25)
                           if c >= earliest - 1e-9 and ok(float(c), lc.relative))
            step = next((st for st in actor.lat_steps if abs(st.t - ev.planned_time) < 1e-6), None)
            if cands:
                new_t = round(float(cands[0][1]), 2)
                actor.events[k] = self._guarded(actor, dataclasses.replace(ev, trigger=Trigger("time", new_t),
                                                                           planned_time=new_t), lc.relative, t, d)
                if step is not None:
                    actor.lat_steps[actor.lat_steps.index(step)] = LateralStep(new_t, step.delta, step.duration)
                actor.notes.append(f"{ev.name} moved to {new_t} s: no lane beside it, or too slow for it, at "
                                   f"{ev.planned_time} s")
            else:
                acts = tuple(a for a in ev.actions if not isinstance(a, LaneChangeAct)) or (
                    SpeedAct(round(float(np.interp(ev.planned_time, t, actor.profile(self.horizon)[1])), 3),
                             self.D.shape, self.D.dimension, self.D.dyn_value),)
                actor.events[k] = dataclasses.replace(ev, actions=acts)
                if step is not None:
                    actor.lat_steps.remove(step)
                actor.notes.append(f"{ev.name}: no lane beside it, at a speed that allows the change, after "
                                   f"the actions reported before it; lane kept")

    def _guarded(self, actor: Actor, ev: EventPlan, rel: int, t: np.ndarray, d: np.ndarray) -> EventPlan:
        """`ev` (a lane change) allowed to start only on the stretch of its path around the planned start where a
        lane lies beside it: a circle over that stretch. A mutated scenario (a slower party, a later start, a
        distance trigger that now fires in a junction) must not start it on a one-lane connector: there is no lane
        to change to, which esmini reports as an `[error]`. Outside the stretch the change does not happen."""
        side = "left" if rel > 0 else "right"
        d_at = actor.d0 + float(np.interp(ev.planned_time, t, d))

        def beside(dd: float) -> bool:
            return 0.0 <= dd <= actor.track.length and self.net.neighbour(actor.track.lane_at(dd), side) is not None

        if not beside(d_at):
            return ev
        lo = hi = d_at
        while hi - d_at < 200.0 and beside(hi + 0.5):
            hi += 0.5
        while d_at - lo < 200.0 and beside(lo - 0.5):
            lo -= 0.5
        mid = actor.track.world(0.5 * (lo + hi))
        radius = max(0.5 * (hi - lo) - 1.0, 1.0)
        return dataclasses.replace(ev, within=(round(mid.x, 3), round(mid.y, 3), round(radius, 2)))

    def trim_trajectories(self, actor: Actor) -> None:
        """Start every trajectory at the point the actor has reached when its event fires."""
        if not isinstance(actor.track, LineTrack):
            return
        t, _, d = actor.profile(self.horizon)
        for k, ev in enumerate(actor.events):
            if any(isinstance(a, TrajectoryAct) for a in ev.actions):
                at = actor.d0 + float(np.interp(ev.planned_time, t, d))
                acts = tuple(TrajectoryAct(a.name, actor.track.vertices(at)) if isinstance(a, TrajectoryAct) else a
                             for a in ev.actions)
                actor.events[k] = dataclasses.replace(ev, actions=acts)

