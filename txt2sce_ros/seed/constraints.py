"""Road constraints read off a sketch (paper §III-B.2, step 1): what a map site must offer for the reported
manoeuvres to be drivable there."""

from __future__ import annotations

from dataclasses import dataclass

from ..sketch import LANED_POSITIONS, Sketch

#: Turns through a junction by action code.
TURN_OF_ACTION = {"d": "left", "e": "right", "j": "uturn"}
#: Which junction leg a party at R1–R4 uses, relative to the AV's approach.
LEG_OF_POSITION = {"R1": "left", "R2": "opposite", "R3": "right", "R4": "exit"}
#: Layouts that need a junction.
JUNCTION_LAYOUTS = ("junction4", "junction3", "roundabout")


def first_turn(actions: str) -> str:
    """The turn a party makes through the junction ('straight' when none)."""
    for c in actions:
        if c in TURN_OF_ACTION:
            return TURN_OF_ACTION[c]
    return "straight"


@dataclass(frozen=True, slots=True)
class RoadConstraints:
    layout: str                          # sketch layout; 'unknown' never reaches here (missing road)
    control: str                         # signal | stop_sign | none | unknown
    min_lanes: int                       # driving lanes in the AV's direction
    one_way: bool | None
    needs_oncoming: bool                 # an opposite-direction lane beside the AV (R7, one_way false)
    ego_turn: str                        # straight | left | right | uturn
    legs: tuple[tuple[str, str], ...]    # (leg, turn) per party at R1–R4, e.g. ('left', 'straight')
    needs_shoulder: bool                 # something stands at the curb (riders, parked vehicles, pedestrians)
    stated_lanes: bool = False           # the report gave the lane count (match it exactly when possible)

    @property
    def junction(self) -> bool:
        return self.layout in JUNCTION_LAYOUTS or bool(self.legs)

    def describe(self) -> dict:
        return {"layout": self.layout, "control": self.control, "min_lanes": self.min_lanes,
                "one_way": self.one_way, "needs_oncoming": self.needs_oncoming, "ego_turn": self.ego_turn,
                "legs": [list(x) for x in self.legs], "needs_shoulder": self.needs_shoulder}


def lanes_needed(sketch: Sketch) -> int:
    """Least number of AV-direction lanes the same-road lane relations and lane changes need."""
    need = 1
    left = right = 0
    for p in sketch.npcs:
        if p.position in ("R5", "R6") and p.category not in ("pedestrian",):
            if p.lane == "left":
                left = 1
            elif p.lane == "right" and p.category not in ("bicycle", "scooter"):
                right = 1  # riders on the right ride the bike lane / curb; cars need a lane
            if p.lane == "same" and any(c in "fg" for c in p.actions):
                # the party changes out of (or back into) the AV's lane: one lane beside it
                if "f" in p.actions:
                    left = max(left, 1)
                if "g" in p.actions:
                    right = max(right, 1)
    for o in sketch.obstacles:
        if o.position in ("R5", "R6") and o.lane == "left" and o.category in ("parked_vehicle",):
            left = 1
    ego_left = sketch.ego.actions.count("f")
    ego_right = sketch.ego.actions.count("g")
    need = max(need, 1 + left + right, 1 + ego_left, 1 + ego_right, 1 + min(ego_left, 1) + min(ego_right, 1))
    return need


def derive_constraints(sketch: Sketch) -> RoadConstraints:
    layout = sketch.road.layout
    legs = tuple((LEG_OF_POSITION[p.position], first_turn(p.actions)) for p in sketch.npcs
                 if p.position in LEG_OF_POSITION)
    needs_oncoming = any(p.position == "R7" for p in sketch.npcs) or sketch.road.one_way is False or any(
        o.position == "R7" for o in sketch.obstacles)
    needs_shoulder = any(o.lane == "shoulder" for o in sketch.obstacles) or any(
        p.category in ("bicycle", "scooter", "pedestrian") and p.lane in ("right", "left")
        for p in sketch.npcs if p.position in LANED_POSITIONS)
    min_lanes = max(sketch.road.lanes or 1, lanes_needed(sketch))
    return RoadConstraints(layout=layout, control=sketch.road.control, min_lanes=min_lanes,
                           one_way=sketch.road.one_way, needs_oncoming=needs_oncoming,
                           ego_turn=first_turn(sketch.ego.actions), legs=legs, needs_shoulder=needs_shoulder,
                           stated_lanes=sketch.road.lanes is not None)
