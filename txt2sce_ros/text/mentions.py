"""Narrative -> sentences -> mentions of the AV, other parties and objects, grouped into entities (coreference).

The narratives name the AV in a dozen ways ("the Waymo AV", "our vehicle", "the Zoox vehicle", "SV"): they are all
rewritten to the token `EGO` (its drivers and operators to `EGOD`) before anything else, so later rules see one name.
Other parties are noun phrases around a head noun (`PARTY_HEADS`, makes and models); an indefinite article opens a
new entity, a definite one refers back to the latest compatible entity.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass, field

from . import fastre as fre
from .fastre import compile_gated
from .lexicon import (COMPANY_ALTERNATION, CONTACT, EGO_DRIVER, EGO_PATTERNS, GROUP_HEADS, MAKES, OBSTACLE_HEADS,
                      PARKED_WORDS, PARTY_HEADS, VAN_MODELS, ego_patterns)

_QUOTE_PAIRS = (("“", '"'), ("”", '"'), ("‘", "'"), ("’", "'"), ("–", "-"), ("—", "-"), ("\u00a0", " "))
_EGO_RES = [compile_gated(p, re.I) for p in EGO_PATTERNS]
_COMPANY_RE = compile_gated(rf"\b(?:{COMPANY_ALTERNATION})\b", re.I)
# How a narrative introduces its AV under its operator's name: "A Waymo Autonomous Vehicle", "an Avride AV",
# "(the "Acme AV")", or as the first vehicle of its first sentence, "(On ..., ) a Zoox vehicle ...". The name found
# there names the AV in the rest of the text, whether or not the operator is one of the companies the lexicon knows.
_DESCRIPTOR = r"(?:autonomous|automated|driverless|self-driving|test|driver-equipped|ads|level|registered|av|sv|" \
              r"the|an?|this|our|its)\b"
# (a dot only inside a name, "Pony.ai": never the end of a sentence)
_WORD = rf"(?!{_DESCRIPTOR})(?-i:[A-Z])(?:[\w&'-]|\.(?=\w))*"
_NAME = rf"({_WORD}(?:\s+{_WORD}){{0,3}}?)"
# (the article may be dropped where a sentence or a form's field opens, as a form-like report writes: "At 2:23pm:
# WeRide driverless vehicle (vehicle 1) ... was travelling")
_OPERATOR_DEF = compile_gated(
    rf"(?:\b(?:an?|the)\s+|(?:^|(?<=[:.;]\s)))(?:registered\s+)?{_NAME}\s+(?:(?:driver-equipped|ads|level\s+4)\s+)*"
    rf"(?:(?:autonomous|automated|driverless|self-driving)\s+(?:test\s+)?(?:vehicle|car|truck|shuttle)|AV)\b|"
    rf"\(\s*[\"']\s*(?:the\s+)?{_NAME}\s+(?:AV|vehicle)\s*[\"']\s*\)", re.I)
_FIRST_VEHICLE = compile_gated(
    rf"\A[^.]{{0,200}}?\b(?:an?|the)\s+(?:registered\s+)?{_NAME}\s+(?:test\s+)?(?:vehicle|car|robotaxi|shuttle)\b",
    re.I)
# Spellings other than the ones the rules read, rewritten first: (words one of which the text must hold for the
# pattern to be tried at all, looked for in the lower-cased text unless the rewrite is case-sensitive; pattern;
# replacement). Scanning every narrative with every pattern costs more than the look for its words.
# ("going north" is travel along a road as "traveling northbound" is: the rules read the latter)
_TRAVEL_VERB = {"going": "traveling", "went": "traveled"}
#: A street's name in police shorthand: one to four capitalised words, "[XXX]" or an ordinal ("16th Street").
_STREET_WORD = r"(?:\[XXX\]|(?-i:[A-Z])[\w'&-]+|\d+(?:st|nd|rd|th)\b)"
_STREET_WORDS = rf"{_STREET_WORD}(?:\s+{_STREET_WORD}){{0,3}}"
_SPELLINGS: tuple[tuple[tuple[str, ...], bool, re.Pattern[str], Callable[[re.Match[str]], str]], ...] = (
    # "a left-turn", "a lane-change", "the stop-sign", "a red-light", "the parking-lot", "the bike-lane": spaced
    (("-turn", "-chang", "-sign", "-light", "-lot", "-lane", "-line", "-guard"), False,
     compile_gated(r"\b(left|right|lane)-(turns?|turning|turned|change[sd]?|changing)\b|"
                   r"\b(stop|red|traffic|parking|bike|bicycle|bus|turn|travel|through|center|centre|"
                   r"median|curb|crossing)-(signs?|lights?|lots?|lanes?|signals?|lines?|guards?)\b", re.I),
     lambda m: " ".join(g for g in m.groups() if g)),
    # "on-coming", "right-most", "west bound", "west-bound", "cross walk": one word
    (("on coming", "on-coming", "left most", "left-most", "right most", "right-most", " bound", "-bound",
      "cross walk", "cross-walk"), False,
     compile_gated(r"\b(on)[- ](coming)\b|\b(left|right)[- ](most)\b|"
                   r"\b((?:north|south)?(?:east|west)|north|south)[- ](bound)\b|\b(cross)[- ](walks?)\b", re.I),
     lambda m: "".join(g for g in m.groups() if g)),
    # Synonyms the rules read in one spelling: "the left-hand lane", "the neighboring lane", "a T-junction",
    # "came to a halt" (the rules know "left lane", "adjacent lane", "intersection", "stop")
    (("-hand", " hand", "neighbo", "junction", "halt", "crossroad"), False,
     compile_gated(r"\b(left|right)[- ]hand(?=\s+(?:lanes?|turns?|side|curb|shoulder|edge|corner)\b)|"
                   r"\b(neighbou?ring)(?=\s+lanes?\b)|\b(junction|crossroad)(s?)\b|\b(halt)(ed|ing|s)?\b", re.I),
     lambda m: m.group(1) if m.group(1) else "adjacent" if m.group(2) else ("intersection" + (
         m.group(4) if m.group(3).lower() == "junction" else ""))
     if m.group(3) else "stop" + {"ed": "ped", "ing": "ping", "s": "s"}.get((m.group(6) or "").lower(), "")),
    # "came to rest behind its lead vehicle", "came to a complete rest", "came slowly to a stop": a standstill told
    # as police tell it, the "came to a stop" the rules read (3 of 6 studyable sentences so reworded read a queue's
    # stop as a slowing, a red light as green or yellow; the one real use, a motorcycle that "came to rest on its
    # right side", is after the contact). ("came nearly to a stop" is a slowing: not a standstill.)
    # ("stopped completely", "stopped fully": the complete stop the rules read)
    (("to rest", "to a rest", "complete rest", "full rest", "ly to ", "stopped completely", "stopped fully"), False,
     compile_gated(r"\b(came|come|comes|coming)\s+(?:(?!nearly\b|almost\b)\w+ly\s+)?to\s+(?:a\s+)?"
                   r"(complete\s+|full\s+)?rest\b|\b(came|come|comes|coming)\s+(?!nearly\b|almost\b)\w+ly\s+"
                   r"(?=to\s+(?:a\s+)?(?:complete\s+|full\s+)?stop\b)|\bstopped\s+(completely|fully)\b", re.I),
     lambda m: f"{m.group(1)} to a {m.group(2) or ''}stop" if m.group(1) else f"{m.group(3)} " if m.group(3) else
     "came to a complete stop"),
    # "came to a stop, at which time a passenger vehicle rear-ended it": the relative "at which time/point" is the
    # "when" the rules read a clause's subject and its time by
    (("at which",), False, compile_gated(r"\bat\s+which\s+(?:time|point)\b", re.I), lambda m: "when"),
    # "from Market St. onto Haight St. at", "between 11th St. and 10th Street": a street's abbreviation inside a
    # sentence loses its period (the rules that read a turn's streets or a clause scan up to a period, and know "St"
    # as a street's suffix; police and DMV reports abbreviate where company narratives spell out; the word itself
    # is kept, so evidence spans still align with the narrative). Not before a capital: "St. Francis", a sentence's
    # end.
    (("St.", "Ave.", "Blvd.", "Rd.", "Hwy.", "Pkwy."), True,
     compile_gated(r"(?<=[A-Za-z0-9] )(St|Ave|Blvd|Rd|Hwy|Pkwy)\.(?=,|\s+[a-z0-9(])"),
     lambda m: m.group(1)),
    # "just past the Mariposa Street intersection", "at the Fillmore/Pine intersection": a junction named by its
    # streets before the noun (police shorthand) told as the rules read it, "the intersection with Mariposa Street",
    # "the intersection of Fillmore and Pine" (session 22: "the intersection with X" so reworded read 10 of 131
    # studyable narratives differently: the rules' "near", "before", "crossed" "the intersection" no longer met,
    # the road read a junction the AV had not reached or had passed).
    # (each name a capitalised word of two letters or more, "[XXX]" or an ordinal: not "the 4-way intersection",
    # "the T intersection")
    (("intersection",), True,
     compile_gated(rf"\b([Tt])he\s+({_STREET_WORDS})(?:\s*/\s*({_STREET_WORDS}))?\s+intersection\b"),
     lambda m: f"{m.group(1)}he intersection " + (f"of {m.group(2)} and {m.group(3)}" if m.group(3) else
                                                 f"with {m.group(2)}")),
    # "a pick-up truck ... the pickup truck": one noun, spelled one way (the name a party is followed by)
    # ("a pick up truck", spaced: the same noun)
    (("pick-up", "pick up"), False, compile_gated(r"\b(pick)[- ](up)(?=\s+trucks?\b)", re.I),
     lambda m: m.group(1) + m.group(2)),
    # "turned to the right", "in back of", "nearing" or "neared the intersection", "came up from the rear",
    # "immediately behind": the words the rules read
    (("to the left", "to the right", "in back of", "nearing", "neared", " up from", "immediately behind"), False,
     compile_gated(r"\b(turn(?:ed|ing|s)?)\s+to\s+the\s+(left|right)\b(?!\s+(?:lane|side|of|curb|shoulder)\b)|"
                   r"\b(in\s+back\s+of)\b|\b(nearing|neared)\b|"
                   r"\b(came|coming|comes|come)\s+up\s+(?=from\s+(?:the\s+)?(?:rear|behind)\b)|"
                   r"\b(immediately)(?=\s+behind\b)", re.I),
     lambda m: f"{m.group(1)} {m.group(2)}" if m.group(1) else "behind" if m.group(3) else
     {"nearing": "approaching", "neared": "approached"}[m.group(4).lower()] if m.group(4)
     else {"came": "approached ", "coming": "approaching ", "comes": "approaches ", "come": "approach "}[
         m.group(5).lower()] if m.group(5) else "directly"),
    # "the left traffic lane", "the adjacent travel lane", "the lane on the left": the lane the rules know by its side
    (("traffic lane", "travel lane", "driving lane", "lane on the"), False,
     compile_gated(r"\b(left|right|center|centre|middle|adjacent|leftmost|rightmost|far\s+left|far\s+right|"
                   r"neighbou?ring)\s+(?:traffic|travel|driving)\s+(lanes?)\b|"
                   r"\b(lane)\s+on\s+the\s+(left|right)\b(?!\s+(?:side\s+)?of\b)", re.I),
     lambda m: f"{m.group(1)} {m.group(2)}" if m.group(1) else f"{m.group(4)} {m.group(3)}"),
    # a heading told with a verb and a bare compass point ("going north", "riding west"): the "-bound" the rules read
    (("going ", "driving ", "moving ", "proceeding ", "riding ", "walking ", "headed ", "continu", "drove ", "went ",
      "rode "), False,
     compile_gated(r"\b(going|driving|moving|proceeding|riding|walking|headed|continuing|continued|drove|went|rode)\s+"
                   r"(north|south|east|west|northeast|northwest|southeast|southwest)\b(?!\s*-?\s*(?:bound|ward|ern))",
                   re.I),
     lambda m: f"{_TRAVEL_VERB.get(m.group(1).lower(), m.group(1))} {m.group(2)}bound"),
    # "a ped", "two peds" (police and NHTSA shorthand): a pedestrian
    ((" ped",), False, compile_gated(r"\b(ped)(s?)\b", re.I), lambda m: f"pedestrian{m.group(2)}"),
    # "autonomous driving mode", "manual driving mode": a mode, not a driving (the rules read "autonomous mode")
    (("driving mode",), False, compile_gated(r"\b(autonomous|manual|conventional)\s+driving(?=\s+mode\b)", re.I),
     lambda m: m.group(1)),
    # "While attempting a right turn in autonomous mode from westbound X onto northbound Y", "was stopped in
    # autonomous mode on the off-ramp": the AV's driving mode does not matter (sketch.md), and told inside a clause
    # it parts the words a reading joins; dropped ("operating in autonomous mode when" reads "operating when")
    (("autonomous mode", "manual mode", "driverless mode", "driving mode"), False,
     compile_gated(r"\s+in\s+(?:(?:fully|supervised|driverless|conventional)\s+)?(?:autonomous|manual|driverless|"
                   r"conventional)\s+mode\b", re.I), lambda m: ""),
    # "in a northerly direction", "in the northbound direction", "heading northward": the "-bound" the rules read
    (("erly direction", "ern direction", "bound direction", "ward"), False,
     compile_gated(r"\bin\s+(?:an?|the)\s+(north|south|east|west|northeast|northwest|southeast|southwest)"
                   r"(?:erly|ern|bound)?\s+direction\b|\b(north|south|east|west)wards?\b", re.I),
     lambda m: f"{m.group(1) or m.group(2)}bound"),
    # "gave way to", "reduced its speed", "a change of lanes", "self-driving mode"
    (("gave way", "giving way", "give way", "gives way", "reduc", "change of lane", "self-driving mode"), False,
     compile_gated(r"\b(gave|giving|give|gives)\s+way\b|\b(reduced|reducing|reduces)\s+(?:(?:its|his|her|their)\s+)?speed\b|"
                   r"\ba\s+change\s+of\s+lanes?\b|\b(self-driving)(?=\s+mode\b)", re.I),
     lambda m: ({"gave": "yielded", "giving": "yielding", "give": "yield", "gives": "yields"}[m.group(1).lower()]
                if m.group(1) else {"reduced": "slowed", "reducing": "slowing", "reduces": "slows"}[m.group(2).lower()]
                if m.group(2) else "autonomous" if m.group(3) else "a lane change")),
    # "made a right" (a turn), "cut ahead of", "traveling to the rear of", "a parallel-parked car"
    (("made a ", "ahead of", "to the rear of", "parallel"), False,
     compile_gated(r"\b(made|making|make|makes)\s+a\s+(left|right)\b(?!\s*-?\s*(?:turn|lane|side|hand|of\b))|"
                   r"\b(cut|cutting|cuts|pulled|pulling|merged|merging|swerved|swerving|moved|moving)\s+ahead\s+of\b|"
                   r"\b(to\s+the\s+rear\s+of)\b|\b(parallel[- ]parked)\b", re.I),
     lambda m: (f"{m.group(1)} a {m.group(2)} turn" if m.group(1) else f"{m.group(3)} in front of" if m.group(3)
                else "behind" if m.group(4) else "parked")),
    # "continued into the intersection", "continued forward": moving on is proceeding ("continued to brake" is not)
    (("continu",), False,
     compile_gated(r"\b(continued|continuing|continues|continue)(?=\s+(?:into|onto|forward|through|straight|across|"
                   r"along|down|up|on\b|ahead|northbound|southbound|eastbound|westbound)|\s*[,.;]|\s*$)", re.I),
     lambda m: {"continued": "proceeded", "continuing": "proceeding", "continues": "proceeds",
                "continue": "proceed"}[m.group(1).lower()]),
    # British spelling, as the rules read US
    (("manoeuv",), False, compile_gated(r"\bmanoeuv(re|res|red|ring|rable)\b", re.I),
     lambda m: {"re": "maneuver", "res": "maneuvers", "red": "maneuvered", "ring": "maneuvering",
                "rable": "maneuverable"}[m.group(1).lower()]),
    # headings abbreviated in capitals, as police and NHTSA narratives write them: "traveling NB", "a S/B sedan"
    (("NB", "SB", "EB", "WB", "/B"), True, compile_gated(r"\b(N|S|E|W|NE|NW|SE|SW)/?B\b"),
     lambda m: {"N": "north", "S": "south", "E": "east", "W": "west", "NE": "northeast", "NW": "northwest",
                "SE": "southeast", "SW": "southwest"}[m.group(1)] + "bound"),
)
#: Capitalised words that open such a phrase without naming an operator.
_NOT_OPERATORS = frozenset({"level", "sae", "fully", "highly", "new", "another", "other", "second", "first",
                            # the SGO form's role names: "a CP vehicle", "the Crash Partner vehicle"
                            "cp", "crash", "ov", "tpv", "pov", "third-party", "third", "non-ads", "non-av"}) | \
    frozenset(MAKES) | frozenset(VAN_MODELS)


def _unknown_operator(t: str) -> str | None:
    """The operator's name the narrative gives its AV when the lexicon does not know it, else None."""
    # (The AV is introduced in the opening sentences: the rest of a long narrative is not searched.)
    m = _OPERATOR_DEF.search(t, 0, 600) or _FIRST_VEHICLE.search(t)
    if m is None:
        return None
    name = " ".join(next(g for g in m.groups() if g).split())
    if _COMPANY_RE.search(name) or name.lower() in _NOT_OPERATORS or name.split()[0].lower() in _NOT_OPERATORS:
        return None
    return name


