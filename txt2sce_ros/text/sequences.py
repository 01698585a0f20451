"""Action strings (the 13 codes) for the AV and each party, and the collision type, under sketch.md's rules."""

from __future__ import annotations

import re

from ..sketch import Party
from .actions import Act, turn_by_headings, turn_from_headings, who_for
from . import fastre as fre
from .fastre import compile_gated
from .mentions import Entity
from .scene import TURNED_GREEN
from .story import TURN_WORDS, Doc, before_contact, context, ego_contact_part, named_behind_by_av

_FORWARD = set("abdefgjm")
#: Words that give a standing party's direction, not a move ("headed toward Charleston Road").
_DIRECTION_ONLY = compile_gated(r"(?:headed|heading|facing)\b", re.I)
#: The AV's own verbs of moving off, as opposed to the participles that only describe it ("approaching").
#: (told in the present as in the past: "the AVO disengages and proceeds in manual")
_MOVES_OFF = compile_gated(r"(?:enter(?:ed|s)|proceed(?:ed|s)|pull(?:ed|s)|continu(?:ed|es)|drove|drives|went|goes|mov(?:ed|es)|"
                           r"accelerat(?:ed|es)|pass(?:ed|es))\b", re.I)


def sequence(acts: list[Act], *, stopped: bool, ego: bool, side: str | None) -> tuple[str, str]:
    """Raw acts of one party -> (start, action string) under sketch.md's rules."""
    codes: list[str] = []
    start = "stopped" if stopped else "moving"
    for k, a in enumerate(acts):
        c = a.code
        if c == "P":
            # told travelling before it, with no stop since: "a sedan traveling behind a bus pulled out"
            on_its_way = start == "moving" and any(x.code in "aA" for x in acts[:k]) and not (
                codes and codes[-1] == "h") and not any(x.code == "S" for x in acts[:k])
            c = "O" if any(x.code == "S" and "park" in x.text.lower() for x in acts[:k]) else \
                "F" if on_its_way else "i"
        if c == "Q":
            if side not in ("left", "right"):
                continue  # across the AV's front from its own lane, a junction or the roadside: told by other words
            c = "F"
        if c == "F" and codes and codes[-1] == "m" and not ego:
            continue  # "exiting a parking garage, crossed into EGO's lane": the crossing itself, not a lane change
        told = next((x for x in reversed(codes) if x != "a"), "")
        if c == "F" and told in ("f", "g") and (ego or codes[-1] == told and acts[k - 1].sent == a.sent):
            # "began a lane change into the right thru lane ... as the Waymo AV began merging": the AV's lane change
            # told again without its side is the one just told; so is a party's told right after it in the same
            # sentence ("attempted to go around the Waymo AV, attempting to merge with traffic in the center lane")
            c = told
        elif c == "F":
            c = "f" if (ego or side != "left") else "g"
            if fre.search(r"around", a.text, re.I) and not ego:
                c = "f"
        if c in ("T", "D"):
            continue  # a turn whose side nothing told (ego_sequence resolves the AV's "D" before this)
        if c in ("i", "b") and "accelerat" in a.text.lower() and codes and codes[-1] == "k":
            continue  # "transitioned into reverse and began to accelerate" (or "and accelerated"): the backing,
            # faster; no start forward, no speed-up of its own
        if c == "i" and "accelerat" in a.text.lower() and (
                start == "moving" and (not codes or codes[-1] != "h") or codes[-1:] == ["c"]):
            # "began to accelerate" while on its way speeds up, as after a slowing ("slowed to yield to the U-turning
            # passenger car and had begun to accelerate again"); only from a standstill is it a start
            c = "b"
        if c == "O":
            # Out of a parking spot at the curb: it stood, moved off, and moved into the traffic lane (left from
            # a right-hand curb, right from a left-hand one).
            if not codes:
                start = "stopped"
            codes += ["i", "g" if side == "left" and not ego else "f"]
            continue
        if c == "S":
            if not codes and not any(x in _FORWARD for x in codes):
                start = "stopped"
                continue
            c = "h"
        if not codes and c == "k":  # backing away is from a standstill (sketch.md)
            start = "stopped"
        if not codes and c == "h" and not ego and not stopped:
            if a.on_its_way or fre.search(r"\b(?:to\s+(?:a\s|an\s|stop\b)|suddenly|abruptly|short|quickly|hard)", a.text,
                                          re.I):
                codes.append("a")  # "the bus stopped suddenly", "came to a stop": an event of a party under way
            else:
                start = "stopped"  # "a vehicle stopped behind EGO then ...": where it stood
                continue
        if start == "stopped" and not codes and c == "h":
            continue  # already standing: no stop to tell
        if start == "stopped" and not codes and c in ("a", "b", "c"):
            c = "i"
        if start == "stopped" and codes and codes[-1] == "h" and c in ("a", "b"):
            c = "i"
        if codes and codes[-1] == "h" and c in ("a", "b") and (not ego or _MOVES_OFF.match(a.text)):
            c = "i"  # the AV's "entered the intersection" after a stop moves it off; "approaching" only describes
        if codes and codes[-1] == "k" and c in ("a", "b") and _MOVES_OFF.match(a.text):
            c = "i"  # "reversed slightly and then proceeded through a vacant marked parking space": forward again
        if start == "stopped" and not codes and c in "defgm":
            codes.append("i")
        if codes and codes[-1] == "h" and c in "defgjmF":
            codes.append("i")  # a turn or lane change after a stop moves off first ("stopped ... then changed lanes")
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
        if c == "i" and out and out[-1] not in "hk":
            continue  # "began moving towards" while already moving is no start; forward after backing up is one
        if c == "h" and out and out[-1] == "c":
            out[-1] = "h"
            continue
        if c == "i" and not out and start == "moving":
            c = "a"
        out.append(c)
    s = "".join(out)
    s = fre.sub(r"h+", "h", s)
    if not ego and s.startswith("ak"):
        # "A passenger car traveling directly in front of the Waymo AV started to reverse": a vehicle backs up only
        # from a standstill, so the run told by the participle is no manoeuvre of the interaction; it began
        # standing and backed (sketch.md: one that backs away from a standstill is just `k`).
        start, s = "stopped", s[1:]
    return start, s


def struck_by(d: Doc, e: Entity) -> bool:
    """Did party `e` do the contact ("a sedan stopped behind it struck its rear bumper"), as the subject of the
    contact verb (not "EGO was struck by a sedan", not "EGO made contact with a sedan")?"""
    if d.contact_sent is None or d.partner != e.idx:
        return False
    if fre.search(r"\b(?:was|were|been|got|is|are)\s+(?:\w+ly\s+)?$", d.sents[d.contact_sent][:d.contact_pos], re.I):
        return False  # "a pedestrian standing between EGO and the truck was contacted": the subject was struck
    return who_for(d.contact_pos, d.ments[d.contact_sent], None, d.sents[d.contact_sent]) == e.idx


