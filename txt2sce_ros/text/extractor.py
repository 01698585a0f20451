"""The offline extractor: one narrative -> one `Sketch`, by rules only (no network, no model, deterministic).

Pipeline: normalise (the AV becomes `EGO`) -> sentences -> mentions -> entities (coreference) -> manoeuvres with
their doers -> the AV's contact -> who counts -> positions -> action strings -> collision type -> `missing`.
Each step is a small function over plain records so a rule can be read, tested and changed on its own.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from ..errors import InputError
from ..sketch import Collision, EgoInfo, Obstacle, Party, Sketch
from .actions import Act, _who_for, find_acts, heading_of, turn_from_headings
from .lexicon import CONTACT, NEGATION
from .mentions import Entity, Mention, find_mentions, mark_parked, normalise, resolve, sentences
from .scene import environment, is_junction, road, signal_state

_SUMMARY = re.compile(r"\b(?:in|involved\s+in|involving)\s+(?:a|an)\s+(?:\w+\s+){0,2}(?:collision|incident|crash)"
                      r"\b|\breceived\s+notice\b|\bcollision\s+involving\b", re.I)
_BOILERPLATE = re.compile(r"\bis\s+reporting\s+this\s+crash\b|\bmay\s+supplement\b|\breport\s+was\s+(?:originally|"
                          r"updated)\b|\bsubmitted\b", re.I)
_DOOR = re.compile(r"\bopen(?:ed|ing|s)?\s+(?:\w+\s+){0,4}?doors?\b|\bdoors?\s+(?:was\s+|were\s+)?(?:opened|open)"
                   r"\b|\bdooring\b", re.I)
_AROUND = re.compile(r"\b(?:around|for|past|avoid(?:ing)?|behind|due\s+to|of)\s+"
                     r"(?:the\s+(?:left|right)\s+side\s+of\s+)?"
                     r"(?:a|an|the|another)?\s*(?:[\w-]+\s+){0,3}$", re.I)
_AROUND_ONLY = re.compile(r"\b(?:around|past)\s+(?:the\s+(?:left|right)\s+side\s+of\s+)?(?:a|an|the|another)?\s*"
                          r"(?:[\w-]+\s+){0,3}$|\baround\s+(?:a|an|the)\s+[\w\s-]{0,30}\band\s+(?:a|an|the)?\s*$", re.I)
_CONTACT_NOTHING = re.compile(r"\b(?:pavement|undercarriage|pothole|road\s+surface|ground|speed\s+bump|dip)\b", re.I)


@dataclass
class _Doc:
    text: str
    sents: list[str]
    ments: list[list[Mention]]
    ents: list[Entity]
    acts: list[Act]
    summary: set[int]
    junction: bool
    contact_sent: int | None = None
    contact_pos: int = 10 ** 9
    partner: int | None = None  # entity index; None with contact_sent set = contact with nothing
    doors: dict[int, int] = field(default_factory=dict)  # door entity -> owner entity
    struck: set[int] = field(default_factory=set)  # further objects the AV struck with the partner


def _summary_sentences(sents: list[str]) -> set[int]:
    """Sentences that summarise or administer rather than tell: "was in a collision involving an SUV", "Waymo is
    reporting this crash under ...", form headers ("Weather: Clear Passengers: 4 ...")."""
    out = {i for i, s in enumerate(sents) if _SUMMARY.search(s) or _BOILERPLATE.search(s)
           or len(re.findall(r"\b[A-Z][\w/]*(?:\s+[\w/]+){0,3}:\s", s)) >= 3}
    if sents and CONTACT.search(sents[0]) and any(CONTACT.search(s) for s in sents[1:]):
        out.add(0)
    return out


