"""LongitudinalAction family: SpeedAction, SpeedProfileAction, LongitudinalDistanceAction."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

from lxml import etree

from ..syntax.xml import ParseContext
from .base import LONGITUDINAL, SHAPE_PEAK, ActionRun, TransitionDynamics, shape_value

if TYPE_CHECKING:
    from ..world.entity import Entity
    from ..world.world import World


@dataclass(frozen=True, slots=True)
class SpeedTarget:
    absolute: float | None
    ref: str | None = None
    value: float = 0.0
    value_type: str = "delta"      # delta | factor
    continuous: bool = False

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "SpeedTarget":
        choice = ctx.only_child(el)
        if choice.tag == "AbsoluteTargetSpeed":
            return cls(ctx.float(choice, "value"))
        if choice.tag == "RelativeTargetSpeed":
            return cls(None, ctx.req(choice, "entityRef"), ctx.float(choice, "value"),
                       ctx.req(choice, "speedTargetValueType"), ctx.bool(choice, "continuous", False))
        raise ctx.error(choice, f"unknown speed target <{choice.tag}>")

    def speed(self, world: "World") -> float:
        if self.absolute is not None:
            return self.absolute
        ref = world.entity(self.ref or "").speed
        return ref * self.value if self.value_type == "factor" else ref + self.value


def transition_time(dyn: TransitionDynamics, v0: float, v1: float, ent: "Entity") -> float:
    """Duration of a speed transition, stretched so its peak acceleration respects the entity's Performance."""
    dv = v1 - v0
    limit = ent.spec.max_accel if dv > 0 else ent.spec.max_decel
    peak = SHAPE_PEAK[dyn.shape]
    if dyn.dimension == "rate":
        rate = abs(dyn.value)
        if limit > 0:
            rate = min(rate, limit)
        return peak * abs(dv) / rate if rate > 0 else 0.0
    if dyn.dimension == "distance":
        mean = 0.5 * (abs(v0) + abs(v1))
        duration = dyn.value / mean if mean > 1e-9 else 0.0
    else:
        duration = dyn.value
    if limit > 0 and duration > 0 and peak * abs(dv) / duration > limit:
        duration = peak * abs(dv) / limit
    return duration


@dataclass(frozen=True, slots=True)
class SpeedAction:
    dynamics: TransitionDynamics
    target: SpeedTarget
    is_private = True

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "SpeedAction":
        return cls(TransitionDynamics.from_xml(ctx, ctx.child(el, "SpeedActionDynamics")),
                   SpeedTarget.from_xml(ctx, ctx.child(el, "SpeedActionTarget")))

    def start(self, world: "World", ent: "Entity | None") -> ActionRun | None:
        assert ent is not None
        run = SpeedRun(ent, self, world)
        return run


class SpeedRun(ActionRun):
    domains = frozenset({LONGITUDINAL})

    def __init__(self, ent: "Entity", spec: SpeedAction, world: "World") -> None:
        super().__init__(ent)
        self.spec = spec
        self.v0 = ent.speed
        self.v1 = spec.target.speed(world)
        self.elapsed = 0.0
        self.duration = 0.0 if spec.dynamics.shape == "step" else transition_time(spec.dynamics, self.v0, self.v1, ent)
        if self.duration <= 0.0:
            # A step takes effect at once (also in Init, so t=0 already shows the speed).
            ent.speed = self.v1
            self.done = not spec.target.continuous

    def step(self, world: "World", dt: float) -> None:
        ent = self.entity
        target = self.spec.target.speed(world) if self.spec.target.continuous else self.v1
        self.elapsed += dt
        if self.duration <= 0.0 or self.elapsed >= self.duration - 1e-9:
            ent.speed = target
            if not self.spec.target.continuous:
                self.done = True
            return
        f = shape_value(self.spec.dynamics.shape, self.elapsed / self.duration)
        ent.speed = self.v0 + (target - self.v0) * f


@dataclass(frozen=True, slots=True)
class SpeedProfileAction:
    """Speed through a list of (duration, speed) entries: 'position' mode interpolates linearly between them,
    'follow' mode chases that profile within the DynamicConstraints (acceleration and its rate)."""

    entries: tuple[tuple[float | None, float], ...]
    following_mode: str
    max_accel: float | None
    max_decel: float | None
    max_accel_rate: float | None
    max_decel_rate: float | None
    max_speed: float | None
    ref: str | None
    is_private = True

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "SpeedProfileAction":
        entries = tuple((None if e.get("time") is None else ctx.float(e, "time"), ctx.float(e, "speed"))
                        for e in el.findall("SpeedProfileEntry"))
        dc = el.find("DynamicConstraints")
        get = (lambda n: None if dc is None or dc.get(n) is None else ctx.float(dc, n))  # noqa: E731
        return cls(entries, el.get("followingMode", "follow"), get("maxAcceleration"), get("maxDeceleration"),
                   get("maxAccelerationRate"), get("maxDecelerationRate"), get("maxSpeed"), el.get("entityRef"))

    def start(self, world: "World", ent: "Entity | None") -> ActionRun | None:
        assert ent is not None
        return SpeedProfileRun(ent, self)