def standing_party(d: Doc, e: Entity, told: list[Act], start: str, actions: str, ego_actions: str) -> tuple[str, str]:
    """A party's string where the text tells no move of it: a party standing that struck the AV moved off first
    (`i`, sketch.md: strings begin where the interaction does); one the backing AV struck, of which no motion is
    told, stood still throughout (`stopped`, empty)."""
    if start == "stopped" and not actions and struck_by(d, e):
        return start, "i"
    if not told and start == "moving" and _av_stood_behind(d, e):
        return "stopped", ""  # "EGO came to a stop behind its lead vehicle": the vehicle it stopped behind stood
    if not told and ego_actions.endswith("k") and d.partner == e.idx and not struck_by(d, e):
        return "stopped", ""
    return start, actions


_GREEN_MOMENT = compile_gated(r"\b(?:when|as|after|once|just\s+as)\s+(?:the\s+)?(?:traffic\s+)?(?:stop\s?)?(?:light|signal)s?"
                              r"\s+(?:then\s+|had\s+)?(?:turned|changed|went|cycled)\s+(?:to\s+)?green\b", re.I)


def queued_behind(d: Doc, e: Entity, told: list[Act], place: tuple[str, str | None], start: str,
                  actions: str) -> tuple[str, str]:
    """A party in the queue behind the standing AV that moved off into it ("the vehicle immediately behind EGO
    began to accelerate", "a vehicle trailing behind EGO moved forward", "when the light turned green, the
    passenger vehicle behind EGO made contact"): it stood behind the AV and started with the queue, so its string
    is a start from a standstill (sketch.md: a party that was stopped and then moved off forward starts with `i`).
    One told travelling or approaching was on its way (`a`)."""
    # ("A passenger car traveling directly behind the Waymo AV ... started to proceed straight": a participle that
    # places the party behind the AV tells where it was, not a run; "directly behind the Waymo AV" tells the same)
    told = [a for a in told if not (a.code == "a" and _PLACED_BEHIND.match(d.sents[a.sent], a.pos))]
    if place != ("R6", "same") or d.ego_start != "stopped" or start != "moving" or \
            any(a.code in "aAcdefgjkmF" for a in told):
        return start, actions
    if told and told[0].code in ("i", "b") and actions in ("", "a", "ab"):
        # its first move told is the start itself ("began to accelerate", "accelerated": from where it stood)
        return "stopped", "i"
    if told or actions not in ("", "a") or d.partner != e.idx or d.contact_sent is None:
        return start, actions
    s = d.sents[d.contact_sent]
    # (the green told before the contact, or after it in a clause of its moment: "the passenger vehicle behind EGO
    # made contact with the rear of EGO when the traffic light turned green", as "When the traffic light turned
    # green, the passenger vehicle ... made contact")
    green = TURNED_GREEN.search(s, 0, d.contact_pos) or _GREEN_MOMENT.search(s, d.contact_pos)
    # the party named in that clause as the one already behind the AV ("the passenger vehicle behind EGO")
    behind = any(m.entity == e.idx and m.det == "the" and fre.match(r"\s+(?:\w+ly\s+)?behind\s+EGO\b", s[m.end:])
                 for m in d.ments[d.contact_sent])
    return ("stopped", "i") if green and behind else (start, actions)


# (any word of the AV's standing: "came to rest behind", "was idling behind", "paused behind", "halting behind")
#: A participle of going that only places the party behind the AV ("traveling directly behind EGO").
_PLACED_BEHIND = compile_gated(r"(?:travel(?:l)?ing|driving|positioned|located)\s+(?:directly\s+|immediately\s+|right\s+)?"
                               r"behind\s+EGO\b", re.I)
_STOP_BEHIND = compile_gated(r"\b(?:stop|stops|stopped|stopping|halt|halts|halted|halting|standstill|rest|waiting|waited|"
                             r"waits|queued|idling|idled|sitting|sat|paused|pausing)\s+"
                             # where it stood told first, in its clause ("came to a stop in the rightmost travel lane
                             # heading south on X at Y, behind a van that was unloading")
                             r"(?:(?:(?!\b(?:when|while|as|and|but|then|after|before)\b)[^.;]){0,90}?[\s,]\s*)?"
                             r"(?:\w+ly\s+)?(?:directly\s+|"
                             r"immediately\s+|right\s+)?behind\s+(?:a|an|the|its|another)\s+(?:[\w-]+\s+){0,2}$", re.I)


def _av_stood_behind(d: Doc, e: Entity) -> bool:
    """Is the party named as what the AV stopped or waited behind ("came to a stop behind its lead vehicle")?"""
    return any(m.sent not in d.summary and named_behind_by_av(d, m, _STOP_BEHIND, 150) for m in e.mentions)


def moved_off_into_object(d: Doc, obstacles: list[Entity], actions: str) -> str:
    """"stopped for a double-parked vehicle ... Then the AV side-swiped the double-parked vehicle": an AV whose
    string ends stopped, and that then itself struck an object standing still, moved off first (`i`)."""
    if not actions.endswith("h") or d.contact_sent is None or d.partner is None or \
            d.partner not in {e.idx for e in obstacles}:
        return actions
    s = d.sents[d.contact_sent]
    before = [m for m in d.ments[d.contact_sent] if m.end <= d.contact_pos]
    # The AV did the striking: its clause's subject, or the mention just before the contact verb ("A minute later
    # the AV side-swiped ...").
    if who_for(d.contact_pos, d.ments[d.contact_sent], None, s) != -1 and \
            not (before and before[-1].kind in ("ego", "egod")):
        return actions
    return actions + "i"


_STANDING_AV = compile_gated(r"\b(?:the|a)\s+(?:stationary|stopped|motionless)\s+EGO\b", re.I)


def stood_at_contact(d: Doc, start: str, actions: str) -> str:
    """"a passenger car traveling directly in front of EGO stopped in lane, and began to reverse ... made contact
    with the front passenger side of the stationary EGO": an AV told on its way whose contact names it standing had
    stopped before it (`ah`), though no stop of it was told (the official gold: "made contact with the rear driver
    side of the stopped Waymo AV", `ah`)."""
    if start != "moving" or not actions or actions[-1] in "hk" or d.contact_sent is None:
        return actions
    return actions + "h" if _STANDING_AV.search(d.sents[d.contact_sent]) else actions


