"""Rewrites that must not change a sketch: a measure of how the extractor holds on the way other reporters write.

Each rewrite is one a new user's reports make without changing the accident (another operator's name, a heading
abbreviated as police write it, the present tense, ...). It is applied to every studyable narrative (dev gold +
study only) that it changes, and the sketch of the rewritten text is compared with the
sketch of the original: evidence spans aside (they move with the words), and the environment aside where the rewrite
touches the time (lighting is read from it). A changed sketch is a phrasing the rules read one way and not the
other: a fault that unseen narratives will meet too, found without reading them.

    python -m tests.text.invariance            # every rewrite: narratives rewritten, sketches changed (dev sample)
    python -m tests.text.invariance --all      # the same over every studyable narrative (602; ~90 s)
    PYTHONPATH=<other checkout> python -m tests.text.invariance   # the same on other code, for a before figure

Session 9, studyable narratives, session-start code -> after: operator renamed 99/130 -> 1/130, a time told first
without a comma 20/66 -> 0/66, headings abbreviated 10/78 -> 0/78, body sides named left/right 7/63 -> 1/63, the
AV called "the robotaxi" 85/104 -> 0/104 and "the ego vehicle" 12/104 -> 0/104, "left-turn" / "lane-change"
hyphenated 22/39 -> 0/39 and 7/7 -> 0/7, "stop-sign", "red-light", "parking-lot" 26/36 -> 0/36, "on-coming"
7/20 -> 0/20, "west bound" 5/72 -> 0/72, "manoeuvre" 3/13 -> 0/13; all rewrites 520/2,095 -> 10/2,095.

Session 21, over all 602 studyable narratives (`--all`: dev gold and study, study2 .. study6) with the 16 rewrites
of NEW_REWRITES added: 218 of 33,372 rewritten narratives read differently on dbaa454; 199 once a looser noun no
longer took the summary's party the telling names later, 193 with "came to rest" / "came slowly to a stop", 190 with
an operator named without an article, 181 with "neared"; 165 of 33,276 once two rewrites that changed the meaning
were corrected (a side of the road told as a passenger side; two makes for one car); 163 with "heading" read as a
run beside a yield; 161 with "stopped completely"; 157 with "en route" and "heading" behind a vehicle. What remains
most: a new operator's name (13 of 583 per name, most from names a rename cannot carry: "a Nuro Prius", a make as
operator), a clause split at "when" (5), a passenger vehicle told "another vehicle" or "a motorist" (8, 7), "then"
dropped (4). Then (helper C2): 150 once "the passenger vehicle" / "the passenger car" reaches back to a party named
loosely before ("involving another vehicle", "a motorist entered"; those two rewrites 8 -> 6 and 7 -> 2); 147 once a
street abbreviated inside a sentence ("Market St. onto") loses its period ("Street -> St." 4 -> 1). Still open: "the
car" after "a double parked car" taken for the parked one (passenger car -> car, 4), "its lead vehicle" named between
the summary's "another vehicle" and "the passenger vehicle behind" it.

Session 22, helper C4 (C4_REWRITES: 26 families of how police, insurers, other companies and DMV form-fillers name
and describe the same things): on d8f8cdd they read 71 of 4,097 rewritten narratives differently, on top of the 147
of 33,276 above. The fixes, each by its general cause: "rear end" read as a part, not the collision kind, and "end" /
"back" as parts a move ends in (rear bumper -> rear end 16 -> 0, the rear of -> the back of 1 -> 0); a party's number
label read back as its whole noun, with a capital at a sentence's start (the party numbered V2 / Party 2 / Vehicle 2
/ Unit 2: 11 -> 0 each); "the X intersection", "the A/B intersection" read as "the intersection with/of" (10 -> 0);
a run told "traveled", "was moving", "was operating north" places the AV on a road (4 -> 1, 2 -> 1, 3 -> 2); "the
other party", "the third-party vehicle" role names for the party (42 -> 0, 5 -> 0), and the side of a truck, bus or
pickup read from the party's first naming (the other vehicle / motorist 2 -> 0, pickup truck -> pickup 3 -> 1); a
noun that is one word of a party's longer name ranked with its own (heavy truck -> large truck 2 -> 0); "private
vehicle" a passenger vehicle (3 -> 0); one rewrite corrected ("in the left lane of X" is not "in the lane on the left
of X": 4 -> 0). All held families: 147 + 71 -> 130 of 38,043 (with the session's other helpers' work).
Families with nothing to find yet: headings "in the northbound direction" / "traveling north", "at a speed of", "miles
an hour", St/Ave/Blvd/Rd without a period, "2-lane", "at approximately <time>", "On <date>, at <time>,", the AV as
"Unit 1" / "Party 1" / "the autonomous test vehicle". Still open: "a passenger vehicle -> another vehicle" (6: "another"
keeps the telling's party from the summary's, and "another sedan stopped in the right lane" loses its standing);
"passenger car -> car" (5: "a car (Vehicle 3)" read back as "the car", which the SUV named before takes); the operator
renamed (13, most not carried by a rename: "a Nuro Prius", "the May vehicle", a make as operator); "driver side ->
left side" (2: "the rear left side corner" places the party on the left); "yielded to -> stopped for" (3, H half).
Tried and dropped: "the car" ranked with the party named "a car" first whatever was named since (passenger car -> car
5 -> 1, but three other families rose and a held slot fell); "A & B" read as a junction (one studyable narrative).
"""

from __future__ import annotations

import json
import re
from collections.abc import Callable
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

from txt2sce_ros.paths import shared_dir
from txt2sce_ros.text.extractor import extract
from txt2sce_ros.text.mentions import _COMPANY_RE

REPORTS = shared_dir() / "data" / "reports"


@dataclass(frozen=True)
class Rewrite:
    name: str
    apply: Callable[[str], str]
    environment: bool = True        # compare the environment too (False: the rewrite touches the time)


def _sub(pattern: str, repl: str | Callable[[re.Match[str]], str], flags: int = 0) -> Callable[[str], str]:
    return lambda t: re.sub(pattern, repl, t, flags=flags)


def _subs(*pairs: tuple[str, str]) -> Callable[[str], str]:
    """Several substitutions of one kind of wording, applied in turn (one rewrite: each alone meets too few)."""
    def apply(t: str) -> str:
        for pattern, repl in pairs:
            t = re.sub(pattern, repl, t)
        return t
    return apply


_GERUND = {"move": "moving", "turn": "turning", "reverse": "reversing", "slow": "slowing", "proceed": "proceeding",
           "merge": "merging", "accelerate": "accelerating", "pass": "passing", "change": "changing", "make": "making",
           "enter": "entering", "cross": "crossing"}
_SIMPLE_PAST = {"traveling": "traveled", "travelling": "travelled", "driving": "drove", "proceeding": "proceeded",
                "heading": "headed"}
_DONE = {"reverse": "reversed", "proceed": "proceeded", "move": "moved", "accelerate": "accelerated",
         "slow": "slowed", "merge": "merged", "pass": "passed", "back up": "backed up"}
_HAVING = {"completing": "completed", "making": "made", "turning": "turned"}


def _after_having(t: str) -> str:
    """"After completing a right turn" -> "After having completed a right turn"; "After the Waymo AV made a right
    turn" -> "After the Waymo AV had made a right turn"."""
    t = re.sub(r"\b([Aa])fter (completing|making|turning)\b", lambda m: f"{m.group(1)}fter having {_HAVING[m.group(2)]}", t)
    return re.sub(r"\b([Aa])fter (the \w+ AV|it) (made|completed|turned)\b", r"\1fter \2 had \3", t)


