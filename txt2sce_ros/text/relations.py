"""A party's place relative to the AV, read from the scene as a person reads it, with explicit precedence.

`positions.party_position` gives a first reading from phrase patterns. Here the evidence a person weighs is
gathered as `Cue`s, each from one kind of fact the narrative states about the party:

| kind | values | read from |
|---|---|---|
| `lane` | left / right / same | "in the lane to the left of EGO", "left adjacent lane", "bike lane", "on EGO's right" |
| `along` | behind / ahead | "behind", "following", "from the rear", "ahead of EGO", "in front of EGO" |
| `passing` | behind (+ side) | "passing/overtaking EGO on the left", "to get around the queue": it came from behind |
| `contact` | front / rear, left / right | the part of the AV the party touched ("left rear corner", "passenger door") |
| `direction` | opposite, path | "oncoming", "opposite direction"; "the oncoming lane", "the wrong side of the road"|

(a side of the street told by compass, "on the west side of 2nd Avenue", is a `lane` cue read against the AV's
heading) and combined in a fixed order, highest first, so a rule can be read and its weight seen:

0. A pedestrian or rider the turning AV meets at a junction, in a crosswalk or yielded to, is on the leg the AV
   turns onto (R4).
1. A party travelling the other way keeps the first reading (R2 at a junction, R7 elsewhere); one that drives the
   opposing lane to pass is behind (R6); one read onto a crossing road but said to come "from the opposite direction"
   is the opposite approach (R2).
2. Along the AV's road (R5/R6): an explicit `along` cue (nearest the party's name first) decides front/behind; else
   `passing` (behind); else the contact on the AV's rear half (behind) or front half (ahead) for a party not backing
   up; else a party moving in the lane beside an AV that stood throughout and touching its side passed it (behind);
   else the first reading. A vehicle going on ahead of which the text tells nothing but the side of the AV it
   struck (no heading, side, lane or end of the AV; no turn or lane change of its own), met at a junction by an AV
   turning left and not on the AV's rear, came from the opposite approach (R2: a left turn across the path of
   oncoming traffic).
3. The lane: a party said to stand behind the AV ("stopped behind EGO") that then passes it on a side is in the AV's
   lane (it moves out to pass); else an explicit `lane` cue (one said relative to the AV before a lane's name on
   the road); else the side the `passing` cue names; else the side of the AV the party touched, for a party ahead or
   passing (one behind that strikes a rear corner was most often right behind); else the first reading. Only what
   the text tells of the party up to the contact places it.
4. A cyclist or scooterist read in the AV's lane from no explicit same-lane phrase rides at the road's edge: on the
   side of the AV it touched, else the curb side (right).

Each decision records the rule that made it and the cue spans (offsets into the normalised text) as evidence.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from . import fastre as fre
from .fastre import compile_gated
from .mentions import Entity, Mention
from .positions import (AV_CLAUSE, BACKING, COMPASS_SIDE_OF, FROM_BEHIND, PLACE_SIDE, YIELDED_TO, exit_street,
                        side_from_flank)
from .lexicon import CARDINALS
from .scene import _STANDING as STANDING
from .story import ONCOMING, TURN_WORDS, Doc, before_contact, context, ego_contact_part, ends_phrase, heading

_SIDE = r"(left|right|driver(?:'s)?|passenger(?:'s)?)"
# Explicit lane relations to the AV, said of the party ("in the lane to the right of EGO", "the left adjacent lane").
_LANE_CUES = compile_gated(
    r"\b(?:lane|lanes)\s+(?:immediately\s+|directly\s+)?to\s+(?:the\s+|our\s+|EGO's\s+)?(left|right)(?:\s+of\s+(?:EGO|it|us))?|"
    r"\b(left|right)(?:-hand|most)?\s+(?:adjacent\s+|neighbou?ring\s+|parallel\s+)?(?:travel\s+)?lane\b|"
    r"\b(?:adjacent|neighbou?ring)\s+(left|right)\s+lane\b|"
    r"\bto\s+(?:the\s+)?(left|right)\s+(?:side\s+)?of\s+(?:EGO|us)\b|"
    # (not a part of the AV's body: "minor damage to EGO's right rear bumper")
    r"\b(?:on|to)\s+(?:EGO's|our)\s+(left|right)\b(?![- ](?:(?:front|rear|back)\b|(?:side[- ])?(?:door|corner|quarter|"
    r"fender|mirror|bumper|wheel|tire|panel)))|"
    r"\bon\s+its\s+(left|right)\b|"
    # "merged into its lane from the left": where it came from, beside the AV
    r"\binto\s+(?:EGO's|its|our)\s+lane\s+from\s+(?:the\s+|EGO's\s+|its\s+)?(left|right)\b(?!\s+(?:turn|side\s+of))|"
    # "a sedan stopped to its left": a party is not beside itself, so "its" is the AV (a move "to its left" is not)
    r"(?<!veered\s)(?<!swerved\s)(?<!steered\s)(?<!moved\s)(?<!merged\s)(?<!drifted\s)(?<!turned\s)"
    r"\bto\s+its\s+(left|right)\b|"
    r"\b(?:on|along)\s+the\s+(left|right)\s+(?:side\s+)?of\s+EGO\b|"
    # "to the rear left of EGO", "to the left and slightly behind EGO": a side and an end together
    r"\bto\s+(?:the\s+)?(?:rear|front)\s+(left|right)\s+of\s+EGO\b|"
    r"\bfrom\s+(?:behind|the\s+rear)\s+on\s+the\s+(left|right)\b|"
    r"\bto\s+(?:the\s+)?(left|right)\s+and\s+(?:slightly\s+|just\s+)?(?:behind|ahead\s+of|in\s+front\s+of)\s+EGO\b|"
    r"\bbetween\s+(?:the\s+)?EGO\s+and\s+(?:the\s+)?(curb|sidewalk|shoulder|median|parked\s+cars)\b|"
    r"\b(bike\s+lane|bicycle\s+lane|sidewalk|parking\s+lane|curb\s+lane|curbside|shoulder|median)\b|"
    # "a taxi parked at the curb ahead": the curb is on the right unless a side is named
    r"(?<!left\s)(?<!right\s)\b(?:at|along|by|near)\s+the\s+(curb)\b", re.I)
# A side of the AV's body: "left rear corner", "rear passenger door", "driver's side", "front right fender".
_PART = r"(?:side|rear|front|door|corner|quarter|fender|mirror|bumper|wheel|tire|panel|pillar|head\s*lamp|head\s*light|" \
        r"tail\s*(?:light|lamp|gate))"
# (police shorthand for a corner, "the RF fender", "its LR bumper": the capital letter is the side)
_BODY_SIDE = compile_gated(rf"\b{_SIDE}[- ](?:(?:front|rear|back|side)[- ])?{_PART}|\b(?:rear|back|front)[- ]{_SIDE}\b|"
                           r"\b(?-i:([LR])[FR])\b", re.I)
# A lane the party moved into is where it went, not where it was.
_INTO = compile_gated(r"\b(?:into|onto|entered|entering|enters|enter|toward|towards|cut\s+in(?:to)?)\s+(?:the\s+)?$", re.I)
_SAME_LANE = compile_gated(r"\b(?:(?:(?:traveling|travelling|driving|riding)\s+(?:directly\s+|closely\s+)?behind|"
                           r"(?:directly\s+|closely\s+)?following)\s+"  # "a sedan following EGO" travels behind it
                           # ("a white pickup truck traveling behind it rear-ended EGO": the AV named by a pronoun)
                           r"(?:(?:the\s+(?:first\s+|second\s+)?)?EGO|it|us)\b"
                           r"(?!\s+(?:and|in\s+the|on\s+the))|same\s+lane|EGO's\s+lane|its\s+lane|in\s+(?:the\s+)?lane\s+(?:of|with)\s+EGO|"
                           r"directly\s+(?:behind|ahead\s+of|in\s+front\s+of)\s+EGO|in\s+the\s+travel\s+lane)\b", re.I)
# ("following behind" alone is the party's place; "EGO was traveling ... following behind a heavy truck" puts the one
# named after it ahead)
_BEHIND = compile_gated(r"\b(?:behind\s+(?:the\s+(?:first\s+|second\s+)?)?(?:EGO|it|us)|"
                        r"following\s+(?:EGO|it|us|behind(?!\s+(?:a|an|another|the)\s+(?!EGO\b)))|trailing\s+(?:EGO|it)|"
                        # following too close: "tailgating EGO", "riding EGO's bumper", "riding the bumper of EGO"
                        r"tail-?gat\w*\s+(?:EGO|it|us)|(?:riding|rode)\s+(?:EGO's|its|our|the)\s+(?:rear\s+)?bumper|"
                        r"from\s+(?:the\s+)?rear|" + FROM_BEHIND + r"|approach\w*\s+from\s+(?:the\s+)?(?:rear|behind)|"
                        r"to\s+EGO's\s+rear|rear\s+of\s+EGO\b(?!'s)(?=[^.]{0,20}\b(?:travel|approach|driv))|"
                        r"rear[- ]?end(?:ed|ing|s)?\s+(?:EGO|it)|rear[- ]?ended\s+by|struck\s+from\s+behind\s+by|(?:came|come|coming|pulled|pulling)\s+up\s+behind|"
                        r"to\s+the\s+rear\s+of\s+EGO|in\s+the\s+rear\s+of\s+EGO|to\s+(?:the\s+)?rear\s+(?:left|right)\s+of\s+EGO|closing\s+(?:in\s+)?on\s+EGO\s+"
                        r"from\s+behind|"
                        # came up beside the AV, tried to get ahead of it, went faster than it: it was behind
                        r"(?:rode|riding|ride|came|coming|come|pulled|pulling|drove|driving|moved|moving)\s+up\s+"
                        r"(?:on|along|beside|alongside|next)\b|(?:get|getting|got|pull|pulling|pulled)\s+ahead\s+of\s+"
                        r"EGO|(?:at|with)\s+a\s+(?:much\s+)?(?:higher|greater|faster)\s+(?:rate\s+of\s+)?speed|"
                        r"faster\s+than\s+EGO|speeding\s+past|"
                        # "a sedan traveling behind in the left lane": behind said without an object is the AV's
                        r"(?:traveling|travelling|driving|riding|coming|approaching)\s+(?:directly\s+|closely\s+)?"
                        r"behind(?=\s+(?:in|on|at|and|,|\.)|$))", re.I)
_AHEAD = compile_gated(r"\b(?:ahead\s+of\s+EGO|in\s+front\s+of\s+EGO|preceding\s+EGO|leading\s+EGO|"
                       r"(?:directly|immediately)\s+ahead|just\s+ahead|(?:lead|preceding)\s+vehicle)\b", re.I)
_PASSING = compile_gated(r"\b(?:pass(?:ed|ing|es)?|overtak(?:e|ing|en)|overtook|lane[- ]split\w*|"
                         r"(?:rode|riding|ride|drove|driving|drive|went|going|go|came|coming|come|moved|moving|move|get|"
                         r"getting|got|"
                         r"accelerat\w+|sped|speeding|raced|racing|zoomed|pulled|pulling)\s+past|"
                         # "went by the Waymo AV on the left": by the AV itself (the side read below)
                         r"(?:rode|drove|went|came|moved|got|sped|zoomed|pulled)\s+by(?=\s+(?:the\s+)?(?:\w+\s+)?EGO\b)|"
                         # squeezing between the AV and the curb, filtering through queued traffic: a pass
                         r"squeez\w*\s+(?:between|past|by|through)|filter\w*\s+(?:between|past|through)|"
                         # "a motorcyclist riding between EGO and a pickup truck": splitting the lane beside it
                         r"(?:rode|riding|rides|traveling|travelling|driving|moving|went|going)\s+between\s+(?:EGO\b|$)|"
                         # riding on between a standing AV and the curb or parked cars (place() keeps it to a
                         # standing AV: beside a moving one it may be alongside)
                         r"(?P<between>(?:rode|riding|ride|traveling|travelling|driving|drove|moving|going|went)\s+"
                         r"(?:\w+\s+){0,2}between\s+EGO\s+and)|"
                         r"(?:go|going|went|get|getting|got|come|came|coming|drive|drove|driving|maneuver\w*|manoeuvr\w*|"
                         # ("swerved around EGO", "pulled around the stopped EGO": any verb of a move with "around")
                         r"steer\w*|swerv\w*|veer\w*|pull\w*|cut|cutting|mov\w*|dart\w*|swung|swing\w*|whip\w*|"
                         r"travel\w*|rode|ride|riding|proceed\w*|head\w*|zip\w*|shot|shoot\w*)\s+around(?=\s+(?:the\s+"
                         r"(?:left|right)\s+side\s+of\s+)?(?:the\s+)?(?:\w+\s+)?EGO)|"
                         # "a sedan that was also going around": the same pass as the traffic told before it
                         r"also\s+(?:going|driving|moving|getting)\s+(?:around|past)(?!\s+(?:a|an|the)\s+(?!EGO))|"
                         r"split(?:ting)?\s+(?:the\s+)?lanes?)\b(?:\s+(?:by\s+)?(?:the\s+)?(?:EGO|it))?"
                         # the side it passed on: "on the left", "on its left", "on EGO's driver side"
                         r"(?:[^.|]{0,40}?\bon\s+(?:the\s+|EGO's\s+|its\s+)?(?P<side>left|right|driver|passenger))?", re.I)
# Lanes named by their place on the road ("the right lane", "the middle lane", "the leftmost lane"): relative to the
# AV only once the AV's own lane is known. Scale: 0 leftmost ... 9 rightmost.
# "the number 1 lane": California's numbering, 1 the leftmost (fast) lane.
# (the lanes named by their use: the fast, inside, HOV or carpool lane is the leftmost; the slow, outside or curb
# lane the rightmost)
_ABS_LANE = compile_gated(r"\b(?:in|within|from|into|of)\s+the\s+(?:(far|second|third)\s+)?(left|right|middle|center|centre|"
                          r"fast|slow|inside|outside|curb|hov|carpool)"
                          # ("the right most lane": the word split as some operators write it)
                          r"(?:-?\s?most)?\s+(?:(?:travel|through|traffic|turn)\s+)?lane\b(?:\s+from\s+the\s+(left|right))?|"
                          r"\b(?:in|from|into|of)\s+(?:the\s+(?:number|no\.?|#)\s*(\d|one|two|three|four|five)\s+lane|"
                          r"lane\s+(?:number\s+|no\.?\s*|#)?(\d|one|two|three|four|five)(?![\d,]|\.\d))\b|"
                          # "in the right of two travel lanes", "in the leftmost of two through lanes", "in the center of
                          # three southbound lanes"
                          r"\b(?:in|from|into|of)\s+the\s+(left|right|middle|center|centre)(?:-?\s?most)?\s+of\s+(?:the\s+)?"
                          r"(?:two|three|four|five|[2-5])\s+(?:[\w-]+\s+)?lanes\b", re.I)
_INTO_LANE = compile_gated(r"\b(?:into|onto)\s+(?:the\s+|EGO's\s+)?(?:[\w-]+\s+){0,2}lane\s+$", re.I)
# The AV is the subject of the clause that ends in "behind it" ("EGO, which had stopped behind it", "EGO came to a
# stop behind it"): the AV is behind. Not "EGO slowed for a motorcyclist behind it", where "it" is the AV.
_EGO_CLAUSE = compile_gated(r"\bEGO(?:,\s*which|\s+(?:was|had|then|also))\b[^.;,]{0,40}$|"
                            r"\bEGO\s+(?:came|stopped|pulled|remained|waited|queued)\b[^.;,]{0,30}?\b(?:stop|stopped|"
                            r"up|waiting|queued|remained)\s+(?:directly\s+|immediately\s+)?$", re.I)
_NUMBERS = {"one": 1, "two": 2, "three": 3, "four": 4, "five": 5}
_OF_PARTY = re.compile(r"\s+of\s+(?:(?:the|a|an)\s+)?", re.I)
_MOVED_TO = compile_gated(r"\b(?:cut|cutting|cuts|pulled|pulling|merged|merging|moved|moving|swerved|swerving|"
                         r"turned|turning|stepped|stepping|darted|ran|walked|rode|veered|maneuver\w*|manoeuvr\w*|"
                         r"(?:changing|change|changed)\s+lanes?|lane[- ]change[sd]?)\s+"
                         # "cut back to the left directly in front of EGO": where it went, a few words on
                         r"(?:(?:back|right|left|directly|suddenly|abruptly|in|into|over|to|the|lane|center|middle|"
                         r"adjacent)\s+){0,6}$", re.I)
# The other party's own front named in the contact sentence ("its front right bumper", "the front of the sedan").
_PARTY_FRONT = compile_gated(r"\b(?:its|their|the\s+(?!EGO)\w+'s)\s+(?:\w+\s+){0,2}?front\b|"
                             r"\bfront\s+(?:\w+\s+){0,2}?of\s+(?:the|a|an|its|their)\s+(?!EGO\b)", re.I)
# Riders who keep to the edge of the road (bike lane, curb side); a motorcycle takes a lane like a car.
_EDGE_RIDERS = ("bicycle", "scooter")
_MOTOR = ("car", "van", "truck", "bus", "motorcycle")
_RIDERS = ("motorcycle", "bicycle", "scooter")
# Riding the line between two lanes of traffic: "lane-splitting", "splitting lanes", "riding between the two lanes",
# "filtering between the stopped cars", "on the lane line", "white-lining".
_SPLITTING = compile_gated(r"\blane[- ]?split\w*|\bsplit(?:ting|s)?\s+(?:the\s+)?(?:lanes?|traffic)\b|"
                           r"\b(?:between|straddl\w*)\s+(?:the\s+)?(?:two\s+|2\s+)?(?:lanes|lane\s+lines?)\b|"
                           r"\bfilter\w*\s+(?:between|past|through)\b|"
                           r"\b(?:on|along|down|straddl\w*)\s+the\s+(?:lane\s+(?:line|divider|marking)|"
                           r"dividing\s+line)s?\b|"
                           r"\bwhite[- ]lin(?:e|ing)\b", re.I)
#: The rule that places a party come out of a driveway, garage, lot or parking space beside or ahead of the AV: it
#: did not travel along the AV's road before its turn (extractor reads its action string so).
OUT_OF_ROADSIDE = "out of a roadside place, not behind"
# A same-lane cue that says so outright, not one inferred from "traveling behind EGO".
_EXPLICIT_SAME = compile_gated(r"\b(?:same\s+lane|EGO's\s+lane|its\s+lane|lane\s+(?:of|with)\s+EGO|directly|"
                               r"travel\s+lane|in\s+front\s+of\s+EGO|ahead\s+of\s+EGO)\b", re.I)
# The traffic the AV stands or moves in ("the queue", "the line of cars", "the stopped traffic"): passing it is
# passing the AV's queue from behind.
_QUEUE = r"(?:queue|line|row|stopped|queued|waiting|slow\w*|backed-up)\b"
_PASSED_OTHER = compile_gated(r"(?:[\w-]+\s+){0,2}?(?:pass(?:ed|ing|es)?|past|around)\s+(?:(?:through|into|across|over|"
                              r"beyond)\s+(?:the\s+|a\s+)?(?:intersection|crosswalk|junction|light|signal|stop|crossing|"
                              r"gate|roundabout)|(?:the|a|an)\s+(?!EGO|(?:left|right|driver|passenger)(?:'s)?\s+side\s+of\s+"
                              # ("the gate arm rose to allow the passenger car to pass through.": through a place)
                              rf"EGO|{_QUEUE})|through\s*(?:[.,;]|$))", re.I)
_PASS_QUEUE = compile_gated(r"\b(?:(?:get|go|going|drive|driving|move|moving|pass|passing|overtake|overtaking|bypass|"
                            r"bypassing|get\w*\s+ahead\s+of|cut\w*)\s+(?:around|past|by|through)?\s*(?:the|a)\s+"
                            rf"(?:long\s+)?{_QUEUE}"
                            r"(?:\s+(?:of\s+)?(?:traffic|vehicles|cars))?|\bbypass(?:ed|ing)?\s+(?:the\s+)?traffic\b)",
                            re.I)
_COMPASS_SIDE = compile_gated(COMPASS_SIDE_OF + r"\s+(?:the\s+)?"
                              # (a street's name, or its redaction in the SGO narratives: "on the north side of [XXX]")
                              r"(?:street|road|roadway|block|(?:(?-i:[A-Z0-9])[\w-]*\s+){1,3}(?:street|st|avenue|ave|"
                              r"boulevard|blvd|road|rd|way|drive|dr|lane|ln)|\[XXX\])(?:\b|(?<=\]))|"
                              # a roadside named by its compass side: "from the west sidewalk", "along the eastern curb"
                              r"\b(?:on|from|along|off|at)\s+the\s+(north|south|east|west)(?:ern)?\s+(?:sidewalk|curb|"
                              r"shoulder)\b", re.I)
# The word before a roadside ("the west sidewalk", "the left shoulder", "the far curb"): it names which side, so the
# right-hand default of a curb, sidewalk or shoulder does not hold.
_ROADSIDE_SIDE = compile_gated(r"\b(?:(north|south|east|west)(?:ern)?|(left|right)|opposite|far|other)(?:[- ]hand)?\s+$", re.I)
# A lane cue told as where the party came from: the cue's own "from the rightmost lane", or "from the" before it
# ("from the right lane", "from its left adjacent lane").
_FROM_LANE = compile_gated(r"from\s", re.I)
_FROM_BEFORE_LANE = compile_gated(r"\bfrom\s+(?:the\s+|its\s+|their\s+|EGO's\s+)?$", re.I)
_RELATIVE_LANE = compile_gated(r"\b(?:EGO|us|it|its|our|adjacent|neighbou?ring)\b", re.I)


@dataclass(frozen=True)
class Cue:
    kind: str  # "lane", "along", "passing", "contact", "direction"
    value: str
    span: tuple[int, int]  # offsets into the normalised text (Doc.text)


@dataclass(frozen=True)
class Placement:
    position: str
    lane: str | None
    rule: str  # which cue decided it ("first reading" when none did)
    cues: tuple[Cue, ...]  # the cues that decided (all gathered ones when the first reading stood)
    seen: tuple[Cue, ...] = ()  # every cue gathered
    passed_side: str = ""  # left/right: the side a party standing behind in the AV's lane moved out to, passing it

    @property
    def cue_placed(self) -> bool:
        """A cue of the scene decided the place (along, passing, contact, ...) or named the lane: the place is told."""
        return not self.rule.startswith(("first reading", "left turn across")) or "; lane" in self.rule

    @property
    def conflicting(self) -> bool:
        """Lane cues that disagree: the reading is weak (hybrid mode asks a model)."""
        return len({c.value for c in self.seen if c.kind == "lane"}) > 1


def _side(word: str | None) -> str | None:
    if not word:
        return None
    w = word.lower()
    if w in ("l", "r"):  # the side letter of "LF", "RR"
        return "left" if w == "l" else "right"
    if w.startswith(("left", "driver")):
        return "left"
    if w.startswith(("right", "passenger")):
        return "right"
    if w.startswith(("bike", "bicycle", "sidewalk", "parking", "curb", "shoulder")):
        return "right"  # right-hand traffic: bike lanes, curbs and sidewalks lie to the right
    if w.startswith("median"):
        return "left"  # and the median to the left
    return None


def _mention_windows(d: Doc, e: Entity) -> list[tuple[int, int, int]]:
    """(sentence, start, end) windows where the text speaks of the party before the contact: from its mention to the
    next other party named (or the sentence end), and the clause leading up to it."""
    out = []
    for m in e.mentions:
        if m.sent in d.summary and any(x.sent not in d.summary for x in e.mentions):
            continue
        if d.contact_sent is not None and m.sent > d.contact_sent and \
                any(x.sent <= d.contact_sent and (x.sent not in d.summary or x.sent == d.contact_sent)
                    for x in e.mentions):
            continue  # told after the contact (also one the opening sentence tells): where it went then
        s = d.sents[m.sent]
        end = _clause_end(d, e, m)
        # The words just before the name belong to it only within its clause ("As EGO proceeded in the far right
        # lane, an SUV ..." places the AV, not the SUV).
        pre = s[max(0, m.start - 40):m.start]
        cut = list(fre.finditer(r"[,;]|\b(?:when|as|while|and|then|after|before)\b", pre, re.I))
        start = max(0, m.start - 40) + (cut[-1].end() if cut else 0)
        out.append((m.sent, start, end))
    return out


_LANE_BY_USE = {"fast": "left", "inside": "left", "hov": "left", "carpool": "left", "slow": "right", "outside": "right",
                "curb": "right"}


def _lane_rank(m: re.Match[str]) -> float:
    mod, side, from_side, number, numeral, side_of = (g.lower() if g else "" for g in m.groups())
    number, side = number or numeral, side or side_of
    if number:
        return float(_NUMBERS.get(number) or int(number)) - 1.0
    if side in ("middle", "center", "centre"):
        return 4.5
    side = _LANE_BY_USE.get(side, side)
    if from_side:  # "the second lane from the left"
        k = {"second": 1, "third": 2}.get(mod, 0)
        return k if from_side == "left" else 9 - k
    if mod in ("second", "third"):
        k = {"second": 1, "third": 2}[mod]
        return k if side == "left" else 9 - k
    return 0 if side == "left" else 9


def av_lane_rank(d: Doc) -> float | None:
    """The AV's own lane on the 0 (leftmost) .. 9 (rightmost) scale, when a clause about the AV names it."""
    for i, s in enumerate(d.sents):
        for m in fre.finditer(r"\bEGO\b", s):
            if fre.search(r"\b(?:of|behind|past|beside|between|than|with|by|to|from|passed|struck|hit|contacted)\s+$",
                          s[max(0, m.start() - 12):m.start()], re.I):
                continue  # "a vehicle ahead of EGO in the left lane": the lane is the other party's
            # ("EGO was stopped in traffic while in the leftmost lane": the AV's own state, in its clause)
            clause = fre.split(r"[,;]|\bwhen\b|\bas\b|\bwhile\b(?!\s+(?:in|on)\s+the\b)", s[m.end():m.end() + 120])[0]
            lm = _ABS_LANE.search(clause)
            # A lane said in a relative clause of another party is that party's ("EGO's right rear made contact
            # with a motorcycle that was traveling in the right lane"); "EGO was traveling behind a pickup truck in
            # the right lane" keeps both in it.
            if lm and any(m.end() < x.start and x.end <= m.end() + lm.start() and x.kind in ("party", "obstacle") and
                          fre.search(r"\b(?:that|which|who|was|were)\b", s[x.end:m.end() + lm.start()], re.I)
                          for x in d.ments[i]):
                lm = None
            # "moved into the left lane": where the AV went, not where it was
            if lm and not fre.match(r"(?:into|onto)\b", lm.group(0), re.I) and \
                    not fre.search(r"\b(?:into|onto|toward)\s+the\s+\S+\s*$", clause[:lm.start() + 5], re.I):
                return _lane_rank(lm)
    if AV_AT_CURB.search(d.text):
        # Standing at the right curb, in no travel lane: every lane named on the road is on its left.
        return _CURB_RANK
    return None