def opens_under_way(acts: list[Act], codes: str = "defgjF") -> tuple[list[Act], bool]:
    """A party whose first manoeuvre is told in progress ("a Tundra traveling south was making a right turn", "the AV
    was changing lanes to the left when") was doing it when the interaction began: its string opens with that letter
    (sketch.md), and a "traveling" told before it only describes the party. Returns the acts from that manoeuvre
    on, and whether the string opens under way. `codes`: the moves that may open a string; the extractor lets a
    party's slowing do so too ("an SUV approaching from the left was slowing": `c...`), and `ego_sequence` the
    AV's slowing, stop or pull-over ("was slowing to a stop ... when": `h`)."""
    k = next((k for k, a in enumerate(acts) if a.code not in "aA"), None)
    if k is None or not acts[k].under_way or acts[k].code not in codes:
        return acts, False
    if any(a.sent < acts[k].sent for a in acts[:k]):
        return acts, False  # told travelling first, in a sentence of its own: a run along its lane, then the move
    return acts[k:], True


#: A start that names the standstill it began from ("departing from a standstill").
_FROM_REST = compile_gated(r"\bfrom\s+(?:a|the)\s+(?:\w+\s+)?(?:standstill|stop)\b", re.I)
_CONTROL = compile_gated(r"\b(?:red|stop\s+sign|signal|stop\s+(?:line|bar)|light|crosswalk|stop-controlled)\b", re.I)


def _at_control(d: Doc, stop: Act, reach: int = 60) -> bool:
    """A stop told at a light, a sign, a line or a crosswalk, within `reach` characters of its clause ("came to a
    stop behind a Nissan Sentra that was stopped for the red light")."""
    clause = fre.split(r";|,(?!\s*(?:which|that|who)\b)", d.sents[stop.sent][stop.pos:stop.pos + reach])[0]
    return bool(_CONTROL.search(clause if reach > 60 else d.sents[stop.sent][stop.pos:stop.pos + reach]))


def _waited(d: Doc, stop: Act) -> bool:
    """A stop that is where the AV waited (a state, a yield, a light, a sign), not an event of the story."""
    return stop.code == "S" or bool(fre.search(r"yield", stop.text, re.I)) or _at_control(d, stop, 100)


#: A run told in the simple past ("The Waymo AV traveled northbound on X, when it reached ..."): the telling gone back
#: to the AV on its way, as "was traveling" is.
_TRAVELLED = compile_gated(r"(?:travel(?:l)?ed|drove|headed)\b", re.I)
#: A clause of the same moment ("while EGO remained stopped", "as EGO was stopped", "just as").
_SAME_MOMENT = compile_gated(r"\b(?:while|as)\b", re.I)
_FROM_BEHIND = compile_gated(r"\brear[- ]?end(?:ed|ing)?\b|\bfrom\s+behind\b|\bbehind\s+EGO\b|\bfrom\s+the\s+rear\b|"
                             r"\bfollowing\s+(?:directly\s+|closely\s+)?EGO\b", re.I)


def _struck_from_behind(d: Doc) -> bool:
    """Was the AV struck at its rear: the part the contact names, else the contact told by its geometry or by a
    party behind the AV ("a sedan behind EGO struck its rear bumper")?"""
    if d.contact_sent is None:
        return False
    fore = ego_contact_part(d)[0]
    return fore == "rear" or (fore is None and bool(_FROM_BEHIND.search(d.sents[d.contact_sent])))


def ego_sequence(d: Doc, first_party_pos: tuple[int, int] | None, *, party_first: bool = False) -> tuple[str, str]:
    """The AV's start state and actions: what it did before the interaction shrinks to its state then (stopped,
    or moving with the manoeuvre under way), then everything up to the contact. When another party opens the
    interaction, an AV that had stopped and then moved off starts "stopped" with "i" (moved off on green).
    A moving AV's string opens with its run (`a`) unless its first manoeuvre was told already under way."""
    start, actions, under_way = _ego_string(d, first_party_pos, party_first)
    if start == "moving" and not actions:
        return start, "a"  # moving with no manoeuvre told: it kept to its lane
    if start == "moving" and actions[0] in "bch" and not under_way:
        return start, "a" + actions  # speeding up, slowing or stopping is done by a party already on its way
    return start, actions


#: Between a standing and the participle that places it, no new clause ("was stopped ... for a red traffic signal on
#: [XXX] approaching [XXX]"; not "was stopped ..., and was approaching", "then approaching").
_CLAUSE_BREAK = compile_gated(r"[,;]|\b(?:and|then|when|while|as|before|after|until|but)\b", re.I)


def _place_approached(d: Doc, acts: list[Act], k: int) -> bool:
    """Is the AV's run `acts[k]` the participle "approaching" that tells where it stood, in the clause of the standing
    told just before it ("A Zoox vehicle ... was stopped behind traffic in the left turn lane (lane 2) for a red
    traffic signal on [XXX] approaching [XXX]": the cross street ahead of the stop, not a move off)?"""
    a = acts[k]
    if a.code != "a" or k == 0 or not fre.match(r"approaching\b", a.text, re.I):
        return False
    prev = acts[k - 1]
    return prev.code == "S" and prev.sent == a.sent and \
        not _CLAUSE_BREAK.search(d.sents[a.sent], prev.pos + len(prev.text), a.pos)


#: A participle of going that tells the speed of a move ("traveling at 16 mph", "moving at approximately 5 mph").
_AT_SPEED = compile_gated(r"(?:travel(?:l)?ing|moving|driving|going|proceeding)\s+at\s+(?:a\s+|an\s+)?(?:speed\s+of\s+)?"
                          r"(?:approximately\s+|about\s+|around\s+|roughly\s+|less\s+than\s+|under\s+)?\d", re.I)


def _describes_move(d: Doc, acts: list[Act], k: int) -> bool:
    """Is the AV's run `acts[k]` only the speed of the turn or lane change told under way just before it, in its
    sentence ("The AV was making a right turn along the [XXX], traveling at 16 mph")? The manoeuvre is what it was
    doing; the participle tells how fast."""
    a = acts[k]
    if a.code != "a" or k == 0 or not _AT_SPEED.match(d.sents[a.sent], a.pos):
        return False
    prev = acts[k - 1]
    between = d.sents[a.sent][prev.pos + len(prev.text):a.pos]
    return prev.code in "defgjF" and prev.under_way and prev.sent == a.sent and \
        not fre.search(r"[;.]|\b(?:and|then|when|while|before|after)\b", between)


#: A clause of the same moment opening just before the AV's move it tells ("... as the AV was slowing", "while EGO was
#: braking"): the move is the background of the main clause.
_AS_EGO_WAS = compile_gated(r"\b(?:as|while|when)\s+(?:EGO|it)\s+was\s+(?:still\s+)?$", re.I)


