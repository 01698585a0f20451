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
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError
from ..mapdb.classify import approach_signals
from ..sketch import Party, Sketch
from .actor import Actor, center_x, predicted_gap
from .constraints import first_turn
from .defaults import SeedDefaults
from .events import EGO_ROUTE_PLACEHOLDER, TURN_CODES, EventRealiser
from .kinematics import LateralStep, box_corners, boxes_gap, lateral_profile, speed_profile, time_to_reach
from .lanes import CURB, case1_lane, ego_lane, party_lane
from .linetrack import LineTrack, perpendicular
from .model import EventPlan, LaneChangeAct, LaneOffsetAct, LanePose, RouteAct, SpeedAct, TrajectoryAct, Trigger
from .sides import on_reported_side, reported_code, start_position
from .sites import JunctionSite, RoadSite, site_network
from .track import Track

__all__ = ["Actor", "Planner", "predicted_gap"]

#: m between a standing AV's front bumper and the stop line that holds it
STOP_LINE_GAP = 1.0
#: m where the AV's lane has no stop line: its front this far before the junction
JUNCTION_EDGE_GAP = 2.0
#: m kept between any two footprints at t=0: a contact in the first frame is an invalid scenario, not a collision.
#: 0.3 m asked for, plus 5 cm for the player placing a lane position a little differently from the plan's samples.
START_CLEARANCE = 0.35
#: m a start may be moved along its path to clear another entity
MAX_START_SHIFT = 30.0
#: the fastest a party may drive, as a multiple of its category's cruise speed, to come from the side of the AV the
#: report puts it (a cyclist overtaking a turning AV from behind at 2 x 3 m/s is still an ordinary cyclist)
MAX_SPEED_FACTOR = 2.0
#: m beside the AV's lane a party pulling into the road behind the AV starts (a driveway, a parking lot's exit)
PULL_IN_RUN = 10.0
#: m between its front and the AV's rear where it turns in (it then runs along the AV's side into its rear corner)
PULL_IN_BEHIND = 2.0


