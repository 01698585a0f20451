"""A challenge set for the offline extractor: 235 narratives written by the team in the styles real reports
use (Cruise, Waymo, Zoox, Apple, Pony.ai, WeRide, Nuro, first-person, NHTSA), each a common conflict pattern, with
the sketch slots a person reads from it labelled under sketch.md (`challenge_narratives.jsonl`).

None is taken from a gold or held-out report: they exist to find phrasings the rules miss, so a rule that fixes one
fixes a kind. Six batches were written in one go and scored before any rule was changed for them (a first, honest
reading of text the rules had not seen): 057-071, short, 12/15 positions, 10/15 events, 14/15 AV strings; 072-081,
long with the reports' boilerplate, 7/10, 9/10, 8/10; 082-091, stopped parties and junction legs, 6/11, 9/11, 9/10;
092-101, parties at junctions on the AV's own road or a crossing one, 10/10, 8/10, 10/10 (three of the labels
corrected to the spec after that scoring); 102-111, lane sides and ahead/behind, 9/10, 8/10, 9/10; 112-119, standing
starts, 6/8, 7/8, 8/8 (two labels corrected to the spec after scoring). Batch 120-135, left-side parties (R5/R6 left)
and junction legs, scored before any fix: 11/16, 13/16, 13/16; 136-147, same-direction parties turning at junctions,
left-turn pockets, stop-sign legs, scored before any fix: 8/12, 8/12, 11/12; 148-149, "oncoming" said of other traffic
in a later clause: 1/2, 0/2, 1/2; 150-157, parties behind and beside, passing a parked AV, reversing: 6/8, 4/8, 6/8;
158-163, NHTSA style (redacted streets, intercardinal headings, V1/V2): 6/6, 6/6, 6/6; 164-168, parties in the lane to
the AV's left, another operator's car ('a Lyft vehicle' in a Cruise report): 4/5, 4/5, 3/5 (one label corrected to the
spec after scoring, one narrative with a contested label dropped). Session 6: 300-315, parties beside the AV ahead
of or behind it in reports' wording, scored before any fix: 16/16, 11/16, 15/16 (one AV label corrected after
scoring); 316-327, parties coming up from behind in a lane beside the AV without the words "behind" or "pass"
(squeezing between the AV and the curb, "move past", "rode up on the right side", "approaching" a standing AV, "at a
higher rate of speed", California lane numbers, a rider "lane-splitting"), scored before any fix: 4/13, 6/13, 9/12
(two event labels corrected after scoring); 400-413, events told in progress ("was making a right turn", "a truck
merging onto the freeway"), a move the AV was forced or caused to make, a repeated contact (the string ends at the
first), lane changes into the AV's lane ("changed into the AV's lane", "moved over into the middle lane in front of"),
a party named by its manoeuvre ("a parallel parking SUV", "a reversing box truck"), an animal and thrown debris,
scored before any fix: 12/13, 8/13, 12/14 (one AV label corrected to the spec after scoring: slowing opens with `a`);
328-341, left-side parties ahead, the opposite approach told without "oncoming" ("waiting to turn left from the
opposite side of the intersection"), a pedestrian stepping from the corner into the crosswalk of the AV's exit leg, scored before any fix: 11/14, 9/14, 14/14 (one position label made consistent
with 058 and one event label corrected after scoring);
414-417, the AV stopping and then moving off before the contact (into a double-parked truck, a cone, past a parked
car, into the next lane), scored before any fix: 0/2, 1/2, 0/4 (one AV label corrected after scoring: going around
the truck is a lane change, `ahif`); 418-420, a sign's "vehicles must merge left" (no one's move), "many cars went
around" (an unnumbered group's move), a stop then a lane change, moving off on green, a party partly entering the lane
ahead, scored before any fix: 3/3, 1/3, 0/3 (after: 2/3, 2/3, 3/3; 419's position lost: "a sedan that was also going
around" with no object is not read as passing); 421-422, numbered parties ("Pedestrian 1 and Pedestrian 2",
"Vehicle 3, a pickup truck,"), scored before any fix: 3/4, 2/4, 2/2, and unchanged after (the numbering now keeps
the parties apart; who was waiting and a chain collision's pushed car still miss); 423-424, moving into a turn lane,
a start from where the AV waited at a light and a later stop, scored before any fix: 1/1, 1/1, 0/2; after 1/1, 1/1,
1/2 (424 still misses: "the shuttle" is not read as the AV, and "the bus stop" is read as it). Scored per party (position with lane, events) and
per report (the AV's start and actions), a party matched by category.

A second file, `challenge_positions.jsonl`, holds the batches written while the position rules were worked on beside
the events work (one file each, so the two can grow at once): 342-355, crossing-road parties told by compass heading
only, parties ahead rolling back or reversing, first-person lanes ("the through lane to our right"), scored before any
fix: 12/13, 8/13, 14/14; 356-367, NHTSA wording (SV/CP, V1/V2, "the ADS vehicle"), a pedestrian crossing the street the
AV turns onto without the word crosswalk, a stop in a left-turn pocket (a junction), scored before any fix: 8/11, 6/11,
10/12 (one narrative with a contested label dropped, one event label corrected after scoring); 368-377, long multi-party
reports (a party going around slowing traffic from behind, a cyclist riding between a standing AV and parked cars, "half
a car length ahead", "our test vehicle"), scored before any fix: 10/13, 7/13, 8/10 (one position label corrected after
scoring: a rider moving into the lane who strikes the AV's mirror was alongside). Four category labels in both files
were corrected to the spec's `van` (minivans, delivery vans) after scoring; a party is matched by category first.
378-385, same-direction parties in the lane to the AV's left (or a left-turn lane) turning across it at a junction,
scored before any fix: 8/8, 1/8, 8/8 (five event labels corrected to the spec after scoring: a party told travelling
before it turns opens with `a`). Session 7: 430-441, parties' sideways moves told without "changed lanes" ("shifted
over toward the center lane", "edged left", "crossed over the lane line into the AV's lane", "moved toward our lane"),
scored before any fix: 11/12, 7/12, 12/12 (two event labels corrected to the files' convention after scoring: a party
not told travelling before its move opens with that move, as 339 does); 442-453, parties whose standing or moving
is told indirectly ("stalled in the lane ahead", "a taxi parked at the curb ahead", "which had begun to move forward",
a cyclist entering the roadway from the curb, a pedestrian stepping off the median), scored before any fix: 12/14,
8/14, 10/12; after 13/14, 11/14, 11/12; 454-461, same-direction parties beside the AV at junctions ("in the lane to
its left made a right turn across", two left-turn lanes with a truck that "swung wide into" the AV's lane, a car
"parked along the left curb" that "pulled out"), scored before any fix: 6/8, 4/8, 8/8; after 7/8, 8/8, 8/8; 462-473,
the AV's own manoeuvres (slowing to a stop, moving over around a double-parked truck into a motorcyclist's lane, a lane
change "to prepare for a right turn" named again as "the lane change", reversing out of a space, proceeding on green
into a red-light runner that struck its passenger side), scored before any fix: 7/11, 9/11, 11/12; after 10/11, 10/11,
12/12; 474-477, chain collisions (a party told after the AV's contact that strikes another party), scored before any
fix: 6/8, 5/8, 4/4; after 7/8, 6/8, 4/4 (474 still misses: "a pickup truck following the sedan" is taken for the sedan).
Session 10: 600-648, parties in the lane to the AV's left or right told by their place on the road, by the point of
contact on the AV ("struck on the right rear quarter panel by a vehicle ... in the lane to the AV's right"), left
turns across the AV's path from the opposite approach, side words that are not the party's ("right of way", "its
left turned"), lane changes told as drifting over the lane line or swinging out into the oncoming lane, scored before
any fix: 35/38, 32/38, 33/37 (four narratives with contested labels dropped, six labels corrected to the files'
conventions after scoring); after 36/38, 35/38, 34/37.
Session 14: eight AV labels (052, 081, 127, 144, 153, 325, 402 here, 453 in the positions file) changed from `ac`/`ah`
to `c`/`h`: the official gold opens the AV's string with a slowing or a pull-over told under way ("was slowing and
moving at approximately 2 mph", dev_gold r376, `c`; "was pulling over ..., when", r508, `l`), as do the study sets'
annotators (study2 s213, study3 30291-7677: "was slowing to a stop ... when", `h`; study3 30270-10649: "was traveling
southbound ... and was slowing to a stop for a passenger drop-off when", `h`); a run told first in a sentence of its
own stays (study2 s250, `ah`).

    python -m tests.text.challenge          # figures and every miss, per file
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path

from txt2sce_ros.text.extractor import extract

DATA = Path(__file__).with_name("challenge_narratives.jsonl")
POSITIONS = Path(__file__).with_name("challenge_positions.jsonl")


@dataclass
class ChallengeScore:
    parties: int = 0
    position: int = 0
    events: int = 0
    reports: int = 0
    ego: int = 0
    misses: list[str] = field(default_factory=list)


def score(path: Path = DATA) -> ChallengeScore:
    sc = ChallengeScore()
    for line in path.read_text(encoding="utf-8").splitlines():
        case = json.loads(line)
        sk = extract(case["text"], case["id"])
        sc.reports += 1
        ego = (sk.ego.start, sk.ego.actions)
        want_ego = (case["ego"]["start"], case["ego"]["actions"])
        sc.ego += ego == want_ego
        if ego != want_ego:
            sc.misses.append(f"{case['id']} ego {ego} want {want_ego}")
        got = list(sk.npcs)
        for want in case["npcs"]:
            sc.parties += 1
            same = [g for g in got if g.category == want["category"]] or got
            p = next((g for g in same if (g.position, g.lane) == (want["position"], want["lane"])),
                     same[0] if same else None)
            if p is not None:
                got.remove(p)
            pos = (p.position, p.lane) if p else None
            if pos == (want["position"], want["lane"]):
                sc.position += 1
            else:
                sc.misses.append(f"{case['id']} position {pos} want {(want['position'], want['lane'])}")
            ev = (p.start, p.actions) if p else None
            if ev == (want["start"], want["actions"]):
                sc.events += 1
            else:
                sc.misses.append(f"{case['id']} events {ev} want {(want['start'], want['actions'])}")
    return sc


def main() -> None:
    for path in (DATA, POSITIONS):
        sc = score(path)
        print(f"{path.name}: {sc.reports} narratives, {sc.parties} parties")
        print(f"  npc position (with lane) {sc.position}/{sc.parties} = {100 * sc.position / sc.parties:.1f}%")
        print(f"  npc events (start + actions) {sc.events}/{sc.parties} = {100 * sc.events / sc.parties:.1f}%")
        print(f"  AV start + actions {sc.ego}/{sc.reports} = {100 * sc.ego / sc.reports:.1f}%")
        for m in sc.misses:
            print("  miss:", m)


if __name__ == "__main__":
    main()