def _operator(new: str) -> Callable[[str], str]:
    """The first known operator named in the text, everywhere, renamed to `new`."""
    def apply(t: str) -> str:
        m = _COMPANY_RE.search(t)
        return re.sub(rf"\b{re.escape(m.group(0))}\b", new, t) if m else t
    return apply


def _time_first(t: str) -> str:
    return "On June 3, 2025 at 4:10 PM " + t[0].lower() + t[1:] if t.startswith(("A ", "An ", "The ")) else t


def _our_vehicle(t: str) -> str:
    m = _COMPANY_RE.search(t)
    if not m:
        return t
    return re.sub(rf"\b([Tt])he {re.escape(m.group(0))} (?:AV|vehicle|autonomous vehicle)\b",
                  lambda x: ("O" if x.group(1) == "T" else "o") + "ur vehicle", t)


def _later_name(name: str) -> Callable[[str], str]:
    """After its introduction, the AV called "the <name>" where the text said "the <operator> AV"."""
    def apply(t: str) -> str:
        m = _COMPANY_RE.search(t)
        if not m:
            return t
        return re.sub(rf"\b([Tt])he {re.escape(m.group(0))} (?:AV|vehicle|autonomous vehicle)\b",
                      lambda x: x.group(1) + "he " + name, t)
    return apply


_BODY_PART = (r"(?:(?:front|rear|left|right|driver(?:'s)?|passenger(?:'s)?)[ -]){1,3}(?:side|bumper|door|fender|corner|"
              r"quarter panel|mirror|wheel)")

def _make_model(t: str) -> str:
    """The party's noun replaced by a make and model everywhere, where the narrative names one kind of party only
    (two nouns given two makes would be two cars; session 21: the rewrite used to leave "(Vehicle 2)"'s noun and
    give "a passenger car" and "the passenger vehicle" two makes), "an SUV" -> "a Ford Explorer"."""
    nouns = {m.group(1) for m in re.finditer(rf"\b({'|'.join(_MAKE_MODEL)})\b", t)}
    if len(nouns) != 1 or re.search(r"\b(?:pick-?up|pick up)\b", t, re.I):
        return t
    noun = nouns.pop()
    t = re.sub(rf"\b([Aa])n ({noun})\b", r"\1 \2", t)
    return re.sub(rf"\b{noun}\b", _MAKE_MODEL[noun], t)


#: Not a side of the road: "the right side of the street", "of southwestbound [XXX]".
_NOT_OF_ROAD = (r"(?!\s+of\s+(?:the\s+)?(?:\w+bound\s+)?(?:road|roadway|street|lane|highway|freeway|ramp|"
                r"intersection|driveway|lot|parking|curb|\[XXX\]|[A-Z]\w*\s+(?:Street|Avenue|Road|Boulevard|Drive)))")

#: Makes and models for the party's usual nouns (a new user's narratives name parties so).
_MAKE_MODEL = {"passenger car": "Toyota Camry", "passenger vehicle": "Honda Accord", "sedan": "Nissan Altima",
               "SUV": "Ford Explorer", "pickup truck": "Ford F-150"}


