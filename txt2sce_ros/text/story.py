"""The story of one narrative, as the extractor reads it: sentences, mentions, entities, manoeuvres, the AV's
contact, and who counts as a party or an obstacle.

`Doc` is the extractor's working state for one report (mutable while the steps fill it in, never returned); the
functions here are the steps that need the whole story at once.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TypeVar

from .actions import Act, heading_of, who_for
from . import fastre as fre
from .fastre import compile_gated
from .lexicon import CONTACT, NEGATION, PARKED_WORDS
from .mentions import Entity, Mention
from .scene import PRIOR_TURN

# Said of a party travelling the other way: "oncoming", "opposite direction", and at a junction the opposite
# approach ("from the opposite side of the intersection", "facing EGO").
ONCOMING = compile_gated(r"\bon-?coming\b|\bopposite\s+(?:direction|approach)\b|\bopposing\b|\bwrong[\s-]+(?:way|side|direction)\b|"
                         # the lanes or side of the road of the other direction ("in the opposite lane", "on the other
                         # side of the road": the words after it tell a path), going against traffic, meeting head-on
                         r"\bopposite(?=\s+(?:travel\s+|traffic\s+)?lanes?\b)|\b(?:opposite|other)\s+side(?=\s+of\s+the\s+"
                         r"(?:road|street|roadway)\b)|\bagainst\s+(?:the\s+)?(?:flow\s+of\s+)?traffic\b|\bhead[\s-]+on\b|"
                         r"\bopposite\s+(?:side|corner|end)\s+of\s+the\s+intersection\b|"
                         r"\bfacing\s+EGO\b|\bacross\s+the\s+intersection\s+from\s+EGO\b|"
                         # the far side of the AV's own road ("reversed out of a driveway across the street from EGO")
                         r"\bacross\s+the\s+(?:street|road|roadway)\s+from\s+EGO\b|"
                         # "going the other way", "in the other direction", "traveling toward EGO" (a vehicle's run
                         # at it; "moving toward" or "heading toward" is also said of a sideways move or one on foot)
                         r"\b(?:the\s+)?other\s+(?:way|direction)\b|\bopposite\s+way\b|"
                         r"\b(?:travel(?:l)?(?:ed|ing|s)?|driv(?:ing|es)|drove)\s+(?:directly\s+|straight\s+)?"
                         r"towards?\s+EGO\b(?!'s)", re.I)  # "toward EGO's destination lane" is no run at it

T = TypeVar("T")

_SUMMARY = compile_gated(r"\b(?:in|involved\s+in|involving)\s+(?:a|an)\s+(?:\w+\s+){0,2}(?:collision|incident|crash)"
                      r"\b|\breceived\s+notice\b|\bcollision\s+involving\b|"
                      # "was alleged to have contributed to a collision between an SUV and a concrete median curb"
                      r"\b(?:collision|crash|incident)\s+between\b|"
                      # "EGO and the passenger vehicle that made contact with it sustained moderate damage": the damage
                      # told after the event, its contact named again only to say whose damage
                      r"\b(?:that|which|who)\s+(?:had\s+)?(?:(?:made|came\s+into)\s+contact|contacted|impacted|collided|"
                      r"struck|hit)\b[^.]*\bsustained\b", re.I)


BOILERPLATE = compile_gated(r"\bis\s+reporting\s+this\s+crash\b|\bmay\s+supplement\b|\breport\s+was\s+(?:originally|"
                          r"updated)\b|\bsubmitted\b", re.I)


_DOOR = compile_gated(r"\bopen(?:ed|ing|s)?\s+(?:[\w'-]+\s+){0,4}?doors?\b|\bdoors?\s+(?:was\s+|were\s+)?(?:opened|open)"
                   r"\b|\bdooring\b|\bdoors?\b[^.]{0,40}?\b(?:swung|flew|popped|came)\s+open\b|"
                   # the owner named between the door and its opening ("the driver's side door of a stopped passenger
                   # vehicle in the right adjacent lane opened")
                   r"\bdoors?\s+of\s+(?:a|an|the)\s+[^.;,]{0,70}?\b(?:was\s+|were\s+)?(?:opened|open)\b", re.I)
# The AV's own door is no obstacle (sketch.md: "a door opened into the AV's path"): "the Waymo AV passenger opened the
# driver side rear door", "the open rear door of the Waymo AV", "EGO's open rear door".
_AV_DOOR_BEFORE = compile_gated(r"(?:\bEGO(?:'s)?\s+(?:(?:rear|front|back)\s+)?(?:passengers?|riders?|occupants?|"
                                r"customers?|EGOD)|\b(?:passengers?|riders?|occupants?|customers?)\s+(?:of|in|inside|"
                                r"riding\s+in)\s+EGO)\s+(?:had\s+|then\s+|also\s+|suddenly\s+)?$")
# ("EGO's open rear passenger door", "the rear door of EGO": the words between the owner and "door" name its place)
_AV_DOOR_NAMED = compile_gated(r"\bEGO's\s+(?:(?:open|opened|front|rear|back|left|right|driver|passenger|side|"
                               r"sliding|'s)\s+){0,4}$")
# ("the open back driver side door of the stationary EGO": a word of its state may stand between)
_AV_DOOR_AFTER = compile_gated(r"s?\s+of\s+(?:the\s+)?(?:[\w-]+\s+)?EGO\b")
# "the (open) door of a parked car": the vehicle named right after the door owns it.
_OF_OWNER = compile_gated(r"^\s*(?:\w+\s+){0,3}?of\s+(?:a|an|the|its|their)\s*$", re.I)


_AROUND = compile_gated(r"\b(?:around|for|past|avoid(?:ing)?|behind|due\s+to|of)\s+"
                     r"(?:the\s+(?:left|right)\s+side\s+of\s+)?"
                     r"(?:a|an|the|another)?\s*(?:[\w-]+\s+){0,3}$|"
                     # the second of two things acted for ("Due to the encroaching city bus and the pylons on the left
                     # edge of EGO's lane, EGO began to brake")
                     r"\b(?:around|for|avoid(?:ing)?|due\s+to)\s+(?:a|an|the)\s+(?:[\w-]+\s+){1,3}and\s+(?:a|an|the)?\s*$",
                     re.I)


_AROUND_ONLY = compile_gated(r"\b(?:around|past)\s+(?:the\s+(?:left|right)\s+side\s+of\s+)?(?:a|an|the|another)?\s*"
                          r"(?:[\w-]+\s+){0,3}$|\baround\s+(?:a|an|the)\s+[\w\s-]{0,30}\band\s+(?:a|an|the)?\s*$", re.I)


_THROWN = r"(?:projected|thrown|threw|kicked\s+up|kicked|launched|flung|propelled|flew|sent\s+flying)"
_THROWN_AFTER = compile_gated(rf"^[\s,]*(?:(?:which|that)\s+)?(?:(?:was|were)\s+)?{_THROWN}\b", re.I)
_THROWN_BEFORE = compile_gated(rf"\b{_THROWN}\s+(?:up\s+)?(?:a|an|the|some)?\s*(?:[\w-]+\s+){{0,3}}$", re.I)
_THROWN_MOD = compile_gated(rf"{_THROWN}\b", re.I)  # "projected road debris": the participle read into the name
_CONTACT_NOTHING = compile_gated(r"\b(?:pavement|undercarriage|pothole|road\s+surface|ground|speed\s+bump|dip)\b", re.I)


@dataclass
class Doc:
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
    starts: list[int] = field(default_factory=list)  # offset of each sentence in `text`
    av_lane: float | None = None  # the AV's own lane, 0 leftmost .. 9 rightmost (relations.av_lane_rank), if named
    ego_start: str = ""  # the AV's start state once read ("moving" / "stopped"): placing parties weighs it
    memo: dict[str, object] = field(default_factory=dict)  # facts of the whole text read once (positions.av_street)

    def offset(self, sent: int) -> int:
        """Where sentence `sent` starts in the normalised text."""
        return self.starts[sent] if sent < len(self.starts) else 0

    def once(self, key: str, read: Callable[[], T]) -> T:
        """`read()` computed once per narrative under `key`: facts of the whole text asked for once per party."""
        if key not in self.memo:
            self.memo[key] = read()
        return self.memo[key]  # type: ignore[return-value]


# A sentence about the report, not the event: "This report is meant to correct ...", "The content of this report is
# unchanged from the initial report ...", "This is a duplicate of 30270-5962-1".
_ABOUT_THE_REPORT = compile_gated(r"\b(?:this|the|original|initial|monthly|previous|prior)\s+(?:[\w-]+\s+){0,2}report\b|"
                                  r"\bduplicate\s+of\b|\breport\s+id\b", re.I)
_FORM_FIELD = compile_gated(r"\b[A-Z][\w/]*(?:\s+[\w/]+){0,3}:\s")  # "Weather: ", "Lighting Conditions: "


_NOTICE = compile_gated(r"\breceived\s+notice\b", re.I)


def summary_sentences(sents: list[str]) -> set[int]:
    """Sentences that summarise or administer rather than tell: "was in a collision involving an SUV", "Waymo is
    reporting this crash under ...", form headers ("Weather: Clear Passengers: 4 ...")."""
    out = {i for i, s in enumerate(sents) if _SUMMARY.search(s) or BOILERPLATE.search(s)
           or len(_FORM_FIELD.findall(s)) >= 3}
    notices = [i for i in sorted(out) if _NOTICE.search(sents[i])]
    # "Waymo received notice of an allegation that ..." a second time: the first announces the event, a later one
    # tells it ("... that as the fire engine proceeded straight, it made contact with the driver side of an SUV that
    # was parked at the curb"), unless it is a summary on other grounds too.
    out -= {i for i in notices[1:] if not _SUMMARY.search(_NOTICE.sub("", sents[i]))}
    # The opening sentence tells the contact in brief when a later one tells it again ("A Zoox vehicle was rear-ended
    # by a passenger car ... The passenger car ..."); notes about the report itself may come first ("This report is
    # meant to correct monthly report 30270-7719-1 ...", "The content of this report is unchanged ...").
    first = next((i for i, s in enumerate(sents) if not (BOILERPLATE.search(s) or _ABOUT_THE_REPORT.search(s))), None)
    if first is not None and CONTACT.search(sents[first]) and any(CONTACT.search(s) for s in sents[first + 1:]):
        out.add(first)
    return out


