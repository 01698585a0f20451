"""Safety oracles: exact contact between the ego's footprint and every other entity's, and the paper's jerk rule.

Contact is the ground truth a simulator can offer: two oriented rectangles overlap or they do not. The time of
contact is placed between the last frame apart and the first frame in contact by bisection on poses interpolated
linearly between the two frames, so it does not depend on the step size.

A contact in which the ego stood still (|speed| below `struck_speed` in the frames either side of it) is not
the ego's collision: Table VI's Collisions is "the vehicle crashes into a static object or a dynamic road user", and
an ego standing still was struck — typically by a non-reactive NPC replaying the accident. Such contacts are
reported beside the verdict (rule `struck_while_stopped`, no category) so a planner fault is not masked by them.

A contact already there in the first frame is the scenario's fault (entities placed overlapping, e.g. debris under
the ego's start), so it is reported as `overlap_at_start` and the verdict is an error, never a fail.

The jerk rule is the paper's (§III-D.2, after Sequeira et al.): a collision is flagged when |jerk| exceeds
T_cj = 300 m/s³ over a short interval (5–15 ms there). Here the interval is the frame period (50 ms for the
player's default step): the finest a recording offers. The rule is kept beside the contact oracle so the two can be
compared run by run; `collision_rule` in the configuration chooses which one decides the Collisions category.
"""

from __future__ import annotations

import math
from typing import Callable, NamedTuple

from txt2sce_ros.contract import EntityState, Frame

from .geometry import FAR_SLACK, Box, box_at, footprint, interpolate, overlaps, penetration
from .params import SafetyParams
from .records import Category, Rule, Violation
from .signals import Sample


class Contact(NamedTuple):
    """One contact between the ego and another entity, at its onset."""

    t: float                  # s, contact time refined between frames
    entity: EntityState       # the other entity, as in the first frame in contact
    depth: float              # m, overlap depth in that frame
    ego_speed: float          # m/s, the ego's largest |speed| in the last frame apart and the first in contact
    at_start: bool = False    # already touching in the first frame of the run (the scenario placed them so)
    ego: EntityState | None = None   # the ego in the first frame in contact


class ContactOracle:
    """Ego vs every entity. Reports each contact once, at its start; a new contact after separation is new."""

    def __init__(self, params: SafetyParams) -> None:
        self.params = params
        self._prev: Frame | None = None
        self._in_contact: set[str] = set()
        self.contacts: list[Contact] = []

    def observe(self, frame: Frame) -> list[Contact]:
        """New contacts in this frame."""
        ego_box = footprint(frame.ego)
        ego_speed = abs(frame.ego.speed)
        if self._prev is not None:
            ego_speed = max(ego_speed, abs(self._prev.ego.speed))
        new: list[Contact] = []
        touching: set[str] = set()
        ex, ey, reach = ego_box.cx, ego_box.cy, ego_box.radius + FAR_SLACK
        for obj in frame.objects:
            # Far from the ego's box: its box (within |center_x| of its reference point) cannot overlap, and need
            # not be built (the circle test `overlaps` starts with would say so too).
            r = reach + math.hypot(0.5 * obj.length, 0.5 * obj.width) + abs(obj.center_x)
            dx, dy = obj.x - ex, obj.y - ey
            if dx * dx + dy * dy > r * r:
                continue
            box = footprint(obj)
            if not overlaps(ego_box, box):
                continue
            touching.add(obj.name)
            if obj.name in self._in_contact:
                continue
            t = self._contact_time(frame, obj)
            item = Contact(t, obj, penetration(ego_box, box), ego_speed, at_start=self._prev is None, ego=frame.ego)
            new.append(item)
            self.contacts.append(item)
        self._in_contact = touching
        self._prev = frame
        return new

    def _contact_time(self, frame: Frame, obj: EntityState) -> float:
        prev = self._prev
        if prev is None:
            return frame.t
        before = next((o for o in prev.objects if o.name == obj.name), None)
        if before is None:                        # appeared already overlapping (spawned, teleported)
            return frame.t
        e0, e1 = prev.ego, frame.ego

        def touching(u: float) -> bool:
            return overlaps(_box_between(e0, e1, u), _box_between(before, obj, u))

        if touching(0.0):                         # was already touching at the previous frame
            return frame.t
        return _bisect(touching, prev.t, frame.t, self.params.contact_refine_steps)