def _find_contact(d: _Doc) -> None:
    """The AV's contact: the last non-negated contact phrase in a sentence about the AV (summaries aside, unless
    nothing else tells it), and the party or object nearest that phrase."""
    candidates: list[tuple[int, int, int | None]] = []
    for i, s in enumerate(d.sents):
        ments = d.ments[i]
        has_ego = any(m.kind in ("ego", "egod") for m in ments) or re.search(r"\b(?:was|were|been|got)\s+"
                                                                             r"(?:struck|hit|contacted)", s, re.I)
        if not has_ego:
            continue
        for m in CONTACT.finditer(s):
            before = s[max(0, m.start() - 45):m.start()]
            if NEGATION.search(before) or re.search(r"\bneither\b|\bno\s+(?:other\s+)?(?:vehicles?|contact)\b", s,
                                                    re.I):
                continue
            others = [x for x in ments if x.kind in ("party", "obstacle") and x.entity >= 0]
            partner = None
            if others:
                # The doer of the contact verb, when it is not the AV; else what the AV touched (after the verb).
                who = _who_for(m.start(), ments, None)
                after = [x for x in others if x.start >= m.end()]
                if who is not None and who >= 0:
                    partner = who
                elif after:
                    partner = after[0].entity
                else:
                    best = min(others, key=lambda x: abs(x.end - m.start()))
                    partner = best.entity
                # A door that opened in the same sentence is what touched the AV.
                for door, owner in d.doors.items():
                    if d.ents[door].first.sent == i or (owner == partner and re.search(r"\bdoor", s[:m.start()])):
                        partner = door  # "opened a door into the AV" / "the edge of the cab's door made contact"
            candidates.append((i, m.start(), partner))
    if not candidates:
        return
    detailed = [c for c in candidates if c[0] not in d.summary]
    chosen = detailed[-1] if detailed else candidates[-1]
    if chosen[2] is None:
        # The detailed sentence may refer to the party by a pronoun ("it struck the AV"): take the summary's party.
        named = [c for c in candidates if c[2] is not None]
        if named:
            chosen = (chosen[0], chosen[1], named[-1][2])
    if chosen[2] is None and not _CONTACT_NOTHING.search(d.sents[chosen[0]]):
        # "Shortly thereafter, contact was made with the AV's front passenger side": the party in focus did it.
        recent = [m.entity for j in range(max(0, chosen[0] - 2), chosen[0]) for m in d.ments[j]
                  if m.kind == "party" and m.entity >= 0 and j not in d.summary and not d.ents[m.entity].parked]
        if recent:
            chosen = (chosen[0], chosen[1], recent[-1])
    d.contact_sent, d.contact_pos, d.partner = chosen
    while d.partner is not None and d.ents[d.partner].merged_into is not None:
        d.partner = d.ents[d.partner].merged_into
    # "contact with a center divider ... and the traffic sign": every object joined to the struck one was struck.
    if d.partner is not None and d.ents[d.partner].kind == "obstacle":
        ms = d.ments[d.contact_sent]
        idx = [k for k, x in enumerate(ms) if x.entity == d.partner]
        for k in range(idx[0] + 1 if idx else len(ms), len(ms)):
            between = d.sents[d.contact_sent][ms[k - 1].end:ms[k].start]
            if ms[k].kind == "obstacle" and re.fullmatch(r"[^,;]{0,30}\band\s*", between):
                d.struck.add(ms[k].entity)
            else:
                break


_AFTERWARDS = re.compile(r"\band\b|\bthen\b|\bbefore\b|\bafter\b|\bcontinued\b|\bleft\s+the\s+scene|\bcausing\b|"
                         r"\bdamaging\b|\bresulting\b", re.I)


def _before_contact(d: _Doc, sent: int, pos: int) -> bool:
    """Is text position (sent, pos) part of the story up to the contact? In the contact sentence, words after the
    contact verb still are, unless a new clause ("and proceeded left", "then") tells what came next."""
    if d.contact_sent is None:
        return True
    if sent != d.contact_sent:
        return sent < d.contact_sent
    if pos <= d.contact_pos:
        return True
    return not _AFTERWARDS.search(d.sents[sent][d.contact_pos:pos])


def _mentions_after_trigger(d: _Doc, e: Entity, *, around_only: bool = False) -> bool:
    """Did the AV act for this object ("around a double-parked vehicle", "stopped for debris")?"""
    rx = _AROUND_ONLY if around_only else _AROUND
    for m in e.mentions:
        s = d.sents[m.sent]
        if rx.search(s[max(0, m.start - 60):m.start]) and m.sent not in d.summary:
            return True
    return False


def _counted(d: _Doc) -> tuple[list[Entity], list[Entity]]:
    parties, obstacles = [], []
    for e in d.ents:
        if e.merged_into is not None:
            continue
        first_detail = [m for m in e.mentions if m.sent not in d.summary]
        first = first_detail[0] if first_detail else e.first
        is_partner = e.idx == d.partner
        if not is_partner and not _before_contact(d, first.sent, first.start):
            continue
        moved = any(a.who == e.idx and a.code in "abcdefgijkmFT" for a in d.acts)
        if e.kind == "party" and not moved and not is_partner and e.category in ("car", "van", "truck", "bus") and \
                _mentions_after_trigger(d, e, around_only=True) and not re.search(
                    r"\b(?:oncoming|approaching|moving|traveling|passing)\b", " ".join(m.mods for m in e.mentions)):
            e.parked = True  # a vehicle the AV went around, that did nothing itself, stood there
        if not is_partner and all(re.search(r"\bof\s+(?:a|an|the)?\s*(?:[\w-]+\s+){0,2}$",
                                            d.sents[m.sent][max(0, m.start - 30):m.start + len(m.mods) + 1])
                                  for m in e.mentions) and not moved:
            continue  # "a skateboard that escaped control of a nearby pedestrian": named only as an owner
        if e.idx in d.doors:
            obstacles.append(e)
        elif e.kind == "party" and e.parked and not moved:
            if is_partner or _mentions_after_trigger(d, e):
                obstacles.append(e)
        elif e.kind == "party":
            if any(d.doors.get(k) == e.idx for k in d.doors) and not moved:
                continue  # the door's vehicle stood still: only its door takes part
            if not first_detail and not is_partner:
                continue  # named in the summary only
            parties.append(e)
        elif e.kind == "obstacle":
            if is_partner or e.idx in d.struck or _mentions_after_trigger(d, e):
                obstacles.append(e)
    return parties, obstacles