_NAME_RES: dict[str, tuple[list[re.Pattern[str]], re.Pattern[str]]] = {}


def _name_patterns(operator: str | None) -> tuple[list[re.Pattern[str]], re.Pattern[str]]:
    """The AV-name and company patterns, with `operator` added to the known companies (compiled once per name;
    most narratives name a known operator and use the module's own patterns)."""
    if operator is None:
        return _EGO_RES, _COMPANY_RE
    if operator not in _NAME_RES:
        if len(_NAME_RES) >= 64:
            _NAME_RES.pop(next(iter(_NAME_RES)))
        co = f"(?:{COMPANY_ALTERNATION}|{re.escape(operator)})"
        _NAME_RES[operator] = ([compile_gated(p, re.I) for p in ego_patterns(co)],
                               compile_gated(rf"\b{co}\b", re.I))
    return _NAME_RES[operator]


# (Words end at a full stop: "the Waymo AV. The truck" is two sentences, not an AV named a truck.)
_FIRST_EGO_NOUN = compile_gated(r"\b(?:[Aa]n?|[Tt]he)\s+[A-Z][\w-]*(?:\.[\w-]+)*\s+(?:[\w-]+(?:\.[\w-]+)*\s+){0,2}?"
                                r"(shuttle|Prius|robotaxi|truck|R2|pod)\b")
_UPPER_BYTES = b"ABCDEFGHIJKLMNOPQRSTUVWXYZ"
_ALPHA_BYTES = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
_NEGATED_NP = compile_gated(r"\b(?:any|no|none|neither|nor)\s+(?:the\s+|other\s+)?(?:[\w-]+\s+)?$", re.I)
# ("the subject Mercedes-Benz": a reporter's name for its own vehicle; "subject" goes with the determiner)
_DET_END = compile_gated(r"\b(?:a|an|the|another|one|that|this|its|their|his|her)(?:\s+subject)?\s*$", re.I)
# After an opening clause that no comma closes, the AV named right before a progressive verb is that verb's subject
# ("When traffic ahead began to move EGO was appropriately following the car ahead"); not the object of a
# preposition ("As a van approaching from the left of EGO was slowing").
_PROGRESSIVE_AFTER = compile_gated(r"\s+(?:was|were|is|are)\s+(?:\w+ly\s+)?\w+ing\b", re.I)
_OPEN_CLAUSE = compile_gated(r"^\W*(?:when|as|while|after|once|before|because|since|until)\b[^,;]*$", re.I)
_PREPOSITION_END = compile_gated(r"\b(?:of|to|from|behind|by|with|at|in|on|for|past|around|near|into|onto|toward|"
                                 r"towards|than|ahead|beside|alongside|and|between)\s*$", re.I)
