"""A resolved position (the world's answer to every OpenSCENARIO Position) and the heading rule applied to one.

The world resolves lane, road and relative positions into a `Pose`; `syntax/positions.py` builds the OpenSCENARIO
Position records that ask for them. The world knows nothing of the syntax: an Orientation reaches it as anything
with `apply(base_heading)`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol


@dataclass(frozen=True, slots=True)
class Pose:
    """A resolved position. Lane fields are set when the position lies on a lane (offset: OpenSCENARIO sense,
    positive toward +t of the road)."""

    x: float
    y: float
    h: float
    road_id: str | None = None
    lane_id: int | None = None
    s: float | None = None
    offset: float = 0.0


class HeadingRule(Protocol):
    """An orientation: the heading it gives, from the heading of the road or reference at the position (rad)."""

    def apply(self, base: float) -> float: ...