def av_lane_number(d: Doc) -> float | None:
    """The AV's lane by its number, counted from the left (0 for "lane 1"), when a sentence that names no other party
    before it numbers the AV's lane ("A Zoox vehicle ... was stopped ... in the left turn lane (lane 2)", "The AV was
    eastbound ..., in the furthest left of five lanes (lane one)"); a party's numbered lane is compared with it."""
    return d.once("av_lane_number", lambda: _read_av_lane_number(d))


_LANE_NUMBER = compile_gated(r"\blane\s+(?:number\s+|no\.?\s*|#)?(\d|one|two|three|four|five)(?![\d,]|\.\d)\b", re.I)


def _read_av_lane_number(d: Doc) -> float | None:
    for i, s in enumerate(d.sents):
        ego = next((m for m in d.ments[i] if m.kind == "ego"), None)
        if ego is None:
            continue
        n = _LANE_NUMBER.search(s, ego.end)
        if n and not any(x.kind == "party" and x.start < n.start() for x in d.ments[i]) and \
                not _INTO.search(s[max(0, n.start() - 25):n.start()]):
            return float(_NUMBERS.get(n.group(1).lower()) or int(n.group(1))) - 1.0
    return None


_CURB_RANK = 10.0  # beyond the rightmost lane (9): the curb, the parking lane
# The AV standing at the right curb, or at the right edge of the road ("was parked along the curb", "was stopped on
# the right side of southwestbound [XXX] for a passenger pick-up").
# (standing told in any of the words the road reading knows: "was sitting", "was at a standstill", "had come to a stop")
AV_AT_CURB = compile_gated(r"\bEGO\b[^.]{0,40}?\b(?:was|had\s+been|had|remained)\s+(?:\w+\s+)?(?:parallel\s+)?"
                           rf"(?:parked|pulled\s+over|{STANDING})\s+(?:(?:at|along|against|by)\s+the\s+"
                           r"(?:right\s+)?curb\b|"
                           r"on\s+the\s+right\s+(?:side|edge|shoulder)\s+of\s+(?:the\s+)?(?:road|roadway|street|"
                           r"(?:north|south|east|west)+bound\b))", re.I)


