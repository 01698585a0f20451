"""Injectable fault modes of the stand-in planner, modelled on the paper's Autoware findings (§V-B).

All are off by default; each flag changes one decision of the nominal planner, so a testing pipeline can be scored
against known ground truth. What each should trigger (the oracle category in brackets):

- `ignore_cyclists`: bicycles and scooters are dropped from the object list before planning, so the planner
  neither follows nor yields to them -> it rear-ends or hits a cyclist in its path [Collisions].
- `late_braking_low_friction`: a braking model tuned on dry roads: planned stops (stop lines, obstacles, yield
  points) start only when `late_brake_decel` (6.5 m/s²) is needed and then brake hard, and following gaps get no
  low-friction margin, whatever the road friction. The player caps deceleration at friction·g, so on slippery
  roads (friction below ~0.66: rain, snow, most fog) the ego overruns -> it hits the obstacle or stopped vehicle
  [Collisions] or stops past a red stop line [Misinterp]. On a dry road the stops succeed but are abrupt [Smooth].
- `no_start_when_close`: at standstill, refuses to start while any NPC is within `close_start_radius` metres ahead
  or behind (even when the path is clear) -> the ego never moves [StartFail] (paper: 91.5 % of start failures had
  an NPC placed in front of or behind Autoware).
- `stale_tracking`: object states reach the planner `stale_tracking_delay` seconds late and are predicted to the
  present at constant velocity, so a lead that brakes, or a party that cuts in or starts to cross the ego's path,
  is seen late (still where it would have been) -> rear-end collisions, or hitting the crossing party [Collisions].
- `aggressive_start`: from standstill, commands high throttle (`aggressive_start_accel`) with a large steering yaw
  rate; the player models wheel slip when the traction demand exceeds friction·g -> on low friction (below ~0.71)
  the ego spins its wheels and does not move [StartFail]; on dry roads it starts with a jolt [Smooth].
- `red_light_misread`: a yellow signal is read as green, so the planner does not stop at yellow when it could
  -> it enters the junction after the signal turned red [Misinterp].
"""

from __future__ import annotations

from dataclasses import dataclass, fields
from typing import Iterable

from txt2sce_ros.errors import InputError


@dataclass(frozen=True, slots=True)
class Faults:
    """One switch per fault mode; the nominal planner has all off."""

    ignore_cyclists: bool = False
    late_braking_low_friction: bool = False
    no_start_when_close: bool = False
    stale_tracking: bool = False
    aggressive_start: bool = False
    red_light_misread: bool = False

    @classmethod
    def names(cls) -> tuple[str, ...]:
        return tuple(f.name for f in fields(cls))

    @classmethod
    def from_names(cls, names: Iterable[str]) -> "Faults":
        """`Faults.from_names(["stale_tracking"])`; raises InputError on an unknown name."""
        chosen = {}
        for name in names:
            key = name.strip().replace("-", "_")
            if not key:
                continue
            if key not in cls.names():
                raise InputError(f"unknown fault mode {name!r} (known: {', '.join(cls.names())})",
                                 element="faults")
            chosen[key] = True
        return cls(**chosen)

    def active(self) -> tuple[str, ...]:
        return tuple(name for name in self.names() if getattr(self, name))

    @property
    def nominal(self) -> bool:
        return not self.active()


#: Sketch categories the `ignore_cyclists` fault drops.
CYCLIST_CATEGORIES = frozenset({"bicycle", "scooter"})