# ("Waymo AV"), (Vehicle 2), (car 1), (AV), (Level 4): definitions and labels, not story. Other parentheses
# ("a fixed object (solar panel)", a lane's number: "the left turn lane (lane 2)") keep their words.
_PAREN_DEF = compile_gated(r"\s*\((?:\s*(?:the\s+)?[\"'][^()]{0,40}|(?:vehicle|car|v)\s*#?\s*\d+|(?!lanes?\b)[A-Z][A-Za-z.]{0,6}"
                        r"(?:\s+\d+)?|\d[^()]{0,20}|[^()]*\bmode\b[^()]*|"
                        # "The subject vehicle (autonomous vehicle - AV)": what the AV is, said again
                        r"\s*(?:autonomous|automated|self-driving|driverless)\s+vehicle\b[^()]{0,20})\)", re.I)
#: A quoted name defined in parentheses: "(the 'TRI Vehicle")", "("the shuttle")".
_ALIAS_DEF = compile_gated(r"\(\s*(?:the\s+)?[\"']\s*([A-Za-z][\w.-]*(?:\s+[\w.-]+){0,3}?)\s*[\"']\s*\)")
# Abbreviations that never end a sentence, and street abbreviations that do only before a capitalised word.
_ABBREV = compile_gated(r"\b(?:Mt|Jr|Sr|No|[Aa]pprox|vs|S|N|E|W|U\.S|a\.m|p\.m|Mr|Ms|Mrs|Dr(?=\.\s+[A-Z][a-z]+\s+"
                     r"(?:St|Ave|Blvd|Rd|Street|Avenue)))\.|"
                     r"\b(?:St|Ave|Blvd|Rd|Dr|Hwy|Pkwy|Ln|Ct|Pl)\.(?=\s+[a-z0-9(,])")
# (a redaction that swallowed the period after a street name: "... involving a passenger car on [XXX] The Waymo AV
# was stopped at the curb": a capitalised determiner or clause word after it opens the next sentence)
_SENT_SPLIT = compile_gated(r"(?<=[.!?])\s+(?=[A-Z\[\"(0-9])|(?<=[a-z]\.)(?=[A-Z][a-z])|"
                            r"(?<=\[XXX\])\s+(?=(?:The|A|An|While|As|When|After|At|Then|It|EGO)\s)")
# ("on westbound Lincoln Way": a heading between the preposition and the street's name)
_HEADING_WORD_END = compile_gated(r"\b(?:north|south|east|west|northeast|northwest|southeast|southwest)bound\s+$", re.I)
_PLACE_PREP = compile_gated(r"\b(?:on|onto|along|at|from|of|near|down|up|to|toward|towards)\s+$")
_STREET_SUFFIX = compile_gated(r"^\s*(?:[A-Z][\w.]*\s+){0,2}(?:Street|St\b|Avenue|Ave\b|Road|Rd\b|Boulevard|Blvd|Drive|"
                            r"Dr\b|Way|Lane|Ln\b|Parkway|Pkwy|Highway|Hwy|Place|Pl\b|Court|Ct\b|Terrace|Circle|"
                            r"Expressway|Alley|Plaza|Park\b|Center)")

_HEADS = sorted(set(PARTY_HEADS) | set(OBSTACLE_HEADS) | set(MAKES) | set(VAN_MODELS) | set(GROUP_HEADS),
                key=len, reverse=True)
def _trie_pattern(words: list[str]) -> str:
    """One regex alternation for many literals, factored as a trie: the engine then tries a few branches per
    position instead of every word (a plain alternation of ~250 heads made this the extractor's hot spot)."""
    trie: dict = {}
    for w in words:
        node = trie
        for ch in w.lower():
            node = node.setdefault(ch, {})
        node[""] = {}

    def emit(node: dict) -> str:
        alts = [re.escape(ch) + emit(sub) for ch, sub in sorted(node.items()) if ch]
        optional = "" in node
        if not alts:
            return ""
        body = alts[0] if len(alts) == 1 and not optional else "(?:" + "|".join(alts) + ")"
        return body + ("?" if optional else "")

    return emit(trie)


_HEAD_RE = compile_gated(r"\b(EGOD|EGO|it|he|she|" + _trie_pattern(_HEADS) + r")(?:'s|s')?\b", re.I)
# A possessive written without its apostrophe, as redacted SGO narratives print it ("the heavy trucks trailer", "the
# passenger cars driver side", "TuSimples position"): a party's or operator's name, an "s", and a part or quality of
# it (not a plural: "Both vehicles sustained damage", "two vehicles front bumpers").
_VEHICLE_PART = (r"(?:(?:front|rear|back|left|right|driver|passenger|lower|upper)(?:[- ]side)?\s+){0,3}(?:bumper|side|door|"
                 r"mirror|fender|trailer|hood|panel|corner|wheel|tire|tyre|quarter|headlight|taillight|windshield|"
                 r"window|roof|trunk|sensor|camera|lidar|lane|path|edge|body|front|rear|driver|passenger|position|"
                 r"level|ads|tailgate|liftgate|hatch|grille|bed|cab|trailer)\b")
_BARE_POSSESSIVE = compile_gated(r"\b(" + _trie_pattern(sorted(set(PARTY_HEADS) | set(MAKES), key=len, reverse=True))
                                 + r")s\s+(?=" + _VEHICLE_PART + ")", re.I)
# (the cheap look: case-sensitive on the lower-cased text, which starts at each "s" only; the text's white space is
# one space by then)
_S_BEFORE_PART = compile_gated(r"s(?<!'s)(?<!\bits)(?<!\bwas)(?<!\bis)(?<!\bhas)(?<!\bhis)(?<!\bthis)(?<!\bas) "
                               + _VEHICLE_PART.replace("\\s+", " "))
_COUNTED_BEFORE = compile_gated(r"\b(?:both|two|three|all|several|multiple|many|other|the\s+two)\s+(?:[\w-]+\s+)?$", re.I)


def _restore_possessives(t: str) -> str:
    """"the heavy trucks trailer" as "the heavy truck's trailer" (see `_BARE_POSSESSIVE`)."""
    if not _S_BEFORE_PART.search(t.lower()):  # (a cheap look first: most narratives hold no such word)
        return t
    return _BARE_POSSESSIVE.sub(lambda m: m.group(0) if _COUNTED_BEFORE.search(t, max(0, m.start() - 30), m.start())
                                else f"{m.group(1)}'s ", t)


# Heads that name something else when followed by these words ("bike lane", "bus stop", "turn signal").
# ("the bus and taxi lane", "a bus/bike lane": a lane two kinds of traffic share is a lane too)
_NOT_HEAD_AFTER = compile_gated(r"^\s*(?:(?:(?:and|or)\s+|/\s*)[\w-]+\s+lanes?\b|lanes?(?![- ]split)|racks?|stops?|paths?|routes?|only|signals?|doors?|mirrors?|drivers?|"
                             # ("the municipal tram line", "the train tracks", "a bus station"; a vehicle's own parts
                             # and systems: "the vehicle control unit", "the left front truck tire")
                             r"lines?|tracks?|stations?|control\s+units?|controls?|systems?|computers?|software|"
                             r"tires?|tyres?|wheels?|"
                             r"operators?|sensors?|side|seat|seating|mode|gear|pedal|bumper|lights?|"
                             r"occupants?|passengers?|lengths?|damages?|cameras?|footage|owners?)\b(?!-)", re.I)  # "a motorcyclist lane(-)splitting" is a rider
_RIDER_PICKUP = compile_gated(r"\b(?:passenger|rider|customer|curbside|scheduled)\s+pick-?ups?\b|"
                              r"\bfor\s+(?:a|the|its|an\s+\w+)\s+pick-?up\s*(?:[.,;]|$|\b(?:and|when|while|at|on|in|facing)\b)|"
                              r"\bpick-?up\s+(?:location|zone|spot|point|area|lane)\b|"
                              # "a pick-up and drop-off zone", "passenger drop-off/pick-up"
                              r"\bpick-?ups?\s*(?:and|or|/|&)\s*drop-?offs?\b|\bdrop-?offs?\s*(?:and|or|/|&)\s*pick-?ups?\b",
                              re.I)
_CAB_OF = compile_gated(r"(?:\bEGO|\btruck|\btractor|\bsemi|\brig|\btrailer|\blorry)(?:'s)?\s+$", re.I)
_CAB_OF_AFTER = compile_gated(r"\s+of\s+(?:(?:the|a|an|its)\s+(?:[\w-]+\s+){0,3}?)?"
                              r"(?:EGO|truck|tractor|semi|rig|lorry)\b", re.I)
_CHAIN_OF = compile_gated(r"^\s*(?:reactions?|collisions?|crash(?:es)?|of\s+events)\b", re.I)
DETS = {"a": "a", "an": "a", "another": "a", "one": "a", "the": "the", "that": "the", "this": "the",
        "its": "the", "their": "the", "his": "the", "her": "the", "other": "the", "second": "a", "third": "a"}
_STOP_BACK = compile_gated(r"^(?:to|of|with|by|for|from|behind|into|onto|on|in|at|near|around|past|and|or|but|"
                        r"when|as|while|was|were|is|had|has|then|that|which|who|EGO|EGOD|,|;|:|"
                        # a verb taking the noun as its object ("struck two unoccupied vehicles") is no modifier
                        r"struck|strikes|hit|hits|contacted|clipped|bumped|impacted|sideswiped|side-swiped|"
                        r"rear-ended)$", re.I)
# ("in the same direction as EGO": a comparison's "as" opens no clause.)
_SUBJ_BEFORE = compile_gated(r"(?:^|[,;:]|\b(?:when|(?<!direction\s)(?<!way\s)(?<!same\s)as|while|and|then|"
                          r"but|after|before|until|because|where|once|"
                          r"since|so|which|that|who|shortly\s+thereafter|thereafter|meanwhile|also))\s*$", re.I)
