"""The AV's side of a plan: its lane and path, where a standing AV waits (stop line, junction edge), and its
mission (route through its path, goal beyond the conflict, time limit).

One concept of the seed planner (`plan.Planner` combines them); the methods work on the planner's state."""

from __future__ import annotations

import dataclasses

import math

import numpy as np

from ..errors import InputError
from ..mapdb.classify import approach_signals
from .constraints import first_turn
from .events import EGO_ROUTE_PLACEHOLDER
from .lanes import ego_lane
from .model import EventPlan, LanePose, RouteAct
from .sites import JunctionSite
from .track import Track

#: m between a standing AV's front bumper and the stop line that holds it
STOP_LINE_GAP = 1.0
#: m where the AV's lane has no stop line: its front this far before the junction
JUNCTION_EDGE_GAP = 2.0


class EgoPlanning:
    """Mixin of `plan.Planner` (the AV's path, waiting place and mission)."""

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
        ego.events = [dataclasses.replace(ev, actions=tuple(ego.route if isinstance(a, RouteAct) and
                                                            a.name == EGO_ROUTE_PLACEHOLDER else a
                                                            for a in ev.actions)) for ev in ego.events]
        self.choices["goal"] = {"road": goal.road_id, "lane": goal.lane_id, "s": goal.s}