# A contact told as a belief ("the driver and operator believed they had run over a rock and did not realize they
# were hit by the vehicle"): no contact.
_BELIEVED = compile_gated(r"\b(?:believed|believing|thought|thinking|assumed|assuming|suspected|presumed)\s+(?:that\s+)?"
                          r"(?:\w+\s+){0,4}$", re.I)
# A relative clause in the pluperfect passive tells what had happened to the thing it describes before the story
# ("made contact with a small dog that had apparently been previously struck by a preceding vehicle"): an earlier
# event between others, no contact of the AV's.
_EARLIER_ADV = r"(?:(?:\w+ly|earlier|already|just|once|also)\s+){0,2}"
_EARLIER_PASSIVE = compile_gated(rf"\b(?:that|which|who)\s+(?:had|has|have)\s+{_EARLIER_ADV}been\s+{_EARLIER_ADV}$",
                                 re.I)


# ... and its agent ("struck by a preceding vehicle") took part in that earlier event only.
_EARLIER_AGENT = compile_gated(rf"\b(?:that|which|who)\s+(?:had|has|have)\s+{_EARLIER_ADV}been\s+{_EARLIER_ADV}"
                               r"\w+\s+by\s+(?:a|an|the|another)?\s*$", re.I)


def _antecedent(ments: list[Mention], pos: int) -> str | None:
    """The kind of the last mention before offset `pos` (what a relative clause there describes)."""
    before = [x for x in ments if x.end <= pos]
    return before[-1].kind if before else None


_PART_OF_BEFORE = compile_gated(r"\b(?:edge|side|end|corner|front|rear|part|portion|piece|arm|top|bottom)\s+of\s+"
                                r"(?:the|a|an|its)\s+$", re.I)
_CLAUSE_END = compile_gated(r"[,;.]|\b(?:and|when|while|as|then|before|after|but)\b", re.I)


def _between_others(d: Doc, i: int, m: re.Match[str]) -> bool:
    """Is contact `m` of sentence `i` one between another party and a thing that is not the AV ("As the SUV ... was
    passing EGO, it maneuvered to the left in its lane, and the driver side made contact with the center concrete
    median curb")? Its doer is a party (or an object by its part: "the edge of the barrier made contact with"), what
    it met (after the verb, in its clause) is another party or an object, and the AV is named neither there nor as
    the thing met ("was struck by a sedan" tells the doer after "by")."""
    s = d.sents[i]
    who = who_for(m.start(), d.ments[i], None)
    # an object's part as the doer ("the rightmost edge of the barrier made contact with the rear driver side of a
    # postal van parked at the curb": the barrier the AV pushed met the van, the AV's contact was the barrier)
    prior = [x for x in d.ments[i] if x.end <= m.start() and x.kind in ("party", "obstacle", "ego")]
    if prior and prior[-1].kind == "obstacle" and prior[-1].entity >= 0 and \
            not _CLAUSE_END.search(s, prior[-1].end, m.start()) and \
            _PART_OF_BEFORE.search(s, max(0, prior[-1].start - 40), prior[-1].start):
        who = prior[-1].entity
    if who is None or who < 0 or d.ents[who].kind not in ("party", "obstacle"):
        return False
    end = _CLAUSE_END.search(s, m.end())
    clause_end = end.start() if end else len(s)
    met = [x for x in d.ments[i] if m.end() <= x.start < clause_end and x.kind in ("party", "obstacle", "ego", "egod")]
    return bool(met) and met[0].kind in ("party", "obstacle") and met[0].entity not in (-1, who) and \
        not fre.search(r"\bby\b|\bEGO", s[m.end():met[0].start], re.I) and "EGO" not in s[m.end():clause_end]


_MET_LIST_END = compile_gated(r"[;.]|\b(?:when|while|as|then|before|after|but|which|that|who)\b", re.I)


def _pushed_on(d: Doc, i: int, m: re.Match[str]) -> None:
    """The object the AV met, pushed on into other things ("it pushed the barrier along with it and the rightmost edge
    of the barrier made contact with the rear driver side of a postal van parked at the curb ... with the driver side
    of two other postal vans and two passenger cars that were also parked"): what it met was struck too."""
    s = d.sents[i]
    prior = [x for x in d.ments[i] if x.end <= m.start() and x.kind in ("party", "obstacle", "ego")]
    if d.partner is None or d.ents[d.partner].kind != "obstacle" or not prior or prior[-1].entity != d.partner:
        return
    end = _MET_LIST_END.search(s, m.end())
    for x in d.ments[i]:
        if m.end() <= x.start < (end.start() if end else len(s)) and x.kind in ("party", "obstacle") and x.entity >= 0:
            d.struck.add(x.entity)


#: A contact told without its object ("made contact at approximately 10mph", "collided"): with the AV the story tells.
_CONTACT_NO_OBJECT = compile_gated(r"\b(?:made|makes|came\s+in(?:to)?)\s+(?:\w+\s+)?contact\b(?!\s+(?:with|between)\b)|"
                                   r"\bcollided\b(?!\s+with\b)", re.I)


