"""Road, environment and signal fields read from the whole narrative (sketch.md's rules for hard cases)."""

from __future__ import annotations

import re

from ..sketch import Environment, RoadInfo
from . import fastre as fre
from .fastre import compile_gated
from .lexicon import CARDINALS, NUMBER_WORDS

#: A stop sign junction told by its legs ("a four-way stop", "an all way stop", "a 2-way stop").
_WAY_STOP = r"\b(?:all|two|four|three|\d)[-\s]way\s+stop\b"
#: A traffic light by its names ("traffic signal", "traffic-control signal", "traffic control light").
_TRAFFIC_LIGHT = r"\btraffic[\s-]+(?:control\s+)?(?:light|signal)s?\b"
#: A light told by its colour after it ("a light that was red", "the signal was still green", "a stoplight that was
#: red"): a traffic light.
_LIGHT_WAS = (r"\b(?:stop\s?)?(?:light|signal)\s+(?:that\s+|which\s+)?(?:was|is|remained)\s+(?:still\s+)?"
              r"(?:red|green|yellow|amber)\b")
#: A red told without its light, as police write it ("stopped at a red", "waiting for the red when"): the colour
#: ends its phrase (not "a red sedan").
_AT_A_RED = (r"\b(?:at|for)\s+(?:a|the)\s+red(?=\s*(?:[,.;:]|$|\b(?:and|when|while|as|at|on|in|before|with|then|until|"
             r"facing|behind|near|for|to|waiting)\b))")
#: Waiting in a turn pocket: turn lanes end at a junction.
_IN_TURN_POCKET = (r"\b(?:stopped|waiting|queued|traffic|traveling|travelling|proceeding|driving)\s+in\s+(?:a|the)\s+"
                   r"(?:(?:dedicated|leftmost|rightmost|left-most|right-most)\s+)?(?:left|right)[- ]turn\s+"
                   r"(?:pocket|lane|only\s+lane)\b")
_TURN_POCKET = compile_gated(_IN_TURN_POCKET, re.I)
_JUNCTION = compile_gated(_LIGHT_WAS + "|" + _AT_A_RED + r"|\bintersection\b|"
                          # "at the corner of Bush Street and Grant Avenue" (not "the front corner of EGO": a street's
                          # name, capitalised or redacted, follows)
                          r"\b(?:at|on)\s+the\s+(?:\w+\s+)?corner\s+of\s+(?-i:[A-Z0-9\[])|\bcross\s*roads\b|\bcrosswalk\b|\b(?:stop|yield)\s+signs?\b|"
                       + _TRAFFIC_LIGHT + r"|\b(?<!its\s)(?<!their\s)stop\s?lights?\b|"
                       r"\b(?:at|for)\s+the\s+(?:light|signal)\b|"
                       # ("a red left-turn arrow": the arrow of a turn lane's light)
                       # (not "solid yellow", "flashing amber": a lane line, a truck's lamps)
                       r"\b(?:red|green|yellow)\s+(?:(?:left|right)[- ]turn\s+)?(?:light|arrow|signal|ball|indication|"
                       r"phase)\b|\b(?:steady|circular)\s+(?:red|green|yellow)\b|"
                       # the line a vehicle stops at before a junction: "stop line", "stop bar", California's "limit line"
                       r"\b(?:stop|limit)\s+(?:bar|line)\b|"
                       + _WAY_STOP + r"|\bjunction\b|\bcross[\s-]+traffic\b|\bcross[\s-]?streets?\b|"
                       r"\bthe\s+light\s+turned\b|" + _IN_TURN_POCKET, re.I)
_CONTROL_AT = compile_gated(r"\b(?:at|for)\s+(?:a|an|the)\s+(?:red\s+(?:traffic\s+)?(?:light|signal)|(?:stop|yield)\s+sign|stop\s?light|"
                          r"(?:all|two|four|three|\d)[-\s]way\s+stop|traffic[\s-]+(?:control\s+)?(?:light|signal))\b|"
                          + _AT_A_RED, re.I)
# (up to six words between: "EGO had been stopped in autonomous mode turning right", "was at a stop in autonomous
# mode turning right")
_AV_TURNING = compile_gated(r"\bEGO\b[^.;]{0,60}?\b(?:was|is|had)\s+(?:\w+\s+){0,6}?(?:turning|making\s+(?:a|an)\s+"
                          r"(?:\w+\s+)?(?:left|right)\s+turn)", re.I)
_NOT_JUNCTION = compile_gated(r"\b(?:near|before|past|from|close\s+to)\s+the\s+intersection\b|"
                           r"\bbefore\s+(?:reaching\s+)?the\s+intersection|\bnear\s+the\s+intersection|"
                           # a junction left behind: "after clearing the intersection", "having passed through the
                           # intersection"
                           # (the AV named between: "After the Waymo AV crossed the intersection with [XXX], an SUV
                           # ..."; or gone through it by another verb: "after EGO proceeded through the intersection")
                           r"\b(?:after|having|had)\s+(?:(?:EGO|it)\s+(?:had\s+)?)?(?:(?:clear|pass|exit|travers|cross)"
                           r"(?:ed|ing)\s+(?:through\s+)?|(?:proceed(?:ed|ing)|travel(?:l)?(?:ed|ing)|went|going|drove|"
                           r"driving)\s+through\s+)the\s+intersection\b", re.I)