class Planner:
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

    # ------------------------------------------------------------------------------------------ schedules
    # ------------------------------------------------------------------------------------------ ego
    def _ego_lane_index(self, n: int, allowed: list[int]) -> tuple[int, str]:
        try:
            idx, why = ego_lane(self.sketch, n)
        except InputError:
            idx, why = 0, "lane relations exceed the lanes; leftmost"
        if allowed and idx not in allowed:
            idx = min(allowed, key=lambda a: (abs(a - idx), a))
            why += f"; moved to lane {idx} which allows the AV's turn"
        return idx, why

    def _ego_track(self) -> tuple[Track, int, float, float]:
        """(track, lane index, d of the junction entry (or None-like inf), lane width)."""
        site = self.site
        if isinstance(site, JunctionSite):
            turn = first_turn(self.sketch.ego.actions)
            allowed = site.ego.lanes_turning(turn) or site.ego.lanes_turning("straight") or \
                list(range(len(site.ego.lanes)))
            if not site.ego.lanes_turning(turn):
                self.choices["ego_turn_relaxed"] = f"{turn} -> not available here"
                turn = "straight" if site.ego.lanes_turning("straight") else next(
                    t for t in ("right", "left", "uturn") if site.ego.lanes_turning(t))
            idx, why = self._ego_lane_index(len(site.ego.lanes), allowed)
            refs = self._through(site.ego.lanes[idx], turn)
            track = Track(self.net, refs)
            k_junction = next((k for k, r in enumerate(refs) if self.net.roads[r.road_id].in_junction), None)
            d_entry = float(track.d[np.nonzero(track.seg == k_junction)[0][0]]) if k_junction is not None \
                else track.length
            self.choices["ego_lane"] = {"index": idx, "lane_id": site.ego.lanes[idx].lane_id, "why": why,
                                        "turn": turn}
            ref = site.ego.lanes[idx]
        else:
            idx, why = self._ego_lane_index(len(site.lanes), [])
            ref = site.lanes[idx]
            track = Track(self.net, [ref])
            d_entry = math.inf
            self.choices["ego_lane"] = {"index": idx, "lane_id": ref.lane_id, "why": why}
        s = self.net.roads[ref.road_id].length / 2
        self.lane_w = self.net.lane_width(ref.road_id, ref.lane_id, min(s, 10.0))
        self.ev.lane_w = self.lane_w
        return track, idx, d_entry, self.lane_w

    def _junction_ref(self, track: Track | LineTrack):
        """The first lane of a track inside a junction (the connecting lane a route must name), or None."""
        if not isinstance(track, Track):
            return None
        return next((r for r in track.refs if self.net.roads[r.road_id].in_junction), None)

    def _through(self, ref, turn: str, *, extra: int = 1, run_up: float = 150.0) -> list:
        """Lane refs: `ref` (preceded by its unique predecessors while it is shorter than `run_up` m: short
        approach roads on third-party maps), the connecting lane making `turn` (or any), then `extra` successors."""
        refs = [ref]
        length = self.net.lane_length(ref)
        for _ in range(4):
            if length >= run_up:
                break
            prev = [r for r in self.net.predecessors(refs[0]) if r not in refs]
            if len(prev) != 1:
                break
            refs.insert(0, prev[0])
            length += self.net.lane_length(prev[0])
        conns = [(self.net.turn_type(ref, c), c) for c in self.net.successors(ref)]
        pick = next((c for t, c in conns if t == turn), conns[0][1] if conns else None)
        if pick is None:
            return refs
        refs.append(pick)
        cur = pick
        for _ in range(extra):
            nxt = self.net.successors(cur)
            if not nxt:
                break
            cur = nxt[0]
            refs.append(cur)
        return refs

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

    # ---- nobody overlaps at t=0
    def _start_box(self, a: Actor, d0: float | None = None) -> np.ndarray:
        p = a.track.world(a.d0 if d0 is None else d0, a.lat0)
        return box_corners(p.x, p.y, p.h, a.length, a.width, a.cx)

    def _separate_at_start(self) -> None:
        """Keep every two footprints START_CLEARANCE apart at t=0. The placement rules each put one entity where it
        meets the AV, so two can land on one spot (two obstacles ahead, a parked car where a reversing car starts)
        or a party can start touching the AV (a reversing car whose run-up is shorter than a car length); the
        player would then start in a collision. Entities are settled one by one — the AV, the reported party, then
        the rest in planning order — each moved along its path just clear of those already settled."""
        target = self.sketch.collision.with_
        order = sorted(self.actors, key=lambda a: (a is not self.ego, a.name != target))
        settled: list[tuple[Actor, np.ndarray]] = []
        for actor in order:
            box = self._start_box(actor)
            hit = next((a for a, b in settled if boxes_gap(box, b) < START_CLEARANCE - 1e-6), None)
            if hit is not None and not (isinstance(actor.track, Track) and self._shift_start(actor, hit, settled)):
                self.choices.setdefault("start_overlap", []).append(f"{hit.name}-{actor.name}")
            settled.append((actor, self._start_box(actor)))

    def _shift_start(self, actor: Actor, hit: Actor, settled: list[tuple[Actor, np.ndarray]]) -> bool:
        """Move `actor` along its path by the smallest distance that clears the settled footprints, away from `hit`
        first, never past the AV (a party reported behind it stays behind). A party reported to touch the AV must
        still do so later in the plan; when no shift allows that, the smallest clearing one is taken and noted."""
        def lon(box: np.ndarray, of: np.ndarray, h: float) -> float:
            """How far the centre of `box` lies ahead of the centre of `of` along heading h."""
            c, ref = box.mean(axis=0), of.mean(axis=0)
            return float((c[0] - ref[0]) * math.cos(h) + (c[1] - ref[1]) * math.sin(h))

        own_h = actor.track.world(actor.d0, actor.lat0).h
        away = -1.0 if lon(self._start_box(hit), self._start_box(actor), own_h) > 0 else 1.0
        ego_box, ego_h = self._start_box(self.ego), self.ego.track.world(self.ego.d0).h
        side = math.copysign(1.0, lon(self._start_box(actor), ego_box, ego_h))
        contact = self.sketch.collision.with_ == actor.name
        d_orig, fallback = actor.d0, None
        for mag in np.arange(0.25, MAX_START_SHIFT + 1e-9, 0.25):
            for sign in (away, -away):
                d = d_orig + sign * float(mag)
                if not 0.0 <= d <= actor.track.length:
                    continue
                box = self._start_box(actor, d)
                if any(boxes_gap(box, b) < START_CLEARANCE for _, b in settled) or \
                        lon(box, ego_box, ego_h) * side < 0:
                    continue
                if contact:
                    actor.d0 = d
                    gap, _ = predicted_gap(self.actors, actor.name, self.horizon)
                    actor.d0 = d_orig
                    if gap > 0.0:
                        fallback = d if fallback is None else fallback
                        continue
                self._moved(actor, d, d_orig, "")
                return True
        if fallback is None:
            return False
        self._moved(actor, fallback, d_orig, "; the reported contact no longer happens in the plan")
        return True

    def _moved(self, actor: Actor, d: float, d_orig: float, why: str) -> None:
        actor.d0 = d
        actor.notes.append(f"start moved {d - d_orig:+.2f} m along its path: it overlapped another entity at "
                           f"t=0{why}")
        self.ev.check_lane_changes(actor)
        if actor.name in self.choices.get("parties", {}):
            self.choices["parties"][actor.name]["start_d"] = round(d, 2)
        elif actor.name in self.choices.get("obstacles", {}):
            self.choices["obstacles"][actor.name]["d"] = round(d, 2)
            self.choices["obstacles"][actor.name]["note"] = actor.notes[-1]

    def _note_reported_sides(self) -> None:
        """Every party whose start does not read as its reported position (R1-R7 + lane, by the one definition in
        analysis.features.derived_position; a crossing party by where it stands) says so, and why, in its notes."""
        for p in self.sketch.npcs:
            actor = next((a for a in self.actors if a.name == p.id), None)
            if actor is None:
                continue
            crossing = p.actions[:1] == "m"
            got = start_position(self.ego, actor, by_place=crossing)
            want = reported_code(p.position, p.lane)
            if got == want:
                continue
            actor.notes.append(f"starts at {'/'.join(x for x in got if x)} by its start pose (reported "
                               f"{'/'.join(x for x in want if x)}): {self._side_reason(p, actor, got, crossing)}")
            self.choices["parties"].setdefault(p.id, {})["notes"] = actor.notes

    def _side_reason(self, p: Party, actor: Actor, got: tuple[str, str | None], crossing: bool) -> str:
        """Why a party cannot start where the report puts it (see _note_reported_sides)."""
        travel = float(np.max(self.ego_d[self.ego_t <= self.T + 2.0 + 1e-9])) if len(self.ego_d) else 0.0
        if crossing and got[0] == p.position:
            return "a crossing party waits beside the road; the lane reported is the one it crosses"
        if crossing and p.position == "R6" and travel > 1.0:
            if self._reversing_time(self.T) is not None:
                return (f"the AV moves {travel:.0f} m forward before it backs into the party, which crosses behind "
                        "where it reverses: ahead of the AV's start")
            return (f"the AV drives {travel:.0f} m to where the party pulls in behind it: the party waits beside "
                    "the road ahead of the AV's start and pulls in once the AV has passed")
        if got[0] == p.position and any(n.startswith("lateral offset") for n in actor.notes):
            return ("no lane change is reported and its first move comes too late to drift toward the AV, so its "
                    "whole path runs beside the AV's box for the reported contact, within a lane half-width of the "
                    "AV's centreline")
        if p.position == "R2" and got[0] == "R7":
            return "an oncoming party on the approach facing the AV reads as R7 while within a road's width of its lane"
        if isinstance(actor.track, Track) and self.net.roads[actor.track.lane_at(actor.d0).road_id].in_junction:
            return "it meets the AV inside the junction and starts there (its run-up is shorter than its way in)"
        if any(n.startswith("no ") and "keeps the reported contact" in n for n in actor.notes):
            return "no re-timing keeps the reported contact from there"
        return "placed where it meets the AV at the conflict time"

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
            party.events[k] = EventPlan(ev.name, ev.code, ev.actions,
                                        Trigger("distance", round(float(gap[i]) + 0.3, 2), party.name, "ego"),
                                        ev.planned_time)
            party.notes.append(f"{ev.name} fires at {float(gap[i]) + 0.3:.1f} m from the AV")

    def _place_ego_default(self) -> None:
        ego = self.ego
        if ego.d0:
            return
        run = float(np.max(self.ego_d[self.ego_t <= self.T + 1e-9])) if len(self.ego_d) else 0.0
        back = -float(np.min(self.ego_d))
        if math.isfinite(self.d_entry):
            ego.d0 = max(back + 2.0, self.d_entry - run - 8.0) if ego.v0 > 0 or run > 0 else \
                max(self._hold_front_d() - (ego.cx + ego.length / 2), 0.0)
        else:
            ego.d0 = min(max(40.0, back + 15.0), max(ego.track.length - run - 40.0, 5.0))
        self.choices["ego_start_d"] = round(ego.d0, 2)

    # ---- parties
    def _party_track(self, p: Party) -> tuple[Track | LineTrack | None, float, str]:
        """(track, lateral offset, mode) where mode says how the meeting is computed: 'cross' (paths meet) or
        'parallel' (same road) or 'line' (off-lane crossing, built later)."""
        site, ego = self.site, self.ego
        turn = first_turn(p.actions)
        rider = p.category in ("bicycle", "scooter", "pedestrian")
        if "m" in p.actions and p.actions.index("m") == 0:
            return None, 0.0, "line"
        if p.position in ("R1", "R2", "R3") and isinstance(site, JunctionSite):
            leg = {"R1": "left", "R2": "opposite", "R3": "right"}[p.position]
            ap = site.legs.get(leg)
            if ap is None:
                raise InputError(f"site has no {leg} leg for {p.id}", source=self.sketch.report_id,
                                 element=f"npcs.{p.id}.position")
            can = {t: ap.lanes_turning(t) for t in ("left", "right", "uturn", "straight")}
            idx = case1_lane(p.actions, len(ap.lanes), can_turn=can)
            if turn in can and can[turn] and idx not in can[turn]:
                idx = can[turn][0] if turn in ("left", "uturn") else can[turn][-1]
            if not can.get(turn):
                turn = "straight" if can["straight"] else next(t for t in ("right", "left", "uturn") if can[t])
            self.choices["parties"].setdefault(p.id, {})["lane"] = {"leg": leg, "road": ap.road_id, "index": idx,
                                                                   "lane_id": ap.lanes[idx].lane_id, "turn": turn}
            return Track(self.net, self._through(ap.lanes[idx], turn)), 0.0, "cross"
        if p.position == "R4" and isinstance(site, JunctionSite):
            return ego.track, 0.0, "exit"
        if p.position == "R7":
            return self._oncoming_track(p)
        # R5 / R6 (and R1–R4 on a road site: treated as ahead on the AV's road)
        n = len(site.ego.lanes) if isinstance(site, JunctionSite) else len(site.lanes)
        lanes = site.ego.lanes if isinstance(site, JunctionSite) else site.lanes
        pidx = party_lane(p, self.ego_idx, n) if p.position in ("R5", "R6") else self.ego_idx
        lat = 0.0
        if pidx == CURB or (rider and p.lane == "right" and pidx == n - 1 and pidx != self.ego_idx):
            pidx, lat = n - 1, -(self.lane_w / 2 + 0.9)
        elif rider and p.lane == "left" and self.ego_idx == 0:
            pidx, lat = 0, (self.lane_w / 2 + 0.6)
        elif p.lane == "left" and self.ego_idx == 0:
            lat = self.lane_w  # no lane to the left: ride the lane line / the oncoming lane's edge
        self.choices["parties"].setdefault(p.id, {})["lane"] = {"index": pidx, "lane_id": lanes[pidx].lane_id,
                                                               "lateral": round(lat, 2)}
        if isinstance(site, JunctionSite):
            ego_turn = self.choices["ego_lane"].get("turn", "straight")
            curb_rider = rider and lat != 0.0
            want = turn if (turn != "straight" or curb_rider) else ego_turn if pidx == self.ego_idx else "straight"
            refs = self._through(lanes[pidx], want)
            if turn != "straight" and not any(t == turn for t, _ in dict(site.ego.turns).get(lanes[pidx], ())):
                # the party turns from a lane that has no such turn (a left turn from the right lane, across the
                # AV): cut across to the lane that does
                line = self._cut_across(site, lanes[pidx], turn)
                if line is not None:
                    return line, 0.0, "cross"
            differ = want != ego_turn
            crossing = differ and (pidx != self.ego_idx or rider)
            return Track(self.net, refs), lat, "cross" if crossing else "parallel"
        return Track(self.net, [lanes[pidx]]), lat, "parallel"

    def _cut_across(self, site: JunctionSite, ref, turn: str) -> LineTrack | None:
        """A path from lane `ref` that merges, before the junction, into the connection of the nearest lane that
        can make `turn`, then follows it out (realised as a FollowTrajectoryAction)."""
        idx = [i for i in site.ego.lanes_turning(turn)]
        if not idx:
            return None
        src = site.ego.lanes[idx[0] if turn in ("left", "uturn") else idx[-1]]
        a = Track(self.net, [ref])
        b = Track(self.net, self._through(src, turn))
        cut = max(a.length - 12.0, 0.0)
        pa = a.world_array(np.arange(0.0, cut, 1.0))
        start_b = b.project(float(a.x[-1]), float(a.y[-1]))
        pb = b.world_array(np.arange(start_b, b.length, 1.0))
        return LineTrack([(float(x), float(y)) for x, y, _ in pa] + [(float(x), float(y)) for x, y, _ in pb])

    def _oncoming_track(self, p: Party) -> tuple[Track, float, str]:
        site = self.site
        if isinstance(site, RoadSite):
            onc = site.oncoming
            ego_ref = site.lanes[self.ego_idx]
        else:
            ego_ref = site.ego.lanes[self.ego_idx]
            road = ego_ref.road_id
            s = 1.0
            ids = [lid for lid in self.net.lane_ids(road, s)
                   if self.net.lane_forward(road, lid, s) != self.net.lane_forward(road, ego_ref.lane_id, s)]
            from ..road import LaneRef

            onc = tuple(sorted((LaneRef(road, ego_ref.section, lid) for lid in ids), key=lambda r: abs(r.lane_id)))
        if p.lane == "same" or not onc:
            self.choices["parties"].setdefault(p.id, {})["lane"] = {"lane_id": ego_ref.lane_id, "wrong_way": True}
            return Track(self.net, [ego_ref], reverse=True), 0.0, "parallel"
        self.choices["parties"].setdefault(p.id, {})["lane"] = {"lane_id": onc[0].lane_id}
        return Track(self.net, [onc[0]]), 0.0, "parallel"

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

    def _retime_to_reported_side(self, p: Party, actor: Actor, build) -> Actor:
        """The party that touches the AV would start on the wrong side of it (a side-swiping car reported behind
        the AV starting ahead of it, a cyclist reported coming from behind starting ahead, a car reported beside it
        at the light starting behind): keep the meeting, change how it gets there. A moving party drives faster
        (to come from behind) or slower (to be caught up with), up to MAX_SPEED_FACTOR of its cruise speed; a
        standing one moves off later or earlier. The first candidate that starts on the reported side and still
        touches the AV in the plan wins; without one the original plan stays and the manifest says why."""
        ego = self.ego
        saved = (ego.d0, self.choices.get("ego_start_d"))
        base_gap, _ = predicted_gap([ego, actor], actor.name, self.horizon)
        behind = p.position == "R6"
        if actor.v0 > 0:
            steps = np.arange(0.1, MAX_SPEED_FACTOR - 1.0 + 1e-9, 0.1) if behind else np.arange(0.1, 0.71, 0.1)
            cands = [("speed", round(actor.v0 * (1.0 + f if behind else 1.0 - f), 2)) for f in steps]
        else:
            cands = [("shift", round(-s if behind else s, 2)) for s in np.arange(0.25, self.T + 1e-9, 0.25)]
        chosen = None
        for kind, value in cands:
            ego.d0 = saved[0]
            cand = build(speed=value) if kind == "speed" else build(shift=value)
            gap, _ = predicted_gap([ego, cand], cand.name, self.horizon)
            if on_reported_side(ego, cand, p.position) and gap <= max(base_gap, 0.0):
                chosen = (kind, value)
                break
        ego.d0 = saved[0]
        if saved[1] is not None:
            self.choices["ego_start_d"] = saved[1]
        if chosen is None:
            actor = build()
            how = f"no speed up to {MAX_SPEED_FACTOR:g}x its own" if actor.v0 > 0 else "no other time to move off"
            actor.notes.append(f"{how} starts it {'behind' if behind else 'beside or ahead of'} the AV (reported "
                               f"{p.position}) and keeps the reported contact")
            return actor
        kind, value = chosen
        actor = build(speed=value) if kind == "speed" else build(shift=value)
        if kind == "speed":
            actor.notes.append(f"speed {value:g} m/s so that it starts {'behind' if behind else 'ahead of'} the AV "
                               f"(reported {p.position}) and still meets it")
        else:
            actor.notes.append(f"moves off {abs(value):g} s {'earlier' if value < 0 else 'later'} so that it starts "
                               f"{'behind' if behind else 'beside or ahead of'} the AV (reported {p.position}) and "
                               "still meets it")
        return actor

    def _party_routes(self, p: Party, actor: Actor) -> dict[str, RouteAct]:
        if not isinstance(actor.track, Track) or len(actor.track.refs) < 2:
            return {}
        out = {}
        for c in p.actions:
            if c in TURN_CODES:
                mid_ref = self._junction_ref(actor.track) or actor.track.refs[1]
                mid = self.net.lane_centerline(mid_ref.road_id, mid_ref.lane_id, 0.5, section=mid_ref.section)
                s_mid = float(mid[len(mid) // 2, 2])
                end = actor.track.lane_pose(actor.track.length - 5.0)
                out[c] = RouteAct(f"{actor.name}_route", (
                    LanePose(mid_ref.road_id, mid_ref.lane_id, round(s_mid, 3)),
                    LanePose(end.road_id, end.lane_id, end.s)))
        return out

    def _through_route(self, actor: Actor) -> RouteAct | None:
        """The route of a party whose planned path passes a junction without a turn of its own (assigned at Init):
        the connecting lane it takes and the end of its path. Without it each player would pick its own branch
        there (esmini picks at random, ours the straightest), and the reported path would be left to chance."""
        mid_ref = self._junction_ref(actor.track)
        if mid_ref is None:
            return None
        mid = self.net.lane_centerline(mid_ref.road_id, mid_ref.lane_id, 0.5, section=mid_ref.section)
        end = actor.track.lane_pose(actor.track.length - 5.0)
        return RouteAct(f"{actor.name}_route", (
            LanePose(mid_ref.road_id, mid_ref.lane_id, round(float(mid[len(mid) // 2, 2]), 3)),
            LanePose(end.road_id, end.lane_id, end.s)))

    def _ego_d_at(self, T: float) -> float:
        return float(np.interp(T, self.ego_t, self.ego_d))

    def _stop_line_d(self) -> float | None:
        """Distance along the AV's path of the first stop line (traffic light or stop sign of the map) that governs
        its lane on the approach to the junction, or None (no junction ahead, or an uncontrolled lane)."""
        track = self.ego.track
        if not math.isfinite(self.d_entry) or not isinstance(track, Track):
            return None
        k = next((k for k, r in enumerate(track.refs) if self.net.roads[r.road_id].in_junction), None)
        if not k:
            return None
        ref = track.refs[k - 1]
        road = self.net.roads[ref.road_id]
        sigs = approach_signals(self.net, road, self.net.lane_forward(ref.road_id, ref.lane_id), [ref.lane_id])
        on = track.seg == k - 1
        if not sigs or on.sum() < 2:
            return None
        order = np.argsort(track.s[on])
        return min(float(np.interp(sg.s, track.s[on][order], track.d[on][order])) for sg in sigs)

    def _hold_front_d(self) -> float:
        """Where a standing AV's front bumper is held: STOP_LINE_GAP before the stop line of its lane, else
        JUNCTION_EDGE_GAP before the junction. (The map's stop line, not the junction entry: the map draws the
        line a metre or so before the junction, and an AV standing at a red light is behind it.)"""
        line = self._stop_line_d()
        if line is not None:
            self.choices["ego_stop_line_d"] = round(line, 2)
            return line - STOP_LINE_GAP
        return self.d_entry - JUNCTION_EDGE_GAP

    def _ego_in_junction(self) -> bool:
        """Whether the report has the standing AV inside the junction. The sketch has no field for it: an AV held
        by a red light, a stop sign or an unknown control stood at the line; only one that had a green or yellow
        light (waiting inside to turn, or caught in the junction) may stand past it."""
        return self.sketch.signal_state in ("green", "yellow")

    def _meet_crossing(self, actor: Actor, T: float, primary: bool, t: np.ndarray, dn: np.ndarray) -> None:
        ego = self.ego
        pts = actor.track.world_array(actor.track.d, actor.lat0)
        # first meeting of the two paths beyond the ego's earliest possible start
        e = ego.track
        dist = np.hypot(e.x[:, None] - pts[None, ::2, 0], e.y[:, None] - pts[None, ::2, 1])
        i, j = np.unravel_index(np.argmin(dist), dist.shape)
        close = np.argwhere(dist < 1.0)
        if close.size:
            k = close[np.argmin(e.d[close[:, 0]])]
            i, j = int(k[0]), int(k[1])
        d_e_star, d_n_star = float(e.d[i]), float(actor.track.d[::2][j])
        if dist[i, j] >= 1.0:
            actor.notes.append(f"paths do not cross; nearest approach {dist[i, j]:.1f} m")
        # the conflict point on the ego's path: its front reaches it; on the party's, its centre
        front = ego.cx + ego.length / 2
        if primary:
            travelled = self._ego_d_at(T)
            if travelled > 1.0:
                ego.d0 = max(d_e_star - front - travelled, 0.0)
                if ego.d0 == 0.0:
                    actor.notes.append("AV run-up shortened by the map")
            else:  # the AV stands: the party comes to it
                ego.d0 = max(min(self._hold_front_d() - front, d_e_star - front - 1.0), 0.0)
                at_line = ego.track.world(ego.d0 + front)
                miss = float(np.min(np.hypot(pts[:, 0] - at_line.x, pts[:, 1] - at_line.y)))
                if self.sketch.collision.with_ == actor.name and dist[i, j] < 1.0 and miss > 3.0 and \
                        self._ego_in_junction():
                    # the party's path crosses inside the junction, far from the stop line, yet they touched:
                    # the AV stood past the line, its front in the party's path
                    ego.d0 = max(d_e_star - front + actor.width / 2 - 0.3, 0.0)
                    actor.notes.append("AV standing inside the junction, its front in the party's path")
            self.choices["ego_start_d"] = round(ego.d0, 2)
        t_e = time_to_reach(self.ego_t, self.ego_d, d_e_star - front - ego.d0)
        at_av = False
        if t_e is None:
            # the AV never gets there: meet at the AV itself, where it is at the conflict time
            stand = ego.d0 + self._ego_d_at(T) + front
            wp = ego.track.world(stand)
            d_n_star = float(actor.track.project(wp.x, wp.y)) if isinstance(actor.track, Track) else d_n_star
            t_e = T
            near = actor.track.world(d_n_star, actor.lat0)
            at_av = math.hypot(near.x - wp.x, near.y - wp.y) >= 1.0
        reach = float(np.interp(t_e, t, dn))
        actor.d0 = d_n_star - reach - actor.cx
        if actor.d0 < 0:
            t_party = time_to_reach(t, dn, d_n_star - actor.cx)
            if primary and t_party is not None and self._ego_d_at(t_e) > 1.0:
                # the party's road is too short for the planned run-up: meet earlier, moving the AV closer
                t_e = t_party
                ego.d0 = max(d_e_star - front - self._ego_d_at(t_e), 0.0)
                self.choices["ego_start_d"] = round(ego.d0, 2)
                actor.notes.append(f"short approach: meeting at {t_e:.1f} s instead of {T:.1f} s")
            else:
                actor.notes.append(f"party start clamped ({actor.d0:.1f} m before its path)")
            actor.d0 = 0.0
        if (dist[i, j] >= 1.0 or at_av) and self.sketch.collision.with_ == actor.name and actor.events:
            # an AV that stays behind its line is met where it stands: the party swings wide toward it (up to a
            # lane and a half, as a turning truck's corner cut does)
            self._graze(actor, d_n_star, t_e, limit=1.5 * self.lane_w if at_av else 4.0)
        self._conflict_times = getattr(self, "_conflict_times", {})
        self._conflict_times[actor.name] = t_e

    def _graze(self, actor: Actor, d_n_star: float, t_e: float, *, limit: float = 4.0) -> None:
        """The paths pass side by side but the report says they touched: bend the party's path toward the AV over
        the 15 m before the meeting point, by at most `limit` m."""
        ego = self.ego
        e_pose = ego.track.world(ego.d0 + self._ego_d_at(t_e) + ego.cx)
        p_pose = actor.track.world(d_n_star)
        vx, vy = e_pose.x - p_pose.x, e_pose.y - p_pose.y
        left = -math.sin(p_pose.h) * vx + math.cos(p_pose.h) * vy
        need = abs(left) - (ego.width / 2 + actor.width / 2) + 0.3
        if need <= 0:
            return
        shift = math.copysign(min(need, limit), left)
        # Realised as a trajectory: the party's own path, bent toward the AV over the 15 m before the meeting
        # point. (A LaneOffsetAction would do, but its sign is tied to the road's +t and flips when the path
        # turns onto a road drawn the other way; world points are unambiguous.)
        start = actor.d0
        d_lo = max(start, d_n_star - 15.0)
        ds = np.arange(start, actor.track.length, 2.0)
        u = np.clip((ds - d_lo) / max(d_n_star - d_lo, 1.0), 0.0, 1.0)
        # the party's own lane changes, turned from time into distance along its path, stay in the bent path
        tp, _, dp = actor.profile(self.horizon)
        t_of_d = np.interp(ds - start, dp, tp) if dp[-1] > dp[0] else np.zeros_like(ds)
        own = lateral_profile(actor.lat0, actor.lat_steps, t_of_d)
        actor.lat_steps = []
        lat = own + shift * (0.5 - 0.5 * np.cos(math.pi * u))
        pts = actor.track.world_array(ds, lat)
        line = LineTrack([(float(x), float(y)) for x, y, _ in pts])
        actor.track, actor.d0, actor.lat0, actor.world_start = line, 0.0, 0.0, True
        traj = TrajectoryAct(f"{actor.name}_path", line.vertices(0.0))
        ev = actor.events[0]
        acts = tuple(a for a in ev.actions if not isinstance(a, (RouteAct, LaneChangeAct, LaneOffsetAct))) + (traj,)
        actor.events[0] = EventPlan(ev.name, ev.code, acts, ev.trigger, ev.planned_time)
        for k in range(1, len(actor.events)):  # later turns and lane changes are already in the bent path
            e = actor.events[k]
            if any(isinstance(a, (RouteAct, LaneChangeAct, LaneOffsetAct)) for a in e.actions):
                rest = tuple(a for a in e.actions if not isinstance(a, (RouteAct, LaneChangeAct, LaneOffsetAct)))
                actor.events[k] = EventPlan(e.name, e.code, rest or (SpeedAct(
                    round(float(np.interp(e.planned_time, *actor.profile(self.horizon)[:2])), 3),
                    self.D.shape, self.D.dimension, self.D.dyn_value),), e.trigger, e.planned_time)
        actor.notes.append(f"paths pass {abs(left):.1f} m apart: bent {shift:+.2f} m toward the AV before the "
                           "meeting point (reported contact)")

    def _meet_parallel(self, p: Party, actor: Actor, T: float, t: np.ndarray, dn: np.ndarray, mode: str) -> None:
        ego = self.ego
        if self.ego.d0 == 0.0 and not getattr(self, "_ego_placed", False):
            self._place_ego_default()
            self._ego_placed = True
        de_T = ego.d0 + self._ego_d_at(T)
        lat_conflict = bool(set(p.actions) & set("fg")) or p.lane in ("left", "right") or p.position == "R7"
        ego_front, ego_rear = ego.cx + ego.length / 2, ego.cx - ego.length / 2
        p_front, p_rear = actor.cx + actor.length / 2, actor.cx - actor.length / 2
        reversing = actor.track.reverse or p.position == "R7"
        if p.position == "R7":
            # front to front (oncoming): party reference point ahead of the ego's front by both front overhangs
            target = de_T + ego_front + p_front
        elif lat_conflict and p.lane == "same" and p.position == "R6":
            target = de_T + ego_rear - p_front + 1.5     # pulls out of the AV's lane and clips its rear corner
        elif lat_conflict and p.lane == "same":
            target = de_T + ego_front - p_rear - 1.0     # changes out ahead of the AV, which clips its rear
        elif lat_conflict:
            target = de_T + (1.0 if p.position == "R5" else -1.0)
        elif p.position == "R6":
            target = de_T + ego_rear - p_front           # its front at the AV's rear
        else:
            target = de_T + ego_front - p_rear           # its rear at the AV's front
        wp = ego.track.world(target)
        d_target = actor.track.project(wp.x, wp.y)
        travelled = float(np.interp(T, t, dn))
        actor.d0 = d_target - travelled
        if p.id != self.sketch.collision.with_ and p.position in ("R5", "R6") and not reversing:
            self._keep_reported_side(p, actor)
        if actor.d0 < 0 or actor.d0 > actor.track.length:
            actor.notes.append(f"start {actor.d0:.1f} m outside its lane; clamped")
            actor.d0 = float(np.clip(actor.d0, 0.0, actor.track.length))
        if lat_conflict and self.sketch.collision.with_ == p.id and not set(p.actions) & set("fgm"):
            # a pass or graze without a lane change: drive close enough to touch (side-swipe reported). Measured
            # in the AV's frame at the meeting, so it holds for neighbour lanes, curb riders and oncoming lanes.
            if p.lane == "same" and p.position != "R7":
                return
            # where the AV is across its lane at T: its own lane change toward the party closes part of the gap
            # (or all of it), and the party keeps to its lane as far as it can
            t_e = self.ego_t
            ego_lat_T = float(np.interp(T, t_e, lateral_profile(ego.lat0, ego.lat_steps, t_e)))
            e_pose = ego.track.world(de_T, ego_lat_T)
            p_pose = actor.track.world(d_target, actor.lat0)
            vx, vy = p_pose.x - e_pose.x, p_pose.y - e_pose.y
            rel = -math.sin(e_pose.h) * vx + math.cos(e_pose.h) * vy      # party left of the AV: > 0
            if abs(rel) < 1e-6:
                rel = 1e-6 if p.lane == "left" else -1e-6
            desired = math.copysign(ego.width / 2 + actor.width / 2 - 0.3, rel)   # 0.3 m of overlap: they touch
            if abs(rel) > abs(desired):
                same_dir = math.cos(p_pose.h - e_pose.h) >= 0.0
                delta = (desired - rel) * (1.0 if same_dir else -1.0)
                if not self._drift(actor, delta, T):
                    actor.lat0 += delta
                    actor.notes.append(f"lateral offset {actor.lat0:.2f} m toward the AV (reported contact)")

    def _drift(self, actor: Actor, delta: float, T: float) -> bool:
        """Let the party start in its own lane and drift `delta` m toward the AV (a LaneOffsetAction beside its first
        event's action, sinusoidal at the configured lateral acceleration), done before the meeting at T: its start
        then reads as the lane the report gives. False (nothing changed) when the first event comes too late, or the
        party already has a lane offset of its own."""
        if not isinstance(actor.track, Track) or not actor.events or \
                any(isinstance(a, LaneOffsetAct) for ev in actor.events for a in ev.actions):
            return False
        acc = self.D.lane_offset_max_lat_acc
        # the player's sinusoidal offset takes pi * sqrt(|delta| / (2 a_lat)) s at peak lateral acceleration a_lat
        dur = math.pi * math.sqrt(abs(delta) / (2.0 * acc))
        first = actor.events[0]
        if first.planned_time + dur > T - 0.5:
            return False
        target = actor.lat0 + delta
        act = LaneOffsetAct(round(self.ev.offset_t(actor, target), 3), acc)
        actor.events[0] = EventPlan(first.name, first.code, first.actions + (act,), first.trigger, first.planned_time)
        actor.lat_steps.append(LateralStep(first.planned_time, delta, round(dur, 2)))
        actor.notes.append(f"drifts {delta:+.2f} m toward the AV from its lane over {dur:.1f} s (reported contact)")
        return True

    def _keep_reported_side(self, p: Party, actor: Actor) -> None:
        """A party reported behind (R6) or ahead of (R5) the AV that did not touch it starts there, clear of it:
        meeting the AV at the conflict time alone would start a follower that stops early ahead of the AV."""
        ego = self.ego
        pose = actor.track.world(actor.d0, actor.lat0)
        d_on_ego = float(ego.track.project(pose.x, pose.y))
        if p.position == "R6":   # its front behind the AV's rear
            shift = min(ego.d0 + ego.cx - ego.length / 2 - START_CLEARANCE - (actor.cx + actor.length / 2) - d_on_ego,
                        0.0)
        else:                    # its rear ahead of the AV's front
            shift = max(ego.d0 + ego.cx + ego.length / 2 + START_CLEARANCE - (actor.cx - actor.length / 2) - d_on_ego,
                        0.0)
        if shift:
            actor.d0 += shift
            actor.notes.append(f"start moved {shift:+.1f} m: reported {'behind' if shift < 0 else 'ahead of'} the AV")

    def _release_if_needed(self, actor: Actor) -> None:
        """Keep a start on the map; nothing else to do: events are timed from the plan."""
        actor.d0 = round(float(np.clip(actor.d0, 0.0, actor.track.length)), 3)

    def _plan_crossing(self, p: Party, T: float, cruise: float, primary: bool) -> None:
        """`m` first: a path perpendicular to the AV's lane through the point the AV's front reaches at T. A party
        reported behind the AV (R6) crosses behind it instead: where the reversing AV's rear comes back to, or
        (an AV going forward or standing) into the road behind it and along its side (`_pull_in`)."""
        ego = self.ego
        if not getattr(self, "_ego_placed", False) and ego.d0 == 0.0:
            self._place_ego_default()
            self._ego_placed = True
        front = ego.cx + ego.length / 2
        dims = self.D.dims(p.category)
        side = "left" if (p.lane == "left" or p.position in ("R1", "R2")) else "right"
        v = cruise
        # a rider or pedestrian, or a party reported on the AV's road (R5-R7), waits within PULL_IN_RUN m of the
        # AV's lane: beside the road, not beyond it
        rider = p.category in ("pedestrian", "bicycle", "scooter")
        max_before = PULL_IN_RUN if rider or p.position in ("R5", "R6", "R7") else 20.0
        t_rev = self._reversing_time(T)
        is_collision = self.sketch.collision.with_ == p.id
        if p.position == "R6" and t_rev is None and is_collision:
            line, reach = self._pull_in(p, T, side)
            before = reach
        else:
            if p.position == "R6" and not is_collision:
                # a bystander reported behind the AV crosses behind where the AV is at T, clear of it
                d_p = ego.d0 + max(self._ego_d_at(T), 0.0) + ego.cx - ego.length / 2 - dims[1] / 2 - \
                    PULL_IN_BEHIND
            elif p.position == "R6":
                # the AV backs into it: it crosses just behind where the AV's rear is once it reverses (half a
                # metre: the AV, not the pedestrian, closes the gap)
                T = t_rev
                d_p = ego.d0 + self._ego_d_at(T) + ego.cx - ego.length / 2 - 0.5
            else:
                travelled = self._ego_d_at(T)
                if travelled < 0.5:  # the AV stands: cross right in front of it
                    travelled = 0.0
                # moving AV: the party's centre crosses the point the AV's front reaches at T; standing AV: the
                # party's side passes 0.3 m into the AV's front
                d_p = ego.d0 + travelled + front + (dims[0] / 2 - 0.3 if travelled == 0.0 else 0.0)
                if p.position in ("R4",) and math.isfinite(self.d_entry):
                    d_p = max(d_p, self.d_entry + 4.0)
            px = ego.track.world(d_p)
            before = min(v * T, max_before)
            line = perpendicular(px.x, px.y, px.h, side, before, 12.0)
            reach = before
        actor = self._actor(p.id, p.category, line)
        actor.world_start = True
        delay = max(0.0, T - reach / v) if v > 0 else 0.0
        moving = p.start == "moving" and delay == 0.0
        actor.v0 = v if moving else 0.0
        traj = TrajectoryAct(f"{p.id}_crossing", line.vertices())
        sched = self.ev.schedule(actor, p.actions, t_first=round(delay, 2), t_critical=T + 2.0)
        self.ev.apply(actor, sched, cruise=v, crossing=traj)
        if delay > 0 and actor.events:
            # released by the AV's approach: the distance at the planned release time (+0.5 m so it fires)
            first = actor.events[0]
            ego_pose = ego.track.world(ego.d0 + self._ego_d_at(delay))
            dist = math.hypot(ego_pose.x - line.x[0], ego_pose.y - line.y[0])
            ego_pose_before = ego.track.world(ego.d0 + self._ego_d_at(max(delay - 0.5, 0.0)))
            dist_before = math.hypot(ego_pose_before.x - line.x[0], ego_pose_before.y - line.y[0])
            if dist_before > dist + 0.05:
                actor.events[0] = EventPlan(first.name, first.code, first.actions,
                                            Trigger("distance", round(dist + 0.5, 2), actor.name, "ego"), delay)
        self.actors.append(actor)
        self.choices["parties"].setdefault(p.id, {}).update({
            "mode": "crossing", "side": side, "run_up": round(before, 2), "release_time": round(delay, 2),
            "speed": v, "conflict_time": round(T, 2), "notes": actor.notes})

    def _reversing_time(self, T: float) -> float | None:
        """When the AV backs up (at or after T, at nine tenths of its reversing speed), or None if it never does."""
        _, v, _ = speed_profile(self.ego.v0, self.ego.speed_steps, self.horizon)
        if v.min() >= -0.1:
            return None
        k = np.nonzero((v <= 0.9 * v.min()) & (self.ego_t >= T - 1e-9))[0]
        return float(self.ego_t[k[0]]) if k.size else None

    def _pull_in(self, p: Party, T: float, side: str) -> tuple[LineTrack, float]:
        """(path, its length up to the contact) of a party that comes out beside the road behind the AV (a
        driveway, a parking lot) into the road and along the AV's side: it turns in PULL_IN_BEHIND m behind the
        AV's rear at T, runs on the side of its later lane change (else the side it came from), its box 0.3 m
        into the AV's, and touches the AV's rear corner."""
        ego = self.ego
        at = ego.track.world(ego.d0 + max(self._ego_d_at(T), 0.0))
        kind = "pedestrian" if p.category in self.D.raw["pedestrian_category"] else "vehicle"
        width, length = self.D.dims(p.category)[:2]
        p_front = center_x(kind, length) + length / 2
        later = p.actions[1:]
        pass_side = "left" if "f" in later else "right" if "g" in later else side
        lat_in = (1.0 if side == "left" else -1.0) * PULL_IN_RUN
        lat_run = (1.0 if pass_side == "left" else -1.0) * (ego.width / 2 + width / 2 - 0.3)
        rear = ego.cx - ego.length / 2
        lon_in = rear - p_front - PULL_IN_BEHIND
        lon_end = ego.cx + ego.length / 2 + 12.0
        c, s = math.cos(at.h), math.sin(at.h)
        pts = [(at.x + lon * c - lat * s, at.y + lon * s + lat * c)
               for lon, lat in ((lon_in, lat_in), (lon_in, lat_run), (lon_end, lat_run))]
        return LineTrack(pts), abs(lat_run - lat_in) + PULL_IN_BEHIND

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

    # ---- mission
    def _ego_mission(self, routes: dict) -> None:
        ego = self.ego
        # the goal lies a little beyond where the AV meets the party (not where its storyboard would end up: a
        # planner must be able to reach it well within the time limit)
        conflict = ego.d0 + max(self._ego_d_at(self.T), 0.0) + ego.cx + ego.length / 2
        goal_d = min(conflict + self.D.timing.ego_goal_beyond_conflict, ego.track.length - 2.0)
        if math.isfinite(self.d_entry):
            goal_d = max(goal_d, min(self.d_entry + 40.0, ego.track.length - 2.0))
        # time for a planner at the AV's cruise speed to get there, with margin (never below the configured limit)
        cruise = self.D.speed("ego")
        self.time_limit = float(max(self.D.timing.time_limit, math.ceil(1.5 * (goal_d - ego.d0) / cruise + 10.0)))
        start = ego.track.lane_pose(ego.d0)
        wps: list = [LanePose(start.road_id, start.lane_id, start.s)]
        mid_ref = self._junction_ref(ego.track)
        if mid_ref is not None:
            mid = self.net.lane_centerline(mid_ref.road_id, mid_ref.lane_id, 0.5, section=mid_ref.section)
            wps.append(LanePose(mid_ref.road_id, mid_ref.lane_id, round(float(mid[len(mid) // 2, 2]), 3)))
        goal = ego.track.lane_pose(goal_d)
        wps.append(LanePose(goal.road_id, goal.lane_id, goal.s, 0.0, goal.x, goal.y, goal.h))
        ego.route = RouteAct("ego_route", tuple(wps))
        self.goal = LanePose(goal.road_id, goal.lane_id, goal.s, 0.0, goal.x, goal.y, goal.h)
        # the ego's own turn events reuse its mission route
        ego.events = [EventPlan(ev.name, ev.code, tuple(ego.route if isinstance(a, RouteAct) and
                                                        a.name == EGO_ROUTE_PLACEHOLDER else a for a in ev.actions),
                                ev.trigger, ev.planned_time) for ev in ego.events]
        self.choices["goal"] = {"road": goal.road_id, "lane": goal.lane_id, "s": goal.s}
