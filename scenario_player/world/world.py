"""The World: the one object actions and conditions talk to (a narrow facade), passed explicitly, no globals.

Positions resolve here (lane, road, relative, route), actions start and take control domains here, and the
storyboard index answers StoryboardElementStateConditions. Motion itself lives in `world/motion.py`.
"""

from __future__ import annotations

import math
from typing import Any, Iterable

import numpy as np

from txt2sce_ros.errors import InputError, UnsupportedFeature
from txt2sce_ros.road import LanePath, LaneRef, RoadNetwork

from .entity import Entity
from .lanes import TrackCache
from .measure import Measure
from .pose import HeadingRule, Pose
from .protocols import Change, Element, Run, Startable
from .signals import SignalBoard

STATIC_POSITIONS = ("WorldPosition", "LanePosition", "RoadPosition", "RoutePosition")


class World:
    def __init__(self, net: RoadNetwork, entities: dict[str, Entity], *, dt: float, seed: int,
                 parameters: dict[str, str], source: str) -> None:
        self.net = net
        self.tracks = TrackCache.of(net)
        self.entities = entities
        self.order = list(entities.values())
        for ent in self.order:
            ent.locator = net.locate
        self.dt = dt
        self.t = 0.0
        self.step_index = 0
        self.seed = seed
        self._rng: np.random.Generator | None = None
        self.friction = 1.0
        self.parameters = dict(parameters)
        self.source = source
        self.signals = SignalBoard(net)
        self.measure = Measure(self)
        self.elements: dict[tuple[str, str], Element] = {}
        self.notes: list[str] = []                 # e.g. storyboard actions ignored on the planner-driven ego
        self.transitions: list[tuple[float, str, str, str]] = []
        self._static_cache: dict[int, tuple[Any, Pose]] = {}    # id(position) -> (position, its pose)
        self._routes: dict[int, tuple[LanePath, list[LaneRef]]] = {}
        self.running: list[Run] = []
        self.global_runs: list[Run] = []

    # -- lookups --------------------------------------------------------------------------------------------------
    @property
    def rng(self) -> np.random.Generator:
        """The run's seeded generator, made on first use: importing numpy.random is a cold start's cost, and no
        element draws from it yet."""
        if self._rng is None:
            self._rng = np.random.default_rng(self.seed)
        return self._rng

    def entity(self, name: str) -> Entity:
        try:
            return self.entities[name]
        except KeyError:
            raise InputError(f"unknown entity '{name}'", source=self.source, element="entityRef") from None

    def parameter(self, name: str) -> str:
        if name not in self.parameters:
            raise InputError(f"unknown parameter '{name}'", source=self.source, element="parameterRef")
        return self.parameters[name]

    def storyboard_element(self, kind: str, name: str) -> Element:
        el = self.elements.get((kind, name))
        if el is None:
            raise InputError(f"no {kind} named '{name}'", source=self.source, element="storyboardElementRef")
        return el

    def log_transition(self, element: Element, transition: Change) -> None:
        self.transitions.append((self.t, element.kind, element.name, transition.value))

    def note(self, text: str) -> None:
        if text not in self.notes:
            self.notes.append(text)

    # -- positions ------------------------------------------------------------------------------------------------
    def resolve_cached(self, position: Any) -> Pose:
        """Resolve a position; absolute ones once per run (conditions test them every step, so a cached one is
        found first, by identity)."""
        hit = self._static_cache.get(id(position))
        if hit is not None and hit[0] is position:
            return hit[1]
        if type(position).__name__ in STATIC_POSITIONS:
            pose = position.resolve(self)
            self._static_cache[id(position)] = (position, pose)
            return pose
        return position.resolve(self)

    def lane_pose(self, road_id: str, lane_id: int, s: float, offset: float,
                  orientation: HeadingRule | None = None) -> Pose:
        try:
            track = self.tracks.at(str(road_id), int(lane_id), s)
        except (InputError, KeyError) as exc:
            raise InputError(f"no lane {lane_id} on road {road_id} at s={s}: {exc}", source=self.source,
                             element="LanePosition") from exc
        s = min(max(s, track.s0), track.s1)
        x, y, h = track.pose(s, offset)
        if orientation is not None:
            h = orientation.apply(h)
        return Pose(x, y, h, str(road_id), int(lane_id), s, offset)

    def road_pose(self, road_id: str, s: float, t: float, orientation: HeadingRule | None = None) -> Pose:
        try:
            road = self.net.road(road_id)
        except (InputError, KeyError) as exc:
            raise InputError(f"no road {road_id}", source=self.source, element="RoadPosition") from exc
        s = min(max(s, 0.0), road.length)
        x, y, h = self.net.road_to_world(road_id, s, t)
        pose = self.locate_pose(x, y, None)
        heading = pose.h if pose.road_id is not None else h
        if orientation is not None:
            heading = orientation.apply(heading)
        return Pose(x, y, heading, pose.road_id, pose.lane_id, pose.s, pose.offset)

    def locate_pose(self, x: float, y: float, h: float | None) -> Pose:
        """A world point, attached to the lane under it when there is one (so motion can follow that lane)."""
        lp = self.net.locate(x, y, h)
        if lp is None or not lp.inside:
            return Pose(x, y, 0.0 if h is None else h)
        heading = lp.heading if h is None else h
        return Pose(x, y, heading, lp.road_id, lp.lane_id, lp.s, lp.offset)

    def road_coordinates(self, name: str) -> tuple[str, float, float]:
        ent = self.entity(name)
        if ent.road_id is None:
            raise InputError(f"entity '{name}' is not on a road", source=self.source, element="RelativeRoadPosition")
        return ent.road_id, ent.road_s, ent.road_t

    def relative_lane_pose(self, name: str, d_lane: int, ds: float, offset: float,
                           orientation: HeadingRule | None) -> Pose:
        ent = self.entity(name)
        if ent.track is not None:
            road_id, lane_id, s0, forward = ent.track.ref.road_id, ent.track.ref.lane_id, ent.s, ent.track.forward
        elif ent.road_id is not None and ent.lane_id is not None:
            road_id, lane_id, s0 = ent.road_id, ent.lane_id, ent.road_s
            forward = self.net.lane_forward(road_id, lane_id, s0)
        else:
            raise InputError(f"entity '{name}' is not on a lane", source=self.source, element="RelativeLanePosition")
        # ds runs along the reference entity's lane (through the lanes that follow it), dLane counts lanes to the
        # left (+) in that lane's driving direction, skipping the centre lane 0.
        from .motion import lane_walk

        track = self.tracks.at(road_id, lane_id, s0)
        along = abs(_wrap(track.pose(s0)[2] - ent.h)) <= math.pi / 2      # entity drives with the lane
        # ds is measured in road s while it stays on this lane section (as esmini reads it); beyond, the rest
        # continues through the lanes that follow.
        lane_dir = 1.0 if track.forward else -1.0
        step = ds if along else -ds                    # + = the lane's driving direction
        s = s0 + lane_dir * step
        flips = 0
        if not track.s0 <= s <= track.s1:
            end = track.s1 if (lane_dir * step) > 0 else track.s0
            track, s, _, flips = lane_walk(self, track, end, math.copysign(abs(s - end) + 1e-9, step),
                                           ent.route_lanes)
        # dLane and offset count to the left of the reference entity's direction of travel.
        with_lane = along if flips % 2 == 0 else not along
        plus_s = track.forward == with_lane
        lane = track.ref.lane_id
        d = d_lane if plus_s else -d_lane               # in road terms: lane ids grow toward +t
        target = lane + d
        if lane < 0 <= target or lane > 0 >= target:
            target += 1 if d > 0 else -1
        return self.lane_pose(track.ref.road_id, target, s, offset if plus_s else -offset, orientation)

    def route_pose(self, rp: Any) -> Pose:
        path, refs = self.route_path(rp.route)
        if rp.from_entity is not None:
            ent = self.entity(rp.from_entity)
            return self.locate_pose(ent.x, ent.y, ent.h)
        lane_ref, lane_s = path.lane_at(min(rp.path_s, path.length))
        lane_id = rp.lane_id if rp.lane_id is not None else lane_ref.lane_id
        return self.lane_pose(lane_ref.road_id, lane_id, lane_s, rp.lane_offset)

    def route_path(self, route: Any) -> tuple[LanePath, list[LaneRef]]:
        """Lane-level path through a Route's waypoints (shortest on the routing graph between consecutive ones)."""
        cached = self._routes.get(id(route))
        if cached is not None:
            return cached
        poses = [self.resolve_cached(w.position) for w in route.waypoints]
        # Same waypoint lanes and s -> same lane sequence and path (both are functions of the map alone). Only
        # successful paths are stored, so a hit never skips an error below.
        key = tuple((p.road_id, p.lane_id, p.s) for p in poses)
        shared = self.tracks.paths.get(key)
        if shared is not None:
            result = (shared[0], list(shared[1]))
            self._routes[id(route)] = result
            return result
        refs: list[LaneRef] = []
        for a, b in zip(poses, poses[1:]):
            if a.road_id is None or b.road_id is None:
                raise InputError("route waypoint is not on a lane", source=self.source, element="Waypoint")
            ra = self.net.lane_ref(a.road_id, a.lane_id, a.s)
            rb = self.net.lane_ref(b.road_id, b.lane_id, b.s)
            leg = self.net.route(ra, rb)
            refs.extend(leg if not refs else [r for r in leg if not refs or r != refs[-1]])
        first, last = poses[0], poses[-1]
        path = LanePath.from_lanes(self.net, refs, s_start=first.s, s_end=last.s)
        self._routes[id(route)] = (path, refs)
        paths = self.tracks.paths
        if len(paths) >= self.tracks.PATHS_KEPT:
            paths.pop(next(iter(paths)))
        paths[key] = (path, tuple(refs))
        return path, refs

    # -- actions (facade) -----------------------------------------------------------------------------------------
    def start_action(self, element: Element, spec: Startable,
                     actors: Iterable[str]) -> list[Run]:
        runs: list[Run] = []
        if not spec.is_private:
            run = spec.start(self, None)
            if run is not None:
                self.global_runs.append(run)
                runs.append(run)
            return runs
        for name in actors:
            ent = self.entity(name)
            if ent.planner:
                self.note(f"ignored: storyboard action '{element.name}' on planner-driven '{name}'")
                continue
            run = spec.start(self, ent)
            if run is not None:
                self.take(ent, run)      # even a run done at once (a step speed) ends the domain's holder
                if not run.done:
                    runs.append(run)
        return runs

    def take(self, ent: Entity, run: Run) -> None:
        """Give `run` its control domains on `ent`, ending the runs that held them."""
        for dom in run.domains:
            old = ent.runs.get(dom)
            if old is not None and old is not run:
                old.cancel()
                for d in [k for k, v in ent.runs.items() if v is old]:
                    del ent.runs[d]
            ent.runs[dom] = run
        if run.done:
            for d in [k for k, v in ent.runs.items() if v is run]:
                del ent.runs[d]
        else:
            self.running.append(run)

    def cancel_runs(self, runs: Iterable[Run]) -> None:
        for run in runs:
            run.cancel()

    def release(self, ent: Entity, domain: str) -> None:
        ent.runs.pop(domain, None)

    def teleport(self, ent: Entity, pose: Pose) -> None:
        ent.placed = True
        if pose.road_id is not None and pose.lane_id is not None and pose.s is not None:
            track = self.tracks.at(pose.road_id, pose.lane_id, pose.s)
            lane_h = track.pose(pose.s, pose.offset)[2]
            ent.place_on_lane(track, pose.s, pose.offset, None if abs(_wrap(pose.h - lane_h)) < 1e-6 else pose.h)
        else:
            ent.place_free(pose.x, pose.y, pose.h)
        # Road-derived timers (end of road, off road) update in the kinematics phase, so every condition of this
        # step still sees the state the step started with.

    def reattach(self, ent: Entity) -> None:
        _reattach_impl(self, ent)

    def step_runs(self, dt: float) -> None:
        """Actions phase: every running action advances once (global first, then in start order)."""
        if self.global_runs:
            for run in self.global_runs:
                if not run.done:
                    run.step(self, dt)
            self.global_runs = [r for r in self.global_runs if not r.done]
        if not self.running:
            return
        # Longitudinal runs first: lateral shapes over distance and trajectories use this step's speed.
        for run in self.running:
            if not run.done and "longitudinal" in run.domains and not run.moves_entity:
                run.step(self, dt)
        finished = False
        for run in self.running:
            if not run.done and ("longitudinal" not in run.domains or run.moves_entity):
                run.step(self, dt)
        for run in self.running:
            if run.done:
                finished = True
                break
        if finished:
            for run in self.running:
                if run.done:
                    ent = run.entity
                    for d in [k for k, v in ent.runs.items() if v is run]:
                        del ent.runs[d]
            self.running = [r for r in self.running if not r.done]