# Someone coming out of a driveway, a lot or a garage (not out of a parking space: a parking manoeuvre).
_OUT_OF_A_LOT = compile_gated(r"\b(?:exit\w*|leaving|left|pull\w*\s+out\s+of|out\s+of)\s+(?:a|an|the)\s+(?:\w+\s+){0,2}"
                              r"(?:parking\s+(?:lot|garage|structure)|driveway|garage|alley)\b", re.I)
# The AV (or a party) on its way to an intersection: at a junction unless someone came out of a driveway or lot there.
_APPROACHING = compile_gated(r"\b(?:approaching|toward|towards)\s+the\s+intersection\b", re.I)
# An intersection named only as ahead: approached, or where the AV was preparing or about to go ("As the pickup truck
# approached the intersection with [XXX]", "preparing to enter the dedicated left turn lane at the intersection").
_AHEAD_ONLY = compile_gated(r"\b(?:approach(?:ed|ing|es)|toward|towards)\s+the\s+intersection\b|"
                            r"\b(?:preparing|about|planning|intending|getting\s+ready)\s+to\s+[^.,;]{0,60}?\bintersection\b",
                            re.I)
# The summary places the collision near a cross street, not at it ("in a collision involving an SUV on [XXX] near
# [XXX]"): 47 of the 53 studyable reports so summarised are gold `straight`, and the 6 at a junction tell the AV
# standing or stopping there ("stopped in a queue of traffic at a red light at the intersection").
# ("close to", "just past", "north of", "approaching" [a cross street] place it away from the junction too)
_NEAR_CROSS_STREET = compile_gated(r"\bon\s+(?:\[XXX\]|(?-i:[A-Z0-9][\w.'-]*)(?:\s+(?-i:[A-Z][\w.'-]*)){0,3})\s+"
                                   r"(?:just\s+)?(?:near|close\s+to|past|approaching|(?:north|south|east|west)\s+of)\s+"
                                   r"(?:\[XXX\]|(?-i:[A-Z0-9]))", re.I)
_T_JUNCTION = compile_gated(r"\b(?:T|Y|tee)-?\s?(?:junction|intersection|instersection)\b|"
                         r"\b(?:three|3)[- ]?(?:way|legged|leg)\s+(?:intersection|stop|junction)\b|"
                         # "where Koval Lane ends at Flamingo Road", "the end of X where it meets Y": a road ending
                         # (a street's name, capitalised: "the bike lane ends at the intersection" is no T)
                         r"\b(?-i:(?:Street|St|Avenue|Ave|Road|Rd|Boulevard|Blvd|Drive|Dr|Way|Lane|Ln)\.?\s+"
                         r"(?:ends|dead-ends|terminates)\s+(?:at|into)\s+[A-Z])|"
                         r"\bend\s+of\s+[^.]{0,40}?\bwhere\s+it\s+(?:meets|joins)\b|"
                         r"\bmerg(?:e|ing)\s+lane\b|\b(?:on|off)-?\s?ramp\b|\bslip[- ]?(?:lane|road)\b", re.I)
# The AV merging onto a named road ("preparing to make a right turn and merge into [XXX] from a roadway", "on the
# interchange from eastbound Alma Street merging onto southbound Oregon Expressway", "attempting a merge onto
# northbound Bayshore Boulevard"): its road ends at that one, a T (4 of the 4 studyable reports so told are gold
# junction3; a party's merge after its turn, "made an unprotected left turn to merge onto eastbound Fulton Street",
# tells the party's road, not the AV's).
# (in the AV's own clause, and onto a road, not into the AV's lane: "As EGO passed through the intersection, a
# scooterist ... merged into EGO's lane")
_AV_MERGES_ONTO = compile_gated(r"\bEGO\b[^.;,]{0,100}?\bmerg(?:e|es|ed|ing)\s+(?:onto|into)\s+(?:the\s+)?"
                                r"(?:(?:north|south|east|west)\w*\s+)?(?:\[XXX\]|(?!EGO\b)(?-i:[A-Z]))", re.I)
# A ramp named as what the junction meets or where a party heads ("at the [XXX] onramp", "the intersection with
# Interstate [XXX] onramp", "a left turn onto the Interstate [XXX] onramp"): one leg of a crossing the AV is at, not
# the ramp the AV is on (a slip lane or ramp the AV is on makes a T: _T_JUNCTION).
_RAMP_AS_LEG = compile_gated(r"\b(?:intersection\s+with|at|onto|to|towards?)\s+(?:the\s+|an?\s+)?(?:[\w\[\]-]+\s+){0,2}"
                             r"(?:on|off)-?\s?ramp\b", re.I)
