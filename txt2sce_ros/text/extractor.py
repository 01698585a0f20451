"""The offline extractor: one narrative -> one `Sketch`, by rules only (no network, no model, deterministic).

Pipeline: normalise (the AV becomes `EGO`) -> sentences -> mentions -> entities (coreference) -> manoeuvres with
their doers -> the AV's contact -> who counts -> positions -> action strings -> collision type -> `missing`.
Each step is a small function over plain records so a rule can be read, tested and changed on its own:
`mentions` (names, coreference), `actions` (manoeuvre phrases), `story` (contact, who counts), `positions`
(R1-R7, lanes), `sequences` (action strings, collision type), `scene` (road, signal, environment); the word
lists are in `lexicon`.
"""

from __future__ import annotations

import re

from ..errors import InputError
from ..sketch import Collision, EgoInfo, Obstacle, Party, Sketch
from . import fastre as fre
from .fastre import compile_gated
from .actions import Act, find_acts
from .lexicon import CONTACT
from .mentions import Entity, find_mentions, mark_parked, normalise, resolve, sentences
from .positions import MOVING_THINGS, obstacle_position, party_position
from .relations import AV_AT_CURB, OUT_OF_ROADSIDE, av_lane_rank, backed_out_behind, place, thing_origin_lane
from .spans import OffsetMap
from .scene import environment, is_junction, road, scene_spans, signal_state
from .sequences import (backed_into_object, collision_type, ego_sequence, moved_off_into_object, opens_under_way,
                        prepend_modifier_acts, queued_behind, sequence, standing_party, stood_at_contact, wide_turn)
from .story import (BOILERPLATE, body_side, came_at_av, context, Doc, add_doors, attach_towed, before_contact,
                    counted, ego_contact_part, find_contact, heading, summary_sentences, thrower)


#: The longest narrative read (characters). Real section-5 narratives run to ~3,500 characters; the extractor's
#: time grows linearly up to this bound (`txt2sce bench extract` prints the per-character cost), and a longer text
#: is refused rather than left to run: it is no single accident narrative.
MAX_NARRATIVE_CHARS = 100_000


# The AV's own turn told in its clause (which a clause word ends, but not "while yielding", its own participle; a
# period inside it is an abbreviation's: "on Sixth St. with a green light").
_AV_TURN_TOLD = compile_gated(r"\bEGO\b(?:(?!\b(?:when|while(?!\s+\w+ing\b)|as|then|whereupon)\b)(?:[^.;]|\.(?=\s+[a-z0-9])))"
                              r"{0,160}?"
                              r"(?:\bturn(?:ed|ing)\b|"
                              r"\b(?:make|making|complete|completing|execute|executing)\s+(?:a|an|its|the)\s+(?:\w+\s+)?"
                              r"(?:left|right)\s+turn)", re.I)
_INTO_EGO_LANE = compile_gated(r"\binto\s+EGO's\s+(?:travel\s+)?lane\b", re.I)


# A lane change told from one outer lane to the other ("made a continuous right lane change from the far left lane,
# through the middle lane, and entered the far right lane", "began to change lanes from the rightmost lane to the
# leftmost lane"), on a road of three lanes (a middle or centre lane, or "three lanes", named): two changes.
_OUTER_TO_OUTER = compile_gated(r"\bfrom\s+the\s+(?:far\s+)?(left|right)(?:most)?\s+(?:[\w-]+\s+)?lane\b[^.;]{0,80}?\b(?:in)?to\s+"
                                r"the\s+(?:far\s+)?(left|right)(?:most)?\s+(?:[\w-]+\s+)?lane\b|"
                                r"\bfrom\s+the\s+(?:far\s+)?(left|right)(?:most)?\s+(?:[\w-]+\s+)?lane\b[^.;]{0,80}?\bentered\s+"
                                r"the\s+(?:far\s+)?(left|right)(?:most)?\s+(?:[\w-]+\s+)?lane\b", re.I)
_THREE_LANES = compile_gated(r"\b(?:three|3)\s+(?:[\w-]+\s+)?lanes\b|\b(?:middle|center|centre)\s+lane\b", re.I)