def thing_origin_lane(d: Doc, e: Entity) -> str | None:
    """The lane (left/right/same) a thing that moved into the AV's path came from, named on the road and read
    against the AV's own lane: "the left front wheel from an SUV traveling in the right most lane ... rolled into EGO's
    lane" (the AV in the middle lane: right), "a domestic animal emerged from a gap between vehicles in the leftmost
    lane" (the AV in the centre of three lanes: left). A lane it went into is where it went, not where it was."""
    own = d.av_lane
    if own is None:
        return None
    for m in e.mentions:
        if d.contact_sent is not None and m.sent > d.contact_sent:
            break
        after = d.sents[m.sent][m.end:m.end + 120]
        for lm in _ABS_LANE.finditer(after):
            if lm.group(0).lower().startswith(("into", "onto")) or _INTO.search(after[max(0, lm.start() - 25):lm.start()]):
                continue
            rank = _lane_rank(lm)
            return "same" if rank == own else "left" if rank < own else "right"
    return None


def gather(d: Doc, e: Entity) -> list[Cue]:
    """Every cue the narrative states about party `e`, in text order."""
    cues: list[Cue] = []
    own = d.av_lane
    for sent, a, b in _mention_windows(d, e):
        s = d.sents[sent]
        win = fre.blank(TURN_WORDS, s[a:b])
        base = d.offset(sent) + a
        absolute = []
        if own is not None:
            for m in _ABS_LANE.finditer(win):
                if fre.search(r"\b(?:adjacent|neighbou?ring)\b", m.group(0), re.I) or \
                        _INTO.search(win[max(0, m.start() - 25):m.start() + 5]):
                    continue
                rank = _lane_rank(m)
                if (number := av_lane_number(d)) is not None and (m.group(4) or m.group(5)):
                    # a numbered lane against the AV's own number: lanes count from the left (police, DMV and
                    # operators number them so: "the left turn lane (lane 2)", "the left through lane (lane 3)")
                    own_rank = number
                else:
                    own_rank = own
                side = "same" if rank == own_rank else "left" if rank < own_rank else "right"
                absolute.append((m.start(), m.end()))
                cues.append(Cue("lane", side, (base + m.start(), base + m.end())))
        passes = list(_PASSING.finditer(win))
        # The side a pass was made on ("passed EGO on its left") is the pass's, read with it below as "on the left"
        # is, not a lane the party was in.
        pass_sides = {p.end("side") for p in passes if p.group("side")}
        for m in _LANE_CUES.finditer(win):
            side = _side(next(g for g in m.groups() if g))
            if any(a0 <= m.start() < b0 for a0, b0 in absolute) or m.end() in pass_sides:
                continue  # read against the AV's own lane above, or the side of a pass
            if side == "right" and m.group(0).lower().startswith(("sidewalk", "curb", "shoulder")) and \
                    (named := _ROADSIDE_SIDE.search(win[max(0, m.start() - 16):m.start()])):
                # "the left shoulder" is on the left; "the far curb" across a two-way street; "the west sidewalk"
                # is read by its compass side below
                if named.group(1):
                    continue
                side = (named.group(2) or "left").lower()
            if side and not _INTO.search(win[max(0, m.start() - 25):m.start()]) and \
                    not _MOVED_TO.search(win[max(0, m.start() - 45):m.start()]):
                # ("cut back to the right lane": where it went)
                if side in ("left", "right") and (of := _OF_PARTY.match(win, m.end())) and \
                        any(x.sent == sent and x.start == a + of.end() for x in e.mentions):
                    # "EGO was traveling in the lane to the left of a city bus": the AV's side of the party, so
                    # the party is on the AV's other side
                    side = "right" if side == "left" else "left"
                cues.append(Cue("lane", side, (base + m.start(), base + m.end())))
        for m in _COMPASS_SIDE.finditer(win):
            # "a vehicle exiting a garage on the west side of the street": west is the left of a northbound AV
            ego_h = heading(d, -1)
            if ego_h is not None:
                rel = (CARDINALS[(m.group(1) or m.group(2)).lower()] - ego_h) % 360
                if rel in (90, 270):
                    cues.append(Cue("lane", "right" if rel == 90 else "left", (base + m.start(), base + m.end())))
        for m in _SAME_LANE.finditer(win):
            if not _INTO.search(win[max(0, m.start() - 25):m.start()]) and \
                    not _MOVED_TO.search(win[max(0, m.start() - 45):m.start()]):
                cues.append(Cue("lane", "same", (base + m.start(), base + m.end())))
        for m in _BEHIND.finditer(win):
            if m.group(0).lower().endswith(" by") and fre.fullmatch(r"\s*(?:(?:a|an|the|another)\s*)?", win[m.end():],
                                                                    re.I):
                # "following the car ahead at low speed when it was rear ended by Vehicle #2": the one named after
                # "by" came from behind, not the party whose words end there
                continue
            if m.group(0).lower().endswith(" it") and (_EGO_CLAUSE.search(win[:m.start()]) or fre.search(
                    r"\bEGO\s+(?:then\s+|subsequently\s+|also\s+)?$", win[:m.start()])):
                # "... the front bumper of EGO, which had come to a stop behind it": the AV is behind the party
                cues.append(Cue("along", "ahead", (base + m.start(), base + m.end())))
                continue
            cues.append(Cue("along", "behind", (base + m.start(), base + m.end())))
        for m in _AHEAD.finditer(win):
            # (the move read on the words as told: `win` has its turn words blanked)
            if _MOVED_TO.search(s[a + max(0, m.start() - 45):a + m.start()]) or \
                    _INTO_LANE.search(win[max(0, m.start() - 40):m.start()]):
                continue  # "cut in front of EGO", "moved into the right lane ahead of EGO": where it went
            cues.append(Cue("along", "ahead", (base + m.start(), base + m.end())))
        for m in passes:
            if fre.match(r"\s+(?:in\s+front\s+of\b|(?:the|a|an)\s+(?!EGO|(?:left|right|driver|passenger)(?:'s)?\s+side\s+"
                         r"of\s+EGO))", win[m.end():]) or _PASSED_OTHER.match(win, m.start()):
                # "changed lanes to pass the bus", "going past the parked cars", "passed through the intersection":
                # passing something else, or through a place, is no pass of the AV; nor is one across its front
                # ("the cyclist passed in front of the vehicle": a crossing, actions)
                continue
            if m.group("between") and d.ego_start != "stopped":
                continue
            cues.append(Cue("passing", _side(m.group("side")) or "", (base + m.start(), base + m.end())))
        for m in _PASS_QUEUE.finditer(win):
            # "to get around the queue of traffic", "passing the stopped cars": it came up from behind the AV's queue
            if any(x.sent == sent and a + m.start() < x.start <= a + m.end() + 1 for x in e.mentions):
                continue  # "EGO began changing lanes ... to pass the stopped pickup truck": the party is what was passed
            cues.append(Cue("passing", "", (base + m.start(), base + m.end())))
        for m in ONCOMING.finditer(win):
            # "the oncoming lane", "the wrong side of the road": a path it drove on, not a direction it came from
            path = fre.match(r"\s*(?:traffic\s+|travel\s+)?lane|\s+of\s+(?:the\s+)?(?:road|street|roadway)\b",
                             win[m.end():], re.I)
            cues.append(Cue("direction", "opposite-lane" if path else "opposite", (base + m.start(), base + m.end())))
    if e.idx == d.partner and d.contact_sent is not None:
        fore, _ = ego_contact_part(d)
        s = d.sents[d.contact_sent]
        base = d.offset(d.contact_sent)
        body = _ego_body_side(s)
        side = _side(next((g for g in body.groups() if g), None)) if body else None
        span = (base + body.start(), base + body.end()) if body else \
            (base + min(d.contact_pos, len(s)), base + min(len(s), d.contact_pos + 60))
        # A side panel touched (door, quarter panel, fender, mirror) puts the party beside the AV, not behind it.
        flank = "flank" if fre.search(r"\b(?:door|quarter|fender|mirror|panel)\b", s[d.contact_pos:], re.I) else ""
        if fore == "rear" and flank and _PARTY_FRONT.search(s) and \
                not any(a.who == e.idx and a.code in "fgF" for a in d.acts):
            flank = ""  # its front into the AV's rear quarter, and it kept its lane: it came from behind
        cues.append(Cue("contact", f"{fore or ''}/{side or ''}/{flank}", span))
    return cues


