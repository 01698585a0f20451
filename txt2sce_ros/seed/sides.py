"""Where a party starts relative to the AV, read by the project's one definition of the sketch's relative positions
(`analysis.features.derived_position`: R1-R7 + lane from two poses), so the planner can check that a party starts
on the side of the AV the report puts it (sketch.md "Relative positions").

A party whose first action is a crossing (`m`) is read by where it stands, not by the way it faces: the spec places
a pedestrian or rider about to cross (and a car about to pull out of a driveway) by its place beside the road; its
heading across the AV's path would read as crossing traffic (R1/R3) wherever it stood.
"""

from __future__ import annotations

import math

from ..analysis.features import derived_position
from .actor import Actor

#: m a start must lie inside its reported side (ahead of / behind the AV): the player places a lane position a few
#: centimetres from the plan's samples, and a start on the boundary would read either way.
SIDE_MARGIN = 0.5


def start_pose(actor: Actor) -> tuple[float, float, float]:
    """World (x, y, heading) of the actor's reference point at t=0, as its Init teleport places it."""
    p = actor.track.world(actor.d0, actor.lat0)
    return p.x, p.y, p.h


def start_position(ego: Actor, actor: Actor, *, by_place: bool = False,
                   nudge: float = 0.0) -> tuple[str, str | None]:
    """(R-code, lane) of the actor's start in the AV's start frame. `by_place`: read by where it stands (the AV's
    heading stands in for its own); `nudge`: the actor moved that many metres along the AV's heading first."""
    ex, ey, eh = start_pose(ego)
    x, y, h = start_pose(actor)
    x, y = x + nudge * math.cos(eh), y + nudge * math.sin(eh)
    return derived_position((ex, ey, eh), (x, y, eh if by_place else h))


def reported_code(position: str, lane: str | None) -> tuple[str, str | None]:
    """The sketch's (position, lane) in derived_position's terms: a lane only for R5-R7."""
    return position, (lane if position in ("R5", "R6", "R7") else None)


def on_reported_side(ego: Actor, actor: Actor, position: str, *, by_place: bool = False) -> bool:
    """Whether the actor starts at the reported R-code, SIDE_MARGIN m inside it (ahead of / behind the AV)."""
    return all(start_position(ego, actor, by_place=by_place, nudge=n)[0] == position
               for n in (0.0, -SIDE_MARGIN, SIDE_MARGIN))
