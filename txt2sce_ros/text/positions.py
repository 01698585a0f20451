"""Where each party and object was relative to the AV when the interaction began (R1-R7 and lane, sketch.md)."""

from __future__ import annotations

import bisect
import re

from . import fastre as fre
from .fastre import compile_gated
from .lexicon import CARDINALS
from .mentions import Entity
from .story import ONCOMING, TURN_WORDS, Doc, body_side, context, ego_contact_part, heading, side_named


def party_position(d: Doc, e: Entity, ego_heading: int | None, ego_turning: bool,
                   ego_actions: str = "", behind_av: frozenset[int] = frozenset()) -> tuple[str, str | None, bool]:
    """(position, lane, known): where the party was relative to the AV when the interaction began.
    `behind_av`: the entities already placed behind the AV (R6); whoever follows them is behind too."""
    ctx = own_context(d, e)
    # A party said to be on another street than the AV's is on a crossing road: the AV is at a junction with it.
    cross = _on_other_street(d, ctx)
    junction = d.junction or cross
    # Behind a party already placed behind the AV, or striking one in a chain ("a second motorcyclist then
    # collided with the first motorcyclist"): it came from further behind. The other party is the one named next
    # after the verb, by its mention, however many words its name has ("the passenger car", "the white SUV").
    for m in e.mentions:
        for x in d.ments[m.sent]:
            if x.start > m.end and x.kind == "party" and x.entity != e.idx and _CHAIN.search(
                    d.sents[m.sent][m.end:x.start][-80:]) and (x.entity in behind_av or _told_behind_av(d, x.entity)):
                return "R6", "same", True
    # ... or by its noun, where the two were taken for one party ("a second motorcyclist then collided with the first
    # motorcyclist")
    heads = {h for k in behind_av for h in d.ents[k].heads}
    queue = _CHAIN_NOUN.search(ctx or d.sents[e.first.sent][e.first.end:]) if heads else None
    if queue and any((w or "").lower() in heads for w in queue.groups()):
        return "R6", "same", True
    fore, cside = ego_contact_part(d) if e.idx == d.partner else (None, None)
    # The words right before each of the first two mentions, in their own clause; a test anchored at the name ("...
    # behind a ") is made on each, not on the two joined.
    pres = [fre.split(r"[,;]|\bwhen\b|\bas\b|\bwhile\b", d.sents[m.sent][max(0, m.start - 50):m.start])[-1]
            for m in e.mentions[:2]]
    pre = " ".join(pres)
    full = " ".join(d.sents[m.sent] for m in e.mentions)
    turns = [a.code for a in d.acts if a.who == e.idx and a.code in "de"]
    if turns and _onto_av_street(d, ctx) and heading(d, e.idx) is None and not PLACE_SIDE.search(ctx) and \
            not fre.search(r"\b(?:driveway|parking|lot|garage|alley)\b", ctx, re.I):
        # Turned onto the AV's street from a crossing one ("an SUV then turned right from Post Street onto Steiner
        # Street and began closely following EGO"): it came from the crossing road, whatever it did next. A left
        # turn towards the AV comes from its right; one that ends up going the AV's way (following it, striking
        # its rear) came from the other side. (A party given a heading or a side is read by it, below; one out of
        # a driveway or lot is no crossing road's.)
        follows = bool(fre.search(r"\bfollow|\bbehind\s+EGO", ctx, re.I)) or fore == "rear"
        return ("R3" if (turns[0] == "d") != follows else "R1"), None, True
    if e.idx == d.partner and d.contact_sent is not None and not (junction and turns) and \
            _REAR_ENDED_EGO.search(" ".join(d.sents[:d.contact_sent + 1])):
        # The contact told as a rear-end of the AV ("a passenger vehicle rear-ended the Waymo AV", "EGO was rear
        # ended by the truck", "struck from behind"): the party came from behind, whatever side or heading a clause
        # about the AV names ("... as the Waymo AV was yielding to approaching traffic from the left"). (One that
        # turned at the junction came from its own approach: "a Toyota Sedan on westbound Sacramento Street was
        # making an unprotected right turn ... onto northbound Van Ness Avenue behind the Cruise AV. Shortly
        # thereafter, the Toyota Sedan rear-ended the Cruise AV" is R3.) 28 of the 29 studyable reports telling it
        # so have the party behind in the gold; the other is that turn.
        return "R6", _rear_lane(d), True
    # (a pass of the AV itself, not of a thing of its: "went past the AV's stop line")
    # (a word between the verb and the AV describes it, "passed the stopped EGO"; a clause word starts another
    # clause: "began reversing as EGO was passing and EGO came to a stop" is the AV's pass)
    passing = fre.search(r"\b(?:pass(?:ed|ing|es)?|past|overtak(?:e|ing|en)|overtook)\s+(?:by\s+)?(?:the\s+)?"
                        r"(?:(?!(?:and|as|when|while|then|but|or|so)\s)\w+\s+)?(?:EGO|it)\b(?!'s)"
                        r"(?:\s+(?:on\s+(?:the|its|EGO's)\s+)?(left|right))?", ctx, re.I)
    h = heading(d, e.idx)
    rel = None if h is None or ego_heading is None else (h - ego_heading) % 360
    # An oncoming party also "passes" the AV, from the front: only a same-direction pass puts it behind. Oncoming is
    # said ("an oncoming car"), or told by a heading opposite the AV's ("a pickup truck traveling southbound ... passed
    # the stationary Waymo AV", the AV northbound).
    passed_oncoming = bool(passing) and (rel == 180 or bool(
        fre.search(r"\boncoming\b|\bopposite\s+direction\b", ctx + " " + pre, re.I)))
    crossing_heading = junction and rel in (90, 270)
    if passing and not passed_oncoming and not crossing_heading:
        # (one heading across the AV's way at a junction came from the crossing road, whatever it passed then: "a
        # wide right turn from eastbound [XXX] into the left lane of southbound [XXX]. As the bus passed the stopped
        # EGO")
        # The side it passed on: said with the pass, else the side of the AV it touched, else a side named just
        # after ("its right mirror struck EGO's left mirror": the AV's side, not the party's own part, decides; nor
        # "As the heavy truck was passing the stopped EGO, the right side of the heavy truck made contact").
        after = fre.blank(_OWN_FLANK, ctx[passing.end():passing.end() + 60])[:30]
        return "R6", (passing.group(1) or "").lower() or cside or side_named(after) or "same", True
    if fre.search(r"^\s*\S*\s*(?:following|trailing)|(?:^|\s)(?:that\s+had\s+been\s+|that\s+was\s+|was\s+)?"
                 r"(?:traveling\s+|travelling\s+|driving\s+)?(?:directly\s+|immediately\s+)?(?:behind|following|"
                 r"trailing)\s+(?:directly\s+)?(?:the\s+)?(?:EGO|it|us|our)\b|\b" + FROM_BEHIND + r"|\bfrom\s+the\s+rear\b|"
                 r"\bto\s+EGO's\s+rear\b|^\s*\S*\s*behind\b|\b(?:following|trailing|behind)\s+(?:vehicle|car)|"
                 r"\bbehind\s+and\s+to\s+the\s+(?:left|right)\s+of\s+EGO",
                 ctx, re.I) or any(fre.search(r"\b(?:following|trailing)\s*$", p, re.I) for p in pres):
        side = None
        sides = fre.blank(_OWN_FLANK, ctx)  # (the party's own flank is no side it passed on)
        if fre.search(r"\bpass(?:ed|ing)\b[^|]{0,40}\b(?:on\s+the\s+)?(left|right)\b", sides, re.I):
            side = side_named(fre.search(r"\bpass(?:ed|ing)\b[^|]{0,40}", sides, re.I).group(0))
        elif fre.search(r"\bbehind\s+and\s+to\s+the\s+(left|right)", ctx, re.I):
            side = side_named(ctx)
        if side is None and fre.search(r"\bsidewalk\b|\bbike\s+lane\b", ctx, re.I):
            side = "right"
        return "R6", side or "same", True
    # Oncoming is said of the party itself ("an oncoming truck", "traveling in the opposite direction"), close to
    # its name; "without yielding to oncoming traffic" further on speaks of others.
    near = " | ".join(f"{m.mods} {_own_clause(d.sents[m.sent][m.end:m.end + 100])}" for m in e.mentions)
    oncoming = ONCOMING.search(near + " " + pre) or _across_by_compass(d, ctx)
    if oncoming and fre.search(r"\b(?:yield\w*|stop\w*|wait\w*)\s+(?:for|to)\s+(?:the\s+)?oncoming\s+traffic", near,
                              re.I) and not fre.search(r"\boncoming\b", " ".join(m.mods for m in e.mentions), re.I):
        oncoming = None
    if not oncoming and e.category in ("car", "van", "truck", "bus", "motorcycle"):
        # A vehicle "heading/coming/moving toward EGO" runs at it head-on; not one that "began moving toward EGO
        # from the bus lane" (a sideways move), nor anyone on foot (who may walk at the AV from any side).
        oncoming = _TOWARD_EGO.search(near)
    if ego_turning and (ex := exit_street(d)) and same_street(_party_street(ctx), ex) and \
            not fre.search(r"\b(?:turn\w*|onto)\b", ctx[:60], re.I) and \
            not fre.search(r"\bfrom\s+(?:the|EGO's)\s+(?:left|right)\b", ctx, re.I):
        # On the street the AV turns onto, and not itself turning onto it; one said to come from the AV's left or
        # right is read in the AV's frame below (R1/R3).
        return "R4", None, True
    # Before headings: the heading it is given may be the one it turned to ("onto westbound California").
    if cross and (side := side_named(ctx) or (cside if rel is None else None)):
        # "a vehicle on Leavenworth, to the right of EGO"; else, with no heading to tell it (below), the side of the
        # AV it struck ("a sedan on the cross street ran the red light and struck EGO's driver side": it came from
        # the AV's left)
        return ("R1" if side == "left" else "R3"), None, True
    if fre.search(r"\bsame\s+direction\b", ctx + " " + pre, re.I):
        oncoming = None
        side_m = fre.search(r"\b(?:to\s+the\s+)?(left|right)\s+of\s+EGO", ctx + " " + full, re.I)
        if side_m:
            return "R5", side_m.group(1).lower(), True
        if (side := side_named(ctx)) and not fre.search(r"\bbehind\b|\bfrom\s+the\s+rear\b", ctx, re.I):
            return "R5", side, True  # "on its left ... traveling in the same direction": beside it, on that side
    if oncoming or rel == 180:
        told = next((m for m in e.mentions if m.sent not in d.summary), e.first)
        opening = _own_clause(d.sents[told.sent][told.end:told.end + 160])
        if (own_lane := _IN_EGO_LANE.search(opening)) and not _INTO_A_LANE.search(opening[:own_lane.start()]):
            # Coming the other way in the AV's own lane when first told ("an oncoming pickup truck traveling
            # eastbound in EGO's lane", "traveling westbound ... in the middle shared turn lane, directly in front
            # of EGO"): on the AV's own road, head-on, also at a junction (sketch.md: a party on the AV's approach
            # road is R5-R7). Not one that got there later ("entered the intersection and veered into EGO's lane of
            # travel ... continued traveling in EGO's lane"): it came from where it was first.
            return "R7", "same", True
        if ego_heading is not None and (lanes := _HEADING_LANE.search(opening)) and \
                CARDINALS[lanes.group(1).lower()] == ego_heading:
            # Coming the other way in the lanes of the AV's direction when first told ("a passenger car traveling
            # eastbound in the westbound lanes", the AV westbound): the wrong way, in the AV's lane.
            return "R7", "same", True
        if junction and not _off_the_junction(d, e, ctx):
            # (one turning off into a driveway or lot, or crossing the median, meets the AV on the AV's own road
            # away from the junction: R7, below)
            return "R2", None, True
        # In the AV's own lane: said ("the wrong way"), or passing the AV on its right (the oncoming lane is on its
        # left: "a passenger car traveling southbound in the parking lot proceeded to pass the Waymo AV on the right").
        wrong_way = fre.search(r"\bwrong[\s-]+(?:way|side|direction)\b|\bagainst\s+(?:the\s+)?(?:flow\s+of\s+)?traffic\b",
                               ctx, re.I) or \
            (passed_oncoming and (passing.group(1) or "").lower() == "right")
        return "R7", "same" if wrong_way else "left", True
    if rel == 0 and not fre.search(r"\bbehind\b", ctx, re.I):
        return "R5", side_named(ctx) or "same", True
    if junction and rel in (90, 270):
        # Coming from the side opposite its heading: heading +90 (clockwise) of the AV's comes from the AV's left.
        return ("R1" if rel == 90 else "R3"), None, True
    if rel in (90, 270) and not ego_turning and side_named(ctx) is None:
        # Away from a junction, heading across the AV's road (out of a driveway, a lot or an alley, or crossing
        # mid-block: "an SUV traveling eastbound exited a driveway", the AV northbound): it came from the side
        # opposite its heading, at the roadside beside or ahead of the AV (sketch.md: R5 on that side).
        return "R5", ("left" if rel == 90 else "right"), True
    # ("from the west sidewalk", "from the eastern curb", "from the north side of the street")
    compass = FROM_COMPASS_SIDE.search(ctx) or (
        # at a junction a bare origin does ("traveling on Flamingo Road from the west")
        junction and fre.search(r"\bfrom\s+the\s+(north|south|east|west)\b(?!\s*-?\s*bound)", ctx, re.I))
    if compass and ego_heading is not None:
        origin = {"north": 0, "east": 90, "south": 180, "west": 270}[compass.group(1).lower()]
        rel_origin = (origin - ego_heading) % 360  # 90: on the AV's right, 270: on its left
        if rel_origin in (90, 270):
            side = "right" if rel_origin == 90 else "left"
            if junction:
                return ("R3" if side == "right" else "R1"), None, True
            return "R5", side, True
    came_from = came_from_side(ctx)
    if junction and came_from and e.category != "pedestrian":  # one on foot crosses the AV's own approach
        return ("R1" if came_from == "left" else "R3"), None, True
    if not junction and came_from and e.category in ("pedestrian", "bicycle", "scooter"):
        return "R5", came_from, True  # mid-block, in from the curb on that side (sketch.md)
    if fore == "rear" and any(a.who == e.idx and a.code == "m" for a in d.acts):
        # Out of a driveway into the AV's lane, striking its rear: it came in behind, on the side it struck.
        return "R6", cside or "same", True
    scan = TURN_WORDS.sub(" ", ctx)
    lane_ctx = fre.search(r"(?:(?:in|from)\s+the\s+(?:\w+\s+){0,2}(?:left|right)(?:\s+\w+){0,2}\s+lane|"
                         r"lane\s+to\s+(?:the|its|our|EGO's)\s+"
                         r"(?:left|right)|(?:left|right)\s+(?:adjacent\s+)?lane|to\s+the\s+(?:left|right)\s+of\s+EGO|"
                         # (a side of a body, "struck the left side of EGO", "its right side", is no lane)
                         r"on\s+the\s+(?:left|right)|(?:to|from|on)\s+EGO's\s+(?:left|right)|"
                         r"(?:from|along)\s+the\s+(?:left|right)\s+side|"
                         # (parallel parking is a manoeuvre in front of or behind the AV, no place beside it)
                         r"bike\s+lane|sidewalk|parallel(?![- ]park)|alongside|"
                         r"adjacent|beside|next\s+to|(?:left|right)\s+curb|driveway)", scan, re.I)
    if lane_ctx and fre.search(r"\b(?:into|onto)\s+(?:the\s+)?$", scan[max(0, lane_ctx.start() - 12):lane_ctx.start()],
                               re.I):
        lane_ctx = None  # "stepped out ... into the left lane": where it went, not where it was
    if lane_ctx and not cross:
        text = lane_ctx.group(0)
        # A side named in the party's phrase ("a driveway on the left side of the street") beats the right-hand
        # default for curbs, driveways and bike lanes.
        side = side_named(text) or side_named(scan[lane_ctx.end():lane_ctx.end() + 40].split("|")[0]) or \
            ("right" if fre.search(r"bike|bus|sidewalk|curb|driveway|parking", text + " " + ctx, re.I) else None)
        if side is None:
            side = side_named(ctx)
        if side is None and fre.search(r"\badjacent\b|\bparallel\b|\balongside\b|\bbeside\b|\bnext\s+to\b", text,
                                      re.I):
            # Beside an AV in the leftmost lane is to its right (and the other way round).
            own = fre.search(r"\bEGO\b[^.]{0,100}?\bin\s+the\s+(?:far\s+|second\s+|third\s+)?(left|right)(?:most)?\s+"
                            r"(?:\w+\s+)?lane",
                            d.text)
            side = {"left": "right", "right": "left"}.get(own.group(1).lower()) if own else None
            if side is None and fre.search(r"\bEGO\b[^.]{0,60}?\b(?:parking\s+lane|shoulder|parked|at\s+the\s+curb)",
                                          d.text):
                side = "left"  # the AV at the curb: the traffic lane beside it is on its left
        side = side or "same"
        if junction and ego_turning and fre.search(r"driveway|parking", ctx, re.I):
            return "R4", None, True
        return "R5", side, True
    if fre.search(r"\b(?:in\s+front\s+of|ahead\s+of)\s+(?:the\s+)?EGO", ctx + " " + pre, re.I) or \
            any(fre.search(r"\bbehind\s+(?:a|an|the)\s+(?:\w+\s+){0,3}$", p, re.I) for p in pres):
        # ahead of the AV: said so, or the AV behind it ("came to a stop behind a passenger car")
        return "R5", "same", True
    if junction and ego_turning and e.category in ("pedestrian", "bicycle", "scooter") and \
            fre.search(r"\bcrosswalk\b", ctx, re.I):
        return "R4", None, True
    if fre.search(r"\b(?:ahead|in\s+front|preceding|in\s+EGO's\s+lane|in\s+its\s+lane|same\s+lane)\b", ctx, re.I):
        return "R5", "same", True
    if e.idx == d.partner and fre.search(r"[fg]", ego_actions) and not fre.search(r"[fg]", "".join(
            a.code for a in d.acts if a.who == e.idx)):
        return "R6", "left" if "f" in ego_actions else "right", True  # the AV moved over into its lane
    if junction and (fore != "rear" or cside) and not turns and \
            (leg := _crossing_leg(d, e, ctx, fore, cside, ego_turning)):
        return leg  # (a party turning at the junction is read by its turn, below)
    if fore == "rear":
        return "R6", _rear_lane(d), True
    if junction and turns and not fre.search(r"\bfrom\s+the\s+(?:left|right)", ctx, re.I):
        # Turning onto the AV's road towards it: a left turn comes from the right, a right turn from the left;
        # a party that then follows the AV turned into its direction, so the sides swap.
        follows = fre.search(r"\bfollow|\bbehind\s+EGO", ctx, re.I)
        onto_ours = _onto_av_street(d, ctx)
        if turns[0] == "d" and not follows and "d" not in ego_actions and not onto_ours:
            # A left turn across the path of an AV going through: the classic conflict comes from the opposite
            # approach (left turn across path, opposite direction) more often than from the crossing road.
            return "R2", None, True
        from_right = (turns[0] == "d") != bool(follows)
        return ("R3" if from_right else "R1"), None, True
    if junction and e.category in ("car", "van", "truck", "bus", "motorcycle") and (
            fre.search(r"\b(?:entered|drove\s+into|proceeded\s+into|came\s+into)\s+the\s+intersection", ctx, re.I)):
        # Straight into the intersection and into the AV's side: it came from the side it struck. Its own flank
        # met by the AV's front puts it on the other side ("EGO's front end struck the driver side of the pickup").
        side = (side_from_flank(d, e) if e.idx == d.partner and fore == "front" and not cside else None) or \
            side_named(ctx) or cside
        return ("R1" if side == "left" else "R3" if side == "right" else "R2"), None, bool(side)
    if fre.search(r"\bbehind\b(?<!from\sbehind)", ctx, re.I) or fre.search(r"\b" + FROM_BEHIND, ctx, re.I):
        return "R6", "same", True
    if junction and (leg := _yielded_at_junction(d, e, fore, ego_actions)):
        return leg
    if fore == "front":
        # The middle of the front of an AV standing still struck by a party going forward: it came at the AV
        # head-on; else the AV ran into it, ahead in its lane.
        return ("R7" if not junction and _came_at_standing_av(d, e, ctx, cside, ego_actions) else "R5"), "same", True
    if e.idx == d.partner and cside is None and d.ego_start == "stopped" and ego_actions == "" and \
            _going_forward(d, e, ctx):
        # Nothing told of its place nor of the part of the AV it struck, and the AV stood still throughout: it drove
        # into a standing AV, most often from behind ("The AV was stopped at a red light when a sedan was unable to
        # stop in time and collided with the AV"). Studyable: of the 119 parties that touched an AV standing
        # throughout, 86 were behind it (69 in its lane), 8 ahead in its lane (backing into it, mostly).
        return "R6", "same", False
    return "R5", "same", False