def find_contact(d: Doc) -> None:
    """The AV's contact: the last non-negated contact phrase in a sentence about the AV (summaries aside, unless
    nothing else tells it), and the party or object nearest that phrase."""
    candidates: list[tuple[int, int, int | None]] = []
    met_by_others: list[tuple[int, re.Match[str]]] = []
    for i, s in enumerate(d.sents):
        ments = d.ments[i]
        has_ego = any(m.kind in ("ego", "egod") for m in ments) or fre.search(r"\b(?:was|were|been|got)\s+(?:\w+ly\s+)?"
                                                                             r"(?:struck|hit|contacted|impacted)", s,
                                                                             re.I) or (
            # "EGO was stopped at a light. A sedan traveling behind it struck its rear bumper": the pronoun is the
            # AV, the subject of the sentence before, when a party is this sentence's subject.
            i > 0 and any(m.kind in ("ego", "egod") and m.subject for m in d.ments[i - 1]) and
            any(m.kind == "party" and m.subject for m in ments) and (fre.search(r"\b(?:it|its)\b", s, re.I) or
                                                                     # "... slowing to a stop behind traffic. Then a
                                                                     # vehicle behind made contact at approximately
                                                                     # 10mph": a contact that names no object
                                                                     _CONTACT_NO_OBJECT.search(s)))
        if not has_ego:
            continue
        for m in CONTACT.finditer(s):
            before = s[max(0, m.start() - 45):m.start()]
            # Only a negation in the contact's own clause counts ("swerved to avoid the door and made contact" is a
            # contact), and being unable to avoid it is none.
            clause = fre.split(r"[,;]|\band\b|\bbut\b|\bthen\b|\bwhen\b", before)[-1]
            negated = bool(NEGATION.search(clause)) and not fre.search(
                r"\b(?:unable|could\s+not|couldn't|failed)\s+to\s+avoid\b", before, re.I)
            if negated or fre.search(r"\bneither\b|\bno\s+(?:other\s+)?(?:vehicles?|contact)\b", s, re.I):
                continue
            if _BELIEVED.search(s, max(0, m.start() - 50), m.start()):
                continue  # "believed they had run over a rock": what the driver thought, not what happened
            if _EARLIER_PASSIVE.search(s, max(0, m.start() - 60), m.start()) and \
                    _antecedent(ments, m.start()) not in ("ego", "egod"):
                continue  # "a small dog that had apparently been previously struck by a preceding vehicle"
            if _between_others(d, i, m):
                met_by_others.append((i, m))
                continue  # "it maneuvered to the left, and the driver side made contact with the median curb"
            others = [x for x in ments if x.kind in ("party", "obstacle") and x.entity >= 0]
            partner = None
            if others:
                # The doer of the contact verb, when it is not the AV; else what the AV touched (after the verb).
                who = who_for(m.start(), ments, None)
                after = [x for x in others if x.start >= m.end()]
                # "The front of the pickup truck then made contact with ...": the owner of the part is the doer
                owner = [x for x in others if x.start < m.start() and _PART_OWNER.search(s[max(0, x.start - 40):x.start])
                         and not fre.search(r"[,;]|\b(?:when|as|while|and|after|before)\b", s[x.end:m.start()], re.I)]
                if who is None and owner:
                    partner = owner[-1].entity
                elif who is not None and who >= 0:
                    partner = who
                elif after:
                    partner = after[0].entity
                else:
                    best = min(others, key=lambda x: abs(x.end - m.start()))
                    partner = best.entity
                # Debris a party threw up ("ran over road debris, which was projected onto EGO") is what touched
                # the AV, not the party that threw it.
                for x in others:
                    if x.kind == "obstacle" and _thrown(s, x):
                        partner = x.entity
                        break
                # A door that opened in the same sentence is what touched the AV.
                for door, owner in d.doors.items():
                    if any(x.entity == door and fre.search(r"\bavoid\w*\s+(?:\w+\s+){0,2}$",
                                                           s[max(0, x.start - 30):x.start]) for x in ments):
                        continue  # "swerved to avoid the open door and made contact": the door was missed
                    if partner is not None and partner != door and any(
                            x.entity == partner and y.entity == door and y.end <= x.start < m.start()
                            for x in others for y in ments):
                        # "with the door open, the passenger car started to proceed straight and made contact", "the
                        # Waymo AV passenger opened the driver side rear door and the passenger side of the van made
                        # contact": a party named after the door as the doer of the contact touched the AV itself
                        continue
                    if d.ents[door].first.sent == i or (owner == partner and fre.search(r"\bdoor", s[:m.start()])):
                        partner = door  # "opened a door into the AV" / "the edge of the cab's door made contact"
            candidates.append((i, m.start(), partner))
    if not candidates:
        return
    # "After this initial contact, the pick-up truck maneuvered to the front of EGO ... and made contact with the
    # front of EGO": what the story tells from there on came after the conflict, whose contact is the first.
    aftermath = next((i for i, s in enumerate(d.sents) if _AFTER_FIRST_CONTACT.match(s)), None)
    if aftermath is not None and any(c[0] < aftermath for c in candidates):
        candidates = [c for c in candidates if c[0] < aftermath]
    detailed = [c for c in candidates if c[0] not in d.summary]
    # "The impact caused the front of EGO to make contact with the rear bumper of the passenger car parked in front
    # of EGO": a contact the first one caused is no conflict of its own; what the AV was driven into was struck.
    knock_on = [c for c in detailed[1:] if _KNOCK_ON.match(d.sents[c[0]])]
    if knock_on:
        detailed = [c for c in detailed if c not in knock_on]
        d.struck.update(c[2] for c in knock_on if c[2] is not None)
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
    if fre.search(r"\b(?:again|a\s+(?:second|third|fourth)\s+time|once\s+more)\b", d.sents[chosen[0]][chosen[1]:], re.I):
        # "... and struck the AV again": the story's conflict ends at the first contact (sketch.md: strings end at
        # the contact), not at the repeat; also where the opening sentence alone tells the first ones ("On July 14,
        # 2021 ... when a passenger vehicle struck EGO from behind two times. The passenger vehicle then struck EGO a
        # third time, on the left side of EGO, as it passed on the left").
        chosen = next(c for c in candidates if c[2] == chosen[2] or c[2] is None)
    elif chosen[2] is not None and (first := next((c for c in detailed if c[2] == chosen[2]), chosen)) != chosen and \
            any(a.who == chosen[2] and first[0] < a.sent and (a.sent, a.pos) < chosen[:2] and
                (a.code in "abdefgjkmFT" and _THEN_BEFORE.search(d.sents[a.sent][max(0, a.pos - 12):a.pos]) or
                 _new_episode(d, a, first)) for a in d.acts):
        # The same party touched the AV, then moved again and touched it once more ("made contact with the front
        # driver side of EGO. The heavy truck then reversed ... it made contact with the driver side"): the
        # conflict is the first contact; the move told next ("then") begins what came after.
        chosen = first
    d.contact_sent, d.contact_pos, d.partner = chosen
    if d.partner is None:
        d.partner = _unnamed_thing(d)
    for i, m in met_by_others:
        _pushed_on(d, i, m)
    while d.partner is not None and d.ents[d.partner].merged_into is not None:
        d.partner = d.ents[d.partner].merged_into
    # "the AV made contact with the cat ... an SUV then made contact with the rear of the AV": an object the AV
    # touched earlier in the telling took part too, though the conflict is the last contact.
    for i, pos, who in detailed:
        if (i, pos) < (d.contact_sent, d.contact_pos) and who is not None and who != d.partner and \
                d.ents[who].kind == "obstacle" and not _named_in_later_clause(d, i, pos, who):
            d.struck.add(who)
    # "contact with a center divider ... and the traffic sign": every object joined to the struck one was struck.
    # (parked vehicles too: "made contact with a van and a sedan that were parked at the curb")
    if d.partner is not None and (d.ents[d.partner].kind == "obstacle" or d.ents[d.partner].parked):
        # A group word inside a name ("traffic" of "the traffic sign") is no object of its own.
        ms = [x for x in d.ments[d.contact_sent] if x.kind != "group"]
        idx = [k for k, x in enumerate(ms) if x.entity == d.partner]
        for k in range(idx[0] + 1 if idx else len(ms), len(ms)):
            between = d.sents[d.contact_sent][ms[k - 1].end:ms[k].start]
            if (ms[k].kind == "obstacle" or ms[k].entity >= 0 and d.ents[ms[k].entity].parked) and \
                    fre.fullmatch(r"[^,;]{0,30}\band\s*(?:(?:the|a|an)\s+)?", between):
                d.struck.add(ms[k].entity)
            else:
                break


