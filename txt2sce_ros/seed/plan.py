"""Placement and timing (paper §III-B.2 step 2 and §III-B.3): a sketch on a matched site becomes a ScenarioPlan.

The rule that makes the reported interaction happen: every party gets a path on the map (`Track`), an event
schedule from its action string, and the speed/lateral profiles those events produce; then its start offset is
solved so that it reaches its conflict point with the AV at the moment the AV does:

- paths that cross (junction legs, turns across a lane, crossings): the conflict point is where the two paths
  meet; the AV's time to it comes from its own profile, the party starts `D_party(T)` before it;
- parallel paths (same road, R5–R7): the party is placed so that, at the conflict time, its box touches the AV's
  box (front to rear for rear-ends, side by side for lane changes and passes, front to front head-on);
- a party that cannot start early enough waits and is released by a distance-to-AV trigger;
- an AV standing at a junction waits with its front bumper 1 m behind the map's stop line of its lane (inside the
  junction only when the report gives it right of way there), and a party that cannot reach it swings toward it;
- a party that touches the AV but would start on the other side of it than reported (R5/R6) gets there faster,
  slower, earlier or later instead; a party reported behind the AV that crosses (`m`) crosses behind it; every start
  that still does not read as its reported position (`sides.start_position`) says why in the manifest;
- finally no two footprints may touch at t=0 (the closed loop would call the scenario invalid): starts are moved
  apart along their paths, never past the AV, keeping the reported contact where a shift allows it.

Everything random is drawn from the caller's numpy Generator (the site pick); the placement is deterministic.

`Planner` (here: the plan's order, parties and obstacles) combines one mixin per concept: `plan_ego` (the AV's
path, waiting place and mission), `plan_paths` (party paths and routes), `plan_meet` (where and when a party meets
the AV), `plan_sides` (reported sides) and `plan_start` (footprints apart at t=0).
"""

from __future__ import annotations

import dataclasses

import math

import numpy as np

from ..sketch import Party, Sketch
from .actor import Actor, center_x, predicted_gap
from .defaults import SeedDefaults
from .events import TURN_CODES, EventRealiser
from .kinematics import lateral_profile, speed_profile
from .linetrack import LineTrack
from .model import EventPlan, TrajectoryAct, Trigger
from .plan_ego import EgoPlanning
from .plan_meet import Meeting
from .plan_paths import PartyPaths
from .plan_sides import ReportedSides
from .plan_start import StartSeparation
from .sides import on_reported_side
from .sites import JunctionSite, RoadSite, site_network
from .track import Track

__all__ = ["Actor", "Planner", "predicted_gap"]