# "lane splitting between EGO and a car": the second of a pair after "between" is no clause's subject
_BETWEEN_AND = compile_gated(r"\bbetween\s+(?:[\w'-]+\s+){1,4}and\s*$", re.I)
# A sentence that opens with when it happened and no comma before its subject: "On June 3, 2025 at 4:10 PM PT a
# Waymo AV was stopped ...", "At approximately 9:44 AM the AV ...".
_TIME_INTRO = compile_gated(r"^\s*(?:on|at|around|about|approximately|shortly\s+(?:before|after))\b"
                            r"(?:(?!\b(?:was|were|is|are|had|has|when|while|as|and|then)\b)[\w\s,:.\[\]]){0,80}?"
                            r"(?:\b\d{1,4}|\[XXX\]|(?:\b|\d)[ap]\.?m\.?|\b(?:P[SD]?T|C[SD]?T|E[SD]?T|M[SD]?T))\s*$", re.I)


@dataclass
class Mention:
    sent: int
    start: int
    end: int
    kind: str  # "ego", "egod", "party", "obstacle", "group"
    head: str
    category: str
    det: str  # "a", "the" or ""
    mods: str
    subject: bool
    entity: int = -1
    count: int = 1  # "two unoccupied vehicles": one mention of that many parties


@dataclass
class Entity:
    idx: int
    kind: str  # "party" or "obstacle"
    category: str
    heads: set[str]
    mentions: list[Mention] = field(default_factory=list)
    parked: bool = False
    merged_into: int | None = None
    door_of: int | None = None
    count: int = 1  # parties this entity stands for ("two unoccupied vehicles")

    @property
    def first(self) -> Mention:
        return self.mentions[0]


# Names of one operator: the first is the key.
_COMPANY_ALIASES = {"pony": "pony.ai", "baidu": "apollo", "may": "may mobility", "motional": "aptiv"}


def _company_key(name: str) -> str:
    key = " ".join(name.lower().split())
    return _COMPANY_ALIASES.get(key, key)


# "V1 (our AV)", "Vehicle 1 (the Cruise AV)", "Car 1 (AV)": a numbered label the narrative gives the AV.
_AV_LABEL = compile_gated(r"\b(?:vehicle|car|unit)\s*#?\s*([1-9])\s*\(\s*(?:the\s+|our\s+|an?\s+)?(?:[\w.-]+\s+){0,3}?"
                          r"(?:AV|ADS|autonomous\s+vehicle|test\s+vehicle|ego|self-driving\s+vehicle|vehicle|car)\s*\)",
                          re.I)


# Other spellings of the forms' numbering: "Unit 2", "Unit #2", "Veh. 2", "Veh #2", "V-2", "V#2", "Party 2".
_OTHER_LABEL = compile_gated(r"\b(?:[Uu]nit|[Vv]eh\.?|V-|V#|[Pp]arty)\s*#?\s*([1-9])\b(?!\s*(?:mph|feet|ft|%|[:.,]\d))")


def _numbered_av(t: str) -> str:
    """The OL 316 numbering: "V2" spelled "Vehicle 2", and a label defined as the AV ("Vehicle 1 (our AV)")
    replaced by "the AV" wherever the text uses it."""
    if fre.search(r"\bV[1-9]\b", t):
        t = fre.sub(r"\bV([1-9])\b", r"Vehicle \1", t)
    if _OTHER_LABEL.search(t):
        t = _OTHER_LABEL.sub(lambda m: f"Vehicle {m.group(1)}", t)
    m = _AV_LABEL.search(t)
    if m:
        t = _rename_label(t[:m.start()] + "the AV" + t[m.end():], m.group(1), "the AV")
    return t


def _rename_label(t: str, number: str, name: str) -> str:
    """Every use of the report's label "(the) Vehicle <number>" ("Car", "Unit"; not a definition in parentheses)
    replaced by `name`."""
    return fre.sub(rf"\b(?:the\s+)?(?:vehicle|car|unit)\s*#?\s*{number}\b(?!\s*\))", name, t, flags=re.I)


_FIRST_PERSON = compile_gated(r"\bour\s+(?:own\s+)?(?:vehicle|car|av|test\s+vehicle|autonomous\s+vehicle|robotaxi|"
                              r"shuttle|truck)\b|\b[Ww]e\s+were\s+(?:stopped|traveling|travelling|driving|waiting|"
                              r"proceeding|moving|slowing|turning|making|approaching|parked|in\s+the)\b", re.I)
# "we were stopped" reads "EGO was stopped"; "we" before a verb of driving is the AV.
_WE_DROVE = compile_gated(r"\b[Ww]e\s+(were)\b|\b[Ww]e\b(?=\s+(?:then\s+|had\s+|slowly\s+)?(?:stopped|proceeded|"
                          r"turned|slowed|braked|began|started|entered|merged|changed|moved|drove|accelerated|"
                          r"reversed|backed|yielded|came|pulled|continued|approached|made|attempted|waited|had\s+been)\b)")


def _squeeze(t: str) -> str:
    """Every run of white space as one space, none at the ends: `re.sub(r"\\s+", " ", t).strip()`. (`str.split`
    and `re`'s `\\s` on text both take Unicode's white space, `Py_UNICODE_ISSPACE`: the same text, without a regex
    match and a replacement for every gap between words; tested on every code point.)"""
    return " ".join(t.split())


_LABEL_WORDS = compile_gated(r"\b(vehicle|car)\s+(two|three|four)\b", re.I)


def _label_digits(t: str) -> str:
    """"Vehicle Two" as "Vehicle 2": a report's number for a party, spelled as the rules read it."""
    if not _LABEL_WORDS.search(t):
        return t
    return _LABEL_WORDS.sub(lambda m: f"{m.group(1)} {dict(two=2, three=3, four=4)[m.group(2).lower()]}", t)


# A report that names its operator and then its vehicle only as "the truck" ("TuSimple's position is ... As the truck
# was being operated on the highway ..."): that bare noun is the AV (not "the vehicle control unit", "the car's").
_COMPANY_S = compile_gated(rf"\b(?:{COMPANY_ALTERNATION})s\b", re.I)  # "TuSimples position": a possessive, unmarked
_BARE_DEFINITE_VEHICLE = compile_gated(r"\bthe\s+(vehicle|car|truck|shuttle|bus|van|suv|pod)\b(?!'s|\s+(?:control|unit|"
                                       r"system|computer|operator|driver|occupant|passenger)s?\b)", re.I)


_NAMED_BEFORE_EGO = compile_gated(r"\b([Tt]he|[Aa]n?|[Aa]nother)\s+([A-Z][a-z]{2,})\s+EGO\b")
_SENTENCE_START = compile_gated(r"(?:^|(?<=[.!?]\s)|(?<=[.!?]\s\s))\s*[a-z]")