def _stop_retold_dropped(d: Doc, acts: list[Act]) -> list[Act]:
    """"slowed to a stop in anticipation of turning right ... A passenger car ... made a U-turn ... just behind the
    Waymo AV as the AV was slowing": a slowing or stop of the AV told in progress in a clause of the same moment, after
    its stop was told, is that stop told again (the contact came while it stopped); no slowing of its own."""
    out: list[Act] = []
    for a in acts:
        if a.code in "ch" and a.under_way and out and out[-1].code == "h" and out[-1].sent < a.sent and \
                _AS_EGO_WAS.search(d.sents[a.sent], max(0, a.pos - 30), a.pos):
            continue
        out.append(a)
    return out


#: A party placed behind the AV by a participle of going or following ("a pickup truck traveling directly behind the
#: Waymo AV", "the vehicle following EGO"): a follower, on its way behind the AV before the AV stopped.
_FOLLOWER = compile_gated(r"(?:travel(?:l)?ing|driving|positioned|located|following)\s+(?:directly\s+|immediately\s+|"
                          r"right\s+|closely\s+)?(?:behind\s+EGO|EGO)\b|\bbehind\s+EGO\s+(?:then\s+)?(?:made|struck|"
                          r"hit|collided|rear-ended)\b", re.I)


def _follower_ran_in(d: Doc) -> bool:
    """Did the AV's contact come from a follower that only ran into its rear: the party placed behind it by a
    participle of going ("a pickup truck traveling directly behind the Waymo AV made contact with the rear"), the
    contact at the AV's rear, and no manoeuvre of the party's told (no pass, lane change or turn around it)?"""
    if d.partner is None or d.contact_sent is None or not _struck_from_behind(d):
        return False
    told = [a for a in d.acts if a.who == d.partner and before_contact(d, a.sent, a.pos)]
    if any(a.code in "defgjkmFPQO" for a in told):
        return False
    return any(_FOLLOWER.search(d.sents[m.sent], m.end, m.end + 60) for m in d.ents[d.partner].mentions
               if m.sent <= d.contact_sent)


#: The AV's standing told as lasting while the party came ("While the Waymo AV remained stopped, a passenger car
#: traveling directly behind ...", "... entered the intersection while the Waymo AV continued to yield"): it stood
#: when the interaction began, follower or not (7 studyable reports tell a stop, a follower and the AV standing on:
#: gold `stopped` in 6; study5 9635 and 8617 read `ah` without this).
_STOOD_ON = compile_gated(r"\bEGO\s+(?:had\s+)?(?:(?:remained|stayed|was\s+still)\s+(?:stopped|stationary|still|"
                          r"parked|halted|in\s+place|at\s+(?:a\s+)?(?:complete\s+|full\s+)?(?:stop|standstill|rest))|"
                          r"(?:continued|continues)\s+to\s+(?:yield|wait|remain|be\s+stopped))\b", re.I)


def _stood_on(d: Doc, stop: Act) -> bool:
    """Is the AV told standing on after its stop `stop`, up to the contact (a lasting state, not the stop's result)?"""
    last = d.contact_sent if d.contact_sent is not None else stop.sent
    return any(_STOOD_ON.search(d.sents[i]) for i in range(stop.sent, last + 1))


def _stop_results_dropped(d: Doc, acts: list[Act]) -> list[Act]:
    """"EGO came to a stop to yield to cross-traffic. As EGO was stopped, a pickup truck traveling directly behind
    EGO made contact with its rear": the state told after a stop (in its sentence or the next) is that stop's result,
    not a fact of its own, when the party met was a follower that ran into the AV's rear: the interaction began as the
    AV stopped before it (`ah`). A party that came in or manoeuvred while the AV "remained stopped" began the
    interaction with the AV standing (stopped, ''; the official gold's rule, sketch.md: the AV's state when the
    interaction begins). 8 W-half studyable reports tell a stop, then the AV's state, then the party's act, none of
    them in the official gold; the gold's start agrees with this reading in 7 of 8 (stopped: study2 s135, study3
    10669 and 10726, study4 8851; `ah` for a follower: study2 s259 and s275, study3 7719); study3's 9347 ("approached
    the Waymo AV from behind") reads `ah`."""
    out: list[Act] = []
    stop: Act | None = None  # the AV's last stop, while only its states follow it
    dropped_after: Act | None = None
    for a in acts:
        if a.code == "S" and stop is not None and stop.sent >= a.sent - 1:
            dropped_after = stop
            continue
        stop = a if a.code == "h" else None
        out.append(a)
    # (who met the AV is read only when a state was told after a stop: most narratives tell none)
    if dropped_after is None or _stood_on(d, dropped_after):
        return acts
    return out if _follower_ran_in(d) else acts