class Planner(EgoPlanning, PartyPaths, Meeting, ReportedSides, StartSeparation):
    """Plans one sketch on one site. Use `plan()`; read `actors`, `choices` afterwards."""

    def __init__(self, sketch: Sketch, site: JunctionSite | RoadSite, defaults: SeedDefaults) -> None:
        self.sketch = sketch
        self.site = site
        self.D = defaults
        self.net = site_network(site)
        self.T = defaults.timing.time_to_conflict
        self.horizon = defaults.timing.time_limit
        self.choices: dict = {"site": site.describe(), "parties": {}}
        self.actors: list[Actor] = []
        self.lane_w = 3.5
        self.ev = EventRealiser(defaults, self.net, self.lane_w, self.horizon)

    # ------------------------------------------------------------------------------------------ entity basics
    def _actor(self, name: str, category: str, track: Track | LineTrack) -> Actor:
        raw = self.D.raw
        if category in raw["pedestrian_category"]:
            kind, xcat = "pedestrian", raw["pedestrian_category"][category]
        elif category in raw["vehicle_category"]:
            kind, xcat = "vehicle", raw["vehicle_category"][category]
        else:
            kind, xcat = "misc", raw["misc_category"][category]
        return Actor(name, kind, category, xcat, self.D.dims(category), track)

    # ------------------------------------------------------------------------------------------ the plan
    def plan(self) -> list[Actor]:
        sk, D = self.sketch, self.D
        track, idx, d_entry, lane_w = self._ego_track()
        ego = self._actor("ego", "car", track)
        ego.category, ego.external = "ego", True
        ego.dims = D.dims("ego")
        ego.v0 = D.speed("ego") if sk.ego.start == "moving" else 0.0
        self.ego, self.ego_idx, self.d_entry = ego, idx, d_entry
        t_first = 0.0
        if sk.ego.start == "stopped" and sk.ego.actions[:1] == "i":
            # moved off from a standstill: after the reported red phase when there was one
            t_first = D.timing.signal_phase_before if sk.signal_state == "red" else 1.0
        self.ego_t_first = t_first
        sched = self.ev.schedule(ego, sk.ego.actions, t_first=t_first, t_critical=self.T)
        ego_routes = {}
        self.ev.apply(ego, sched, cruise=D.speed("ego"), route_for=ego_routes)
        self.actors = [ego]
        t, _, de = ego.profile(self.horizon)
        self.ego_t, self.ego_d = t, de
        # ---- ego start: where the collision (or first) party's conflict needs it
        collision = sk.collision.with_
        order = sorted(sk.npcs, key=lambda p: (p.id != collision, p.id))
        first = True
        for p in order:
            self._plan_party(p, primary=first)
            first = False
        if not sk.npcs:
            self._place_ego_default()
        for o in sk.obstacles:
            self._plan_obstacle(o)
        self.ev.check_lane_changes(ego)
        self._separate_at_start()
        self._relative_triggers()
        self._note_reported_sides()
        # the ego's mission: route through its path, goal beyond the conflict
        self._ego_mission(ego_routes)
        return self.actors

    def _relative_triggers(self) -> None:
        """The collision party's critical later manoeuvre (a lane change, stop, slow-down or reversing) fires by
        its distance to the AV rather than by the clock when the AV is closing in at that moment: in closed loop
        the planner's AV is not where the plan put it, and the manoeuvre should still come when the AV is near."""
        target = self.sketch.collision.with_
        party = next((a for a in self.actors if a.name == target and a.events), None)
        if party is None or isinstance(party.track, LineTrack):
            return
        t, pe = self.ego.states(self.horizon)
        _, pp = party.states(self.horizon)
        gap = np.hypot(pe[:, 0] - pp[:, 0], pe[:, 1] - pp[:, 1])
        for k, ev in enumerate(party.events):
            if k == 0 or ev.code not in "fghck" or ev.trigger.kind != "time":
                continue
            i = int(np.searchsorted(t, ev.planned_time))
            j = int(np.searchsorted(t, max(ev.planned_time - 1.0, 0.0)))
            if i >= len(t) or gap[j] - gap[i] < 0.5 or np.any(np.diff(gap[: i + 1]) > 1e-6):
                continue  # not steadily closing up to then: a distance threshold would fire early or never
            party.events[k] = dataclasses.replace(
                ev, trigger=Trigger("distance", round(float(gap[i]) + 0.3, 2), party.name, "ego"))
            party.notes.append(f"{ev.name} fires at {float(gap[i]) + 0.3:.1f} m from the AV")

    def _plan_party(self, p: Party, *, primary: bool) -> None:
        track, lat, mode = self._party_track(p)
        cruise = self.D.speed(p.category)
        is_collision = self.sketch.collision.with_ == p.id
        T = self.T if primary or is_collision else self.T * 0.7
        if mode == "line":
            self._plan_crossing(p, T, cruise, primary)
            return

        def build(speed: float | None = None, shift: float = 0.0) -> Actor:
            return self._realise(p, track, lat, mode, T, primary, speed=speed, shift=shift)

        actor = build()
        if is_collision and p.position in ("R5", "R6") and mode in ("parallel", "cross") and \
                not actor.track.reverse and not on_reported_side(self.ego, actor, p.position):
            actor = self._retime_to_reported_side(p, actor, build)
        self.actors.append(actor)
        self.choices["parties"].setdefault(p.id, {}).update({
            "mode": mode, "start_d": round(actor.d0, 2), "speed": actor.v0, "conflict_time": round(T, 2),
            "notes": actor.notes})

    def _realise(self, p: Party, track: Track | LineTrack, lat: float, mode: str, T: float, primary: bool, *,
                 speed: float | None = None, shift: float = 0.0) -> Actor:
        """The party on its path, its events, and the start that meets the AV at T. `speed` overrides its cruise
        speed (and the closing-speed rules), `shift` moves its event schedule later (> 0) or earlier."""
        D, ego = self.D, self.ego
        cruise = D.speed(p.category)
        is_collision = self.sketch.collision.with_ == p.id
        actor = self._actor(p.id, p.category, track)
        actor.lat0 = lat
        actor.v0 = cruise if p.start == "moving" else 0.0
        # Parallel rear-end: the faster one must close the gap.
        ego_v_T = float(np.interp(T, self.ego_t, speed_profile(ego.v0, ego.speed_steps, self.horizon)[1]))
        if speed is not None:
            cruise = speed
            actor.v0 = speed if p.start == "moving" else 0.0
        elif mode in ("parallel", "exit") and p.position in ("R6",) and p.lane == "same" and actor.v0 > 0 and \
                not set(p.actions) & set("hck") and is_collision:
            if actor.v0 < ego_v_T + 2.0:
                actor.v0 = cruise = round(ego_v_T + 3.0, 2)
                actor.notes.append("speed raised so that it closes on the AV")
        elif mode in ("parallel", "exit") and p.position in ("R5", "R4") and p.lane in ("same", None) and \
                actor.v0 > 0 and not set(p.actions) & set("hckfg") and ego_v_T > 0:
            if actor.v0 > 0.6 * ego_v_T:
                actor.v0 = cruise = round(0.5 * ego_v_T, 2)
                actor.notes.append("speed lowered so that the AV closes on it")
        routes = self._party_routes(p, actor)
        if isinstance(track, LineTrack):
            traj = TrajectoryAct(f"{p.id}_path", track.vertices())
            routes = {c: traj for c in p.actions if c in TURN_CODES}
        sched = self.ev.schedule(actor, p.actions, t_first=0.0, t_critical=T)
        if shift:
            sched = [(c, round(max(t + shift, 0.0), 2)) for c, t in sched]
        self.ev.apply(actor, sched, cruise=cruise, route_for=routes)
        if not routes:
            actor.route = self._through_route(actor)
        t, _, dn = actor.profile(self.horizon)
        # ---- the meeting
        if mode == "cross":
            self._meet_crossing(actor, T, primary, t, dn)
        else:
            self._meet_parallel(p, actor, T, t, dn, mode)
        self._release_if_needed(actor)
        self.ev.check_lane_changes(actor)
        self.ev.trim_trajectories(actor)
        return actor

    # ---- obstacles
    def _plan_obstacle(self, o) -> None:
        ego = self.ego
        if not getattr(self, "_ego_placed", False) and ego.d0 == 0.0 and not self.sketch.npcs:
            self._place_ego_default()
        is_collision = self.sketch.collision.with_ == o.id
        front = ego.cx + ego.length / 2
        dims = self.D.dims(o.category)
        travelled_T = self._ego_d_at(self.T)
        final = float(self.ego_d[-1])
        kind_vehicle = o.category == "parked_vehicle"
        cx = center_x("vehicle", dims[1]) if kind_vehicle else 0.0
        if o.position == "R6":
            back = min(float(np.min(self.ego_d)), 0.0)
            rear = ego.cx - ego.length / 2
            d = ego.d0 + back + rear - (cx + dims[1] / 2) + (0.2 if is_collision else -3.0)
        else:
            reach = travelled_T if travelled_T > 1.0 else max(final, 0.0)
            if not is_collision:
                reach = max(reach, 20.0) if self.sketch.collision.with_ else reach
            d = ego.d0 + reach + front + (dims[1] / 2 - cx) + (-0.3 if is_collision else 4.0)
            if o.position == "R4" and math.isfinite(self.d_entry):
                d = max(d, self.d_entry + 15.0)
        t_e, pe = ego.states(self.horizon)
        ego_lat_T = float(np.interp(self.T, t_e, lateral_profile(ego.lat0, ego.lat_steps, t_e)))
        if o.position == "R6":
            ego_lat_T = ego.lat0
        lat = ego_lat_T if is_collision else 0.0
        edge = self.lane_w / 2
        if o.lane in ("left", "right", "shoulder") or (o.position == "R7"):
            sign = 1.0 if (o.lane == "left" or o.position == "R7") else -1.0
            if is_collision:
                lat = ego_lat_T + sign * (ego.width / 2 + dims[0] / 2 - 0.3)   # overlapping the AV's path by 0.3 m
            else:
                lat = sign * (edge + dims[0] / 2 + 0.3)
            if o.position == "R7":
                lat = sign * (self.lane_w + edge + dims[0] / 2) if not is_collision else lat
        actor = self._actor(o.id, o.category, ego.track)
        actor.d0, actor.lat0, actor.v0 = float(np.clip(d, 0.0, ego.track.length)), lat, 0.0
        self.actors.append(actor)
        self.choices.setdefault("obstacles", {})[o.id] = {"d": round(actor.d0, 2), "lateral": round(lat, 2)}