def normalise(text: str) -> str:
    """Unify quotes/dashes, drop parenthetical definitions, name the AV `EGO` and its drivers `EGOD`."""
    # (Speed: on a text with any non-ASCII character str.translate looks every character up in its table, ~150 us
    # on a narrative. The quote table maps single non-ASCII characters to ASCII ones none of which it maps again,
    # so one str.replace per character present gives the same text; ASCII letters are counted on the UTF-8 bytes,
    # where every byte of a non-ASCII character is >= 0x80. The same results, ~20x faster.)
    quoted = text
    if not text.isascii():
        for old, new in _QUOTE_PAIRS:
            if old in quoted:
                quoted = quoted.replace(old, new)
    t = _squeeze(quoted)
    low = t.lower()
    for words, cased, rx, repl in _SPELLINGS:
        if any(w in (t if cased else low) for w in words):
            t = rx.sub(repl, t)
    t = _restore_possessives(t)
    raw = t.encode("utf-8", "surrogatepass")
    n_upper = len(raw) - len(raw.translate(None, _UPPER_BYTES))
    n_alpha = len(raw) - len(raw.translate(None, _ALPHA_BYTES))
    if n_upper > 0.6 * n_alpha:
        # all-caps narratives: case carries no information there; told again in sentence case (each sentence's first
        # letter a capital, as the sentence splitter and the rules written for prose expect)
        t = _SENTENCE_START.sub(lambda m: m.group(0).upper(), t.lower())
    ego_res, company_re = _name_patterns(_unknown_operator(t))
    # Told in the first person ("our vehicle ... behind us", "We were stopped"): looked for before the AV's names
    # are replaced, since "our AV" and "our vehicle" are among them.
    first_person = _FIRST_PERSON.search(t) is not None
    t = _numbered_av(t)
    # "An SUV (Vehicle 2) ... Vehicle 2 continued": the numbered name becomes the noun it was given to.
    # (The label alone is looked for first: a scan for a word before it tries every position of the text.)
    numbered = fre.search(r"\((?:vehicle|car|v)\s*#?\s*[2-9]\)", t, re.I) is not None
    for m in fre.finditer(r"\b(?:(?:([A-Za-z][\w-]*)\s+)?([A-Za-z][\w-]*)\s+)?([A-Za-z][\w-]*)\s*"
                          r"\((?:vehicle|car|v)\s*#?\s*([2-9])\)", t, re.I) if numbered else ():
        # "A Ford Explorer (Vehicle 2)": the make and the model name the party; the model alone is no party noun.
        # So does a noun of two or three words ("a passenger vehicle (V2) ... V2 then attempted", "a sport utility
        # vehicle (Vehicle 2)"): "the vehicle" alone is a looser name the rules may give another party (session 22:
        # with "V2" for the party's later mentions, 11 of 209 studyable narratives read differently, the party's
        # moves given to the AV or a second party made).
        two, three = f"{m.group(2)} {m.group(3)}", f"{m.group(1)} {m.group(2)} {m.group(3)}"
        head = three if three.lower() in PARTY_HEADS else two if (m.group(2) or "").lower() in MAKES or \
            two.lower() in PARTY_HEADS else m.group(3)
        # ("V2 continued to reverse": the name opens a sentence, so does its article, as the splitter expects)
        t = fre.sub(rf"(^|[.!?]\s+)?\b(?:vehicle|car|v)\s*#?\s*{m.group(4)}\b(?!\))",
                    lambda x, h=head: f"{x.group(1)}The {h}" if x.group(1) is not None else f"the {h}", t, flags=re.I)
    t = _label_digits(t)
    # "A Zoox vehicle (Vehicle 1) in autonomous mode ... Vehicle 1 applied its brakes": the number names the AV.
    one = fre.search(r"\(\s*(?:vehicle|car|v)\s*#?\s*1\s*\)", t, re.I)
    if one and company_re.search(t[max(0, one.start() - 60):one.start()]):
        t = fre.sub(r"\b(?:vehicle|car|v)\s*#?\s*1\b(?!\s*\))", "the AV", t, flags=re.I)
    alias = _ALIAS_DEF.search(t)
    if alias and not any(rx.search(alias.group(1)) for rx in ego_res) and \
            any(rx.search(t[max(0, alias.start() - 80):alias.start()]) for rx in ego_res):
        # "A Toyota Research Institute Vehicle (the 'TRI Vehicle") ... the TRI Vehicle then impacted the barrier":
        # a quoted name given right after the AV's name is the AV's, wherever the text uses it.
        t = t[:alias.end()] + fre.sub(rf"\b(?:the\s+)?{re.escape(alias.group(1))}\b", "the AV", t[alias.end():],
                                      flags=re.I)
    t = _PAREN_DEF.sub("", t)
    # The AV's operator: the company in the first name given to an AV ("On May 7 ..." names no company).
    several = len({_company_key(m.group(0)) for m in company_re.finditer(t)}) > 1  # else nothing to tell apart
    found = (rx.search(t) for rx in ego_res) if several else ()
    named = [m for m in found if m and company_re.search(m.group(0))]
    first_co = company_re.search(min(named, key=lambda m: m.start()).group(0)) if named else None
    av_company = _company_key(first_co.group(0)) if first_co else None

    def ego_or_other(m: re.Match[str]) -> str:
        # "a Lyft vehicle" or "a Waymo AV" in a Cruise report is another party: the AV is its reporter's own.
        co = company_re.search(m.group(0))
        return m.group(0) if co and av_company and _company_key(co.group(0)) != av_company else " EGO"
    for rx in ego_res:
        t = rx.sub(ego_or_other, t)
    # "crossed into the Waymo AVs lane", "the Cruise AVs front bumper": a possessive written without its apostrophe
    # (the names' plural "AVs" is read as the AV) before a noun the AV has.
    t = _EGO_BARE_POSSESSIVE.sub("EGO's", t)
    # "yielding to the other Waymo AV", "a second Waymo AV approached": another AV of the fleet is a party, a car.
    t = _OTHER_EGO.sub(r"\1 car", t)
    # "While the Wamo AV remained stopped": a misspelt operator's name before the AV's own name is the AV's; another
    # operator's, introduced as one ("A Cruise AV traveling behind the Waymo AV struck its rear"), makes another
    # party, a car (a name the AV itself is given besides its operator's, "the Pony AV", stays the AV's).
    others = {m.group(2) for m in _NAMED_BEFORE_EGO.finditer(t) if m.group(1)[0] in "Aa" and
              company_re.fullmatch(m.group(2)) and _company_key(m.group(2)) != av_company}

    def misspelt_or_other(m: re.Match[str]) -> str:
        if not company_re.fullmatch(m.group(2)):
            return "EGO"
        return f"{m.group(1)} {m.group(2)} car" if m.group(2) in others else m.group(0)
    t = _NAMED_BEFORE_EGO.sub(misspelt_or_other, t)
    # "EGO, operating in autonomous mode, was traveling": the mode dropped (above) leaves an empty aside behind, which
    # parts the AV's name from its verb; the AV's clause is told without it.
    t = _EMPTY_AV_ASIDE.sub("EGO", t)
    if first_person:
        # First-person narratives ("our vehicle ... strikes our passenger rear bumper ... behind us"); "we" is the
        # AV where it drives ("we were stopped", "we proceeded"), not the company reporting ("we are reporting").
        t = fre.sub(r"\bus\b(?!\s+(?:hwy|highway|route|\d))", "EGO", t)
        t = _WE_DROVE.sub(lambda m: "EGO was" if m.group(1) else "EGO", t)
        t = fre.sub(r"\bour\b(?=\s+(?:front|rear|passenger|driver|left|right|bumper|side|lane|vehicle's))",
                   "EGO's", t)
    # "a Navya ARMA shuttle ... the shuttle", "a Nuro Prius ... the Prius": a distinctive noun the AV was named
    # with (with its operator's name) refers to the AV afterwards.
    first_ego = _FIRST_EGO_NOUN.search(quoted)
    if first_ego and company_re.search(first_ego.group(0)):
        t = fre.sub(rf"\bthe\s+{first_ego.group(1)}\b", "EGO", t, flags=re.I)
    if not fre.search(r"\bEGO\b", t):  # ("EGOD", the AV's driver, is not the AV)
        # No name for the AV at all ("a Navya ARMA shuttle operated by Beep ... the shuttle"): the first vehicle
        # the narrative introduces is the AV, and so is that noun with "the" afterwards.
        # (the subject the narrative opens with first: "The Udelv van was stopped ...")
        first = fre.match(r"(?:the|a|an|our)\s+(?:[\w.-]+\s+){0,3}?(vehicle|car|truck|shuttle|bus|van|suv|pod|robot)\b"
                          r"(?=\s+(?:was|is|had|has|were)\b)", t, re.I) or \
            fre.search(r"\b(?:autonomous|automated|driverless|self-driving)\s+(vehicle|car|truck|shuttle|bus|van|pod)\b",
                       t, re.I) or \
            fre.search(r"\b(?:a|an)\s+(?:[\w-]+\s+){0,4}?(vehicle|car|truck|shuttle|bus|van|suv)\b", t, re.I) or \
            ((company_re.search(t) or _COMPANY_S.search(t)) and _BARE_DEFINITE_VEHICLE.search(t))
        if fre.search(r"\b(?:vehicle|car|unit)\s*#?\s*1\b", t, re.I) and \
                fre.search(r"\b(?:vehicle|car|unit)\s*#?\s*2\b", t, re.I):
            # "Vehicle 1 was stopped ... Vehicle 2 rear-ended Vehicle 1": the form's numbering, the AV first
            t = _rename_label(t, "1", "EGO")
        elif first:
            noun = first.group(1)
            t = t[:first.start()] + "EGO" + fre.sub(rf"\bthe\s+{noun}\b", "EGO", t[first.end():], flags=re.I)
    t = fre.sub(r"\bEGO(?:\s+EGO)+\b", "EGO", t)
    t = EGO_DRIVER.sub(_ego_driver, t)
    t = fre.sub(r"\bEGOD\s+of\s+EGO\b", "EGOD", t)
    t = fre.sub(r"\bEGO\s+EGOD\b", "EGOD", t)
    return _squeeze(t)


_OWNER_BEFORE = compile_gated(r"(?:\b(?:" + "|".join(re.escape(h) for h in sorted(set(PARTY_HEADS) | set(MAKES),
                                                                            key=len, reverse=True))
                           + r")(?:'s)?|\bthe\s+other(?:\s+party's)?|\btheir|\bits|\b[2-9])\s*$", re.I)


def _ego_driver(m: re.Match[str]) -> str:
    """A driver or operator is the AV's unless the text ties them to another party ("the SUV driver", "the
    driver of the Lexus")."""
    before = m.string[max(0, m.start() - 30):m.start()]
    after = m.string[m.end():m.end() + 12]
    if "EGO" not in m.group(0) and (_OWNER_BEFORE.search(before) or fre.match(r"\s+of\s+(?:the|a|an)\s", after)):
        return m.group(0)
    return " EGOD"


def sentences(text: str) -> list[str]:
    """Split on sentence ends, keeping abbreviations ("St.", "approx.") inside their sentence."""
    protected = _ABBREV.sub(lambda m: m.group(0).replace(".", "\x00"), text)
    parts = _SENT_SPLIT.split(protected)
    return [p.replace("\x00", ".").strip() for p in parts if p and p.strip()]


_KICK_SCOOTER = compile_gated(r"\b(?:electric|e|kick|stand-up|standing|rental|shared|dockless)\b", re.I)


def _category(head: str, mods: str) -> tuple[str, str]:
    h = head.lower()
    if h in ("ego",):
        return "ego", "ego"
    if h == "egod":
        return "egod", "ego"
    if h in GROUP_HEADS:
        return "group", "group"
    if h in PARTY_HEADS:
        cat = PARTY_HEADS[h]
        words = mods.lower().split()  # once, not once per model name
        if any(v in words for v in VAN_MODELS):
            cat = "van"
        elif h == "scooterist" and _KICK_SCOOTER.search(mods):
            cat = "scooter"  # "an electric scooterist", "a kick scooterist": no motor scooter
        return "party", cat
    if h in VAN_MODELS:
        return "party", "van"
    if h in MAKES:
        return "party", "car"
    return "obstacle", OBSTACLE_HEADS.get(h, "other")


# "the motorcycle operator accelerated", "the SUV driver backed up": the person driving is the party (not its
# "driver side" or "driver door").
_PARTY_DRIVER = compile_gated(r"^\s*(?:driver|operator)\b(?!'s)(?!\s*-?\s*(?:side|door|seat|window|mirror))", re.I)
_NUMBERS = {"two": 2, "2": 2, "three": 3, "3": 3, "four": 4, "4": 4}
_COUNTED_GROUPS = {"vehicles": "car", "cars": "car", "trucks": "truck", "pedestrians": "pedestrian",
                   "people": "pedestrian", "cyclists": "bicycle", "bicyclists": "bicycle", "scooters": "scooter",
                   "motorists": "car", "bikes": "bicycle", "bicycles": "bicycle", "motorcycles": "motorcycle",
                   "individuals": "pedestrian", "persons": "pedestrian", "vans": "van", "minivans": "van",
                   "suvs": "car", "sedans": "car", "buses": "bus", "pickups": "car", "pickup trucks": "car",
                   "motorcyclists": "motorcycle", "taxis": "car"}