def _ctx(d: _Doc, e: Entity) -> str:
    """Text around an entity's mentions before the contact: what the narrative says of its place."""
    parts = []
    for m in e.mentions:
        if not _before_contact(d, m.sent, m.start) and m.sent != d.contact_sent:
            continue
        s = d.sents[m.sent]
        nxt = [x.start for x in d.ments[m.sent] if x.start > m.end and x.kind in ("party", "obstacle")]
        end = min([m.end + 110, *nxt]) if nxt else m.end + 110
        parts.append(f"{m.mods} {m.head} {s[m.end:end]}")
    return " | ".join(parts)


_TURN_WORDS = re.compile(r"\b(?:left|right)[- ](?:hand\s+)?turn|\bturn(?:ed|ing|s)?\s+(?:left|right)|"
                         r"\b(?:left|right)\s+lane"
                         r"\s+change|\blane\s+change\s+to\s+the\s+(?:left|right)|\bright\s+of\s+way|\bleft\s+the\s+"
                         r"scene", re.I)


def _side(ctx: str) -> str | None:
    """The first side named in `ctx` ("in the rightmost lane", "to the left of"), turns and "right of way" aside."""
    ctx = _TURN_WORDS.sub(" ", ctx)
    left = re.search(r"\bleft(?:most)?\b", ctx, re.I)
    right = re.search(r"\bright(?:most)?\b", ctx, re.I)
    if left and right:
        return "left" if left.start() < right.start() else "right"
    return "left" if left else "right" if right else None


def _heading(d: _Doc, who: int) -> int | None:
    for i, s in enumerate(d.sents):
        for m in d.ments[i]:
            ent = -1 if m.kind in ("ego", "egod") else m.entity
            if ent == who:
                # Read up to the next party named in the sentence: its heading is its own.
                nxt = [x.start for x in d.ments[i] if x.start > m.end and x.kind == "party" and x.entity != who]
                window = s[m.end:min([m.end + 120, *nxt])]
                final = re.search(r"\b(?:onto|to)\s+((?:north|south|east|west)+)bound\b", window, re.I)
                if final and who == -1:  # the AV "turned right from southbound X onto westbound Y": heads west
                    return heading_of(final.group(1) + "bound")
                h = heading_of(window)
                if h is not None:
                    return h
    return None


def ego_contact_part(d: _Doc) -> tuple[str | None, str | None]:
    """Where the AV was touched, (front/rear, left/right), from the contact sentence's "the rear driver side of
    EGO" / "EGO's front bumper" (US vehicles: the driver side is the left)."""
    if d.contact_sent is None:
        return None, None
    s = d.sents[d.contact_sent]
    parts = [m.group(1) for m in re.finditer(r"((?:[\w-]+\s+){1,6})(?:of|on|to)\s+EGO\b", s)]
    passive = re.search(r"\b(?:was|were)\s+(?:\w+ly\s+)?(?:struck|hit|contacted|clipped|bumped|rear-ended)\b"
                        r"([^.]{0,80}?)"
                        r"(?:\bby\b|$)", s)
    if passive:
        parts.append(passive.group(1))  # "EGO was struck on a sensor attached to the rear ... by a minivan"
    parts += [m.group(1) for m in re.finditer(r"\bEGO's\s+((?:[\w-]+\s+){1,6})", s)]
    text = " ".join(parts).lower()
    fore = "rear" if re.search(r"\brear\b|\bback\b|\btail", text) else "front" if re.search(r"\bfront\b|\bhood\b",
                                                                                          text) else None
    side = "left" if re.search(r"\bdriver|\bleft\b", text) else "right" if re.search(r"\bpassenger|\bright\b",
                                                                                     text) else None
    return fore, side


