"""A party's path on the map and the routes that pin it: its track (own lane, oncoming, across, a pull-in),
the connecting lane through a junction, and the routes assigned for turns and for passing a junction.

One concept of the seed planner (`plan.Planner` combines them); the methods work on the planner's state."""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError
from ..sketch import Party
from .actor import Actor, center_x
from .constraints import first_turn
from .events import TURN_CODES
from .lanes import CURB, case1_lane, ego_lane, party_lane
from .linetrack import LineTrack
from .model import LanePose, RouteAct
from .sites import JunctionSite, RoadSite
from .track import Track

#: m beside the AV's lane a party pulling into the road behind the AV starts (a driveway, a parking lot's exit)
PULL_IN_RUN = 10.0
#: m between its front and the AV's rear where it turns in (it then runs along the AV's side into its rear corner)
PULL_IN_BEHIND = 2.0


class PartyPaths:
    """Mixin of `plan.Planner` (party paths and routes)."""

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