def reported_beside(contact: Contact, params: SafetyParams) -> Violation | None:
    """The contact as an event that is not the ego's collision, or None (the caller judges it as the ego's).

    - Already touching in the first frame: the scenario placed them overlapping (`overlap_at_start`; the verdict
      turns it into an error of the scenario — nothing the ego did).
    - The ego stood still in it: it was struck (`struck_while_stopped`, reported beside the verdict).
    - With `struck_from_behind`: the other came up from behind, in line, faster than the ego (a rear-end: the
      ego did not crash into it), reported beside as `struck_from_behind`."""
    obj = contact.entity
    if contact.at_start:
        return Violation(Rule.OVERLAP_AT_START, None, contact.t, contact.depth, 0.0, "m", (obj.name,),
                         f"ego and {obj.category} {obj.name} overlap by {contact.depth:.2f} m in the first frame")
    if contact.ego_speed >= params.struck_speed:
        closing = rear_closing_speed(contact.ego, obj) if params.struck_from_behind and contact.ego else None
        if closing is None or closing <= params.struck_speed:
            return None
        return Violation(Rule.STRUCK_FROM_BEHIND, None, contact.t, closing, params.struck_speed, "m/s",
                         (obj.name,), f"rear-ended by {obj.category} {obj.name} closing at {closing:.2f} m/s (ego "
                         f"{contact.ego.speed:.2f} m/s, overlap {contact.depth:.2f} m)")
    return Violation(Rule.STRUCK_WHILE_STOPPED, None, contact.t, contact.ego_speed, params.struck_speed, "m/s",
                     (obj.name,), f"struck by {obj.category} {obj.name} while standing still (ego "
                     f"{contact.ego_speed:.2f} m/s, {obj.name} {obj.speed:.2f} m/s, overlap {contact.depth:.2f} m)")


def rear_closing_speed(ego: EntityState, other: EntityState) -> float | None:
    """How fast `other` closes on the ego from behind (m/s, its speed along the ego's heading less the ego's
    forward speed), or None when it is not behind the ego in line: its box centre behind the ego's rear bumper,
    laterally within their half widths, heading the same way (within 45°)."""
    h = ego.heading
    c, s = math.cos(h), math.sin(h)
    ex, ey = ego.x + ego.center_x * c, ego.y + ego.center_x * s
    ox = other.x + other.center_x * math.cos(other.heading)
    oy = other.y + other.center_x * math.sin(other.heading)
    lon = (ox - ex) * c + (oy - ey) * s
    lat = -(ox - ex) * s + (oy - ey) * c
    dh = math.remainder(other.heading - h, math.tau)
    if lon >= -0.5 * ego.length or abs(lat) > 0.5 * (ego.width + other.width) or abs(dh) > math.pi / 4:
        return None
    return other.speed * math.cos(dh) - max(ego.speed, 0.0)


def _box_between(e0: EntityState, e1: EntityState, u: float) -> Box:
    x, y, h = interpolate(e0, e1, u)
    return box_at(x, y, h, e1.center_x, e1.length, e1.width)


def _bisect(touching: Callable[[float], bool], t0: float, t1: float, steps: int) -> float:
    """Earliest time in (t0, t1] with `touching` true, to (t1 - t0) / 2**steps; touching(1) is known true."""
    lo, hi = 0.0, 1.0
    for _ in range(steps):
        mid = 0.5 * (lo + hi)
        if touching(mid):
            hi = mid
        else:
            lo = mid
    return t0 + hi * (t1 - t0)


class JerkCollisionOracle:
    """|jerk| > T_cj over one frame interval; one event per run of consecutive samples above the threshold."""

    def __init__(self, params: SafetyParams, category: Category | None) -> None:
        self.params = params
        self.category = category
        self._above = False
        self.coarse_interval: float | None = None     # largest frame period seen above the paper's 15 ms

    def observe(self, sample: Sample, frame: Frame) -> Violation | None:
        if sample.jerk is None:
            return None
        if sample.dt > self.params.jerk_max_interval:
            self.coarse_interval = max(sample.dt, self.coarse_interval or 0.0)
        above = abs(sample.jerk) > self.params.jerk_threshold
        fire = above and not self._above
        self._above = above
        if not fire:
            return None
        near = _nearest(frame)
        return Violation(Rule.JERK_COLLISION, self.category, sample.t, abs(sample.jerk), self.params.jerk_threshold,
                         "m/s³", (near,) if near else (),
                         f"jerk {sample.jerk:+.1f} m/s³ over {sample.dt * 1000:.0f} ms")


def _nearest(frame: Frame, within: float = 5.0) -> str:
    """The entity whose footprint is closest to the ego's (within `within` m), to name beside a jerk event."""
    ego = footprint(frame.ego)
    best, best_gap = "", within
    for obj in frame.objects:
        gap = -penetration(ego, footprint(obj))
        if gap < best_gap:
            best, best_gap = obj.name, gap
    return best