def _ego_body_side(s: str) -> re.Match[str] | None:
    """The side of the AV's body named in the contact sentence: a part "of EGO" or "EGO's" part first; a part
    said of the other party ("the passenger side of the van made contact with ...") never."""
    found = list(_BODY_SIDE.finditer(s))
    for k, m in enumerate(found):
        of = fre.match(r"[\w\s-]{0,30}?\bof\s+(?:the\s+)?(?:stopped\s+|stationary\s+)?EGO\b", s[m.end():])
        # "its right mirror struck the left mirror of EGO": the part nearest "of EGO" is the AV's
        if of and k + 1 < len(found) and found[k + 1].start() < m.end() + of.end():
            of = None
        if of or fre.search(r"\bEGO's\s+(?:[\w-]+\s+){0,2}$", s[max(0, m.start() - 30):m.start()]):
            return m
    for m in found:
        if not fre.match(r"[\w\s-]{0,30}?\bof\s+(?:the|a|an|its|their)\s+(?!EGO)", s[m.end():]):
            return m
    return None


# "stopped behind EGO", "had been stopped directly behind EGO", "initially stopped behind EGO": standing in the
# AV's queue, in its lane ("parked behind" stands at the curb; "from behind" says only where it came from).
_STOPPED_BEFORE = compile_gated(r"\b(?:stopped|stationary|standing|sitting|waiting|queued|idling|halted|at\s+(?:a\s+)?"
                                r"(?:standstill|rest))\b[^.,;]{0,30}$", re.I)