def _ego_string(d: Doc, first_party_pos: tuple[int, int] | None, party_first: bool) -> tuple[str, str, bool]:
    """`ego_sequence`'s reading, and whether the string opens with a manoeuvre told under way."""
    # A summary sentence still tells the AV's state ("was stopped ... when a vehicle reversed into it").
    acts = [a for a in d.acts if a.who == -1 and (a.sent not in d.summary or a.code == "S")
            and before_contact(d, a.sent, a.pos) and not _done_before(d, a)]
    acts = _ended_in_retold_move(d, [_driveway_turn(d, a) for a in acts])
    # "was proceeding through the intersection after stopping": the stop came first, though told last.
    # "It slowed to yield to northbound traffic as EGO entered the intersection": a run told in a clause of the same
    # moment after the main one is the background the main clause's move happened against, so it comes first.
    told = list(acts)
    acts.sort(key=lambda a: (a.sent, not (a.code == "S" and _AFTER.search(d.sents[a.sent][:a.pos])),
                             not _background(d, a, told), a.pos))
    acts = _during_first(d, acts)
    # "was stopped in traffic ... on southbound San Antonio Road headed toward Charleston Road": after a stop, the
    # direction it faced is no move.
    acts = [a for k, a in enumerate(acts) if not (a.code == "a" and _DIRECTION_ONLY.match(a.text) and k > 0 and
                                                  acts[k - 1].code in "hS") and not _place_approached(d, acts, k)]
    acts = _stop_results_dropped(d, acts)
    acts = [a for k, a in enumerate(acts) if not _describes_move(d, acts, k)]
    acts = _stop_retold_dropped(d, acts)
    # "EGO was stopped ... when it was involved in a collision. EGO was traveling northbound ...": a summary's state
    # is the AV's at the contact when the telling goes back to it travelling.
    told = [a for a in acts if a.sent not in d.summary]
    if told and told[0].code == "a" and (told[0].under_way or _TRAVELLED.match(told[0].text)):
        acts = [a for a in acts if not (a.sent in d.summary and a.code == "S")]
    # "A Zoox vehicle in autonomous mode was slowing to a stop ... when a vehicle behind made contact", "While
    # traveling west on Post Street, the Waymo AV was executing a pullover maneuver and made contact": a slowing, a
    # stop or a pull-over told already under way, as a party's is, was what the AV was doing when the interaction
    # began; its string opens with it (sketch.md; the official gold's `c`, `l`), as it does after a run told in the
    # same sentence ("was traveling southbound ... and was slowing to a stop for a passenger drop-off when": `h`).
    # A run told first in a sentence of its own is kept ("was traveling eastbound. As the Cruise AV was coming to
    # a stop": `ah`).
    acts, opened = opens_under_way(acts, "chl")
    if first_party_pos is None:
        return (*sequence(acts, stopped=False, ego=True, side=None), opened)
    fs, fp = first_party_pos
    clause_start = fp
    s = d.sents[fs]
    m = list(fre.finditer(r"(?:,|;|\bwhen\b|\bas\b|\bwhile\b|\bthen\b)", s[:fp]))
    if m:
        clause_start = m[-1].start()
    else:
        clause_start = 0
    # A stop where the AV waited (a light, a sign), told in the first party's own clause before the party ("EGO came
    # to a stop behind a Nissan that was stopped for the red light"), is where the AV stood when it began; a stop
    # made for the party ("stopped for a scooterist ... violating a red light") is not.
    pre = [a for a in acts if (a.sent, a.pos) < (fs, clause_start) or
           (a.sent == fs and a.pos < fp and a.code == "h" and not a.under_way and "yield" not in a.text.lower() and
            not _FOR_IT.search(s[a.pos + len(a.text):fp]) and _at_control(d, a, 100) and
            not any(x.who == -1 and x.code not in "hS" for x in acts
                    if (fs, clause_start) <= (x.sent, x.pos) < (fs, a.pos)))]
    # "A passenger car traveling behind EGO made contact with its rear while EGO remained stopped at a stop sign":
    # the AV's state told in a clause of the same moment after the party's ("while", "as") is where it stood when
    # the party came in, as the same clause told first is ("While EGO remained stopped ..., a passenger car ...").
    pre += [a for a in acts if a.code == "S" and a not in pre and a.sent == fs and a.pos > fp and
            _SAME_MOMENT.search(s, fp, a.pos)]
    # So is any move of the AV told there ("An SUV approached EGO from behind, and ... made contact with the rear of
    # EGO as EGO began to proceed straight through the intersection", "the pickup truck ... made contact with the
    # drivers side of EGO as EGO moved into the left lane"): the clause tells what the AV was doing when the party
    # came in, as it does told first ("As EGO began to proceed ..., an SUV approached"); its moves come before the
    # party's in the telling, so they open the interaction, not follow it. (A lane change told again there, "began
    # a lane change into the right thru lane ... The passenger car ... accelerated as EGO began merging", is the one
    # told before: `sequence` reads it so after the party's moves.)
    # A run told there ("as EGO was traveling") only describes the AV on its way: no move of its own.
    late = [a for a in acts if a not in pre and a.code not in "aA" and a.sent == fs and a.pos > fp and
            (opener := _same_moment_opener(d, a)) is not None and opener.start() > fp and not _retells(a, pre)]
    if late:
        pre = [a for a in acts if a in pre or a in late]
    post = [a for a in acts if a not in pre]
    stopped = False
    prefix: list[Act] = []
    stops = [k for k, a in enumerate(pre) if a.code in ("h", "S")]
    if party_first and stops and any(a.code in ("a", "i", "b", "A") for a in pre[stops[-1] + 1:]):
        moves = [a for a in pre[stops[-1] + 1:] if a.code in "defgjklF"]
        return (*sequence([Act(pre[-1].sent, pre[-1].pos, "i", -1, "")] + moves + post, stopped=True, ego=True,
                          side=None), opened)
    waited = [k for k in stops if _waited(d, pre[k]) and k < stops[-1]]
    if waited and any(a.code in "aibAdefgjF" for a in pre[waited[-1] + 1:stops[-1]]):
        # "stopped at red light ... As the shuttle was crossing the intersection and slowing to a stop, the bus
        # made contact", "came to a complete stop at the stop sign. After EGO began to initiate a right-hand turn,
        # EGO came to a stop in response to oncoming traffic": it started where it waited, moved off (ahead or
        # into a turn), and its later stop, whatever it was made for, is an event of the story.
        rest = [a for a in pre[waited[-1] + 1:] if a.code not in ("a", "A", "i", "S")]
        if rest and rest[0].code == "b":
            rest = rest[1:]  # "accelerated" away from where it waited is its moving off
        return (*sequence([Act(pre[-1].sent, pre[-1].pos, "i", -1, "")] + rest + post, stopped=True, ego=True,
                          side=None), opened)
    if stops and pre[-1].code in "defgjF" and stops[-1] < len(pre) - 1:
        # Stopped, then moved off into a turn or lane change before the party comes in ("slowed and stopped behind
        # the arrow board, then began a lane change to the left"): a stop told as an event after a run keeps the
        # run (`a h i f`); a stop where the AV waited (a state, a light, a sign, a yield) is its start (`i f`).
        stop = pre[stops[-1]]
        moves = [a for a in pre[stops[-1] + 1:] if a.code in "defgjklF"]
        went = Act(stop.sent, stop.pos, "i", -1, "")
        if any(a.code in ("a", "A") for a in pre[:stops[-1]]) and not _waited(d, stop):
            return (*sequence([Act(stop.sent, stop.pos, "a", -1, ""), stop, went] + moves + post, stopped=False,
                              ego=True, side=None), opened)
        return (*sequence([went] + moves + post, stopped=True, ego=True, side=None), opened)
    if pre:
        last = pre[-1]
        if opened and all(a.code in "aA" for a in pre[1:]):
            # the manoeuvre told under way, and what only describes it ("was slowing and moving at approximately 2
            # mph"): the string opens with the manoeuvre
            prefix = [pre[0]]
        elif last.code == "h" and not last.under_way and _stood_on(d, last) and not _stopped_for_partner(d, last):
            # "slowed to a stop to yield to traffic ahead ... While EGO continued to yield, a passenger car traveling
            # directly behind EGO made contact": told standing on when the party came, the AV stood (`_STOOD_ON`)
            stopped = True
        elif last.code == "h" and any(a.code in ("a", "A") for a in pre[:-1]) and (
                not _waited(d, last) or (_struck_from_behind(d) and (last.sent, last.pos) < (fs, clause_start))):
            # "was traveling ... when it came to a stop behind a queue": a stop told as an event of the story is
            # part of the interaction (the AV was moving when it began); a stop at a light or a sign, a yield, or a
            # state ("was stopped") is where the AV waited when it began; but a vehicle behind that runs into the
            # AV's rear ("was traveling ... and stopped at a stop sign. While yielding, a pickup truck traveling
            # behind made contact") met it as it stopped: the stop is told, `ah` (sketch.md's own example).
            prefix = [Act(last.sent, last.pos, "a", -1, ""), last]
        elif last.code == "h" and last.under_way and not last.text.lower().startswith("yield"):
            # "was traveling ... and was slowing to stop for a red light when ...": a stop still under way is an
            # event of an AV on its way (one that opens the telling opens the string)
            prefix = [last] if opened else [Act(last.sent, last.pos, "a", -1, ""), last]
        elif last.code == "h" and not _waited(d, last) and _stopped_for_partner(d, last):
            # "EGO came to a stop in the parking lot while yielding to ... an oncoming pickup truck", which then
            # struck it: the AV stopped for the very party it met, so the interaction began while it was on its way.
            prefix = [Act(last.sent, last.pos, "a", -1, ""), last]
        elif last.code == "h" and not _waited(d, last):
            # "EGO came to a stop to yield for approaching traffic": a stop told as an event, not at a light or a
            # sign, nor as a state, was made by an AV on its way (the gold sketches' `ah`, `h`).
            prefix = [Act(last.sent, last.pos, "a", -1, ""), last]
        elif last.code in ("h", "S"):
            stopped = True
        elif last.code == "i" and (not last.under_way or _FROM_REST.search(last.text)) and \
                not any(a.code in "aAbcdefgjF" for a in pre[:-1]):
            stopped, prefix = True, [last]  # "moved off on a green light": no run told before it, it stood
            # ("was moving forward", told in progress, is a run along its lane; "while departing from a
            # standstill" names where it began)
        elif last.code == "l" and not last.under_way and last.sent < fs and d.contact_sent is not None and \
                _STANDING_AV.search(d.sents[d.contact_sent]):
            # "The Waymo AV was traveling east on [XXX], then pulled over at the curb for a passenger drop-off. The
            # Waymo AV passenger opened the rear driver side door ... An SUV ... attempted to pass the Waymo AV on the
            # left, and ... made contact with the open back driver side door of the stationary Waymo AV": a pull-over
            # finished in a sentence before the party comes in, the AV met standing, is where it stood when the
            # interaction began (stopped, ''); a contact during the pull-over keeps `l`
            stopped = True
        elif last.code == "k" and len(pre) > 2 and pre[-2].code == "h" and pre[-3].code in "aA" and \
                not _waited(d, pre[-2]):
            # "was proceeding through a parking lot ... came to a stop, and shortly thereafter EGOD assumed manual
            # control. EGOD reversed slightly": a run, a stop and the backing told before the party comes in are
            # the story that ends at it (`ahk`), as a stop and a start are (`ahi`, below)
            prefix = [Act(last.sent, last.pos, "a", -1, ""), pre[-2], last]
        elif last.code in ("d", "e", "f", "g", "j", "k", "l", "F", "O", "c"):
            prefix = [last]
            if last.code in "fgF" and not last.under_way and any(a.code in ("a", "A") for a in pre[:-1]):
                # "was traveling north ... causing the AV to steer to the right": a run along its lane, then the
                # lane change; one told in progress ("was changing lanes when") opens the string.
                prefix = [Act(last.sent, last.pos, "a", -1, ""), last]
            turning = [a for a in pre[:-1] if (a.code in ("d", "e") and _turning(d, a)) or
                       (a.code in "fgF" and a.under_way)]
            if last.code == "c" and turning and all(a.code in ("c", "h", "S") or a is turning[-1]
                                                    for a in pre[pre.index(turning[-1]):]):
                # "was traveling west and turning right onto X. While executing the turn, the AV braked": it was
                # turning when the interaction began, and slowed in the turn ("was changing lanes into the left
                # turn lane ... when EGO slowed down": so with a lane change under way).
                prefix = [turning[-1], last]
        elif last.code == "T":
            # ("was traveling east on X and turned north onto Y": compass words with no "-bound")
            turn = turn_from_headings(d.sents[last.sent]) or turn_by_headings(
                d.sents[last.sent], 0, last.pos, last.pos + len(last.text))
            if turn:
                prefix = [Act(last.sent, last.pos, turn, -1, last.text)]
        elif last.code == "i" and any(a.code == "h" for a in pre[:-1]):
            # "slowed to a stop while entering a narrow roadway ... proceeded forward, making contact with a parked
            # vehicle": a stop and a start told before the party comes in are part of the story that ends at it.
            k = max(j for j, a in enumerate(pre[:-1]) if a.code == "h")
            run = pre[k - 1] if k > 0 and pre[k - 1].code in "adefgA" else Act(last.sent, last.pos, "a", -1, "")
            prefix = [run, pre[k], last]
        else:
            prefix = [Act(last.sent, last.pos, "a", -1, "")]
    return (*sequence(prefix + post, stopped=stopped, ego=True, side=None), opened)


