"""NCM's reach into seeds that lack a party: a new party inserted on the AV's path (the `new_party` slot).

A seed holds the parties its report names, so a report about a parked car gives no cyclist, no lead that brakes
and nobody close to the AV at its start; mutating the parties it has cannot bring those in. The new-party slot
(empty in the seed: a ScenarioObject, its Init Private and a Story) takes one of a few parties placed where the
road model says they conflict with the AV's path:

| role | party | where | what it does | trigger conditions it brings |
|---|---|---|---|---|
| `cyclist_ahead` | bicycle | `ahead` m ahead in the AV's lane (along its route) | rides on at its category's speed | a cyclist on the AV's path (`category:bicycle`, R5/same) |
| `lead_brakes` | car | `ahead` m ahead in the AV's lane | drives at the AV's speed, brakes to a stop at `brake_at` s | a lead that brakes (`events:h`, R5+h) |
| `close_behind` | car | `near_gap` m behind the AV's rear bumper, same lane | stands | a party close to the AV at the start (`near_start:yes`) |
| `crossing` | pedestrian | beside the AV's lane `ahead` m ahead, `cross_kerb` m out from its edge | stands, then walks across the AV's path when the AV is as many seconds from the crossing point as the walk to the lane's centre takes | a party that starts to cross into the path (`events:m`) |

The crossing is the nearside pedestrian dash of Euro NCAP's AEB tests (CPNA): walking at its category's speed, it
would meet the middle of the AV's front had the AV kept its speed. A planner that sees it start can brake in time;
one that sees it late (or not at all) cannot. The trigger is a TimeToCollisionCondition of the AV to the crossing
point, so it fires whatever speed the AV reaches there (from a standing or a moving start).

Names follow docs/seed_format.md (`npc<k>` with the first free k, events `npc<k>_e1_stop`), so the analysis reads
the new party like a reported one (category, derived position, events).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from lxml import etree

from ..seed.context import LanePos, SeedContext
from .dynamics import initial_speed
from .environment import ahead_on_path
from .physical import _sub, ncm  # one element helper for the tree's XML
from .trajectory import feasible_s, footprint_extent
from .values import Recorder, uniform

#: In the order a small node budget keeps them (`prune.diagonal` covers an enumerated block's versions in order).
ROLES = ("cyclist_ahead", "close_behind", "crossing", "lead_brakes")
#: The ego start state a role tests (`Variant.needs`): a car standing close behind tests a start from standstill
#: (an AV that drives off leaves it behind), a lead driving at the AV's speed an AV that follows it.
ROLE_NEEDS = {"close_behind": (("ego", "standing"),), "lead_brakes": (("ego", "moving"),)}
#: Ego starts a role's party cannot stand beside: placed `near_gap` m behind the seed's AV, the car standing close
#: behind overlaps an AV started back on its approach to a light (moved further back than `near_gap`).
ROLE_EXCLUDES = {"close_behind": (("ego", "approach"),)}


def free_name(prefix: str, taken: set[str | None]) -> str:
    """The first `<prefix><k>` no entity uses yet (then marked taken), so inserted entities never clash."""
    k = 1
    while f"{prefix}{k}" in taken:
        k += 1
    taken.add(f"{prefix}{k}")
    return f"{prefix}{k}"


def _behind_ego(ctx: SeedContext, party_front: float, gap: float, min_gap: float) -> LanePos | None:
    """The party's reference-point position in the ego's lane with `gap` m between its front bumper and the ego's
    rear one, when that is on the ego's start road and clear of every other start (`feasible_s`)."""
    ego = ctx.starts.get("ego")
    if ego is None or ctx.map is None or not ctx.map.has_road(ego.road):
        return None
    sign = ctx.map.direction(ego.road, ego.lane)
    e_rear, _ = footprint_extent(ctx.root.find("Entities/ScenarioObject[@name='ego']"))
    s = ego.s + sign * (e_rear - gap - party_front)
    # feasible_s checks a move of a start: as a move of the ego's own start it keeps the new place on the road, on
    # the lane's type, clear of parties beside and never past another party in the lane
    return LanePos(ego.road, ego.lane, float(s)) if feasible_s(ctx, "ego", ego, s, 0.0, min_gap) else None


def _lane_clear_ahead(ctx: SeedContext, pos: LanePos, length: float) -> bool:
    """No entity of the seed starts in `pos`'s lane within `length` m ahead of it: a scripted party does not steer
    round what stands in its lane, so a new one placed behind an obstacle would run into it."""
    if ctx.map is None:
        return True
    sign = ctx.map.direction(pos.road, pos.lane)
    return not any((p.road, p.lane) == (pos.road, pos.lane) and 0.0 <= sign * (p.s - pos.s) <= length
                   for name, p in ctx.starts.items() if name != "ego")