# The thing the AV struck named by a noun no word list holds ("struck a house", "made contact with a set of tire
# spikes at the exit of the lot"): the noun phrase right after the AV's contact verb, up to a preposition or a clause
# word; a noun of a group ("a set of") gives way to the noun after it.
_STRUCK_NOUN = compile_gated(r"\s*(?:with\s+|into\s+|against\s+|onto\s+|upon\s+)?(?:a|an|the|some|several)\s+"
                             r"(?:(?:set|row|pair|piece|section|line|strip|series|number|couple)\s+of\s+(?:the\s+)?)?"
                             r"(?:[a-z][\w-]*\s+){0,3}?([a-z][\w-]*)(?=\s*(?:[,;.()]|$|\b(?:at|on|in|near|that|which|"
                             r"while|when|as|and|before|after|of|to|from|along|beside|next|by|with|causing|resulting|"
                             r"located|mounted|installed|placed|positioned)\b))", re.I)
# ... but not a part of the AV or of a vehicle, the ground it scraped, or a word that names no thing
_NOT_A_THING = compile_gated(r"(?:rear|front|back|side|sides|corner|bumper|fender|door|mirror|hood|panel|wheel|tire|"
                             r"tyre|undercarriage|underside|underbody|roof|trunk|sensor|portion|part|area|end|edge|"
                             r"top|bottom|left|right|way|time|speed|rate|manner|amount|moment|point|distance|impact|"
                             r"contact|collision|damage|lane|road|roadway|street|intersection|lot|driveway|EGO|EGOD|"
                             r"it|itself|them|something|nothing|anything|object|thing|one|"
                             # the ground's own shapes (sketch.md: scraped pavement, a driveway lip, is no obstacle)
                             r"apron|lip|gutter|grade|slope|incline|hump|bump|dip|crown|seam|joint|crack|asphalt|"
                             r"concrete|surface|ground|gravel|dirt|pavement|ramp|hill|transition|swale)$|"
                             r".*ly$", re.I)


def _unnamed_thing(d: Doc) -> int | None:
    """An obstacle ("other") for what the AV's own contact verb met, when no party or object word named it: the
    thing struck is in the story, so the report is no empty one (sketch.md: `npcs` is missing only when no party and
    no object is described). Pavement, a pothole, a speed bump stay contact with nothing."""
    i, pos = d.contact_sent, d.contact_pos
    if i is None:
        return None
    s = d.sents[i]
    verb = CONTACT.match(s, pos)
    if verb is None or _CONTACT_NOTHING.search(s):
        return None
    near = [x for x in d.ments[i] if x.end <= pos and pos - x.end <= 12]
    if who_for(pos, d.ments[i], None, s) != -1 and not (near and near[-1].kind in ("ego", "egod")):
        return None  # (the AV the doer: its clause's subject, or named right before the verb: "resulting in EGO
        # crashing")
    m = _STRUCK_NOUN.match(s, verb.end())
    if m is None or _NOT_A_THING.fullmatch(m.group(1)):
        return None
    idx = len(d.ents)
    ment = Mention(sent=i, start=m.start(1), end=m.end(1), kind="obstacle", head=m.group(1).lower(), category="other",
                   det="a", mods="", subject=False, entity=idx)
    d.ents.append(Entity(idx=idx, kind="obstacle", category="other", heads={ment.head}, mentions=[ment]))
    d.ments[i].append(ment)
    d.ments[i].sort(key=lambda x: x.start)
    return idx


_THEN_BEFORE = compile_gated(r"\bthen\s+$", re.I)
#: A party's moves that, told after its first contact with the AV, begin another episode (backing, speeding up).
_NEW_EPISODE = "bk"


def _new_episode(d: Doc, a: Act, first: tuple[int, int, int | None]) -> bool:
    """Does the party's move `a`, told after its first contact with the AV at `first`, begin another episode with or
    without "then" ("The heavy truck reversed and proceeded eastbound", "The passenger car accelerated and ... made
    contact with the rear left corner")? A backing or a speed-up does, unless the party was told doing it up to that
    first contact: then the later telling retells how the contact came about ("A passenger vehicle reversed into it.
    ... the passenger vehicle began to reverse out of the parking spot and made contact"). A run never begins one
    ("The bus was traveling less than 2mph when it hit the Zoox vehicle" retells the first contact)."""
    return a.code in _NEW_EPISODE and not any(x.who == a.who and x.code == a.code and (x.sent, x.pos) <= first[:2]
                                              for x in d.acts)
_AFTER_FIRST_CONTACT = compile_gated(r"\s*(?:after|following)\s+(?:the|this|that)\s+(?:initial|first)\s+"
                                     r"(?:contact|impact|collision)\b", re.I)
# A sentence that tells a contact as the effect of the one before ("The impact caused the front of EGO to make
# contact with", "As a result, EGO made contact with", "In a secondary impact, ...").
_KNOCK_ON = compile_gated(r"\s*(?:as\s+a\s+result(?:\s+of\s+(?:the|this|that)\s+(?:initial\s+|first\s+)?(?:impact|collision|contact))?\b|"
                          r"(?:the\s+)?(?:force\s+of\s+the\s+)?(?:(?:the|this|that)\s+)?(?:initial\s+|first\s+)?"
                          r"(?:impact|collision|contact)\s+(?:then\s+|also\s+)?"
                          r"(?:caused|pushed|propelled|forced|sent|knocked|shoved|moved)\b|"
                          r"(?:in\s+)?(?:a|the)\s+secondary\s+(?:impact|collision|contact)\b)", re.I)
_CLAUSE_OPENER = compile_gated(r"[,;]|\b(?:when|while|as|after|before|because|until)\b", re.I)


def _named_in_later_clause(d: Doc, sent: int, pos: int, who: int) -> bool:
    """Is the object taken for the contact phrase at (sent, pos) named only in a clause after it ("Contact occurred
    when EGO was stopped at a stop sign"): where the AV was, not what it touched?"""
    s = d.sents[sent]
    verb = CONTACT.match(s, pos)
    end = verb.end() if verb else pos
    after = [x for x in d.ments[sent] if x.entity == who and x.start >= end]
    return bool(after) and not any(x.entity == who and x.end <= pos for x in d.ments[sent]) and \
        bool(_CLAUSE_OPENER.search(s[end:after[0].start]))


# Words that tell what came next; `_LATER` is the same list less "and" (which in a clause of the same moment joins
# what happened then).
_LATER_WORDS = (r"\bthen\b|\bbefore\b|\bafter\b|\bcontinued\b|\bleft\s+the\s+scene|\bcausing\b|\bdamaging\b|"
                r"\bresulting\b")
_AFTERWARDS = compile_gated(r"\band\b|" + _LATER_WORDS, re.I)
# A verb in the simple past after a comma, the next of a list of what was done ("made contact with the front passenger
# side of the stationary EGO, backed the bicycle up slightly, dropped the bicycle, then fell").
_NEXT_IN_LIST = compile_gated(r",\s+(?:\w+ly\s+)?[a-z]+ed\s+(?:the|a|an|its|his|her|their|up|out|away|off)\b", re.I)