REWRITES: tuple[Rewrite, ...] = (
    Rewrite("operator renamed: Acme", _operator("Acme")),
    Rewrite("operator renamed: Avride", _operator("Avride")),
    Rewrite("operator renamed: Oxa Robotics", _operator("Oxa Robotics")),
    Rewrite("time told first, no comma", _time_first, environment=False),
    Rewrite("headings abbreviated (NB, SB)",
            _sub(r"\b(north|south|east|west)bound\b", lambda m: m.group(1)[0].upper() + "B", re.I)),
    Rewrite("driver side -> left side", _sub(r"\bdriver(?:'s)? side\b", "left side")),
    Rewrite("passenger side -> right side", _sub(r"\bpassenger side\b", "right side")),
    Rewrite("passenger side -> passenger's side", _sub(r"\bpassenger side\b", "passenger's side")),
    Rewrite("the <operator> AV -> our vehicle", _our_vehicle),
    *(Rewrite(f"the <operator> AV -> the {n}", _later_name(n))
      for n in ("ego vehicle", "robotaxi", "SV", "subject vehicle", "test vehicle", "ADS-equipped vehicle")),
    Rewrite("made contact with -> collided with", _sub(r"\bmade contact with\b", "collided with")),
    Rewrite("made contact with -> struck", _sub(r"\bmade contact with\b", "struck")),
    Rewrite("was traveling -> was proceeding", _sub(r"\bwas traveling\b", "was proceeding")),
    Rewrite("approximately -> about", _sub(r"\bapproximately\b", "about")),
    Rewrite("SUV -> sport utility vehicle", lambda t: re.sub(r"\bSUV\b", "sport utility vehicle",
                                                             re.sub(r"\b([Aa])n SUV\b", r"\1 SUV", t))),
    Rewrite("cyclist -> bicyclist", _sub(r"\bcyclist\b", "bicyclist")),
    Rewrite("Street -> St.", _sub(r"\b(Street|Avenue|Boulevard)\b(?!\.)",
                                  lambda m: {"Street": "St.", "Avenue": "Ave.", "Boulevard": "Blvd."}[m.group(1)])),
    Rewrite("', when a' -> '. Then a'", _sub(r",? when (a|an|the) ", r". Then \1 ")),
    Rewrite("left turn -> left-turn", _sub(r"\b(left|right) turn\b", r"\1-turn")),
    Rewrite("lane change -> lane-change", _sub(r"\blane change\b", "lane-change")),
    Rewrite("stop sign, red light, parking lot hyphenated", _sub(r"\b(stop|red|parking) (sign|light|lot)\b", r"\1-\2")),
    Rewrite("oncoming -> on-coming", _sub(r"\boncoming\b", "on-coming")),
    Rewrite("rightmost -> right-most", _sub(r"\b(left|right)most\b", r"\1-most")),
    Rewrite("westbound -> west bound", _sub(r"\b(north|south|east|west)bound\b", r"\1 bound")),
    Rewrite("making a left turn -> turning left", _sub(r"\bmaking a (left|right) turn\b", r"turning \1")),
    Rewrite("reversed -> backed up", _sub(r"\breversed\b", "backed up")),
    Rewrite("braked -> applied the brakes", _sub(r"\bbraked\b", "applied the brakes")),
    Rewrite("began to proceed -> started to move", _sub(r"\bbegan to proceed\b", "started to move")),
    Rewrite("maneuver -> manoeuvre (British spelling)",
            _sub(r"\bmaneuver(ing|ed|s)?\b", lambda m: {None: "manoeuvre", "ing": "manoeuvring", "ed": "manoeuvred",
                                                       "s": "manoeuvres"}[m.group(1)])),
    # Session 10: paraphrases of manoeuvres, speeds, times and parties that reports use interchangeably.
    Rewrite("turned/turning left -> made/making a left turn",
            _sub(r"\bturn(ed|ing) (left|right)\b", lambda m: ("made" if m.group(1) == "ed" else "making")
                 + f" a {m.group(2)} turn")),
    Rewrite("was traveling -> was driving", _sub(r"\bwas traveling\b", "was driving")),
    Rewrite("traveling <dir>bound -> heading <dir>", _sub(r"\btraveling (north|south|east|west)bound\b",
                                                          r"heading \1")),
    Rewrite("MPH -> miles per hour", _sub(r"\b(\d+) ?(?:MPH|mph)\b", r"\1 miles per hour")),
    Rewrite("12-hour clock -> 24-hour clock", _sub(r"\b(1[0-2]|[1-9]):([0-5]\d) ?([AP])\.?M\.?", lambda m: (
        f"{(int(m.group(1)) % 12) + (12 if m.group(3) == 'P' else 0):02d}:{m.group(2)}")), environment=False),
    Rewrite("a pedestrian -> a person on foot", _sub(r"\b([Aa]) pedestrian\b", r"\1 person on foot")),
    Rewrite("passenger vehicle -> passenger car", _sub(r"\bpassenger vehicle\b", "passenger car")),
    Rewrite("struck -> hit", _sub(r"\bstruck\b", "hit")),
    Rewrite("was stopped -> was stationary", _sub(r"\bwas stopped\b", "was stationary")),
    Rewrite("boilerplate appended", lambda t: t.rstrip() + " Both vehicles sustained minor damage. No injuries were "
                                                         "reported and the police were not called to the scene."),
    # Session 11: where the AV was touched told the other way round, lane and junction synonyms, a standstill told
    # as a halt, headings told with a verb, passives, and words reports use interchangeably.
    Rewrite("the <part> of the AV -> the AV's <part>", _sub(
        rf"\bthe ({_BODY_PART}) of the ((?:\w+ ){{0,2}}?(?:AV|vehicle))\b",
        lambda m: f"the {m.group(2)}'s {m.group(1)}")),
    Rewrite("the AV's <part> -> the <part> of the AV", _sub(
        rf"\bthe ((?:Waymo|Cruise|Zoox) (?:AV|vehicle))(?:'s|\u2019s) ({_BODY_PART})", r"the \2 of the \1")),
    Rewrite("driver side -> driver's side", _sub(r"\bdriver side\b", "driver's side")),
    Rewrite("left lane -> left-hand lane", _sub(r"\b(left|right) lane\b", r"\1-hand lane")),
    Rewrite("adjacent lane -> neighboring lane", _sub(r"\badjacent lane\b", "neighboring lane")),
    Rewrite("intersection -> junction", _sub(r"\bintersection\b", "junction")),
    Rewrite("stopped -> halted", _sub(r"\bstopped\b", "halted")),
    Rewrite("came to a stop -> stopped", _sub(r"\bcame to a (?:complete )?stop\b", "stopped")),
    Rewrite("attempted to -> tried to", _sub(r"\battempted to\b", "tried to")),
    Rewrite("Shortly thereafter -> Moments later", _sub(r"\bShortly (?:thereafter|after)\b", "Moments later")),
    Rewrite("made contact with -> came into contact with", _sub(r"\bmade contact with\b", "came into contact with")),
    Rewrite("SUV -> sedan", _sub(r"\bSUV\b", "sedan")),
    Rewrite("passenger car -> sedan", _sub(r"\bpassenger (?:car|vehicle)\b", "sedan")),
    Rewrite("'At the time of the impact ...' dropped", _sub(r"At the time of the impact[^.]*\.\s*", "")),
    Rewrite("a/the vehicle -> a/the car", _sub(r"\b(a|the) (white |black |silver )?vehicle\b", r"\1 \2car")),
    Rewrite("traveling -> travelling", _sub(r"\btraveling\b", "travelling")),
    Rewrite("was stopped -> was at a standstill", _sub(r"\bwas stopped\b", "was at a standstill")),
    Rewrite("approximately -> roughly", _sub(r"\bapproximately\b", "roughly")),
    Rewrite("(bi)cyclist -> bike rider", _sub(r"\b(?:bi)?cyclist\b", "bike rider")),
    Rewrite("struck -> impacted", _sub(r"\bstruck\b", "impacted")),
    Rewrite("when -> as", _sub(r"\bwhen\b", "as")),
    Rewrite("'then' dropped", _sub(r"\bthen ", "")),
    Rewrite("the Waymo AV -> Waymo's vehicle", _sub(r"\b[Tt]he Waymo AV\b", "Waymo's vehicle")),
    Rewrite("the <operator> AV -> the AV", _sub(r"\b([Tt])he (?:Waymo|Cruise|Zoox) (?:AV|vehicle)\b", r"\1he AV")),
    Rewrite("northbound -> north-bound", _sub(r"\b(north|south|east|west)bound\b", r"\1-bound")),
    Rewrite("traveling <dir>bound -> going <dir>", _sub(r"\btraveling (north|south|east|west)bound\b", r"going \1")),
    Rewrite("yielded -> gave way", _sub(r"\byielded\b", "gave way")),
    Rewrite("slowed/decelerated -> reduced speed", _sub(r"\b(?:decelerated|slowed down|slowed)\b", "reduced speed")),
    Rewrite("pickup truck -> pickup", _sub(r"\bpickup truck\b", "pickup")),
    Rewrite("<side> lane -> <side> traffic lane",
            _sub(r"\b(left|right|center|middle|adjacent) lane\b", r"\1 traffic lane")),
    Rewrite("in autonomous mode -> in self-driving mode", _sub(r"\bin autonomous mode\b", "in self-driving mode")),
    Rewrite("made contact with -> contacted", _sub(r"\bmade contact with\b", "contacted")),
    Rewrite("a passenger vehicle -> a motorist", _sub(r"\b([Aa]) passenger (?:vehicle|car)\b", r"\1 motorist")),
    Rewrite("front bumper -> front end", _sub(r"\bfront bumper\b", "front end")),
    # (a vehicle's side only: "the right side of the road" has no passenger side)
    Rewrite("left side -> driver side", _sub(rf"\bleft side\b{_NOT_OF_ROAD}", "driver side")),
    Rewrite("right side -> passenger side", _sub(rf"\bright side\b{_NOT_OF_ROAD}", "passenger side")),
    Rewrite("behind the AV -> to the rear of the AV",
            _sub(r"\bbehind the ((?:Waymo |Cruise |Zoox )?(?:AV|vehicle))\b", r"to the rear of the \1")),
    Rewrite("green/red light -> green/red signal", _sub(r"\b(green|red) light\b", r"\1 signal")),
    Rewrite("the test driver -> the safety driver", _sub(r"\bthe test driver\b", "the safety driver")),
    Rewrite("manual mode -> conventional mode", _sub(r"\bmanual mode\b", "conventional mode")),
    # (a bare "scooterist" rides a motor scooter, a moped: a motorcycle in 2 of the 3 studyable gold sketches that
    # name one, while a "scooter" is a scooter in all 6; so each kind is rewritten to its own synonym)
    Rewrite("scooterist -> electric scooter rider / moped rider",
            _sub(r"\b(electric |motor )?scooterist\b",
                 lambda m: {"electric ": "electric scooter rider", "motor ": "motor scooter rider"}.get(
                     (m.group(1) or "").lower(), "moped rider"))),
    Rewrite("heavy truck -> large truck", _sub(r"\bheavy truck\b", "large truck")),
    Rewrite("began to -> started to", _sub(r"\bbegan to\b", "started to")),
    Rewrite("parked car -> parallel-parked car", _sub(r"\bparked (car|vehicle)\b", r"parallel-parked \1")),
    Rewrite("double-parked -> double parked", _sub(r"\bdouble-parked\b", "double parked")),
    Rewrite("mph -> MPH", _sub(r"\bmph\b", "MPH")),
    Rewrite("proceeded -> continued", _sub(r"\bproceeded\b", "continued")),
    # Session 12: a party by its make and model, compass words other operators use, other names for the AV.
    Rewrite("a party named by make and model", _make_model),
    Rewrite("traveling <dir>bound -> traveling in a <dir>erly direction",
            _sub(r"\btraveling (north|south|east|west)bound\b", r"traveling in a \1erly direction")),
    Rewrite("traveling <dir>bound -> heading in a <dir>erly direction",
            _sub(r"\btraveling (north|south|east|west)bound\b", r"heading in a \1erly direction")),
    Rewrite("<dir>bound -> <dir>ward", _sub(r"\b(north|south|east|west)bound\b", r"\1ward")),
    Rewrite("was traveling -> had been traveling", _sub(r"\bwas traveling\b", "had been traveling")),
    Rewrite("came to a stop -> came to rest", _sub(r"\bcame to a (?:complete )?stop\b", "came to rest")),
    Rewrite("the <operator> AV -> the autonomous vehicle",
            _sub(r"\b([Tt])he (?:Waymo|Cruise|Zoox) (?:AV|vehicle)\b", r"\1he autonomous vehicle")),
    Rewrite("the <operator> AV -> the robotaxi", _sub(r"\b([Tt])he (?:Waymo|Cruise|Zoox) (?:AV|vehicle)\b", r"\1he robotaxi")),
    # (not before "of": "in the left lane of traffic" told "in the lane on the left of traffic" places the lane by
    # traffic's side; session 22 corrected the measure: 2 of its 4 changed narratives were so rewritten)
    Rewrite("in the <side> lane -> in the lane on the <side>",
            _sub(r"\bin the (left|right) lane\b(?! of\b)", r"in the lane on the \1")),
    Rewrite("made contact with -> impacted", _sub(r"\bmade contact with\b", "impacted")),
    Rewrite("lane of travel -> lane", _sub(r"\blane of travel\b", "lane")),
    Rewrite("proceeding -> moving", _sub(r"\bproceeding\b", "moving")),
    Rewrite("stationary -> stopped", _sub(r"\bstationary\b", "stopped")),
    Rewrite("behind the AV -> in back of the AV",
            _sub(r"\bbehind (the (?:Waymo |Cruise |Zoox )?(?:AV|vehicle))\b", r"in back of \1")),
    Rewrite("turn <side> -> turn to the <side>",
            _sub(r"\bturn(ed|ing)? (left|right)\b", lambda m: f"turn{m.group(1) or ''} to the {m.group(2)}")),
    Rewrite("approaching -> nearing", _sub(r"\bapproaching\b", "nearing")),
    Rewrite("intersection -> crossroads", _sub(r"\bintersection\b", "crossroads")),
    Rewrite("at a red light -> for a red light", _sub(r"\bat a red light\b", "for a red light")),
    Rewrite("on the <side> -> on the <side>-hand side", _sub(r"\bon the (left|right)\b(?! (?:side|of|lane))", r"on the \1-hand side")),
    Rewrite("entered the intersection -> drove into the intersection",
            _sub(r"\bentered the intersection\b", "drove into the intersection")),
    Rewrite("an oncoming <party> -> a <party> approaching from the opposite direction", _sub(
        r"\b(an|the) oncoming (vehicle|car|truck|pickup truck|passenger vehicle|bus|cyclist|bicyclist|SUV|sedan)\b",
        lambda m: ("a" if m.group(1) == "an" else m.group(1)) + f" {m.group(2)} approaching from the opposite direction")),
    Rewrite("traveling -> driving (every use)", _sub(r"\btraveling\b", "driving")),
    Rewrite("passenger vehicle -> private vehicle", _sub(r"\bpassenger vehicle\b", "private vehicle")),
    Rewrite("in the same direction -> in the same direction of travel",
            _sub(r"\bin the same direction\b", "in the same direction of travel")),
    Rewrite("approached from behind -> came up from behind", _sub(
        r"\bapproach(ed|ing) from (behind|the rear)\b", lambda m: ("came" if m.group(1) == "ed" else "coming") +
        " up from " + m.group(2))),
    Rewrite("directly behind -> immediately behind", _sub(r"\bdirectly behind\b", "immediately behind")),
    Rewrite("traveling behind the AV -> following the AV",
            _sub(r"\b(?:traveling|driving) behind (the (?:Waymo |Cruise |Zoox )?(?:AV|vehicle))\b", r"following \1")),
    Rewrite("rear bumper -> back bumper", _sub(r"\brear bumper\b", "back bumper")),
    Rewrite("the front of the AV -> the AV's front end",
            _sub(r"\bthe front of (the (?:Waymo |Cruise |Zoox )?(?:AV|vehicle))\b", r"\1's front end")),
    Rewrite("oncoming lane -> opposing lane", _sub(r"\boncoming (traffic )?lane\b", "opposing lane")),
    Rewrite("from the <side> -> from the AV's <side>",
            _sub(r"\bfrom the (left|right)\b(?! (?:side|lane|turn))", r"from the AV's \1")),
    Rewrite("a passenger vehicle -> another vehicle", _sub(r"\ba passenger vehicle\b", "another vehicle")),
    Rewrite("came to a stop behind -> stopped behind", _sub(r"\bcame to a (?:complete )?stop behind\b", "stopped behind")),
    Rewrite("a <party> -> a white <party>", _sub(
        r"\b([Aa]) (passenger vehicle|passenger car|sedan|SUV|pickup truck|box truck|van)\b", r"\1 white \2")),
    Rewrite("was traveling -> was traveling at approximately 20 mph",
            _sub(r"\bwas traveling\b(?! at)", "was traveling at approximately 20 mph")),
    Rewrite("the AV's quoted short name dropped", _sub(r"\s*\((?:\u201c|\")[^)]*?(?:\u201d|\")\)", "")),
    Rewrite("a sedan/SUV -> a 2019 sedan/SUV", _sub(r"\b([Aa]) (sedan|SUV)\b", r"\1 2019 \2")),
    Rewrite("At the time of the impact -> At the time of the collision",
            _sub(r"\bAt the time of the impact\b", "At the time of the collision")),
    Rewrite("there were no injuries -> no one was hurt", _sub(r"\b[Tt]here were no (?:reported )?injuries\b", "no one was hurt")),
    Rewrite("police were not called -> no police report was made",
            _sub(r"\bpolice were not called\b", "no police report was made")),
    Rewrite("autonomous mode -> autonomous driving mode", _sub(r"\bautonomous mode\b", "autonomous driving mode")),
    Rewrite("the Cruise AV -> the Cruise vehicle", _sub(r"\bCruise AV\b", "Cruise vehicle")),
    Rewrite("Zoox vehicle -> Zoox robotaxi", _sub(r"\bZoox vehicle\b", "Zoox robotaxi")),
    Rewrite("test driver -> vehicle operator", _sub(r"\btest driver\b", "vehicle operator")),
    Rewrite("the <side> lane -> the far <side> lane", _sub(r"\bthe (left|right) lane\b", r"the far \1 lane")),
    Rewrite("the opening date and time dropped", _sub(
        r"^On [A-Z][a-z]+ \d{1,2}(?:st|nd|rd|th)?, \d{4}(?: at [\d:]+ ?[AP]\.?M\.?(?: [A-Z]{2,3})?)?,? ", ""),
            environment=False),
    Rewrite("red light -> red traffic light", _sub(r"\bred light\b", "red traffic light")),
    Rewrite("green light -> green traffic signal", _sub(r"\bgreen light\b", "green traffic signal")),
    Rewrite("pedestrian -> ped", _sub(r"\bpedestrian\b", "ped")),
    Rewrite("San Francisco -> SF", _sub(r"\bSan Francisco\b", "SF")),
    Rewrite("a stop sign -> a posted stop sign", _sub(r"\ba stop sign\b", "a posted stop sign")),
    Rewrite("the Waymo AV -> the Waymo AV, in autonomous mode, (an aside after its name)",
            lambda t: re.sub(r"\b(The Waymo AV) (was|had)\b", r"\1, in autonomous mode, \2", t, count=1)),
    # Session 12: the AV's own start and actions (the readings of sequences.ego_sequence and actions.find_acts),
    # each rewrite told as another operator would tell the same moves.
    Rewrite("after completing a turn -> after having completed it", _after_having),
    Rewrite("the AV's stop words (came to a halt, pulled up behind, would have stopped)",
            _subs((r"\bcame to a stop\b", "came to a halt"), (r"\bpulled behind\b", "pulled up behind"),
                  (r"\bwould have come to a (?:full |complete )?stop\b", "would have stopped"))),
    Rewrite("', yielding to' <-> ' while yielding to'", _sub(r"(, | while )yielding to\b",
                                                             lambda m: (" while " if m.group(1) == ", " else ", ")
                                                             + "yielding to")),
    Rewrite("disengaged (from) autonomous mode -> transitioned to manual mode",
            _sub(r"\bdisengaged (?:the (?:\w+ )?AV )?(?:from )?(?:autonomous mode|autonomy)\b", "transitioned to manual mode")),
    Rewrite("As the AV -> Just as the AV", _sub(r"\bAs the (\w+) AV\b", r"Just as the \1 AV")),
    Rewrite("the AV's way off the road (turning into a driveway or lot, parallel-parking)",
            _subs((r"\b(?:pulling into|entering) (a|the) (driveway|parking lot)\b", r"turning into \1 \2"),
                  (r"\bparallel parking\b", "parallel-parking"))),
    Rewrite("slowed to a stop -> slowed to stop",
            _sub(r"\b(slowed|slowing|braked|braking|decelerated) to a (?:complete )?stop\b", r"\1 to stop")),
    Rewrite("a stop behind a standing vehicle (complete stop, ', which was stopped')",
            _subs((r"\bcame to a stop behind\b", "came to a complete stop behind"),
                  (r"(?<!,) that was stopped\b", ", which was stopped"))),
    Rewrite("yielded to -> stopped for", _sub(r"\byielded to\b", "stopped for")),
    Rewrite("was stopped -> was waiting", _sub(r"\bwas stopped\b", "was waiting")),
    Rewrite("began to accelerate -> started accelerating / began to move -> started moving",
            _subs((r"\bbegan to accelerate\b", "started accelerating"), (r"\bbegan to move\b", "started moving"),
                  (r"\bbegan to proceed\b", "started proceeding"))),
    # Session 15 (issue 13): the AV's standstill told with other verbs of staying put (unattested in the studyable
    # narratives, so a rule written from them alone missed them).
    Rewrite("remained stopped -> stayed stopped", _sub(r"\bremained (stopped|stationary)\b", r"stayed \1")),
    Rewrite("the AV was stopped -> the AV was sitting", _sub(r"\b(AV|vehicle) was stopped\b", r"\1 was sitting")),
    Rewrite("', when a' -> ', at which time a'", _sub(r", when (a|an|the) ", r", at which time \1 ")),
    Rewrite("The <operator> AV was (second sentence on) -> It was",
            lambda t: re.sub(r"(?<=\. )The (?:Waymo|Cruise|Zoox) (?:AV|vehicle) (was|had)\b", r"It \1", t, count=1)),
    # Session 16 (issue 13): the same moves told in the simple past, and begun moves told as done (another
    # reporter's habit; 2 + 4 of the 379 studyable narratives so rewritten read differently on fa444a1).
    Rewrite("was traveling -> traveled (the simple past)",
            _sub(r"\b(?:was|were) (traveling|travelling|driving|proceeding|heading)\b",
                 lambda m: _SIMPLE_PAST[m.group(1)])),
    Rewrite("passed -> went past", _sub(r"\bpassed\b", "went past")),
    Rewrite("was stopped -> had stopped", _sub(r"\bwas stopped\b", "had stopped")),
    Rewrite("was stopped -> had come to a stop", _sub(r"\bwas stopped\b", "had come to a stop")),
    Rewrite("approached -> neared", _sub(r"\bapproached\b", "neared")),
    Rewrite("at a red light -> at a light that was red", _sub(r"\bat a red light\b", "at a light that was red")),
    Rewrite("at the intersection of -> at the corner of", _sub(r"\bat the intersection of\b", "at the corner of")),
    Rewrite("came to a stop -> came slowly to a stop", _sub(r"\bcame to a stop\b", "came slowly to a stop")),
    Rewrite("turned left/right -> turned sharply left/right",
            _sub(r"\b(turned|turning|turns) (left|right)\b", r"\1 sharply \2")),
    Rewrite("proceeded forward -> proceeded slowly forward", _sub(r"\bproceeded forward\b", "proceeded slowly forward")),
    Rewrite("slowed to a stop -> slowed gradually to a stop",
            _sub(r"\b(slowed|braked|decelerated) to a stop\b", r"\1 gradually to a stop")),
    Rewrite("was traveling -> had been traveling", _sub(r"\bwas traveling\b", "had been traveling")),
    Rewrite("began to <move> -> began <moving>",
            _sub(r"\b(began|started) to (move|turn|reverse|slow|proceed|merge|accelerate|pass|change|make|enter|cross)\b",
                 lambda m: f"{m.group(1)} {_GERUND[m.group(2)]}")),
    # Session 18: the AV's (and a party's) run told by other verbs of going, or by its heading alone (over all 379
    # studyable narratives, each of these changed the AV's start or string in 10 to 21 on 78babff).
    Rewrite("was traveling <dir> -> was operating <dir>", _sub(r"\bwas traveling (?=(?:north|south|east|west))",
                                                                "was operating ")),
    Rewrite("was traveling -> was en route", _sub(r"\bwas traveling\b", "was en route")),
    Rewrite("was traveling <dir>bound -> was <dir>bound", _sub(r"\bwas traveling (?=(?:north|south|east|west)\w*bound)",
                                                               "was ")),
    # Session 18: the AV's standing told in other words (over all 379 studyable narratives, "was idling" changed the
    # AV's road in 2, "was at a stop" its road or signal in 5, "had been stopped" 1, "stopped completely" its string
    # in 3, on 78babff; "was idling in traffic" was no queue, "at a stop at a red light" no standing at the red).
    Rewrite("was stopped -> was idling", _sub(r"\bwas stopped\b", "was idling")),
    Rewrite("was stopped -> was at a stop", _sub(r"\bwas stopped\b", "was at a stop")),
    Rewrite("came to a stop -> stopped completely", _sub(r"\bcame to a stop\b", "stopped completely")),
    # Session 18: a light and a place told in police shorthand ("at a red", "close to Y"; over all 379 studyable
    # narratives these changed the road or signal in 14 and 4 on 78babff).
    Rewrite("at a red light -> at a red", _sub(r"\bat a red light\b", "at a red")),
    Rewrite("on X near Y -> on X close to Y", _sub(r"\b(on (?:\[XXX\]|[A-Z]\w+ (?:Street|Avenue|Boulevard))) near\b",
                                                   r"\1 close to")),
    # ("yielding to" -> "waiting for": 9 of 38 AV strings changed on the session's start code, 4 after; left out of
    # this list: "before waiting for a pedestrian" is no stop as "before yielding to" is, and "while waiting" after
    # "stopped at a stop sign" no longer tells the stop's moment; those readings stay "yielding"'s own.)
    Rewrite("began to <move> -> <moved>",
            _sub(r"\b(?:began|started) to (reverse|proceed|move|accelerate|slow|merge|pass|back up)\b(?!\s+and\s)",
                 lambda m: _DONE[m.group(1)])),
)