# Where a party or a thing came from, told by a compass side of the street ("from the west sidewalk", "from the
# eastern curb", "ran from the north side of [XXX]").
FROM_COMPASS_SIDE = compile_gated(r"\bfrom\s+the\s+(north|south|east|west)(?:ern)?\s+(?:side|curb|sidewalk|shoulder|edge)",
                                  re.I)
# ... or by a side of the AV ("from the left side" is a direction too; "from the left side of the road" a place, "from
# the left lane" a lane; "from right to left" across the AV's path: it came from the right)
_FROM_SIDE = compile_gated(r"\bfrom\s+(?:the|EGO's|its)\s+(left|right)\b(?!\s+adjacent|\s+(?:turn\s+|hand\s+)?lane|"
                           r"\s+side\s+of)|\bfrom\s+(?=(?:left\s+to\s+right|right\s+to\s+left)\b)(left|right)", re.I)


def came_from_side(ctx: str) -> str | None:
    """The side of the AV (left/right) a party or thing came from, when its words say so."""
    m = _FROM_SIDE.search(ctx)
    return (m.group(1) or m.group(2)).lower() if m else None


def _compass_side(d: Doc, ctx: str) -> str | None:
    """The side of the AV a thing came from, told by a compass side of the street against the AV's heading."""
    m = FROM_COMPASS_SIDE.search(ctx)
    ego_heading = heading(d, -1)
    if m is None or ego_heading is None:
        return None
    rel = (CARDINALS[m.group(1).lower()] - ego_heading) % 360
    return "right" if rel == 90 else "left" if rel == 270 else None