def _position(d: _Doc, e: Entity, ego_heading: int | None, ego_turning: bool,
              ego_actions: str = "", behind_av: frozenset[str] = frozenset()) -> tuple[str, str | None, bool]:
    """(position, lane, known): where the party was relative to the AV when the interaction began.
    `behind_av`: head nouns of parties already placed behind the AV (R6); whoever follows them is behind too."""
    ctx = _ctx(d, e)
    queue = re.search(r"\b(?:behind|following|trailing)\s+(?:the|a|an)\s+(?:[\w-]+\s+)?([\w-]+)", ctx, re.I)
    if queue and queue.group(1).lower() in behind_av:
        return "R6", "same", True
    fore, cside = ego_contact_part(d) if e.idx == d.partner else (None, None)
    pre = " ".join(re.split(r"[,;]|\bwhen\b|\bas\b|\bwhile\b", d.sents[m.sent][max(0, m.start - 50):m.start])[-1]
                   for m in e.mentions[:2])
    full = " ".join(d.sents[m.sent] for m in e.mentions)
    passing = re.search(r"\b(?:pass(?:ed|ing|es)?|overtak(?:e|ing|en)|overtook)\s+(?:by\s+)?(?:the\s+)?(?:\w+\s+)?"
                        r"(?:EGO|it)\b(?:\s+(?:on\s+the\s+)?(left|right))?", ctx, re.I)
    if passing:
        return "R6", (passing.group(1) or "").lower() or _side(ctx[passing.end():passing.end() + 30]) or cside or \
            "same", True
    if re.search(r"^\s*\S*\s*(?:following|trailing)|(?:^|\s)(?:that\s+had\s+been\s+|that\s+was\s+|was\s+)?"
                 r"(?:traveling\s+|travelling\s+|driving\s+)?(?:directly\s+|immediately\s+)?(?:behind|following|"
                 r"trailing)\s+(?:directly\s+)?(?:the\s+)?(?:EGO|it|us|our)\b|\bfrom\s+behind\b|\bfrom\s+the\s+rear\b|"
                 r"\bto\s+EGO's\s+rear\b|^\s*\S*\s*behind\b|\b(?:following|trailing|behind)\s+(?:vehicle|car)|"
                 r"\bbehind\s+and\s+to\s+the\s+(?:left|right)\s+of\s+EGO",
                 ctx, re.I) or re.search(r"\b(?:following|trailing)\s*$", pre, re.I):
        side = None
        if re.search(r"\bpass(?:ed|ing)\b[^|]{0,40}\b(?:on\s+the\s+)?(left|right)\b", ctx, re.I):
            side = _side(re.search(r"\bpass(?:ed|ing)\b[^|]{0,40}", ctx, re.I).group(0))
        elif re.search(r"\bbehind\s+and\s+to\s+the\s+(left|right)", ctx, re.I):
            side = _side(ctx)
        if side is None and re.search(r"\bsidewalk\b|\bbike\s+lane\b", ctx, re.I):
            side = "right"
        return "R6", side or "same", True
    oncoming = re.search(r"\boncoming\b|\bopposite\s+direction\b|\bopposing\b|\bwrong\s+(?:way|side)\b|\bon-?coming\b",
                         ctx + pre,
                         re.I)
    h = _heading(d, e.idx)
    rel = None if h is None or ego_heading is None else (h - ego_heading) % 360
    if re.search(r"\bsame\s+direction\b", ctx + " " + pre, re.I):
        oncoming = None
        side_m = re.search(r"\b(?:to\s+the\s+)?(left|right)\s+of\s+EGO", ctx + " " + full, re.I)
        if side_m:
            return "R5", side_m.group(1).lower(), True
    if oncoming or rel == 180:
        if d.junction:
            return "R2", None, True
        return "R7", "same" if re.search(r"\bwrong\s+(?:way|side)\b", ctx, re.I) else "left", True
    if rel == 0 and not re.search(r"\bbehind\b", ctx, re.I):
        return "R5", _side(ctx) or "same", True
    if d.junction and rel in (90, 270):
        # Coming from the side opposite its heading: heading +90 (clockwise) of the AV's comes from the AV's left.
        return ("R1" if rel == 90 else "R3"), None, True
    compass = re.search(r"\bfrom\s+the\s+(north|south|east|west)\s+(?:side|curb)", ctx, re.I)
    if compass and ego_heading is not None:
        origin = {"north": 0, "east": 90, "south": 180, "west": 270}[compass.group(1).lower()]
        rel_origin = (origin - ego_heading) % 360  # 90: on the AV's right, 270: on its left
        if rel_origin in (90, 270):
            side = "right" if rel_origin == 90 else "left"
            if d.junction:
                return ("R3" if side == "right" else "R1"), None, True
            return "R5", side, True
    from_side = re.search(r"\bfrom\s+the\s+(left|right)\b(?!\s+adjacent|\s+(?:turn\s+|hand\s+)?(?:lane|side))", ctx, re.I)
    if d.junction and from_side:
        return ("R1" if from_side.group(1).lower() == "left" else "R3"), None, True
    if d.junction and "d" in ego_actions and re.search(r"\bapproaching\b", ctx, re.I):
        return "R2", None, True  # the AV turning left, a party approaching: the opposite approach
    if fore == "rear" and any(a.who == e.idx and a.code == "m" for a in d.acts):
        # Out of a driveway into the AV's lane, striking its rear: it came in behind, on the side it struck.
        return "R6", cside or "same", True
    lane_ctx = re.search(r"(?:(?:in|from)\s+the\s+(?:\w+\s+){0,2}(?:left|right)(?:\s+\w+){0,2}\s+lane|"
                         r"lane\s+to\s+the\s+"
                         r"(?:left|right)|(?:left|right)\s+(?:adjacent\s+)?lane|to\s+the\s+(?:left|right)\s+of\s+EGO|"
                         r"on\s+the\s+(?:left|right)|(?:left|right)\s+side|bike\s+lane|sidewalk|parallel|alongside|"
                         r"adjacent|beside|next\s+to|(?:left|right)\s+curb|driveway)", _TURN_WORDS.sub(" ", ctx), re.I)
    if lane_ctx:
        text = lane_ctx.group(0)
        side = _side(text) or ("right" if re.search(r"bike|bus|sidewalk|curb|driveway|parking", text + " " + ctx,
                                                     re.I) else None)
        if side is None:
            side = _side(ctx)
        if side is None and re.search(r"\badjacent\b|\bparallel\b|\balongside\b|\bbeside\b|\bnext\s+to\b", text,
                                      re.I):
            # Beside an AV in the leftmost lane is to its right (and the other way round).
            own = re.search(r"\bEGO\b[^.]{0,100}?\bin\s+the\s+(?:far\s+)?(left|right)(?:most)?\s+(?:\w+\s+)?lane",
                            d.text)
            side = {"left": "right", "right": "left"}.get(own.group(1).lower()) if own else None
            if side is None and re.search(r"\bEGO\b[^.]{0,60}?\b(?:parking\s+lane|shoulder|parked|at\s+the\s+curb)",
                                          d.text):
                side = "left"  # the AV at the curb: the traffic lane beside it is on its left
        side = side or "same"
        if d.junction and ego_turning and re.search(r"driveway|parking", ctx, re.I):
            return "R4", None, True
        return "R5", side, True
    if re.search(r"\b(?:in\s+front\s+of|ahead\s+of)\s+(?:the\s+)?EGO|\bEGO\b[^.|]{0,40}\bbehind\s+(?:a|an|the)\s+"
                 r"(?:\w+\s+){0,3}$", ctx + " " + pre, re.I) or re.search(r"\bbehind\s+(?:a|an|the)\s+(?:\w+\s+){0,3}$",
                                                                            pre, re.I):
        return "R5", "same", True
    if d.junction and ego_turning and e.category in ("pedestrian", "bicycle", "scooter") and \
            re.search(r"\bcrosswalk\b", ctx, re.I):
        return "R4", None, True
    if re.search(r"\b(?:ahead|in\s+front|preceding|in\s+EGO's\s+lane|in\s+its\s+lane|same\s+lane)\b", ctx, re.I):
        return "R5", "same", True
    if e.idx == d.partner and re.search(r"[fg]", ego_actions) and not re.search(r"[fg]", "".join(
            a.code for a in d.acts if a.who == e.idx)):
        return "R6", "left" if "f" in ego_actions else "right", True  # the AV moved over into its lane
    if fore == "rear":
        return "R6", "same", True
    turns = [a.code for a in d.acts if a.who == e.idx and a.code in "de"]
    if d.junction and turns and not re.search(r"\bfrom\s+the\s+(?:left|right)", ctx, re.I):
        # Turning onto the AV's road towards it: a left turn comes from the right, a right turn from the left;
        # a party that then follows the AV turned into its direction, so the sides swap.
        follows = re.search(r"\bfollow|\bbehind\s+EGO", ctx, re.I)
        from_right = (turns[0] == "d") != bool(follows)
        return ("R3" if from_right else "R1"), None, True
    if d.junction and e.category in ("car", "van", "truck", "bus", "motorcycle") and (
            re.search(r"\bentered\s+the\s+intersection", ctx, re.I)):
        side = _side(ctx)
        return ("R1" if side == "left" else "R3" if side == "right" else "R2"), None, bool(side)
    if re.search(r"\bbehind\b", ctx, re.I):
        return "R6", "same", True
    if e.idx == d.partner and re.search(r"[fg]", ego_actions) and not re.search(r"[fg]", "".join(
            a.code for a in d.acts if a.who == e.idx)):
        return "R6", "left" if "f" in ego_actions else "right", True  # the AV moved over into its lane
    if fore == "rear":
        return "R6", "same", True
    if fore == "front":
        return "R5", "same", True
    return "R5", "same", False