_RIDING_ON = compile_gated(r"\s+(?:who\s+were\s+)?riding\s+(?:on\s+)?(scooters|bikes|bicycles|motorcycles)\b", re.I)


def _last_words(s: str, end: int, n: int) -> list[str]:
    """`s[:end].split()[-n:]`, reading only the tail of the text (a long sentence is split once per mention)."""
    window = 24 * n
    while True:
        start = max(0, end - window)
        words = s[start:end].split()
        if start > 0 and not s[start - 1].isspace() and words and not s[start].isspace():
            words = words[1:]  # the first word may be cut
        if len(words) >= n or start == 0:
            return words[-n:]
        window *= 2


def find_mentions(sent_idx: int, s: str) -> list[Mention]:
    """The mentions in one sentence, in order; a make directly before a head noun joins that noun phrase."""
    out: list[Mention] = []
    for m in _HEAD_RE.finditer(s):
        head = m.group(1)
        if head not in ("EGO", "EGOD") and ((m.start() > 0 and s[m.start() - 1] == "-") or
                                            s[m.end():m.end() + 1] == "-"):
            continue  # "single-car collision", "truck-mounted": a compound adjective, not a party
        after = s[m.end():m.end() + 120]  # the words right after the head (whitespace is collapsed to one space)
        hl = head.lower()
        if hl in ("it", "he", "she"):
            pre = s[max(0, m.start() - 60):m.start()]
            if _SUBJ_BEFORE.search(pre) or not s[:m.start()].strip():
                out.append(Mention(sent=sent_idx, start=m.start(), end=m.end(), kind="pron", head=hl,
                                   category="pron", det="", mods="", subject=True))
            continue
        if hl not in ("ego", "egod"):
            if _NOT_HEAD_AFTER.match(after) and not m.group(0).lower().endswith(("'s", "s'")) and \
                    not (hl in PARTY_HEADS and _PARTY_DRIVER.match(after)):
                if hl not in MAKES:
                    continue
            # Street names ("Van Ness Avenue", "Post Street"): a capitalised head followed by a street word.
            if head[0].isupper() and m.start() > 0 and _STREET_SUFFIX.match(after) and (
                    hl not in MAKES or _PLACE_PREP.search(_HEADING_WORD_END.sub("", s[max(0, m.start() - 30):m.start()]))):
                continue  # a make is a street only after a preposition of place ("east on Lincoln Way")
            if head[0].isupper() and hl in ("van", "post", "mission", "gate", "church") and m.start() > 0:
                continue
            if head[0].islower() and hl in _WORD_MODELS:
                continue  # "a truck-mounted light matrix", "in accord with": the word, not the car model
            if hl == "cab" and (_CAB_OF.search(s, max(0, m.start() - 24), m.start()) or _CAB_OF_AFTER.match(after)):
                continue  # "the driver side of the Waymo AV cab", "the cab of the truck": a truck's cab, no taxi
            if hl == "chain" and _CHAIN_OF.match(after):
                continue  # "a chain reaction", "a chain of events": no object
            if hl in ("pickup", "pick-up") and _RIDER_PICKUP.search(s[max(0, m.start() - 30):m.end() + 30]):
                continue  # "stopped for a passenger pickup": a robotaxi's errand, not a pickup truck
        if PARTY_HEADS.get(hl) == "pedestrian" and _IN_VEHICLE.match(after):
            continue  # "a person in a parked SUV opened the door": an occupant, no one on foot
        back = _last_words(s, m.start(), 5) if hl not in ("ego", "egod") else []
        mods: list[str] = []
        det = ""
        for w in reversed(back[-5:]):
            wl = w.lower().strip(",;:")
            if w.endswith((",", ";", ":")) or _STOP_BACK.match(wl):
                if wl in DETS:
                    det = DETS[wl]
                break
            if wl in DETS:
                det = DETS[wl]
                if wl in ("other", "second", "third"):
                    mods.insert(0, wl)
                    continue
                break
            mods.insert(0, wl)
        mod_text = " ".join(mods)
        if hl in ("tire", "tyre") and (det == "the" or _OWN_PART.search(mod_text)):
            continue  # "its right front tire": a part of a vehicle; "a tire in the roadway" is an object
        kind, cat = _category(head, mod_text)
        count = 1
        # ("two other postal vans": "other" after the number is no article; "the two vehicles" names ones told before)
        if kind == "group" and (not det or det == "the" and mod_text.split()[1:2] == ["other"]) and mod_text and \
                _NUMBERS.get(mod_text.split()[0]) and hl in _COUNTED_GROUPS:
            # "made contact with two unoccupied vehicles", "followed by 2 people riding on scooters": a numbered
            # group is that many parties (sketch.md counts a group only when the text numbers it).
            count, kind, cat = _NUMBERS[mod_text.split()[0]], "party", _COUNTED_GROUPS[hl]
            ride = _RIDING_ON.match(s, m.end())
            if ride:
                cat = _COUNTED_GROUPS.get(ride.group(1).lower(), cat)
        if kind in ("party", "obstacle") and _NEGATED_NP.search(s[max(0, m.start() - 40):m.start()]):
            kind = "group"  # "did not contact any vehicle": a negated mention names nobody
        # Join "Toyota Corolla", "Mercedes SUV", "Ford pickup truck": keep one mention, the last head wins.
        gap = s[out[-1].end:m.start()] if out else ""
        # "Toyota Corolla", "Mercedes SUV", and a make with a model code between: "Lexus RX 350 vehicle".
        # ... and a model named in capitalised words: "a Ford Transit van", "a Honda Odyssey minivan".
        if out and out[-1].kind in ("party",) and kind == "party" and (gap.strip() == "" or (
                out[-1].head in MAKES and (fre.fullmatch(r"\s+(?:[A-Za-z]*\d[\w-]*|[A-Z]{1,4})(?:\s+[\w-]+)?\s+", gap)
                                           or fre.fullmatch(r"\s+(?:[A-Z][a-z][\w-]*\s+){1,2}", gap)))):
            prev = out.pop()
            if prev.category == "van" and cat == "car" or hl in _GENERIC and cat == "car":
                cat = prev.category  # "a Toyota Sienna car", "an asphalt roller vehicle": the kind named first
            det, mod_text = prev.det, (prev.mods + " " + prev.head).strip()
            start = prev.start
        elif out and out[-1].kind == "obstacle" and kind == "obstacle" and gap.strip() == "":
            # "a metal railing", "a plastic crate": the last noun names the object, the first its material
            prev = out.pop()
            det, mod_text = prev.det, (prev.mods + " " + prev.head).strip()
            start = prev.start
        else:
            start = m.start() - sum(len(w) + 1 for w in mods)
        pre = s[max(0, start - 60):max(0, start)]
        pre_wo_det = _DET_END.sub("", pre)
        subject = (bool(_SUBJ_BEFORE.search(pre_wo_det)) and not _BETWEEN_AND.search(pre_wo_det)) or \
            (start <= 60 and pre_wo_det.strip() == "") or \
            (start <= 120 and bool(_TIME_INTRO.match(_DET_END.sub("", s[:max(0, start)])))) or \
            (kind in ("ego", "egod") and bool(_PROGRESSIVE_AFTER.match(s, m.end())) and
             bool(_OPEN_CLAUSE.match(s[:max(0, start)])) and not _PREPOSITION_END.search(pre_wo_det))
        out.append(Mention(sent=sent_idx, start=max(0, start), end=m.end(), kind=kind, head=hl, category=cat,
                           det=det, mods=mod_text, subject=subject, count=count))
    return out


#: Models named by a common word: a car only when capitalised ("a Honda Accord", not "a light matrix").
_WORD_MODELS = frozenset({"matrix", "accord", "civic", "genesis", "express", "quest", "caravan", "mini", "ram",
                          "voyager", "carnival", "mustang", "pacifica", "sentra", "juke"})
_IN_VEHICLE = compile_gated(r"^\s*(?:who\s+was\s+|that\s+was\s+)?(?:sitting\s+|seated\s+)?(?:in|inside)\s+(?:a|an|the)\s+"
                            r"(?:[\w-]+\s+){0,2}?(?:car|vehicle|suv|sedan|truck|van|minivan|pickup|taxi|cab|bus)\b", re.I)
_OWN_PART = compile_gated(r"\b(?:front|rear|back|left|right|driver|passenger|spare|its|their|his|her)\b", re.I)
_RIDE = compile_gated(r"^\s*(?:who\s+was\s+|that\s+was\s+)?(?:riding|on|operating|aboard)\s+(?:a|an|the|his|her|their)?"
                   r"\s*(?:[\w-]+\s+){0,2}$", re.I)
# (a model's name may follow the make the mention names: "a Ford Explorer that was parked at the curb")
_AFTER_PARKED = compile_gated(r"^(?:\s+(?-i:[A-Z])[\w-]*)?\s*,?\s*(?:that|which)?\s*(?:was|were|is|are|had\s+been|has\s+been)?\s*"
                              r"(?:(?:\w+ly|also|still|both)\s+)?(?:double[- ])?parked\b", re.I)
_GENERIC = {"vehicle", "car", "passenger vehicle", "passenger car", "private vehicle", "private car", "automobile"}
#: Names of a vehicle by who drives it, as general as "a vehicle" ("a motorist ... the passenger vehicle").
_DRIVER_NAMES = frozenset({"motorist", "agent"})
#: Role names for the other party ("the CP", "the OV"): they name whichever party the report is about, of any kind.
ROLE_HEADS = frozenset({"crash partner", "cp", "ov", "tpv", "pov", "other party", "third-party vehicle",
                        "third party vehicle"})