# Backing up: "reversed", "backed up / out / into", "rolled back".
BACKING = compile_gated(r"\brevers|\bback(?:ed|ing|s)?\s+(?:up|out|into)\b|\bbacking\b|\brolled\s+back", re.I)


def _came_at_standing_av(d: Doc, e: Entity, ctx: str, cside: str | None, ego_actions: str) -> bool:
    """Did a vehicle or rider strike the front of the AV, no side of it, while the AV stood (stopped throughout or
    before the contact), going forward, with no turn, lane change or crossing of its own? Then it came the other
    way ("One cyclist then made contact with the front of the stationary Waymo AV": the gold's R7). Studyable: of
    the 13 parties that met the middle of the front of a standing AV, the 10 that backed into it are ahead (R5), the
    3 going forward oncoming (R7; lane same 1, left 2, the two on the left placed before this by their words)."""
    if cside or not (ego_actions == "" or ego_actions.endswith("h")):
        return False
    return _going_forward(d, e, ctx)


def _going_forward(d: Doc, e: Entity, ctx: str) -> bool:
    """A vehicle or rider on its way ahead along its lane: no backing in its string or words, no turn, lane change
    or crossing of its own, not told standing, parked or pulling out ("A car that was parked at the curb pulled out
    and struck the Waymo AV" stood at the curb beside or ahead of it), not named as stopped or parked."""
    own = {a.code for a in d.acts if a.who == e.idx}
    return e.category != "pedestrian" and not own & set("dekfgjmFTOPS") and not BACKING.search(ctx) and \
        not fre.search(r"\b(?:stopped|parked|stationary|waiting|stalled|idling|queued)\b",
                       " ".join(m.mods for m in e.mentions), re.I)