def _across_three_lanes(d: Doc, pacts: list[Act], acts: str) -> str:
    """A party's single lane change told from one outer lane of a three-lane road to the other is two changes
    (studyable gold: 2 of 2 such parties, `agg` and `ff`)."""
    lateral = [c for c in acts if c in "fg"]
    if len(lateral) != 1:
        return acts
    for a in pacts:
        if a.code not in "fgF":
            continue
        span = d.sents[a.sent][max(0, a.pos - 60):a.pos + 200]
        m = _OUTER_TO_OUTER.search(span)
        if m and len({g.lower() for g in m.groups() if g}) == 2 and \
                d.once("three_lanes", lambda: bool(_THREE_LANES.search(d.text))):
            k = acts.index(lateral[0])
            return acts[:k + 1] + lateral[0] + acts[k + 1:]
    return acts


def _came_into_lane_from(d: Doc) -> str | None:
    """The side a party moving into the AV's lane from behind came from: the open side of a leftmost or rightmost
    AV lane, else the side of the AV the contact (or the damage told after it) names."""
    if d.av_lane is not None and d.av_lane <= 0:
        return "right"
    if d.av_lane is not None and d.av_lane >= 9:
        return "left"
    _, side = ego_contact_part(d)
    if side is None and d.contact_sent is not None:
        for s in d.sents[d.contact_sent + 1:d.contact_sent + 3]:
            if fre.search(r"\bdamag", s, re.I) and (m := fre.search(r"\b(driver|passenger|left|right)(?:'s)?[- ](?:side[- ])?"
                                                                  r"(?:rear|back)\b[^.]{0,40}?\bof\s+EGO\b", s, re.I)):
                side = body_side(m.group(1))
                break
    return side




def sentence_starts(t: str, sents: list[str]) -> list[int]:
    """Offset of each sentence in the normalised text (sentences are its consecutive, stripped pieces)."""
    out, pos = [], 0
    for s in sents:
        found = t.find(s[:60], pos)
        pos = found if found >= 0 else pos
        out.append(pos)
        pos += len(s)
    return out


# A sentence opening with "It" and a verb of what a vehicle did or was ("It was stopped in traffic", "It then
# turned"), not the impersonal "It was determined", "It is unknown", "It is a two-way stop".
_IT_OPENS = compile_gated(r"It(?=\s+(?:was|is|had|has|then|came|stopped|began|proceeded|continued|slowed|braked|"
                          r"turned|moved|made|remained|entered|pulled|reversed|started|yielded)\b)(?!\s+(?:was|is|"
                          r"has\s+been|had\s+been)\s+(?:determined|unknown|unclear|not|reported|believed|noted|"
                          r"likely|unlikely|possible|a|an|the|also|later|estimated|observed|confirmed|found|"
                          r"important|clear|evident|raining|dark|night|daylight)\b)")


def _it_named(t: str, sents: list[str], ments: list[list]) -> str:
    """The text with a sentence-opening "It" that continues the AV named as the AV ("EGO was struck by a cyclist on
    X. It was stopped in traffic ..."): the previous sentence's last subject, or with none its first mention, is
    the AV. Every rule written for "EGO was ..." then reads the pronoun's sentence as it reads the name's."""
    starts = sentence_starts(t, sents)
    for i in range(len(sents) - 1, 0, -1):
        if not _IT_OPENS.match(sents[i]) or not ments[i - 1]:
            continue
        subjects = [m for m in ments[i - 1] if m.subject]
        topic = subjects[-1] if subjects else ments[i - 1][0]
        if topic.kind == "ego" and t.startswith("It", starts[i]):
            t = t[:starts[i]] + "EGO" + t[starts[i] + 2:]
    return t


class Evidence:
    """Slot path -> normalised-text spans the slot was read from; mapped to the narrative as given at the end."""

    def __init__(self, d: Doc) -> None:
        self.d = d
        self.slots: dict[str, list[tuple[int, int]]] = {}

    def spans(self, slot: str, spans: list[tuple[int, int]] | None, *, fallback: Entity | None = None) -> None:
        if not spans and fallback is not None:
            self.mention(slot, fallback)
            return
        if spans:
            self.slots.setdefault(slot, []).extend(spans)

    def mention(self, slot: str, e: Entity) -> None:
        m = next((x for x in e.mentions if x.sent not in self.d.summary), e.first)
        self.spans(slot, [(self.d.offset(m.sent) + m.start, self.d.offset(m.sent) + m.end)])

    def acts(self, slot: str, acts: list) -> None:
        self.spans(slot, [(self.d.offset(a.sent) + a.pos, self.d.offset(a.sent) + a.pos + max(1, len(a.text)))
                          for a in acts if a.text])

    def mapped(self, original: str) -> tuple[tuple[str, tuple[tuple[int, int], ...]], ...]:
        omap = OffsetMap(original, self.d.text)
        out = []
        for slot, spans in self.slots.items():
            got = sorted({sp for a, b in spans if (sp := omap.to_original(a, b)) is not None})
            if got:
                out.append((slot, tuple(got)))
        return tuple(out)