# "After completing a right turn onto Taraval, ...", "After EGO made a right turn from Pleasant Street, ...", "had made
# a right turn from Oakdell Rd.": a turn told as done before the clause that tells the story.
# "Having completed ...", "Shortly after turning left ...": an "after" that opens the sentence or a clause, or a
# pluperfect; "EGO stopped after turning right" (mid-clause) may tell the story's own order and is left alone.
_DONE_BEFORE = compile_gated(r"(?:(?:^|[,;])\W*(?:(?:shortly|just|immediately|right|soon)\s+)?after|\bhad|\bhaving)\s+"
                             r"(?:just\s+)?(?:(?:EGO|EGOD|it)\s+(?:had\s+)?|having\s+)?(?:(?:completing|completed|making|made|turning|"
                             r"turned|finishing|finished|executing|executed)\b[^,.;]*)?$", re.I)


#: A clause of the same moment that follows its main clause (" as EGO entered", ", while EGO was approaching",
#: " while completing a right turn").
_TRAILING_SAME_MOMENT = compile_gated(r"(?:,\s*|\s)(?:just\s+)?(?:as|while)\s+(?:EGO\b|it\b|\w+ing\b)", re.I)


def _same_moment_opener(d: Doc, a: Act) -> re.Match[str] | None:
    """The opener (" as EGO", ", while EGO was", " while completing") of the clause of the same moment, told after
    a main clause, that act `a` lies in; None when `a` lies in no such clause (or past its end: a comma or a
    semicolon between the opener and the act)."""
    s = d.sents[a.sent]
    opener = None
    for m in _TRAILING_SAME_MOMENT.finditer(s, 0, a.pos + len(a.text)):
        if m.start() < a.pos:
            opener = m  # the last one before the act (or opening it: "while traveling northwest")
    if opener is None or ("," in s[opener.end():a.pos] or ";" in s[opener.end():a.pos]):
        return None
    return opener