# A party told as crossing the AV's way at a junction: running the light or the stop sign ("ran the red light",
# "failed to stop for the stop sign", "proceeded through the red light"), cross traffic, heading perpendicular to
# the AV, or striking it broadside ("broadsided", "T-boned").
_CROSSING_TOLD = compile_gated(r"\b(?:ran|run|runs|running|through|against|violat\w*|disregard\w*|ignor\w*|"
                               r"fail\w*\s+to\s+(?:stop|yield)\s+(?:at|for))\s+(?:a|the|its|their)\s+"
                               r"(?:steady\s+|solid\s+|circular\s+)?(?:red|stop\s+sign)|\bred[- ]light[- ]runn\w*|"
                               r"\bcross[\s-]traffic\b|\bperpendicular\b|\bbroadsid\w*|\bt-?bon(?:ed|ing|es)\b", re.I)
# The AV stopped or slowed for the party: "yielding to the other Waymo AV", "stopped for a vehicle" (the words
# before its name).
YIELDED_TO = compile_gated(r"\b(?:yield\w*|stopp\w*|wait\w*|brak\w*)\s+(?:for|to)\s+(?:a|an|the|another)\s+"
                           r"(?:\w+\s+){0,2}$", re.I)
# ... gave it the right of way: "yield(ed/ing) to", "gave way to", "gave the right of way to" (not "stopped for" or
# "braked for": those may be the car ahead).
_GAVE_WAY_TO = compile_gated(r"\b(?:yield\w*(?:\s+the\s+right[- ]of[- ]way)?|gave\s+way|giving\s+way|gave\s+(?:the\s+)?"
                             r"right[- ]of[- ]way)\s+(?:for|to)\s+(?:a|an|the|another)\s+(?:\w+\s+){0,2}$", re.I)


def _crossing_leg(d: Doc, e: Entity, ctx: str, fore: str | None, cside: str | None,
                  ego_turning: bool) -> tuple[str, None, bool] | None:
    """A vehicle or rider at a junction that no heading, side or lane placed, told in its own words crossing the
    AV's way (running the light or the stop sign, cross traffic, broadside), and not behind the AV: on the crossing
    road on the side of the AV it struck, else on the left. Studyable: 10 reports tell a party running a red light
    or a stop sign; 6 of those parties are on a crossing road in the gold (2 more on the opposite approach, 2 behind
    the AV), all placed by a heading, a side or "from behind" before this; it reads the scene when those are
    missing (a redacted street, no heading), and a rear corner struck is then the tail of an AV crossing its way. A
    turning AV struck on its left met it from there too ("As the AV was making the left turn, a Subaru ... failed to
    stop for the stop sign and struck the front left side of the Cruise AV": R1)."""
    if e.category == "pedestrian" or fre.search(r"\bbehind\b|\bfollowing\b|\bfrom\s+the\s+rear\b", ctx, re.I):
        return None
    # (in the party's own words: "EGO was yielding to check for cross traffic ... when it was rear-ended" is not)
    if not _CROSSING_TOLD.search(ctx):
        return None
    side = cside or (side_from_flank(d, e) if e.idx == d.partner and fore == "front" else None)
    if ego_turning and side != "left":
        return None  # (a turning AV struck on its right or front may have met the opposite approach, R2)
    return ("R3" if side == "right" else "R1"), None, True