# Only a braking is read there: the AV's reaction just before the contact, told after it.
_BEFORE_IMPACT = compile_gated(r"\b(?:brak(?:ed|ing)|slow(?:ed|ing)|decelerat(?:ed|ing)|applied\s+(?:the\s+)?brakes)\b"
                               r"[^.;]{0,30}?\b(?:before|prior\s+to)\s+(?:the\s+)?(?:impact|contact|collision)\b", re.I)
_SAME_TIME = compile_gated(r"\b(?:as|while|just\s+as)\b", re.I)
#: "after" opening a clause of its own (a subject, or a participle: "after EGO had begun", "after the light turned
#: green", "after having stopped"), not the contact's own aftermath ("after the impact").
_TOLD_BEFORE = compile_gated(r"\bafter\s+(?!(?:the|this|that|its|an?)\s+(?:\w+\s+)?(?:impact|contact|collision|"
                             r"incident|crash|accident)\b)(?:EGO|it|the|a|an|having|\w+ing)\b", re.I)
_LATER = compile_gated(_LATER_WORDS, re.I)


def before_contact(d: Doc, sent: int, pos: int) -> bool:
    """Is text position (sent, pos) part of the story up to the contact? In the contact sentence, words after the
    contact verb still are, unless a new clause ("and proceeded left", "then") tells what came next."""
    if d.contact_sent is None:
        return True
    if sent != d.contact_sent:
        # "EGO had braked before the impact.": a later sentence that places its telling before the contact
        return sent < d.contact_sent or bool(_BEFORE_IMPACT.search(d.sents[sent]))
    if pos <= d.contact_pos:
        return True
    listed = _NEXT_IN_LIST.search(d.sents[sent], d.contact_pos, pos + 40)
    if listed and listed.start() < pos:
        return False
    after = d.sents[sent][d.contact_pos:pos]
    # "the passenger vehicle behind EGO struck the rear of EGO after the traffic light turned green and EGO had begun
    # to accelerate": a clause of what came before the contact, told after it (as "After the traffic light turned
    # green and EGO had begun to accelerate, the passenger vehicle ... struck" tells it first); its "and" joins what
    # happened before, up to the sentence's end or a word of what came next.
    earlier = _TOLD_BEFORE.search(after)
    if earlier and not _AFTERWARDS.search(after[:earlier.start()]):
        return not _LATER.search(after[earlier.end():])
    # "walked into EGO's front bumper as the light turned green and EGO began to move": a clause of the same moment
    # ("as", "while") runs to the sentence's end; its "and" joins what happened then, not what came next.
    same_time = _SAME_TIME.search(after)
    if same_time and not _AFTERWARDS.search(after[:same_time.start()]):
        return not _LATER.search(after[same_time.end():])
    return not _AFTERWARDS.search(after)


def acted_for(d: Doc, e: Entity, *, around_only: bool = False) -> bool:
    """Did the AV act for this object ("around a double-parked vehicle", "stopped for debris")?"""
    rx = _AROUND_ONLY if around_only else _AROUND
    for m in e.mentions:
        s = d.sents[m.sent]
        if rx.search(s[max(0, m.start - 60):m.start]) and m.sent not in d.summary and \
                who_for(m.start - 1, [x for x in d.ments[m.sent] if x.start < m.start], -1, s) == -1:
            return True  # the AV (not another party: "failed to stop for the stop sign") acted for it
    return False


# The AV driven by the contact into something ahead of it: "pushing EGO into the passenger car ahead", "EGO was
# pushed forward into a sedan", "causing EGO to strike the vehicle in front of it" (the words up to the thing met).
_PUSHED_INTO = compile_gated(r"(?:\b(?:push|propel|shov|forc|knock|send|sent|thr[eo]w)\w*\s+(?:EGO\s+|it\s+)?(?:forward\s+|"
                             r"ahead\s+)?into|\bcaus(?:ed|ing)\s+(?:EGO|it)\s+to\s+(?:\w+\s+)?(?:strike|hit|collide\s+with|"
                             r"contact|make\s+contact\s+with|rear-end|bump|roll\s+into|move\s+(?:forward\s+)?into))"
                             r"[^,;.]{0,40}$", re.I)


def _in_chain(d: Doc, e: Entity, first: Mention) -> bool:
    """A party named after the AV's contact that itself makes contact in the next sentences ("A second passenger
    car then made contact with the SUV"), or that the contact drove the AV into ("pushing EGO into the passenger car
    ahead"): a chain collision's party takes part in the event (sketch.md)."""
    if e.kind == "party" and d.contact_sent is not None and 0 <= first.sent - d.contact_sent <= 1 and \
            first.sent not in d.summary and (first.sent > d.contact_sent or first.start > d.contact_pos) and \
            _PUSHED_INTO.search(d.sents[first.sent], max(0, first.start - 90), first.start):
        return True
    if e.kind == "party" and d.contact_sent is not None and first.sent == d.contact_sent and \
            first.start > d.contact_pos and first.sent not in d.summary and \
            fre.search(r"\band\s+(?:also\s+)?(?:with|into)\b", d.sents[first.sent][d.contact_pos:first.start], re.I):
        return True  # "made contact with EGO's rear and with the side of another pickup truck": the same contact
    if e.kind != "party" or d.contact_sent is None or first.sent in d.summary or \
            not 0 < first.sent - d.contact_sent <= 2:
        return False
    # In the sentence that names it, or in the next ones that name it again ("..., which was occupied by a
    # scooterist. The front tire of the scooter made contact with the crate").
    for x in e.mentions:
        if x.sent < first.sent or x.sent - d.contact_sent > 2 or x.sent in d.summary:
            continue
        s = d.sents[x.sent]
        for m in CONTACT.finditer(s):
            if m.start() > x.end and who_for(m.start(), d.ments[x.sent], None) == e.idx:
                return True
        if _met_by_party(d, x):
            return True  # "A second passenger car then made contact with the SUV and the first passenger car"
    return False


# (any verb of the AV's run: "was en route ... behind a box truck", "was heading east behind")
_TRAVELLED_BEHIND = compile_gated(r"\b(?:travel(?:l)?(?:ed|ing)|driving|drove|proceed(?:ed|ing)|moving|cruising|"
                                  r"en\s+route|head(?:ed|ing))\b"
                                  r"[^,;.]{0,60}?\bbehind\s+(?:a|an|another)\s+(?:[\w-]+\s+){0,2}$", re.I)


def named_behind_by_av(d: Doc, m: Mention, before: re.Pattern[str], reach: int) -> bool:
    """Is mention `m` the object of something the AV did behind it ("EGO was traveling ... behind a box truck",
    "EGO came to a stop behind its lead vehicle"): `before` matches the `reach` characters before the mention,
    and the AV is the doer there?"""
    s = d.sents[m.sent]
    return bool(before.search(s[max(0, m.start - reach):m.start])) and \
        who_for(m.start - 1, [x for x in d.ments[m.sent] if x.start < m.start], None, s) == -1


def body_side(word: str) -> str:
    """A side of a vehicle's body as the AV's left or right ("driver" is the left in right-hand traffic)."""
    word = word.lower()
    return {"driver": "left", "passenger": "right"}.get(word, word)


def _only_travelled_behind(d: Doc, e: Entity) -> bool:
    """Is the party named only as what the AV travelled behind ("EGO was traveling ... behind a box truck in the
    number 3 lane"), doing nothing and named no more? (A vehicle the AV stopped or slowed for takes part.)"""
    told = [m for m in e.mentions if m.sent not in d.summary]
    return bool(told) and all(named_behind_by_av(d, m, _TRAVELLED_BEHIND, 100) for m in told)