# A slip lane, merge lane or ramp is the AV's place even in a summary: the report is not filed from one.
_CONNECTOR = compile_gated(r"\bmerg(?:e|ing)\s+lane\b|\b(?:on|off)-?\s?ramp\b|\bslip[- ]?(?:lane|road)\b", re.I)
_TURN_ONTO = compile_gated(r"\bturn(?:ed|ing|s)?\s+(?:\w+ly\s+)?(?:left|right)?\s*(?:from\s+[^,;]{1,40}?\s+)?onto\b|\b(?:left|right)"
                        r"\s+turn\s+(?:from\s+[^,;]{1,40}?\s+)?(?:onto|towards?\s+\w+bound)\b|\bturning\s+from\b|\bunprotected\s+(?:left|"
                        r"right)\b|\bwaiting\s+to\s+(?:make|turn)\b|"
                        # "turned left in front of EGO to enter Elm Street": a turn into a named street is a junction
                        r"\bturn(?:ed|ing|s)?\s+(?:\w+ly\s+)?(?:left|right)\b[^.,;]{0,50}?\b(?:to\s+enter|into)\s+"
                        r"(?:[\w.'-]+\s+){1,3}(?:Street|St|Avenue|Ave|Road|Rd|Boulevard|Blvd|Drive|Dr|Way)\b|"
                        # "a wide right turn from eastbound [XXX] into the left lane of southbound [XXX]", "a left turn
                        # from the ... lane on Admiralty Way into lane two ... in the eastbound direction of Bali Way":
                        # a turn from one road into a lane of another told by its heading is made at a junction
                        r"\b(?:turn(?:ed|ing|s)?\s+(?:\w+ly\s+)?(?:left|right)|(?:left|right)[- ]turn)\s+from\s+[^,;.]{1,60}?\binto\s+"
                        r"[^,;.]{0,60}?\b(?:north|south|east|west)+bound\b", re.I)
# A turn finished before the interaction began: the AV is then on the street (and heading) it turned onto.
PRIOR_TURN = compile_gated(r"\b(?:after|had|having)\s+(?:completing|making|turning|completed|made|turned)\b[^.]*?"
                         r"\bonto\b|\bafter\s+turning\b", re.I)
_ROUNDABOUT = compile_gated(r"\broundabout\b|\btraffic\s+circle\b|\brotary\b", re.I)
_PARKING = compile_gated(r"\b(?:in|inside|within|through|at)\s+(?:a|an|the)\s+(?:[\w'-]+\s+){0,3}(?:parking\s+(?:lot|"
                      r"structure|garage|facility|deck|ramp)|garage|parking\s+area|depot|lot|car\s+park)\b|\bparking\s+(?:structure|"
                      # the lanes of a lot: "a parking aisle", "the drive aisle of a parking lot"
                      r"garage|deck)\b|\b(?:drive|driving|parking)\s+aisles?\b", re.I)
# The entrance, exit or driveway of a lot is where it meets the road, and a driveway is `straight` ("a chain at the
# entrance of a parking lot", "at the parking garage exit"): no place inside the lot.
_LOT_EDGE = compile_gated(r"\b(?:(?:entrance|entry|exit|driveway|gate)\s+(?:of|to|from|into)\s+(?:a|an|the)\s+(?:[\w'-]+\s+){0,2}?"
                          r"(?:parking\s+(?:lot|garage|structure|deck|area)|garage|lot|car\s+park)|(?:parking\s+(?:lot|garage|"
                          r"structure|deck)|garage|lot)\s+(?:entrance|entry|exit|driveway|gate))\b", re.I)
_CURVE = compile_gated(r"\b(?:curve|curved|curves|curving|curvature|curvy|bend|bends|winding)\b", re.I)
_ROADWAY = compile_gated(r"\b(?:street|st\b|avenue|ave\b|road|rd\b|boulevard|blvd|drive|highway|hwy|freeway|"
                      r"interstate|i-\d+|expressway|parkway|pkwy|lane|roadway|block|way\b|traveling|travelling|"
                      # (the run told in the simple past, as some reporters tell it: "The Waymo AV traveled north on
                      # [XXX] behind a passenger car")
                      # (or by a verb of motion, and a heading: "was moving in autonomous mode on southbound [XXX]",
                      # "was operating north on [XXX]")
                      r"traveled|travelled|drove|moving|operating\s+(?:north|south|east|west)|"
                      # (a run told by another verb of going on a road: "was en route north on [XXX]"; a bare "was in
                      # motion" names no place)
                      r"driving|proceeding|heading|headed|cruising|navigating|en\s+route|"
                      r"northbound|southbound|eastbound|westbound|us\s+\d+|route|"
                      r"road|curb|driveway|oncoming|opposite\s+direction|opposing|traffic|"
                      # a queue of cars, a parking space, a passenger let on or off: a place on a street
                      r"queue|line\s+of\s+(?:cars|vehicles)|parking\s+(?:space|spot|stall)|drop(?:ping|ped)?[- ]off|"
                      r"pick(?:ing|ed)?[- ]?up\s+(?:a\s+)?passengers?|passenger\s+(?:pick-?up|drop-?off)|"
                      # the block between two cross streets ("between [XXX] and [XXX]", "between Noe and Sanchez
                      # Streets"), a level crossing of rails: a place on a road, away from its junctions
                      r"(?-i:between\s+(?:\[XXX\]|[A-Z0-9][\w.]*)(?:\s+[A-Z][\w.]*){0,3}\s+and\s+(?:\[XXX\]|[A-Z0-9]))|"
                      r"(?:railroad|railway|rail|train)\s+crossing)", re.I)
# "was preparing to make a right-on-red": a turn made on red is made at a signal.
_TURN_ON_RED = r"\b(?:right|left)(?:[- ]turn)?[- ]on[- ]red\b"
_SIGNAL = compile_gated(_LIGHT_WAS + "|" + _AT_A_RED + r"|\b(?:red|green|yellow|amber)\s+(?:(?:left|right)[- ]turn\s+)?(?:light|arrow|signal|ball|"
                     r"indication|phase)\b|"
                     + _TRAFFIC_LIGHT + r"|\b(?<!its\s)(?<!their\s)stop\s?lights?\b|\bsignali[sz]ed\b|\bthe\s+(?:light|signal)\b|\bon\s+(?:a\s+)?(?:green|red|yellow)\b|"
                     r"\b(?:solid|flashing|steady|circular)\s+(?:green|red|yellow|amber)\b|"
                     r"\b(?:its|their|EGO's)\s+(?:traffic\s+)?(?:light|signal)\s+(?:\w+\s+){0,2}?(?:green|red|yellow|amber)\b|"
                     r"\b(?:green|red|yellow|amber)\s+(?:turn\s+)?arrow\b|\b(?:signal|light)[- ]controlled\b|"
                     + _TURN_ON_RED, re.I)