_BEHIND_AV = compile_gated(r"^behind\s+(?:the\s+)?(?:first\s+|second\s+)?(?:EGO|it)\b", re.I)


# The AV's own clause ending in the party's name as what it came up on: "EGO approached a", "EGO was stopped behind
# the", "EGO came to a stop behind a". (Not what it stopped or slowed for: "stopped for a parallel parking vehicle
# ahead on the right" may be beside its path.)
# ("EGO was traveling southwest bound on [XXX] when it slowed to a stop as it approached an SUV": the AV named
# again by "it" in its own sentence)
_AV_CAME_UP_ON = compile_gated(r"(?:\bEGO\b[^.;,]{0,50}?|\bEGO\b[^.;]{0,100}?\b(?:when|as|and|then)\s+it\s+(?:\w+\s+){0,2}?)"
                               r"\b(?:behind|approach(?:ed|ing)|came\s+up\s+(?:on|behind))\s+(?:a|an|the)\s+(?:[\w-]+\s+){0,3}$",
                               re.I)


# A place beside the AV's path told by the roadside or a side ("a cyclist in the bike lane", "ahead on the right").
_ROADSIDE_OR_SIDE = compile_gated(r"\b(?:bike|bicycle|parking|bus)\s+lane|\bsidewalk|\bcurb|\bshoulder|"
                                  r"\bon\s+the\s+(?:left|right)\b|\bto\s+the\s+(?:left|right)\s+of\b", re.I)


def _in_the_av_s_path(d: Doc, e: Entity) -> bool:
    """Is the party first told (past the summary) as what the AV came up on, in the AV's own clause, and not at the
    roadside or on a side in that first telling?"""
    m = next((x for x in e.mentions if x.sent not in d.summary), e.first)
    s = d.sents[m.sent]
    return bool(_AV_CAME_UP_ON.search(s[max(0, m.start - 160):m.start])) and \
        not _ROADSIDE_OR_SIDE.search(s[m.start:_clause_end(d, e, m)])


def _queued_behind(d: Doc, along: list[Cue], pass_side: str) -> Cue | None:
    """The party's own nearest `along` cue, when it says the party stood behind the AV in its queue, or was behind
    the standing AV, in its lane, and passed it on the left, out of that lane ("a cyclist that had been traveling
    behind the Waymo AV", "An SUV ... directly behind the Waymo AV", "a passenger car that had been behind the Waymo
    AV": 4 of 4 studyable gold sketches R6/same); not a direction it came from ("approaching from behind the Waymo
    AV"), nor a follower of the AV on its way ("a SUV following closely behind the Waymo AV passed the Waymo AV on
    the left side" as the AV pulled up: R6/left in the gold). (On the right a rider passes along the curb edge.)"""
    if not along or along[0].value != "behind":
        return None
    told, before = d.text[along[0].span[0]:along[0].span[1]], d.text[max(0, along[0].span[0] - 40):along[0].span[0]]
    if _BEHIND_AV.search(told) and _STOPPED_BEFORE.search(before):
        return along[0]
    if d.ego_start == "stopped" and pass_side == "left" and _FOLLOWING_AV.search(told) and \
            not _FROM_BEFORE.search(before):
        return along[0]
    return None