_BARE = {"vehicle", "car", "automobile"}  # generic heads the narratives also use for the AV
_LOCATIVE_AFTER = compile_gated(r"^\s*(?:behind|in\s+front|ahead|next\s+to|beside|to\s+the|directly|immediately|"
                             r"following|traveling|that|which|in\s+the|"
                             # ("the passenger car stopped ahead": a place, where "the vehicle stopped" tells the AV's stop)
                             r"(?:stopped|waiting|standing|parked)\s+(?:directly\s+|immediately\s+)?(?:ahead|in\s+front|"
                             r"behind|next\s+to|beside))", re.I)


# A ride told lying where it was left ("an electric scooter lying in the roadway", "a bicycle that was left on the
# ground", "a scooter on its side").
_LEFT_LYING = compile_gated(r"\s*,?\s*(?:(?:that|which)\s+(?:was|had\s+been)\s+)?(?:lying|laying|left|sitting\s+on\s+the\s+ground|"
                            r"resting\s+on|on\s+(?:its|the)\s+(?:side|ground)|knocked\s+over|tipped\s+over)\b", re.I)
#: A vehicle noun that names a toy or a model ("a remote controlled toy car", "an RC truck").
_TOY = compile_gated(r"\b(?:toy|remote[- ]controlled|remote[- ]control|rc)\b", re.I)
#: Kinds of party a summary and the telling name by the rider or the ride ("a collision involving a motorcycle ... A
#: motorcyclist then approached", "involving a pedestrian ... a man stepped off the curb"): one party, whatever noun.
_RIDER_KINDS = frozenset({"motorcycle", "bicycle", "scooter", "pedestrian"})
_RIDES = ("scooter", "bicycle", "bike", "motorcycle", "skateboard", "e-scooter", "e-bike", "moped", "motorbike",
          "motor scooter", "motorscooter", "dirt bike", "tricycle", "trike", "unicycle", "hoverboard", "segway",
          "onewheel", "wheelchair", "mobility scooter")


#: A party's number in the report's own numbering, right after its noun: "Cyclist 3", "Vehicle #2" (not "2 mph").
_NUMBER_LABEL = compile_gated(r"\s+#?([1-9])\b(?!\s*(?:mph|miles?|feet|foot|ft|meters?|m\b|seconds?|sec|s\b|%|"
                           r"inches|km|[:.,]\d))", re.I)


# A thing placed ahead as it is named ("pushing it into the passenger car ahead", "the passenger car stopped in front
# of it"): a vehicle met there, not one told before by its kind.
_PLACED_AHEAD = compile_gated(r"\s*(?:(?:stopped|waiting|standing|parked)\s+)?(?:directly\s+|immediately\s+)?"
                              r"(?:ahead|in\s+front)\b", re.I)


def _told_parked(m: Mention, sents: list[str]) -> bool:
    """Is the vehicle of mention `m` told parked as it is named ("the parked vehicle", "a passenger car parked outside
    the marked parking spaces", "an SUV that was parked")?"""
    return bool(PARKED_WORDS.search(m.mods) or _AFTER_PARKED.match(sents[m.sent][m.end:m.end + 80]))


def _compatible(e: Entity, m: Mention, sents: list[str], *, placed_ahead: bool = False) -> bool:
    if e.kind == "party" and _told_parked(m, sents) and not any(_told_parked(x, sents) for x in e.mentions):
        # "the parked vehicle", "the passenger car parked in front of the Waymo AV" is not the moving one named
        # before ("a black passenger car traveling north ... made contact"); "the parked passenger car" is the one
        # named "a passenger car parked outside the marked parking spaces"
        return False
    if e.kind == "obstacle" or m.kind == "obstacle":
        return e.kind == m.kind and (m.head in e.heads or e.category == m.category)
    if m.head in e.heads:
        return True
    if m.head in ROLE_HEADS or e.heads & ROLE_HEADS:
        return True  # "a cyclist ... the CP", "the CP ... the sedan": a role name fits a party of any kind
    mod_words = set(m.mods.split())
    if any(h in mod_words or any(w in h.split() for w in mod_words) for h in e.heads if h in MAKES or
           h in VAN_MODELS):
        return True
    if m.head in MAKES or m.head in VAN_MODELS:
        # "the Mercedes" names the party introduced as "a Mercedes car", not another make.
        named = set(e.heads) | {w for x in e.mentions for w in x.mods.split()}
        return m.head in named or any(m.head in h.split() for h in e.heads)
    if m.head in _GENERIC and m.head not in _BARE:
        # "the passenger vehicle" is not the bus named before, nor, placed ahead as it is named, a party the text
        # named by its kind only ("A pickup truck struck the rear of the Waymo AV, pushing it into the passenger car
        # ahead")
        return e.category in ("car", "van") and (not placed_ahead or any(
            h in _GENERIC or h in _DRIVER_NAMES or h in MAKES or h in VAN_MODELS for h in e.heads))
    if _names_part_of(m.head, e):
        return True  # "the truck" after "a pick-up truck": the last word of its name
    if m.head in _GENERIC or m.mods.startswith("other"):
        return e.category in ("car", "van", "truck", "bus")
    return e.category == m.category and m.category not in ("car",)


_ANOTHER_BEFORE = compile_gated(r"\banother\s*$", re.I)


_FIRST_OF_PAIR = compile_gated(r"\bfirst\b", re.I)


def _the_other_party(s: str, m: Mention) -> bool:
    """Is mention `m` of sentence `s` "the other vehicle", the party besides the AV ("The other vehicle also made
    contact with the vehicle in front of them")? Not the second of a pair the sentence opens with "the first" ("The
    first Waymo AV was preparing to make a right turn, while yielding to the other car": another AV)."""
    return m.mods.split()[:1] == ["other"] and not _FIRST_OF_PAIR.search(s, 0, m.start)


def _another(s: str, m: Mention) -> bool:
    """Is mention `m` of sentence `s` introduced as a party other than one named before ("another vehicle", "a
    second passenger car", "a third car")?"""
    return bool(_ANOTHER_BEFORE.search(s, max(0, m.start - 10), m.start)) or \
        bool({"second", "third", "other"} & set(m.mods.split()))


_CLAUSE_WORD = compile_gated(r"\b(?:when|while|as|and|but|then|before|after|until|because)\b", re.I)


def _names_part_of(head: str, e: Entity) -> bool:
    """Is `head` one word of a longer name the entity was given ("truck" of "pick-up truck", "pickup" of "pickup
    truck")? Such a noun names the same party, whose category stays the longer name's (a pickup is a car)."""
    return any(head != h and head in h.replace("-", " ").split() for h in e.heads)


_MOTOR = frozenset({"car", "van", "truck", "bus"})
# (a "then" between tells a next event, whose "the vehicle" may be the AV again: "the SUV then struck the vehicle")
_CLAUSE_GAP = compile_gated(r"[,;()]|\b(?:when|while|as|and|but|then|before|after|until|because|which|that|who)\b",
                            re.I)


def _struck_by(e: Entity, m: Mention, sents: list[str]) -> bool:
    """Is the vehicle named by `m` what vehicle `e`, the subject of the same clause, made contact with ("The other
    vehicle also made contact with the vehicle in front of them")? A clause's object is not its subject (English
    would say "itself"), however loosely the noun fits."""
    if e.category not in _MOTOR or m.category not in _MOTOR:
        return False
    s = sents[m.sent]
    return any(x.sent == m.sent and x.subject and x.end <= m.start and CONTACT.search(s, x.end, m.start) and
               not _CLAUSE_GAP.search(s, x.end, m.start) for x in e.mentions)


def _between(sents: list[str], a: Mention, b: Mention) -> str:
    """Text between two mentions of one sentence (`b.start` already includes its modifiers)."""
    return sents[a.sent][a.end:b.start] if a.sent < len(sents) else ""


# (not a verb made of a part: "EGO rear-ended the sedan", "EGO side-swiped the parked vehicle" are what it did)
_EGO_BARE_POSSESSIVE = compile_gated(r"\bEGO(?=\s+(?:lane|path|front|rear|bumper|hood|door|mirror|sensor|roof|trunk|"
                                     r"fender|tire|wheel|side|direction)\b(?![- ]?(?:end(?:ed|ing|s)?|swip\w*)\b))")


# What is left of an aside after the AV's name once its driving mode is dropped: "EGO, operating, was", "EGO,, was",
# "EGO, which was, was".
_EMPTY_AV_ASIDE = compile_gated(r"\bEGO\s*,\s*(?:(?:operating|driving|running)|(?:which|that)\s+(?:was|is))?\s*,(?=\s)")


_OTHER_EGO = compile_gated(r"\b((?:a|an|the)\s+(?:second|other|third)|another)\s+EGO\b(?!'s)", re.I)


def _loosely_named(e: Entity) -> bool:
    """Was party `e` named by no more than a vehicle or its driver ("another vehicle", "a motorist")? Such a party
    is the one a definite "the passenger vehicle" / "the passenger car" with no antecedent of its own noun means."""
    return e.kind == "party" and all(h in _BARE or h in _DRIVER_NAMES for h in e.heads)


def _introduced_later(mentions: list[Mention], e: Entity, m: Mention, summary_sents: set[int]) -> bool:
    """Does the telling introduce, after mention `m`, a party by one of summary entity `e`'s own nouns ("an SUV")?"""
    return any(x.det == "a" and x.head in e.heads and x.sent not in summary_sents and
               (x.sent, x.start) > (m.sent, m.start) for x in mentions)