class SpeedProfileRun(ActionRun):
    """Speed over time from the entries. 'position': straight lines through the entries. 'follow': the same lines,
    each corner rounded by a constant-jerk transition (maxAccelerationRate / maxDecelerationRate) that leaves one
    line and lands tangentially on the next, so the speed follows the entries' slopes with bounded jerk (the
    scheme esmini uses). Times are local: 0 when the action starts."""

    domains = frozenset({LONGITUDINAL})

    def __init__(self, ent: "Entity", spec: SpeedProfileAction) -> None:
        super().__init__(ent)
        self.spec = spec
        acc = ent.spec.max_accel if spec.max_accel is None else spec.max_accel
        dec = ent.spec.max_decel if spec.max_decel is None else spec.max_decel
        entries = list(spec.entries)
        follow = spec.following_mode != "position"
        times, speeds = [0.0], [ent.speed]
        if entries and entries[0][0] is not None and abs(entries[0][0]) < 1e-9:
            if follow:
                entries = entries[1:]          # the profile starts from the current speed
            else:
                speeds = [entries[0][1]]
                entries = entries[1:]
        t = 0.0
        for dur, v in entries:
            if dur is None:                    # no time: reach it at the limit acceleration
                dv = v - speeds[-1]
                lim = acc if dv > 0 else dec
                dur = abs(dv) / lim if lim > 0 else 0.0
            t += max(dur, 0.0)
            if t - times[-1] < 1e-9:
                speeds[-1] = v                 # zero duration: replaces the previous point
                continue
            times.append(t)
            speeds.append(v)
        self.times, self.speeds = times, speeds
        self.segments = self._follow_segments(acc, dec) if follow and len(times) > 1 else None
        self.elapsed = 0.0

    def _follow_segments(self, acc: float, dec: float) -> list[tuple[float, float, float, float]]:
        sp = self.spec
        j_up = sp.max_accel_rate if sp.max_accel_rate else 1e3
        j_dn = sp.max_decel_rate if sp.max_decel_rate else 1e3
        ts, vs = self.times, self.speeds
        slopes = [(vs[i + 1] - vs[i]) / (ts[i + 1] - ts[i]) for i in range(len(ts) - 1)] + [0.0]
        intercepts = [vs[i] - slopes[i] * ts[i] for i in range(len(ts))]
        segs: list[tuple[float, float, float, float]] = []      # (t start, v start, slope, jerk)
        k_prev = self.entity.accel if abs(self.entity.accel) < 50 else 0.0
        # First: jerk from the current acceleration onto the first slope, then that slope (a parallel line).
        k1 = slopes[0]
        j = j_up if k1 >= k_prev else -j_dn
        tau = (k1 - k_prev) / j if abs(j) > 0 else 0.0
        segs.append((0.0, vs[0], k_prev, j))
        t3 = tau
        v3 = vs[0] + k_prev * tau + 0.5 * j * tau * tau
        segs.append((t3, v3, k1, 0.0))
        k0, m0 = k1, v3 - k1 * t3
        for i in range(1, len(ts)):
            k1, m1 = slopes[i], intercepts[i]
            if abs(k1 - k0) < 1e-9:
                continue
            j = j_up if k1 > k0 else -j_dn
            # Leave line 0 at t1 so that the jerk arc lands on line 1 with its slope.
            t1 = ((k1 - k0) ** 2 / (2 * j) + (m1 - m0)) / (k0 - k1)
            t1 = max(t1, segs[-1][0])
            v1 = k0 * t1 + m0
            tau = (k1 - k0) / j
            segs.append((t1, v1, k0, j))
            t3 = t1 + tau
            v3 = v1 + k0 * tau + 0.5 * j * tau * tau
            segs.append((t3, v3, k1, 0.0))
            k0, m0 = k1, v3 - k1 * t3
        return segs

    def _profile(self, t: float) -> float:
        if self.segments is not None:
            seg = self.segments[0]
            for cand in self.segments:
                if cand[0] <= t + 1e-9:
                    seg = cand
                else:
                    break
            dt = t - seg[0]
            return seg[1] + seg[2] * dt + 0.5 * seg[3] * dt * dt
        ts, vs = self.times, self.speeds
        if t >= ts[-1]:
            return vs[-1]
        for i in range(len(ts) - 1):
            if ts[i] <= t < ts[i + 1]:
                return vs[i] + (vs[i + 1] - vs[i]) * (t - ts[i]) / (ts[i + 1] - ts[i])
        return vs[-1]

    def step(self, world: "World", dt: float) -> None:
        ent, sp = self.entity, self.spec
        self.elapsed += dt
        ent.speed = self._profile(self.elapsed)
        if sp.max_speed is not None:
            ent.speed = min(ent.speed, sp.max_speed)
        last = self.segments[-1][0] if self.segments else self.times[-1]
        if self.elapsed >= max(last, self.times[-1]) - 1e-9:
            ent.speed = self.speeds[-1]
            self.done = True