# "made contact with a passenger car parked ...", "made contact with the driver side of an SUV that was parked",
# "made contact with the center concrete median curb": the words between a contact verb and the thing it met
# (the second of two things met, too: "made contact with the SUV and the first passenger car")
_CONTACT_OBJECT = compile_gated(r"^\s*(?:with\s+|into\s+|against\s+)?(?:(?:the|an?)\s+(?:[\w-]+\s+){1,3}and\s+)?"
                                r"(?:the\s+|an?\s+)?(?:(?:front|rear|back|left|right|"
                                r"driver|passenger|side|corner|bumper|door|mirror)(?:'s)?\s+){0,4}(?:of\s+)?(?:the\s+|an?\s+)?$",
                                re.I)


def _met_by_party(d: Doc, m: Mention) -> bool:
    """Is mention `m` what another party (not the AV) made contact with: a contact verb of that party's clause, then
    the thing met ("made contact with the driver side of an SUV that was parked")?"""
    s = d.sents[m.sent]
    for c in CONTACT.finditer(s, max(0, m.start - 60), m.start):
        if not _CONTACT_OBJECT.match(s[c.end():m.start]) or NEGATION.search(s[max(0, c.start() - 20):c.start()]):
            continue
        who = who_for(c.start(), [x for x in d.ments[m.sent] if x.start < c.start()], None, s)
        if who is not None and who >= 0 and who != m.entity and d.ents[who].kind == "party" and \
                not d.ents[who].parked:
            return True
    return False


def struck_by_party(d: Doc, e: Entity) -> bool:
    """Did another party (not the AV) strike this object or parked vehicle in the telling ("A pickup truck ... made
    contact with a passenger car parked facing south at the curb", "the driver side made contact with the center
    concrete median curb")? What a party of the event ran into takes part in it (the studyable gold counts it)."""
    return any(m.sent not in d.summary and _met_by_party(d, m) for m in e.mentions)


# The AV's reason told after the contact ("EGO chose to maneuver at the curb due to perceived risk from a car in an
# adjacent lane"): the party it reacted to took part before the contact, wherever the telling names it.
_REASON_BEFORE = compile_gated(r"\b(?:due\s+to|because\s+of|in\s+response\s+to|risk\s+(?:from|of|posed\s+by)|to\s+avoid|"
                               r"in\s+order\s+to\s+avoid)\s+(?:[\w-]+\s+){0,2}?(?:a|an|the|another)\s+(?:[\w-]+\s+){0,2}$", re.I)


def _reason_told_after(d: Doc, m: Mention) -> bool:
    """Is mention `m`, told after the contact, the party the AV acted for (its reason, told after the event)?"""
    s = d.sents[m.sent]
    return m.kind == "party" and bool(_REASON_BEFORE.search(s, max(0, m.start - 70), m.start)) and \
        who_for(m.start - 1, [x for x in d.ments[m.sent] if x.start < m.start], None, s) == -1


def _moved(d: Doc, who: int) -> bool:
    """Is any move of party `who` told (O, P: out of a parking spot)?"""
    return any(a.who == who and a.code in "abcdefgijkmFTOP" for a in d.acts)


def counted(d: Doc) -> tuple[list[Entity], list[Entity]]:
    parties, obstacles = [], []
    for e in d.ents:
        if e.merged_into is not None:
            continue
        first_detail = [m for m in e.mentions if m.sent not in d.summary]
        first = first_detail[0] if first_detail else e.first
        is_partner = e.idx == d.partner
        if not is_partner and e.idx not in d.struck and not before_contact(d, first.sent, first.start) and \
                not _in_chain(d, e, first) and not _reason_told_after(d, first):
            continue
        moved = _moved(d, e.idx)
        if e.kind == "party" and not moved and not is_partner and e.category in ("car", "van", "truck", "bus") and \
                acted_for(d, e, around_only=True) and not fre.search(
                    r"\b(?:oncoming|approaching|moving|traveling|passing)\b", " ".join(m.mods for m in e.mentions)) and \
                not (any(a.who == e.idx and a.code == "S" for a in d.acts) and not fre.search(
                    r"\bpark", " ".join(m.mods + " " + context(d, e) for m in e.mentions[:1]), re.I)):
            # A vehicle the AV went around, that did nothing itself, stood there: parked, unless the text says it
            # was stopped (in traffic, in the lane) and never parked: that is a party standing still (sketch.md).
            e.parked = True
        if e.kind == "party" and not is_partner and e.idx not in d.struck and not e.parked and \
                not PARKED_WORDS.search(" ".join(m.mods for m in e.mentions)) and \
                not any(a.who == e.idx for a in d.acts) and _only_travelled_behind(d, e):
            continue  # "EGO was traveling ... behind a box truck": where the AV was, named in passing (sketch.md)
        if not is_partner and e.idx not in d.struck and first_detail and not moved and all(
                _EARLIER_AGENT.search(d.sents[m.sent], max(0, m.start - 90), m.start) for m in first_detail):
            continue  # "a small dog that had apparently been previously struck by a preceding vehicle": earlier
        if not is_partner and e.idx not in d.struck and all(fre.search(r"\bof\s+(?:a|an|the)?\s*(?:[\w-]+\s+){0,2}$",
                                            d.sents[m.sent][max(0, m.start - 30):m.start + len(m.mods) + 1])
                                  for m in e.mentions) and not moved:
            continue  # "a skateboard that escaped control of a nearby pedestrian": named only as an owner
        owns_door = e.idx in d.doors.values()  # a vehicle whose opened door is an obstacle
        if e.idx in d.doors:
            if is_partner or e.idx in d.struck or not _moved(d, d.doors[e.idx]):
                obstacles.append(e)
            # (else the door of a vehicle that moved and did the touching, "as they did so with the door open, the
            # passenger car started to proceed straight and made contact": the vehicle takes part, not its door)
        elif e.kind == "party" and e.parked and not moved:
            # A parked vehicle the telling names before the contact stands in the scene: an obstacle (sketch.md: "A
            # parked, unattended vehicle is an obstacle `parked_vehicle`"), whether the AV went around it, a party
            # struck it or it only hemmed a manoeuvre in ("unable to proceed past the garbage truck and an SUV parked
            # parallel to the curb"); one the summary alone names is not told of. (Being named before the contact is
            # checked above.) A vehicle whose opened door is the obstacle stands for it only through its door
            # ("a passenger exiting a parked car opened the rear door": sketch.md places the door where it stands).
            if is_partner or e.idx in d.struck or acted_for(d, e) or struck_by_party(d, e) or \
                    (first_detail and not owns_door):
                obstacles.append(e)
        elif e.kind == "party":
            if owns_door and not moved:
                continue  # the door's vehicle stood still: only its door takes part
            if not first_detail and not is_partner:
                continue  # named in the summary only
            parties.append(e)
        elif e.kind == "obstacle":
            if "sign" in e.heads and not (is_partner or e.idx in d.struck):
                continue  # a stop sign the AV obeyed is traffic control, not an object in the scene
            if is_partner or e.idx in d.struck or acted_for(d, e) or struck_by_party(d, e):
                obstacles.append(e)
    # A numbered group ("two unoccupied vehicles parked") is that many parties, each read alike; in a summary
    # ("a collision involving two SUVs") it only announces parties the telling names one by one, unless the telling
    # names none ("when it was struck on its right front fender by two individuals ... The two individuals fled the
    # scene": the opening sentence is the only one to tell who took part).
    told = [x for x in parties + obstacles if x.first.sent not in d.summary]

    def times(e: Entity) -> int:
        return e.count if e.first.sent not in d.summary or not told else 1
    return [e for e in parties for _ in range(times(e))], [e for e in obstacles for _ in range(times(e))]


