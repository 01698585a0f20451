"""Making the reported interaction happen: a party's start solved so that it meets the AV at the conflict time,
whether the paths cross (crossings, turns, grazes) or run side by side (rear-ends, passes, drifts).

One concept of the seed planner (`plan.Planner` combines them); the methods work on the planner's state."""

from __future__ import annotations

import math

import numpy as np

from ..sketch import Party
from .actor import Actor
from .kinematics import LateralStep, lateral_profile, speed_profile, time_to_reach
from .linetrack import LineTrack, perpendicular
from .model import EventPlan, LaneChangeAct, LaneOffsetAct, RouteAct, SpeedAct, TrajectoryAct, Trigger
from .plan_paths import PULL_IN_RUN, PULL_IN_BEHIND
from .track import Track


class Meeting:
    """Mixin of `plan.Planner` (where and when a party meets the AV)."""

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
            line = perpendicular(px.x, px.y, px.h, side, before, self._crossing_beyond(v))
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

    def _crossing_beyond(self, v: float) -> float:
        """How far a crossing runs on past the AV's path: at least 12 m, and long enough that the party is still on
        it when the run ends, even at twice its speed (the tree's speed mutations reach 1.5 times). What an
        entity does after its trajectory the standard leaves to the player, and players differ where the end lies
        beside the road: a crossing pedestrian made a car by the tree joined the sidewalk in ours and stopped at
        the junction, in esmini it joined the driving lane and drove on into the junction (25 m apart)."""
        return max(12.0, round(2.0 * max(v, 1.0) * self.horizon, 1))

    def _reversing_time(self, T: float) -> float | None:
        """When the AV backs up (at or after T, at nine tenths of its reversing speed), or None if it never does."""
        _, v, _ = speed_profile(self.ego.v0, self.ego.speed_steps, self.horizon)
        if v.min() >= -0.1:
            return None
        k = np.nonzero((v <= 0.9 * v.min()) & (self.ego_t >= T - 1e-9))[0]
        return float(self.ego_t[k[0]]) if k.size else None