_NUMBER_WORD = {1: "one", 2: "two", 3: "three", 4: "four", 5: "five", 6: "six", 7: "seven", 8: "eight", 9: "nine",
                10: "ten", 11: "eleven", 12: "twelve", 15: "fifteen", 20: "twenty", 25: "twenty-five", 30: "thirty"}
_AV_NAME = r"\b([Tt])he (?:Waymo|Cruise|Zoox) (?:AV|vehicle)\b"


def _active_struck(t: str) -> str:
    """"a car struck the AV" -> "a car made contact with the AV"; a passive ("was (previously) struck") kept."""
    return re.sub(r"\b((?:was|were|been|being|is|are|be|get|got)(?: \w+ly)? )?struck\b",
                  lambda m: m.group(0) if m.group(1) else "made contact with", t)


def _speed_in_words(t: str) -> str:
    """"approximately 5 mph" -> "about five miles per hour" (the speeds police spell out)."""
    return re.sub(r"\b(?:approximately|about) (\d{1,2}) ?(?:mph|MPH)\b",
                  lambda m: (f"about {_NUMBER_WORD[int(m.group(1))]} miles per hour" if int(m.group(1)) in _NUMBER_WORD
                             else m.group(0)), t)


def _numbered_av(name: str) -> Callable[[str], str]:
    """The AV called by a police report's number for it ("V1", "Vehicle 1"), where the text numbers no vehicle."""
    def apply(t: str) -> str:
        if re.search(r"\b(?:V|Vehicle |vehicle |Veh\.? ?|Unit |#)\d\b|\bV-\d\b", t):
            return t
        return re.sub(_AV_NAME, name, t)
    return apply