def _yielded_at_junction(d: Doc, e: Entity, fore: str | None, ego_actions: str) -> tuple[str, None, bool] | None:
    """A vehicle at a junction that nothing else placed and that the AV, going straight or turning right, yielded
    to ("stopped to yield to another vehicle at the intersection", "while yielding to the other Waymo AV"), touching
    no end of the AV: on the crossing road from the left, which a driver going straight or turning right yields to
    (3 of the 3 such studyable parties no other words place are R1 in the gold)."""
    if e.category not in ("car", "van", "truck", "bus", "motorcycle") or "d" in ego_actions or fore is not None:
        return None
    if any(_GAVE_WAY_TO.search(d.sents[m.sent][max(0, m.start - 50):m.start]) for m in e.mentions):
        return "R1", None, True
    return None


# A clause about the AV joined after the party's ("... began to reverse as EGO was parked at the curb", "...
# passed on the left while EGO waited"): what it says of a curb, a lane or a side is the AV's place.
AV_CLAUSE = compile_gated(r",?\s+\b(?:as|when|while|whilst|after|before|until|because|since|whereas)\s+(?:the\s+)?EGO\b",
                          re.I)


def own_context(d: Doc, e: Entity) -> str:
    """`story.context` of the party, each of its pieces cut where a clause about the AV begins."""
    return " | ".join(part[:av.start()] if (av := AV_CLAUSE.search(part)) else part
                      for part in context(d, e).split(" | "))


def _rear_lane(d: Doc) -> str:
    """The lane of a party that met the AV's rear: a corner of the rear ("the left rear corner", "the right tail
    lamp") is met by a party coming up on that side, a bumper ("the left rear bumper") by one behind in the lane
    (the official gold reads them so)."""
    corner = _REAR_CORNER.search(d.sents[d.contact_sent]) if d.contact_sent is not None else None
    return (body_side(corner.group(1) or corner.group(2)) if corner else None) or "same"


# The AV rear-ended by the party: "rear-ended EGO", "EGO was rear ended", "EGO ... struck from behind" (not "EGO
# rear-ended the sedan": the party is then ahead).
_REAR_ENDED_EGO = compile_gated(r"\brear[- ]?end(?:ed|ing|s)?\s+(?:the\s+)?(?:(?:stopped|stationary|waiting|slowing)\s+)?EGO\b|"
                                r"\bEGO\b[^.;]{0,60}?\b(?:was|were|got|been|being|is)\s+(?:\w+\s+)?(?:rear[- ]?ended\b|"
                                r"(?:struck|hit|impacted|bumped)\s+from\s+(?:behind|the\s+rear)\b)", re.I)


# "from behind" the AV, not from behind another thing ("came out from behind a parked truck": where it was hidden;
# the other thing is named next, so the party's words end there)
_NOT_ANOTHER = r"(?!\s*(?:$|\||(?:a|an|the|another|some|its|their)\s+(?!EGO\b)))"
FROM_BEHIND = r"from\s+behind\b" + _NOT_ANOTHER


# An oncoming party's move that is no junction's: a turn into a roadside place ("attempted to make a left turn across
# the stationary Waymo AV's lane of travel to the entrance of a parking lot"), or a run across the median ("swerved to
# the left, crossing the curbed median"). Met so, it is on the AV's own road even where the AV waits for a junction
# (sketch.md: a party on the AV's approach road is R5-R7). Studyable: the 2 oncoming parties read at a junction that
# are told so are both R7/left in the gold; the 17 others there are R2 (15), R1 and R3.
_OFF_THE_JUNCTION = compile_gated(r"\b(?:into|to|toward|towards)\s+(?:a|an|the)\s+(?:[\w-]+\s+){0,3}?(?:driveway|parking\s+"
                                  r"(?:lot|garage|structure)|garage|entrance|alley|gas\s+station)\b|"
                                  r"\b(?:cross\w*|over|across|jump\w*|mount\w*)\s+(?:the\s+)?(?:[\w-]+\s+)?"
                                  r"(?:median|divider)\b", re.I)


#: A roadside told by its compass side of the street ("on the north side of [XXX]", "on the west curb of 2nd
#: Avenue"); `relations` reads the street after it as a lane cue.
COMPASS_SIDE_OF = r"\bon\s+the\s+(north|south|east|west)(?:ern)?\s+(?:side|curb|edge)\s+of\b"
_PARTY_SIDE_OF = compile_gated(COMPASS_SIDE_OF, re.I)
# ... the AV's own, in its clause ("EGO was parked at the curb facing westbound on the north side of [XXX]")
_AV_SIDE_OF = compile_gated(r"\bEGO\b(?:(?!\b(?:when|while|as|and)\b)[^.;]){0,100}?" + COMPASS_SIDE_OF, re.I)


def _across_by_compass(d: Doc, ctx: str) -> re.Match[str] | None:
    """The party's roadside on the compass side of the street opposite the AV's own ("The Waymo AV was parked at the
    curb ... on the north side of [XXX] when a pickup truck reversed out of a driveway on the south side of [XXX]"):
    across the street from the AV, beyond the oncoming lane, as "across the street from EGO" says (R7/left)."""
    theirs = _PARTY_SIDE_OF.search(ctx)
    mine = theirs and d.once("av_side_of_street", lambda: _AV_SIDE_OF.search(d.text))
    if not (theirs and mine):
        return None
    return theirs if (CARDINALS[theirs.group(1).lower()] - CARDINALS[mine.group(1).lower()]) % 360 == 180 else None


def _off_the_junction(d: Doc, e: Entity, ctx: str) -> bool:
    """Does the oncoming party turn off into a roadside place or cross the median (its words, or the words of its own
    turn, which may be told further on than its context reaches)?"""
    return bool(_OFF_THE_JUNCTION.search(ctx)) or any(
        _OFF_THE_JUNCTION.search(d.sents[a.sent][a.pos:a.pos + 100]) for a in d.acts if a.who == e.idx and a.code in "de")


# In the AV's own lane or right before it, said of a party ("in EGO's lane", "directly in front of EGO"); not one
# only partly in it (a straddle of the centre line), nor one moving into it ("crossed into EGO's lane").
_IN_EGO_LANE = compile_gated(r"(?<!partially\s)(?<!partly\s)\b(?:in|within)\s+EGO's\s+(?:travel\s+)?lane\b|"
                             r"\b(?:directly|immediately|right)\s+(?:in\s+front|ahead)\s+of\s+EGO\b", re.I)
# A lane named by the direction it carries ("in the westbound lanes of [XXX]", "within the northbound travel lane").
_HEADING_LANE = compile_gated(r"\b(?:in|within|along|down)\s+(?:the\s+)?(north|south|east|west)bound\s+(?:travel\s+|"
                              r"traffic\s+|through\s+)?lanes?\b", re.I)