_GEOMETRY_TOLD = compile_gated(r"\brear[- ]?end(?:ed|ing|s)?\b|\bhead[- ]?on\b|\bfrom\s+behind\b", re.I)


def _told_finite(d: Doc, acts: list[Act]) -> bool:
    """Is the party's first lane change told by a verb of its own clause ("attempted to change lanes"), not by a
    participle describing it ("struck by a minivan attempting to maneuver around it")?"""
    first = next((a for a in acts if a.code in "fgF"), None)
    return first is not None and not _PARTICIPLE_BEFORE.search(d.sents[first.sent][max(0, first.pos - 40):first.pos])


def _own_telling_after_contact(d: Doc, e: Entity) -> list[Act]:
    """A party first named after the AV's contact (a chain collision's: "A passenger car then braked to a stop behind
    the Waymo and to the left of the SUV. A second passenger car then made contact with the SUV"): its string is what
    its own sentence tells, up to its own contact (sketch.md: strings end at the contact)."""
    told = [m for m in e.mentions if m.sent not in d.summary]
    if d.contact_sent is None or not told or told[0].sent <= d.contact_sent:
        return []
    first = told[0].sent
    s = d.sents[first]
    met = CONTACT.search(s, told[0].end)
    return [a for a in d.acts if a.who == e.idx and a.sent == first and (met is None or a.pos < met.start())]


_PARTICIPLE_BEFORE = compile_gated(r"\b(?:attempting|trying|beginning|starting)\s+to\s+(?:\w+\s+)?$", re.I)


def extract(text: str, report_id: str) -> Sketch:
    """Read one narrative into a sketch. Raises InputError for an empty or over-long text; otherwise always returns
    a sketch (with `missing` naming what the text lacks)."""
    return extract_weighed(text, report_id)[0]