_FROM_BEFORE = compile_gated(r"\bfrom\s+$", re.I)
#: Behind the AV as a place in its lane: "behind EGO", "following EGO", "trailing EGO".
_FOLLOWING_AV = compile_gated(r"^(?:behind|following|trailing)\s+(?:the\s+)?(?:first\s+|second\s+)?(?:EGO|it)\b", re.I)


def _nearest_first(cues: list[Cue], d: Doc, e: Entity) -> list[Cue]:
    """Cues said after the party's name (its own phrase) before those said before it, nearest first."""
    starts = sorted(d.offset(m.sent) + m.end for m in e.mentions)

    def key(c: Cue) -> tuple[int, int]:
        after = [c.span[0] - p for p in starts if c.span[0] >= p]
        return (0, min(after)) if after else (1, min(abs(p - c.span[1]) for p in starts))
    return sorted(cues, key=key)




def _clause_end(d: Doc, e: Entity, m: Mention) -> int:
    """Where the text stops speaking of the party named at `m`: the next other party named, a clause about the AV,
    or the sentence end."""
    s = d.sents[m.sent]
    nxt = [x.start for x in d.ments[m.sent] if x.start > m.end and ends_phrase(d, x) and x.entity != e.idx]
    end = min(nxt) if nxt else len(s)
    av = AV_CLAUSE.search(s, m.end, end)
    return av.start() if av else end


def _crosses_exit_street(d: Doc, clause: str) -> re.Match[str] | None:
    """Is the party crossing the street the AV turns onto ("crossing the street EGO was turning onto", "crossing
    Taylor Street" when the AV turns onto Taylor)?"""
    m = fre.search(r"\bcross\w*\s+(?:the\s+)?(?:street|road|roadway)\s+(?:that\s+)?EGO\s+(?:was\s+|is\s+)?"
                   r"(?:turning|turned|about\s+to\s+turn)\s+(?:onto|into)\b", clause, re.I)
    ex = exit_street(d)
    if m or not ex:
        return m
    return fre.search(rf"\b(?:cross\w*|(?:walk|ran|run|jogg|rid|rode|mov)\w*\s+across)\s+(?:the\s+)?"
                      rf"{re.escape(ex)}\s+\w+", clause, re.I)


def _on_exit_crosswalk(d: Doc, e: Entity, far_only: bool = False) -> Cue | None:
    """A pedestrian or rider the turning AV meets at a junction is on the leg it turns onto (R4): said by "in the
    crosswalk", or by the AV yielding to it. For an AV going straight (`far_only`) only a crosswalk said to be
    beyond the junction ("on the far side of the intersection") is on its exit leg."""
    if e.category not in ("pedestrian", "bicycle", "scooter"):
        return None
    for m in e.mentions:
        s = d.sents[m.sent]
        win = s[max(0, m.start - 40):min(len(s), m.end + 60)]
        if far_only:
            far = fre.search(r"\bcrosswalk\b[^.]{0,30}\b(?:far|other|opposite)\s+side\b|\bfar(?:-side)?\s+crosswalk\b",
                             win, re.I)
            if far:
                a = d.offset(m.sent) + max(0, m.start - 40)
                return Cue("junction", "exit leg", (a + far.start(), a + far.end()))
            continue
        clause = s[m.end:_clause_end(d, e, m)]
        # "..., stepped into the crosswalk"; "crossing the street EGO was turning onto", "crossing Taylor Street"
        cw = fre.search(r"\bcrosswalk\b", win, re.I) or fre.search(r"\bcrosswalk\b", clause, re.I) or \
            (not far_only and _crosses_exit_street(d, clause))
        if cw or YIELDED_TO.search(s[max(0, m.start - 40):m.start]):
            a = d.offset(m.sent) + max(0, m.start - 40)
            return Cue("junction", "exit leg", (a + cw.start(), a + cw.end()) if cw else
                       (d.offset(m.sent) + m.start, d.offset(m.sent) + m.end))
    return None


_TAIL_END = compile_gated(r"\brear\s+(?:quarter|bumper|corner|end|fender|wheel|tire|light)|\btail(?:light|gate)?\b|"
                          r"\bback\s+(?:bumper|corner)", re.I)
_REAR_DOOR = compile_gated(r"\brear\s+(?:\w+\s+){0,2}door", re.I)
# "in the adjacent lane", "from the adjacent straight lane": beside the AV, on a side the words do not name.
_ADJACENT_LANE = compile_gated(r"\b(?:in|from|within)\s+(?:the|an)\s+adjacent\s+(?!left\b|right\b)(?:[\w-]+\s+)?lane\b", re.I)
# Leaving a place off the roadway that lines the curb: "reversed out of a parking spot", "exiting a driveway".
# ("out of one of the parking stalls", "from his parking space", "out of a diagonal stall", "from a parking bay")
_OUT_OF_CURBSIDE = compile_gated(r"\b(?:out\s+of|from|exit(?:ed|ing|s)?|leav(?:ing|es)|pull(?:ed|ing)\s+out\s+of)\s+"
                                 r"(?:one\s+of\s+)?(?:a|an|the|its|their|his|her)\s+(?:[\w-]+\s+){0,3}?(?:garage|driveway|"
                                 r"carport|parking\s+(?:lot|space|spot|stall|garage|structure|bay|place)|stall|bay)s?\b", re.I)
# A party astride two lanes: "partially in the number 1 lane (leftmost) and partially in the number 2 lane",
# "straddling the lane line", "straddling two lanes". Studyable: the 2 parties beside or behind the AV told so are on
# the side of the lane it did not share with the AV in the gold.
_STRADDLING = compile_gated(r"\b(?:partially|partly|half)\s+in\s+[^.;|]{0,80}?\band\s+(?:partially|partly|half)\s+in\b|"
                            r"\bstraddl\w*\s+(?:the\s+|two\s+)?(?:lanes?|lane\s+lines?|lane\s+markings?)\b", re.I)
# Level with the AV or ahead of it ("alongside", "adjacent to EGO"); "the adjacent lane" names a lane, no place
# along it ("in the adjacent lane to the left sideswiped EGO's left rear quarter panel": it came up from behind).
_LEVEL = compile_gated(r"\b(?:ahead|in\s+front|alongside|beside|next\s+to|adjacent(?!\s+(?:[\w-]+\s+){0,2}?lanes?\b))\b", re.I)


def backed_out_behind(d: Doc, e: Entity) -> bool:
    """Did the party come out of a driveway, garage, lot or parking space into the AV's rear end, no side of it
    ("reversed out of a parking spot into a Pony.ai autonomous testing vehicle's rear bumper")? It came out behind
    the AV, facing across its road, not along it."""
    fore, cside = ego_contact_part(d) if e.idx == d.partner else (None, None)
    return fore == "rear" and not cside and bool(_OUT_OF_CURBSIDE.search(context(d, e)))