def _obstacle_position(d: _Doc, e: Entity, ego_codes: str, ego_turning: bool) -> tuple[str, str]:
    ctx = _ctx(d, e)
    full = " ".join(d.sents[m.sent] for m in e.mentions)
    cat = "door" if e.idx in d.doors else e.category
    if cat in ("barrier",) and re.search(r"\b(?:median|divider|island)\b", " ".join(e.heads) + ctx, re.I):
        lane = "left"
    elif re.search(r"\bon\s+the\s+divider|\bon\s+the\s+median", ctx, re.I):
        lane = "left"
    elif cat in ("barrier",) or re.search(r"\b(?:curb|parked\s+at|parallel|sidewalk|shoulder|side\s+of\s+the\s+"
                                          r"(?:road|street)|parking\s+(?:lane|spot|space))\b", ctx, re.I):
        lane = "shoulder"
        if re.search(r"\bleft\s+side\s+of\s+the\s+road|\bto\s+the\s+left\b", ctx, re.I):
            lane = "left"
    elif re.search(r"\bon\s+the\s+right\b|\bright\s+side\b", ctx, re.I) and cat == "parked_vehicle":
        lane = "shoulder"
    elif re.search(r"\b(?:in|on)\s+(?:its|the|EGO's)\s+lane|\bin\s+the\s+(?:middle|road|roadway)|\bahead\b", ctx,
                   re.I):
        lane = "same"
    elif e.kind == "party" and e.parked and not re.search(r"double", " ".join(m.mods for m in e.mentions)):
        lane = "shoulder"
    else:
        lane = _side(ctx) if re.search(r"\b(?:to|on)\s+the\s+(?:left|right)\b", ctx, re.I) else "same"
    if cat == "door":
        owner = d.ents[d.doors[e.idx]]
        oc = _ctx(d, owner) + " " + full
        lane = "left" if re.search(r"\bon\s+the\s+right\b|\bbetween\b|\bmiddle\s+of\s+the\s+road", oc, re.I) else \
            "shoulder" if re.search(r"\bparked\b|\bcurb\b", oc, re.I) else (_side(oc) or "shoulder")
    pos = "R5"
    if re.search(r"\bbehind\s+(?:it|EGO)\b|\brear\s+of\s+EGO|\bEGO's\s+rear\b|\breversing|\bbacking", full, re.I) or \
            (ego_codes.endswith("k") and e.idx == d.partner):
        pos = "R6"
    elif d.junction and ego_turning and e.idx == d.partner:
        pos = "R4"
    return pos, lane