def resolve(mentions: list[Mention], summary_sents: set[int], sents: list[str]) -> list[Entity]:
    """Group party/obstacle mentions into entities (coreference), in order of first mention."""
    ents: list[Entity] = []
    by_sent: dict[int, list[Mention]] = {}
    for m in mentions:
        by_sent.setdefault(m.sent, []).append(m)
    prev: Mention | None = None
    labels: dict[int, str] = {}  # entity -> its number in the report's own numbering ("Cyclist 3", "Vehicle 2")
    for m in mentions:
        if m.kind not in ("party", "obstacle"):
            prev = m
            continue
        lab = _NUMBER_LABEL.match(sents[m.sent][m.end:]) if m.kind == "party" else None
        if lab is not None:
            # "Cyclist 1 and Cyclist 2 approaching ... Cyclist 3 ... veered left": a numbered party is the one with
            # that number; once the report numbers its parties, a new number is a new party.
            same = [e for e in ents if labels.get(e.idx) == lab.group(1) and e.merged_into is None]
            # "EGO came to a stop for a vehicle ahead when Vehicle 2 made contact from behind": a number the report
            # gives a party for the first time, right after another party named in the same sentence without one,
            # names a party of its own (one named in an earlier sentence may be the one it numbers)
            # (but not an apposition, "a white SUV, Vehicle 2, ...": another clause lies between the two)
            near = [x for e in ents if e.kind == "party" and e.merged_into is None for x in e.mentions
                    if x.sent == m.sent and x.end <= m.start]
            beside = not same and not labels and m.det == "" and bool(near) and bool(_CLAUSE_WORD.search(
                sents[m.sent][max(x.end for x in near):m.start]))
            if same or labels or beside:
                target_l = same[0] if same else Entity(idx=len(ents), kind=m.kind, category=m.category,
                                                       heads={m.head}, count=m.count)
                if not same:
                    ents.append(target_l)
                    labels[target_l.idx] = lab.group(1)
                target_l.heads.add(m.head)
                m.entity = target_l.idx
                target_l.mentions.append(m)
                prev = m
                continue
        # "an individual riding a motorized scooter": the rider and the ride are one party of the ride's category.
        # ("a person in a wheelchair", "a man on a mobility scooter": one pedestrian)
        if (prev is not None and prev.sent == m.sent and prev.kind == "party" and prev.category == "pedestrian"
                and m.kind in ("party", "obstacle") and prev.entity >= 0 and m.head in _RIDES):
            e = ents[prev.entity]
            m.entity = e.idx
            e.heads.add(m.head)
            e.category = {"skateboard": "scooter"}.get(m.head, PARTY_HEADS.get(m.head, "scooter"))
            e.mentions.append(m)
            prev = m
            continue
        target: Entity | None = None
        live = [e for e in ents if e.merged_into is None]
        if m.head in _RIDES and (fre.search(r"\b(?:abandoned|unattended|dropped|fallen|parked|discarded)\b", m.mods) or
                                 _LEFT_LYING.match(sents[m.sent], m.end)):
            m.kind, m.category = "obstacle", "other"  # a scooter left lying in the road is an object
        elif m.kind == "party" and _TOY.search(m.mods):
            m.kind, m.category = "obstacle", "other"  # "a remote controlled toy car": a thing, no traffic participant
        # "The trailing vehicle is a bus": a predicate noun names the same party more precisely.
        if m.det == "a" and prev is not None and prev.sent == m.sent and prev.kind == "party" and m.kind == "party" \
                and prev.entity >= 0 and (fre.fullmatch(r"\s+(?:is|was)\s+(?:a|an)\s*", _between(sents, prev, m)) or
                                          (prev.entity in labels and fre.fullmatch(
                                              r"\s+#?[1-9]\s*,\s*(?:a|an)\s*", _between(sents, prev, m))) or
                                          (prev.head in ROLE_HEADS and fre.fullmatch(
                                              r"\s*,?\s*(?:a|an)\s*", _between(sents, prev, m)))):
            # ... and so does an appositive after a numbered party ("Vehicle 3, a pickup truck, was traveling") or a
            # role name ("The Crash Partner (CP), a cyclist, ...").
            m.det = "the"
            target = ents[prev.entity]
            target.category = m.category if m.category != "car" else target.category
        # "the curb of a traffic island median": one object named twice.
        if m.kind == "obstacle" and prev is not None and prev.kind == "obstacle" and prev.sent == m.sent and \
                prev.entity >= 0 and fre.fullmatch(r"\s*(?:of|on)\s+(?:a|an|the)?\s*", _between(sents, prev, m)):
            target = ents[prev.entity]
            target.heads.add(m.head)
            if m.category == "barrier" and target.category == "other":
                target.category = "barrier"  # (but "a fire hydrant on the curb" stays the hydrant it names first)
            m.entity = target.idx
            target.mentions.append(m)
            prev = m
            continue
        if target is not None:
            pass
        elif m.det != "a" and m.count == 1:  # ("two other postal vans": a numbered group is new, never one named)
            recent = list(reversed(sorted(live, key=lambda e: (e.mentions[-1].sent, e.mentions[-1].start))))
            if "first" in m.mods.split():
                # "A passenger car then braked to a stop ... A second passenger car then made contact with the SUV
                # and the first passenger car": "the first" is the one introduced last before "a second" (the
                # latest named is that second, or another party named again in between)
                recent = sorted((e for e in recent if not any("second" in x.mods.split() for x in e.mentions)),
                                key=lambda e: (-e.mentions[0].sent, -e.mentions[0].start))
            if m.kind == "party" and m.head not in _BARE:
                # "the passenger vehicle" repeats the noun of "a passenger vehicle": the party named so is the one
                # meant, before any other party a looser noun fits ("its lead vehicle" named in between)
                # ("involving another vehicle ... The passenger vehicle behind the Waymo AV", "a motorist entered
                # ... As the passenger car entered": the party named loosely before, not a pickup truck or a lead
                # vehicle named in between)
                # (a noun that is one word of a party's longer name fits it as well as its own: "involving a large
                # truck ... a U-Haul box truck ... The truck exited the lot" is the box truck, the one told last)
                recent.sort(key=lambda e: (m.head not in e.heads and not _names_part_of(m.head, e),
                                           m.head in _GENERIC and not _loosely_named(e)))
            for e in recent:
                if _struck_by(e, m, sents):
                    continue  # "The other vehicle also made contact with the vehicle in front of them": another
                if m.head in _GENERIC and m.sent not in summary_sents and not _the_other_party(sents[m.sent], m) and \
                        all(x.sent in summary_sents for x in e.mentions) and \
                        (m.head in _BARE or (m.head not in e.heads and not _loosely_named(e))) and \
                        not (m.head in e.heads and m.subject and
                             fre.search(r"\bEGO\b", sents[m.sent][m.end:]) is not None):
                    # A bare "the vehicle" in the telling does not reach back to the summary's party; "the
                    # passenger vehicle" after "a collision involving a passenger vehicle" does, and so does "the
                    # vehicle" after "a collision involving a vehicle" as the subject of a sentence that names the AV
                    # after it ("the vehicle approached the Waymo AV from behind"; not "the test driver transitioned
                    # the vehicle to manual mode"). "The other vehicle" names the party told before, not the AV.
                    # "The passenger vehicle" after "a collision involving another vehicle" reaches back too: a
                    # more precise noun for a party the summary named loosely.
                    continue
                if _compatible(e, m, sents, placed_ahead=bool(_PLACED_AHEAD.match(sents[m.sent], m.end))):
                    target = e
                    break
        else:
            # Opening sentences summarise ("was in a collision involving an SUV"); the same indefinite noun later
            # is the same party, told in detail.
            for e in live:
                # (by its noun, or by its category when one of the two names no more than a vehicle: "a pickup
                # truck" the AV yielded to is not the summary's SUV; "another vehicle", "a second car" is not the
                # one named before, whatever the summary named; nor is a looser noun the summary's party when the
                # telling introduces that party by the summary's own noun later: "involving an SUV ... when a
                # passenger car in the rightmost lane ... an SUV that was traveling in the leftmost lane")
                if all(x.sent in summary_sents for x in e.mentions) and m.sent not in summary_sents and \
                        not _another(sents[m.sent], m) and (
                        m.head in e.heads or (e.kind == m.kind and e.category == m.category and (
                            m.head in _GENERIC or all(h in _GENERIC for h in e.heads) or
                            m.category in _RIDER_KINDS) and not _introduced_later(mentions, e, m, summary_sents))):
                    target = e
                    break
        if target is None and m.det != "a" and m.kind == "party" and m.head in _GENERIC and \
                not _LOCATIVE_AFTER.match(sents[m.sent][m.end:]) and not m.mods and \
                not _NUMBER_LABEL.match(sents[m.sent][m.end:]):  # "Vehicle 2" is the report's second vehicle
            # "the vehicle" with nothing before it to refer to: these narratives mean the AV.
            m.kind, m.category = "ego", "ego"
            prev = m
            continue
        if target is None:
            target = Entity(idx=len(ents), kind=m.kind, category=m.category, heads={m.head}, count=m.count)
            ents.append(target)
        else:
            target.heads.add(m.head)
            if target.kind == "party" and m.kind == "party" and target.category == "car" and m.category != "car" \
                    and not _names_part_of(m.head, target):
                target.category = m.category  # "the vehicle" then "the Toyota Sienna": the specific noun wins
        m.entity = target.idx
        target.mentions.append(m)
        if lab is not None and target.idx not in labels:
            labels[target.idx] = lab.group(1)  # "An SUV (Vehicle 2) ... Vehicle 2 continued": the number names it
        prev = m
    return ents


def mark_parked(ents: list[Entity], sents: list[str]) -> None:
    for e in ents:
        if e.kind != "party" or e.category not in ("car", "van", "truck", "bus"):
            continue
        for m in e.mentions:
            if _told_parked(m, sents) or _joined_parked(ents, sents, m):
                e.parked = True


_AND_NEXT = compile_gated(r"\s+and\s+", re.I)


def _joined_parked(ents: list[Entity], sents: list[str], m: Mention) -> bool:
    """Is the party named by `m` joined by "and" to a next one that the text says was parked ("two other postal vans
    and two passenger cars that were also parked")?"""
    s = sents[m.sent]
    gap = _AND_NEXT.match(s, m.end)
    if not gap:
        return False
    nxt = next((x for e in ents for x in e.mentions if x.sent == m.sent and x.kind == "party" and
                gap.end() <= x.start <= gap.end() + 30), None)
    return nxt is not None and bool(fre.match(r"\s*,?\s*(?:that|which)\s+(?:were|are)\b", s[nxt.end:])) and \
        bool(_AFTER_PARKED.match(s[nxt.end:]))