def add_doors(d: Doc) -> None:
    """"opened a rear door into the side of the AV": a door obstacle, owned by the latest vehicle named before."""
    for i, s in enumerate(d.sents):
        for m in _DOOR.finditer(s):
            door_at = m.start() + m.group(0).lower().index("door")
            if _AV_DOOR_BEFORE.search(s, max(0, m.start() - 40), m.start()) or \
                    _AV_DOOR_NAMED.search(s, max(0, door_at - 60), door_at) or _AV_DOOR_AFTER.match(s, door_at + 4):
                break  # the AV's own door (and "the door" after it in the sentence): no obstacle
            owners = [x for x in d.ments[i] if x.kind == "party" and x.start > door_at and x.entity >= 0 and
                      _OF_OWNER.match(s[door_at + 4:x.start])][:1] or \
                [x for x in d.ments[i] if x.kind == "party" and x.start < m.start() and x.entity >= 0]
            if not owners:
                owners = [x for j in range(max(0, i - 2), i) for x in d.ments[j] if x.kind == "party" and x.entity >= 0]
            idx = len(d.ents)
            # "a car door opened into its path": a vehicle's door whose vehicle the text does not name apart (the
            # door stands for it)
            if not owners and not fre.search(r"\b(?:car|vehicle|truck|van|suv|taxi|cab)\s+doors?\b",
                                             s[max(0, door_at - 12):door_at + 5], re.I):
                continue
            owner = owners[-1].entity if owners else idx
            ment = Mention(sent=i, start=m.start(), end=m.end(), kind="obstacle", head="door", category="other",
                           det="a", mods="", subject=False, entity=idx)
            ent = Entity(idx=idx, kind="obstacle", category="other", heads={"door"}, mentions=[ment])
            d.ents.append(ent)
            d.ments[i].append(ment)
            d.ments[i].sort(key=lambda x: x.start)
            d.doors[idx] = owner
            break


def _thrown(s: str, x: Mention) -> bool:
    """Is the object named by mention `x` of sentence `s` told as thrown ("road debris, which was projected onto
    EGO", "kicked up a rock", "projected road debris")?"""
    return bool(_THROWN_AFTER.match(s[x.end:x.end + 50]) or _THROWN_BEFORE.search(s[max(0, x.start - 40):x.start]) or
                _THROWN_MOD.match(x.mods))


# The AV (or its part) struck by a thing: "the front windshield was struck by an unknown object".
_STRUCK_BY_THING = compile_gated(r"\b(?:was|were)\s+(?:\w+ly\s+)?(?:struck|hit|impacted|contacted|damaged|cracked|"
                                 r"chipped)\s+by\s+(?:a|an|the|some)\s*$", re.I)


def came_at_av(d: Doc, e: Entity) -> bool:
    """Did object `e` come at the AV rather than lie in its way: thrown onto it ("road debris, which was projected onto
    the test vehicle") or striking it ("the front windshield was struck by an unknown object")?"""
    for m in e.mentions:
        s = d.sents[m.sent]
        if _thrown(s, m) or m.sent == d.contact_sent and _STRUCK_BY_THING.search(s, max(0, m.start - 40), m.start):
            return True
    return False


def thrower(d: Doc, e: Entity) -> int | None:
    """The party that threw object `e` at the AV: the last party named before the object in a sentence that tells
    it thrown ("a nearby semi-trailer truck ... generated a draft that projected road debris onto EGO")."""
    for m in e.mentions:
        if _thrown(d.sents[m.sent], m):
            before = [x.entity for x in d.ments[m.sent] if x.kind == "party" and x.entity >= 0 and x.end <= m.start]
            if before:
                return before[-1]
    return None


def attach_towed(d: Doc) -> None:
    """"a pickup truck that was dragging a basketball hoop": what a party drags or carries moves with it, so a
    contact with it is a contact with the party."""
    for i, s in enumerate(d.sents):
        for m in d.ments[i]:
            if m.kind != "obstacle" or m.entity < 0:
                continue
            if fre.search(r"\b(?:dragging|towing|pulling|carrying|hauling|dragged|towed)\s+(?:a|an|the)?\s*"
                         r"(?:[\w-]+\s+){0,3}$",
                         s[:m.start + len(m.mods) + 1]):
                owners = [x for x in d.ments[i] if x.kind == "party" and x.start < m.start and x.entity >= 0]
                if owners:
                    d.ents[m.entity].merged_into = owners[-1].entity


_FURNITURE = frozenset({"barrier", "pole"})


def ends_phrase(d: Doc, x: Mention) -> bool:
    """Does mention `x` end what the text says of the party named before it? The next party or object does; road
    furniture ("stepped off the curb from the right", "standing on the median") is a landmark of that phrase."""
    return x.kind == "party" or (x.kind == "obstacle" and not (
        0 <= x.entity < len(d.ents) and d.ents[x.entity].category in _FURNITURE))


def context(d: Doc, e: Entity) -> str:
    """Text around an entity's mentions before the contact: what the narrative says of its place."""
    parts = []
    for m in e.mentions:
        if not before_contact(d, m.sent, m.start) and m.sent != d.contact_sent:
            continue
        s = d.sents[m.sent]
        nxt = [x.start for x in d.ments[m.sent] if x.start > m.end and ends_phrase(d, x)]
        end = min(nxt + [m.end + 110]) if nxt else m.end + 110
        parts.append(f"{m.mods} {m.head} {s[m.end:end]}")
    return " | ".join(parts)


TURN_WORDS = compile_gated(r"\b(?:left|right)[- ](?:hand\s+)?turn(?!ed)|\bturn(?:ed|ing|s)?\s+(?:left|right)|"
                         r"\bchang(?:ed|ing|es|e)\s+lanes?\s+(?:to\s+the\s+)?(?:left|right)|"
                         r"\b(?:left|right)\s+lane"
                         r"\s+changes?\b|\blane\s+change\s+to\s+the\s+(?:left|right)|\bright\s+of\s+way|\bleft\s+the\s+"
                         r"scene", re.I)


def side_named(ctx: str) -> str | None:
    """The first side named in `ctx` ("in the rightmost lane", "to the left of"), turns and "right of way" aside."""
    ctx = TURN_WORDS.sub(" ", ctx)
    left = fre.search(r"\bleft(?:most)?\b", ctx, re.I)
    right = fre.search(r"\bright(?:most)?\b", ctx, re.I)
    if left and right:
        return "left" if left.start() < right.start() else "right"
    return "left" if left else "right" if right else None


def heading(d: Doc, who: int) -> int | None:
    """The compass heading (degrees) the text gives the AV (-1) or entity `who`, read once per story."""
    return d.once(f"heading:{who}", lambda: _heading(d, who))


def _heading(d: Doc, who: int) -> int | None:
    for i, s in enumerate(d.sents):
        for m in d.ments[i]:
            ent = -1 if m.kind in ("ego", "egod") else m.entity
            if ent == who:
                said = fre.search(r"\b(north|south|east|west)bound\b", m.mods, re.I)
                if said:  # "a northbound sedan"
                    return heading_of(said.group(0))
                # Read up to the next party named in the sentence: its heading is its own.
                nxt = [x.start for x in d.ments[i] if x.start > m.end and x.kind == "party" and x.entity != who]
                # (up to the next party named; 200 characters hold an aside: "EGO, in autonomous mode, had stopped
                # at a stop sign on Cabrillo Street and, when the intersection was clear, began to proceed westbound")
                window = s[m.end:min(nxt + [m.end + 200])]
                approach = fre.search(r"\bfrom\s+((?:north|south|east|west)+)bound\b", window, re.I)
                if who == -1:
                    # "after completing a right turn ... onto westbound Haight": the heading it turned to
                    told = s[m.end:min(nxt + [m.end + 200])]
                    done = PRIOR_TURN.search(told)
                    to = done and fre.match(r"\s*(?:the\s+)?((?:north|south|east|west)+bound)\b", told[done.end():],
                                            re.I)
                    if to:
                        return heading_of(to.group(1))
                if approach and who == -1:
                    # The AV "turned left from northbound X onto westbound Y": the frame of R1-R7 is taken when
                    # the interaction begins, on its approach (an oncoming party is R2 there).
                    return heading_of(approach.group(1) + "bound")
                # "made a right turn onto southbound Hyde Street": the heading it turned to, not the one it came on.
                h = heading_of(_DESTINATION_HEADING.sub(" ", window))
                if h is not None:
                    return h
    return None