_FORWARD = set("abdefgjm")


def _sequence(acts: list[Act], *, stopped: bool, ego: bool, side: str | None) -> tuple[str, str]:
    """Raw acts of one party -> (start, action string) under sketch.md's rules."""
    codes: list[str] = []
    start = "stopped" if stopped else "moving"
    for a in acts:
        c = a.code
        if c == "F":
            c = "f" if (ego or side != "left") else "g"
            if re.search(r"around", a.text, re.I) and not ego:
                c = "f"
        if c == "T":
            continue
        if c == "S":
            if not codes and not any(x in _FORWARD for x in codes):
                start = "stopped"
                continue
            c = "h"
        if not codes and c == "k" and not ego:
            start = "stopped"
        if not codes and c == "h" and not ego:
            start = "stopped"
            continue
        if start == "stopped" and not codes and c == "h":
            continue  # already standing: no stop to tell
        if start == "stopped" and not codes and c in ("a", "b", "c"):
            c = "i"
        if start == "stopped" and codes and codes[-1] == "h" and c in ("a", "b"):
            c = "i"
        if codes and codes[-1] == "h" and c in ("a", "b") and not ego:
            c = "i"
        if start == "stopped" and not codes and c in "defgm":
            codes.append("i")
        codes.append(c)
    out: list[str] = []
    for c in codes:
        if out and out[-1] == c:
            continue
        if c == "a" and out:
            continue  # "go straight" opens a string; later "approaching"/"following" only describe the same run
        if c == "A":
            c = "a"  # an explicit "continued straight" is a manoeuvre of its own
            if out and out[-1] == "a":
                continue
        if c == "i" and out and out[-1] != "h":
            continue  # "began moving towards" while already moving is no start from a standstill
        if c == "h" and out and out[-1] == "c":
            out[-1] = "h"
            continue
        if c == "i" and not out and start == "moving":
            c = "a"
        out.append(c)
    s = "".join(out)
    s = re.sub(r"h+", "h", s)
    return start, s


def _ego_sequence(d: _Doc, first_party_pos: tuple[int, int] | None, *, party_first: bool = False) -> tuple[str, str]:
    """The AV's start state and actions: what it did before the interaction shrinks to its state then (stopped,
    or moving with the manoeuvre under way), then everything up to the contact. When another party opens the
    interaction, an AV that had stopped and then moved off starts "stopped" with "i" (moved off on green)."""
    # A summary sentence still tells the AV's state ("was stopped ... when a vehicle reversed into it").
    acts = [a for a in d.acts if a.who == -1 and (a.sent not in d.summary or a.code == "S")
            and _before_contact(d, a.sent, a.pos)]
    if first_party_pos is None:
        return _sequence(acts, stopped=False, ego=True, side=None)
    fs, fp = first_party_pos
    clause_start = fp
    s = d.sents[fs]
    m = list(re.finditer(r"(?:,|;|\bwhen\b|\bas\b|\bwhile\b|\bthen\b)", s[:fp]))
    if m:
        clause_start = m[-1].start()
    else:
        clause_start = 0
    pre = [a for a in acts if (a.sent, a.pos) < (fs, clause_start)]
    post = [a for a in acts if (a.sent, a.pos) >= (fs, clause_start)]
    stopped = False
    prefix: list[Act] = []
    stops = [k for k, a in enumerate(pre) if a.code in ("h", "S")]
    if party_first and stops and any(a.code in ("a", "i", "b", "A") for a in pre[stops[-1] + 1:]):
        moves = [a for a in pre[stops[-1] + 1:] if a.code in "defgjklF"]
        return _sequence([Act(pre[-1].sent, pre[-1].pos, "i", -1, "")] + moves + post, stopped=True, ego=True,
                         side=None)
    if pre:
        last = pre[-1]
        if last.code in ("h", "S"):
            stopped = True
        elif last.code in ("d", "e", "f", "g", "j", "k", "l", "F"):
            prefix = [last]
        elif last.code == "T":
            turn = turn_from_headings(d.sents[last.sent])
            if turn:
                prefix = [Act(last.sent, last.pos, turn, -1, last.text)]
        else:
            prefix = [Act(last.sent, last.pos, "a", -1, "")]
    return _sequence(prefix + post, stopped=stopped, ego=True, side=None)


