"""Initial lane assignment (paper §III-B.2, step 2), on abstract lane indices.

Index 0 is the leftmost lane in the direction of travel, n-1 the rightmost. The map layer turns indices into
OpenDRIVE lane ids afterwards.

- Case 1 (party not on the AV's road segment: R1–R4, R7): the lane follows the party's own action string; the
  first action that constrains the lane decides (`d`: leftmost lane that can turn left, `e`: rightmost that can
  turn right, `f`: a lane right of the leftmost, `g`: a lane left of the rightmost, `j`: leftmost), else leftmost.
- Case 2 (same segment: R5, R6): the AV first: leftmost by default, the rightmost feasible lane when a party
  overtakes or passes on its left, changes left out of the AV's lane, or changes right from another lane; then each
  party by its `lane` relation (left = AV-1, same = AV, right = AV+1; riders/pedestrians right of the rightmost
  lane go to the curb).
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence

from ..errors import InputError
from ..sketch import Party, Sketch

CURB = -1  # sentinel index: beyond the rightmost driving lane (bike lane, parking lane, sidewalk edge)


def case1_lane(actions: str, n: int, *, can_turn: dict[str, Sequence[int]] | None = None) -> int:
    """Lane index (0 = leftmost) for a party off the AV's segment, from its first lane-constraining action.
    `can_turn` maps 'left'/'right'/'uturn' to the indices that have that connection (default: leftmost / rightmost)."""
    turns = can_turn or {}
    for k, c in enumerate(actions):
        if c == "d":
            # Later lane changes before the turn shift the start lane rightward ("afd": start right of the turn lane)
            shift = actions[:k].count("f") - actions[:k].count("g")
            lanes = sorted(turns.get("left", [0]))
            return min(max(lanes[0] + shift, 0), n - 1)
        if c == "j":
            lanes = sorted(turns.get("uturn", turns.get("left", [0])))
            return lanes[0]
        if c == "e":
            shift = actions[:k].count("g") - actions[:k].count("f")
            lanes = sorted(turns.get("right", [n - 1]))
            return min(max(lanes[-1] - shift, 0), n - 1)
        if c == "f":
            return min(1, n - 1)
        if c == "g":
            return 0
    return 0


def _is_rider_or_walker(p: Party) -> bool:
    return p.category in ("bicycle", "scooter", "pedestrian")


def ego_lane(sketch: Sketch, n: int) -> tuple[int, str]:
    """Case 2 AV lane index and the reason, for a road with `n` AV-direction lanes."""
    same_segment = [p for p in sketch.npcs if p.position in ("R5", "R6")]
    rightmost = False
    reason = "default leftmost"
    for p in same_segment:
        if _is_rider_or_walker(p) and p.lane != "left":
            continue
        if p.lane == "left" and (p.position == "R6" or "f" not in p.actions):
            rightmost, reason = True, f"{p.id} passes on the left"
        elif p.lane == "same" and "f" in p.actions:
            rightmost, reason = True, f"{p.id} changes left out of the AV's lane"
        elif p.lane in ("left",) and "g" in p.actions:
            rightmost, reason = True, f"{p.id} changes right from another lane"
    ego_acts = sketch.ego.actions
    lo = 0
    hi = n - 1
    # Feasibility: every lane the parties and the AV's own lane changes need must exist.
    need_left = ego_acts.count("f") + (1 if any(p.lane == "left" and not _is_rider_or_walker(p)
                                                 for p in same_segment) else 0)
    need_right = ego_acts.count("g") + (1 if any(p.lane == "right" and not _is_rider_or_walker(p)
                                                  for p in same_segment) else 0)
    need_right = max(need_right, 1 if any(p.lane == "same" and "g" in p.actions for p in same_segment) else 0)
    need_left = max(need_left, 1 if any(p.lane == "same" and "f" in p.actions for p in same_segment) else 0)
    lo = min(need_left, n - 1)
    hi = max(n - 1 - need_right, 0)
    if lo > hi:
        raise InputError(f"{n} lane(s) cannot hold the reported lane relations (need {need_left} left, "
                         f"{need_right} right of the AV)", source=sketch.report_id, element="road.lanes")
    if any(p.position == "R7" and p.lane == "left" for p in sketch.npcs):
        # the oncoming lane beside the AV: only the leftmost lane has it
        return lo, "oncoming party beside the AV: leftmost"
    if rightmost:
        return hi, f"rightmost feasible ({reason})"
    return lo, reason if lo == 0 else f"leftmost feasible ({need_left} lane(s) needed to the left)"


def party_lane(p: Party, ego_index: int, n: int) -> int:
    """Case 2 party lane index (CURB for a rider or pedestrian right of the rightmost lane)."""
    if p.lane == "same" or p.lane is None:
        return ego_index
    if p.lane == "left":
        return max(ego_index - 1, 0) if ego_index > 0 else 0
    idx = ego_index + 1
    if idx >= n:
        return CURB
    return idx


def lane_indices(ids_left_to_right: Iterable[int]) -> list[int]:
    """Helper for the map layer: OpenDRIVE lane ids ordered left to right in the driving direction."""
    return list(ids_left_to_right)
