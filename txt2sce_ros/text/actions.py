"""Manoeuvre phrases -> the 13 action codes, and who did them.

Each phrase is a regex tagged with a code. A phrase is attributed to the clause's subject: the latest mention in
subject position (sentence start, after a comma or a conjunction, before a relative "that/which/who" or a
participle such as "traveling"), or, for an opening subordinate clause ("While reversing, the car ..."), the first
subject that follows. Intentions are not actions: "preparing to turn" or "waiting to make a left turn" add nothing,
while "began to", "attempted to" and "proceeded to" do.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass

from . import fastre as fre
from .fastre import compile_gated
from .lexicon import CARDINALS
from .mentions import Mention

_DIR = r"(?:north|south|east|west|northeast|northwest|southeast|southwest)"
#: After "turn": the name of a lane, a light or a lamp ("left turn lane", "right turn signal"), not a turn made.
_NOT_A_TURN = r"(?!\s+(?:lane|signal|indicator|pocket|arrow|light|only|bay))"

#: (code, regex). "X" codes are resolved by context: "S" = the party's state became stopped.
PHRASES: tuple[tuple[str, str], ...] = (
    # Left in reverse, a space is backed out of (`k`), not pulled out of: "(?!...in reverse)" closes the pattern.
    ("O", r"(?:\b(?:left|leav(?:e|es|ing)|exit(?:ed|ing|s)?|depart(?:ed|ing|s)?\s+from)\s+(?:a|an|the|its)\s+"
          r"(?:curbside\s+|parallel\s+)?(?:parking\s+(?:spot|space|stall|position|lane)|parked\s+position|curb)\b|"
          # out of its space, the parking lane or off the curb by any verb of moving forward ("moved out of", "began
          # to move forward out of", "nosed out from the curb", "moved away from the curb", "merged from the parking
          # lane")
          r"\b(?:pull|mov|driv|drove|roll|edg|nos|inch|creep|crept|came|com|eas|merg|steer)\w*\s+(?:forward\s+)?"
          r"(?:out\s+|away\s+)?(?:of|from|off)\s+(?:a|an|the|its)\s+(?:curbside\s+|parallel\s+)?"
          r"(?:parking\s+(?:spot|space|stall|position|lane)|parked\s+position|curb\b)|\bpull(?:ed|ing|s)?\s+(?:away\s+)?from\s+"
          r"the\s+curb|\bpull(?:ed|ing|s)?\s+out\s+(?:from\s+(?:the\s+)?curb|into\s+traffic)|"
          r"\bpull(?:ed|ing|s)?\s+(?:out|away)\s+from\s+(?:a|an|the|its)\s+(?:bus\s+stop|loading\s+zone|"
          r"stop\b(?!\s+(?:line|bar|sign|light)))|"
          r"\bpull(?:ed|ing|s)?\s+out\s+into\s+(?:EGO's|the|its|our)\s+(?:\w+\s+)?(?:lane|path)|"

          r"\b(?:proceed(?:ed|s)|pull(?:ed|ing|s)|mov(?:ed|es)|merg(?:ed|es))\s+(?:back\s+)?(?:out\s+)?into\s+the\s+"
          r"(?:driving|travel|traffic)\s+lane\b|"
          r"\b(?:enter(?:ed|ing|s)?|merg(?:ed|ing|es|e))\s+(?:into\s+)?traffic\s+from\s+(?:a|an|the|its)\s+"
          r"(?:curbside\s+|parallel\s+)?(?:parked\s+position|parking\s+(?:spot|space|stall|position)|curb))"
          r"(?!\s+in\s+reverse)"),
    # "pulled out and struck", "swung out around the bus": out of a parking spot if it was parked, a start if it
    # stood, a move out of its lane if it was on its way (sequences.sequence); out of a driveway or lot is `m`.
    ("P", r"\b(?:pull(?:ed|ing|s)?|sw(?:ung|ing|ings|inging))\s+out\b(?!\s+(?:(?:of|from)\s+(?:a|an|the)\s+(?:[\w-]+\s+){0,2}"
          r"(?:driveway|garage|parking|lot|alley|space|spot|stall|gas)|into\s+the\s+intersection|"
          # "swung out into the oncoming lane", "pulled out into the left lane": the lane named tells the move
          r"into\s+the\s+(?:oncoming|opposing|opposite|left|right)\b))|"
          # Into traffic or onto the road from where it stood ("pulled into traffic", "entered the roadway", "began to
          # enter the travel lane"): as "pulled out", its place before tells the move; from a curb, a sidewalk, a
          # driveway or a lot named after it, the crossing or the exit is read by its own words (`m`).
          r"\b(?:(?:pull|nos|eas|edg|inch)(?:ed|ing|es|e|s)?\s+(?:out\s+)?(?:into|onto)|enter(?:ed|ing|s)?(?:\s+into)?)\s+"
          r"(?:traffic\b|the\s+(?:roadway|road|street|travel\s+lane|traffic\s+lane|driving\s+lane)\b)"
          r"(?!\s+(?:from|out\s+of)\s+(?:the\s+|a\s+|an\s+)?(?:[\w-]+\s+){0,2}?(?:curb|sidewalk|median|driveway|"
          r"parking\s+lot|lot|garage|alley))"),
    ("Y", r"\b(?:began|started|initiated|commenced|made|completed)\s+(?:its|the|his|her|their)\s+turn\b|"
          r"\b(?:attempt(?:ed|ing|s)|beg(?:an|ins)|start(?:ed|s)|tr(?:ied|ies)|proceed(?:ed|s))\s+to\s+(?:make\s+(?:a|the|its|his|her|their)\s+)?"
          r"turn\b(?!\s+(?:left|right|lane|signal))"),
    # (any dash a report's text carries, "U‑turn" with a non-breaking hyphen; a three-point or K-turn turns the car
    # around in as many moves: a U-turn)
    ("j", r"\bu[-\u2010\u2011]?\s?turn|\bturn(?:ed|ing|s)?\s+around\b|\bmulti[-\u2010\u2011\s]?point\s+turn|"
          r"\b(?:three|3)[-\u2010\u2011\s]?point\s+turn|\b[KY][-\u2010\u2011]turn\b"),
    ("k", r"\b(?:switched|shifted|put\s+\w+)\s+(?:in)?to\s+reverse\b|\brevers(?:ed|ing|es|e)\b(?!\s+(?:lights?|lamps?|camera|alarm|beep\w*|signal))|"
          r"\b(?:(?<!remained\s)(?<!remains\s)(?<!was\s)(?<!were\s)(?<!got\s)(?<!is\s)(?<!are\s)backed|backing|backs)\s+"
          r"(?:up|out|into|away|toward|towards|onto|across|down|along|in)\b|"
          r"(?<=\bto\s)back\s+(?:up|out|into|away|toward|towards|onto|across|down|along|in)\b|"
          # a bare "backed" of a vehicle, as "reversed" ("the SUV backed and the rear of the SUV made contact", "backed
          # approximately 113 meters", "backed at a low speed from an adjacent driveway"); not a state ("was backed
          # up") nor "backed by"
          r"\b(?<!remained\s)(?<!remains\s)(?<!was\s)(?<!were\s)(?<!got\s)(?<!is\s)(?<!are\s)(?<!been\s)backed\b(?!-|\s+by\b)|"
          # "began to back", "started to back and": the infinitive with no particle is the backing itself
          r"(?<=\bto\s)back\b(?=\s*(?:[,.;]|$|and\b|slowly\b|while\b|when\b))|"
          r"\b(?:roll|drift|coast)(?:ed|ing|s)?\s+back(?:wards?)?\b(?!\s+(?:to|into)\s+(?:its|their|the)\s+(?:own\s+)?lane)|"
          # any verb of going told backward or in reverse ("drove backward", "traveled in reverse", "began moving in
          # reverse")
          r"\b(?:mov|roll|drift|creep|crept|coast|driv|drove|went|go|travel|travell|proceed|inch|edg)(?:ed|ing|es|e|s)?\s+"
          r"(?:\w+ly\s+)?(?:backwards?|in\s+reverse)\b|"
          r"\bbacking\b"),
    # ("was pulled over at the curb" is where it stood, _STATE_STOP; "was pulling over" the manoeuvre under way)
    ("l", r"\b(?:pull(?:ing|s)?|(?<!was\s)(?<!were\s)(?<!been\s)(?<!is\s)pulled)\s+over\b|(?<!been\s)(?<!was\s)(?<!were\s)\bparallel[-\s]+park(?:ing|ed)?\b(?!\s+(?:spot|space|position|stall|lane))|"
          # "was parallel parking" is a manoeuvre under way; only "was parallel parked" tells where a car stood
          r"(?:(?<=\bwas\s)|(?<=\bwere\s))parallel[-\s]+parking\b(?!\s+(?:spot|space|position|stall|lane))|"
          r"\binto\s+a\s+(?:parallel[-\s]+)?parking\s+"
          r"(?:space|spot|stall)|(?<!waiting\s)(?<!preparing\s)(?<!planning\s)\b(?:to|attempting\s+to)\s+park\b|"
          r"\bpull(?:ed|ing|s)?\s+(?:over\s+|up\s+)?(?:to|toward|towards)\s+the\s+(?:curb|shoulder|(?:(?:right|left)\s+)?"
          r"side\s+of\s+the\s+(?:road|street|roadway))\b|"
          # onto the shoulder or into the parking lane: out of traffic to the road's edge
          r"\b(?:pull|mov|steer|eas)(?:ed|ing|es|e|s)?\s+(?:over\s+)?(?:onto|into)\s+the\s+(?:right\s+|left\s+)?"
          r"(?:shoulder|parking\s+lane)\b|"
          r"\b(?:making|made|performing|performed)\s+(?:a|an|the|its)\s+(?:parallel[-\s]+)?parking\s+maneuver|"
          r"\bpull[-\s]?over\s+(?:maneuver|manoeuvre)\b|"
          # "executed a pullover", "began its pull-over"; into a place at the curb for its riders or loads ("pulled
          # into a loading zone", "a pick-up zone", "a bus stop", "the curb lane"); "pulled alongside the curb"
          r"\b(?:execut|perform|initiat|begin|began|begun|start|complet|conduct|commenc)\w*\s+(?:a|an|the|its)\s+"
          r"(?:[\w-]+\s+)?pull[-\s]?over\b|"
          r"\bpull(?:ed|ing|s)?\s+(?:in\s*to|into)\s+(?:a|an|the)\s+(?:[\w-]+\s+)?(?:(?:loading|pick[-\s]?up|drop[-\s]?off|passenger|"
          r"curbside)\s+(?:zone|area|bay|spot|space)|bus\s+stop|curb\s+lane)\b|"
          r"\b(?:pull|steer|eas)(?:ed|ing|es|e|s)?\s+(?:in\s+to|alongside|(?:up\s+)?(?:toward|towards))\s+the\s+curb\b|"
          # to the roadside to let a passenger on or off: pulling over
          r"\b(?:pull(?:ed|ing|s)?|mov(?:ed|ing|es|e)|steer(?:ed|ing|s)?)\s+(?:over\s+)?to\s+the\s+(?:curb|(?:right\s+)?side\s+of\s+the\s+(?:road|"
          r"street))\b(?=[^.]{0,30}\b(?:drop|pick|let|load|unload|board|park)|[^.]{0,4}$)"),
    # Not to a complete stop is a slowing ("did not come to a complete stop and made contact", "failed to completely
    # stop"): the negation denies the standstill, not the braking (a plain "failed to stop" denies both).
    ("c", r"\b(?:did\s+not|didn't|failed\s+to|fail(?:s|ing)\s+to)\s+(?:(?:come|came|coming)\s+to\s+(?:a\s+)?"
          r"(?:complete|full)\s+(?:stop|halt|standstill)|(?:completely|fully)\s+stop)\b|"
          # Short of a standstill is a slowing too: "came to a near stop", "slowed to a rolling stop", "came nearly
          # to a stop", "came to an almost complete stop"
          r"\b(?:c(?:a|o)m(?:e|es|ing)|slow(?:ed|ing|s)?(?:\s+down)?|brak(?:ed|ing|es)|decelerat(?:ed|ing|es))\s+"
          r"(?:(?:nearly|almost|virtually)\s+)?to\s+(?:a|an)\s+(?:near|almost|nearly|rolling|partial|virtual)\s+"
          r"(?:(?:complete|full)\s+)?(?:stop|halt|standstill)\b|"
          r"\bc(?:a|o)m(?:e|es|ing)\s+(?:nearly|almost|virtually)\s+to\s+(?:a\s+)?(?:complete\s+|full\s+)?"
          r"(?:stop|halt|standstill)\b"),
    # (a manner adverb may stand between the verb and its end: "came slowly to a stop", "turned sharply left",
    # "proceeded slowly forward")
    ("h", r"\b(?:(?:came|come|comes|coming)\s+(?:\w+ly\s+)?to|brought\s+(?:EGO|it|the\s+\w+)\s+to|brings?\s+\w+\s+to|"
          r"slow(?:ed|ing|s)?\s+(?:down\s+|\w+ly\s+)?to|brak(?:ed|ing)\s+(?:\w+ly\s+)?to|decelerat(?:ed|ing|es)\s+(?:\w+ly\s+)?to|"
          # ("applied the brakes to a stop": the braking told by its noun, as "braked to a stop")
          r"appl(?:ied|ying|ies)\s+(?:the|its|their|his|her)\s+brakes?\s+to|"
          # "screeched to a halt", "ground to a halt", "skidded to a stop", "rolled to a stop": any verb of a vehicle
          # ending its run, with the standstill it reached
          r"(?:screech|skid|slamm|jerk|lurch|roll|eas|glid|coast|slid|drift|pull|grind)(?:ed|ing|s|e)?\s+(?:\w+ly\s+)?to|"
          # ("before coming to another complete stop": a second stop of the same run)
          r"(?:ground|grinds|slid|slides)\s+(?:\w+ly\s+)?to)\s+(?:a|an|another)\s+"
          # (one word for the manner of the stop: "a sudden stop", "an unexpected halt", "an emergency stop"; not a
          # stop sign's kind, "a four-way stop", and not a stop short of a standstill, "a near stop", "a rolling stop")
          r"(?:(?![\w-]*way\s|(?:near|almost|nearly|rolling|partial|virtual)\s)[\w-]+\s+)?(?:stop|halt|standstill)|\bstopp(?:ed|ing)\s+(?:suddenly|abruptly|short|quickly|hard)\b|\bstopp(?:ed|ing)\b|"
          r"\bstops\b|\byield(?:ed|ing|s)?\b|\bhalt(?:ed|ing|s)?\b|"
          r"\bbrought\s+(?:itself\s+)?to\s+(?:a|an)\s+(?:\w+\s+)?(?:stop|halt)\b|"
          r"\bhad\s+to\s+(?:come\s+to\s+a\s+(?:\w+\s+)?)?stop\b|"
          # "was slowing to stop for a red light": slowing that ends at a standstill
          # ("slowed, preparing to stop", "braked in preparation to stop": the standstill it was slowing for)
          r"\b(?:slow|brak|decelerat)(?:ed|ing|es|e|s)?(?:\s+down)?(?:\s*,)?\s+(?:(?:preparing|in\s+preparation|"
          r"getting\s+ready|in\s+order)\s+)?to\s+stop\b|"
          r"\b(?:made|make|making|makes)\s+(?:a|an)\s+(?:\w+\s+)?stop\b|\bc(?:a|o)me\s+to\s+rest\b|"
          # "experienced an unknown e-stop", "performed an emergency stop": the shuttles' word for a hard stop
          r"\b(?:made|execut(?:ed|es|ing)|perform(?:ed|s|ing)|experienc(?:ed|es|ing))\s+(?:a|an)\s+(?:\w+\s+)?"
          r"(?:e-stop|emergency\s+stop)\b|"
          r"\bpull(?:ed|ing|s)?\s+(?:up\s+)?to\s+(?:a|an)\s+(?:\w+\s+)?stop\b|"
          # Pulling (up or in) behind a vehicle that stands ("pulled behind the double-parked vehicle") ends behind
          # it: a stop. Behind a moving one it is following (the `a` phrase below).
          r"\bpull(?:ed|ing|s)?\s+(?:up\s+|in\s+)?behind\s+(?:a|an|the)\s+(?:[\w-]+\s+){0,2}?(?:double[- ]parked|"
          r"parked|stopped|stalled|stationary|disabled|idling)\b"),
    # "began to move into EGO's lane" begins the move it names, not a start from a standstill.
    # ("began to pass the truck on the left": a move begun past what it had stopped for; "began to proceed around the
    # truck" is the going around, read as that move, F)
    ("i", r"\b(?:began|begin|begins|begun|beginning|started|starts|start|starting)\s+to\s+(?:slowly\s+)?(?:proceed|move|roll|drive|go|creep|"
          r"edge|accelerate|follow|pass|nudge|inch|pull\s+(?:forward|out|away))"
          r"(?!\s+(?:\w+ly\s+)?(?:into|onto|over|toward|towards|left|right|around|"
          r"across|to\s+the)\b)|\b(?:began|started)\s+(?:moving|proceeding|rolling|"
          # ("began passing", as "began to pass"; "began proceeding around the truck", as "began to proceed around": the
          # move begun, read by its own words)
          r"driving|creeping|accelerating|passing)(?!\s+(?:\w+ly\s+)?(?:into|onto|over|toward|towards|left|right|around|"
          r"across|to\s+the)\b)|\b(?:(?:mov|pull|nudg|creep|edg|inch|roll|lurch|surg|launch|jolt|jerk|eas|start)(?:ed|ing|es|e|s)?|crept|"
          r"accelerated|drove|drives|driving)\s+(?:\w+ly\s+)?forward\b|"
          # "moved ahead", "crept ahead", "pulled up": forward told by another adverb ("pulled ahead of EGO" places it,
          # "moved up behind" or "pulled up to the curb" ends somewhere: no start)
          r"\b(?:(?:mov|pull|nudg|creep|edg|inch|roll|eas)(?:ed|ing|es|e|s)?|crept)\s+(?:\w+ly\s+)?ahead\b(?!\s+of\b)|"
          r"\b(?:mov|inch|creep|edg)(?:ed|ing|es|e|s)?\s+up\b(?!\s+(?:behind|beside|alongside|next|to|on)\b)|"
          r"\bstart(?:ed|ing|s)?\s+(?:up\s+)?(?:again\s+)?from\s+(?:a|the|its)\s+(?:\w+\s+)?(?:stop|standstill)\b|"
          # the SGO form's "Starting in Traffic", told in a narrative
          r"\bstart(?:ed|ing|s)?\s+(?:up\s+)?in\s+traffic\b|"
          r"\btook\s+off\b(?!\s+(?:from\s+the\s+scene|the\b|its\b|his\b|her\b|a\b))|"
          r"\bproceed(?:ed|ing|s)?\s+(?:\w+ly\s+)?forward\b|\bproceed(?:ed)?\s+from\s+"
          r"(?:a|the)\s+stop|\bbegins\s+to\s+move|\bbegan\s+to\s+proceed(?!\s+(?:\w+ly\s+)?around\b)|\bproceeded\s+again|"
          r"\b(?:moved|moves|moving|pulled|pulling|set|sets|setting)\s+off\b|\bpull(?:ed|ing|s)?\s+away\b|"
          r"\bresum(?:ed|ing|es)\s+(?:travel|driving|moving|motion)\b|"
          r"\b(?:depart(?:ed|ing|s)?|accelerat(?:ed|ing|es)|mov(?:ed|ing|es)\s+away|pull(?:ed|ing|s)\s+away)\s+from\s+(?:a|the)\s+"
          r"(?:complete\s+|full\s+)?(?:standstill|stop)\b|"
          # "As EGO advanced and then came to a stop": advancing is moving forward
          r"\badvanc(?:ed|ing|es)\b(?!\s+(?:warning|notice))"),
    ("f", r"\b(?:left|leftward)\s+lane\s+change\b|\blane[-\s]chang(?:e|ed|ing|es)\s+(?:to\s+the\s+|into\s+the\s+)?left\b|\bchang(?:ed|"
          r"ing|es|e)\s+lanes?\s+(?:to\s+the\s+|into\s+the\s+)?left|\bmerg(?:ed|ing|es|e)\s+(?:left|to\s+the\s+left|"
          r"(?:back\s+)?into\s+the\s+left\s+lane)|\b(?:moved|moving|move|switched|switching|pulled|pulling|swung|swinging)\s+"
          r"(?:out\s+|back\s+)?into\s+the\s+left\s+lane|(?<=\s)into\s+the\s+(?:adjacent\s+)?left\s+(?:adjacent\s+)?(?:travel\s+|through\s+)?lane\b|"
          # "changed lanes to the right and then back to the left": the return told without its verb
          r"\b(?:and|then)\s+(?:then\s+)?back\s+(?:over\s+)?(?:to|into)\s+the\s+left\b|"
          # "started to return to the left lane behind the pickup truck": back into the lane it had left
          r"\breturn(?:ed|ing|s)?\s+(?:back\s+)?(?:to|into)\s+the\s+left(?:most)?\s+lane\b|"
          # "merged into the lane to its left", "moved one lane to the left": the side said of the lane
          r"\b(?:chang|mov|merg|shift|switch|pull|steer)(?:ed|ing|es|e|s)?\s+(?:over\s+)?into\s+the\s+(?:adjacent\s+)?"
          r"lane\s+(?:immediately\s+)?to\s+(?:its|the|EGO's|our|their)\s+left\b|"
          r"\b(?:moved|shifted|merged|changed)\s+(?:over\s+)?(?:one|a)\s+lane\s+(?:over\s+)?to\s+the\s+left\b|"
          # "moved from the right lane into the left lane": the lane it went into names the side
          r"\b(?:(?!turn)[a-z]+(?:ed|ing)|came|went|drove|swung|cut|slid)\s+(?:over\s+)?from\s+the\s+(?:[\w-]+\s+){0,2}lane\s+(?:in)?to\s+the\s+"
          r"(?:adjacent\s+)?left(?:most)?\s+lane\b|"
          r"\b(?:entered|entering|enters|enter|crossed|crossing|crosses|cross|moved|moves|veered|veers|maneuvered|"
          r"manoeuvred|swerved|swerves|drove|drives|swung|swings|swinging|pulled|pulling|went|going)\s+"
          r"(?:out\s+|over\s+|wide\s+)?(?:into\s+)?the\s+(?:oncoming|"
          # ("entered the leftmost lane": a lane reached only by a move to the left; the rightmost lane is also
          # entered from the curb, a move left, so it is not read so; "re-enter" is the return, read below)
          r"opposing|opposite)\s+(?:\w+\s+)?lane|(?<!-)\b(?:partially\s+)?enter(?:ed|ing|s)?\s+(?:into\s+)?the\s+left(?:most)?(?:\s+adjacent)?\s+"
          r"lane\b|\bsteer(?:ed|ing)?\s+(?:to\s+the\s+)?left\b|"
          # any verb of motion with the side and where it went ("began maneuvering left into the path of EGO",
          # "veered left into EGO's travel lane"); a turn, a pull into a space or a backing is read by its own words
          r"\b(?:(?!turn|pull|back|revers)[a-z]+(?:ed|ing)|cut|cutting)\s+left\s+(?:into|in\s+front)\b|"
          r"\bcut(?:s|ting)?\s+(?:back\s+)?(?:in\s+)?(?:over\s+)?to\s+the\s+left\b|"
          # Into a left-turn lane is a move to the left ("was entering the leftmost dedicated left turn lane").
          r"\b(?:enter(?:ed|ing|s)?|(?:merg|mov|pull)(?:ed|ing|es|e|s)?\s+into)\s+the\s+(?:[\w-]+\s+){0,2}?"
          r"left[- ]turn\s+(?:lane|pocket|bay)|\bswerv(?:ed|ing|es)\s+"
          r"(?:to\s+the\s+)?left\b|\bcross(?:ed|ing|es)?\s+(?:over\s+)?(?:the\s+)?(?:center\s*line|centerline|"
          r"double\s+(?:yellow|solid)|(?:center\s+|centre\s+)?median|yellow\s+line)|\b(?:veer|drift)(?:ed|ing|s)?\s+(?:to\s+the\s+)?left\b|"
          # a sideways move told without "lane": "moved left and made contact", "drifted over the center line"
          r"\b(?:mov|shift|nudg|edg|inch|swung|swing|pull)(?:ed|ing|es|e|s)?\s+(?:over\s+)?(?:to\s+the\s+)?left\b"
          r"(?!\s+(?:of\s+(?:the\s+)?EGO|turn\b|hand))|"
          r"\b(?:drift|veer|swerv|wander)(?:ed|ing|e|s)?\s+(?:over|across)\s+(?:the\s+)?(?:center\s*line|centerline|"
          r"double\s+(?:yellow|solid)|yellow\s+line|median)"),
    ("g", r"\b(?:right|rightward)\s+lane\s+change\b|\blane[-\s]chang(?:e|ed|ing|es)\s+(?:to\s+the\s+|into\s+the\s+)?right\b|\bchang"
          r"(?:ed|ing|es|e)\s+lanes?\s+(?:to\s+the\s+|into\s+the\s+)?right|\bmerg(?:ed|ing|es|e)\s+(?:right|to\s+the\s+"
          r"right|(?:back\s+)?into\s+the\s+right\s+lane)|\b(?:moved|moving|move|switched|switching)\s+(?:(?:back\s+)?into\s+the\s+right\s+"
          r"lane|over\s+to\s+the\s+right)|\b(?:pulled|pulling|swung|swinging)\s+(?:out\s+|back\s+)?into\s+the\s+right\s+lane\b|"
          r"(?<=\s)into\s+the\s+(?:adjacent\s+)?right\s+(?:adjacent\s+)?(?:travel\s+|through\s+)?lane\b|"
          r"\b(?:and|then)\s+(?:then\s+)?back\s+(?:over\s+)?(?:to|into)\s+the\s+right\b|"
          r"\breturn(?:ed|ing|s)?\s+(?:back\s+)?(?:to|into)\s+the\s+right(?:most)?\s+lane\b|"
          r"\b(?:chang|mov|merg|shift|switch|pull|steer)(?:ed|ing|es|e|s)?\s+(?:over\s+)?into\s+the\s+(?:adjacent\s+)?"
          r"lane\s+(?:immediately\s+)?to\s+(?:its|the|EGO's|our|their)\s+right\b|"
          r"\b(?:moved|shifted|merged|changed)\s+(?:over\s+)?(?:one|a)\s+lane\s+(?:over\s+)?to\s+the\s+right\b|"
          r"\b(?:(?!turn)[a-z]+(?:ed|ing)|came|went|drove|swung|cut|slid)\s+(?:over\s+)?from\s+the\s+(?:[\w-]+\s+){0,2}lane\s+(?:in)?to\s+the\s+"
          r"(?:adjacent\s+)?right(?:most)?\s+lane\b|"
          r"\bre-?enter(?:ed|ing)?\s+the\s+(?:\w+\s+){0,2}lane|"  # ("re-entering the far right lane")
          # "began to merge back into the northbound lane" after passing on the left: the return, as "re-enter" (a
          # side named is read by the side: "merging back into the left lane of traffic")
          r"\bmerg(?:ed|ing|es|e)\s+back\s+into\s+the\s+(?:(?!(?:left|right)(?:most)?\s)[\w-]+\s+){0,2}lane\b|"
          r"\b(?:partially\s+)?enter(?:ed|ing|s)?\s+(?:into\s+)?the\s+right(?:\s+adjacent)?\s+lane\b|"
          r"\b(?:(?!turn|pull|back|revers)[a-z]+(?:ed|ing)|cut|cutting)\s+right\s+(?:into|in\s+front)\b|"
          r"\bcut(?:s|ting)?\s+(?:back\s+)?(?:in\s+)?(?:over\s+)?to\s+the\s+right\b|"
          r"\b(?:enter(?:ed|ing|s)?|(?:merg|mov|pull)(?:ed|ing|es|e|s)?\s+into)\s+the\s+(?:[\w-]+\s+){0,2}?"
          r"right[- ]turn\s+(?:lane|pocket|bay)|"
          # Into a lane that runs along the right-hand curb, named by its kind ("maneuvering into the bus and taxi
          # lane to pass the semi-trailer truck", "moved into the bike lane"): a move to the right.
          r"\b(?:enter(?:ed|ing|s)?|(?:merg|mov|pull|shift|steer|maneuver|manoeuvr|swerv|veer|swung|swing|cut|nudg)"
          r"(?:ed|ing|es|e|s)?\s+(?:over\s+)?into)\s+the\s+(?:bus|bike|bicycle|curb|transit)(?:\s+and\s+taxi)?"
          r"(?:\s+only)?\s+lane\b|\bsteer(?:ed|ing)?\s+(?:to\s+the\s+)?"
          r"right\b|\bswerv(?:ed|ing|es)\s+(?:to\s+the\s+)?right\b|\b(?:veer|drift)(?:ed|ing|s)?\s+(?:to\s+the\s+)?right\b|"
          r"\b(?:mov|shift|nudg|edg|inch|swung|swing|pull)(?:ed|ing|es|e|s)?\s+(?:over\s+)?(?:to\s+the\s+)?right\b"
          r"(?!\s+(?:of\s+(?:the\s+)?EGO|turn\b|hand))"),
    # Onto a freeway from its ramp is a merge into the lane beside it ("entered the freeway").
    # ("joined the freeway", "entered Interstate 15 from the on-ramp": the road named by its number)
    ("F", r"\b(?:enter|join)(?:ed|ing|s)?\s+(?:onto\s+)?(?:the\s+(?:freeway|highway|interstate|expressway|motorway)\b|"
          r"(?:Interstate|I-|Highway|Hwy|US|SR|Route|State\s+Route)\s*-?\s*\d+\b(?=[^.]{0,40}\bramp\b))|"
          r"\b(?:cut|cutting|cuts)\s+(?:in|into|over|off\s+EGO)|\bchang(?:ed|ing|es|e)\s+lanes?\b|\blane\s+change\b|"
          # ("lane-changed", "lane changed to the left": the noun made a verb)
          r"\blane[-\s]chang(?:ed|ing|es)\b|"
          r"\b(?:switch|shift)(?:ed|ing|es|s)?\s+lanes?\b|"
          # Any verb of motion into the AV's lane ("darted", "nosed", "squeezed", "moved laterally into EGO's lane"):
          # the lane entered tells the manoeuvre, whatever the verb; a turn into it is the turn's end, not a change.
          r"\b(?:(?!turn)[a-z]+(?:ed|ing)|came|went|drove|ran|rode|swung|cut|slid|crept)\s+(?:\w+ly\s+)?(?:over\s+|back\s+)?into\s+"
          r"(?:EGO's|the\s+EGO's|our)\s+(?:travel\s+)?lane\b|"
          # ... and after any verb group that ends in one of going ("began to proceed into EGO's lane", "moved
          # forward into the lane occupied by EGO"): the lane entered, read on its own (no overlap with the start)
          r"(?<=\s)into\s+(?:EGO's|the\s+EGO's|our)\s+(?:travel\s+|driving\s+)?lane\b|"
          r"(?<=\s)into\s+the\s+lane\s+(?:occupied\s+by|of)\s+EGO\b|"
          # "attempted to move over": over, with no side told, is toward the lane beside it
          r"\b(?:mov|shift|edg|swung|swing)(?:ed|ing|es|e|s)?\s+over\b(?!\s+(?:to\s+|toward\s+|into\s+)?(?:the\s+)?"
          r"(?:left|right|curb|shoulder|side|far))|"
          r"\bmerg(?:ed|ing|es|e)\b|\b(?:maneuver(?:ed|ing)?|manoeuvr(?:ed|ing)|navigat(?:ed|ing)|proceed(?:ed|ing)?|"
          r"go(?:ing)?|went|drove|driving|steer(?:ed|ing))\s+around\b|\bswerv(?:ed|ing|es)\b|\bencroach(?:ed|ing|es)?\b|"
          r"\bveer(?:ed|ing|s)\s+into\b|\bdrift(?:ed|ing|s)\s+into\b|\bsw(?:ung|ing|ings|inging)\s+wide\s+into\b|"
          r"\b(?:moved|moving|move|came|coming|come|pulled|pulling)\s+"
          r"(?:over\s+)?into\s+(?:EGO's|the\s+EGO's|its|our|the\s+same)\s+lane\b|"
          # "entered the lane occupied by EGO": the AV's lane named by it
          r"\b(?:enter(?:ed|ing|s)?|(?:mov|merg|chang|cross)(?:ed|ing|es|e)\s+(?:over\s+)?into)\s+the\s+"
          r"lane\s+(?:occupied\s+by|of)\s+EGO\b|"
          # leaving its own lane toward the AV: "failed to stay in its lane", "drifted out of its lane"
          r"\bfail(?:ed|ing|s)?\s+to\s+(?:stay|remain|keep|maintain)\s+(?:in\s+)?(?:its|their|his|her)\s+lane\b|"
          r"\b(?:drift|veer|swerv|wander|stray|mov)(?:ed|ing|es|e|s)?\s+out\s+of\s+(?:its|their|his|her)\s+lane\b|"
          # ... or told as leaving it ("departed its lane into the path of left-turning traffic", "left its lane")
          r"\b(?:depart(?:ed|ing|s)?|left|leaving|leaves)\s+(?:from\s+)?(?:its|their|his|her)\s+(?:own\s+)?lane\b|"
          # "entered EGO's lane": the AV's own lane, entered from beside it
          r"\benter(?:ed|ing|s)?\s+(?:into\s+)?(?:EGO's|the\s+EGO's|our)\s+(?:travel\s+)?lane\b|"
          # "changed into the AV's lane", "moved over into the middle lane in front of the AV", "partially entered
          # the leftmost through lane ahead of the AV": a move into the lane the AV is in, from the party's side.
          r"\bchang(?:ed|ing|es?)\s+(?:lanes?\s+)?into\s+(?:EGO's|the\s+EGO's|its|our|the\s+same)\s+lane\b|"
          r"\b(?:(?:moved|moving|came|coming|pulled|pulling|merged|merging|swung|cut|cutting)\s+(?:over\s+|wide\s+)?into|"
          r"(?:partially\s+)?enter(?:ed|ing|s)(?:\s+into)?)\s+the\s+(?:[\w-]+\s+){0,3}lane\s+(?:just\s+|directly\s+|"
          r"immediately\s+)?(?:ahead\s+of|in\s+front\s+of)\s+(?:EGO|it)\b|"
          # "attempted to move into the turn lane", "change into the left turn lane": into a named lane, the side
          # read from where the party was
          r"\b(?:chang|mov|merg|shift)(?:ed|ing|es|e|s)?\s+(?:over\s+)?into\s+the\s+(?:[\w-]+\s+){0,3}lane\b|"
          # ... or entered, whatever names it ("partially entered the number 2 lane", "entered the center lane",
          # "entered lane 2"), as "moved into" it (a party's: find_acts leaves the AV's to its own rules; from a
          # driveway or the curb it is the way out, read by its own words)
          r"\b(?:partially\s+)?enter(?:ed|ing|s)?\s+(?:into\s+)?(?:the\s+(?:[\w#.-]+\s+){1,3}lane\b|lane\s+\d\b)"
          r"(?!\s+(?:of\s+traffic|from\s+(?:a|an|the)\s+(?:[\w-]+\s+){0,2}?(?:driveway|lot|garage|curb|alley|parking)))|"
          # "shifted over toward the center lane", "crossed over the lane line into EGO's lane", "moved toward our lane"
          r"\b(?:mov|shift|drift|veer|swerv|edg|nudg|inch|steer|swung|swing|cross|merg|wander)(?:ed|ing|es|e|s)?\s+"
          r"(?:over\s+)?(?:(?:(?:across|over)\s+)?(?:the\s+)?(?:lane\s+(?:line|divider|markings?)|line)\s+)?"
          r"(?:into|toward|towards)\s+(?:the\s+|EGO's\s+|our\s+|its\s+)(?:[\w-]+\s+){0,3}lane\b|"
          # "drifted over the lane line", "veered across the dividing line": over the line between two lanes
          r"\bcross(?:ed|ing|es)?\s+(?:the\s+)?(?:(?:dashed|dividing|white|broken)\s+(?:lane\s+)?|lane\s+)"
          r"(?:line|divider|markings?|boundary)\b|"
          r"\b(?:mov|shift|drift|veer|swerv|edg|cross|wander)(?:ed|ing|es|e|s)?\s+(?:over|across)\s+(?:the\s+)?"
          r"(?:lane\s+(?:line|divider|markings?|boundary)|(?:dividing|white|dashed)\s+(?:lane\s+)?line)"),
    # "moved in front of EGO", "got in front of EGO", "pulled into EGO's path", "cut EGO off": a move across the
    # AV's front; from a lane beside the AV it is a lane change into its lane (sequences.sequence), else no letter.
    # ("cut sharply in front of EGO": any manner adverb; "moved into the path of EGO", "entered EGO's path": the
    # AV's path named either way)
    ("Q", r"\b(?:mov|pull|came|com|got|get|swerv|dart|slid|slip|squeez|nos|jump|swung|swing|duck|veer|drift|edg|"
          r"shift|steer)\w*\s+(?:over\s+|back\s+|out\s+)?(?:(?:\w+ly|right|just)\s+)?"
          r"(?:in\s+front\s+of\s+EGO\b|into\s+(?:(?:EGO's|our)\s+(?:travel\s+)?path|the\s+(?:travel\s+)?path\s+of\s+EGO)\b)|"
          r"\bcut(?:s|ting)?\s+(?:\w+ly\s+)?in\s+front\s+of\s+EGO\b|"
          r"\benter(?:ed|ing|s)?\s+(?:EGO's\s+(?:travel\s+)?path|the\s+(?:travel\s+)?path\s+of\s+EGO)\b|"
          r"\bcut(?:s|ting)?\s+EGO\s+off\b"),
    ("d", r"\b(?:took|take|takes|taking|hung|hang|hangs|hanging)\s+a\s+left\b(?!\s+lane)|"
          rf"\bturn(?:ed|ing|s)?\s+(?:\w+ly\s+)?left\b|\bleft[- ]hand\s+turn\b|\bleft\s+turn{_NOT_A_TURN}\b|"
          r"\bunprotected\s+left\b(?!\s+turn\s+lane)"),
    ("e", r"\b(?:took|take|takes|taking|hung|hang|hangs|hanging)\s+a\s+right\b(?!\s+lane)|"
          rf"\bturn(?:ed|ing|s)?\s+(?:\w+ly\s+)?right\b|\bright[- ]hand\s+turn\b|\bright\s+turn{_NOT_A_TURN}\b|\bwide\s+right\b"),
    # (the name of a lane is no turn: "stopped ... in the dedicated left turn lane, preparing to make a left turn
    # onto northbound X" turns nowhere)
    ("T", rf"\bturn(?:ed|ing|s)?\s+from\s+{_DIR}bound|\bturn(?:ed|ing|s)?\b{_NOT_A_TURN}(?=[^.]{{0,40}}\bonto\b)"),
    # Into a driveway, a lot or a garage off the road is a turn whose side the sentence or the contact tells
    # (sequences.ego_sequence resolves it for the AV; a party's is left to its other words).
    ("D", r"\b(?:enter(?:ed|ing|s)?|(?:pull|turn)(?:ed|ing|s)?\s+into|(?:drive|drives|driving|drove)\s+into)\s+(?:a|an|the)\s+"
          r"(?:[\w-]+\s+){0,2}?(?:driveway|(?:parking\s+)?lot|parking\s+(?:garage|structure)|garage)\b"),
    ("m", r"\bjaywalk(?:ing|ed)\b|\b(?:cross(?:ed|ing|es)|cross(?=\s+(?:the|all|both|several)\b)|walk(?:ed|ing)|ran|running|darted|stepped)\s+(?:into\s+"
          r"|across\s+|in\s+front\s+of\s+)?(?:the\s+|all\s+|both\s+|several\s+)?(?:street|road|roadway|crosswalk|"
          r"lanes|driveway|alley)|"
          # out of a driveway, a lot or an alley by any verb of going forward ("pulled out from", "nosed out of",
          # "began to exit", "departed a parking lot", "pulls out of")
          r"\b(?:(?:pull|nos|edg|inch|eas|roll|creep|driv|mov)(?:ed|ing|es|e|s)?\s+(?:out\s+)?(?:of|from)|"
          r"(?:crept|came|coming|comes|come|drove|rode|riding|walked|walking|ran)\s+out\s+(?:of|from)|"
          r"exit(?:ed|ing|s)?(?:\s+out\s+of|\s+from)?|leaving|left|leaves|depart(?:ed|ing|s)?(?:\s+from)?|"
          r"emerg(?:ed|ing|es|e)\s+(?:out\s+)?from)\s+(?:a|an|the)\s+"
          r"(?:[\w-]+\s+){0,2}?(?:driveway|garage|gas\s+station|"
          r"parking\s+(?:lot|garage|structure|spot|space|area)|alley|(?:shopping\s+)?(?:center|plaza|mall)|business)"
          r"(?!\s+in\s+reverse)|"
          # a walker or rider out on the road from its edge, or across a named street ("rode across Koval Lane")
          r"\bent(?:er|ered|ering|ers)\s+the\s+(?:roadway|road|street)\s+from\s+(?:the\s+|a\s+)?(?:[\w-]+\s+){0,2}?"
          r"(?:curb|sidewalk|median|driveway|parking\s+lot)\b|"
          # (a walker's or rider's verbs of going, in any tense: "pedaled", "rides", "jogged", "hurried", "scooted")
          r"\b(?:walk(?:ed|ing|s)?|ran|runs|running|rode|rides|riding|cycl(?:ed|ing|es)|skat(?:ed|ing|es)|cut|cutting|"
          r"dart(?:ed|ing|s)?|pedal(?:l)?(?:ed|ing|s)|jogg(?:ed|ing)|jogs|dash(?:ed|ing|es)|hurr(?:ied|ying|ies)|"
          r"scoot(?:ed|ing|s)|bik(?:ed|ing|es))\s+"
          r"across\s+(?:[\w.]+\s+){1,3}?(?:street|st|road|rd|avenue|ave|lane|boulevard|blvd|drive|way)\b|"
          # crossing told by where it was not allowed: "crossed mid-block", "crossed against the light"
          # ("crossed from the west side of the street", "crossing from the far curb")
          r"\bcross(?:ed|ing|es)\s+from\s+(?:the\s+)?(?:[\w-]+\s+){0,3}?(?:side|curb|sidewalk|corner|median)\b|"
          r"\bcross(?:ed|ing|es)\b[^.,;]{0,40}?(?:\bmid-?block\b|\bagainst\s+the\s+(?:light|signal|red)\b|"
          r"\boutside\s+(?:of\s+)?(?:the|a)\s+crosswalk\b)|\bent(?:er|ered|ering|ers)\s+(?:the|a)\s+crosswalk\s+from\b|"
          r"\bentered\s+the\s+(?:lane|roadway|road|street)\s+"
          r"(?:of\s+traffic\s+|from\s+(?:the\s+)?(?:[\w-]+\s+){0,2}(?:curb|sidewalk|median)\s+(?:directly\s+|just\s+)?)?"
          r"in\s+front|\bcross(?:ed|ing)\s+(?:in\s+front|the\s+path|its\s+path|EGO's\s+path)|"
          # a pass across the AV's front ("the cyclist passed in front of the vehicle", "was proceeding past the
          # front of EGO"): across its path, not along its side
          r"\b(?:pass(?:ed|ing|es)|(?:proceed(?:ed|ing)|mov(?:ed|ing)|went|going)\s+past)\s+(?:directly\s+|just\s+)?"
          r"(?:in\s+front\s+of|the\s+front\s+of)\s+(?:EGO\b|the\s+vehicle\b)|"
          # ("came off the sidewalk into the roadway", "rolled off the curb": off the roadside only)
          r"\b(?:came|coming|roll(?:ed|ing))\s+off\s+the\s+(?:curb|sidewalk|median)\b|"
          r"\b(?:stepp(?:ed|ing)|dart(?:ed|ing)|jump(?:ed|ing)|walk(?:ed|ing)|ran|running|rode|riding|cut|cutting|"
          r"pedal(?:l)?(?:ed|ing))\s+"
          r"(?:out\s+)?"
          r"(?:off\s+the\s+(?:curb|sidewalk|median|(?:traffic\s+)?island)|into\s+(?:the\s+|EGO's\s+)?(?:path|street|road|roadway|traffic|crosswalk)|"
          r"out\s+(?:from\s+(?:between|behind)|in\s+front)|across\s+(?:the\s+)?(?:street|road|roadway|lanes?|"
          r"intersection|crosswalk))"),
    ("b", r"\baccelerat(?:ed|ing|es|e)\b(?!\s+(?:pedal|forward))|"
          # a foot on the gas: "stepped on the gas", "pressed the accelerator", "floored it", "gunned the engine"
          r"\b(?:stepp(?:ed|ing)|steps?|hit|hitting|press(?:ed|ing|es)?|push(?:ed|ing|es)?|floor(?:ed|ing|s)?|"
          r"mash(?:ed|ing|es)?|stomp(?:ed|ing|s)?)\s+(?:on\s+)?(?:the|its|their|his|her)\s+(?:gas|accelerator|throttle)"
          r"(?:\s+pedal)?\b|\bfloor(?:ed|ing|s)?\s+it\b|\bgunn?(?:ed|ing|s)?\s+(?:it|the\s+engine)\b|"
          r"\bsped\s+(?:forward|ahead|off)\b|"
          r"\b(?:pick(?:ed|ing|s)?\s+up|gain(?:ed|ing|s)?)\s+speed\b|\bsped\s+up\b|\bspeed(?:ing|s)\s+up\b|\bincreas(?:ed|ing|es)\s+"
          r"(?:its\s+|their\s+|his\s+|her\s+)?speed\b"),
    ("c", r"\bslow(?:ed|ing|s)?\b(?![-\s]moving\b)(?!\s+(?:speed|(?:down\s+|\w+ly\s+)?to\s+(?:a\s+|an\s+)?(?:[\w-]+\s+)?(?:stop|halt|standstill)))|\bdecelerat(?:ed|ing|e|es)\b|\bbrak(?:ed|ing|es)\b|"
          r"\bbrake\b(?!\s+(?:and\s+[\w-]+\s+)?(?:lights?|lamps?)\b)|\bapplied\s+(?:the|its|their|his|her)\s+brakes?|\bhard\s+brak|"
          # any hand on the brakes: "hit", "slammed on", "tapped", "pumped", "engaged", "activated" its brakes
          r"\b(?:hit|hits|hitting|slamm(?:ed|ing)\s+on|slams?\s+on|stepp(?:ed|ing)\s+on|steps?\s+on|jamm(?:ed|ing)\s+on|"
          r"tap(?:ped|ping|s)?|(?:pump|engag|activat|depress|press|touch|feather)(?:ed|ing|es|e|s)?(?:\s+on)?)\s+"
          r"(?:the|its|their|his|her)\s+brakes?\b(?!\s+(?:lights?|lamps?|pedal\s+lights?))|"
          r"\b(?:reduc|lower|decreas|cut|cutting|dropp|drop)(?:ed|ing|es|e|s)?\s+(?:its\s+|their\s+|his\s+|her\s+)?speed\b"),
    ("A", r"\b(?:continu(?:ed|ing)|proceed(?:ed|ing)|went|going|drove|driving)\s+straight\b"),
    # ("proceeded to reverse": the verb after it tells the move, not a run along the lane)
    # ("the lane of travel", "its direction of travel": the noun, no manoeuvre)
    ("a", r"\b(?:(?<!of\s)travel(?:l)?(?:ed|ing|s)?|driving|drove|drives|proceed(?:ed|ing|s)?(?!\s+to\s+(?:revers|back))|heading|headed|approach(?:ed|ing|es)|"
          r"continu(?:ed|ing)\s+straight|going\s+straight|went\s+straight|pass(?:ed|ing|es)|follow(?:ed|ing)|near(?:ed|ing)|"
          # the infinitive of a pass a party set out on ("then maneuvered to pass EGO on the left", "attempted to pass"):
          # after a stop of its own, a move off (`i`)
          r"(?<=\bto\s)pass\b(?!\s+(?:through|by)\b)|"
          # "went past EGO on the left", "went by EGO": a pass told with a verb of going
          r"(?:went|going|drove|driving|moved|moving|rode|riding)\s+past|"
          r"(?:went|going|drove|driving|rode|riding)\s+by(?=\s+(?:the\s+)?(?:\w+\s+)?EGO\b)|"
          r"drift(?:ed|ing|s)|enter(?:ed|ing|s)\s+the\s+intersection|"
          r"pull(?:ed|ing)\s+(?:out\s+)?into\s+the\s+intersection|riding|rode|cruising|"
          r"moving|tailgating|overtak(?:e|es|ing|en)|overtook|crossing\s+the\s+intersection|"
          r"pull(?:ed|ing|s)?\s+up\s+(?:behind|beside|next\s+to|alongside)|"
          r"continued\s+(?:its|on|forward|through)|walking|walked|running|"
          # A run told by other verbs of going, or by the heading alone ("was going north", "was operating
          # southbound", "was en route", "was northbound on X"): the AV's and a party's run along its road (each
          # wording, put for "was traveling" in the 158 studyable narratives that use it, changed 10-21 AV strings).
          rf"go(?:ing|es)\s+{_DIR}(?:bound|ward)?|operat(?:ed|ing|es)\s+{_DIR}(?:bound|ward)?|en\s+route|"
          # ("being driven in conventional mode" tells the mode, no run)
          rf"in\s+motion|navigat(?:ed|ing|es)|being\s+driven(?!\s+(?:in\s+(?:[\w-]+\s+)?mode|manually|autonomously|by)\b)|"
          rf"(?:(?<=was\s)|(?<=were\s)){_DIR}bound(?=\s+(?:on|along|in)\b)|"
          r"roll(?:ed|ing|s)?(?!\s+(?:back|backward|backwards|in\s+reverse|stop))(?=\s+(?:forward|along|ahead|down|"
          rf"through|at|on|{_DIR})))\b"),
)
_PHRASE_RES = [(c, compile_gated(p, re.I)) for c, p in PHRASES]
#: Words one of which every match of a code's phrase contains: a sentence without any of them skips that regex
#: (the extractor's hot loop; the results are the same).
_NEEDS: dict[str, tuple[str, ...]] = {
    "j": ("turn",), "k": ("revers", "back"), "l": ("pull", "park", "curb", "side", "shoulder"),
    "h": ("stop", "halt", "standstill", "yield", "rest", "behind"),
    "i": ("began", "begin", "begun", "start", "forward", "proceed", "off", "away", "resum", "depart", "accelerat",
          "advanc", "ahead", "ed up", "es up", "ing up", "ve up"),
    "f": ("left", "oncoming", "opposing", "opposite", "merg", "center", "double", "median", "yellow"),
    "O": ("pull", "traffic", "lane", "park", "curb"),
    "P": ("pull", "swung", "swing", "enter", "nose", "nosi", "ease", "easi", "edge", "edgi", "inch"),
    "g": ("right", "enter", "merg", "bus", "bike", "bicycle", "curb", "transit"),
    "F": ("cut", "lane", "merg", "around", "swerv", "encroach", "veer", "drift", "enter", "path", "line", "over", "join"),
    "d": ("left",), "e": ("right",), "T": ("turn",),
    "b": ("accelerat", "sped", "speeding", "increas", "speed", "gas", "throttle", "floor", "gun"),
    "c": ("slow", "decelerat", "brak", "reduc", "speed", "stop"), "A": ("straight",), "Y": ("turn",),
    "Q": ("front", "path", "off"), "D": ("driveway", "lot", "garage"),
}
_NEEDS_SETS = {code: frozenset(words) for code, words in _NEEDS.items()}
_ALL_NEEDS = tuple(sorted(set().union(*_NEEDS_SETS.values())))
# A bare "to" before a possessive is a place ("stopped to its left began to move"), and before an article an object
# ("yielded to a parallel parking vehicle"), not an infinitive.
_INTENT = compile_gated(r"\b(?:to(?!\s+(?:its|his|her|their|our|my|EGO|a|an|the)\b)|preparing\s+to|waiting\s+to|planning\s+to|"
                     r"prepar(?:e|ed|ing)\s+for|(?:get|getting)\s+ready\s+(?:for|to)|"
                     r"intending\s+to|in\s+order\s+to|should|would|could|might|must|ought\s+to|"
                     r"in\s+preparation\s+for|before(?!\s+(?:eventually|then|finally)\s)|prior\s+to|"
                     # "planning a left turn", "in anticipation of a left turn", "was about to turn left", "waiting to
                     # proceed with a left turn": all ahead
                     r"planning|in\s+anticipation\s+of|about\s+to|(?:waiting|preparing)\s+to\s+\w+\s+with)"
                     r"\s+(?:\w+\s+){0,2}$", re.I)
# ("stopped behind EGO before eventually proceeding forward": an adverb of sequence after "before" tells the next
# step, done, not a plan)
# "continued straight through the intersection before braking and coming to a complete stop", "began to make a right
# turn ... before yielding to a pedestrian": a stop or a slowing told after "before" is the next thing the party did
# (a turn or a lane change after "before" may never have begun: "stopped before turning left").
# An event after "following" makes it a preposition of time ("following a passenger drop-off", "following the
# collision"), not a party followed.
_EVENT_AFTER = compile_gated(r"\s+(?:a|an|the|its)\s+(?:[\w-]+\s+)?(?:drop|pick|collision|impact|contact|incident|crash|"
                             r"stop\b|turn\b|disengage)", re.I)
# (from the turn's own article: "to the left made a right turn" strips "a ", not "the left made a ", which would
# leave the "to" of a place read as an intention)
_TURN_NOUN_PHRASE = compile_gated(r"\b(?:a|an|the|its|their)\s+(?:(?!(?:to|a|an|the|its|their)\b)[\w-]+,?\s+){0,3}$",
                                  re.I)
_TURN_NOUN = compile_gated(r"(?:(?:un)?protected\s+)?(?:turn\b(?!\s+from)|left\b|right\b|u-?\s?turn\b)", re.I)
_APPROACHED = compile_gated(r"\bapproach(?:ed|ing|es)?\s+(?:a|an|the|its)\s+(?:[\w-]+\s+){0,2}$", re.I)
_FOR_MOVE = compile_gated(r"\bfor\s+(?:a|an|the|its)\s+(?:[\w-]+\s+){0,2}$", re.I)
_BEFORE_STOP = compile_gated(r"\bbefore\s+(?:\w+ing\s+and\s+)?$", re.I)
_WHICH_WAS = compile_gated(r",\s*(?:which|that)\s+(?:(?:was|were|had\s+been|had|is)\s+(?:\w+ly\s+)?)?$", re.I)
_STANDING = compile_gated(r"\b(?:stopped|stationary|parked|standing|idle|motionless)\s*$", re.I)
# The side of a turn announced before it is begun ("waiting to turn left", "signaling to make a left turn").
_TURN_SIDE = compile_gated(r"\b(?:turn\s+(left|right)|(left|right)[- ]turn)\b", re.I)
# "slowing to begin to execute a right turn", "waiting for eastbound traffic to clear before proceeding to merge
# right": "begin to", "proceeding to" inside an infinitive of purpose or after "before" is still an intention.
_INTENT_TO_BEGIN = compile_gated(r"\b(?:to|before|prior\s+to)\s+(?:begin(?:ning)?|start(?:ing)?|proceed(?:ing)?)\s+to\s+"
                                 r"(?:\w+\s+){0,2}$", re.I)
# "was making a right turn", "were in the process of changing lanes", "while turning": the manoeuvre in progress.
# ("had been traveling": the progressive told in the past perfect; up to two adverbs between, any manner adverb:
# "was gradually slowing to a stop", "was still slowly creeping", not only "was slowly")
_PROGRESSIVE = compile_gated(r"(?:\b(?:was|were|is|are|had\s+been|has\s+been)\s+"
                             r"(?:(?:already|still|just|\w+ly)\s+){0,2}"
                             r"(?:in\s+the\s+(?:process|middle)\s+of\s+)?|(?:^|[,;]\s*)while\s+)$", re.I)
# The verbs that put a manoeuvre's noun under way ("making a left turn", "executing a lane change").
_DOING_NOUN = r"making|executing|performing|completing|conducting"
# ("swung wide ... while making a right turn": "while" with the noun of the manoeuvre tells it under way too)
_PROGRESSIVE_NOUN = compile_gated(r"\b(?:was|were|is|are|while)\s+(?:(?:already|still|currently|just)\s+)?"
                               r"(?:(?:in\s+the\s+(?:process|middle)\s+of\s+)?(?:" + _DOING_NOUN + r"|negotiating)|"
                               r"in\s+the\s+(?:middle|midst)\s+of|"
                               r"(?:partway|midway|halfway)\s+(?:through|into))\s+(?:a|an|its|the|their|his|her)\s+"
                               r"(?:[\w-]+\s+)?$", re.I)
_MAKING_NOUN = compile_gated(r"\s*(?:" + _DOING_NOUN + r")\s+(?:a|an|its|the|their)\s+(?:[\w-]+\s+)?", re.I)
#: A lane entered, by the words of PHRASES' generic "F" alternative ("entered the number 2 lane").
_ENTERED_LANE = compile_gated(r"(?:partially\s+)?enter(?:ed|ing|s)?\s+(?:into\s+)?(?:the\s+(?:[\w#.-]+\s+){1,3}lane\b|"
                              r"lane\s+\d\b)", re.I)
#: A place off the roadway a party leaves across the road (`m`), named before its move out.
_OFF_ROAD_PLACE = compile_gated(r"\b(?:driveway|parking\s+(?:lot|garage|structure)|garage|alley|carport)\b", re.I)
#: A stop told as the party's first state ("initially stopped", "at first came to a stop", "was originally stopped").
_AT_FIRST = compile_gated(r"\b(?:initially|originally|at\s+first|first)\s+(?:(?:was|were|had)\s+)?$", re.I)
# "abruptly stopped", "suddenly halted": a manner adverb makes a stop an event of a party on its way.
_SUDDEN = compile_gated(r"\b(?:suddenly|abruptly|quickly|unexpectedly|immediately)\s+$", re.I)
# What a stop is made at when it is where a party waited: a sign, a light, a line.
_AT_CONTROL = compile_gated(r"\s+(?:at|for)\s+(?:a|an|the|its)\s+(?:[\w-]+\s+)?(?:stop\s+(?:sign|line|bar)|limit\s+line|"
                            r"(?:traffic\s+)?(?:light|signal)|red|crosswalk)\b", re.I)
# "If left in autonomy, the vehicle would have come to a full stop and remained stopped": a sentence that opens
# with a condition and tells what would have happened tells no manoeuvre at all.
_HYPOTHETICAL = compile_gated(r"^\W*if\b[^.]*\bwould\b", re.I)
# "EGOD disengaged from autonomous mode to make the left turn": the driver took over to do it, and the story goes
# on from there; the purpose of a take-over is the manoeuvre made, not an intention.
_TAKEOVER_TO = compile_gated(r"\b(?:disengag\w*|took\s+(?:over|(?:manual\s+)?control)|(?:transitioned|switched|changed)\s+"
                             r"(?:[\w-]+\s+){0,4}?to\s+manual(?:\s+mode)?)\b[^.,;]{0,60}?\bto\s+(?:\w+\s+){0,2}$", re.I)
# "proceeded into the intersection to turn left": moving into the junction to turn is the turn begun (the contact
# comes in it); to go around something there ("entered the intersection to maneuver around the truck") stays a plan.
_INTO_JUNCTION_TO = compile_gated(r"\b(?:proceed|mov|pull|enter|edg|creep|inch)(?:ed|ing)\s+(?:forward\s+)?(?:into\s+)?"
                                  r"the\s+intersection\s+to\s+(?:\w+\s+){0,2}$", re.I)
# "was attempting to make a right turn ... while yielding to a pedestrian" (or ", yielding to"): an attempt while
# still waiting has not begun.
_ATTEMPT_WAITING = compile_gated(r"\b(?:was|were|is|are)\s+(?:attempting|trying)\s+to\s+(?:\w+\s+){0,2}$", re.I)
# (a full stop before a lower-case word ends an abbreviation, "from 24th St. onto Capp St. while", not the sentence)
_WHILE_WAITING = compile_gated(r"(?:[^.;]|\.(?=\s+[a-z]))*?(?:\bwhile\s+|,\s*)(?:yielding|waiting|stopped)\b")
# "was proceeding south ..., yielding to a pedestrian", "slowed to 3 MPH when yielding": a yield told beside a run
# or a slowing of the AV, with no stop told, is the reason it slowed (`c`), not a stop of its own; told alone as
# what the AV was doing ("was yielding", "while yielding"), it is the AV standing where it waited (`S`).
_YIELD_ASIDE = compile_gated(r"(?:,|\bwhen|\bwhile|\bas)\s*$", re.I)
# ("was heading southbound ..., yielding to a pedestrian": heading is a run as travelling is)
_AV_MOVING = compile_gated(r"\b(?:proceed(?:ed|ing)|travel(?:l)?(?:ed|ing)|head(?:ed|ing)|driving|drove|moving|"
                           r"mov(?:ed|es)\s+forward|slow(?:ed|ing)|decelerat(?:ed|ing)|approach(?:ed|ing)|continu(?:ed|ing))\b",
                           re.I)
_STOP_TOLD = compile_gated(r"\bstop|\bstationary\b|\bwaiting\b|\bhalt|\bstandstill\b|\bparked\b", re.I)
_AT_CONTACT = compile_gated(r"\s+(?:\w+\s+)?(?:just|immediately|moments?|right|a\s+split\s+second)\s+(?:before|prior\s+to)\s+"
                            r"(?:the\s+)?(?:[^.;]{0,60}?\b(?:(?:made|came\s+into)\s+contact|contacted|struck|hit|collided|"
                            r"impact(?:ed)?)|impact|contact|"
                            r"collision)\b", re.I)
# Where a standing AV is ("stopped in traffic", "stopped at the light", "stopped behind a bus").
_IN_PLACE = compile_gated(r"\s+(?:in\s+(?:traffic|(?:a\s+)?(?:queue|line))|"
                          r"at\s+(?:a|the)\s+(?:red\s+)?(?:light|signal|stop\s+sign)|"
                          r"behind\b)", re.I)
# A manoeuvre whose words name the AV as its goal ("into EGO's lane", "the lane occupied by EGO").
_NAMES_EGO = compile_gated(r"\b(?:into|toward|towards)\s+(?:the\s+)?EGO's\b|\blane\s+(?:occupied\s+by|of)\s+EGO\b")
# A stop told with the queue it ended in ("came to a stop in a queue of traffic", "stopped in a line of cars").
# (an adverb of the stop may come between: "stopped completely in a queue of traffic")
# A group noun of traffic right after a participle ("approaching traffic", "passing cross-traffic"): its adjective.
_BEFORE_TRAFFIC = compile_gated(r"\s+(?:cross[\s-]?)?traffic\b", re.I)
#: A yield kept up, told after the verb of keeping on ("while continuing to yield", "still yielding").
_KEPT_ON = compile_gated(r"\b(?:continu(?:ed|ing|es|e)\s+(?:to\s+)?|kept\s+(?:on\s+)?|keeping\s+(?:on\s+)?)$", re.I)
#: The word before a participle used as an adjective of a noun ("a queue of stopped traffic", "past stopped cars").
_ADJECTIVE_PLACE = compile_gated(r"\b(?:of|a|an|the|past|passing|by|between|among|alongside|beside)\s+$", re.I)
_IN_QUEUE = compile_gated(r"\s+(?:\w+ly\s+)?in\s+(?:a|the)\s+(?:\w+\s+)?(?:queue|line)\b", re.I)
_NEGATED = compile_gated(r"\b(?:not|n't|never|without|unable\s+to|failed\s+to)\s+(?:\w+\s+){0,2}$", re.I)
_NEW_CLAUSE = compile_gated(r"\b(?:and|then|but)\s+(?:then\s+)?$", re.I)
_PAST = compile_gated(r"(?:\w+ed|made|took|ran|went|drove|began|cut|swung|rode|struck|hit|came|backed|stopped)\b", re.I)
# "forcing the AV to steer left", "which caused EGO to brake": the object of the causing verb did it; no intention.
_CAUSED = compile_gated(r"\b(?:forc(?:ed|ing|es)|caus(?:ed|ing|es)|prompt(?:ed|ing|s)|requir(?:ed|ing|es)|"
                     r"compell(?:ed|ing))\s+(?:(?:EGO|EGOD|it|him|her|them|the\s+[\w-]+|an?\s+[\w-]+)\s+){1,2}"
                     r"to\s+(?:\w+\s+){0,2}$", re.I)
# "passed EGO on the left to enter the left turn lane": a lane taken by way of a move the party made is no mere
# intention (the pass is how it got there).
_PURPOSE_DONE = compile_gated(r"\b(?:passed|overtook|(?:went|drove|moved)\s+past|went\s+around|drove\s+around|"
                              r"maneuvered\s+around|swerved\s+around)\b[^,.;]{0,50}\bto\s+(?:\w+\s+){0,2}$", re.I)
# (told in the present as in the past: "the AVO disengages and proceeds to make a left turn")
_INTENT_OK = compile_gated(r"\b(?:began|begin|begins|started|start|starts|attempted|attempting|attempts|tried|trying|tries|"
                        r"proceeded|proceeding|proceeds|continued|continuing|continue|continues|beginning|starting|"
                        r"went\s+on|goes\s+on|"
                        # "had to stop for a pedestrian", "was forced to brake": it did
                        r"had|(?:was|were)\s+forced|"
                        # a move made for the next ("then maneuvered to pass EGO on the left", "swerved to go around"):
                        # the purpose is what the move did
                        r"maneuver(?:ed|ing|s)?|manoeuvred|moved|swerved|veered|steered)\s+to\s+"
                        r"(?:\w+\s+){0,2}$", re.I)
_STATE_STOP = compile_gated(r"\b(?:had|has)\s+not\s+(?:yet\s+)?moved\b|\bwaited\s+(?:\w+ly\s+)?(?:at|for|behind|in|on)\b|"
                         r"\b(?:was|were|is|remained|remains|stayed|stays|being|sat|had\s+been)\s+(?:(?!(?:approaching|following|nearing|passing|behind)\s)\w+\s+|\w+-)?(?:stopped|stationary|"
                         r"parked|waiting|sitting|idle|at\s+a\s+(?:complete\s+|full\s+|dead\s+)?stop|at\s+a\s+stand\s?still|at\s+rest|standing|"
                         r"yielding|idling|motionless|not\s+moving|holding\s+(?:its|their|his|her)\s+position|"
                         # ("was paused", "was broken down", "was stuck in traffic", "was in park", "was pulled over at
                         # the curb": standing, in other words)
                         r"paused|immobile|broken\s+down|stuck\s+in\s+(?:traffic|a\s+queue|a\s+line)|in\s+park|"
                         r"pulled\s+over(?!\s+by\b)|in\s+a\s+(?:queue|line)\s+of\s+(?:stopped|stationary)\s+(?:traffic|vehicles|cars))\b|^\s*(?:stopped|parked|stationary|waiting|idling)\b|(?<=\w\s)idling\s+(?:in|at|on)\b|\bwhile\s+(?:in\s+traffic\s+and\s+)?(?:stopped|waiting|"
                         r"parked)\b|\band\s+(?:was\s+)?(?:waiting|stationary)\b|"
                         # "a pickup truck stalled in the lane ahead", "a taxi parked at the curb ahead": its state
                         r"\bstalled\b|\bhad\s+broken\s+down\b|(?<=\w\s)(?<!EGO\s)parked\s+(?:in|at|on|along|by|near|beside|behind|ahead)\b|"
                         # "a sedan waiting at the light ahead", "a sedan queued ahead of it": a noun's state
                         r"(?<=\w\s)(?<!EGO\s)(?:waiting|queued|idling|sitting|standing)\s+(?:\w+ly\s+|still\s+)?"
                         r"(?:in|at|on|for|behind|ahead|to)\b",
                         re.I)
# (the simple past too, as police and operators write it: "a pickup truck traveled west on [XXX]", "drove south")
_HEADING = compile_gated(rf"\b(?:(?:traveling|travelling|heading|headed|facing|driving|proceeding|going|approaching|"
                      rf"moving|riding|operating|cruising|navigating|en\s+route|was|traveled|travelled|drove|"
                      rf"proceeded|went|moved|rode|cruised|continued|continuing)\s+"
                      # "traveling at approximately 20 mph northwest": a speed told between the verb and its heading
                      rf"(?:at\s+(?:approximately\s+|about\s+|around\s+|roughly\s+)?\d+\s*(?:mph|miles\s+per\s+hour|"
                      rf"km/h)\s+)?(?:in\s+the\s+)?(?:north\s+)?({_DIR})(?:bound|ward)?\b|"
                      rf"\bon\s+({_DIR})bound\b|\b({_DIR})bound\b)", re.I)


# The end of a relative clause's verb group before its verb: an adverb, an attempt or a beginning.
_ATTEMPT = r"(?:\w+ly\s+)?(?:(?:attempting|trying|beginning|starting|about|preparing|waiting)\s+to\s+)?"
_RELATIVE = compile_gated(r"\s*,?\s*(?:(?:(?:on|in|at|near|from)\s+(?:[\w.]+\s+){1,4}?|(?:[\w-]+\s+){1,2}?)?"
                       r"(?:that|which|who)\s+)?"
                       r"(?:(?:had\s+been|has\s+been|had|has|was|were|is|then|also)\s+)*"
                       # "a pickup truck that was in the intersection making a left turn": where it was, then the
                       # verb whose object names the manoeuvre
                       r"(?:(?<=was\s)(?:in|at|on)\s+(?:the|a|an)\s+[\w-]+\s+)?" + _ATTEMPT +
                       r"(?:(?:making|executing|performing|completing|initiating)\s+(?:a|an|the|its)\s+(?:[\w-]+\s+)?)?",
                       re.I)
# A short phrase of means or place between a party's noun and its participle ("on foot", "on a bicycle", "in a
# wheelchair").
# Between two participles of one noun: the first one's words, then "and" ("traveling west on [XXX] and crossing").
_AND_PARTICIPLE = compile_gated(r"[^.;,]{0,60}?\s+and\s+(?:then\s+)?", re.I)
_PP_BEFORE_PARTICIPLE = compile_gated(r"\s+(?:on|in|with)\s+(?:(?:a|an|the|its|his|her|their)\s+)?[\w-]+\s+", re.I)
# After a possessor inside a party's phrase of place ("to EGO's right, which was ..."): the place noun, then the
# relative pronoun.
_POSSESSED_RELATIVE = compile_gated(r"\s*[\w-]+(?:\s+[\w-]+)?\s*,\s*(?:that|which|who)\s+"
                                    r"(?:(?:had\s+been|has\s+been|was|were|is|then|also)\s+)*" + _ATTEMPT, re.I)


@dataclass(frozen=True)
class Act:
    sent: int
    pos: int
    code: str  # a-m, "F" (lane change, side unknown), "T" (turn, side from headings), "S" (stopped state),
    # "O" (out of a parking spot), "P" (pulled out: "O" if it was parked, else a start), "Q" (across the AV's
    # front: a lane change from a lane beside it, else nothing), "D" (into a driveway or lot: a turn, its side
    # told by the sentence or the contact)
    who: int  # entity index, -1 = ego
    text: str
    #: Told in the progressive ("was making a right turn", "a truck merging onto the highway", "while changing
    #: lanes"): the manoeuvre was under way when the story took it up, so the party's string opens with it.
    under_way: bool = False
    #: A stop told as something the party did on its way ("the sedan stopped", "abruptly stopped", "halted"), not
    #: as where it stood ("a vehicle stopped behind EGO").
    on_its_way: bool = False


#: The heading a turn ends on, named after it: "turned north onto X", "turned to head north".
_TURNED_TO = compile_gated(rf"\bturn(?:ed|ing|s)?\s+(?:to\s+(?:head|travel|go)\s+)?({_DIR})(?:bound|ward)?\b", re.I)


def turn_by_headings(s: str, start: int, b: int, e: int) -> str | None:
    """A turn whose side is told only by headings ("a sedan traveling eastbound on 16th Street turned onto
    northbound Mission Street", "traveling west ... turned south onto X"): from the last heading told from `start`
    (a party's mention, so not the AV's told before it) to the turn at `b`, to the first after it in the same clause.
    """
    came = [m for m in _HEADING.finditer(s, start, b)]
    clause = fre.split(r"[,;]", s[b:e + 80])[0]
    went = _TURNED_TO.search(clause) or _HEADING.search(clause)
    if not came or went is None:
        return None
    h0 = CARDINALS[next(g for g in came[-1].groups() if g).lower()]
    h1 = CARDINALS[next(g for g in went.groups() if g).lower()]
    return {90: "e", 270: "d", 180: "j"}.get((h1 - h0) % 360)


def heading_of(s: str) -> int | None:
    """The first compass heading in `s`, in degrees (north 0, clockwise)."""
    m = _HEADING.search(s)
    if not m:
        return None
    word = (m.group(1) or m.group(2) or m.group(3)).lower()
    return CARDINALS.get(word)


def turn_from_headings(s: str) -> str | None:
    """"from southbound X to westbound Y" / "southbound ... onto westbound": the turn's side by the heading change."""
    found = [CARDINALS[w.lower()] for w in fre.findall(rf"\b({_DIR})bound\b", s, re.I)]
    if len(found) < 2:
        return None
    diff = (found[1] - found[0]) % 360
    return {90: "e", 270: "d", 180: "j"}.get(diff)


# A subjectless opening clause of standing still ("While stopped,", "While yielding to pedestrians,"): the narratives
# use it of the AV they tell about, whatever the main clause's subject (a dangling modifier, not the party's state).
_OPENING_WAIT = compile_gated(r"\s*(?:while|when|as)\s+(?:still\s+)?(?:in\s+traffic\s+and\s+)?(?:stopped|stationary|waiting|yielding|idling|"
                              r"at\s+(?:a\s+)?(?:stop|standstill))\b[^,;]{0,80},", re.I)
# A place told against the AV inside a party's noun phrase: "the vehicle directly in front of EGO".
_PLACE_OF_EGO = compile_gated(r"\s+(?:directly\s+|immediately\s+|right\s+|just\s+)?(?:in\s+front\s+of|behind|ahead\s+of|"
                              r"next\s+to|beside|alongside)\s+", re.I)
_DEVIATION = compile_gated(r"(?:drift|veer|swung|swing|wander)", re.I)
_ASIDE = compile_gated(r",\s*(?:as|while|when|after|before|because)\b[^,]*,\s*$", re.I)


def who_for(pos: int, ments: list[Mention], fallback: int | None, sentence: str = "") -> int | None:
    """Entity index (-1 ego) whose clause covers `pos`: latest subject mention before it, else the first after
    (an opening "While reversing, the car ..."), except after "During ...", which continues the last story."""
    best: Mention | None = None
    for m in ments:
        if m.start <= pos and m.subject:
            best = m
    if best is not None and sentence and (aside := _ASIDE.search(sentence[:pos])) and aside.start() < best.start:
        # "A cyclist in the bike lane, as EGO waited for traffic to clear, moved left": a clause set off by commas
        # is an aside; the verb after it belongs to the subject before it.
        outer = [m for m in ments if m.start < aside.start() and m.subject]
        if outer:
            best = outer[-1]
    if best is not None and best.kind == "pron":
        # "when it slowed to a stop": the pronoun continues the sentence's (or the story's) last subject.
        earlier = [m for m in ments if m.start < best.start and m.subject and m.kind != "pron"]
        if earlier:
            best = earlier[0]
        else:
            return fallback
    if best is None and fre.match(r"\s*(?:during|following)\b", sentence, re.I):
        return fallback
    if best is None and fallback in (-1, None) and _OPENING_WAIT.match(sentence):
        # "While stopped, a vehicle approached from behind": the AV the story is about stood (also where the
        # narrative opens so: "While in traffic and stopped at 0mph in autonomy, a motorized scooter ... clipped
        # the May Mobility vehicle's mirror")
        return -1
    if best is None:
        for m in ments:
            if m.start > pos and m.subject:
                best = m
                break
    if best is None:
        return fallback
    return -1 if best.kind in ("ego", "egod") else (best.entity if best.entity >= 0 else fallback)


#: A verb form that tells a move going on: the participle ("turning"), or a state of going told after "was" ("was en
#: route", "was in motion", "was being driven", "was northbound on X"), read as "was traveling" is.
_GOING_FORM = compile_gated(rf"\w+ing\b|en\s+route\b|in\s+motion\b|being\s+driven\b|{_DIR}bound\b", re.I)


def _in_progress(s: str, b: int, e: int, rel: Mention | None) -> bool:
    """Is the manoeuvre at s[b:e] told as already in progress: "was turning right", "was making a right turn",
    "while changing lanes", or a participle right after its doer as subject ("A truck merging onto the freeway")?"""
    before = s[max(0, b - 70):b]
    if _GOING_FORM.match(s[b:e]):
        # The participle opens the subject's own clause ("A truck merging onto ... moved into"); after an object of
        # seeing ("seeing the car crossing the centerline") it tells what was seen, not when it began.
        return bool(_PROGRESSIVE.search(before)) or (rel is not None and rel.subject and not s[rel.end:b].strip())
    # So does the noun of the manoeuvre after a participle ("a passenger car making a left turn in the leftmost
    # lane crossed into ..." as "a passenger car turning left in ...")
    return bool(_PROGRESSIVE_NOUN.search(before)) or (rel is not None and rel.subject and
                                                       bool(_MAKING_NOUN.fullmatch(s[rel.end:b])))


def find_acts(sent_idx: int, s: str, ments: list[Mention], fallback: int | None,
              prior: Sequence[str] = ()) -> list[Act]:
    """The manoeuvres in one sentence, each attributed to its doer; `prior` are the sentences just before it,
    where a turn begun without a side ("attempted to turn behind EGO") was announced ("signaling to make an
    unprotected left turn")."""
    spans: list[tuple[int, int, str]] = []
    low = s.lower()
    present = {w for w in _ALL_NEEDS if w in low}  # one pass over the words, not one per code
    for code, rx in _PHRASE_RES:
        needs = _NEEDS_SETS.get(code)
        if needs is not None and not needs & present:
            continue
        for m in rx.finditer(s):
            start = m.start()
            if any(start < e and m.end() > b for b, e, _ in spans):
                # An earlier (more specific) phrase already covers this text; but where it took only the verb of
                # a move into a lane ("began to proceed | into EGO's lane"), the lane entered is read on its own.
                into = m.group(0).lower().find("into ") if code in ("f", "g", "F") else -1
                start = m.start() + into
                if into <= 0 or any(start < e and m.end() > b for b, e, _ in spans):
                    continue
            spans.append((start, m.end(), code))
    for m in _STATE_STOP.finditer(s):
        # (its own words win where they hold "stop", or deny a move: "was not moving")
        if not any(m.start() < e and m.end() > b for b, e, _ in spans) or "stop" in m.group(0).lower() or \
                "not moving" in m.group(0).lower():
            spans.append((m.start(), m.end(), "S"))
    out: list[Act] = []
    if _HYPOTHETICAL.search(s):
        spans = []
    for b, e, code in sorted(spans):
        before = s[max(0, b - 40):b]
        caused = _CAUSED.search(before)
        # "failed to yield and turned left": a past tense after the conjunction opens a clause of its own, out of
        # the reach of the intention or negation before it ("preparing to stop and turn" stays an intention).
        own_clause = bool(_NEW_CLAUSE.search(before)) and bool(_PAST.match(s[b:e]))
        # "preparing to make an unprotected left turn": the turn's noun phrase (article and modifiers) does not
        # count toward the intention's reach
        aim = _TURN_NOUN_PHRASE.sub("", before) if code in "dejT" and _TURN_NOUN.match(s[b:e]) else before
        if _INTENT.search(aim) and not caused and not own_clause and \
                not (code in "hc" and _BEFORE_STOP.search(before)) and \
                (not _INTENT_OK.search(before) or _INTENT_TO_BEGIN.search(before)) and \
                not (code in "fgF" and _PURPOSE_DONE.search(s[max(0, b - 80):b])) and \
                not _TAKEOVER_TO.search(s[max(0, b - 100):b]) and \
                not (code in "dejY" and _INTO_JUNCTION_TO.search(s[max(0, b - 80):b])):
            continue
        if code in "defgjDFTY" and _ATTEMPT_WAITING.search(before) and _WHILE_WAITING.match(s[e:]):
            continue
        if code in "dejT" and _TURN_NOUN.match(s[b:e]) and _APPROACHED.search(before):
            continue  # "as EGO approached a right turn from Cesar Chavez onto Evans Avenue": the turn ahead, not made
        if code in "defgjFT" and _FOR_MOVE.search(before):
            continue  # "stopped in the left turn lane for an unprotected left turn": the turn it stood there for
        if code == "c" and _AT_CONTACT.match(s[e:]):
            continue  # "braked just before the front of EGO made contact": a reaction at the contact, no manoeuvre
        if _NEGATED.search(before) and not own_clause:
            continue  # "did not immediately proceed"
        if code in ("h", "S") and fre.search(r"\b(?:vehicles|cars|trucks|traffic|queue|line\s+of\s+\w+)\s+"
                                            r"(?:(?:that|which)\s+(?:(?:were|was|had)\s+(?:been\s+)?)?)?$", before, re.I):
            continue  # "a line of vehicles stopped at a red light": a group's state, not the subject's ("traffic that
            # was stopped": the auxiliary may be inside the state's own span)
        if code == "a" and s[b:e].lower() == "following" and _EVENT_AFTER.match(s[e:]):
            continue  # "parked at the curb following a passenger drop-off": "after", no following of anyone
        if fre.search(r"\btraffic\s+$", before) and fre.match(r"\w+ing\b", s[b:e]):
            continue  # "to gain visibility of oncoming traffic traveling southbound": traffic's move, no party's
        if code == "a" and fre.match(r"\w+ing$", s[b:e]) and _BEFORE_TRAFFIC.match(s, e):
            continue  # "was waiting for approaching traffic": the participle describes the traffic, no one's move
        if code in ("h", "S", "a", "c") and fre.search(r"\b(?:the|a|an|its|their)\s+$", before) and \
                fre.match(r"\s+(?:EGO\b|[A-Za-z])", s[e:e + 12]):
            continue  # "the stopped EGO", "the approaching car": an adjective of a noun, not a manoeuvre
        if code == "F" and fre.search(r"\bthe\s+$", before, re.I) and fre.match(r"\s+(?:EGO\b|[A-Za-z])", s[e:e + 12]):
            continue  # "due to the encroaching pickup": a party named again by what it did, not a new move
        if code == "F" and fre.search(r"\b(?:during|after|throughout|completing|completed)\s+(?:the|this|that|its)\s+$",
                                      before, re.I):
            continue  # "During the lane change, ...": the move told before, named again
        inside = [m for m in ments if m.kind == "party" and m.start <= b < m.end and m.entity >= 0]
        if code == "a" and before.endswith("-") and not inside:
            continue  # "a gap in a slow-moving traffic stack", "the self-driving system": an adjective, no party's move
        # "the approaching vehicle", "a jaywalking pedestrian": a participle in the noun phrase is its own move;
        # "a scooterist traveling north", "a cyclist that had been traveling behind": so is a relative clause.
        left = [m for m in ments if m.end <= b]
        rel = left[-1] if left and _RELATIVE.fullmatch(s[left[-1].end:b]) else None
        if rel is None and len(left) >= 2 and s[left[-1].start:left[-1].end].endswith("'s") and \
                left[-2].kind == "party" and _POSSESSED_RELATIVE.fullmatch(s[left[-1].end:b]) and \
                not fre.search(r"[,;]", s[left[-2].end:left[-1].start]):
            # "a vehicle traveling in the lane to EGO's right, which was attempting to merge left": the clause
            # tells of the noun phrase's head (the vehicle), not of the possessor inside its place.
            rel = left[-2]
        if rel is not None and rel.kind in ("ego", "egod") and not rel.subject and len(left) >= 2 and \
                left[-2].kind == "party" and left[-2].entity >= 0 and fre.search(r",\s*(?:that|which|who)\b", s[rel.end:b]) \
                and _PLACE_OF_EGO.fullmatch(s[left[-2].end:rel.start]):
            # "the vehicle directly in front of EGO, which stopped": the clause tells of the noun phrase's head,
            # not of the AV named in its place
            rel = left[-2]
        if rel is not None and not rel.subject and not fre.search(r"\b(?:that|which|who)\b|ing\b", s[rel.end:b]) and \
                not (s[rel.end:b].strip() == "" and fre.match(r"\w+ing\b", s[b:e], re.I)):
            # "from the left of EGO was slowing": EGO here is no subject; but "seeing the oncoming vehicle crossing
            # the centerline": a participle right after a noun tells that noun's move.
            rel = None
        elif rel is not None and not rel.subject and fre.match(r"\s*,", s[rel.end:b]) and \
                not fre.search(r"\b(?:that|which|who)\b", s[rel.end:b]):
            # "attempted to go around EGO, attempting to merge with traffic": a participle set off by a comma after
            # the object tells more of the clause's subject (a free adjunct), not of the object before the comma.
            rel = None
        if rel is not None and not rel.subject and code in "abcfgF" and (
                _STANDING.search(rel.mods) or _STANDING.search(s[max(0, rel.start - 24):rel.start])):
            # "struck the rear of the stopped EGO traveling at 5.5 miles per hour": what stood still did not
            # travel; the participle tells of the clause's subject, the striker.
            rel = None
        if rel is None and left and left[-1].kind == "party" and fre.match(r"\w+ing\b", s[b:e]) and \
                _PP_BEFORE_PARTICIPLE.fullmatch(s[left[-1].end:b]):
            rel = left[-1]  # "a person on foot crossing the street": the participle tells of the noun, not the subject
        if rel is None and out and out[-1].who >= 0 and fre.match(r"\w+ing\b", s[b:e]) and \
                fre.match(r"\w+ing\b", out[-1].text) and not any(out[-1].pos < m.start < b for m in ments) and \
                _AND_PARTICIPLE.fullmatch(s[out[-1].pos + len(out[-1].text):b]):
            # "it detected a vehicle traveling west on [XXX] and crossing into the opposing lane": a participle
            # joined by "and" to the party's own participle tells more of that party.
            rel = next((m for m in left if m.entity == out[-1].who), None)
        # "The sedan stopped and ...": the finite verb of a subject the story already named; "a vehicle stopped
        # in the right lane": a past participle telling where a noun stood.
        finite = code == "h" and bool(left) and left[-1].subject and left[-1].det == "the" and \
            not s[left[-1].end:b].strip()
        if (code == "h" and s[b:e].lower() == "stopped" and not finite or code == "S" and fre.match(
                r"(?:waiting|queued|idling|stalled|parked|sitting|standing)\b", s[b:e], re.I)) and left and \
                left[-1].kind == "party" and left[-1].entity >= 0 and not s[left[-1].end:b].strip():
            # "navigated around a double-parked vehicle stopped in the right lane": a past participle right after
            # a noun is that noun's state, not the subject's stop.
            out.append(Act(sent=sent_idx, pos=b, code="S", who=left[-1].entity, text=s[b:e]))
            continue
        made = [m for m in ments if caused and b - len(before) + caused.start() < m.start < b and
                m.kind in ("ego", "egod", "party")]
        if made:
            who = -1 if made[-1].kind in ("ego", "egod") else made[-1].entity
            if who < 0 and made[-1].kind == "party":
                continue
        elif inside:
            who = inside[0].entity
        elif rel is not None and rel.kind in ("party", "obstacle") and rel.entity >= 0:
            who = rel.entity
        elif rel is not None and rel.kind in ("ego", "egod"):
            who = -1
        else:
            who = who_for(b, ments, fallback, s)
            group = [m for m in ments if m.subject and m.end <= b][-1:]
            if group and group[0].kind == "group" and group[0].entity < 0 and \
                    not s[group[0].start:group[0].end].lower().startswith("both") and \
                    not any(m.subject and m.kind != "group" and group[0].end <= m.start < b for m in ments):
                continue  # "Several vehicles passed EGO": an unnumbered group's move is no party's (sketch.md)
        if who == -1 and (which := _WHICH_WAS.search(before)) and left and \
                fre.search(r"\b(?:a|an|the)\s", s[left[-1].end:b - len(before) + which.start()], re.I):
            continue  # "EGO approached a motorized articulating boom lift ("ABL"), which was stopped in EGO's lane":
            # a relative clause tells of the noun before it, one the AV's clause took as its object, not of the AV
        if who is None:
            continue
        if who == -1 and _NAMES_EGO.search(s[b:e]):
            continue  # "the left front wheel from an SUV ... rolled into EGO's lane of travel": the AV does not move
            # into its own lane; the doer is something the story does not name as a party here
        subj = [m for m in ments if m.subject and m.end <= b]
        if subj and subj[-1].kind == "group" and s[subj[-1].start:subj[-1].end].lower().startswith("both") and \
                code in "abcdefghikF" and who >= 0:
            # "both vehicles proceeded forward": the AV did it too.
            out.append(Act(sent=sent_idx, pos=b, code=code, who=-1, text=s[b:e]))
        if code == "F" and who == -1 and _ENTERED_LANE.match(s, b):
            continue  # the AV's entry into a lane is read by its own rules (a turn lane entered is a move left)
        if code in "PO" and who >= 0 and _OFF_ROAD_PLACE.search(s, max(0, b - 90), b):
            # "stopped in a driveway on the right ... pulled out": out of the driveway, across the road; "an SUV
            # parked in a carport to the right of the Waymo AV began to exit its parking stall": a space off the
            # road (a carport, a lot, a garage) is left across the way, not from the curb into a lane
            code = "m"
        if code == "h" and s[b:e].lower() == "stopped" and fre.match(r"\s+(?:traffic|vehicles|cars|queue)\b", s[e:]) \
                and (any(x.code == "S" and x.who == who for x in out) or
                     (who == -1 and _ADJECTIVE_PLACE.search(s, max(0, b - 12), b))):
            # "EGO was stopped ... behind stopped traffic": the queue's state, the AV's told already; "passing a queue
            # of stopped traffic": the adjective of what the AV went by, after an article or a preposition
            continue
        if code in "hl" and fre.search(r"\bhad\s+(?:already\s+|just\s+)?$", before, re.I):
            # "had come to a stop", "had pulled up to the curb ... for a requested passenger pickup": where it stood
            # when the story begins, not an event of it
            code = "S"
        elif code == "h" and who >= 0 and _AT_CONTROL.match(s[e:e + 60]):
            code = "S"  # a party's stop "at the stop sign", "for the red light": where it waited
        elif code == "h" and who >= 0 and _AT_FIRST.search(before):
            # "a passenger car traveling westbound initially stopped behind the Waymo AV, then proceeded to pass":
            # the stop told as the first state is where the party stood when the story begins (3 of 3 studyable
            # reports telling a party's stop "initially": gold `stopped`, the string from its move off)
            code = "S"
        if code == "S" and fre.match(r"(?:waiting|queued|idling|sitting|standing)\b", s[b:e], re.I):
            # "a vehicle that was stopped in the travel lane waiting to parallel park": a participle right after a
            # party's state, in the same clause, tells more of that state.
            prev = next((x for x in reversed(out) if x.sent == sent_idx and x.code == "S" and x.who >= 0), None)
            if prev is not None and not fre.search(r"[,;]|\b(?:and|but|when|while|as)\b",
                                                   s[prev.pos + len(prev.text):b], re.I):
                who = prev.who
        if code == "h" and who == -1 and s[b:e].lower() == "stopped" and fre.search(r",\s*$", before) and \
                _IN_PLACE.match(s[e:]):
            code = "S"  # "EGO was in the right lane, stopped in traffic behind a bus": where it stood
        elif code == "h" and who == -1 and _IN_QUEUE.match(s, e):
            # "was traveling southeastbound on [XXX] and came to a stop in a queue of traffic for a red light": the
            # stop names where the AV then stood, in the queue, as "was stopped in traffic" does (5 of 5 studyable
            # reports with the AV stopping "in a queue" are gold `stopped`; "for a queue" is a stop made, `ah`)
            code = "S"
        if code in "hS" and who == -1 and fre.search(r"\bafter\s+(?:having\s+|(?:it|EGO)\s+had\s+)?$", before, re.I):
            code = "S"  # "was proceeding through the intersection after stopping": it had stood (sequences)
        if code == "h" and who == -1 and s[b:e].lower().startswith("yield") and _KEPT_ON.search(before):
            continue  # "began to slowly move ahead while continuing to yield to the traffic ahead": the yield it kept
            # up as it moved is how it moved, no stop
        if code == "h" and who == -1 and s[b:e].lower() == "yielding":
            if _YIELD_ASIDE.search(before) and _AV_MOVING.search(s[:b]) and not _STOP_TOLD.search(s[:b]):
                code = "c"
            elif fre.search(r"(?:\b(?:was|were|is|are|while|and)|,)\s*$", before, re.I):
                code = "S"  # "was yielding", "while yielding", ", yielding", "was stopped ... and yielding": where
                # the AV stood waiting (no event); told in the present ("is yielding") as in the past
        if code == "T" and who >= 0:
            own = [m for m in ments if m.entity == who and m.end <= b]
            code = (turn_by_headings(s, own[-1].start, b, e) if own else None) or code
        if code == "Y":
            # "waiting to turn left ... began its turn": the turn it was said to wait for
            side = _TURN_SIDE.findall(s[:b]) or _TURN_SIDE.findall(" ".join(prior))
            if not side:
                continue
            code = "d" if "left" in (side[-1][0] or side[-1][1]).lower() else "e"
        out.append(Act(sent=sent_idx, pos=b, code=code, who=who, text=s[b:e],
                       under_way=_in_progress(s, b, e, rel),
                       on_its_way=code == "h" and (finite or bool(_SUDDEN.search(before)) or
                                                   # "the vehicle in front of EGO, which stopped": a relative
                                                   # clause's own verb, an event of the party
                                                   (rel is not None and rel.kind == "party" and
                                                    bool(fre.search(r"(?:^|[\s,])(?:which|that|who)\s+(?:then\s+)?$",
                                                                    before))) or
                                                   s[b:e].lower().startswith("halt"))))
    # A state "was stopped" and the "stopped" inside it are one fact; "accelerated while still in reverse" is
    # the backing up, not a speed-up forward.
    dedup: list[Act] = []
    for k, a in enumerate(out):
        nxt = out[k + 1] if k + 1 < len(out) else None
        if a.code in "lO" and dedup and dedup[-1].code == "k" and dedup[-1].who == a.who and \
                fre.fullmatch(r"\s*(?:to\s+|in\s+order\s+to\s+)?", s[dedup[-1].pos + len(dedup[-1].text):a.pos]):
            # "reversing into a parking space", "began to reverse to parallel park": where (or why) the backing
            # was headed; the string ends at the contact. "proceeded to reverse to exit the parking stall": out of
            # the space in reverse is the backing itself (as "left the space in reverse" is, PHRASES "O")
            continue
        turn = next((x for x in reversed(dedup) if x.who == a.who), None)
        if a.code in "de" and a.who >= 0 and turn is not None and turn.code == "m" and turn.sent == a.sent and \
                fre.fullmatch(r"[^,.;]{0,60}", s[turn.pos + len(turn.text):a.pos]):
            # "an SUV was exiting a shopping center driveway making a right turn onto southbound [XXX]", "exited a
            # driveway and turned right onto": the way out of the driveway or lot is the turn onto the road (the
            # gold `e`), and the party's first move there: no run along the AV's road opens its string (the turn
            # opens it, as one told under way does)
            dedup[dedup.index(turn)] = Act(a.sent, a.pos, a.code, a.who, a.text, True)
            continue
        if a.code in ("f", "g", "F") and a.text[:4].lower() == "into" and turn is not None and \
                turn.code in ("d", "e", "j", "k", "m", "O", "P", "T") and turn.sent == a.sent and \
                0 <= a.pos - turn.pos <= 70:
            # "turned right into EGO's lane", "pulled out of its space into the left lane", "began reversing
            # further into EGO's lane", "a wide right turn from eastbound [XXX] into the left lane" (a turn whose
            # side the headings tell, "T"): where it ended
            continue
        if a.code in ("f", "g", "F") and a.text[:4].lower() == "into" and turn is not None and \
                turn.code in ("f", "g", "F") and turn.sent == a.sent and 0 <= a.pos - turn.pos - len(turn.text) <= 3:
            if turn.code == "F":  # "merged | into the left lane": one move, its side told by the lane
                dedup[dedup.index(turn)] = Act(turn.sent, turn.pos, a.code, turn.who, turn.text + " " + a.text,
                                               turn.under_way)
            continue
        if (a.code in ("F", "Q") or (a.code in ("f", "g") and a.text[:5].lower() == "enter")) and turn is not None and \
                turn.code in ("d", "e") and fre.fullmatch(r"[^,.;]{0,60}\band\s+(?:\w+ly\s+)?",
                                                         s[turn.pos + len(turn.text):a.pos]) and \
                not _DEVIATION.match(a.text):
            # "turned right and cut (or pulled) in front of EGO", "... and entered the right lane": where the turn
            # ends; but "turned left and drifted into EGO's lane" strays from it: a move of its own.
            continue
        if a.code in ("a", "b") and nxt is not None and nxt.code == "k" and nxt.who == a.who and fre.fullmatch(
                r"\s*(?:\w+ly\s+)?(?:while|when)?\s*(?:still\s+)?in\s+", s[a.pos + len(a.text):nxt.pos], re.I):
            continue
        if dedup and a.who == dedup[-1].who and a.sent == dedup[-1].sent and {a.code, dedup[-1].code} == {"S", "h"} \
                and a.pos <= dedup[-1].pos + len(dedup[-1].text) + 1:
            # (one span inside the other, or next to it; "came to a stop while yielding" is a stop, then a state)
            # The AV's stop told as an event and a state told right after it ("came to a stop while waiting for a
            # pickup truck"): the event stays, the state is its result (sequences: the official gold's `ah`).
            after_stop = dedup[-1].code == "h" and a.who == -1 and a.pos >= dedup[-1].pos + len(dedup[-1].text)
            if dedup[-1].code == "h" and not after_stop:
                dedup[-1] = a
            continue
        dedup.append(a)
    return dedup