_PARTY_NOUN = r"(?:passenger car|passenger vehicle|sedan|SUV|pickup truck|box truck|van|motorcycle|bus)"


def _party_numbered(t: str) -> str:
    """"a passenger car traveling ..." -> "a passenger car (V2) traveling ...": a parenthetical after the first
    party named with an article, where the text numbers no vehicle."""
    if re.search(r"\bV\d\b|\b[Vv]ehicle \d\b", t):
        return t
    return re.sub(rf"\b([Aa]n?) ({_PARTY_NOUN})\b(?! \()", r"\1 \2 (V2)", t, count=1)


def _party_described(t: str) -> str:
    """"a passenger car traveling ..." -> "a passenger car (a gray 2018 Honda) traveling ...": a description in
    parentheses after the first party named with an article."""
    return re.sub(rf"\b([Aa]n?) ({_PARTY_NOUN})\b(?! \()", r"\1 \2 (a gray 2018 model)", t, count=1)


def _split_at_and(t: str) -> str:
    """"X, and the pickup truck made contact ..." -> "X. The pickup truck made contact ...": a sentence split where
    "and" joins two clauses, each with its subject."""
    return re.sub(r", and (the|a|an) (?=(?:\w+ ){0,3}?(?:AV|vehicle|car|truck|sedan|SUV|van|cyclist|bicyclist|"
                  r"pedestrian|motorcyclist|bus)\b (?:was|had|then|\w+ed)\b)",
                  lambda m: ". " + m.group(1).capitalize() + " ", t)