@dataclass(frozen=True, slots=True)
class LongitudinalDistanceAction:
    """Keep a distance (or time gap) to `ref`. Without DynamicConstraints the actor is placed at the distance at
    once every step (as esmini does); with them a critically damped gap controller within the limits is used."""

    ref: str
    distance: float | None
    time_gap: float | None
    freespace: bool
    continuous: bool
    displacement: str
    cs: str
    max_accel: float | None
    max_decel: float | None
    max_speed: float | None
    is_private = True

    @classmethod
    def from_xml(cls, ctx: ParseContext, el: etree._Element) -> "LongitudinalDistanceAction":
        dc = el.find("DynamicConstraints")
        get = (lambda n: None if dc is None or dc.get(n) is None else ctx.float(dc, n))  # noqa: E731
        dist = None if el.get("distance") is None else ctx.float(el, "distance")
        gap = None if el.get("timeGap") is None else ctx.float(el, "timeGap")
        if dist is None and gap is None:
            raise ctx.error(el, "LongitudinalDistanceAction needs distance or timeGap")
        return cls(ctx.req(el, "entityRef"), dist, gap, ctx.bool(el, "freespace", False),
                   ctx.bool(el, "continuous", False), el.get("displacement", "trailingReferencedEntity"),
                   el.get("coordinateSystem", "entity"), get("maxAcceleration"), get("maxDeceleration"),
                   get("maxSpeed"))

    def start(self, world: "World", ent: "Entity | None") -> ActionRun | None:
        assert ent is not None
        return LongitudinalDistanceRun(ent, self, world)


class LongitudinalDistanceRun(ActionRun):
    domains = frozenset({LONGITUDINAL})

    def __init__(self, ent: "Entity", spec: LongitudinalDistanceAction, world: "World") -> None:
        super().__init__(ent)
        self.spec = spec
        self.ref = world.entity(spec.ref)
        self.has_dynamics = spec.max_accel is not None or spec.max_decel is not None or spec.max_speed is not None
        if not self.has_dynamics:
            self.step(world, 0.0)        # without dynamics the distance holds from the start (t = 0 in Init)

    def _wanted(self) -> float:
        sp = self.spec
        if sp.distance is not None:
            return sp.distance
        return (sp.time_gap or 0.0) * abs(self.ref.speed)      # a time gap at the reference's speed

    def step(self, world: "World", dt: float) -> None:
        ent, ref, sp = self.entity, self.ref, self.spec
        cs = "road" if sp.cs in ("road", "lane") else "entity"
        # Gap measured from the actor to the referenced entity (positive: the reference is ahead).
        gap = world.measure.between(ent, ref, "longitudinal", cs, sp.freespace)
        behind = sp.displacement != "leadingReferencedEntity"
        if sp.displacement == "any":
            behind = gap >= 0
        wanted = self._wanted() if behind else -self._wanted()
        error = gap - wanted                 # > 0: the actor should move forward
        if not self.has_dynamics:
            if ent.track is not None:
                # The gap is in road s when measured on the road, else in metres along the entity.
                ds = error if cs == "road" else error * ent.track.ds_per_metre(ent.s, ent.offset)
                s, _ = ent.track.advance(ent.s, -ds if ent.reverse else ds)
                ent.s = s
                ent.x, ent.y, ent.h = ent.track.pose(s, ent.offset)
                ent._sync_road()
            ent.speed = ref.speed
        else:
            acc_lim = sp.max_accel if sp.max_accel is not None else ent.spec.max_accel
            dec_lim = sp.max_decel if sp.max_decel is not None else ent.spec.max_decel
            # Critically damped spring on the gap error; stiffer toward the side with more authority.
            k = 0.4 * (acc_lim if error < 0 else dec_lim)
            acc = error * k - (ent.speed - ref.speed) * 2.0 * math.sqrt(k)
            acc = min(max(acc, -dec_lim), acc_lim)
            ent.speed += acc * dt
            if sp.max_speed is not None:
                ent.speed = min(max(ent.speed, -sp.max_speed), sp.max_speed)
        if not sp.continuous and abs(error) < 0.1 and dt > 0:
            self.done = True