def _speed_action(speed: float, dynamics: tuple[str, str, float]) -> etree._Element:
    shape, dim, value = dynamics
    sa = etree.Element("SpeedAction")
    _sub(sa, "SpeedActionDynamics", dynamicsShape=shape, value=f"{value:.3f}", dynamicsDimension=dim)
    _sub(_sub(sa, "SpeedActionTarget"), "AbsoluteTargetSpeed", value=f"{speed:.3f}")
    return sa


def _private(name: str, pos: LanePos, speed: float) -> etree._Element:
    priv = etree.Element("Private", entityRef=name)
    tp = _sub(_sub(_sub(priv, "PrivateAction"), "TeleportAction"), "Position")
    _sub(tp, "LanePosition", roadId=pos.road, laneId=str(pos.lane), offset="0", s=f"{pos.s:.3f}")
    _sub(_sub(priv, "PrivateAction"), "LongitudinalAction").append(_speed_action(speed, ("step", "time", 0.0)))
    return priv


def _one_event_story(name: str, what: str) -> tuple[etree._Element, etree._Element, etree._Element]:
    """(story, act, event) of `<name>_story`: one act, one maneuver group acting on `name`, one event `<name>_e1_<what>`
    (the caller adds the event's actions and both start triggers)."""
    story = etree.Element("Story", name=f"{name}_story")
    act = _sub(story, "Act", name=f"{name}_act")
    mg = _sub(act, "ManeuverGroup", name=f"{name}_mg", maximumExecutionCount="1")
    _sub(_sub(mg, "Actors", selectTriggeringEntities="false"), "EntityRef", entityRef=name)
    man = _sub(mg, "Maneuver", name=f"{name}_maneuver")
    ev = _sub(man, "Event", name=f"{name}_e1_{what}", priority="parallel", maximumExecutionCount="1")
    return story, act, ev


def _stop_story(name: str, at: float, speed: float, decel: float) -> etree._Element:
    """`<name>_story`: one event `<name>_e1_stop` braking to 0 at `decel` from simulation time `at`."""
    story, act, ev = _one_event_story(name, "stop")
    action = _sub(ev, "Action", name=f"{name}_e1_stop_action")
    _sub(_sub(action, "PrivateAction"), "LongitudinalAction").append(
        _speed_action(0.0, ("linear", "time", max(speed / decel, 0.1))))
    for parent, cname, value in ((ev, f"{name}_e1_stop_start", at), (act, f"{name}_act_start", 0.0)):
        cond = _sub(_sub(_sub(parent, "StartTrigger"), "ConditionGroup"), "Condition", name=cname, delay="0",
                    conditionEdge="none")
        _sub(_sub(cond, "ByValueCondition"), "SimulationTimeCondition", value=f"{value:g}", rule="greaterThan")
    return story


def _world(x: float, y: float, h: float) -> etree._Element:
    return etree.Element("WorldPosition", x=f"{x:.3f}", y=f"{y:.3f}", z="0", h=f"{h:.4f}", p="0", r="0")


def _cross_story(name: str, path: list[tuple[float, float]], heading: float, speed: float,
                 point: LanePos, ttc: float) -> etree._Element:
    """`<name>_story`: one event `<name>_e1_cross` (walk at `speed` along `path`) that starts once the ego's time
    to collision with the crossing `point` (front bumper, straight-line distance, as the dilemma-zone yellow
    measures its stop line) drops below `ttc` s."""
    story, act, ev = _one_event_story(name, "cross")
    walk = _sub(ev, "Action", name=f"{name}_e1_cross_speed")
    _sub(_sub(walk, "PrivateAction"), "LongitudinalAction").append(_speed_action(speed, ("step", "time", 0.0)))
    follow = _sub(_sub(_sub(ev, "Action", name=f"{name}_e1_cross_action"), "PrivateAction"), "RoutingAction")
    fta = _sub(follow, "FollowTrajectoryAction")
    line = _sub(_sub(_sub(fta, "Trajectory", name=f"{name}_crossing", closed="false"), "Shape"), "Polyline")
    for x, y in path:
        _sub(_sub(line, "Vertex", time="0"), "Position").append(_world(x, y, heading))
    _sub(_sub(fta, "TimeReference"), "None")
    _sub(fta, "TrajectoryFollowingMode", followingMode="position")
    cond = _sub(_sub(_sub(ev, "StartTrigger"), "ConditionGroup"), "Condition", name=f"{name}_e1_cross_start",
                delay="0", conditionEdge="none")
    by = _sub(cond, "ByEntityCondition")
    _sub(_sub(by, "TriggeringEntities", triggeringEntitiesRule="any"), "EntityRef", entityRef="ego")
    ttc_el = _sub(_sub(by, "EntityCondition"), "TimeToCollisionCondition", value=f"{ttc:.3f}", freespace="true",
                  alongRoute="false", rule="lessThan")
    _sub(_sub(_sub(ttc_el, "TimeToCollisionConditionTarget"), "Position"), "LanePosition", roadId=point.road,
         laneId=str(point.lane), s=f"{point.s:.3f}", offset="0")
    start = _sub(_sub(_sub(act, "StartTrigger"), "ConditionGroup"), "Condition", name=f"{name}_act_start", delay="0",
                 conditionEdge="none")
    _sub(_sub(start, "ByValueCondition"), "SimulationTimeCondition", value="0", rule="greaterThan")
    return story