# (a yield sign is the sign control the schema's `stop_sign` stands for: "The AV stopped at a yield sign in the
# right-turn only lane before merging")
_STOP_SIGN = compile_gated(r"\bstop\s+sign|\byield\s+sign|" + _WAY_STOP + r"|\b(?:stop|yield)-controlled\b", re.I)
# A junction the text says has no control: the AV's approach is then `none`, not `unknown`.
_NO_CONTROL = compile_gated(r"\b(?:uncontrolled|unsignali[sz]ed|non-?signali[sz]ed)\s+(?:[\w-]+\s+)?intersection\b|"
                            r"\bno\s+traffic\s+(?:controls?|signals?|lights?)\b|"
                            r"\btraffic\s+control(?:\s+device)?s?\s*:\s*none\b", re.I)
# Road furniture the AV struck that happens to be a sign or a signal's pole tells of no control and no junction
# ("made contact with a stop sign", "the post of a stop sign", "a traffic signal pole"); a place that is no junction
# though it has a crosswalk ("a mid-block crosswalk").
_NOT_CONTROL = compile_gated(r"\b(?:stop\s+sign|traffic\s+(?:light|signal)|signal|light)\s+(?:pole|post|standard|mast|"
                             r"arm|box|cabinet)s?\b|\b(?:post|pole|base)\s+of\s+(?:a|an|the)\s+(?:stop\s+sign|traffic\s+"
                             r"(?:light|signal))\b|\b(?:contact\s+with|struck|striking|hit|hitting|collided\s+with|"
                             r"into|knocked\s+(?:down|over))\s+(?:a|an|the)\s+(?:[\w-]+\s+){0,2}?stop\s+sign\b|"
                             r"\bmid-?\s?block\s+(?:pedestrian\s+)?crosswalk\b", re.I)
_ONE_WAY = compile_gated(r"\bone[- ]way\b", re.I)
_TWO_WAY = compile_gated(r"\boncoming\b|\bopposite\s+direction\b|\bopposing\s+(?:lane|traffic|direction)\b|"
                      r"\bon-?coming\b|\bopposite\s+lane\b|\btraveling\s+the\s+wrong\s+way\b", re.I)
_LANES_N = compile_gated(r"\b(one|two|three|four|five|six|\d)[- ]lanes?\b|\b(one|two|three|four|five|six|\d)\s+"
                      r"(?:\w+\s+)?lanes\b", re.I)
_LANE_ORD = compile_gated(r"\b(second|third|fourth|2nd|3rd|4th)\s+lane\s+from\s+the\s+(?:left|right)", re.I)
_LANE_MIDDLE = compile_gated(r"\b(?:middle|center|centre)\s+lane\b", re.I)
_LANE_SIDE = compile_gated(r"\b(?:left|right)most\b|\bfar\s+(?:left|right)\s+lane\b|\b(?:left|right)\s+lane\b|"
                        r"\b(?:left|right)\s+(?:adjacent\s+)?lane\b|\badjacent\s+lane\b|\blane\s+to\s+the\s+(?:left|"
                        r"right)\b|\b(?:left|right)\s+turn\s+lane\b|\bturn\s+lane\b|\bbus\s+(?:only\s+)?lane\b|"
                        r"\bthe\s+(?:left|right)\s+lane\b", re.I)
_OPPOSING_LANE = compile_gated(r"\b(?:oncoming|opposing|opposite)\s+(?:\w+\s+)?lane", re.I)

_WEATHER_P = (("rain", r"\brain(?:ing|y|ed)?\b|\bdrizzl"), ("fog", r"\bfog(?:gy)?\b|\bmist(?:y)?\b"),
            ("snow", r"\bsnow(?:ing|y)?\b|\bsleet\b"), ("cloudy", r"\bcloudy\b|\bovercast\b"),
            ("clear", r"\bsunny\b|\bclear\s+(?:weather|skies|day|conditions)\b|\bweather:?\s+clear\b|"
                      r"\bweather(?:\s+conditions)?\s+(?:was|were)\s+(?:\w+\s+)?clear\b"))
_SURFACE_P = (("wet", r"\bwet\b|\bslick\b|\bpuddl"), ("snow_ice", r"\bic(?:y|e)\b|\bsnow[- ]covered\b"),
            ("dry", r"\bdry\s+(?:road|pavement|surface|roadway)\b|\bsurface:?\s+dry\b"))
_WEATHER = tuple((w, compile_gated(p, re.I)) for w, p in _WEATHER_P)
_SURFACE = tuple((w, compile_gated(p, re.I)) for w, p in _SURFACE_P)
_CLOCK = compile_gated(r"\b(\d{1,2})(?::(\d{2}))?\s*(a\.?m\.?|p\.?m\.?)(?![a-z])", re.I)