def _collision_type(d: _Doc, partner: Entity | None, party: Party | None, obstacle: bool, ego_actions: str) -> str:
    if d.contact_sent is None:
        return "none"
    if partner is None:
        return "other"
    if obstacle:
        return "hit_object"
    if partner.category == "pedestrian":
        return "pedestrian"
    s = d.sents[d.contact_sent]
    if re.search(r"\brear[- ]end", d.text, re.I):
        return "rear_end"
    if re.search(r"\bside[- ]?swip", d.text, re.I):
        return "side_swipe"
    if re.search(r"\bhead[- ]on\b", s, re.I):
        return "head_on"
    if re.search(r"\bbroadside|\bt-bone", s, re.I):
        return "broadside"
    assert party is not None
    rear_hit = re.search(r"\brear\b(?!\s+(?:driver|passenger|left|right)?\s*(?:side|door|quarter|wheel))", s, re.I) \
        and not re.search(r"\b(?:side|door|mirror|quarter|fender)\b", s, re.I)
    if party.position == "R6" and party.lane == "same" and ego_actions.endswith("k"):
        return "rear_end"  # the AV backed into the party behind it
    if party.position == "R6":
        return "rear_end" if party.lane == "same" and (rear_hit or re.search(r"\bbumper\b", s, re.I)) else "side_swipe"
    if party.position == "R5":
        if party.lane == "same" and "k" in party.actions:
            return "rear_end"  # backed into the AV behind it
        if party.lane == "same" and ego_actions.endswith(("a", "b", "i")) and \
                re.search(r"\b(?:rear|front)\s+(?:bumper|of)|\bbumper\b", s, re.I) and "m" not in party.actions:
            return "rear_end"
        if party.lane in ("left", "right") and re.search(r"\bside\b|\bmirror|\bfender|\bdoor|\bquarter", s, re.I) \
                and "k" not in party.actions:
            return "side_swipe"
        return "broadside" if ("m" in party.actions or "k" in party.actions) else "side_swipe"
    if party.position == "R7":
        touched = s[d.contact_pos:]
        return "head_on" if party.lane == "same" and re.search(r"\bfront\b", touched, re.I) and not \
            re.search(r"\bside\b", touched, re.I) else "side_swipe"
    if party.position in ("R1", "R3", "R4", "R2"):
        if re.search(r"\bside\s+of\s+the\s+(?:\w+\s+)?(?:truck|bus)|\bmirror", s, re.I):
            return "side_swipe"
        return "broadside"
    return "other"


def extract(text: str, report_id: str) -> Sketch:
    """Read one narrative into a sketch. Raises InputError for an empty text; otherwise always returns a sketch
    (with `missing` naming what the text lacks)."""
    if not text or not text.strip():
        raise InputError("empty narrative", source=report_id)
    t = normalise(text)
    sents = sentences(t)
    summary = _summary_sentences(sents)
    ments = [find_mentions(i, s) for i, s in enumerate(sents)]
    flat = [m for ms in ments for m in ms]
    ents = resolve(flat, summary, sents)
    mark_parked(ents, sents)
    d = _Doc(text=t, sents=sents, ments=ments, ents=ents, acts=[], summary=summary, junction=False)
    _add_doors(d)
    _attach_towed(d)
    fallback: int | None = None
    for i, s in enumerate(sents):
        d.acts += find_acts(i, s, ments[i], fallback)
        subj = [m for m in ments[i] if m.subject]
        if subj:
            fallback = -1 if subj[-1].kind in ("ego", "egod") else subj[-1].entity
    _find_contact(d)
    parties, obstacles = _counted(d)
    first_pos = None
    for e in parties + obstacles:
        ms = [m for m in e.mentions if m.sent not in summary] or e.mentions
        p = (ms[0].sent, ms[0].start)
        first_pos = p if first_pos is None or p < first_pos else first_pos
    junction = d.junction = is_junction([s if not _BOILERPLATE.search(s) else "" for s in sents],
                                        first_pos[0] if first_pos else 0, frozenset(summary))
    first_is_party = bool(parties) and (not obstacles or min(
        (([m for m in e.mentions if m.sent not in summary] or e.mentions)[0].sent,
         ([m for m in e.mentions if m.sent not in summary] or e.mentions)[0].start) for e in parties) == first_pos)
    ego_start, ego_actions = _ego_sequence(d, first_pos, party_first=first_is_party)
    if ego_start == "moving" and not ego_actions:
        ego_actions = "a"  # moving with no manoeuvre told: it kept to its lane
    ego_heading = _heading(d, -1)
    ego_turning = bool(set(ego_actions) & set("dej")) or bool(re.search(r"\bturn(?:ed|ing)\b", t)) and junction
    npcs: list[Party] = []
    missing: list[str] = []
    idmap: dict[int, str] = {}
    behind: set[str] = set()
    for k, e in enumerate(parties, 1):
        pos, lane, known = _position(d, e, ego_heading, ego_turning, ego_actions, frozenset(behind))
        if pos == "R6":
            behind |= e.heads
        pacts = [a for a in d.acts if a.who == e.idx and a.sent not in summary and _before_contact(d, a.sent, a.pos)]
        pacts = _prepend_mod_acts(d, e, pacts)
        first_sent = ([m.sent for m in e.mentions if m.sent not in summary] or [e.first.sent])[0]
        setup_stop = [k for k, a in enumerate(pacts) if a.code == "S" and a.sent == first_sent]
        if setup_stop:
            # "A passenger car, traveling in the same direction, was stopped in the adjacent lane": the scene's
            # opening state is stopped; the participle before it only describes the car.
            pacts = pacts[setup_stop[0]:]
        stopped = bool(re.search(r"\b(?:stopped|parked|stationary|waiting)\b", " ".join(m.mods for m in e.mentions)))
        start, acts = _sequence(pacts, stopped=stopped, ego=False, side=lane)
        if start == "moving" and acts[:1] in ("d", "e", "f", "g") and pos == "R5":
            acts = "a" + acts  # it travelled along the AV's road before turning off it
        if start == "moving" and not acts:
            acts = "a"  # a party in motion that the text gives no manoeuvre: it kept to its lane
        if pos not in ("R5", "R6", "R7"):
            lane = None
        if not known and not pacts:
            missing += ["position", "actions"]
        npcs.append(Party(id=f"npc{k}", category=e.category, position=pos, lane=lane,  # type: ignore[arg-type]
                          start=start, actions=acts))  # type: ignore[arg-type]
        idmap[e.idx] = f"npc{k}"
    obs: list[Obstacle] = []
    for k, e in enumerate(obstacles, 1):
        pos, lane = _obstacle_position(d, e, ego_actions, ego_turning)
        cat = "door" if e.idx in d.doors else ("parked_vehicle" if e.kind == "party" else e.category)
        obs.append(Obstacle(id=f"obs{k}", category=cat, position=pos, lane=lane))  # type: ignore[arg-type]
        idmap[e.idx] = f"obs{k}"
    partner = d.ents[d.partner] if d.partner is not None else None
    with_id = idmap.get(d.partner) if d.partner is not None else None
    if partner is not None and with_id is None:
        partner = None
    party = next((n for n in npcs if n.id == with_id), None)
    ctype = _collision_type(d, partner, party, bool(with_id and with_id.startswith("obs")), ego_actions)
    if d.contact_sent is None and not npcs and not obstacles:
        ctype = "none"
    if not npcs and not obs:
        missing.append("npcs")
        if d.contact_sent is not None:
            missing.append("actions")
    # Road facts come from the story up to the contact ("pulled over at a nearby parking lot" afterwards is no
    # part of the scene).
    scene = " ".join(sents[:d.contact_sent + 1]) if d.contact_sent is not None else t
    r = road(scene, junction=junction)
    if r.layout == "unknown":
        missing.append("road")
    sig = signal_state(t, layout=r.layout, control=r.control)
    return Sketch(report_id=report_id, road=r, environment=environment(t), signal_state=sig,  # type: ignore[arg-type]
                  ego=EgoInfo(start=ego_start, actions=ego_actions),  # type: ignore[arg-type]
                  npcs=tuple(npcs), obstacles=tuple(obs),
                  collision=Collision(with_=with_id, type=ctype),  # type: ignore[arg-type]
                  missing=tuple(dict.fromkeys(missing)))  # type: ignore[arg-type]