def _crossing(ctx: SeedContext, point: LanePos, kerb: float, beyond: float
              ) -> tuple[tuple[float, float, float], list[tuple[float, float]], float]:
    """Start pose, path and walk to the lane centre (m) of a party crossing the AV's lane at `point` from its right:
    `kerb` m out from the lane's right edge, across to `beyond` m past its left edge."""
    x, y, h = ctx.map.network.lane_to_world(point.road, point.lane, point.s)
    half = 0.5 * ctx.map.lane_width(point.road, point.lane, point.s)
    rx, ry = math.sin(h), -math.cos(h)                   # unit vector to the right of the lane's direction
    out = half + kerb
    start = (x + rx * out, y + ry * out)
    end = (x - rx * (half + beyond), y - ry * (half + beyond))
    heading = math.atan2(-ry, -rx)                       # walking to the left across the lane
    return (start[0], start[1], heading), [start, (x, y), end], out


def new_party(role: str, name: str, ctx: SeedContext, rng: np.random.Generator, cfg: dict[str, Any],
              rec: Recorder) -> tuple[etree._Element, etree._Element, etree._Element | None] | None:
    """(ScenarioObject, Init Private, Story or None) of the party `role` names, or None where the road gives no
    place for it (no map, no ego start, the AV's path too short, no room behind the AV)."""
    spec = cfg["new_party"]
    init = cfg["trajectory"]["init_location"]
    ego_priv = ctx.root.find("Storyboard/Init/Actions/Private[@entityRef='ego']")
    ego_speed = initial_speed(ego_priv) or 0.0
    cats = cfg["physical"]["categories"]
    category = {"cyclist_ahead": "bicycle", "crossing": "pedestrian"}.get(role, "car")
    obj = etree.Element("ScenarioObject", name=name)
    ncm(obj, category, rng, cfg, rec)
    story = None
    world = None
    if role in ("cyclist_ahead", "lead_brakes", "crossing"):
        found = ahead_on_path(ctx, uniform(rng, *spec["ahead"]))
        if found is None or not found[1]:
            return None
        pos = found[0]
        ego = ctx.starts["ego"]
        # a party or obstacle of the seed in the way: between the AV and the place, or (for a party that goes on
        # along the lane; a crossing one leaves it) in the lane ahead of it
        if pos.road == ego.road and not (feasible_s(ctx, "ego", ego, pos.s, 0.0, init["min_gap"])
                                         and (role == "crossing"
                                              or _lane_clear_ahead(ctx, pos, float(spec["clear_ahead"])))):
            return None
        if role == "cyclist_ahead":
            speed = float(cats[category]["speed"])
        elif role == "crossing":
            walk = float(cats[category]["speed"])
            world, path, to_centre = _crossing(ctx, pos, float(spec["cross_kerb"]), float(spec["cross_beyond"]))
            story = _cross_story(name, path, world[2], walk, pos, to_centre / walk)
            rec.note(f"Story[@name='{name}_story']", None,
                     f"{name}_e1_cross at {walk:.2f} m/s when ego TTC to road {pos.road} lane {pos.lane} "
                     f"s {pos.s:.2f} < {to_centre / walk:.2f} s")
            speed = 0.0
        else:
            speed = ego_speed if ego_speed > 0 else float(cats[category]["speed"])
            at = uniform(rng, *spec["brake_at"])
            story = _stop_story(name, at, speed, float(spec["brake_decel"]))
            rec.note(f"Story[@name='{name}_story']", None, f"{name}_e1_stop at t > {at:.2f} s")
    elif role == "close_behind":
        pos = _behind_ego(ctx, footprint_extent(obj)[1], float(init["near_gap"]), float(init["min_gap"]))
        if pos is None:
            return None
        speed = 0.0
    else:
        raise ValueError(f"unknown new-party role {role!r}")
    priv = _private(name, pos, speed)
    if world is not None:                                # beside the lane, facing across it: a world pose
        tp = priv.find("PrivateAction/TeleportAction/Position")
        tp.replace(tp[0], _world(*world))
    rec.check_tree(obj)
    rec.check_tree(priv)
    if story is not None:
        rec.check_tree(story)
    rec.note(f"Entities/ScenarioObject[@name='{name}']", None, f"{category} ({role})")
    rec.note(f"Init/Private[@entityRef='{name}']/LanePosition", None,
             f"road {pos.road} lane {pos.lane} s {pos.s:.2f}, {speed:.2f} m/s")
    return obj, priv, story