_LIGHT = (("dusk_dawn", compile_gated(r"\b(?:dusk|dawn|twilight|sunset|sunrise)\b", re.I)),
          ("day", compile_gated(r"\b(?:daylight|daytime|sunny\s+day)\b", re.I)),
          ("night_dark", compile_gated(r"\bdark\b[^.]{0,30}\b(?:no|without)\s+street\s*lights?|\bunlit\b|"
                                    r"\bpitch\s+dark", re.I)),
          ("night_lit", compile_gated(r"\bstreet\s*lights?\b|\bdark\b|\bnight(?:time)?\b", re.I)))


def lighting_from_text(t: str) -> str:
    """Lighting as sketch.md reads it: words for the light first, else a clock time 8:00 AM-4:59 PM is day."""
    for value, rx in _LIGHT:
        if rx.search(t):
            return value
    m = _CLOCK.search(t)
    if m:
        hour = int(m.group(1)) % 12 + (12 if m.group(3).lower().startswith("p") else 0)
        if 8 <= hour <= 16:
            return "day"
    return "unknown"


def environment(t: str) -> Environment:
    weather = next((w for w, rx in _WEATHER if rx.search(t)), "unknown")
    surface = next((w for w, rx in _SURFACE if rx.search(t)), "unknown")
    if weather == "rain" and surface == "unknown":
        surface = "wet"
    return Environment(weather=weather, lighting=lighting_from_text(t), surface=surface)  # type: ignore[arg-type]


_LOT_EXIT = compile_gated(r"\b(?:exit\w*|leaving|left|pull\w*\s+out\s+of|out\s+of|from)\s+(?:a|an|the)\s+(?:\w+\s+){0,2}"
                       r"(?:parking\s+(?:lot|garage|structure|space|spot)|driveway|garage|alley|lot)\b[^.]*?"
                       r"(?:\bonto\b|$)", re.I)
# (a turn ahead that the AV "approached": the junction it was approaching, sketch.md's R1-R4)
# (a turn under way told by any of the verbs that make one: "was executing a left turn from ... into lane two")
_ONGOING_TURN = compile_gated(r"\b(?:turning|completing|making|executing|performing|conducting|preparing\s+to|"
                              r"waiting\s+to|about\s+to|attempting(?:\s+to)?|trying\s+to|"
                              r"approach(?:ed|ing)\s+(?:a|an|the|its)\s+(?:\w+\s+)?(?:left|right)[- ]turn)\b", re.I)


_DISPLAYED = compile_gated(r"\b(?:displaying|showing|with)\s+(?:a|an)\s+(?:red|green|yellow|amber)\s+arrow", re.I)
#: The collision placed inside a lot ("was in a collision involving a passenger car in a parking lot at [XXX]. The
#: Waymo AV was exiting a parking lot ... when it slowed to a stop to yield for pedestrians"): a way out of the lot
#: told beside it is the lot's own aisle, not the driveway where it meets the road.
_IN_LOT = compile_gated(r"\b(?:in|inside|within)\s+(?:a|an|the)\s+(?:[\w-]+\s+){0,2}parking\s+(?:lot|garage|structure)\b", re.I)


def is_junction(sents: list[str], first_sent: int, summary: frozenset[int] = frozenset()) -> bool:
    """Did the interaction happen at a junction? Turns finished before the interaction began ("after turning right
    onto X", a turn told in a sentence before the other party appears), turns out of a driveway or lot, and
    intersections the AV was only near do not count. One it was approaching does (sketch.md: R1-R4 are at a junction
    the AV is in or approaching), unless someone came out of a driveway, lot or garage: the interaction is then at
    that exit (sketch.md: a driveway is `straight`), and a turn onto the road from there is no junction's.

    Where the junction words stand relative to the contact, over the 602 studyable gold sketches (session 22, before
    the story was cut at the contact; J = gold junction3/junction4):
      a summary placing the event in an intersection     J 22, straight 0
      junction words in the contact sentence             J 88, straight 2
      junction words only before the contact             J 166, straight 14, parking 3
      junction words before and after the contact        J 5
      junction words only after the contact              straight 1 (the caller passes the story up to the contact)
      no contact told, junction words                    J 4, straight 1
      no junction words                                  straight 251, parking 28, unknown 7, curve 3, J 7
    So a junction told before or at the contact is the scene (the default when nothing says it was left behind, only
    the report's address, or a driveway's), and no junction told is a road. The 14 told before and gold `straight`
    are singletons by kind (a queue short of the light, a gore point near a junction, a junction cleared before the
    contact, a lot exit, a stop sign approached on the way to a parked car); no cue over the text separates them
    from the 166 (an intersection only approached with a same-road party: J 16, straight 6; a queue: J 42,
    straight 22)."""
    exit_at = next((i for i, s in enumerate(sents) if i not in summary and _OUT_OF_A_LOT.search(s)), None)
    near = any(_NEAR_CROSS_STREET.search(sents[i]) for i in summary if i < len(sents))
    for i, s in enumerate(sents):
        # An arrow on a work truck's light board is no traffic signal.
        cleaned = _NOT_JUNCTION.sub(" ", _LOT_EXIT.sub(" ", PRIOR_TURN.sub(" ", _DISPLAYED.sub(" ", _NOT_CONTROL.sub(
            " ", s)))))
        if near and i not in summary and not _STOOD.search(cleaned):
            # near a cross street: the intersection ahead is not the scene, unless the sentence stops or stands the
            # AV there ("As the Waymo AV approached the intersection with 22nd Street, it came to a stop behind its
            # lead vehicle": a queue at the junction)
            cleaned = _AHEAD_ONLY.sub(" ", cleaned)
        if near and i not in summary:
            # near a cross street, a turn lane the AV waits in is the approach to the junction, short of it ("was
            # stopped in traffic in the dedicated right turn lane of southwestbound [XXX]": 3 of 3 W-half studyable
            # reports so told with a "near" summary are gold `straight`)
            cleaned = _TURN_POCKET.sub(" ", cleaned)
        if exit_at is not None:
            # "As the AV was approaching the intersection with Stillman Street, a blue Model 3 Tesla exited out of a
            # parking garage into the AV's lane of travel"; "allowing for a passenger car to exit a parking lot ...
            # As the passenger car turned left onto [XXX]": the junction ahead and the turn out of the lot are not
            # where they met
            cleaned = _APPROACHING.sub(" ", cleaned)
            if i >= exit_at:
                cleaned = _TURN_ONTO.sub(" ", cleaned)
        if fre.search(r"\bintersection\b", cleaned, re.I) and i in summary and \
                fre.search(r"\b(?:at|in|through|entering|entered|crossing)\s+the\s+(?:[\w.'-]+\s+){0,6}?intersection\b",
                          cleaned, re.I):
            return True  # a summary placing the event in an intersection ("at the Grant Ave. and Union St. ...")
        if i in summary and not _CONTROL_AT.search(cleaned) and not _CONNECTOR.search(cleaned) and \
                not _AV_MERGES_ONTO.search(cleaned) and not (
                _TURN_ONTO.search(cleaned) and _AV_TURNING.search(cleaned)):
            # A summary's junction words are often where the report was filed from; a signal or stop sign the AV
            # stood at ("was stopped at a red light on X when it was rear-ended"), or a turn it was making ("was
            # stopped turning right from Park Drive onto Miramonte Avenue when it was rear-ended"), is the scene.
            continue
        if _JUNCTION.search(cleaned) or _T_JUNCTION.search(cleaned) or _AV_MERGES_ONTO.search(cleaned):
            return True
        if _TURN_ONTO.search(cleaned) and (i >= first_sent or _ONGOING_TURN.search(cleaned)):
            return True
    return exit_at is None and _queued_at_cross_street(sents, summary)