_INTO_A_LANE = compile_gated(r"\binto\s+(?:the\s+|EGO's\s+)?(?:[\w-]+\s+){0,2}lane\b", re.I)
# A part at a rear corner, on one side: the corner or quarter itself, a tail light, the rear wheel or tyre.
_CORNER_PART = r"(?:corner|quarter|tail[- ]?(?:light|lamp)|(?:wheel|tire|tyre)(?!\s+well))"
_REAR_CORNER = compile_gated(r"\bEGO's\s+(?:rear\s+)?(left|right|driver|passenger)(?:'s)?(?:[- ]side)?[- ](?:rear\s+)?"
                             rf"{_CORNER_PART}|\b(?:the\s+)?(?:rear\s+)?(left|right|driver|"
                             rf"passenger)(?:'s)?(?:[- ]side)?[- ](?:rear[- ]{_CORNER_PART}|tail[- ]?(?:light|lamp))\w*\s+of\s+EGO\b",
                             re.I)
# A side the party's place is given by ("to the right of EGO", "from the left"), not a side of a body.
PLACE_SIDE = compile_gated(r"\bto\s+the\s+(?:left|right)\s+of\s+EGO\b|\bfrom\s+(?:the|EGO's)\s+(?:left|right)\b"
                            r"(?!\s+(?:side|rear|front)\b)|\bon\s+EGO's\s+(?:left|right)\b(?!\s+(?:side|rear|front)\b)", re.I)


# The verbs that put one party right behind another: following it, or striking it in a chain.
_CHAIN_VERBS = (r"\b(?:behind|following|trailing|approached|collided\s+(?:with|into)|(?:made|came\s+into)\s+contact\s+"
                r"with(?:\s+the\s+(?:rear|back)(?:\s+bumper)?\s+of)?|rear[- ]ended|struck|impacted|contacted|hit)\s+"
                r"(?:the|a|an)\s+")
# ("struck the rear of the pickup truck": the other party named after a part of it)
_CHAIN = compile_gated(_CHAIN_VERBS + r"(?:(?:rear|back)(?:\s+(?:end|bumper))?\s+of\s+(?:the|a|an)\s+)?(?:[\w-]+\s+)?$",
                       re.I)
_CHAIN_NOUN = compile_gated(_CHAIN_VERBS + r"([\w-]+)(?:\s+([\w-]+))?", re.I)
# A party told standing or going behind the AV in its own words ("an SUV that was stopped behind the Waymo AV").
_BEHIND_EGO = compile_gated(r"\bbehind\s+(?:the\s+)?(?:stopped\s+|stationary\s+)?EGO\b", re.I)


def _told_behind_av(d: Doc, k: int) -> bool:
    """Is the party `k` told behind the AV in its own words? One that strikes it in a chain came from further
    behind, whichever of the two the text names first ("A sedan ... rear-ended an SUV that was stopped behind the
    Waymo AV, and the SUV then struck the rear of the Waymo AV")."""
    return bool(_BEHIND_EGO.search(own_context(d, d.ents[k])))


_TOWARD_EGO = re.compile(r"(?<!began\s)(?<!begun\s)(?<!started\s)(?<!begin\s)(?<!start\s)"
                         r"\b(?:heading|headed|coming|came|moving)\s+(?:directly\s+|straight\s+)?towards?\s+EGO\b(?!'s)"
                         r"(?![^|.]{0,25}\bfrom\s+(?:the|a|an|its)\s+(?:[\w-]+\s+){0,3}lane\b)", re.I)
_CLAUSE_END = re.compile(r"[;]|\b(?:when|while|as|but|after|before|because|until|then)\b|"
                         r",?\s+(?:and\s+)?(?:EGO|(?:the|a|an)\s+(?:other\s+)?(?!opposite\b|oncoming\b)\w+)\s+"
                         r"(?:was|were|had|is|yield\w*|stopp\w*|wait\w*|brak\w*)\b", re.I)


# The party's own flank named as where it was touched: "the passenger side of the sedan", "the rear driver side door
# of the vehicle" (a corner or a bumper may be an off-centre rear-end: no flank).
# ... and that flank named before its owner, wherever it stands ("the right side of the heavy truck", "its left mirror")
_OWN_FLANK = compile_gated(r"\b(?:its|their)\s+(?:(?:front|rear)[- ])?(?:left|right)\b|\b(?:left|right)(?:[- ](?:front|rear))?[- ]"
                           r"(?:side|door|quarter|fender|panel|mirror)\w*\s+of\s+(?:the|a|an|its|their)\s+(?!EGO\b)", re.I)
_FLANK_OF = compile_gated(r"\b(?:(?:front|rear)[- ])?(left|right|driver(?:'s)?|passenger(?:'s)?)(?:[- ](?:front|rear))?[- ]"
                          r"(?:side|door|quarter|fender|panel)\w*(?:\s+(?:door|panel))?\s+of\s+(?:the|a|an|that)\s+"
                          r"(?:[\w-]+\s+){0,2}$", re.I)


def side_from_flank(d: Doc, e: Entity) -> str | None:
    """The side (left/right) the party came from, told by its own flank the contact sentence says was touched:
    met by the AV's front (the callers' condition), its left flank faced the AV, so it came from the right."""
    for m in e.mentions:
        if m.sent == d.contact_sent and (f := _FLANK_OF.search(d.sents[m.sent][max(0, m.start - 60):m.start])):
            return "right" if f.group(1)[0] in "lLdD" else "left"
    return None


def _own_clause(after: str) -> str:
    """The words after a party's name up to the end of its clause: "oncoming" further on speaks of another party
    ("a van in the left lane, as EGO yielded to an oncoming car")."""
    m = _CLAUSE_END.search(after)
    return after[:m.start()] if m else after


_STREET = r"((?:[A-Z0-9][\w.'-]*\s+){1,3}?)(?:Street|St\b|Avenue|Ave\b|Road|Rd\b|Boulevard|Blvd|Drive|Dr\b|Way\b|" \
          r"Lane\b|Parkway|Highway|Hwy|Expressway|Place|Court|Terrace)"


def av_street(d: Doc) -> str | None:
    return d.once("av_street", lambda: _read_av_street(d))


def exit_street(d: Doc) -> str | None:
    return d.once("exit_street", lambda: _read_exit_street(d))


def _read_av_street(d: Doc) -> str | None:
    """The street the AV travels on, from the first clause that puts it on one ("EGO was traveling westbound on
    Vallejo Street", a turning AV's "from Harrison Street"); the name's words without the suffix, lower-cased."""
    turned_from = _turn_street(d, "from", 40)
    if turned_from:
        return turned_from
    for i, s in enumerate(d.sents):
        for m in d.ments[i]:
            if m.kind != "ego" or not m.subject:
                continue  # (not "behind EGO, made a left turn across EGO's lane onto Mason Street": the party's way)
            # Read in the AV's own clause: up to the next party named, a clause word or 160 characters ("EGO,
            # operating in driverless autonomous mode, was traveling at approximately 20 mph eastbound on Bush
            # Street"), not on into another's ("... as EGO began to enter, the SUV turned left onto Larkin Street").
            # (a sign is where the AV stopped, "at a stop sign on Jerrold Avenue", no other's clause)
            end = min([x.start for x in d.ments[i] if x.start > m.end and (x.kind == "party" or x.kind == "obstacle"
                                                                           and "sign" not in x.head)] + [m.end + 160])
            clause = _AV_CLAUSE_END.split(s[m.end:end], 1)[0]
            if (on := _ON_STREET.search(clause)):
                return on.group(1).strip().lower()
    return None