def _at_impact_last(t: str) -> str:
    """"At the time of the impact, the Waymo AV was in autonomous mode." moved to the narrative's end."""
    m = re.search(r"At the time of the impact[^.]*\.\s*", t)
    if not m or m.end() >= len(t.rstrip()):
        return t
    return (t[:m.start()] + t[m.end():]).rstrip() + " " + m.group(0).strip()


#: Session 21: the way police and other companies' reporters write (the AV by a number or "the test vehicle",
#: another verb of contact, speeds in words, police headings, a party numbered or described in parentheses, a
#: sentence split at "and", the mode boilerplate moved). Each keeps every slot's meaning.
NEW_REWRITES: tuple[Rewrite, ...] = (
    Rewrite("the <operator> AV -> V1", _numbered_av("V1")),
    Rewrite("the <operator> AV -> Vehicle 1", _numbered_av("Vehicle 1")),
    Rewrite("the <operator> AV -> the test vehicle", _sub(_AV_NAME, r"\1he test vehicle")),
    Rewrite("the <operator> AV -> the SV", _sub(_AV_NAME, r"\1he SV")),
    Rewrite("made contact with -> hit", _sub(r"\bmade contact with\b", "hit")),
    Rewrite("collided with -> struck", _sub(r"\bcollided with\b", "struck")),
    Rewrite("struck -> made contact with (active voice)", _active_struck),
    Rewrite("approximately 5 mph -> about five miles per hour", _speed_in_words),
    Rewrite("passenger car -> car", _sub(r"\bpassenger car\b", "car")),
    Rewrite("passenger vehicle -> vehicle", _sub(r"\bpassenger vehicle\b", "vehicle")),
    Rewrite("northbound -> N/B", _sub(r"\b(north|south|east|west)bound\b", lambda m: m.group(1)[0].upper() + "/B", re.I)),
    Rewrite("a party numbered in parentheses (V2)", _party_numbered),
    Rewrite("a party described in parentheses", _party_described),
    Rewrite("', and the <party> was' -> '. The <party> was' (a sentence split)", _split_at_and),
    Rewrite("'At the time of the impact ...' moved to the end", _at_impact_last),
    Rewrite("was traveling -> was moving", _sub(r"\bwas traveling\b", "was moving")),
)



#: The party's noun kinds a narrative names (one kind only: a police report's numbering can then be given to it).
_ONE_PARTY_NOUN = r"(?:passenger car|passenger vehicle|sedan|SUV|pickup truck|box truck|van|motorcycle|bus|truck|car)"
#: A street's name: capitalised words (an ordinal's digits first), or "[XXX]"; never past a sentence's end.
_A_STREET = r"(?:\[XXX\]|(?:\d+(?:st|nd|rd|th)|[A-Z]\w*)(?: [A-Z]\w*){0,3})"
_NUMBERED = r"\b(?:V|Vehicle |vehicle |Veh\.? ?|Unit |Party |#)\d\b|\bV-\d\b"