def extract_weighed(text: str, report_id: str) -> tuple[Sketch, tuple[str, ...]]:
    """The sketch and the slot paths whose evidence was weak or conflicting (`hybrid` asks a model for those):
    a position no cue decided and the phrase patterns could not place, lane cues that disagree, or actions
    defaulted because no manoeuvre was told of the party."""
    if not text or not text.strip():
        raise InputError("empty narrative", source=report_id)
    if len(text) > MAX_NARRATIVE_CHARS:
        raise InputError(f"narrative is {len(text):,} characters, over the limit of {MAX_NARRATIVE_CHARS:,} "
                         f"(one accident narrative runs to a few thousand)", source=report_id)
    t = normalise(text)
    sents = sentences(t)
    ments = [find_mentions(i, s) for i, s in enumerate(sents)]
    named = _it_named(t, sents, ments)
    if named != t:
        t, sents = named, sentences(named)
        ments = [find_mentions(i, s) for i, s in enumerate(sents)]
    summary = summary_sentences(sents)
    flat = [m for ms in ments for m in ms]
    ents = resolve(flat, summary, sents)
    mark_parked(ents, sents)
    d = Doc(text=t, sents=sents, ments=ments, ents=ents, acts=[], summary=summary, junction=False,
            starts=sentence_starts(t, sents))
    add_doors(d)
    attach_towed(d)
    fallback: int | None = None
    for i, s in enumerate(sents):
        d.acts += find_acts(i, s, ments[i], fallback, sents[max(0, i - 2):i])
        subj = [m for m in ments[i] if m.subject]
        if subj:
            fallback = -1 if subj[-1].kind in ("ego", "egod") else subj[-1].entity
    find_contact(d)
    d.av_lane = av_lane_rank(d)  # read once: every party's lane named on the road is compared with it
    parties, obstacles = counted(d)
    first_pos = None
    for e in parties + obstacles:
        ms = [m for m in e.mentions if m.sent not in summary] or e.mentions
        p = (ms[0].sent, ms[0].start)
        first_pos = p if first_pos is None or p < first_pos else first_pos
    # Where the interaction happened is read from the story up to the contact, as the road's other facts are: a
    # junction told only after it ("then pulled over past the intersection", "the police met them at the corner")
    # is no part of the scene.
    told = len(sents) if d.contact_sent is None else d.contact_sent + 1
    junction = d.junction = is_junction([s if k < told and not BOILERPLATE.search(s) else "" for k, s in enumerate(sents)],
                                        first_pos[0] if first_pos else 0, frozenset(summary))
    first_is_party = bool(parties) and (not obstacles or min(
        (([m for m in e.mentions if m.sent not in summary] or e.mentions)[0].sent,
         ([m for m in e.mentions if m.sent not in summary] or e.mentions)[0].start) for e in parties) == first_pos)
    ego_start, ego_actions = ego_sequence(d, first_pos, party_first=first_is_party)
    ego_actions = moved_off_into_object(d, obstacles, ego_actions)
    ego_start, ego_actions = backed_into_object(d, obstacles, ego_start, ego_actions)
    d.ego_start = ego_start
    ego_actions = stood_at_contact(d, ego_start, ego_actions)
    ego_heading = heading(d, -1)
    # The AV's own turn, told in its own clause ("EGO ... was proceeding southbound in the turn lane ..., yielding to
    # a pedestrian before completing a right turn"), not another's ("..., when an SUV was exiting a shopping center
    # driveway making a right turn").
    ego_turning = bool(set(ego_actions) & set("dej")) or bool(_AV_TURN_TOLD.search(t)) and junction
    npcs: list[Party] = []
    ev = Evidence(d)
    weak: list[str] = []
    ev.acts("ego.actions", [a for a in d.acts if a.who == -1 and before_contact(d, a.sent, a.pos)])
    missing: list[str] = []
    idmap: dict[int, str] = {}
    behind: set[int] = set()
    placed_at: dict[int, tuple[str, str | None]] = {}  # entity -> (position, lane) of its party
    for k, e in enumerate(parties, 1):
        pos, lane, known = party_position(d, e, ego_heading, ego_turning, ego_actions, frozenset(behind))
        placed = place(d, e, (pos, lane), ego_actions, ego_turning, told=known)
        pos, lane = placed.position, placed.lane
        known = known or placed.cue_placed
        slot = f"npcs[{k - 1}]"
        if not known or placed.conflicting:
            weak += [f"{slot}.position", f"{slot}.lane"]
        ev.mention(f"{slot}.category", e)
        ev.spans(f"{slot}.position", [c.span for c in placed.cues] or None, fallback=e)
        if pos == "R6":
            behind.add(e.idx)
        placed_at.setdefault(e.idx, (pos, lane))
        pacts = [a for a in d.acts if a.who == e.idx and a.sent not in summary and before_contact(d, a.sent, a.pos)]
        if not pacts and e.idx != d.partner:
            pacts = _own_telling_after_contact(d, e)
        if not any(a.code in "defgjkmFT" for a in pacts):
            # The telling gives no manoeuvre of the party but the summary does ("A Nissan made a left turn into
            # the AV"): the summary is the narrative's own account of it.
            pacts = sorted(pacts + [a for a in d.acts if a.who == e.idx and a.sent in summary and a.code in "defgjkm"],
                           key=lambda a: (a.sent, a.pos))
        pacts = wide_turn(prepend_modifier_acts(d, e, pacts))
        first_sent = ([m.sent for m in e.mentions if m.sent not in summary] or [e.first.sent])[0]
        setup_stop = [k for k, a in enumerate(pacts) if a.code == "S" and a.sent == first_sent]
        if setup_stop:
            # "A passenger car, traveling in the same direction, was stopped in the adjacent lane": the scene's
            # opening state is stopped; the participle before it only describes the car.
            pacts = pacts[setup_stop[0]:]
        pacts, under_way = opens_under_way(pacts, "cdefgjlF")
        stopped = bool(fre.search(r"\b(?:stopped|parked|stationary|waiting|stalled|idling|queued|disabled)\b",
                                  " ".join(m.mods for m in e.mentions)))
        # An oncoming party's move into the AV's lane is to its own left: its side is not the AV's.
        if pos == "R6" and lane == "same" and any(a.code == "F" and _INTO_EGO_LANE.search(a.text) for a in pacts):
            # Behind the AV and moving into its lane ("rear-ended by a passenger vehicle maneuvering into EGO's
            # lane"): it came from the next lane, the side the AV's own lane leaves open, else the side of the AV
            # it touched (the damage told, if the contact names no side).
            lane = _came_into_lane_from(d) or lane
        start, acts = sequence(pacts, stopped=stopped, ego=False, side="oncoming" if pos == "R7" else lane)
        acts = _across_three_lanes(d, pacts, acts)
        if start == "moving" and acts[:1] in ("b", "c", "h") and not under_way:
            acts = "a" + acts  # speeding up, slowing or stopping is done by a party already on its way
        if start == "moving" and not under_way and (acts[:1] in ("d", "e", "f", "g") and pos == "R5" and
                                                     OUT_OF_ROADSIDE not in placed.rule or
                                                     acts[:1] in ("f", "g") and pos == "R6" and _told_finite(d, pacts) or
                                                     acts[:1] in ("f", "g") and pos == "R7"):
            # it travelled along the AV's road (ahead, behind it: "the vehicle behind EGO then attempted to change
            # lanes", or towards it: "an oncoming passenger car crossed into the Waymo AV's lane") before turning off
            # it or changing lane
            acts = "a" + acts
        if start == "moving" and acts in ("", "a") and e.category == "pedestrian" and \
                not fre.search(r"\b(?:along|sidewalk)\b", context(d, e)):
            acts = "m"  # a pedestrian on the move in a collision report is crossing the AV's path (sketch.md, `m`)
        start, acts = standing_party(d, e, pacts, start, acts, ego_actions)
        start, acts = queued_behind(d, e, pacts, (pos, lane), start, acts)
        if pos in ("R1", "R2", "R3") and e.category in ("car", "van", "truck", "bus", "motorcycle") and "m" in acts:
            # A motor vehicle on another approach of the junction that goes across it ("crossed the intersection
            # against the red light") travels straight along its own road; `m` is for walkers and riders crossing
            # and for vehicles leaving a driveway or lot (sketch.md).
            acts = fre.sub(r"a+", "a", acts.replace("m", "a"))
        if e.category == "pedestrian" and set(acts) & set("fg"):
            # A walker's sideways move into the road ("darted in front of EGO") is its crossing of the AV's path.
            acts = fre.sub(r"m+", "m", acts.replace("f", "m").replace("g", "m"))
        if start == "stopped" and acts[:1] == "i" and acts[1:2] in ("f", "g") and acts[2:3] in ("d", "e", "j"):
            # Moving off from the curb or a space straight into a turn or a U-turn ("pulled out of the parking spot
            # and began attempting a multi-point U-turn"): the turn is its way out, no lane change before it.
            # Studyable gold, parties moving off into a turn: `id` 2, `ie` 1, `ij` 1; never a change between.
            acts = "i" + acts[2:]
        if acts.startswith("am"):
            acts = acts[1:]  # crossing the AV's path is the whole interaction, not a turn off a run along its road
        if start == "moving" and not acts:
            acts = "a"  # a party in motion that the text gives no manoeuvre: it kept to its lane
        side = next((c.value for c in placed.seen if c.kind == "passing" and c.value), "")
        if pos == "R6" and lane == "same" and side and not set(acts) & set("fg"):
            # Passing the AV from behind it in its own lane takes a move to the side it passed on; one that stood
            # behind it moved off first ("had been stopped ... behind the Waymo AV overtook": `if`, as "passed" gives).
            acts = (acts or ("i" if start == "stopped" else "a")) + ("f" if side == "left" else "g")
        if pos == "R6" and lane == "same" and ego_start == "stopped" and start == "moving" and \
                not set(acts) & set("fgklm") and AV_AT_CURB.search(t):
            # The AV parked at the curb ("was parallel parked along the curb when it began to pull away"): a
            # vehicle coming up behind it in traffic is in the travel lane, on its left.
            lane = "left"
        lateral = [c for c in acts if c in "fg"]
        if pos in ("R5", "R6") and lane in ("left", "right") and lateral[:1] == ["f" if lane == "left" else "g"] and \
                not side:
            # A lane change away from the AV toward the side it was placed on ("a truck stopped behind EGO entered
            # the oncoming lane to go around it"): it began in the AV's lane; the change is how it reached the side.
            # (One placed by the side it passed on stays there: sketch.md places a pass by its side; so does one
            # whose first sideways move is toward the AV.)
            lane = "same"
        if pos == "R6" and acts.endswith("k") and e.idx == d.partner and not backed_out_behind(d, e):
            # It touched the AV backing up: a vehicle going the AV's way moves away from the AV backing from behind
            # it, so it backed from ahead or alongside (R5), on the side it was read on. Studyable collision parties
            # backing at the contact and read behind: gold R5 in 3 of 3 (sgo6 9285 "the asphalt roller was
            # reversing ... made contact with the rear passenger side"); the two gold R6 backing parties moved
            # forward again before the contact (`kif`). One backing out of a parking space into the AV's rear end
            # faced across the road, behind it (the gold's R6 placeholder of study2 s159, whose place it calls
            # untold).
            pos = "R5"
        if pos not in ("R5", "R6", "R7"):
            lane = None
        # A party standing still throughout that the AV, moving forward, ran into stood in its path: both its
        # manoeuvre (none) and its place (ahead, in the AV's lane: the first reading) are told.
        in_path = start == "stopped" and not acts and ego_start == "moving" and "k" not in ego_actions
        # The part of the AV it touched (its front, rear, a side) tells where the party was: a place a reader can
        # tell, so no refusal (sketch.md: `position` is missing only when the place cannot be told).
        # So does a contact named by its geometry ("rear-ended", "head-on", "from behind").
        touched = any(c.kind == "contact" and any(c.value.split("/")[:2]) for c in placed.seen) or \
            (e.idx == d.partner and d.contact_sent is not None and
             bool(_GEOMETRY_TOLD.search(d.sents[d.contact_sent])))
        if not known and not pacts and not in_path and not touched and (e.idx == d.partner or d.partner is None):
            # Only the party the conflict is about can leave a scenario unbuildable: a bystander the text does
            # not place still gets its best reading (sketch.md: refuse only what is truly missing).
            missing += ["position", "actions"]
        ev.acts(f"{slot}.actions", pacts)
        if not pacts:
            weak.append(f"{slot}.actions")
        npcs.append(Party(id=f"npc{k}", category=e.category, position=pos, lane=lane,  # type: ignore[arg-type]
                          start=start, actions=acts))  # type: ignore[arg-type]
        idmap.setdefault(e.idx, f"npc{k}")  # a numbered group: the first of its parties is the one touched
    obs: list[Obstacle] = []
    for k, e in enumerate(obstacles, 1):
        pos, lane = obstacle_position(d, e, ego_actions, ego_turning)
        if e.category in MOVING_THINGS and (origin := thing_origin_lane(d, e)):
            lane = origin  # a thing that moved into the AV's path came from the lane the road names for it
        thrown_from = placed_at.get(thrower(d, e) if e.category == "debris" else None)
        if thrown_from and thrown_from[0] in ("R5", "R6", "R7") and thrown_from[1]:
            # Debris a party threw at the AV ("a nearby semi-trailer truck merging from Interstate 238 generated a
            # draft that projected road debris onto the test vehicle") came from where that party was.
            pos, lane = thrown_from
        cat = "door" if e.idx in d.doors else ("parked_vehicle" if e.kind == "party" else e.category)
        ev.mention(f"obstacles[{k - 1}].category", e)
        obs.append(Obstacle(id=f"obs{k}", category=cat, position=pos, lane=lane))  # type: ignore[arg-type]
        idmap.setdefault(e.idx, f"obs{k}")
    partner = d.ents[d.partner] if d.partner is not None else None
    with_id = idmap.get(d.partner) if d.partner is not None else None
    if partner is not None and with_id is None:
        partner = None
    party = next((n for n in npcs if n.id == with_id), None)
    ctype = collision_type(d, partner, party, bool(with_id and with_id.startswith("obs")), ego_actions)
    if partner is not None and partner.kind == "obstacle" and partner.category in ("debris", "other") and \
            came_at_av(d, partner):
        ctype = "other"  # struck by a thing thrown or flying at the AV: the form's "other", not hitting an object
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
    sig = signal_state(t, layout=r.layout, control=r.control, ego_start=ego_start)
    env = environment(t)
    for slot, spans in scene_spans(t, r, env, sig).items():
        ev.spans(slot, spans)
    if d.contact_sent is not None:
        ev.spans("collision.with", [(d.offset(d.contact_sent), d.offset(d.contact_sent) + len(sents[d.contact_sent]))])
    sketch = Sketch(report_id=report_id, road=r, environment=env, signal_state=sig,  # type: ignore[arg-type]
                  ego=EgoInfo(start=ego_start, actions=ego_actions),  # type: ignore[arg-type]
                  npcs=tuple(npcs), obstacles=tuple(obs),
                  collision=Collision(with_=with_id, type=ctype),  # type: ignore[arg-type]
                  missing=tuple(dict.fromkeys(missing)),  # type: ignore[arg-type]
                  evidence=ev.mapped(text))
    return sketch, tuple(weak)