_ON_STREET = re.compile(rf"\b(?:on|along|onto)\s+(?:the\s+)?(?:\w+bound\s+)?{_STREET}")
_AV_CLAUSE_END = re.compile(r"\b(?:when|while|as|then|and\s+(?:a|an|the)\s)\b|;", re.I)


def _party_street(ctx: str) -> str | None:
    m = fre.search(rf"(?<!\bonto\s)\b(?:on|along|of)\s+(?:the\s+)?(?:\w+bound\s+)?{_STREET}", ctx)
    return m.group(1).strip().lower() if m else None


def _read_exit_street(d: Doc) -> str | None:
    """The street a turning AV turns onto ("turning right from Harrison Street onto 8th Street")."""
    return _turn_street(d, "onto", 60)


def _turn_street(d: Doc, preposition: str, reach: int) -> str | None:
    """The street named after `preposition` ("from" / "onto") in the AV's turn, when that turn is the
    interaction; the name's words without the suffix, lower-cased."""
    # (in the AV's own clause: "EGO was traveling on Grant Street when another vehicle, turning right from Clay
    # Street onto Grant Street, ..." is the party's turn)
    m = fre.search(rf"\bEGO\b(?:(?!\b(?:when|while|whereupon)\b)[^.]){{0,120}}?\bturn\w*\b[^.]{{0,{reach}}}?\b{preposition}\s+"
                   rf"(?:the\s+)?(?:\w+bound\s+)?{_STREET}", d.text)
    return m.group(1).strip().lower() if m and _turn_is_the_interaction(d, m.start()) and \
        not _party_between(d, m.start(), m.start() + m.group(0).find("turn")) else None


def _party_between(d: Doc, start: int, end: int) -> bool:
    """Is a party named between two offsets of the normalised text ("EGO was stopped ... yielding to a pickup truck
    that was in the intersection making a left turn from Barneveld Avenue": the turn is the truck's)?"""
    sent = max(0, bisect.bisect_right(d.starts, start) - 1) if d.starts else 0
    base = d.starts[sent] if d.starts else 0
    return any(x.kind == "party" and start < base + x.start < end for x in d.ments[sent])


def _turn_is_the_interaction(d: Doc, offset: int) -> bool:
    """A turn told in a sentence before any other party appears was finished before the interaction began (the
    AV is then on the street it turned onto)."""
    if fre.search(r"\bafter\s+(?:\w+\s+){0,2}$", d.text[max(0, offset - 30):offset], re.I):
        return False  # "After EGO made a right turn from Pleasant Street, ...": done before
    if fre.match(r"EGO\s+(?:was|is)\s+(?:\w+ing\b[^.;]{0,80}?\band\s+)?(?:in\s+the\s+(?:process|middle)\s+of\s+)?"
                 r"(?:making|turning|executing|completing)\b", d.text[offset:offset + 160], re.I):
        # "EGO was making a right turn from Stockton Street", "EGO was traveling north and turning right onto X":
        # the turn is going on as the party comes
        return True
    sent = max(0, bisect.bisect_right(d.starts, offset) - 1) if d.starts else 0
    first = d.once("first_party_sentence", lambda: min(
        (m.sent for e in d.ents for m in e.mentions[:1] if m.sent not in d.summary), default=None))
    return first is not None and sent >= first


# A road that crosses the AV's, told without its name: "on the cross street", "from a side road", "on the
# intersecting roadway", "out of the cross-street", "traveling perpendicular to EGO", "in cross traffic".
_CROSS_ROAD = compile_gated(r"\b(?:on|from|along|down|via|out\s+of|off)\s+(?:the|a|an)\s+(?:(?:cross(?:ing)?|side|perpendicular|"
                            r"intersecting|adjoining|transverse)[\s-]+|cross-?)(?:street|road|roadway|avenue|thoroughfare)s?\b|"
                            r"\bcross[\s-]street's\b|\bperpendicular\s+to\s+(?:EGO|EGO's|the\s+direction)\b|"
                            r"\b(?:in|from|with)\s+(?:the\s+)?cross[\s-]traffic\b", re.I)


def _on_other_street(d: Doc, ctx: str) -> bool:
    """Is the party put on a street other than the AV's ("a vehicle on Leavenworth Street ...", "on the cross
    street")?"""
    if _CROSS_ROAD.search(ctx):
        return True
    street, theirs = av_street(d), _party_street(ctx)
    return bool(street and theirs and not same_street(theirs, street) and not same_street(theirs, exit_street(d)))


def same_street(a: str | None, b: str | None) -> bool:
    """Two names of one street: equal, or one letter apart in a name of five or more (the narratives keep their
    typos: "on Winson Drive ... onto westbound Winston Drive")."""
    if a is None or b is None:
        return False
    if a == b:
        return True
    if min(len(a), len(b)) < 5 or abs(len(a) - len(b)) > 1 or re.sub(r"\D", "", a) != re.sub(r"\D", "", b):
        return False  # (numbered streets differ by their number: 18th and 19th Avenue are two streets)
    # one substitution, insertion or deletion
    i = next((k for k, (x, y) in enumerate(zip(a, b)) if x != y), min(len(a), len(b)))
    return a[i + 1:] == b[i + 1:] or a[i:] == b[i + 1:] or a[i + 1:] == b[i:]


def _onto_av_street(d: Doc, ctx: str) -> bool:
    """Does the party turn onto the AV's own street (so it came from a crossing road)?"""
    street = av_street(d)
    m = fre.search(rf"\bonto\s+(?:the\s+)?(?:\w+bound\s+)?{_STREET}", ctx)
    if street and m is None:
        # "completing a left turn from Clay onto Grant": the AV's street named without its suffix
        m = fre.search(r"\bonto\s+(?:\w+bound\s+)?((?:[A-Z0-9][\w.'-]*\s*){1,2}?)(?=[,.;]|\s+(?:and|when|then|as)\b)", ctx)
    return bool(street and m and m.group(1).strip().lower() == street)


# An object's lane told relative to the AV's ("a cone in the adjacent left lane", "debris in the lane to its right",
# "in the left lane next to it"): a lane named without such a word may be the AV's own.
_OBJECT_NEXT_LANE = compile_gated(r"\b(?:in|into|within)\s+the\s+(?:adjacent\s+(left|right)\s+lane|(left|right)[- ]"
                                  r"adjacent\s+lane|lane\s+to\s+(?:its|the|EGO's)\s+(left|right)|(left|right)\s+lane\s+"
                                  r"(?:next\s+to|beside|adjacent\s+to)\s+(?:it|EGO)\b)", re.I)