def _party_labelled(label: str, av: str | None = None, *, role: bool = False) -> Callable[[str], str]:
    """The party numbered as police and DMV forms number it: "a passenger car" -> "a passenger car (V2)" at its
    first naming and "the passenger car" -> "V2" after it; with `av`, the AV numbered too ("the Waymo AV" -> "V1");
    with `role`, the party named after its first naming by the role an insurer or a form gives it ("the passenger
    car" -> "the other party", "the third-party vehicle"). Only where the narrative names one kind of party, with no
    other, second, lead or parked one, and numbers no vehicle (two parties of one noun would be one label for two)."""
    def apply(t: str) -> str:
        nouns = {m.group(1) for m in re.finditer(rf"\b(?:[Aa]n?|[Tt]he) ({_ONE_PARTY_NOUN})\b", t)}
        if len(nouns) != 1 or re.search(r"\b(?:another|second|other|two|both|parked|lead|motorcyclist)\b", t) or \
                re.search(_NUMBERED, t):
            return t
        noun = nouns.pop()
        m = re.search(rf"\b[Aa]n? {noun}\b", t)
        if not m:
            return t
        if role:
            return t[:m.end()] + re.sub(rf"\b([Tt])he {noun}\b", lambda x: f"{x.group(1)}he {label}", t[m.end():])
        told = t[:m.end()] + f" ({label})" + re.sub(rf"\b[Tt]he {noun}\b", label, t[m.end():])
        return re.sub(_AV_NAME, av, told) if av else told
    return apply


#: Session 22 (helper C4): how police, insurers, other companies and DMV form-fillers name and describe the same
#: things (a body part as the "rear end" or "back", headings "in the northbound direction", speeds "at a speed of",
#: "miles an hour", streets abbreviated without a period, "the A/B intersection", "2-lane", "at approximately" a
#: time, the AV as "Unit 1" / "Party 1" / "the autonomous test vehicle", the party and the AV numbered "V1"/"V2",
#: "Vehicle 1"/"Vehicle 2", "Unit 1"/"Unit 2"). Each keeps every slot's meaning.
C4_REWRITES: tuple[Rewrite, ...] = (
    Rewrite("rear bumper -> rear end", _sub(r"\brear bumper\b", "rear end")),
    Rewrite("the rear of -> the back of", _sub(r"\bthe rear of\b", "the back of")),
    Rewrite("traveling <dir>bound -> traveling in the <dir>bound direction",
            _sub(r"\b(traveling|driving|proceeding|heading) (north|south|east|west)bound\b", r"\1 in the \2bound direction")),
    Rewrite("traveling <dir>bound -> traveling <dir>", _sub(r"\btraveling (north|south|east|west)bound\b", r"traveling \1")),
    Rewrite("at N mph -> at a speed of N mph",
            _sub(r"\bat (approximately |about )?(\d+) ?(mph|MPH)\b", r"at a speed of \1\2 \3")),
    Rewrite("N mph -> N miles an hour", _sub(r"\b(\d+) ?(?:mph|MPH)\b", r"\1 miles an hour")),
    Rewrite("Street/Avenue/Boulevard/Road -> St/Ave/Blvd/Rd (no period)", _sub(
        r"\b(Street|Avenue|Boulevard|Road)\b",
        lambda m: {"Street": "St", "Avenue": "Ave", "Boulevard": "Blvd", "Road": "Rd"}[m.group(1)])),
    Rewrite("the intersection of A and B / with A -> the A/B intersection / the A intersection", _subs(
        (rf"\bthe intersection of ({_A_STREET}) and ({_A_STREET})", r"the \1/\2 intersection"),
        (rf"\bthe intersection with ({_A_STREET})", r"the \1 intersection"))),
    Rewrite("two-lane, two lanes -> 2-lane, 2 lanes", _sub(r"\b(two|three|four|five|six)([- ]lanes?)\b", lambda m: {
        "two": "2", "three": "3", "four": "4", "five": "5", "six": "6"}[m.group(1).lower()] + m.group(2), re.I)),
    Rewrite("at <time> -> at approximately <time>",
            _sub(r"\bat (\d{1,2}:\d\d ?[AP]\.?M\.?)", r"at approximately \1"), environment=False),
    Rewrite("On <date> at <time> -> On <date>, at <time>,", _sub(
        r"^(On [A-Z][a-z]+ (?:\d{1,2}|\[XXX\])(?:st|nd|rd|th)?, \d{4}) at ([\d:]+ ?[AP]\.?M\.?(?: [A-Z]{2,3})?) ",
        r"\1, at \2, "), environment=False),
    Rewrite("the <operator> AV -> Unit 1", _numbered_av("Unit 1")),
    Rewrite("the <operator> AV -> Party 1", _numbered_av("Party 1")),
    Rewrite("the <operator> AV -> the autonomous test vehicle", _sub(_AV_NAME, r"\1he autonomous test vehicle")),
    Rewrite("the <party> -> V2 (numbered after its first naming)", _party_labelled("V2")),
    Rewrite("the <party> -> Party 2", _party_labelled("Party 2")),
    Rewrite("the AV and the party -> Vehicle 1 / Vehicle 2", _party_labelled("Vehicle 2", "Vehicle 1")),
    Rewrite("the AV and the party -> Unit 1 / Unit 2", _party_labelled("Unit 2", "Unit 1")),
    Rewrite("the <party> (after its first naming) -> the other party", _party_labelled("other party", role=True)),
    Rewrite("the <party> (after its first naming) -> the third-party vehicle",
            _party_labelled("third-party vehicle", role=True)),
    Rewrite("the <party> (after its first naming) -> the other vehicle", _party_labelled("other vehicle", role=True)),
    Rewrite("the <party> (after its first naming) -> the other motorist", _party_labelled("other motorist", role=True)),
)

def _clause_after(t: str) -> str:
    """"While the Waymo AV remained stopped, a car made contact." -> "A car made contact while the Waymo AV remained
    stopped.": an opening clause of the same moment told after its main clause. (Session 22: not where the main
    clause runs on past a sentence that lacks its period, "... with [XXX] The Waymo AV came to a stop", nor where
    the opening clause is only the mode aside "While in autonomous mode": moved, those change what they tell.)"""
    return _opening_clause_after(t, "While|As")


def _opening_clause_after(t: str, words: str) -> str:
    """"<Word> <clause>, <main>." -> "<Main> <word> <clause>." for the opening words `words` ("After|Before"); for
    words other than While/As only a main clause with no comma (the clause moved after "..., damaging the tire"
    would tell of the damage) and no opening pronoun (moved before its antecedent, "it" would name another)."""
    def moved(m: re.Match[str]) -> str:
        if re.search(r"\] [A-Z]", m.group(3)) or re.fullmatch(r"in (?:\w+ )?(?:autonomous|manual) mode", m.group(2)):
            return m.group(0)
        if words != "While|As" and ("," in m.group(3) or re.match(r"(?:it|they|he|she)\b", m.group(3))):
            return m.group(0)
        return f"{m.group(3)[0].upper()}{m.group(3)[1:]} {m.group(1).lower()} {m.group(2)}."
    return re.sub(rf"(?:(?<=^)|(?<=\. ))({words}) ([^,.]{{5,90}}?), ([a-z][^.]{{10,300}}?)\.", moved, t)


def _trailing_clause_first(t: str) -> str:
    """"A car made contact with the Waymo AV as the Waymo AV began to proceed." -> "As the Waymo AV began to
    proceed, a car made contact with the Waymo AV.": a clause of the same moment with its own subject, told after its
    main clause, told first (the other way round from `_clause_after`; not "such as", "as well as")."""
    def moved(m: re.Match[str]) -> str:
        main = m.group(1)
        if re.search(r"\b(?:such|well|same|so|known|identified|described)$", main) or re.search(r"\] [A-Z]", main) \
                or m.group(3).startswith("it "):  # ("it" told before its antecedent would name another)
            return m.group(0)
        if re.match(r"(?:The|A|An|It)\b", main):
            main = main[0].lower() + main[1:]
        return f"{m.group(2).capitalize()} {m.group(3)}, {main}."
    return re.sub(r"(?:(?<=^)|(?<=\. ))([A-Z][^.,;]{10,300}?) (as|while) ((?:the|a|an|it)\b[^,.;]{5,150})\.", moved, t)


