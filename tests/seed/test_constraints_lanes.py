"""Road constraints and the paper's lane-assignment rules, on hand-labelled dev sketches."""

from __future__ import annotations

import dataclasses

from txt2sce_ros.seed.constraints import derive_constraints, first_turn
from txt2sce_ros.seed.lanes import CURB, case1_lane, ego_lane, party_lane


def test_constraints_from_real_sketches(gold) -> None:
    # AV changes lane left (f) on a 2-lane road with a barrier on its left
    c = derive_constraints(gold["dmvca-ponyai-20211028-r235"])
    assert c.layout == "straight" and c.min_lanes == 2 and not c.junction
    # a party on the crossing road to the AV's right (R3) turning left
    c = derive_constraints(gold["dmvca-waymo-20240411-r574"])
    assert c.junction and c.legs == (("right", "left"),) and c.control == "signal"
    # an oncoming truck (R7) needs an opposite-direction lane beside the AV
    c = derive_constraints(gold["nhtsa-sgo-ads-30270-7938-v1"])
    assert c.needs_oncoming and c.needs_shoulder


def test_first_turn() -> None:
    assert first_turn("ad") == "left" and first_turn("ehkf") == "right" and first_turn("aj") == "uturn"
    assert first_turn("agg") == "straight"


def test_case1_follows_the_first_lane_constraining_action() -> None:
    turns = {"left": [0], "right": [2], "uturn": [0]}
    assert case1_lane("ad", 3, can_turn=turns) == 0          # leftmost left-turn lane
    assert case1_lane("afd", 3, can_turn=turns) == 1         # starts right of it to change left before turning
    assert case1_lane("ae", 3, can_turn=turns) == 2          # rightmost right-turn lane
    assert case1_lane("af", 3) == 1                          # a lane right of the leftmost
    assert case1_lane("a", 3) == 0                           # default leftmost


def test_case2_av_lane(gold) -> None:
    # van behind in the AV's lane changes left: AV goes rightmost feasible
    s = gold["dmvca-apple-20211111-r241"]
    idx, why = ego_lane(s, 2)
    assert idx == 1 and "rightmost" in why
    # truck passing on the left: AV rightmost
    s = gold["dmvca-cruise-20230303-r431"]
    assert ego_lane(s, 3)[0] == 2
    # nothing forcing a move: leftmost
    s = gold["dmvca-apple-20231013-r537"]
    assert ego_lane(s, 3) == (0, "default leftmost")


def test_case2_party_lane(gold) -> None:
    s = gold["dmvca-apple-20211111-r241"]
    p = s.npcs[0]
    assert party_lane(p, 1, 2) == 1
    left = dataclasses.replace(p, lane="left")
    right = dataclasses.replace(p, lane="right")
    assert party_lane(left, 1, 2) == 0
    assert party_lane(right, 1, 2) == CURB     # nothing right of the rightmost lane: the curb