def place(d: Doc, e: Entity, first: tuple[str, str | None], ego_actions: str,
          ego_turning: bool = False, told: bool = True) -> Placement:
    """Combine the party's cues with the first reading `first` = (position, lane) in the documented order.
    `told`: the first reading was read from the text (False: its fallback, ahead in the AV's lane, for want of any)."""
    pos, lane = first
    cues = gather(d, e)
    if d.junction and pos in ("R3", "R1", "R5") and (exit_leg := _on_exit_crosswalk(d, e, far_only=not ego_turning)):
        return Placement("R4", None, "crossing on the AV's exit leg", (exit_leg,), tuple(cues) + (exit_leg,))
    if d.junction and e.category == "pedestrian" and pos in ("R1", "R2", "R3", "R5") and \
            not any(c.kind in ("along", "passing") for c in cues) and \
            fre.search(r"\bcross", ctx := context(d, e), re.I) and not PLACE_SIDE.search(ctx):
        # A walker told crossing at the junction, neither behind nor passing the AV nor on a side of it, is on the
        # crosswalk of the leg ahead (R4), whatever way it walks ("a pedestrian who was traveling south on the
        # sidewalk ... had just entered the intersection to cross", the AV northbound, is no vehicle on the opposite
        # approach; "waiting for a pedestrian to cross" at a stop sign: not ahead in the AV's lane). ("crossing the
        # street outside of a crosswalk from the AV's left" stays where its side puts it, and one "standing on the
        # median" that "stepped off and walked into" the AV where it stood.)
        return Placement("R4", None, "a walker crossing at the junction", (), tuple(cues))
    passing_path = [c for c in cues if c.value == "opposite-lane"]
    overtakes = any(c.kind == "passing" or (c.kind == "along" and c.value == "behind") for c in cues)
    if passing_path and overtakes and not any(c.value == "opposite" for c in cues) and pos in ("R2", "R7", "R5", "R6"):
        # "passed EGO by driving in the oncoming lane": the lane is its path, the party goes the AV's way.
        pos = "R6"
        lane = lane if pos in ("R5", "R6") and lane not in (None, "same") else "left"
    elif pos in ("R1", "R3") and d.junction and heading(d, e.idx) is None and \
            (opp := next((c for c in cues if c.kind == "direction" and c.value == "opposite"), None)):
        # Read onto a crossing road from the side of the AV it struck, but said to come "from the opposite
        # direction": the opposite approach (R2); a heading of its own would have placed it.
        return Placement("R2", None, "opposite direction", (opp,), tuple(cues))
    elif pos not in ("R5", "R6"):
        return Placement(pos, lane, "first reading", tuple(cues), tuple(cues))
    if any(c.kind == "direction" and c.value == "opposite" for c in cues):
        return Placement(pos, lane, "first reading", tuple(cues), tuple(cues))
    rule = "first reading"
    ctx = context(d, e)  # the words of its place, read by several rules below
    backing = any(a.who == e.idx and a.code == "k" for a in d.acts) or bool(BACKING.search(ctx))
    along = _nearest_first([c for c in cues if c.kind == "along"], d, e)
    passing = [c for c in cues if c.kind == "passing"]
    contact = next((c for c in cues if c.kind == "contact"), None)
    fore, cside, flank = (contact.value.split("/") if contact else ("", "", ""))
    used: list[Cue] = []
    if along:
        pos, rule = ("R6" if along[0].value == "behind" else "R5"), "along"
        used.append(along[0])
    elif passing and not backing and "k" not in ego_actions:
        pos, rule = "R6", "passing"
        used.append(passing[0])
    elif fore == "rear" and not flank and not backing and "k" not in ego_actions and contact is not None and \
            not any(a.who == e.idx and a.code in "OPS" for a in d.acts):
        # (a party that stood, at the curb or a stop, and moved off into the passing AV was beside it, not behind)
        pos, rule = "R6", "contact on the AV's rear"
        used.append(contact)
    elif pos == "R5" and d.ego_start == "stopped" and not backing and \
            any(c.kind == "lane" and c.value in ("left", "right") for c in cues) and \
            fre.search(r"\bapproach(?:ed|ing|es)?\b(?!\s+(?:the\s+)?(?:intersection|crosswalk|junction))",
                       ctx, re.I):
        # Coming up in a lane beside an AV that stood still: it came from behind.
        pos, rule = "R6", "approaching a standing AV"
    elif pos == "R5" and d.ego_start == "stopped" and not ego_actions and not backing and contact is not None and \
            (flank or fore == "rear" or not fore) and \
            any(c.kind == "lane" and c.value in ("left", "right") and c.value == (cside or c.value) for c in cues) and \
            not any(a.who == e.idx and a.code not in "abc" for a in d.acts) and not _LEVEL.search(ctx) and \
            not fre.search(r"\b(?:stopped|parked|stationary|waiting|stalled|idling|queued|standing)\b",
                           " ".join(m.mods for m in e.mentions) + " " + ctx[:60], re.I):
        # On the move in a lane beside an AV that stood still throughout, without a turn, a lane change or a start
        # from a stop of its own, and touching the AV's side: it was passing it, so it came from behind
        # (sketch.md: a party passing a stopped AV is R6 on the side it passed).
        pos, rule = "R6", "passing a standing AV"
        used.append(contact)
    if pos == "R6" and not (along and along[0].value == "behind") and _OUT_OF_CURBSIDE.search(ctx) and \
            not (fore == "rear" and not cside):
        # Coming out of a driveway, garage, lot or parking space ("allowing for a passenger car to exit a parking
        # lot ... As the passenger car turned left onto [XXX] and attempted to pass EGO", "began reversing out of
        # the garage and ... made contact with the rear passenger side of EGO"): it was at the roadside beside or
        # ahead of the AV when the interaction began, not behind it in traffic, whatever it passed or touched then.
        # (One that struck the AV's rear end, no side of it, came out behind it: "reversed out of a parking spot
        # into a Pony.ai autonomous testing vehicle's rear bumper".)
        pos, rule = "R5", rule + "; " + OUT_OF_ROADSIDE
    if not told and rule == "first reading" and d.junction and "d" in ego_actions and e.category in _MOTOR and \
            fore != "rear" and all(c.kind == "contact" for c in cues) and \
            not any(a.who == e.idx and a.code in "defgjkFT" for a in d.acts):
        # Nothing told of its place but the side of the AV it struck, no manoeuvre of its own but going on, and the
        # AV turning left at the junction: a vehicle met there, not at the AV's rear, came from the opposite approach
        # (a left turn across the path of oncoming traffic, struck on the AV's right or front).
        return Placement("R2", None, "left turn across its path", tuple(c for c in cues if c.kind == "contact"),
                         tuple(cues))
    # A lane said relative to the AV ("to the left of EGO", "the adjacent lane") outranks a lane's name on the road
    # ("the right lane of the freeway"), which says where the party is only against the AV's own lane.
    lanes = _nearest_first([c for c in cues if c.kind == "lane"], d, e)
    if _STRADDLING.search(ctx):
        # Half in the AV's lane and half in another ("traveling partially in the rightmost lane and partially in the
        # left-adjacent dedicated left turn lane", the AV in the rightmost): the lane it shares with the AV is not
        # its side; the other lane, the side it passed on or the side of the AV it touched is.
        lanes = [c for c in lanes if c.value != "same"]
    beside = [c for c in lanes if c.value in ("left", "right") and _RELATIVE_LANE.search(d.text[c.span[0]:c.span[1]])]
    if beside:
        lanes = beside + [c for c in lanes if c not in beside]
    # The lane it came out of ("began to change lanes from the rightmost lane to the leftmost lane", the AV in the
    # centre lane; "merged from the right lane") is where it was when the interaction began: it outranks the lanes
    # it went through or into.
    origin = [c for c in lanes if _FROM_LANE.match(d.text[c.span[0]:c.span[1]]) or
              _FROM_BEFORE_LANE.search(d.text[max(0, c.span[0] - 20):c.span[0]])]
    if origin:
        lanes = origin + [c for c in lanes if c not in origin]
    pass_side = next((c.value for c in passing if c.value), "")
    passed_side = ""
    if pos == "R6" and passing and (queued := _queued_behind(d, along, pass_side)) and \
            not any(c.value in ("left", "right") for c in lanes) and \
            pass_side and not (e.category in _EDGE_RIDERS and pass_side == "right"):
        # Stopped behind the AV, then passing it ("a passenger car that had been stopped behind the Waymo AV passed
        # the Waymo AV on the left"): it stood in the AV's queue, in its lane, and moved out to the side it passed
        # on: R6/same and a lane change (the gold reads it so). (A cyclist passing on the right rides at the curb
        # edge: beside, no change.)
        lane, rule, passed_side = "same", rule + "; behind it, then passed", pass_side
        used.append(queued)
    elif lanes and pass_side and all(c.value == "same" for c in lanes):
        # "traveling behind EGO, then passed it on the right": it came up in the AV's lane and passed on that side
        lane, rule = pass_side, rule + "; passing side"
        used.append(next(c for c in passing if c.value))
    elif lanes and passing and cside and contact is not None and pos == "R6" and not backing and \
            all(c.value == "same" and not _EXPLICIT_SAME.search(d.text[c.span[0]:c.span[1]]) for c in lanes) and \
            not any(a.who == e.idx and a.code in "fgF" for a in d.acts):
        # "a Honda Accord traveling behind the Cruise AV attempted to pass the Cruise AV and made contact ...,
        # damaging the rear passenger side bumper": behind it, then passing on a side no word names, with no lane
        # change told: the side of the AV it struck is the side it passed on (sketch.md: a party passing the AV
        # without a stated lane change is R6 on the side it passed). (One that changed lanes to pass began in the
        # AV's lane: R6/same, its string the change.)
        lane, rule = cside, rule + "; passing on the side it struck"
        used.append(contact)
    elif lanes:
        lane, rule = lanes[0].value, rule + "; lane"
        used.append(lanes[0])
    elif pass_side:
        lane, rule = pass_side, rule + "; passing side"
        used.append(next(c for c in passing if c.value))
    elif lane == "same" and not cside and d.av_lane is not None and (d.av_lane <= 0 or d.av_lane >= 9) and \
            _ADJACENT_LANE.search(ctx or d.sents[e.first.sent][e.first.end:e.first.end + 60]):
        # "a car in an adjacent lane", the AV in the right lane of a two-lane road (or the leftmost, or at the
        # curb): the only lane beside an AV at the road's edge is on its open side. (A party told only after the
        # contact, the reason for the AV's move, is read at its first mention: "due to perceived risk from a car in
        # an adjacent lane".)
        lane, rule = ("right" if d.av_lane <= 0 else "left"), rule + "; the adjacent lane beside an AV at an edge"
    elif pos == "R5" and lane == "same" and (changes := [a.code for a in d.acts if a.who == e.idx and a.code in "fgF"]):
        # Cutting in ahead of the AV: a move to the left came from the right-hand lane, and the other way round. A
        # lane change of no stated side came from the side of the AV it touched, or from the side opposite its own
        # flank the AV's front met, else it is written as a move to the left (sequences.sequence), so it came from
        # the right: the place and the action string agree.
        came = side_from_flank(d, e) if contact is not None and fore == "front" and not cside else None
        lane = {"f": "right", "g": "left"}.get(changes[0]) or (cside if contact is not None and cside else None) or \
            came or "right"
        rule += "; cut in"
    elif pos == "R5" and lane == "same" and contact is not None and fore == "front" and not cside and not along and \
            not backing and (came := side_from_flank(d, e)):
        # The AV's front met the party's flank ("the front of EGO struck the passenger side of the sedan"): the party
        # was crossing or cutting across its path from the other side.
        lane, rule = came, rule + "; its flank met by the AV's front"
    elif pos == "R6" and lane == "same" and (moves := [c for c in ego_actions if c in "fg"]) and \
            cside in ("", "left" if moves[-1] == "f" else "right") and \
            not any(a.who == e.idx and a.code in "fgF" for a in d.acts):
        # The AV moved over (or pulled out) into the lane of a party behind it: the party is on that side. Not one
        # changing lanes itself ("was changing lanes into the left turn lane ... another vehicle changing into the
        # same lane made contact with the rear bumper"): both moved over from one lane, it behind the AV in it.
        lane, rule = ("left" if moves[-1] == "f" else "right"), rule + "; AV moved over"
    elif pos == "R6" and lane == "same" and fore == "rear" and cside and \
            (moves := [a.code for a in d.acts if a.who == e.idx and a.code in "fg" and
                       before_contact(d, a.sent, a.pos)]) and moves[0] == ("f" if cside == "right" else "g"):
        # Behind the AV, moving over toward its lane from one side and striking its rear corner on that side: it came
        # from the lane on that side ("merging from the on-ramp ... struck the rear passenger side corner"). The
        # studyable gold holds the geometry in 28 of the 30 parties behind with a rear corner struck and a lane
        # change told: moving toward the AV, the side struck (7 of 7); moving out toward that side, the AV's lane
        # (21 of 23, the passers of sketch.md's queue).
        lane, rule = cside, rule + "; moved over toward the AV from the side it struck"
        used.append(contact)
    elif cside and lane == "same" and (pos == "R5" or passing or flank or _ADJACENT_LANE.search(ctx)) and \
            contact is not None and \
            not (backing and pos == "R5" and fore == "front"):
        # A party behind that strikes a rear corner was most often right behind (a rear-end off-centre); only one
        # passing, splitting lanes or said to be in the adjacent lane (no side named: "approached EGO from behind
        # in the adjacent straight lane") was beside the AV on the side it touched. (One ahead backing into a front
        # corner of the AV came straight back in its lane: "began reversing in front of the vehicle ... collided
        # with the front left corner".)
        lane, rule = cside, rule + "; contact side"
        used.append(contact)
    if pos in ("R5", "R6") and lane == "same" and not lanes and _OUT_OF_CURBSIDE.search(ctx) and \
            not fre.search(r"\b(?:left|right)\b", ctx, re.I) and \
            not any(c.kind == "along" and c.value == "ahead" for c in cues) and \
            not (backing and fore == "front" and not cside):
        # Out of a driveway, garage or parking space, no side named ("a passenger vehicle reversed out of a parking
        # spot into EGO's rear bumper"): those places line the curb, on the AV's right (right-hand traffic). One
        # said to be in front of the AV ("reversing out of an angled parking space in front of EGO") is in its path;
        # so is one backing into the AV's front, no side of it ("a parked SUV began reversing out of a diagonal
        # parking stall. The rear driver side of the SUV made contact with the front of EGO": studyable, 2 of 2
        # parties backing out of a space into the AV's front with no side are R5/same in the gold).
        lane, rule = "right", rule + "; out of a curbside place"
    if pos == "R5" and lane in ("left", "right") and not along and contact is not None and \
            fore == "rear" and cside in ("", lane) and not backing and \
            not any(a.who == e.idx and a.code == "i" for a in d.acts) and \
            (_TAIL_END.search(d.sents[d.contact_sent]) or not _REAR_DOOR.search(d.sents[d.contact_sent])) and \
            not _LEVEL.search(ctx):
        # In the next lane and touching the AV's rear on that side (its quarter, bumper or corner; a rear door
        # alone is the middle of the side): it was level with the AV's tail or further back when the interaction
        # began, not ahead of it. One that stood beside it and moved off meets the rear half from level.
        pos, rule = "R6", rule + "; contact on the AV's rear, beside it"
        used.append(contact)
    if pos == "R5" and lane in ("left", "right") and not beside and not passing and \
            _in_the_av_s_path(d, e) and not any(c.kind == "contact" and c.value.endswith("/flank") for c in cues):
        # First named as what the AV came up behind ("EGO approached a semi-trailer truck that was stopped in the
        # left lane", "EGO came to a stop behind a GMC Yukon"): it stood or went ahead in the AV's path, whatever
        # lane the road names it in (no lane said relative to the AV: "the left lane" is the AV's too).
        lane, rule = "same", rule + "; in the AV's path"
    if pos in ("R5", "R6") and lane == "same" and e.category in _RIDERS and _SPLITTING.search(ctx) and \
            not any(c.kind == "along" and c.value == "ahead" for c in cues):
        # Riding the line between two lanes of traffic ("a motorized scooter riding between the 2 lanes of traffic
        # clipped the May Mobility vehicle's mirror", "a lane-splitting electric scooterist"): never in the AV's lane
        # but beside it, coming up past it from behind, on the side of the AV it struck, else on its left (2 of the
        # 2 studyable lane splitters are R6/left; California's riders split the lanes to the left of traffic most).
        pos, lane, rule = "R6", cside or "left", rule + "; splitting lanes"
    if pos in ("R5", "R6") and lane == "same" and e.category in _EDGE_RIDERS and \
            not any(c.kind in ("lane", "along") and c.value in ("same", "ahead") and
                    _EXPLICIT_SAME.search(d.text[c.span[0]:c.span[1]]) for c in cues) and \
            not (pos == "R6" and contact is not None and fore == "rear" and not cside and not flank) and \
            not passed_side:
        # (one that ran into the middle of the AV's rear, no side of it named, was in line behind it)
        # A cyclist or scooterist rides at the edge of the road, beside a car rather than centred in its lane:
        # "same" read from nothing but "behind EGO" or from no lane cue at all is the side it touched, else the
        # curb side (right-hand traffic). "Directly behind", "in EGO's lane", "in front of EGO" (in its path) keep
        # it in the AV's lane.
        lane = cside if cside and contact is not None else "right"
        rule += "; rider at the lane edge"
        if cside and contact is not None:
            used.append(contact)
    return Placement(pos, lane, rule, tuple(dict.fromkeys(used)) or tuple(cues), tuple(cues), passed_side)
