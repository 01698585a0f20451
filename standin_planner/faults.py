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
from typing import TYPE_CHECKING, Iterable

from txt2sce_ros.errors import InputError

if TYPE_CHECKING:
    from lxml import etree


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


def inert_faults(scenario_root: "etree._Element") -> frozenset[str]:
    """Fault modes that provably cannot change a single decision of the planner in this scenario, so a run with
    one of them on is the nominal run step for step (a study may skip it and reuse the nominal verdict):

    - `ignore_cyclists` when no entity is a bicycle or scooter (the fault only filters those from the object list;
      the category is read as the player reads it: `txt2sce:category`, else the Vehicle's `vehicleCategory`);
    - `red_light_misread` when no controller phase or signal state action sets a light to yellow (the fault only
      rewrites a yellow; a light nothing sets shows `off`).
    Every other fault acts on the ego's own motion or on every object and is never called inert."""
    out = set()
    cats = set()
    for obj in scenario_root.iterfind("Entities/ScenarioObject"):
        body = next((c for c in obj if c.tag in ("Vehicle", "Pedestrian", "MiscObject")), None)
        if body is None:
            continue
        prop = body.find("Properties/Property[@name='txt2sce:category']")
        cats.add(prop.get("value", "") if prop is not None else
                 ("bicycle" if body.get("vehicleCategory") == "bicycle" else body.tag))
    if not cats & CYCLIST_CATEGORIES:
        out.add("ignore_cyclists")
    # every way a scenario can set a light: controller phases and (timed) state actions
    states = [s.get("state", "") for tag in ("TrafficSignalState", "TrafficSignalStateAction")
              for s in scenario_root.iter(tag)]
    if not any(s.strip().lower() == "yellow" or s.replace(" ", "") == "off;on;off" for s in states):
        out.add("red_light_misread")
    return frozenset(out)