def _queued_at_cross_street(sents: list[str], summary: frozenset[int]) -> bool:
    """The AV stood in a queue ("was stopped in traffic", "behind stopped traffic", "in a queue of traffic") and the
    summary places the collision at a cross street ("on 2nd Street at Minna Street", "at Bush Street and Grant
    Avenue"): a queue stands at the junction ahead, so the interaction is there (the official and study gold read
    junction4 in all 17 studyable reports told so)."""
    return any(_AT_CROSS_STREET.search(sents[i]) for i in summary if i < len(sents)) and \
        any(_QUEUED.search(s) for k, s in enumerate(sents) if k not in summary)


_DIR = "(" + "|".join(sorted(CARDINALS, key=len, reverse=True)) + ")"  # a compass heading (its word captured)
_STREET = (r"((?-i:(?:[A-Z0-9][\w.']*\s+){0,3}?(?:Street|St|Avenue|Ave|Road|Rd|Boulevard|Blvd|Drive|Dr|Way|Lane|Ln|"
           r"Expressway|Parkway|Highway|Real)\b)|\[XXX\])")
# "southbound on Albion Street", "on northbound [XXX]": a heading told on a named (or redacted) street.
_HEADING_ON = (compile_gated(rf"\b{_DIR}(?:bound|ward)?\s+on\s+{_STREET}", re.I),
               compile_gated(rf"\bon\s+{_DIR}(?:bound)?\s+{_STREET}", re.I))

# The summary's place of the collision at a cross street ("on [XXX] at [XXX]", "at Bush Street and Grant Avenue");
# "on X near Y" places it away from the junction.
_AT_CROSS_STREET = compile_gated(rf"\b(?:on|at)\s+{_STREET}\.?\s+(?:at|and)\s+{_STREET}", re.I)  # "Bush St. and"
# Words for standing still (a red the AV stood at is its signal when its actions begin; a queue it stood in is at
# the junction ahead). ("had come to a stop at a traffic light": a stop reached is a standing too; "was at a stop",
# "was sitting", "was idling in traffic": the same standing in other words)
_STANDING = (r"(?:stopped|waiting|stationary|idle|idling|halted|queued|sitting|standing(?:\s+still)?|"
             r"at\s+(?:a\s+)?(?:standstill|rest)|at\s+a\s+(?:complete\s+|full\s+)?stop(?!\s+(?:sign|line|bar|light))|"
             r"(?:came|come)\s+to\s+a\s+(?:\w+\s+)?(?:stop|halt|standstill))")
_STOOD = compile_gated(rf"\b{_STANDING}", re.I)
# Standing in a queue of traffic (not a lone stop, not traffic the AV yielded to).
_QUEUED = compile_gated(rf"\b{_STANDING}\s+in\s+traffic\b|\bbehind\s+stopped\s+traffic\b|"
                        r"\b(?:in|behind)\s+a\s+queue\s+of\s+(?:\w+\s+)?traffic\b", re.I)