def _wrap(a: float) -> float:
    return (a + math.pi) % (2.0 * math.pi) - math.pi


__all__ = ["World", "UnsupportedFeature"]


#: Lanes an entity leaving a trajectory is put back on (esmini's choice in the conformance cases: a pedestrian
#: beside a sidewalk joins the sidewalk, one on a border strip the driving lane next to it).
REATTACH_LANE_TYPES = ("driving", "sidewalk")


def _reattach_impl(self: "World", ent: Entity) -> None:
    """After a trajectory the entity goes on along the road under it, as esmini does: on the nearest driving lane
    or sidewalk (also from beside it, e.g. a pedestrian who ended on a border strip: the lateral offset keeps it
    where it is; on a sidewalk without successor it stops at the road's end, as there), toward
    the road's +s when its heading points within 90 degrees of the reference line's direction, else toward -s (a
    crossing exactly square to the road goes +s, as there). Off every road (no lane projects onto the point) it
    goes on straight."""
    lp = self.net.locate(ent.x, ent.y, ent.h, lane_types=REATTACH_LANE_TYPES)
    if lp is None:
        ent.track = None
        ent.lane_locked = False
        return
    track = self.tracks.at(lp.road_id, lp.lane_id, lp.s)
    x, y, _ = track.pose(lp.s, lp.offset)
    if math.hypot(x - ent.x, y - ent.y) > 0.5:
        # The point lies beyond the road's ends: there is no road position to keep.
        ent.track = None
        ent.lane_locked = False
        return
    road_h = lp.heading if track.forward else lp.heading + math.pi
    plus_s = math.cos(ent.h - road_h) >= -1e-9        # square to the road, up to rounding: +s
    against = plus_s != track.forward
    ent.place_on_lane(track, lp.s, lp.offset, lp.heading + math.pi if against else None)