def _when_to_as(t: str) -> str:
    """"The Waymo AV was stopped at X when a car struck it." -> "A car struck it as the Waymo AV was stopped at X."."""
    return re.sub(r"(?:(?<=^)|(?<=\. ))The ((?:Waymo|Cruise|Zoox) (?:AV|vehicle)) was ([^.,]{5,150}?),? when "
                  r"((?:a|an) [^.]{10,300}?)\.", lambda m: f"{m.group(3)[0].upper()}{m.group(3)[1:]} as the "
                  f"{m.group(1)} was {m.group(2)}.", t)


#: Session 16: clause-order rewrites, measured (printed by `main`) but not yet held by a test. Over all 379 studyable
#: narratives (dev gold and study, study2, study3) the first read 28 of 144 differently at the session's start and
#: 21 at its end (here, the dev narratives only: 9 of 52); the second 3 of 42. What still differs: a trailing
#: clause whose subject is not named ("while stopped"), the AV's state or run told after the party's contact, the
#: AV's merge attempt told after its stop, a clause that now follows "damaging ..." (read as after the contact).
CLAUSE_ORDER: tuple[Rewrite, ...] = (
    Rewrite("While/As <clause>, <main>. -> <Main> while/as <clause>.", _clause_after),
    Rewrite("The AV was <...> when a <party> ... -> A <party> ... as the AV was <...>", _when_to_as),
)

#: Session 22 (helper C3): more clause orders a new reporter brings, each keeping the order of events ("After X, Y"
#: and "Y after X"; "When X, Y" and "Y when X"; "Y. Then X" and "Y, after which X"), measured like CLAUSE_ORDER.
#: Over all 602 studyable narratives (`--all`), session 22 start (d8f8cdd) -> helper C3's end: While/As told after
#: 39 of 240 -> 30 of 236 (the AV's moves in a clause of the same moment after the first party's clause open the
#: interaction; its move retold after the contact ends its string; 4 rewrites that changed the meaning left out);
#: "The AV was <...> when a <party>" told as "as" 7 -> 4 of 92; After 5 -> 3 of 22 (a clause opened by "after"
#: told after the contact tells what came before it; the queue behind moves off on a green told after the contact);
#: When 2 -> 1 of 10; the trailing clause told first 3 of 32. What still differs: a subjectless "while stopped" /
#: "while yielding" told after the party's contact is read as the party's (reading it as the AV's left the AV's
#: "yielding" read as a slowing: a held report fell when that was changed too, so neither landed); a move of the AV
#: told after its stop in a trailing clause ("came to a stop ... while attempting a merge", "came to a stop as EGO
#: braked") is not put before the stop (the general sort moved a held check figure and was dropped); a turn told
#: done in a trailing "after EGO made a right turn" is kept in the string (the opening "After ..." drops it).
C3_CLAUSE_ORDER: tuple[Rewrite, ...] = (
    Rewrite("After <clause>, <main>. -> <Main> after <clause>.", lambda t: _opening_clause_after(t, "After")),
    Rewrite("When <clause>, <main>. -> <Main> when <clause>.", lambda t: _opening_clause_after(t, "When")),
    Rewrite("Before <clause>, <main>. -> <Main> before <clause>.", lambda t: _opening_clause_after(t, "Before")),
    Rewrite("<Main> as/while <the X ...>. -> As/While <the X ...>, <main>.", _trailing_clause_first),
    Rewrite("'. Then a' -> ', after which a'", _sub(r"\. Then (a|an|the) ", r", after which \1 ")),
)


HERE = Path(__file__).parent

#: The studyable sets beyond dev, each file named (never a glob: a check set's file lies beside each of them).
STUDY_FILES = (HERE / "csvr" / "study2.jsonl", HERE / "sgo" / "study3.jsonl", HERE / "sgo4" / "study4.jsonl",
               HERE / "sgo5" / "study5.jsonl", HERE / "sgo6" / "study6.jsonl")


def _ids(path: Path) -> set[str]:
    return {json.loads(line)["report_id"] for line in path.read_text(encoding="utf-8").splitlines() if line.strip()}


@lru_cache(maxsize=1)
def studyable() -> dict[str, str]:
    """id -> narrative of the dev gold and study sketches (dev.jsonl holds the texts): the sample the held test
    runs on (fast enough for every commit)."""
    ids = _ids(REPORTS / "dev_gold.jsonl") | _ids(REPORTS / "dev_gold_study.jsonl")
    rows = [json.loads(line) for line in (REPORTS / "dev.jsonl").read_text(encoding="utf-8").splitlines()]
    return {r["id"]: r["text"] for r in rows if r["id"] in ids}


@lru_cache(maxsize=1)
def every_studyable() -> dict[str, str]:
    """id -> narrative of every studyable set: dev gold and study, study2 .. study6 (602 narratives; the wider
    measure, `python -m tests.text.invariance --all`)."""
    texts = dict(studyable())
    for path in STUDY_FILES:
        for line in path.read_text(encoding="utf-8").splitlines():
            if line.strip():
                row = json.loads(line)
                texts[row["id"]] = row["text"]
    return texts


@lru_cache(maxsize=4096)
def content(text: str, rid: str, environment: bool = True) -> str:
    """The sketch as compared: evidence spans aside, and the environment when `environment` is False."""
    d = extract(text, rid).to_dict()
    d.pop("evidence", None)
    if not environment:
        d.pop("environment")
    return json.dumps(d, sort_keys=True)


def changed(rw: Rewrite, corpus: dict[str, str] | None = None) -> tuple[int, list[str]]:
    """(narratives the rewrite changes, ids of those whose sketch changed with it), over `corpus` (the dev sample
    when None)."""
    told, ids = 0, []
    for rid, text in (studyable() if corpus is None else corpus).items():
        other = rw.apply(text)
        if other == text:
            continue
        told += 1
        if content(other, rid, rw.environment) != content(text, rid, rw.environment):
            ids.append(rid)
    return told, ids


def main() -> None:
    import sys
    corpus = every_studyable() if "--all" in sys.argv[1:] else studyable()
    total_told = total_changed = 0
    print(f"{'rewrite':<46}{'rewritten':>10}{'changed':>9}  first changed")
    for rw in REWRITES + NEW_REWRITES + C4_REWRITES:
        told, ids = changed(rw, corpus)
        total_told, total_changed = total_told + told, total_changed + len(ids)
        print(f"{rw.name:<46}{told:>10}{len(ids):>9}  {', '.join(ids[:3])}")
    print(f"{'all':<46}{total_told:>10}{total_changed:>9}  ({total_changed / max(1, total_told):.1%} of rewritten "
          f"narratives read differently)")
    print("clause order (measured, not held):")
    for rw in CLAUSE_ORDER + C3_CLAUSE_ORDER:
        told, ids = changed(rw, corpus)
        print(f"{rw.name:<46}{told:>10}{len(ids):>9}  {', '.join(ids[:3])}")


if __name__ == "__main__":
    main()