def _opposite_on_first_road(t: str) -> bool:
    """Does the text put someone on the first road it names with a heading (the AV's, as the story opens) heading
    the opposite way ("was traveling southbound on Albion Street ... a Ford pickup truck was traveling northbound on
    Albion Street")? Then that road carries both directions (sketch.md: `one_way` false)."""
    told = sorted((m.start(), CARDINALS[m.group(1).lower()], m.group(2)) for rx in _HEADING_ON for m in rx.finditer(t))
    if not told:
        return False
    _, first, street = told[0]
    return any(road == street and abs(heading - first) == 180 for _, heading, road in told[1:])


def road(t: str, *, junction: bool) -> RoadInfo:
    if _ROUNDABOUT.search(t):
        layout = "roundabout"
    elif _PARKING.search(_LOT_EDGE.sub(" ", t)) and (_IN_LOT.search(t) or not fre.search(
            r"\b(?:exit(?:ed|ing)?|leaving|out\s+of)\s+(?:a|an|the)\s+(?:\w+\s+)?parking\s+(?:lot|garage|structure)", t, re.I)):
        layout = "parking"
    elif junction:
        layout = "junction3" if _T_JUNCTION.search(_RAMP_AS_LEG.sub(" ", t)) or _AV_MERGES_ONTO.search(t) else \
            "junction4"
    elif _CURVE.search(t):
        layout = "curve"
    elif _ROADWAY.search(t):
        layout = "straight"
    else:
        layout = "unknown"
    t = _NOT_CONTROL.sub(" ", _DISPLAYED.sub(" ", t))
    if _STOP_SIGN.search(t):
        control = "stop_sign"
    elif _SIGNAL.search(t) and layout.startswith("junction"):
        control = "signal"
    elif _NO_CONTROL.search(t) and layout.startswith("junction"):
        control = "none"
    elif layout.startswith("junction") or layout == "roundabout":
        control = "unknown"
    else:
        control = "none" if layout != "unknown" else "unknown"
    one_way: bool | None = None
    if _ONE_WAY.search(t):
        one_way = True
    elif _TWO_WAY.search(t) or _opposite_on_first_road(t):
        one_way = False
    return RoadInfo(layout=layout, control=control, one_way=one_way, lanes=lane_count(t))  # type: ignore[arg-type]


#: The AV's road said to have one lane ("in the single lane of southwestbound [XXX]", "a one-lane section of
#: northbound [XXX]"): a turn lane or a widening named beside it is where the road goes next, not a second lane.
_SINGLE_LANE = compile_gated(r"\bsingle(?:[- ]|\s+travel\s+)lane\b|\bone-lane\b|\bone\s+lane\s+(?:road|street|section|"
                             r"roadway|portion)\b", re.I)


def lane_count(t: str) -> int | None:
    """The least lane count the text states or implies for the AV's direction."""
    t2 = _OPPOSING_LANE.sub(" ", t)
    if _SINGLE_LANE.search(t2) and not _LANE_ORD.search(t2) and not _LANE_MIDDLE.search(t2):
        return 1  # (3 of 3 W-half studyable reports saying so are gold 1, all with a turn lane named ahead)
    n = 0
    for m in _LANES_N.finditer(t2):
        w = (m.group(1) or m.group(2)).lower()
        n = max(n, NUMBER_WORDS.get(w, int(w) if w.isdigit() else 0))
    for m in _LANE_ORD.finditer(t2):
        n = max(n, {"second": 2, "2nd": 2, "third": 3, "3rd": 3, "fourth": 4, "4th": 4}[m.group(1).lower()])
    if _LANE_MIDDLE.search(t2):
        n = max(n, 3)
    if _LANE_SIDE.search(t2):
        n = max(n, 2)
    return n or None




# A light that turned green was red before it: an AV that stood when the interaction began stood at that red.
TURNED_GREEN = compile_gated(r"\b(?:stop\s?)?(?:light|signal|lights|signals)\s+(?:then\s+|had\s+|subsequently\s+)?(?:turned|changed|"
                             r"went|cycled)\s+(?:to\s+)?green\b", re.I)


# A red light named as such (not "a red sedan"): "a red light", "the red traffic signal", "a right-on-red", "turned red".
# ("a light that was red", "while the signal was still red": the colour told of the light after it)
_RED_LIGHT = compile_gated(r"\bred\s+(?:traffic\s+)?(?:light|signal|arrow|ball)s?\b|" + _TURN_ON_RED + "|" + _AT_A_RED +
                           r"|\b(?:turned|changed\s+to|went)\s+red\b|\bon\s+(?:a\s+)?red\b|"
                           r"\b(?:light|signal)\s+(?:that\s+|which\s+)?(?:was|is|remained)\s+(?:still\s+)?red\b", re.I)
# ("a stoplight", "a stop light": a traffic light)
_AT_A_LIGHT = compile_gated(rf"\b{_STANDING}\s+(?:at|for)\s+(?:a|the)\s+(?:traffic[\s-]+(?:control\s+)?|stop\s?)?(?:light|signal)\b",
                            re.I)
# Waiting for a green is standing at a red ("waiting for the light to turn green", "waiting for a green light").
_WAITING_FOR_GREEN = compile_gated(r"\bwait(?:ed|ing|s)?\s+for\s+(?:(?:the|its)\s+(?:traffic\s+)?(?:light|signal)\s+to\s+"
                                   r"(?:turn|change)(?:\s+to)?\s+green|(?:a|the)\s+green(?:\s+(?:light|signal|arrow))?)\b", re.I)