def _retells(a: Act, told: list[Act]) -> bool:
    """Is `a` a lane change told without its side ("began merging") after one of the AV's told in `told`?"""
    return a.code == "F" and any(x.code in "fgF" for x in told)


def _background(d: Doc, a: Act, acts: list[Act]) -> bool:
    """Is the AV's run `a` (or a turn or lane change told under way) told in a clause of the same moment after a
    main clause that tells another move of the AV in the same sentence ("It slowed to yield ... as EGO entered the
    intersection", "slowed to a stop ... while completing a right turn")?"""
    if a.code not in "aA" and not (a.under_way and a.code in "defg"):
        return False
    opener = _same_moment_opener(d, a)
    if opener is None:
        return False  # no such clause, or the run is past its end
    return any(x.sent == a.sent and x.pos < opener.start() and x.code not in "aAS" for x in acts)


def _done_before(d: Doc, a: Act) -> bool:
    """A turn of the AV told as finished before the interaction: it set the AV's road and heading (read elsewhere),
    and is no part of the action string, which starts when the interaction begins (sketch.md)."""
    return a.code in "deTj" and bool(_DONE_BEFORE.search(d.sents[a.sent][:a.pos]))


_AFTER = compile_gated(r"\bafter\s+(?:having\s+|(?:it|EGO)\s+had\s+)?$", re.I)
#: A clause of the same moment about the AV, opening the sentence ("As EGO moved into the left lane, the pickup made
#: contact") or told after the contact's clause ("the pickup ... made contact with the drivers side of EGO as EGO moved
#: into the left lane"): where it ends at the act, the act is the AV's move when the contact came.
_RETOLD = compile_gated(r"(?:^\W*|[\s,])(?:as|while|when|just\s+as)\s+EGO\s+(?:was\s+)?$", re.I)


def _ended_in_retold_move(d: Doc, acts: list[Act]) -> list[Act]:
    """"EGO attempted to merge into the left lane and make a left turn ... As EGO moved into the left lane, the pickup
    made contact": the contact sentence opens by telling again a move the AV made before it; the contact came
    during that move, so the string ends with it, and what was told between (the turn it meant to make next) had not
    happened (sketch.md: strings end at the contact)."""
    for k, a in enumerate(acts):
        if a.sent != d.contact_sent or a.code not in "defgjklF" or not _RETOLD.search(d.sents[a.sent][:a.pos]):
            continue
        first = next((j for j in range(k) if acts[j].code == a.code and acts[j].sent < a.sent), None)
        if first is not None and any(x.code not in "aA" for x in acts[first + 1:k]):
            return acts[:first + 1] + acts[k + 1:]
    return acts


_SIDE_WORD = compile_gated(r"\b(?:left|right|driver|passenger)\b", re.I)


def _driveway_turn(d: Doc, a: Act) -> Act:
    """The AV's move into a driveway or lot ("D") is a turn; its side is the one the sentence says of it ("a
    driveway on the right"), else the side of the AV that touched (its inner corner meets what stands at the kerb:
    "pulling into a driveway, making contact with its left front bumper"), else unknown ("D", left out)."""
    if a.code != "D":
        return a
    s = d.sents[a.sent]
    said = fre.match(r"\s*(?:on|to)\s+(?:the|its|EGO's)\s+(left|right)\b", s[a.pos + len(a.text):])
    side = said.group(1).lower() if said else None
    if side is None and d.contact_sent is not None:
        words = {w.lower() for w in _SIDE_WORD.findall(TURN_WORDS.sub(" ", d.sents[d.contact_sent]))}
        sides = {"left" if w in ("left", "driver") else "right" for w in words}
        side = sides.pop() if len(sides) == 1 else None
    if side is None:
        return a
    return Act(a.sent, a.pos, "d" if side == "left" else "e", a.who, a.text, a.under_way)


_FOR_IT = compile_gated(r"\b(?:yield\w*|for)\s+(?:[^.;]*?\band\s+)?(?:a|an|the)?\s*(?:[\w-]+\s+){0,2}$", re.I)


def _stopped_for_partner(d: Doc, stop: Act) -> bool:
    """Is the AV's stop told as made for the party it then met ("came to a stop ... while yielding to both
    pedestrians and an oncoming pickup truck")?"""
    if d.partner is None:
        return False
    s = d.sents[stop.sent]
    end = stop.pos + len(stop.text)
    m = next((x for x in d.ments[stop.sent] if x.entity == d.partner and x.start >= end), None)
    return m is not None and bool(_FOR_IT.search(s[end:m.start]))


_BACKING_PARTS = frozenset({"parked_vehicle", "barrier", "pole", "other", "cone"})


def backed_into_object(d: Doc, obstacles: list[Entity], start: str, actions: str) -> tuple[str, str]:
    """"While EGOD was parallel parking ..., the rear of EGO made contact with the front of a parked pickup truck":
    an object standing still that the AV touched with its rear end was backed into (a forward-moving AV meets
    nothing with it), so the string ends backing (`k`); with nothing else told, the AV backed from a standstill."""
    if d.partner is None or "k" in actions or d.partner in d.doors:
        return start, actions
    e = next((x for x in obstacles if x.idx == d.partner), None)
    if e is None or (e.category not in _BACKING_PARTS and e.kind != "party"):
        return start, actions
    if ego_contact_part(d) != ("rear", None):
        return start, actions  # a rear corner ("the right rear sensor housing") is also met going forward, steering
    if actions in ("", "a"):
        return "stopped", "k"
    return start, actions + "k"


def _turning(d: Doc, a: Act) -> bool:
    """A turn told as under way: "turning right", "making a right turn", "executing a left turn", "during an
    unprotected left turn"."""
    return bool(fre.match(r"turning\b", a.text, re.I) or fre.search(
        r"\b(?:making|executing|completing|performing|during)\s+(?:a|an|the|its)\s+(?:\w+\s+)?$",
        d.sents[a.sent][max(0, a.pos - 40):a.pos], re.I))


_DURING = compile_gated(r"\bduring\s+(?:a|an|the|its)\s+(?:\w+\s+)?$", re.I)


def _during_first(d: Doc, acts: list[Act]) -> list[Act]:
    """"began to slow down during an unprotected left turn": a manoeuvre named after "during" was under way before
    the one told first in its sentence, so it comes first in the string (`dc`)."""
    out = list(acts)
    for k in range(1, len(out)):
        a, b = out[k - 1], out[k]
        if a.sent == b.sent and b.code in "defgjF" and a.code in "bch" and \
                _DURING.search(d.sents[b.sent][max(0, b.pos - 40):b.pos]):
            out[k - 1], out[k] = b, a
    return out