_MOD_ACTS = (("m", re.compile(r"\bjaywalking\b|\bcrossing\b", re.I)), ("a", re.compile(r"\boncoming\b|\bapproaching\b|"
                                                                                       r"\bfollowing\b", re.I)))


def _prepend_mod_acts(d: _Doc, e: Entity, pacts: list[Act]) -> list[Act]:
    """"a jaywalking pedestrian", "an oncoming vehicle": the modifier tells the manoeuvre."""
    first = e.mentions[0]
    for code, rx in _MOD_ACTS:
        if rx.search(first.mods) and not any(a.code == code for a in pacts[:1]):
            return [Act(first.sent, first.start, code, e.idx, first.mods)] + pacts
    if not pacts and e.category == "pedestrian" and re.search(r"\bcross", _ctx(d, e), re.I):
        return [Act(first.sent, first.start, "m", e.idx, "cross")]
    return pacts


def _add_doors(d: _Doc) -> None:
    """"opened a rear door into the side of the AV": a door obstacle, owned by the latest vehicle named before."""
    for i, s in enumerate(d.sents):
        for m in _DOOR.finditer(s):
            owners = [x for x in d.ments[i] if x.kind == "party" and x.start < m.start() and x.entity >= 0]
            if not owners:
                owners = [x for j in range(max(0, i - 2), i) for x in d.ments[j] if x.kind == "party" and x.entity >= 0]
            if not owners:
                continue
            owner = owners[-1].entity
            idx = len(d.ents)
            ment = Mention(sent=i, start=m.start(), end=m.end(), kind="obstacle", head="door", category="other",
                           det="a", mods="", subject=False, entity=idx)
            ent = Entity(idx=idx, kind="obstacle", category="other", heads={"door"}, mentions=[ment])
            d.ents.append(ent)
            d.ments[i].append(ment)
            d.ments[i].sort(key=lambda x: x.start)
            d.doors[idx] = owner
            break


def _attach_towed(d: _Doc) -> None:
    """"a pickup truck that was dragging a basketball hoop": what a party drags or carries moves with it, so a
    contact with it is a contact with the party."""
    for i, s in enumerate(d.sents):
        for m in d.ments[i]:
            if m.kind != "obstacle" or m.entity < 0:
                continue
            if re.search(r"\b(?:dragging|towing|pulling|carrying|hauling|dragged|towed)\s+(?:a|an|the)?\s*"
                         r"(?:[\w-]+\s+){0,3}$",
                         s[:m.start + len(m.mods) + 1]):
                owners = [x for x in d.ments[i] if x.kind == "party" and x.start < m.start and x.entity >= 0]
                if owners:
                    d.ents[m.entity].merged_into = owners[-1].entity