# An object on the far side of a two-way street ("parked on the opposite side of the street", "along the opposite
# curb"; a heading opposite the AV's, "parked on southbound 36th Avenue"): beside the oncoming lane.
_FAR_SIDE = compile_gated(r"\b(?:opposite|other|far)\s+(?:side|curb)\b", re.I)
_SIDE_HEADING = compile_gated(r"\b(?:on|along|of)\s+(?:the\s+)?((?:north|south|east|west)+)bound\b", re.I)
# The heading the AV turned to, in its own clause ("As EGO made a right turn onto southwestbound [XXX]").
_AV_TURNED_ONTO = compile_gated(r"\bEGO\b(?:(?!\b(?:when|while|whereupon)\b)[^.]){0,120}?\bturn\w*\b[^.]{0,60}?\b"
                                r"onto\s+(?:the\s+)?((?:north|south|east|west)+)bound\b", re.I)


# A barrier that closes a way rather than lining it: a gate or its arm, a barricade, a portable or construction
# barrier. It stands across the AV's path, in its lane; curbs, medians, walls and guardrails line the road. Studyable
# gold: the 4 barriers so named are all in the AV's lane (13 others: shoulder 8, left 4, same 1, a chain).
# ("a gate reader box", "the gate post": a thing beside the gate, no gate)
_ACROSS_THE_WAY = compile_gated(r"\b(?:(?:gate|gates|gate\s+arm|arm)\b(?!\s+(?:reader|box|post|pole|key\w*|control\w*|"
                                r"sign|house|booth|card|button|motor))|barricade\w*\b|(?:portable|temporary|construction|"
                                r"movable|moveable|water[- ]filled)\s+(?:\w+\s+)?barrier\b)", re.I)
# Things that move into the AV's path of themselves or thrown (an animal, a wheel come loose, a toy car).
MOVING_THINGS = ("animal", "debris", "other")


def obstacle_position(d: Doc, e: Entity, ego_codes: str, ego_turning: bool) -> tuple[str, str]:
    ctx = context(d, e)
    full = " ".join(d.sents[m.sent] for m in e.mentions)
    cat = "door" if e.idx in d.doors else e.category
    own = ctx.split(" | ")[0]  # what the first mention itself says of its place
    next_lane = _OBJECT_NEXT_LANE.search(own)
    # (a thing first named after the contact, struck on the way on, stood where its first mention puts it: "two
    # passenger cars that were also parked at the curb of southwestbound [XXX]")
    told = _SIDE_HEADING.search(own or d.sents[e.first.sent][e.first.end:e.first.end + 110])
    ego_heading = heading(d, -1)
    far = bool(_FAR_SIDE.search(own)) or (told is not None and ego_heading is not None and
                                          (CARDINALS[told.group(1).lower()] - ego_heading) % 360 == 180)
    if far and cat != "door":
        return "R7", "shoulder"
    if next_lane:
        lane = next(g for g in next_lane.groups() if g).lower()
    elif cat in ("barrier",) and fre.search(r"\b(?:median|divider|island)\b", " ".join(e.heads) + " " + ctx, re.I):
        # (the heads and the context joined by a space: "the median curb" opens the context with its modifier)
        lane = "left"
    elif fre.search(r"\bon\s+the\s+divider|\bon\s+the\s+median", ctx, re.I):
        lane = "left"
    elif cat == "barrier" and _ACROSS_THE_WAY.search(own):
        lane = "same"
    elif cat in ("barrier",) or fre.search(r"\b(?:curb|parked\s+at|parallel|sidewalk|shoulder|side\s+of\s+the\s+"
                                          r"(?:road|street)|parking\s+(?:lane|spot|space))\b", ctx, re.I):
        lane = "shoulder"
        if fre.search(r"\bleft\s+side\s+of\s+the\s+road|\bto\s+the\s+left\b", ctx, re.I):
            lane = "left"
    elif fre.search(r"\bon\s+the\s+right\b|\bright\s+side\b", ctx, re.I) and cat == "parked_vehicle":
        lane = "shoulder"
    elif fre.search(r"\b(?:in|on|blocking|obstructing|within)\s+(?:its|the|EGO's)\s+(?:own\s+|travel\s+)?lane|"
                    r"\bin\s+the\s+(?:middle|road|roadway)|\bahead\b", ctx, re.I):
        lane = "same"
    elif e.kind == "party" and e.parked and not fre.search(r"double", " ".join(m.mods for m in e.mentions) + own):
        lane = "shoulder"  # (a double-parked vehicle stands in a travel lane)
    else:
        lane = (side_named(ctx) or "same") if fre.search(r"\b(?:to|on)\s+the\s+(?:left|right)\b", ctx, re.I) else \
            "same"
    if cat == "door":
        owner = d.ents[d.doors[e.idx]]
        oc = context(d, owner) + " " + full
        lane = "left" if fre.search(r"\bon\s+the\s+right\b|\bbetween\b|\bmiddle\s+of\s+the\s+road", oc, re.I) else \
            "shoulder" if fre.search(r"\bparked\b|\bcurb\b", oc, re.I) else (side_named(oc) or "shoulder")
    if cat in MOVING_THINGS and (origin := _compass_side(d, ctx) or came_from_side(ctx)):
        # An animal or a thing that moved into the AV's path from one side ("a dog ran from the north side of [XXX]
        # towards the path of EGO", the AV eastbound) was beside the AV's lane on that side, as a walker crossing
        # mid-block is (sketch.md).
        lane = origin
    pos = "R5"
    # Behind the AV: said of the object itself, or (for the object the AV touched) its rear touched or the AV backing
    # into it, up to the contact ("The dog then crossed behind EGO" is where it went after); words about another party
    # in the same sentences ("a sedan traveling behind it") are not the object's.
    upto = " ".join(d.sents[m.sent] for m in e.mentions if d.contact_sent is None or m.sent <= d.contact_sent)
    if fre.search(r"\bbehind\s+(?:it|EGO)\b", own, re.I) or (e.idx == d.partner and fre.search(
            r"\bbehind\s+(?:it|EGO)\b|\brear\s+of\s+EGO|\bEGO's\s+rear\b|\breversing|\bbacking", upto, re.I)) or \
            (ego_codes.endswith("k") and e.idx == d.partner):
        pos = "R6"
    elif d.junction and ego_turning and e.idx == d.partner:
        pos = "R4"
    elif d.junction and told is not None and (onto := _AV_TURNED_ONTO.search(d.text)) and \
            CARDINALS.get(told.group(1).lower()) == CARDINALS.get(onto.group(1).lower()):
        # On the road the AV turned onto, told by the heading the AV turned to ("As EGO made a right turn onto
        # southwestbound [XXX] ... two passenger cars that were also parked at the curb of southwestbound [XXX]"):
        # beyond the junction, on its exit leg, whatever the AV touched first.
        pos = "R4"
    return pos, lane