# (a party on its way told by any participle of going: "an opposing vehicle", "the trailing bus", "a speeding car")
_MOD_ACTS = (("m", compile_gated(r"\bjaywalking\b|\bcrossing\b", re.I)),
             ("a", compile_gated(r"\b(?:on-?coming|opposing|approaching|advancing|following|trailing|speeding|"
                                 r"lane-splitting)\b", re.I)))


_CENTRE_LINE = compile_gated(r"\b(?:cent(?:er|re)[\s-]?lines?|double[\s-]yellow|median\s+lines?)\b", re.I)


def wide_turn(acts: list[Act]) -> list[Act]:
    """A turn that swings over the centre line ("As the truck turned left, it partially crossed the centerline", "made
    a right turn onto X crossing the center line into the lane the Waymo AV was traveling in"): the crossing is the
    turn's own path, no lane change of its own (the studyable gold: `d`, `ea`)."""
    out: list[Act] = []
    for a in acts:
        turned = next((x for x in reversed(out) if x.code not in "aA"), None)
        if a.code in "fgF" and _CENTRE_LINE.search(a.text) and turned is not None and turned.code in "de" and \
                0 <= a.sent - turned.sent <= 1:
            continue
        out.append(a)
    return out


def prepend_modifier_acts(d: Doc, e: Entity, pacts: list[Act]) -> list[Act]:
    """"a jaywalking pedestrian", "an oncoming vehicle": the modifier tells the manoeuvre."""
    first = e.mentions[0]
    for code, rx in _MOD_ACTS:
        if rx.search(first.mods) and not any(a.code == code for a in pacts[:1]):
            return [Act(first.sent, first.start, code, e.idx, first.mods)] + pacts
    if e.category == "pedestrian" and not any(a.code in "mkhS" for a in pacts) and \
            fre.search(r"\bcross|\bjaywalk", context(d, e), re.I):
        # A pedestrian crossing, or in a crosswalk, crosses the AV's path: that is its manoeuvre, whatever verb
        # ("walking", "traveling") the text moved it with.
        return [Act(first.sent, first.start, "m", e.idx, "cross")] + [a for a in pacts if a.code not in "aA"]
    return pacts


#: The collision told as a rear-end ("rear-ended", "rear ended by", "a rear-end collision", "to rear-end"), not a
#: part of a vehicle called its rear end ("the left rear end of the AV", "into the right rear end", "its rear end":
#: another reporter's "rear bumper"). Over the 602 studyable narratives every "rear-end"/"rear end" not followed by
#: -ed/-ing is a part but for the two "rear-end collision"s; a part named so read as the kind made 16 of 90 rear
#: bumpers told "rear end" rear-ends (side swipes and broadsides).
_REAR_END_TOLD = compile_gated(r"\brear[- ]end(?:ed|ing)\b|\brear-ends\b|"
                               r"\brear[- ]end(?=\s+(?:collision|crash|accident|impact|type)\b)|"
                               r"\b(?:to|would|could|did|not)\s+rear[- ]end\b", re.I)


_SIDE_OF = compile_gated(r"\bside\s+of\s+(?:the\s+|an?\s+)?(?:[\w-]+\s+){0,2}$", re.I)


def _side_of_long_partner(d: Doc, partner: Entity) -> bool:
    """Did the contact meet the side of a truck, a bus or a pickup, however the contact's sentence names it ("the side
    of the pickup truck", and of the same party called "the pickup", "the other vehicle", "the third-party vehicle"
    there)? The partner's kind is its first naming's, not the noun the sentence happens to use."""
    long = any(w in ("truck", "bus", "pickup") for h in partner.heads for w in h.replace("-", " ").split())
    s = d.sents[d.contact_sent] if d.contact_sent is not None else ""
    return long and any(m.sent == d.contact_sent and _SIDE_OF.search(s, max(0, m.start - 40), m.start)
                        for m in partner.mentions)


def collision_type(d: Doc, partner: Entity | None, party: Party | None, obstacle: bool, ego_actions: str) -> str:
    if d.contact_sent is None:
        return "none"
    if partner is None:
        return "other"
    if obstacle:
        return "hit_object"
    if partner.category == "pedestrian":
        return "pedestrian"
    s = d.sents[d.contact_sent]
    if _REAR_END_TOLD.search(d.text):
        return "rear_end"
    if fre.search(r"\bside[- ]?swip", d.text, re.I):
        return "side_swipe"
    if fre.search(r"\bhead[- ]on\b", s, re.I):
        return "head_on"
    if fre.search(r"\bbroadside|\bt-bone", s, re.I):
        return "broadside"
    assert party is not None
    rear_hit = fre.search(r"\brear\b(?!\s+(?:driver|passenger|left|right)?\s*(?:side|door|quarter|wheel))", s, re.I) \
        and not fre.search(r"\b(?:side|door|mirror|quarter|fender)\b", s, re.I)
    if party.position == "R6" and party.lane == "same" and ego_actions.endswith("k"):
        return "rear_end"  # the AV backed into the party behind it
    if party.position == "R6":
        # Struck from behind is a rear-end (sketch.md) unless the text puts the contact on the AV's side.
        side_hit = fre.search(r"\b(?:side|mirror|door|fender|quarter)\b", s[d.contact_pos:], re.I) and not rear_hit
        return "rear_end" if party.lane == "same" and not side_hit else "side_swipe"
    if party.position == "R5":
        if party.lane == "same" and "k" in party.actions:
            return "rear_end"  # backed into the AV behind it
        if party.lane == "same" and ego_actions.endswith(("a", "b", "i")) and \
                fre.search(r"\b(?:rear|front)\s+(?:bumper|of)|\bbumper\b", s, re.I) and "m" not in party.actions:
            return "rear_end"
        if party.lane in ("left", "right") and fre.search(r"\bside\b|\bmirror|\bfender|\bdoor|\bquarter", s, re.I) \
                and "k" not in party.actions:
            return "side_swipe"
        return "broadside" if ("m" in party.actions or "k" in party.actions) else "side_swipe"
    if party.position == "R7":
        if "k" in party.actions and party.lane != "same":
            return "broadside"  # backed across the road into the AV's side, as a backing party beside it (R5) does
        touched = s[d.contact_pos:]
        return "head_on" if party.lane == "same" and fre.search(r"\bfront\b", touched, re.I) and not \
            fre.search(r"\bside\b", touched, re.I) else "side_swipe"
    if party.position in ("R1", "R3", "R4", "R2"):
        # (a party passing the AV as they touch, "passing the Waymo AV on the left, and the cyclist made contact",
        # met it along its side)
        if fre.search(r"\bside\s+of\s+the\s+(?:\w+\s+)?(?:truck|bus)|\bmirror|\bpass(?:ed|ing)\s+(?:the\s+)?EGO\b", s,
                      re.I) or _side_of_long_partner(d, partner):
            return "side_swipe"
        return "broadside"
    return "other"