_DESTINATION_HEADING = compile_gated(r"\b(?:onto|into|toward|towards)\s+(?:the\s+)?(?:north|south|east|west)+bound\b",
                                     re.I)


# "the rear driver's side of EGO": up to six words before "of/on/to EGO". The quantifiers inside the group are
# possessive: a word ([\w'-], so "driver's" is one) is always followed by whitespace and whitespace by a word or
# "of", so giving back characters can never lead to a match - possessive matching finds the same matches without
# the backtracking that made this pattern cost more than any other in the extractor.
# "the rear of the stationary EGO", "the front driver side corner of the parked EGO": the AV named with its state.
_PART_OF_EGO = compile_gated(r"((?:[\w'-]++\s++){1,6})(?:of|on|to)\s+(?:the\s+(?:still\s+)?(?:stationary|stopped|parked|"
                             r"idle|idling|standing|waiting|unoccupied|empty)\s+)?EGO\b")
_PART_OWNER = compile_gated(r"^(?:[\w-]+\s+){0,2}?(?:front|rear|back|side|corner|bumper|door|fender|mirror|end|trailer|"
                            r"wheel|tire|hood|bed|load|cargo)\s+of\s+(?:the|a|an|its)\s+$", re.I)
_PASSIVE_CONTACT = compile_gated(r"\b(?:was|were|is|are)\s+(?:\w+ly\s+)?(?:struck|hit|contacted|clipped|bumped|rear-ended|"
                                 r"impacted|sideswiped|side-swiped)"
                                 r"\b([^.]{0,80}?)(?:\bby\b|$)")
# The parts of a car's body that lie at one end of it, in the words owners, police and operators use: a rear
# part ("the trunk", "its tailgate", "the taillight", "the license plate") is met from behind, a front one ("the
# hood", "the grille", "the headlight") from ahead. (A hatchback is a car, not a part: "hatch" alone is.)
REAR_PARTS = r"rear|back|tail\w*|trunk|boot|lift\s?gate|hatch|deck\s?lid|license\s+plate|(?:trailer\s+)?hitch"
FRONT_PARTS = r"front|hood|bonnet|grill\w*|nose|head\s?(?:light|lamp)s?|windshield|windscreen"
# Police shorthand for a corner: "LF" (left front), "RR" (right rear) ...
_CORNER_ABBREV = {"LF": ("front", "left"), "RF": ("front", "right"), "LR": ("rear", "left"), "RR": ("rear", "right")}
# "in front of EGO, impacting its front passenger side sensors": a participle of contact after the AV's name
_ITS_PART = compile_gated(r"\bEGO\b[^.;]{0,40},\s+(?:impacting|striking|hitting|contacting|damaging|clipping|scraping)\s+"
                          r"its\s+((?:[\w-]+\s+){1,5})", re.I)
_CONTACT_ITS = compile_gated(r"\b(?:made\s+contact\s+with|contacted|struck|hit|impacted|rear-ended|collided\s+with|"
                             r"sideswiped)\s+its\s+((?:[\w-]+\s+){0,3}?(?:bumper|side|corner|door|fender|"
                             rf"panel|end|sensor|mirror|wheel|tire|{REAR_PARTS}|{FRONT_PARTS})\b)", re.I)
# "struck EGO on its passenger side", "hit EGO in the right rear door": the part named after the AV's name.
_EGO_ON_PART = compile_gated(r"\bEGO\s+(?:broadside\s+)?(?:on|in|at|along)\s+(?:its|the)\s+((?:[\w-]+\s+){0,3}?"
                             rf"(?:bumper|side|corner|door|fender|panel|quarter|sensor|mirror|wheel|tire|{REAR_PARTS}|"
                             rf"{FRONT_PARTS})\b)", re.I)
_PART_END = re.compile(r"\b(?:collided|made|struck|hit|contacted|impacted|came|was|were|had|sideswiped|scraped|"
                       r"clipped|rubbed|touched|bumped|with|against|into)\b", re.I)
_PART_WORD = compile_gated(rf"\b(?:{REAR_PARTS}|{FRONT_PARTS}|driver|passenger|left|right|(?-i:LF|RF|LR|RR))\b", re.I)
# "EGO's left rear." names the part at the sentence end too
# ("EGO's driver's side rear corner": a possessive inside the part's words)
# (and never over the AV named again: "EGO's lane and made contact with EGO's rear quarter panel")
_EGOS_PART = compile_gated(r"\bEGO's\s+((?:(?!EGO\b)[\w'-]+(?:\s+|(?=[.,;:!?)])|$)){1,6})")


def ego_contact_part(d: Doc) -> tuple[str | None, str | None]:
    """Where the AV was touched, (front/rear, left/right), from the contact sentence's "the rear driver side of
    EGO" / "EGO's front bumper" (US vehicles: the driver side is the left). Read once per contact."""
    return d.once(f"ego_contact_part:{d.contact_sent}", lambda: _ego_contact_part(d))


def _ego_parts(s: str) -> list[str]:
    """The AV's parts a sentence names: "the rear driver side of EGO", "EGO's front bumper", "EGO was struck on the
    passenger side", "... EGO, impacting its front fender"."""
    # (the words after the contact's verb: "the scooter's front tire struck the rear bumper of EGO" names the rear)
    parts = [_PART_END.split(m.group(1))[-1] for m in _PART_OF_EGO.finditer(s)]
    passive = _PASSIVE_CONTACT.search(s)
    if passive:
        parts.append(passive.group(1))  # "EGO was struck on a sensor attached to the rear ... by a minivan"
    # "EGO's front end collided with the driver side of the pickup": the AV's part ends where the verb begins
    parts += [_PART_END.split(m.group(1), 1)[0] for m in _EGOS_PART.finditer(s)]
    parts += [m.group(1) for m in _ITS_PART.finditer(s)]
    parts += [m.group(1) for m in _EGO_ON_PART.finditer(s)]
    # "... when another vehicle made contact with its rear bumper": a party that touched "its" part touched the
    # AV's (a vehicle does not strike its own bumper); not where the AV itself is the doer just before.
    parts += [m.group(1) for m in _CONTACT_ITS.finditer(s) if "EGO" not in s[max(0, m.start() - 40):m.start()]]
    return parts


def _ego_contact_part(d: Doc) -> tuple[str | None, str | None]:
    if d.contact_sent is None:
        return None, None
    parts = _ego_parts(d.sents[d.contact_sent])
    if not _PART_WORD.search(" ".join(parts)):
        # The contact sentence names no part of the AV ("it hit EGO, which was stopped"): the part is the one
        # another sentence of the contact names ("EGO was struck on the passenger side fender by a bus").
        parts = next((p for k, s in enumerate(d.sents) if k != d.contact_sent and CONTACT.search(s)
                      and _PART_WORD.search(" ".join(p := _ego_parts(s)))), [])
    joined = " ".join(parts)
    abbrev = fre.search(r"\b(LF|RF|LR|RR)\b", joined)
    if abbrev and not fre.search(r"\b(?:front|rear|back|left|right|driver|passenger)\b", joined, re.I):
        return _CORNER_ABBREV[abbrev.group(1)]  # "EGO's RR bumper": its right rear corner
    text = joined.lower()
    rear = fre.search(rf"\b(?:{REAR_PARTS})\b", text)
    front = fre.search(rf"\b(?:{FRONT_PARTS})\b", text)
    # "the driver side front and rear passenger door": both halves touched, neither end decides.
    fore = None if (rear and front) else "rear" if rear else "front" if front else None
    side = "left" if fre.search(r"\bdriver|\bleft\b", text) else "right" if fre.search(r"\bpassenger|\bright\b",
                                                                                     text) else None
    return fore, side