_COLOUR = compile_gated(r"\b(?:red|green|yellow|amber)\b", re.I)
# A light showing nothing ("a malfunctioning traffic light", "the traffic light was not illuminated", "the signals were
# dark during a power outage"): no signal state at all (csvr-waymo-20241214-s355, gold `none`).
_DARK_LIGHT = compile_gated(r"\b(?:malfunctioning|inoperative|inoperable|non-?functioning|non-?operational|dark|broken|"
                            r"unlit|out-of-service)\s+(?:traffic\s+|stop\s?)?(?:lights?|signals?)\b|"
                            # ("the traffic light was not illuminated"; not "the brake lights were off")
                            r"\b(?:the|its|their|a)\s+(?:traffic\s+)?(?:light|signal)s?\s+(?:\w+\s+){0,2}?(?:was|were|is|are|"
                            r"had\s+been)\s+(?:\w+ly\s+)?"
                            r"(?:not\s+(?:illuminated|lit|working|functioning|operating|operational)|dark|out|off|"
                            r"malfunctioning|inoperative|without\s+power)\b|"
                            r"\bpower\s+(?:outage|failure)\b", re.I)


def signal_state(t: str, *, layout: str, control: str, ego_start: str = "moving") -> str:
    """The AV's light when its actions begin."""
    if layout == "unknown":
        return "unknown"  # no telling whether it was at a junction at all (sketch.md: `none` is away from junctions)
    if not layout.startswith("junction") and layout != "roundabout":
        return "none"
    if control in ("stop_sign", "none"):
        return "none"  # (a junction the text says has no control has no signal either)
    if control != "signal":
        return "unknown"
    if _DARK_LIGHT.search(t):
        return "none"  # a light that showed no colour: no signal to begin on (sketch.md: `none` where there is none)
    if ego_start == "stopped" and (TURNED_GREEN.search(t) or _WAITING_FOR_GREEN.search(t)):
        return "red"  # sketch.md: "an AV stopped at a red light that moves off on green has red"
    # The AV standing, stopping or slowing for a red light ("As the Cruise AV was slowing for a red light at the
    # intersection with Polk Street, an Infiniti Q60 ... failed to stop for the red light"): its own light.
    if fre.search(rf"\bEGO(?:D)?\b[^.]{{0,60}}\b(?:{_STANDING}|stop|slow(?:ed|ing)|brak(?:ed|ing)|decelerat(?:ed|ing))\b"
                 rf"[^.]{{0,30}}\bred\b|\bred\s+light\b[^.]{{0,40}}\bEGO\b[^.]{{0,20}}\b{_STANDING}\b", t, re.I):
        return "red"
    # A red another party ran is its light, not the AV's ("a passenger vehicle which had previously been stopped at a
    # red light, proceeded through the red light"): read before a standing at a red that names no one.
    if fre.search(r"\b(?:violat\w+|ran|running|against|through)\s+(?:a|the|its|their)\s+red\b", t, re.I):
        return "green"
    if fre.search(rf"\b{_STANDING}\s+(?:at|for)\s+(?:a|the)\s+red", t, re.I):
        return "red"
    if ego_start == "stopped" and (_RED_LIGHT.search(t) or (_AT_A_LIGHT.search(t) and not _COLOUR.search(t))):
        # An AV standing when the interaction began, in a story that names a red light (or stands it at a light
        # of no told colour: "was stopped at a traffic light"), stood at that red (sketch.md: it is the AV's
        # signal when its actions begin, even if it then moved off on green).
        return "red"
    for colour, words in (("green", "green"), ("yellow", "yellow|amber"), ("red", "red")):
        if fre.search(rf"\b(?:{words})\b", t, re.I):
            return colour  # (amber is the yellow's other name)
    return "unknown"


_LAYOUT_WORDS = {"roundabout": _ROUNDABOUT, "parking": _PARKING, "junction3": _T_JUNCTION, "junction4": _JUNCTION,
                 "curve": _CURVE, "straight": _ROADWAY}


def scene_spans(t: str, road_info: RoadInfo, env: Environment, signal: str) -> dict[str, list[tuple[int, int]]]:
    """Where the road, environment and signal fields were read (first match of the pattern that gave each value);
    fields left `unknown` have no evidence."""
    out: dict[str, list[tuple[int, int]]] = {}

    def first(slot: str, rx: re.Pattern[str] | None) -> None:
        m = rx.search(t) if rx is not None else None
        if m:
            out[slot] = [m.span()]

    first("road.layout", _LAYOUT_WORDS.get(road_info.layout))
    first("road.control", {"signal": _SIGNAL, "stop_sign": _STOP_SIGN}.get(road_info.control))
    if road_info.one_way is not None:
        first("road.one_way", _ONE_WAY if road_info.one_way else _TWO_WAY if _TWO_WAY.search(t) else _HEADING_ON[0])
    if road_info.lanes:
        first("road.lanes", _LANE_ORD if _LANE_ORD.search(t) else _LANES_N if _LANES_N.search(t) else _LANE_SIDE)
    first("environment.weather", dict(_WEATHER).get(env.weather))
    first("environment.surface", dict(_SURFACE).get(env.surface))
    first("environment.lighting", dict(_LIGHT).get(env.lighting) or (_CLOCK if env.lighting == "day" else None))
    if signal in ("green", "yellow", "red"):
        first("signal_state", fre.cached(rf"\b{signal}\b", re.I))   # compiled once, not per report
    return out
