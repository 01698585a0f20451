"""Wording probes: one slot at a time, many wordings of the same fact in one fixed sentence, the reading that must come
out. Where the invariance tool (`invariance.py`) rewrites real narratives, a probe asks for the wordings real
narratives happen not to use, so a gap shows before a user's report meets it. Session 10 wrote the sets below; on
that session's start code (2e462c3) 17 of 26 lane changes, 13 of 13 parties behind, 9 of 12 passing the standing AV
on its left, 5 of 10 standing ahead that the AV runs into, 7 of 10 oncoming, 8 of 9 opposite-approach left turns and
7 of 8 crossing parties, 6 of 8 pedestrians on the turning AV's exit leg and 3 of 5 mid-block, 6 of 8 parked cars
pulling out, 5 of 6 weather wordings, 14 of 15 road layouts, 6 of 8 lights, 7 of 12 stops, 11 of 12 starts, 12 of 16
lane changes of the AV, 11 of 14 turns, 15 of 15 names of the AV, 0 of 4 contacts told with a pronoun for the AV, 19
of 23 contact verbs, 21 of 23 objects struck and 49 of 56 party nouns came out right (251 of 313); now all of them
(`test_probes.py` holds that). Session 11 added 49 sets on parties' action strings (sketch.md's codes and hard-case
rules: moving off, stopping, slowing, backing, U-turns, crossing, driveways, merges, strings that end at the contact,
parties standing throughout, manoeuvres under way, the present tense); on that session's start code (39a178f) 476 of
their 611 wordings came out right, now all. Five sets of whole scenes came with them (a party beside, ahead or behind
the AV told as each operator tells it; a party at a junction by its road and compass heading; the party struck in the
OL 316 forms' numbering, "V1 (our AV)", and other operators' words; the AV named by an operator not listed, its
vehicle or its role; a party using the opposing lane to get around a queue, passing through a junction, beside the
AV there): 147 of their 177 narratives read right on 39a178f, now all. Session 11 also added 28 sets on objects
(what counts, by name and by verb; doors; lanes; the far side of the street), the road's layout and control, the AV's
own start and actions, and refusals (a party placed by the part of the AV it touched or by the contact's geometry, a
party or place named in rarer words), written from sketch.md's definitions and the operators' ways of telling them:
185 of their 319 wordings came out right on 39a178f, now all. Session 12 added 11 sets on the AV's own start and
actions, each from a reading the real dev narratives showed wrong (a turn done before the story, a counterfactual
stop, parking that ended backing, pulling up behind a standing vehicle, a yield beside a run or as a state, a stop
made for the party met, a take-over made to turn, a move told again at the contact, a driveway or lot entered): 11
of their 74 wordings came out right on that session's start code (746ca19), now all; 9 more sets from the
challenge narratives' AV misses (a stop told after the move that followed it, a stop under way, waiting at a light
behind a car, the same moment after the contact, into the junction to turn, ...): 12 of their 49 wordings then, now
all; and 5 on who did a participle after a comma and on contacts (named again in the damage, a move into a part of
the AV or onto it, a braking at the contact): 6 of 24 then, now all. Session 21 added 12 sets on who counts and
what was struck (a move ending in the AV, crashing into a thing, a door opened after its owner is named, rider and
ride one party, "the other vehicle", a vehicle struck before the story, road-works machines, a truck's cab, a thing
no word list names, a thing thrown at the AV, and the ground as a guard): 21 of their 86 wordings came out right on
that session's start code (97617ab), now all.

    python -m tests.text.probes          # per probe set: wordings read as wanted, and every miss
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from txt2sce_ros.sketch import Sketch
from txt2sce_ros.text.extractor import extract


@dataclass(frozen=True)
class Probe:
    name: str
    template: str                       # "{w}": the wording; "{W}": the wording with a capital (sentence start)
    wordings: tuple[str, ...]
    want: Callable[[Sketch], object]    # the reading compared
    expected: object | Callable[[str], object]


def _party(sk: Sketch) -> object:
    return [(p.position, p.lane, p.actions) for p in sk.npcs][:1]


def _ego(sk: Sketch) -> object:
    return sk.ego.start, sk.ego.actions


def _npc_actions(sk: Sketch) -> object:
    return [(p.start, p.actions) for p in sk.npcs][:1]


def _position(sk: Sketch) -> object:
    return [(p.position, p.lane) for p in sk.npcs][:1]


_CATEGORIES = {
    "car": ("sedan", "hatchback", "coupe", "SUV", "pickup truck", "taxi", "cab", "Tesla", "police car", "convertible",
            "limousine", "minicab", "jeep", "crossover", "passenger car"),
    "van": ("minivan", "delivery van", "cargo van", "Sprinter van", "panel van"),
    "truck": ("box truck", "tractor-trailer", "semi-truck", "dump truck", "garbage truck", "tow truck", "fire truck",
              "cement mixer", "big rig", "18-wheeler", "delivery truck", "flatbed", "flatbed truck", "car carrier",
              "car hauler"),
    "bus": ("city bus", "Muni bus", "school bus", "shuttle bus", "coach"),
    # (a bare "scooterist" rides a motor scooter: a motorcycle in 2 of the 3 studyable gold sketches naming one)
    "motorcycle": ("motorcyclist", "moped", "motor scooter", "dirt bike", "motorbike", "scooterist", "sport bike",
                   "sportbike", "Vespa"),
    "bicycle": ("cyclist", "bicyclist", "bike rider", "e-bike rider"),
    "scooter": ("scooter rider", "e-scooter rider", "skateboarder", "electric scooterist"),
    "pedestrian": ("pedestrian", "jogger", "man", "woman", "child", "person", "runner", "construction worker",
                   "worker", "flagger", "crossing guard", "teenager", "passerby", "boy", "girl"),
}

_OBJECTS = {
    "barrier": ("a parking gate", "a gate arm", "a parking garage gate", "a concrete barrier", "a jersey barrier",
                "a k-rail", "a curb", "a raised median", "a traffic island", "a concrete median", "a wall", "a fence",
                "a chain-link fence", "a guardrail", "a wooden barricade", "a construction barricade",
                "a parking block", "a wheel stop", "a concrete planter", "a retaining wall", "a security gate",
                "a rolling gate", "a crash attenuator", "a gate"),
    "pole": ("a utility pole", "a light pole", "a street light", "a stop sign", "a street sign", "a fire hydrant",
             "a parking meter", "a bollard", "a metal post", "a sign post", "a pillar", "a concrete column",
             "a parking structure pillar", "a traffic signal pole", "a delineator post"),
    "cone": ("a traffic cone", "a cone", "a construction cone", "a construction barrel", "a traffic barrel", "a pylon",
             "a delineator", "a plastic delineator"),
    "debris": ("debris", "road debris", "a piece of debris", "a wooden pallet", "a tire tread", "a ladder",
               "a mattress", "a piece of metal", "a metal pipe", "a tire", "a hubcap", "a rock", "a piece of wood",
               "a steel plate", "a bumper cover", "a piece of lumber"),
    "animal": ("a dog", "a cat", "a deer", "a coyote", "a raccoon", "a bird", "a pigeon", "a skunk", "an opossum",
               "a squirrel", "a rabbit", "a goose", "a duck", "a chicken", "a fox", "a javelina", "a bobcat",
               "a stray dog", "an animal", "a small animal", "a seagull", "a crow"),
    "other": ("a tree", "a tree branch", "a low-hanging branch", "a shopping cart", "a trash bin", "a trash can",
              "a recycling bin", "a garbage can", "a dumpster", "a mailbox", "a bus shelter", "a power line", "a cable",
              "a bike rack", "a newspaper stand", "a remote controlled toy car", "a toy car", "an RC truck",
              "a plastic bag", "an electric scooter lying in the road", "a parked e-scooter",
              "a scooter lying in the road", "a bicycle that was left on the ground", "a bike on its side"),
}
_AV_STOPPED = "The Waymo AV was stopped at a red light on Mission Street at 16th Street. "
# A lane entered after a verb of going forward or of starting (two probe sets: a party moving, one standing).
_LANE_ENTERED_GOING = ("began to proceed into the Waymo AV's lane", "proceeded into the Waymo AV's lane",
                       "started moving into the Waymo AV's lane", "moved forward into the Waymo AV's lane",
                       "pulled forward into the Waymo AV's lane", "crept into the Waymo AV's lane",
                       "inched into the Waymo AV's lane", "began to creep into the Waymo AV's lane",
                       "proceeded to enter the Waymo AV's lane", "began to nose into the Waymo AV's lane",
                       "rolled forward into the Waymo AV's lane",
                       "proceeded forward into the lane occupied by the Waymo AV")


def _partner_told(sk: Sketch) -> object:
    return sk.collision.with_, sk.missing


def _partner_touched(sk: Sketch) -> object:
    return sk.collision.with_, sk.collision.type != "none"


def _partner_id(sk: Sketch) -> object:
    return sk.collision.with_


def _partner_position(sk: Sketch) -> object:
    return next(((p.position, p.lane) for p in sk.npcs if p.id == sk.collision.with_), None)


def _scenes(name: str, want: Callable[[Sketch], object], cases: tuple[tuple[str, object], ...]) -> Probe:
    """A probe of whole narratives, each with its own reading: scenes told as different operators tell them."""
    table = dict(cases)
    return Probe(name, "{w}", tuple(table), want, table.__getitem__)


# Session 17: each manoeuvre's vocabulary, the ways English tells it (verb forms, particles, "began to", "attempted",
# "executed a ... maneuver", adverbs of manner, the present tense), held once and asked of a party and of the AV.
_TURN_LEFT = (
    "turned left", "made a left turn", "made a left", "executed a left turn", "executed a left-hand turn",
    "initiated a left turn", "began a left turn", "commenced a left turn", "performed a left turn", "took a left",
    "began to turn left", "started to turn left", "attempted to turn left", "attempted a left turn",
    "began making a left turn", "started making a left turn", "began turning left", "started turning left",
    "proceeded to turn left", "proceeded to make a left turn", "made an unprotected left turn",
    "completed a left turn", "conducted a left turn", "negotiated a left turn", "turned to the left",
    "cut a left turn", "made a left-hand turn", "made a sharp left turn", "turned left onto 16th Street",
    "carried out a left turn", "initiated a left hand turn", "made a quick left turn", "turned left suddenly",
    "suddenly turned left", "abruptly turned left", "made an abrupt left turn", "attempted to make a left turn",
    "tried to turn left", "made a left turn maneuver", "performed a left-turn maneuver", "began its left turn",
    "started its left turn", "initiated its left turn", "turns left", "makes a left turn",
)
_LANE_CHANGE_LEFT = (
    "changed lanes to the left", "made a lane change to the left", "made a left lane change",
    "performed a lane change to the left", "initiated a lane change to the left", "began a lane change to the left",
    "began changing lanes to the left", "began to change lanes to the left",
    "attempted to change lanes to the left", "attempted a lane change to the left",
    "executed a lane change to the left", "merged left", "merged to the left", "merged into the left lane",
    "moved into the left lane", "moved over into the left lane", "moved over to the left",
    "shifted into the left lane", "switched into the left lane", "switched lanes to the left",
    "cut into the left lane", "crossed into the left lane", "drifted into the left lane",
    "veered into the left lane", "entered the left lane", "came into the left lane",
    "changed lanes into the Waymo AV's lane", "moved into the Waymo AV's lane", "merged into the Waymo AV's lane",
    "cut into the Waymo AV's lane", "entered the Waymo AV's lane", "encroached into the Waymo AV's lane",
    "crossed into the Waymo AV's lane", "swerved into the Waymo AV's lane", "cut in front of the Waymo AV",
    "changed lanes", "made a lane change", "performed a lane change", "attempted a lane change",
    "initiated a lane change", "began a lane change", "merged", "tried to change lanes to the left",
    "started to change lanes", "started changing lanes", "executed a left lane change",
    "made a leftward lane change", "changed into the left lane", "changes lanes to the left",
    "began merging into the left lane", "started merging left", "attempted to merge left",
    "tried to merge into the left lane", "crossed over into the left lane", "moved laterally into the left lane",
    "moved left into the Waymo AV's lane", "veered left", "swerved left", "drifted left", "veered to the left",
    "drifted to the left", "changed lanes from the right lane to the left lane",
    "moved from the right lane to the left lane", "merged from the right lane into the left lane",
    "crossed the lane line", "crossed the lane divider", "crossed over the dashed lane line",
    "began to encroach into the Waymo AV's lane", "encroached into the left lane",
    "encroached on the Waymo AV's lane", "encroached upon the Waymo AV's lane", "intruded into the Waymo AV's lane",
    "entered into the Waymo AV's lane of travel", "moved into the Waymo AV's lane of travel",
    "moved into the Waymo AV's travel lane", "merged into the Waymo AV's travel lane",
    "cut over into the Waymo AV's lane",
    "lane-changed to the left", "lane changed to the left", "lane-changed into the Waymo AV's lane",
    "performed a lane-change to the left", "made a lane-change", "initiated a lane-change", "switched lane",
    "changed lanes leftward", "merged leftward", "changed into the left lane",
)
_U_TURN = (
    "made a U-turn", "made a u-turn", "made a U turn", "made a uturn", "performed a U-turn", "executed a U-turn",
    "U-turned", "u-turned", "began a U-turn", "initiated a U-turn", "attempted a U-turn",
    "attempted to make a U-turn", "began to make a U-turn", "started a U-turn", "turned around",
    "made a three-point turn", "made a 3-point turn", "performed a three point turn", "made a K-turn",
    "made a multi-point turn", "began to U-turn", "attempted to U-turn", "made a U-turn maneuver",
    "conducted a U-turn", "made an illegal U-turn", "pulled a U-turn", "did a U-turn", "made a U‑turn",
    "began a three-point turn", "turned around in the roadway",
)
_BACKING = (
    "backed up", "reversed", "began to back up", "began backing up", "started backing up", "started to reverse",
    "began reversing", "began to reverse", "backed into the Waymo AV", "rolled backward", "rolled backwards",
    "rolled back", "moved backward", "moved backwards", "moved in reverse", "traveled in reverse",
    "drove in reverse", "drove backward", "went in reverse", "shifted into reverse and backed up",
    "put the car in reverse", "reversed toward the Waymo AV", "backed toward the Waymo AV", "was backing up",
    "was reversing", "attempted to back up", "attempted to reverse", "proceeded to reverse", "proceeded to back up",
    "reversed into the Waymo AV", "backs up", "reverses", "began to roll backward", "began rolling backward",
    "started rolling back", "began to move backward", "began moving in reverse", "reversed slowly",
    "slowly backed up", "suddenly reversed", "drifted backward", "crept backward", "began to back",
    "was traveling in reverse", "was moving in reverse", "was driving in reverse", "backed out",
)
_STOPPING = (
    "stopped", "came to a stop", "came to a halt", "came to a complete stop", "came to a sudden stop",
    "braked to a stop", "halted", "slowed to a stop", "came to a standstill", "stopped short", "stopped abruptly",
    "abruptly stopped", "suddenly stopped", "stopped suddenly", "pulled to a stop", "screeched to a halt",
    "slammed on its brakes and stopped", "braked hard and stopped", "came to an abrupt stop", "made a sudden stop",
    "made an abrupt stop", "stopped quickly", "slowed and stopped", "decelerated to a stop", "slowed to a halt",
    "came to a full stop", "came to a rapid stop", "came to an unexpected stop", "came to a stop in the lane",
    "stopped in the lane", "braked to a complete stop", "stopped in front of the Waymo AV", "stopped unexpectedly",
    "unexpectedly stopped", "hard braked to a stop", "came to a sudden halt", "ground to a halt",
    "slammed to a stop", "comes to a stop", "came to rest", "decelerated rapidly to a stop",
    "stopped short in front of the Waymo AV", "came to an emergency stop", "made an emergency stop",
    "performed an emergency stop", "slowed down to a stop", "slowed down and stopped", "stopped for a pedestrian",
    "yielded to a pedestrian and stopped", "stopped to yield to a pedestrian",
)
_SLOWING = (
    "slowed", "slowed down", "decelerated", "braked", "braked suddenly", "suddenly braked", "braked hard",
    "hard braked", "applied its brakes", "applied the brakes", "hit the brakes", "slammed on the brakes",
    "slammed on its brakes", "reduced speed", "reduced its speed", "began to slow", "began slowing",
    "started to slow", "began to brake", "began braking", "started braking", "slowed abruptly", "abruptly slowed",
    "decelerated rapidly", "rapidly decelerated", "slowed rapidly", "slowed suddenly", "suddenly slowed",
    "slowed quickly", "decreased speed", "decreased its speed", "lowered its speed", "braked abruptly",
    "abruptly braked", "braked sharply", "slowed unexpectedly", "braked unexpectedly", "slowed significantly",
    "stepped on the brakes", "tapped its brakes", "tapped the brakes", "engaged its brakes", "slows", "brakes",
    "slowed its speed", "cut its speed", "dropped its speed", "slowed sharply", "hard-braked",
    "performed a hard brake", "executed a hard braking maneuver", "made a hard brake",
    "came to a near stop", "came to a rolling stop", "came to an almost complete stop", "slowed to a near stop",
    "came nearly to a stop", "slowed almost to a stop", "slowed to a near standstill",
    "hits its brakes", "taps its brakes", "slams on its brakes", "steps on its brakes", "pumps its brakes",
)
_MOVING_OFF = (
    "began to move", "began moving", "started moving", "started to move", "moved forward", "began to move forward",
    "accelerated from a stop", "pulled forward", "started from a stop", "took off", "began moving forward",
    "crept forward", "inched forward", "rolled forward", "began to accelerate", "began to roll forward",
    "started rolling", "began rolling forward", "began to creep forward", "proceeded forward", "moved off",
    "pulled away", "set off", "resumed motion", "resumed moving", "began to proceed", "started to proceed",
    "accelerated forward", "lurched forward", "surged forward", "moved ahead", "pulled ahead",
    "began to pull forward", "edged forward", "nudged forward", "accelerated from a standstill",
    "began to drive forward", "started driving forward", "began to go", "started to go", "proceeded from its stop",
    "started forward", "moved up", "crept ahead", "inched ahead", "rolled ahead", "began to creep",
    "began creeping forward", "started creeping forward", "began inching forward", "started to roll",
    "drove forward", "accelerated", "proceeded", "began to travel forward", "moved forward slowly",
    "slowly moved forward", "slowly began to move", "released its brakes and rolled forward",
    "departed from the stop", "accelerated quickly from a stop", "launched forward", "moved forward unexpectedly",
)

_PULLING_OUT = (
    "pulled out", "pulled out from the curb", "pulled away from the curb", "pulled out of its parking space",
    "pulled out of a parking spot", "left its parking spot", "exited its parking space", "exited a parking spot",
    "began to pull out", "began pulling out", "started to pull out", "attempted to pull out", "pulled into traffic",
    "pulled out into traffic", "merged into traffic", "entered traffic", "entered the roadway",
    "pulled into the roadway", "pulled out into the roadway", "pulled out into the lane",
    "pulled into the travel lane", "moved into the travel lane", "departed from the curb", "left the curb",
    "pulled out from its parked position", "pulled out of its parked position", "began to pull away from the curb",
    "began to merge into traffic", "pulled off the curb", "moved away from the curb", "merged into the travel lane",
    "pulled out into the travel lane", "entered the travel lane", "moved out from the curb",
    "pulled out from the parking lane", "pulled out of the parking lane", "left the parking lane",
    "exited the parking lane", "moved out of the parking lane", "began to enter the roadway",
    "pulled from the curb", "pulled away from the curb into the Waymo AV's lane", "nosed out from the curb",
    "eased out from the curb", "pulled out of a parallel parking spot", "pulled out of a curbside parking space",
    "merged from the parking lane",
)

_PULLING_OVER = (
    "pulled over", "pulled over to the curb", "pulled to the curb", "pulled up to the curb", "began to park",
    "pulled into a parking spot", "pulled into a parking space", "began to parallel park", "was parallel parking",
    "attempted to parallel park", "pulled over to the right", "pulled toward the curb",
    "pulled over to the side of the road", "pulled onto the shoulder", "pulled over onto the shoulder",
    "moved onto the shoulder", "pulled into the parking lane", "moved into the parking lane",
    "pulled to the side of the road", "began to pull over", "started to pull over", "attempted to pull over",
)

_SPEEDING_UP = (
    "accelerated", "sped up", "picked up speed", "increased its speed", "increased speed", "gained speed",
    "began to accelerate", "started to accelerate", "accelerated rapidly", "rapidly accelerated",
    "suddenly accelerated", "accelerated suddenly", "stepped on the gas", "hit the gas", "floored it",
    "pressed the accelerator", "stepped on the accelerator", "accelerated quickly", "began accelerating",
    "was accelerating", "sped forward", "gunned the engine", "speeds up", "accelerates", "began speeding up",
    "continued to accelerate",
)

_CROSSING_ON_FOOT = (
    "crossed the street", "walked across the street", "was crossing the street", "ran across the street",
    "darted across the street", "stepped off the curb", "jaywalked", "entered the crosswalk",
    "crossed in front of the Waymo AV", "walked in front of the Waymo AV", "ran into the street",
    "darted into the street", "stepped into the street", "stepped into the roadway", "stepped out into the road",
    "began to cross the street", "started crossing the street", "attempted to cross the street",
    "crossed mid-block", "crossed against the light", "crossed outside the crosswalk",
    "walked into the path of the Waymo AV", "emerged from between parked cars",
    "stepped out from between two parked cars", "crossed the roadway", "walked across the roadway",
    "was walking across the road", "entered the roadway from the sidewalk", "came out from behind a parked truck",
    "ran out in front of the Waymo AV", "dashed across the street", "hurried across the street",
    "jogged across the street", "was jaywalking across Mission Street", "crosses the street",
    "walks across the street", "walked out into traffic", "stepped off the sidewalk", "stepped down from the curb",
    "crossed Mission Street", "walked across Mission Street", "ran across Mission Street",
    "was crossing Mission Street", "began crossing Mission Street", "crossed from the west curb",
    "crossed from east to west", "walked from the east side of the street to the west side",
)

_OUT_OF_A_DRIVEWAY = (
    "exited a driveway", "pulled out of a driveway", "emerged from a parking lot", "left a gas station",
    "came out of an alley", "pulled out of a parking lot", "exited a parking lot", "drove out of a driveway",
    "pulled out from a driveway", "exited from a driveway", "was exiting a driveway", "began to exit a driveway",
    "pulled out of an alley", "exited an alley", "emerged from an alley", "exited a parking garage",
    "pulled out of a parking garage", "came out of a parking garage", "exited a private driveway",
    "pulled out of a residential driveway", "left a driveway", "departed a parking lot",
    "exited the driveway of a gas station", "pulled out from a gas station", "exited a shopping center parking lot",
    "pulled out of the driveway on the right", "rolled out of a driveway", "nosed out of a driveway",
    "edged out of a driveway", "exited a driveway on the right side of the street",
    "pulled out of a business driveway", "came out of a driveway", "pulled from a driveway", "exits a driveway",
    "pulls out of a driveway", "emerged from a driveway", "exited a parking structure",
)

# A move of a party behind the AV and the rear corner of the AV it struck -> the party's lane (session 18).
# The side of a numbered lane from the AV's lane 2 (lanes count from the left).
_NUMBERED_SIDE = {"1": "left", "one": "left", "2": "same", "two": "same", "3": "right", "three": "right"}
# A lane beside the AV named without its side.
_ADJACENT_NO_SIDE = ("in an adjacent lane", "in the adjacent lane", "traveling in the adjacent lane",
                     "in the adjacent travel lane", "driving in an adjacent lane")
_REAR_CORNER_MOVES = {
    "changed lanes to the left and struck the rear passenger side corner of the Waymo AV": "right",
    "changed lanes to the right and struck the rear driver side corner of the Waymo AV": "left",
    "moved over to the right and made contact with the Waymo AV's left rear corner": "left",
    "merged to the left and made contact with the right rear corner of the Waymo AV": "right",
    "changed lanes to the left and made contact with the rear left corner of the Waymo AV": "same",
    "changed lanes to the right and made contact with the Waymo AV's right rear corner": "same",
}


_MOVING_THING_SIDES = {
    "ran from the west side of [XXX] into the roadway": "left", "darted into the road from the left": "left",
    "ran into the street from the east side of the street": "right", "came from the right": "right",
    "crossed from the western curb": "left", "ran out from the left side": "left",
    "emerged from the east sidewalk": "right", "ran across the road from the right": "right",
}


# Session 19: whole scenes of the collision party's place, one per construction the fresh SGO narratives use.
_SESSION19_SCENES: tuple[tuple[str, object], ...] = (
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was stopped in a queue of traffic '
     'on northbound [XXX]. A passenger car traveling northbound approached from behind and the front of the '
     "passenger car made contact with the rear of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 "
     'ADS was engaged in autonomous mode. Both vehicles sustained damage.',
     ('R6', 'same')),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling northbound on [XXX] '
     'and slowed for traffic ahead. The front of a passenger car made contact with the rear of the Waymo AV. At the '
     "time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles sustained "
     'damage.',
     ('R6', 'same')),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was stopped on northbound [XXX]. A '
     'passenger car that was approaching from behind made contact with the rear bumper of the Waymo AV. At the time '
     "of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage.",
     ('R6', 'same')),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was stopped on northbound [XXX]. A '
     'passenger car traveling in the adjacent lane to the left approached from behind and made contact with the '
     "rear driver side of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in "
     'autonomous mode. Both vehicles sustained damage.',
     ('R6', 'left')),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling northbound on [XXX]. '
     'A passenger car that was traveling in the adjacent lane to the left began to change lanes to the right, and '
     'the passenger side of the passenger car made contact with the front driver side of the Waymo AV. At the time '
     "of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage.",
     ('R5', 'left')),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling northbound on [XXX]. '
     "A passenger car that was traveling in the adjacent lane to the right merged into the Waymo AV's lane and made "
     "contact with the front passenger side of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS "
     'was engaged in autonomous mode. Both vehicles sustained damage.',
     ('R5', 'right')),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling northbound on [XXX] '
     'in the left lane. A passenger car traveling northbound in the right lane changed lanes to the left and made '
     "contact with the front passenger side of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS "
     'was engaged in autonomous mode. Both vehicles sustained damage.',
     ('R5', 'right')),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling northbound on [XXX] '
     'in the left lane. A passenger car traveling northbound in the right lane behind the Waymo AV changed lanes to '
     'the left and made contact with the rear passenger side of the Waymo AV. At the time of the impact, the Waymo '
     "AV's Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage.",
     ('R6', 'right')),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling northbound on [XXX]. '
     'A passenger car traveling southbound in the opposing lane crossed the center line and the front of the '
     'passenger car made contact with the front driver side of the Waymo AV. At the time of the impact, the Waymo '
     "AV's Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage.",
     ('R7', 'left')),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling northbound on [XXX]. '
     'A passenger car traveling in the opposing lane drifted across the double yellow line and made contact with '
     "the driver side of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in "
     'autonomous mode. Both vehicles sustained damage.',
     ('R7', 'left')),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling northbound on [XXX]. '
     "A southbound passenger car crossed into the Waymo AV's lane and made contact with the front left of the Waymo "
     "AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles "
     'sustained damage.',
     ('R7', 'left')),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling northbound on [XXX]. '
     'A passenger car traveling in the opposite direction made contact with the driver side mirror of the Waymo AV. '
     "At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles sustained "
     'damage.',
     ('R7', 'left')),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling northbound on [XXX] '
     'and proceeded through the intersection with [XXX] on a green light. A passenger car traveling eastbound on '
     '[XXX] entered the intersection and made contact with the driver side of the Waymo AV. At the time of the '
     "impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage.",
     ('R1', None)),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling northbound on [XXX] '
     'and proceeded through the intersection with [XXX] on a green light. A passenger car traveling westbound on '
     '[XXX] entered the intersection and made contact with the passenger side of the Waymo AV. At the time of the '
     "impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage.",
     ('R3', None)),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling northbound on [XXX] '
     "and entered the intersection with [XXX]. A passenger car crossing from the Waymo AV's left made contact with "
     "the driver side of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in "
     'autonomous mode. Both vehicles sustained damage.',
     ('R1', None)),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling northbound on [XXX] '
     'and entered the intersection with [XXX]. A passenger car crossing from the right made contact with the front '
     "passenger side of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in "
     'autonomous mode. Both vehicles sustained damage.',
     ('R3', None)),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling northbound on [XXX] '
     'and entered the intersection with [XXX]. A passenger car that was stopped facing westbound on the cross '
     'street began to proceed and made contact with the passenger side of the Waymo AV. At the time of the impact, '
     "the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage.",
     ('R3', None)),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling northbound on [XXX] '
     'and entered the intersection with [XXX]. A passenger car that was stopped facing eastbound on [XXX] proceeded '
     'into the intersection and made contact with the driver side of the Waymo AV. At the time of the impact, the '
     "Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage.",
     ('R1', None)),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling northbound on [XXX]. '
     'A passenger car exited a driveway on the right and made contact with the passenger side of the Waymo AV. At '
     "the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles sustained "
     'damage.',
     ('R5', 'right')),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling northbound on [XXX]. '
     'A passenger car exiting a parking lot on the right side of the road pulled into the path of the Waymo AV and '
     "made contact with the front of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was "
     'engaged in autonomous mode. Both vehicles sustained damage.',
     ('R5', 'right')),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling northbound on [XXX]. '
     'A passenger car exited a driveway on the left and made contact with the driver side of the Waymo AV. At the '
     "time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles sustained "
     'damage.',
     ('R5', 'left')),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling northbound on [XXX]. '
     'A passenger car exited a parking lot on the west side of [XXX] and made contact with the driver side of the '
     "Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles "
     'sustained damage.',
     ('R5', 'left')),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling northbound on [XXX] '
     'and proceeded through the intersection with [XXX] on a green light. A passenger car traveling southbound on '
     '[XXX] made a left turn in front of the Waymo AV and the front of the Waymo AV made contact with the passenger '
     "side of the passenger car. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous "
     'mode. Both vehicles sustained damage.',
     ('R2', None)),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was stopped at a red light on '
     'northbound [XXX]. A passenger car traveling northbound passed the Waymo AV on the left and made contact with '
     "the driver side mirror of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in "
     'autonomous mode. Both vehicles sustained damage.',
     ('R6', 'left')),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling northbound on [XXX] '
     'behind a passenger car. The passenger car braked suddenly and the front of the Waymo AV made contact with the '
     "rear of the passenger car. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous "
     'mode. Both vehicles sustained damage.',
     ('R5', 'same')),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling northbound on [XXX] '
     'following a passenger car. The passenger car began to reverse and made contact with the front of the Waymo '
     "AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles "
     'sustained damage.',
     ('R5', 'same')),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling northbound on [XXX] '
     'following behind a passenger car. The passenger car began to reverse and made contact with the front of the '
     "Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles "
     'sustained damage.',
     ('R5', 'same')),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was stopped at a red light on '
     'northbound [XXX]. A passenger car traveling behind the Waymo AV failed to stop and made contact with the rear '
     "of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both "
     'vehicles sustained damage.',
     ('R6', 'same')),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was stopped at a red light on '
     'northbound [XXX]. A passenger car in the lane to the right of the Waymo AV attempted to change lanes to the '
     "left and made contact with the rear passenger side of the Waymo AV. At the time of the impact, the Waymo AV's "
     'Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage.',
     ('R6', 'right')),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling northbound on [XXX]. '
     'A passenger car traveling in the adjacent lane to the right of the Waymo AV changed lanes to the left into '
     "the Waymo AV's lane, and the driver side of the passenger car made contact with the passenger side of the "
     "Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles "
     'sustained damage.',
     ('R5', 'right')),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was stopped on northbound [XXX]. A '
     "southbound passenger car made a left turn into a driveway across the Waymo AV's lane and made contact with "
     "the front of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous "
     'mode. Both vehicles sustained damage.',
     ('R7', 'left')),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was parked at the curb on the east '
     'side of northbound [XXX]. A passenger car reversed out of a driveway on the west side of [XXX] and made '
     "contact with the driver side of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was "
     'engaged in autonomous mode. Both vehicles sustained damage.',
     ('R7', 'left')),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling northbound on [XXX]. '
     'An oncoming passenger car made contact with the driver side mirror of the Waymo AV. At the time of the '
     "impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage.",
     ('R7', 'left')),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling northbound on [XXX]. '
     'A passenger car traveling behind the Waymo AV made contact with the rear of the Waymo AV. At the time of the '
     "impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage.",
     ('R6', 'same')),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was stopped on northbound [XXX] '
     "when it was rear-ended by a passenger car. At the time of the impact, the Waymo AV's Level 4 ADS was engaged "
     'in autonomous mode. Both vehicles sustained damage.',
     ('R6', 'same')),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. While the Waymo AV was stopped on northbound '
     "[XXX], a passenger car collided with the rear of the Waymo AV. At the time of the impact, the Waymo AV's "
     'Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage.',
     ('R6', 'same')),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was stopped on northbound [XXX]. A '
     "passenger car struck the Waymo AV from behind. At the time of the impact, the Waymo AV's Level 4 ADS was "
     'engaged in autonomous mode. Both vehicles sustained damage.',
     ('R6', 'same')),
    ('On March [XXX], 2025 at 1:14 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in Phoenix, Arizona was '
     'in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was stopped on northbound [XXX]. A '
     "passenger car made contact with the Waymo AV's rear bumper. At the time of the impact, the Waymo AV's Level 4 "
     'ADS was engaged in autonomous mode. Both vehicles sustained damage.',
     ('R6', 'same')),
    ('On May [XXX], 2024 at 2:10 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
     'California was in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling '
     'northbound on [XXX]. A passenger car traveling in the opposite direction made a left turn in front of the '
     'Waymo AV into a driveway, and the front of the Waymo AV made contact with the passenger side of the passenger '
     "car. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles "
     'sustained damage.',
     ('R7', 'left')),
    ('On May [XXX], 2024 at 2:10 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
     'California was in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling '
     'northbound on [XXX]. A passenger car that was stopped in the left turn lane to the left of the Waymo AV began '
     "to merge into the Waymo AV's lane and made contact with the driver side of the Waymo AV. At the time of the "
     "impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage.",
     ('R5', 'left')),
    ('On May [XXX], 2024 at 2:10 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
     'California was in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling '
     'northbound on [XXX]. A passenger car, which had been parked on the right side of the road, pulled into the '
     "Waymo AV's lane and made contact with the passenger side of the Waymo AV. At the time of the impact, the "
     "Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage.",
     ('R5', 'right')),
    ('On May [XXX], 2024 at 2:10 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
     'California was in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling '
     'northbound on [XXX]. A cyclist riding in the bike lane to the right of the Waymo AV swerved into the lane and '
     "made contact with the passenger side of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS "
     'was engaged in autonomous mode. Both vehicles sustained damage.',
     ('R5', 'right')),
    ('On May [XXX], 2024 at 2:10 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
     'California was in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling '
     'northbound on [XXX]. A bus that was pulling away from a bus stop on the right made contact with the passenger '
     "side of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. "
     'Both vehicles sustained damage.',
     ('R5', 'right')),
    ('On May [XXX], 2024 at 2:10 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
     'California was in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling '
     'northbound on [XXX] in the left lane. A passenger car traveling in the same direction in the lane to the '
     "right moved into the Waymo AV's lane and made contact with the passenger side of the Waymo AV. At the time of "
     "the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage.",
     ('R5', 'right')),
    ('On May [XXX], 2024 at 2:10 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
     'California was in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling '
     'northbound on [XXX]. A passenger car emerged from a parking garage on the left side of the street and made '
     "contact with the driver side of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was "
     'engaged in autonomous mode. Both vehicles sustained damage.',
     ('R5', 'left')),
    ('On May [XXX], 2024 at 2:10 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
     'California was in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling '
     'northbound on [XXX]. A passenger car reversing out of a parking space on the right made contact with the '
     "passenger side of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in "
     'autonomous mode. Both vehicles sustained damage.',
     ('R5', 'right')),
    ('On May [XXX], 2024 at 2:10 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
     'California was in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was stopped on '
     'northbound [XXX]. The Waymo AV began to reverse and made contact with a passenger car that was stopped behind '
     "it. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles "
     'sustained damage.',
     ('R6', 'same')),
    ('On May [XXX], 2024 at 2:10 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
     'California was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV was traveling '
     'northbound on [XXX] and entered the intersection with [XXX] on a green light. A passenger car approaching '
     'from the opposite direction made a left turn across the path of the Waymo AV and made contact with the front '
     "of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both "
     'vehicles sustained damage.',
     ('R2', None)),
    ('On May [XXX], 2024 at 2:10 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
     'California was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV was traveling '
     'northbound on [XXX] and entered the intersection with [XXX] on a green light. A passenger car traveling on '
     "the cross street from the Waymo AV's right entered the intersection and made contact with the passenger side "
     "of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both "
     'vehicles sustained damage.',
     ('R3', None)),
    ('On May [XXX], 2024 at 2:10 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
     'California was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV was stopped at a stop '
     'sign on northbound [XXX] at the intersection with [XXX]. A pickup truck that was stopped at the stop sign on '
     'the cross street to the right of the Waymo AV proceeded into the intersection and made contact with the front '
     "of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both "
     'vehicles sustained damage.',
     ('R3', None)),
    ('On May [XXX], 2024 at 2:10 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
     'California was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV was traveling '
     'northbound on [XXX] and entered the intersection with [XXX]. A passenger car coming from the left on [XXX] '
     'failed to yield and made contact with the driver side of the Waymo AV. At the time of the impact, the Waymo '
     "AV's Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage.",
     ('R1', None)),
    ('On May [XXX], 2024 at 2:10 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
     'California was in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling '
     'northbound on [XXX]. A passenger car ahead of the Waymo AV in the same lane stopped suddenly, and the front '
     "of the Waymo AV made contact with the rear of the passenger car. At the time of the impact, the Waymo AV's "
     'Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage.',
     ('R5', 'same')),
    ('On May [XXX], 2024 at 2:10 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
     'California was in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling '
     'northbound on [XXX]. The lead vehicle braked hard, and the Waymo AV made contact with the rear of the lead '
     "vehicle. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles "
     'sustained damage.',
     ('R5', 'same')),
    ('On May [XXX], 2024 at 2:10 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
     'California was in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling '
     'northbound on [XXX] in the right lane. A passenger car traveling in the left lane behind the Waymo AV '
     'attempted to change into the right lane and made contact with the rear driver side of the Waymo AV. At the '
     "time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles sustained "
     'damage.',
     ('R6', 'left')),
    ('On May [XXX], 2024 at 2:10 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
     'California was in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling '
     'northbound on [XXX] in the left lane. A motorcyclist approaching from behind in the right lane attempted to '
     'pass and made contact with the passenger side mirror of the Waymo AV. At the time of the impact, the Waymo '
     "AV's Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage.",
     ('R6', 'right')),
    ('On May [XXX], 2024 at 2:10 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
     'California was in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling '
     'northbound on [XXX]. A scooter rider on the sidewalk to the right of the Waymo AV rode into the roadway and '
     "made contact with the passenger side of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS "
     'was engaged in autonomous mode. Both vehicles sustained damage.',
     ('R5', 'right')),
    ('On May [XXX], 2024 at 2:10 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
     'California was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV was making a right '
     'turn from northbound [XXX] onto eastbound [XXX]. A pedestrian crossing [XXX] in the crosswalk made contact '
     "with the passenger side of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in "
     'autonomous mode. Both vehicles sustained damage.',
     ('R4', None)),
    ('On May [XXX], 2024 at 2:10 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
     'California was in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was stopped in '
     'traffic on northbound [XXX]. A passenger car traveling northbound on [XXX] did not stop in time and its front '
     "made contact with the Waymo AV's rear. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in "
     'autonomous mode. Both vehicles sustained damage.',
     ('R6', 'same')),
    ('On May [XXX], 2024 at 2:10 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
     'California was in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was slowing to a '
     'stop on northbound [XXX] for a pedestrian. The vehicle behind the Waymo AV, a passenger car, made contact '
     "with the rear of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in "
     'autonomous mode. Both vehicles sustained damage.',
     ('R6', 'same')),
    ('On May [XXX], 2024 at 2:10 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
     'California was in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling '
     'northbound on [XXX]. A passenger car traveling southbound on [XXX] made a U-turn and made contact with the '
     "driver side of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in autonomous "
     'mode. Both vehicles sustained damage.',
     ('R7', 'left')),
    ('On May [XXX], 2024 at 2:10 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
     'California was in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling '
     'northbound on [XXX]. A passenger car that was parallel parked on the right began to make a U-turn and made '
     "contact with the front passenger side of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS "
     'was engaged in autonomous mode. Both vehicles sustained damage.',
     ('R5', 'right')),
    ('On May [XXX], 2024 at 2:10 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
     'California was in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling '
     'northbound on [XXX] on a two-lane road. A southbound passenger car swerved to avoid a cyclist and crossed '
     "into the Waymo AV's lane, making contact with the front of the Waymo AV. At the time of the impact, the Waymo "
     "AV's Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage.",
     ('R7', 'left')),
    ('On May [XXX], 2024 at 2:10 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
     'California was in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was traveling '
     'northbound on [XXX]. A delivery van double-parked in the right lane began to pull forward and made contact '
     "with the passenger side of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in "
     'autonomous mode. Both vehicles sustained damage.',
     ('R5', 'right')),
    ('On May [XXX], 2024 at 2:10 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San Francisco, '
     'California was in a collision involving a passenger car on [XXX] near [XXX]. The Waymo AV was stopped for a '
     'red light on northbound [XXX]. A passenger car in the adjacent left lane, which had been stopped behind the '
     "Waymo AV's rear, began to move forward and made contact with the driver side of the Waymo AV. At the time of "
     "the impact, the Waymo AV's Level 4 ADS was engaged in autonomous mode. Both vehicles sustained damage.",
     ('R6', 'left')),
    ('A Cruise autonomous vehicle ("Cruise AV"), operating in driverless autonomous mode, was stopped at a red '
     'light on eastbound Pine Street at Polk Street when a Toyota Prius approached from behind and made contact '
     'with the rear bumper of the Cruise AV.',
     ('R6', 'same')),
    ('A Cruise autonomous vehicle ("Cruise AV"), operating in autonomous mode, was traveling eastbound on Pine '
     'Street in the right lane. A Honda Civic traveling in the left lane attempted to merge into the right lane '
     'behind the Cruise AV and made contact with the rear left bumper of the Cruise AV.',
     ('R6', 'left')),
    ('A Cruise autonomous vehicle ("Cruise AV"), operating in autonomous mode, was traveling northbound on Valencia '
     'Street. A cyclist in the bike lane to the right of the Cruise AV moved left into the lane and made contact '
     'with the right side of the Cruise AV.',
     ('R5', 'right')),
    ('A Waymo Autonomous Vehicle ("Waymo AV") was stopped in the left lane of northbound Mission Street at a red '
     'light. A motorcyclist riding between the lanes passed on the right side of the Waymo AV and made contact with '
     'the right side mirror.',
     ('R6', 'right')),
    ('A Zoox vehicle was traveling northbound on Market Street in autonomous mode. A vehicle traveling southbound '
     'crossed over the double yellow lines and sideswiped the left side of the Zoox vehicle.',
     ('R7', 'left')),
    ('A Cruise autonomous vehicle ("Cruise AV") was traveling northbound on Fillmore Street through the '
     'intersection with Geary Boulevard on a green light when a Ford Fusion traveling eastbound on Geary Boulevard '
     'ran the red light and struck the left side of the Cruise AV.',
     ('R1', None)),
    ('A Cruise autonomous vehicle ("Cruise AV") was traveling northbound on Fillmore Street through the '
     'intersection with Geary Boulevard on a green light when a Ford Fusion traveling westbound on Geary Boulevard '
     'ran the red light and struck the right side of the Cruise AV.',
     ('R3', None)),
    ('A Cruise autonomous vehicle ("Cruise AV") was traveling northbound on Fillmore Street and entered the '
     'intersection with Geary Boulevard on a green light when a southbound Nissan Altima made a left turn across '
     'the path of the Cruise AV, and the front of the Cruise AV made contact with the right side of the Nissan '
     'Altima.',
     ('R2', None)),
    ('The Waymo vehicle was stopped for a pedestrian at the crosswalk on westbound El Camino Real when another '
     'vehicle traveling in the same direction collided with the rear of the Waymo vehicle.',
     ('R6', 'same')),
    ('Our vehicle (V1) was stopped at the limit line. V2 was behind V1 and rear-ended V1.',
     ('R6', 'same')),
    ('Our AV was traveling behind a box truck on westbound Howard Street. The box truck stopped and began '
     'reversing, making contact with the front bumper of our AV.',
     ('R5', 'same')),
    ('The Pony.ai vehicle was stopped at a red light in the number 2 lane of northbound Main Street. A sedan in the '
     'number 1 lane approached from behind and made contact with the left rear quarter panel of the Pony.ai vehicle '
     'while changing lanes.',
     ('R6', 'left')),
    ('The WeRide vehicle was traveling in the number 1 lane of northbound Main Street. A pickup truck in the number '
     '2 lane changed lanes to the left and made contact with the right front fender of the WeRide vehicle.',
     ('R5', 'right')),
    ('The AutoX vehicle was traveling in the number 2 lane of eastbound Stevens Creek Boulevard. A sedan in the '
     'number 1 lane made an unsafe lane change to the right and struck the left front of the AutoX vehicle.',
     ('R5', 'left')),
    ('The Apple vehicle was stopped in traffic on northbound De Anza Boulevard when it was struck in the rear by a '
     'passenger vehicle.',
     ('R6', 'same')),
    ('While stopped at the red light, our vehicle was hit from behind by a Honda Accord.',
     ('R6', 'same')),
    ('The Nuro vehicle was traveling northbound on Bay Area Boulevard when a vehicle pulled out of a driveway on '
     'the right and struck the right side of the Nuro vehicle.',
     ('R5', 'right')),
    ('The Waymo AV was stopped at the stop sign on southbound Hill Street at Elm Street and then proceeded into the '
     'intersection. A sedan traveling eastbound on Elm Street failed to stop at its stop sign and made contact with '
     'the right side of the Waymo AV.',
     ('R3', None)),
    ('The Cruise AV was stopped in the left-turn lane on northbound Van Ness Avenue. A pickup truck in the adjacent '
     'through lane to its right, traveling northbound, moved left and made contact with the rear passenger side of '
     'the Cruise AV.',
     ('R6', 'right')),
    ('The Cruise AV was proceeding northbound on Van Ness Avenue. A Tesla following too closely behind the Cruise '
     'AV failed to stop and made contact with the rear of the Cruise AV.',
     ('R6', 'same')),
)


PROBES: tuple[Probe, ...] = (
    # A turn that swings over the centre line: the crossing is the turn's own path, no lane change.
    Probe("a turn that crosses the centre line",
          "The Waymo AV was stopped at a red light on Mission Street at 16th Street. A heavy truck traveling west on "
          "16th Street {w}, and the left side of the truck made contact with the driver side front corner of the "
          "Waymo AV.",
          ("made a left turn onto Mission Street crossing the center line",
           "turned left onto Mission Street and partially crossed the centerline",
           "turned left onto Mission Street, partially crossing the double yellow line",
           "made a left turn onto Mission Street, crossing over the centre line"),
          lambda sk: [p.actions for p in sk.npcs], ["ad"]),
    # The party the AV reacted to, named in the AV's reason told after the contact.
    Probe("the party the AV acted for, named after the contact",
          "The Zoox vehicle was traveling in the right lane of Main Street when it struck the curb. The Zoox vehicle "
          "had moved toward the curb {w} a truck in the adjacent lane.",
          ("due to", "because of", "in response to", "to avoid", "due to perceived risk from", "in order to avoid"),
          lambda sk: ([p.category for p in sk.npcs], [o.category for o in sk.obstacles]), (["truck"], ["barrier"])),
    # A chain collision's party named after the AV's contact: its string is what its own sentence tells.
    Probe("a party of the chain that stopped after the AV's contact",
          "The Waymo AV was stopped at a red light on Mission Street. An SUV traveling behind the Waymo AV struck its "
          "rear bumper. A passenger car then {w} behind the SUV. A pickup truck then made contact with the rear of the "
          "passenger car.",
          ("braked to a stop", "came to a stop", "slowed to a stop", "came to an abrupt stop", "came to a complete stop",
           "braked hard and stopped", "applied the brakes to a stop", "braked to stop", "slowed to stop"),
          lambda sk: [(p.start, p.actions) for p in sk.npcs], [("moving", "a"), ("moving", "ah"), ("moving", "a")]),
    # The vehicle the AV stopped behind stood, wherever the AV's clause places the AV first.
    Probe("the vehicle the AV stopped behind, its place told between",
          "The Waymo AV came to a stop {w} behind a van that was unloading passengers in the travel lane. A sedan "
          "behind the Waymo AV then changed lanes to pass and struck the rear left corner of the Waymo AV.",
          ("", "in the rightmost lane", "in the right lane heading south on Mission Street at 16th Street,",
           "in its lane on Mission Street,", "on southbound Mission Street near 16th Street,",
           "in the travel lane, directly", "at the curb lane of Mission Street,"),
          lambda sk: [(p.start, p.actions) for p in sk.npcs if p.category == "van"], [("stopped", "")]),
    # The AV's operator's name misspelt ("the Wamo AV"): still the AV, whose standing is no party's; another
    # operator's AV is a party, a car.
    Probe("the AV's operator's name misspelt",
          "The Waymo AV was stopped in traffic on Mission Street. While the {w} AV remained stopped, a van traveling "
          "behind the Waymo AV entered the left adjacent lane to go around the Waymo AV, and the front passenger side "
          "of the van made contact with the rear driver side of the Waymo AV.",
          ("Waymo", "Wamo", "Wamyo", "Waymoo", "Wayom", "Wyamo"),
          _npc_actions, [("moving", "af")]),
    Probe("another operator's AV behind the AV",
          "A Zoox vehicle in autonomy was stopped at a red light on Folsom Street. {W} traveling behind the Zoox "
          "vehicle struck its rear bumper.",
          ("a Cruise AV", "a Waymo AV", "a Waymo autonomous vehicle", "a Cruise autonomous vehicle", "another AV"),
          lambda sk: ([p.category for p in sk.npcs], sk.collision.with_), (["car"], "npc1")),
    # Objects by name, as SGO and DMV narratives name them (a ride left lying and a toy are things, not parties).
    Probe("an object the AV's front met, by name",
          "The Waymo AV was traveling north on Mission Street when the front of the Waymo AV made contact with {w} in "
          "its lane.",
          tuple(w for ws in _OBJECTS.values() for w in ws),
          lambda sk: ([o.category for o in sk.obstacles], len(sk.npcs)),
          lambda w: ([next(c for c, ws in _OBJECTS.items() if w in ws)], 0)),
    # Session 19 (who counts, what the parties do), from study4's fresh narratives: a stop of the party's own, then
    # a move made to pass the AV (any verb of moving with the pass as its purpose) starts it off again.
    Probe("a party that stopped behind the AV, then moved to pass it",
          "The Waymo AV was stopped at the curb on Mission Street for a passenger pickup when a passenger car "
          "approached the Waymo AV from behind and came to a stop. The passenger car then {w} the Waymo AV on the "
          "left, and the passenger side of the passenger car made contact with the rear driver side of the Waymo AV.",
          ("maneuvered to pass", "moved to pass", "veered to pass", "steered to pass", "attempted to pass",
           "tried to pass", "began to pass", "passed", "proceeded to pass", "started to pass", "overtook",
           "overtakes"),
          _npc_actions, [("moving", "ahi")]),
    # The AV's own door, whatever word of its state stands between "of" and the AV's name.
    Probe("the AV's own open door met by a passing party",
          "A Waymo AV was traveling east on Mission Street, then pulled over at the curb for a passenger drop-off. An "
          "SUV traveling east on Mission Street attempted to pass the Waymo AV on the left, and the passenger side of "
          "the SUV made contact with the open rear door of the {w} Waymo AV.",
          ("stationary", "stopped", "parked", "idle", "standing"),
          lambda sk: (len(sk.obstacles), sk.collision.with_), (0, "npc1")),
    # A vehicle noun naming the damage is no party.
    Probe("a vehicle noun before the damage",
          "The Zoox vehicle was traveling eastbound on Main Street in autonomy. The road curved to the left and the "
          "Zoox vehicle struck the curb, resulting in minor {w}. No other party was involved.",
          ("vehicle damage", "car damage", "vehicle damages", "damage to the vehicle"),
          lambda sk: len(sk.npcs), 0),
    _scenes("the AV told in the first person: the contact and the party's place", lambda sk: (
            sk.collision.with_, [(p.position, p.lane) for p in sk.npcs]), (
            ("Our vehicle was stopped at a red light. A car behind us struck our rear bumper.",
             ("npc1", [("R6", "same")])),
            ("Our AV was stopped at a red light. A car behind us hit our rear bumper.", ("npc1", [("R6", "same")])),
            ("Our test vehicle was stopped at a red light. The car behind struck our rear bumper.",
             ("npc1", [("R6", "same")])),
            ("We were stopped at a red light when a car behind us struck our rear bumper.",
             ("npc1", [("R6", "same")])),
            ("We were traveling northbound in the right lane when a sedan in the left lane changed lanes and struck "
             "our driver side door.", ("npc1", [("R5", "left")])),
            ("Our autonomous vehicle was waiting to turn left. A pickup truck behind us then rear-ended our vehicle.",
             ("npc1", [("R6", "same")])),
            ("At about 9 am we were proceeding through the intersection on a green light when a sedan on the cross "
             "street to our right ran the red light and struck our passenger side.", ("npc1", [("R3", None)])),
    )),
    _scenes("the AV's part named in another sentence than the contact's; a cut-in placed by the part it touched",
            _position, (
            ("On March 3 a Zoox vehicle was struck on the rear bumper by a sedan. The Zoox vehicle was stopped at a red "
             "light on Folsom Street when the sedan hit it.", [("R6", "same")]),
            ("On March 3 a Zoox vehicle was struck on its rear bumper by a sedan. The Zoox vehicle was stopped at a "
             "red light on Folsom Street when the sedan hit the Zoox vehicle, which was stopped.", [("R6", "same")]),
            ("The Zoox vehicle was traveling north on Kearny in the rightmost lane when a bus attempted to change lanes "
             "in front of the Zoox vehicle, impacting its front passenger side fender. The bus then hit the Zoox "
             "vehicle.", [("R5", "right")]),
            ("The Zoox vehicle was traveling north on Kearny when a sedan attempted a lane change in front of the Zoox "
             "vehicle, striking its front driver side bumper.", [("R5", "left")]),
            ("The Cruise AV was traveling in the left lane when a pickup truck merged into the Cruise AV's lane and "
             "made contact with the Cruise AV's front right bumper.", [("R5", "right")]),
            ("The Cruise AV was traveling in the right lane when a pickup truck merged into the Cruise AV's lane and "
             "made contact with the Cruise AV's front left bumper.", [("R5", "left")]),
    )),
    _scenes("the party's own flank met by the AV's front; a merge into the AV's lane from a side", _position, (
            ("The Waymo AV was traveling northbound on Mission Street in the right lane. A sedan in the left "
             "lane began to change lanes to the right, and the front of the Waymo AV made contact with the "
             "right rear of the sedan.",
             [("R5", "left")]),
            ("The Cruise AV was traveling eastbound in the right lane when a passenger vehicle merged into its "
             "lane from the left. The Cruise AV's front bumper made contact with the passenger side of the "
             "vehicle.",
             [("R5", "left")]),
            ("The Zoox vehicle was traveling in the right lane. A vehicle traveling in the left lane moved "
             "into the Zoox vehicle's lane, and the front right of the Zoox vehicle made contact with the rear "
             "passenger side of the vehicle.",
             [("R5", "left")]),
            ("The AV was traveling straight in the center lane when a pickup truck from the left lane cut in "
             "front of it. The AV struck the right rear bumper of the pickup truck.",
             [("R5", "left")]),
            ("The Waymo AV was stopped in the right lane at a red light. A box truck passing on the left side "
             "of the Waymo AV made contact with the Waymo AV's side mirror with its right side.",
             [("R6", "left")]),
            ("The Cruise AV was traveling in the left lane when a sedan in the right lane merged left, and the "
             "front left of the Cruise AV contacted the driver side rear door of the sedan.",
             [("R5", "right")]),
            ("The Cruise AV was traveling in the right lane when a passenger vehicle changed lanes in front of "
             "it. The front of the Cruise AV made contact with the passenger side of the vehicle.",
             [("R5", "left")]),
            ("The Cruise AV was traveling in the left lane when a sedan moved over in front of it. The Cruise "
             "AV's front bumper struck the driver side of the sedan.",
             [("R5", "right")]),
            ("The Cruise AV was traveling in the right lane behind a sedan. The sedan braked suddenly and the "
             "front of the Cruise AV made contact with the left rear corner of the sedan.",
             [("R5", "same")]),
            ("The Waymo AV was traveling northbound on Mission Street and entered the intersection with 16th "
             "Street on a green light. A sedan traveling westbound on 16th Street entered the intersection "
             "against a red light, and the front of the Waymo AV made contact with the driver side of the "
             "sedan.",
             [("R3", None)]),
            ("The Cruise AV was proceeding through the intersection on a green light when a vehicle entered "
             "the intersection from the right, running the red light. The front bumper of the Cruise AV struck "
             "the driver side doors of the vehicle.",
             [("R3", None)]),
            ("The Cruise AV was proceeding through the intersection on a green light when a vehicle entered "
             "the intersection, running the red light. The front bumper of the Cruise AV struck the passenger "
             "side of the vehicle.",
             [("R1", None)]),
            ("The Zoox vehicle was proceeding through the intersection when a pickup truck ran the stop sign "
             "and entered the intersection. The Zoox vehicle's front end collided with the driver side of the "
             "pickup truck.",
             [("R3", None)]),
    )),
    _scenes("a party that passed the AV and moved back: its side is where it passed, not the lane it went to",
            _position, (
            ("The Waymo AV was traveling northbound on Mission Street in the right lane. A sedan passed the "
             "Waymo AV on the left and then cut back to the right lane, making contact with the front left of "
             "the Waymo AV.",
             [("R6", "left")]),
            ("The Cruise AV was traveling in the right lane when a motorcycle passed it on the left side and "
             "moved back to the right lane in front of the AV, clipping its front bumper.",
             [("R6", "left")]),
            ("The AV was traveling in the right lane of a two-lane road. A pickup truck overtook the AV on its "
             "left and swerved into the right lane ahead of it, striking the AV's front left fender.",
             [("R6", "left")]),
            ("The Zoox vehicle was traveling in the left lane. A vehicle passed on the right and then changed "
             "into the left lane, contacting the Zoox vehicle's front right bumper.",
             [("R6", "right")]),
            ("The Waymo AV was stopped in the right lane behind a double-parked truck. A passenger car passed "
             "the Waymo AV on the left and pulled back into the right lane, making contact with the Waymo AV's "
             "front left corner.",
             [("R6", "left")]),
            ("The Cruise AV was traveling in the left lane on Geary Boulevard. A cyclist in the bike lane "
             "passed the Cruise AV on the right and contacted the passenger side mirror.",
             [("R6", "right")]),
            ("The Waymo AV was traveling in the right lane. A box truck in the left lane passed the Waymo AV "
             "and then merged right, its rear end striking the Waymo AV's front left bumper.",
             [("R6", "left")]),
    )),
    _scenes("a rider splitting the lane between the AV and another vehicle: the rider is the party that touched it",
            lambda sk: [(p.category, p.position, p.lane) for p in sk.npcs if p.id == sk.collision.with_], (
            ("The AV was stopped in the right lane at a red light. A motorcycle lane splitting between the AV "
             "and a car in the left lane struck the AV's left mirror.",
             [("motorcycle", "R6", "left")]),
            ("The Waymo AV was stopped in traffic in the right lane. A motorcyclist riding between the Waymo "
             "AV and a pickup truck in the left lane made contact with the Waymo AV's driver side mirror.",
             [("motorcycle", "R6", "left")]),
            ("The Cruise AV was stopped at a red light. A cyclist squeezing between the Cruise AV and the curb "
             "struck the passenger side mirror of the Cruise AV.",
             [("bicycle", "R6", "right")]),
            ("The Cruise AV was stopped in traffic behind a stopped box truck on Post Street. A pedestrian who was "
             "standing in the roadway between the AV and the box truck was contacted when the AV inched forward.",
             [("pedestrian", "R5", "same")]),
    )),
    _scenes("the AV placed relative to the party (\"the AV was in the lane to the left of a bus\")", _position, (
            ("The Waymo AV was following a box truck in the right lane on Mission Street. The box truck "
             "stopped suddenly and the Waymo AV made contact with the rear of the box truck.",
             [("R5", "same")]),
            ("The Cruise AV was traveling in the lane to the left of a city bus. The bus merged left into the "
             "Cruise AV's lane and made contact with the Cruise AV's right side.",
             [("R5", "right")]),
            ("The Zoox vehicle was traveling to the right of a pickup truck on Folsom Street. The pickup truck "
             "drifted right into the Zoox vehicle's lane and struck its left side.",
             [("R5", "left")]),
            ("The Waymo AV was passing a box truck that was stopped in the right lane when the box truck "
             "pulled out into the Waymo AV's lane and made contact with its right side.",
             [("R5", "right")]),
            ("The AV was traveling behind a sedan on Van Ness Avenue when the sedan braked abruptly. The AV "
             "was unable to stop and struck the rear of the sedan.",
             [("R5", "same")]),
            ("The Waymo AV was ahead of a motorcycle in the adjacent left lane. The motorcycle changed lanes "
             "to the right and struck the rear of the Waymo AV.",
             [("R6", "left")]),
            ("The Cruise AV was in the left lane alongside a delivery van in the right lane. The delivery van "
             "moved left into the Cruise AV and contacted its passenger side.",
             [("R5", "right")]),
            ("The Waymo AV was stopped at a red light with a pickup truck behind it. When the light turned "
             "green, the pickup truck accelerated and struck the rear of the Waymo AV.",
             [("R6", "same")]),
    )),
    _scenes("a crossing road told as the side, perpendicular or intersecting street; a side told as 'from its right'",
            _position, (
            ("The Waymo AV was traveling northbound on Valencia Street through the intersection with 16th "
             "Street on a green light. A vehicle on the side street to the right ran the red light and struck "
             "the passenger side of the Waymo AV.",
             [("R3", None)]),
            ("The Cruise AV was proceeding straight through the intersection when a vehicle coming from the "
             "perpendicular street on the left failed to stop and collided with the driver side of the Cruise "
             "AV.",
             [("R1", None)]),
            ("The AV was traveling east on Oak Street and entered the intersection with Pine Street. A "
             "southbound sedan on Pine Street entered the intersection and struck the right side of the AV.",
             [("R3", None)]),
            ("The AV was traveling east on Oak Street and entered the intersection with Pine Street. A "
             "northbound sedan on Pine Street entered the intersection and struck the left side of the AV.",
             [("R1", None)]),
            ("The Zoox vehicle was proceeding through a four-way stop intersection when a pickup truck "
             "approaching from its right did not stop at the stop sign and struck the Zoox vehicle's front "
             "passenger side.",
             [("R3", None)]),
            ("The Waymo AV was traveling southbound on Fillmore Street through the intersection at Geary when "
             "a northbound vehicle on Fillmore turned left in front of the Waymo AV and the two vehicles "
             "collided.",
             [("R2", None)]),
            ("The Waymo AV was stopped at the stop sign on northbound 24th Street at Church Street. A "
             "westbound vehicle on Church Street turned right onto northbound 24th Street and made contact "
             "with the front of the Waymo AV.",
             [("R3", None)]),
            ("The Cruise AV was waiting at a red light on westbound Geary at Masonic. A vehicle traveling "
             "southbound on Masonic turned right onto westbound Geary and swung wide, contacting the front "
             "bumper of the Cruise AV.",
             [("R3", None)]),
    )),
    _scenes("a party striking one already placed behind the AV is behind it too", _position_all := (
            lambda sk: [(p.position, p.lane) for p in sk.npcs]), (
            ("The Waymo AV was stopped at a red light. An SUV stopped directly behind the Waymo AV. A passenger car "
             "then made contact with the SUV and pushed it into the Waymo AV.", [("R6", "same"), ("R6", "same")]),
            ("The Waymo AV was stopped at a red light. An SUV stopped directly behind the Waymo AV. A passenger car "
             "then struck the SUV, which then struck the Waymo AV.", [("R6", "same"), ("R6", "same")]),
            ("The Waymo AV was stopped at a red light. A white SUV stopped directly behind the Waymo AV. A passenger "
             "car then collided with the white SUV, pushing it into the Waymo AV.", [("R6", "same"), ("R6", "same")]),
    )),
    _scenes('a party beside, ahead or behind, told as each operator tells it', _position, (
            ("A Cruise autonomous vehicle was traveling northbound on Valencia Street in the right lane. A sedan "
             "traveling in the left lane overtook the Cruise AV and then merged right, making contact with the front "
             "left bumper of the Cruise AV.", [('R6', 'left')]),
            ("A Cruise autonomous vehicle was traveling northbound on Valencia Street in the right lane. A sedan "
             "passed the Cruise AV on the left and then merged right, making contact with the front left bumper of the"
             " Cruise AV.", [('R6', 'left')]),
            ("A Zoox vehicle was traveling in the right lane of Koval Lane. A vehicle approaching from behind in the "
             "left lane changed lanes to the right and sideswiped the Zoox vehicle.", [('R6', 'left')]),
            ("The Waymo AV was traveling southbound on Rural Road in the right lane when a passenger car in the left "
             "lane, traveling at a higher speed, made a right lane change and made contact with the driver side of the"
             " Waymo AV.", [('R6', 'left')]),
            ("The Waymo AV was traveling southbound on Rural Road in the right lane when a passenger car that was "
             "traveling in the left lane behind the Waymo AV made a right lane change and made contact with the rear "
             "driver side of the Waymo AV.", [('R6', 'left')]),
            ("A Zoox vehicle was stopped at a red light in the right lane of Koval Lane. A box truck in the left lane "
             "made a wide right turn and its trailer made contact with the left side of the Zoox vehicle.",
             [('R5', 'left')]),
            ("A Zoox vehicle was stopped at a red light in the right lane of Koval Lane. A box truck to the left of "
             "the Zoox vehicle made a wide right turn and contacted the Zoox vehicle's front left corner.",
             [('R5', 'left')]),
            ("The Cruise AV was traveling eastbound on Folsom Street in the middle lane. A taxi in the lane to the "
             "left of the Cruise AV swerved into the Cruise AV's lane and struck the Cruise AV's driver side mirror.",
             [('R5', 'left')]),
            ("The Cruise AV was traveling eastbound on Folsom Street. A vehicle traveling alongside the Cruise AV on "
             "its left veered right and scraped the left side of the Cruise AV.", [('R5', 'left')]),
            ("The Cruise AV was traveling eastbound on Folsom Street. A vehicle on the Cruise AV's left side veered "
             "right and scraped the Cruise AV.", [('R5', 'left')]),
            ("The Cruise AV was traveling eastbound on Folsom Street in the number two lane. A vehicle in the number "
             "one lane changed lanes to the right and struck the Cruise AV's left front fender.", [('R5', 'left')]),
            ("The Cruise AV was traveling eastbound on Folsom Street in the #2 lane. A vehicle in the #1 lane changed "
             "lanes to the right and struck the Cruise AV's left front fender.", [('R5', 'left')]),
            ("The Cruise AV was traveling eastbound on Folsom Street in the rightmost lane. A vehicle in the center "
             "lane changed lanes to the right and struck the Cruise AV's left front fender.", [('R5', 'left')]),
            ("The Cruise AV was traveling eastbound on Folsom Street in the right lane. A vehicle in the middle lane "
             "changed lanes to the right and struck the Cruise AV's left front fender.", [('R5', 'left')]),
            ("The Cruise AV was traveling eastbound on Folsom Street in the middle lane. A vehicle in the leftmost "
             "lane changed lanes to the right and struck the Cruise AV's left front fender.", [('R5', 'left')]),
            ("The Cruise AV was traveling eastbound on Folsom Street in the middle lane. A vehicle in the rightmost "
             "lane changed lanes to the left and struck the Cruise AV's right front fender.", [('R5', 'right')]),
            ("The Cruise AV was traveling eastbound on Folsom Street in the left lane. A vehicle in the center lane "
             "changed lanes to the left and struck the Cruise AV's right front fender.", [('R5', 'right')]),
            ("The Zoox vehicle was stopped in the right lane waiting to turn right. A sedan went around the Zoox "
             "vehicle on the left and then turned right in front of it, making contact with the front left of the Zoox"
             " vehicle.", [('R6', 'left')]),
            ("The Apple vehicle was traveling in the left lane of Lawrence Expressway. A pickup truck traveling in the"
             " right lane sped up, passed the Apple vehicle and then cut into its lane, clipping its front right "
             "bumper.", [('R6', 'right')]),
            ("The Waymo AV was traveling in the left lane when a vehicle in the right lane, which was slightly ahead "
             "of the Waymo AV, began changing lanes to the left and made contact with the Waymo AV's passenger side.",
             [('R5', 'right')]),
            ("The Waymo AV was traveling in the right lane when a vehicle in the left lane slightly behind the Waymo "
             "AV began changing lanes to the right and made contact with the Waymo AV's driver side.",
             [('R6', 'left')]),
            ("The Waymo AV was traveling in the right lane when a vehicle in the left lane, slightly behind the Waymo "
             "AV, began changing lanes to the right and made contact with the Waymo AV's driver side.",
             [('R6', 'left')]),
            ("The Cruise AV was traveling on Mission Street. A motorcyclist splitting lanes on the Cruise AV's left "
             "side made contact with the Cruise AV's left mirror.", [('R6', 'left')]),
            ("A Zoox test vehicle was traveling eastbound on Harmon Avenue in the right lane when a passenger vehicle "
             "traveling in the left lane made an unsafe lane change into the Zoox vehicle's lane. The passenger "
             "vehicle's right rear made contact with the Zoox vehicle's front left.", [('R5', 'left')]),
            ("A Zoox test vehicle was traveling eastbound on Harmon Avenue in the right lane. A passenger vehicle "
             "traveling eastbound in the left lane began to merge into the Zoox lane, and its right side contacted the"
             " Zoox vehicle's left rear.", [('R6', 'left')]),
            ("A Zoox test vehicle was stopped at a red light in the right lane. A box truck positioned to the left of "
             "the Zoox vehicle began a right turn and contacted the left side of the Zoox vehicle.",
             [('R5', 'left')]),
            ("The Zoox vehicle was travelling southbound on Folsom Street when a vehicle on its left side moved into "
             "its lane and made contact with the Zoox vehicle.", [('R5', 'left')]),
            ("The Zoox vehicle was traveling in the number 2 lane of Las Vegas Boulevard. A motorcycle traveling in "
             "the number 1 lane moved into the number 2 lane and struck the Zoox vehicle's left side.",
             [('R5', 'left')]),
            ("A Cruise autonomous vehicle (\"Cruise AV\"), operating in driverless autonomous mode, was traveling "
             "westbound on Geary Boulevard in the right lane. A Toyota Camry in the left lane moved into the Cruise "
             "AV's lane, making contact with the driver side of the Cruise AV.", [('R5', 'left')]),
            ("A Cruise autonomous vehicle (\"Cruise AV\"), operating in autonomous mode, was traveling northbound "
             "on Van Ness Avenue. A vehicle traveling in the adjacent lane to the left of the Cruise AV drifted "
             "into the Cruise AV's lane and made contact with the Cruise AV's driver side mirror.", [('R5', 'left')]),
            ("A Cruise autonomous vehicle (\"Cruise AV\"), operating in autonomous mode, was stopped in the right lane "
             "of Market Street. A vehicle traveling in the left lane made a right turn from the left lane across the "
             "Cruise AV's path and made contact with the front bumper of the Cruise AV.", [('R5', 'left')]),
            ("A Cruise autonomous vehicle (\"Cruise AV\"), operating in autonomous mode, was traveling on Market "
             "Street. A vehicle approaching from behind on the Cruise AV's left overtook it and made contact with "
             "the driver side of the Cruise AV.", [('R6', 'left')]),
            ("A Cruise autonomous vehicle (\"Cruise AV\"), operating in autonomous mode, was traveling on Market "
             "Street. A Prius in the lane to its left, traveling slightly behind the Cruise AV, changed lanes and "
             "struck the left rear door of the Cruise AV.", [('R6', 'left')]),
            ("On May 4, 2022 at 3:10 PM PT a Waymo Autonomous Vehicle (\"Waymo AV\") operating in San Francisco, "
             "California was in a collision involving a passenger car on Geary Boulevard. The Waymo AV was traveling "
             "westbound on Geary Boulevard in the right lane. A passenger car traveling westbound in the adjacent left"
             " lane initiated a lane change to the right, and the front passenger side of the passenger car made "
             "contact with the rear driver side of the Waymo AV.", [('R6', 'left')]),
            ("On May 4, 2022 at 3:10 PM PT a Waymo Autonomous Vehicle (\"Waymo AV\") operating in San Francisco, "
             "California was in a collision involving a passenger car on Geary Boulevard. The Waymo AV was traveling "
             "westbound on Geary Boulevard. A passenger car that was traveling westbound to the left of the Waymo AV "
             "initiated a lane change to the right, and the passenger side of the passenger car made contact with the "
             "driver side of the Waymo AV.", [('R5', 'left')]),
            ("On May 4, 2022 at 3:10 PM PT a Waymo Autonomous Vehicle (\"Waymo AV\") operating in Phoenix, Arizona was "
             "in a collision involving a passenger car. The Waymo AV was stopped in the right turn lane at a red "
             "light. A passenger car in the adjacent through lane to the left of the Waymo AV made a right turn from "
             "the through lane and made contact with the front driver side of the Waymo AV.", [('R5', 'left')]),
            ("On May 4, 2022 at 3:10 PM PT a Waymo Autonomous Vehicle (\"Waymo AV\") operating in Phoenix, Arizona was "
             "in a collision involving a pickup truck. The Waymo AV was stopped facing north at a red light. The "
             "pickup truck, which had been stopped to the left of the Waymo AV, proceeded forward and turned right in "
             "front of the Waymo AV, making contact with the front bumper of the Waymo AV.", [('R5', 'left')]),
            ("An Apple test vehicle in autonomous mode was traveling in the right lane of Stevens Creek Boulevard. A "
             "vehicle in the left lane merged into the Apple vehicle's lane, striking the Apple vehicle's front left "
             "fender.", [('R5', 'left')]),
            ("The Pony.ai vehicle was traveling in the middle lane of Fremont Boulevard in autonomous mode. A vehicle "
             "from the left lane changed lanes into the Pony.ai vehicle's lane and the rear of that vehicle made "
             "contact with the front of the Pony.ai vehicle.", [('R5', 'left')]),
            ("The WeRide AV was traveling straight in lane 2. A sedan in lane 1 made a right lane change and hit the "
             "left side of the WeRide AV.", [('R5', 'left')]),
            ("A Nuro vehicle was traveling eastbound on Bellaire Boulevard in the right lane. A pickup truck that was "
             "passing the Nuro vehicle on the left cut back into the right lane and struck the front left of the Nuro "
             "vehicle.", [('R6', 'left')]),
            ("The Mercedes-Benz test vehicle was traveling in the right lane on Interstate 280. A vehicle traveling in"
             " the left lane next to the test vehicle moved right and its right side made contact with the test "
             "vehicle's left side.", [('R5', 'left')]),
            ("The Apple vehicle was traveling in the left lane of El Camino Real. A vehicle traveling in the right "
             "lane changed lanes into the Apple vehicle's lane and made contact with the front right of the Apple "
             "vehicle.", [('R5', 'right')]),
            ("The Apple vehicle was stopped at a red light. A vehicle pulled up on the right side of the Apple vehicle"
             " and, while turning right, made contact with the Apple vehicle's right rear.", [('R6', 'right')]),
            ("The Apple vehicle was stopped at a red light. A vehicle pulled up alongside the Apple vehicle on the "
             "right and, while turning right, made contact with the Apple vehicle's right front bumper.",
             [('R6', 'right')]),
            ("The Apple test vehicle was traveling straight. A bicycle on its right side moved left into its path and "
             "made contact with the Apple vehicle's passenger side.", [('R5', 'right')]),
            ("The Apple test vehicle was traveling straight on Stevens Creek. A cyclist riding in the bike lane made a"
             " left turn in front of the Apple vehicle and was struck.", [('R5', 'right')]),
            ("The AV was traveling in the right lane when a vehicle in front of the AV stopped abruptly and the AV "
             "rear-ended it.", [('R5', 'same')]),
            ("The AV was traveling in the right lane. The vehicle ahead braked suddenly and the AV made contact with "
             "its rear bumper.", [('R5', 'same')]),
            ("The AV was traveling in the right lane. The lead vehicle braked hard and the AV struck it.",
             [('R5', 'same')]),
            ("The AV was stopped in traffic. The vehicle in front of the AV reversed and struck the AV's front bumper.",
             [('R5', 'same')]),
            ("The AV was stopped in traffic. The car ahead rolled backward and struck the AV's front bumper.",
             [('R5', 'same')]),
            ("The AV was stopped in traffic behind a box truck. The box truck began to back up and struck the front of"
             " the AV.", [('R5', 'same')]),
            ("The AV was stopped at a red light when it was struck from behind by a sedan.", [('R6', 'same')]),
            ("The AV was stopped at a red light when a sedan collided with the rear of the AV.", [('R6', 'same')]),
            ("The AV was slowing for traffic when the following vehicle failed to stop and struck the AV.",
             [('R6', 'same')]),
            ("The AV was slowing for traffic when the vehicle behind it failed to stop and struck the AV.",
             [('R6', 'same')]),
            ("The AV was traveling in the middle lane when a vehicle in the right lane attempted to pass the AV and "
             "made contact with the AV's right side.", [('R6', 'right')]),
            ("The AV was stopped at the curb when a vehicle traveling in the lane to its left struck its left mirror.",
             [('R6', 'left')]),
            ("The AV was double-parked for a passenger pickup when a passing vehicle struck its left mirror.",
             [('R6', 'left')]),
            ("The AV was stopped in the right lane for a pickup when a box truck passing in the adjacent lane clipped "
             "its left mirror.", [('R6', 'left')]),
            ("The AV was traveling in the right lane when a vehicle entered its lane from the right shoulder, striking"
             " the AV's right side.", [('R5', 'right')]),
            ("The AV was traveling in the right lane when a vehicle merged from the on-ramp on the right and struck "
             "the AV's passenger side.", [('R5', 'right')]),
            ("The AV was traveling in the left lane when a vehicle in the center lane merged left and struck the AV's "
             "passenger side.", [('R5', 'right')]),
            ("The Cruise AV was stopped at a red light at the intersection of Market Street and 5th Street. A vehicle "
             "next to the Cruise AV on the left made a right turn in front of the Cruise AV and struck its front "
             "bumper.", [('R5', 'left')]),
            ("The Cruise AV was stopped at a red light at the intersection of Market Street and 5th Street. A vehicle "
             "on the Cruise AV's left side turned right across its path and made contact with its front bumper.",
             [('R5', 'left')]),
            ("The Cruise AV was waiting at the intersection of Market Street and 5th Street. A taxi that was also "
             "waiting at the light, to the left of the Cruise AV, made a right turn when the light turned green and "
             "made contact with the Cruise AV's front left fender.", [('R5', 'left')]),
            ("The Waymo AV was proceeding straight through the intersection when a vehicle traveling in the same "
             "direction in the left lane made a right turn in front of the Waymo AV, and the Waymo AV made contact "
             "with its passenger side.", [('R5', 'left')]),
            ("The Waymo AV was proceeding straight through the intersection when a vehicle approaching from behind in "
             "the left lane made a right turn in front of the Waymo AV, and the Waymo AV made contact with its "
             "passenger side.", [('R6', 'left')]),
            ("The Waymo AV was traveling northbound on 3rd Street and entered the intersection at Oak Street. A "
             "northbound vehicle on its left made a right turn onto Oak Street and collided with the front left of the"
             " Waymo AV.", [('R5', 'left')]),
            ("The Waymo AV was traveling northbound on 3rd Street and entered the intersection at Oak Street. Another "
             "northbound vehicle, to the left of the Waymo AV, turned right onto Oak Street and collided with the "
             "Waymo AV.", [('R5', 'left')]),
            ("The Zoox vehicle was turning left at the intersection from the right of two left turn lanes. A vehicle "
             "turning left from the leftmost turn lane drifted into the Zoox vehicle's lane and contacted its driver "
             "side.", [('R5', 'left')]),
            ("The Zoox vehicle was turning left at the intersection. A vehicle turning left beside it on its left "
             "drifted into the Zoox vehicle's lane and contacted its driver side.", [('R5', 'left')]),
            ("The Zoox vehicle was turning left at the intersection. A vehicle that was turning left alongside it in "
             "the adjacent turn lane to its left cut into its path and contacted its left side.", [('R5', 'left')]),
            ("The Cruise AV was traveling in the right lane on Geary Boulevard approaching the intersection with "
             "Masonic Avenue. A vehicle in the left lane behind the Cruise AV sped up and turned right in front of the"
             " Cruise AV at the intersection, striking the Cruise AV's front left.", [('R6', 'left')]),
    )),
    _scenes('a party at or near a junction, by its road and heading', _position, (
            ("The Waymo AV was making an unprotected left turn from northbound Main Street onto Oak Street when an "
             "oncoming sedan traveling straight through the intersection made contact with the front passenger side of"
             " the Waymo AV.", [('R2', None)]),
            ("The Cruise AV was stopped at the stop sign on Main Street at the intersection with Oak Street. After "
             "stopping, the Cruise AV proceeded into the intersection. A vehicle approaching from the left on Oak "
             "Street did not stop and struck the driver side of the Cruise AV.", [('R1', None)]),
            ("The Cruise AV was stopped at the stop sign on Main Street at the intersection with Oak Street. A vehicle"
             " on Oak Street approaching from the Cruise AV's right did not stop and struck the passenger side of the "
             "Cruise AV.", [('R3', None)]),
            ("The Cruise AV was proceeding straight through the intersection of Main Street and Oak Street on a green "
             "light when a vehicle on the cross street ran the red light from the right and struck the passenger side "
             "of the Cruise AV.", [('R3', None)]),
            ("The Waymo AV was turning right from Main Street onto Oak Street. A vehicle traveling on Oak Street from "
             "the left, heading toward the Waymo AV's destination lane, made contact with the Waymo AV's front.",
             [('R1', None)]),
            ("The Zoox vehicle was stopped at a red light on Main Street. A vehicle on the opposite side of the "
             "intersection made a left turn and cut the corner, striking the front of the Zoox vehicle.",
             [('R2', None)]),
            ("The AV was traveling north on Main Street when a vehicle exited a parking lot on the right side of the "
             "road and struck the AV's passenger side.", [('R5', 'right')]),
            ("The AV was traveling north on Main Street when a vehicle pulled out of a driveway on the left and struck"
             " the AV's driver side.", [('R5', 'left')]),
            ("The AV was traveling north on Main Street when a vehicle pulled out of a driveway to the AV's right and "
             "struck the AV.", [('R5', 'right')]),
            ("The AV was traveling north on Main Street when a vehicle that was parked along the left curb pulled out "
             "and struck the AV.", [('R5', 'left')]),
            ("The AV was stopped at a red light on northbound Main Street at the intersection of Oak Street, in the "
             "left-turn lane. A vehicle in the adjacent left turn lane to the right of the AV turned left and drifted "
             "into the AV's lane, striking its passenger side.", [('R5', 'right')]),
            ("The AV was in the right of two left-turn lanes turning left from Main Street onto Oak Street. A vehicle "
             "turning left from the left turn lane to the left of the AV drifted into the AV's path and made contact "
             "with the AV's driver side.", [('R5', 'left')]),
            ("The Waymo AV was traveling eastbound on Main Street and was making a right turn onto Oak Street. A "
             "cyclist riding eastbound in the bike lane to the right of the Waymo AV continued straight and made "
             "contact with the Waymo AV's passenger side.", [('R5', 'right')]),
            ("The Waymo AV was traveling eastbound on Main Street and was making a right turn onto Oak Street. A "
             "cyclist approaching from behind in the bike lane continued straight and made contact with the Waymo AV's"
             " passenger side.", [('R6', 'right')]),
            ("The Waymo AV was traveling eastbound on Main Street and was making a left turn onto Oak Street. A "
             "westbound cyclist on Main Street continued straight through the intersection and made contact with the "
             "Waymo AV.", [('R2', None)]),
            ("The Waymo AV was traveling eastbound on Main Street and was making a left turn onto Oak Street. A "
             "pedestrian crossing Oak Street in the crosswalk made contact with the Waymo AV.", [('R4', None)]),
            ("The Waymo AV was traveling northwest on El Camino Real and entered the intersection at Westborough "
             "Boulevard on a green light. A vehicle traveling northeast on Westborough Boulevard entered the "
             "intersection against a red light and struck the driver side of the Waymo AV.", [('R1', None)]),
            ("The Waymo AV was traveling northwest on El Camino Real and entered the intersection at Westborough "
             "Boulevard on a green light. A vehicle traveling southwest on Westborough Boulevard entered the "
             "intersection against a red light and struck the passenger side of the Waymo AV.", [('R3', None)]),
            ("The Waymo AV was traveling northwest on El Camino Real and entered the intersection at Westborough "
             "Boulevard on a green light. A vehicle traveling southeast on El Camino Real turned left in front of the "
             "Waymo AV.", [('R2', None)]),
            ("The Waymo AV was stopped facing northeast on Folsom Street at a red light. A vehicle traveling northeast"
             " on Folsom Street behind the Waymo AV struck its rear.", [('R6', 'same')]),
            ("The Cruise AV was traveling northeast bound on Folsom Street. A vehicle traveling southwest bound on "
             "Folsom Street crossed into the Cruise AV's lane and struck its front.", [('R7', 'left')]),
            ("The Cruise AV was traveling north on Valencia Street. A cyclist traveling south on Valencia Street in "
             "the bike lane on the other side of the road swerved and struck the Cruise AV.", [('R7', 'left')]),
            ("The Zoox vehicle was traveling westbound on Harmon Avenue approaching Koval Lane. A vehicle traveling "
             "southbound on Koval Lane failed to stop at the red light and struck the right side of the Zoox vehicle.",
             [('R3', None)]),
            ("The Zoox vehicle was traveling westbound on Harmon Avenue approaching Koval Lane. A vehicle traveling "
             "northbound on Koval Lane failed to stop at the red light and struck the left side of the Zoox vehicle.",
             [('R1', None)]),
            ("The Waymo AV was traveling south on 2nd Avenue when a vehicle exiting a parking garage on the west side "
             "of the street pulled out and struck the Waymo AV.", [('R5', 'right')]),
            ("The Waymo AV was traveling north on 2nd Avenue when a vehicle exiting a parking garage on the west side "
             "of the street pulled out and struck the Waymo AV.", [('R5', 'left')]),
    )),
    _scenes("the party struck, in the forms' numbering and other operators' words", _partner_position, (
            ("The Cruise AV was stopped at a red light. A sedan traveling behind the Cruise AV failed to stop. The "
             "front of the sedan then made contact with the rear bumper of the Cruise AV and with a parked van.",
             ("R6", "same")),
            ("V1 (our AV) was traveling southbound in lane 2. V2 was traveling southbound in lane 1. V2 changed lanes "
             "into lane 2 and the right side of V2 struck the left side of V1.", ('R5', 'left')),
            ("Vehicle 1 (AV) was stopped at a red light in the #1 lane. Vehicle 2 was stopped behind Vehicle 1. When "
             "the light turned green, Vehicle 2 moved forward and rear-ended Vehicle 1.", ('R6', 'same')),
            ("Our AV was proceeding straight in the middle lane when the vehicle in the right lane made an unsafe lane"
             " change to the left, hitting our AV on the right front door.", ('R5', 'right')),
            ("The subject vehicle was traveling eastbound in the rightmost lane. The other vehicle, traveling "
             "eastbound in the adjacent lane to the left, attempted to make a right turn across the subject vehicle's "
             "lane and collided with the subject vehicle's left front.", ('R5', 'left')),
            ("The test vehicle was travelling in the left lane at approximately 25 mph when a Honda Civic in the right"
             " lane sped up, overtook the test vehicle and merged in front of it, striking the front right bumper of "
             "the test vehicle.", ('R6', 'right')),
            ("While the AV was stopped at the intersection waiting for the light, a white Toyota on its left side "
             "attempted a right turn in front of the AV and made contact with the AV's front left corner.",
             ('R5', 'left')),
            ("The AutoX vehicle was traveling in autonomous mode in the second lane from the right. A vehicle on the "
             "left side of the AutoX vehicle suddenly changed lanes to the right and made contact with the AutoX "
             "vehicle's left side.", ('R5', 'left')),
            ("The Pony.ai vehicle was stopped at a red light. A motorcycle came up from behind between the Pony.ai "
             "vehicle and the vehicle to its left and scratched the left side of the Pony.ai vehicle.",
             ('R6', 'left')),
            ("The Nuro vehicle was traveling northbound in the right lane. A Ford F-150 traveling in the lane to the "
             "left of the Nuro vehicle began to drift right and made contact with the left side mirror of the Nuro "
             "vehicle.", ('R5', 'left')),
            ("The Argo AV was travelling in the center lane. A sedan, which had been traveling behind the Argo AV in "
             "the left lane, changed lanes to the right and struck the Argo AV's left rear quarter panel.",
             ('R6', 'left')),
            ("The Motional vehicle was stopped in traffic. A scooter rider traveling between the Motional vehicle and "
             "parked cars on the right struck the Motional vehicle's right mirror.", ('R6', 'right')),
            ("The Lyft AV was driving in the rightmost lane. A vehicle to its left and slightly ahead turned right "
             "across its path, and the AV struck the vehicle's passenger side.", ('R5', 'left')),
            ("The Aurora vehicle was traveling in the second lane from the left on I-45. A tractor-trailer in the "
             "leftmost lane moved right into the Aurora vehicle's lane and the trailer contacted the Aurora vehicle's "
             "driver side.", ('R5', 'left')),
            ("The Apple test vehicle was merging onto the freeway from an on-ramp when a vehicle in the right lane of "
             "the freeway, to the left of the test vehicle, struck the test vehicle's left side.", ('R5', 'left')),
            ("The Mercedes test vehicle was waiting to turn left. A car behind it in the same lane pulled out to the "
             "left to go around it and hit its left rear corner.", ('R6', 'same')),
    )),
    _scenes('a party using the opposing lane, passing through or beside the AV at a junction', _position, (
            ("The Cruise AV was stopped at a red light at the intersection of Mission Street and 16th Street. A "
             "vehicle driving in the opposing lane to get around the queue of traffic turned right in front of the "
             "Cruise AV and struck its front left corner.", [('R6', 'left')]),
            ("The Cruise AV was stopped at a red light at the intersection of Mission Street and 16th Street. A "
             "vehicle traveling on the wrong side of the road to bypass the line of stopped cars made contact with the"
             " Cruise AV's front left bumper.", [('R6', 'left')]),
            ("The Cruise AV was stopped at a red light at the intersection. A motorcycle using the oncoming lane to "
             "pass the stopped traffic swerved back and struck the Cruise AV's left mirror.", [('R6', 'left')]),
            ("The Waymo AV was traveling through the intersection. A vehicle on its left that was traveling in the "
             "same direction made a left turn and its rear struck the Waymo AV's front left.", [('R5', 'left')]),
            ("The Waymo AV was proceeding through the intersection when a vehicle that had been traveling next to it "
             "on the left made a sudden right turn in front of the Waymo AV.", [('R5', 'left')]),
            ("The Zoox vehicle was traveling through the intersection on a green light. A vehicle in the adjacent left"
             " lane that was also proceeding through the intersection drifted right and sideswiped the Zoox vehicle.",
             [('R5', 'left')]),
            ("The Zoox vehicle was stopped at the intersection waiting to turn right. A vehicle approached from behind"
             " on the left and attempted to turn right from the through lane, making contact with the Zoox vehicle's "
             "front left corner.", [('R6', 'left')]),
            ("The Zoox vehicle was traveling westbound and entered the intersection. A westbound vehicle to its left "
             "entered the intersection at the same time and turned right across the Zoox vehicle's path.",
             [('R5', 'left')]),
            ("The Waymo AV was traveling northbound on Main Street and entered the intersection at Oak Street on a "
             "green light. A vehicle passing through the intersection from the left struck the driver side of the "
             "Waymo AV.", [('R1', None)]),
            ("The Waymo AV was traveling northbound on Main Street and entered the intersection at Oak Street on a "
             "green light. An eastbound vehicle on Oak Street drove past the stop sign without stopping and struck the"
             " Waymo AV.", [('R1', None)]),
            ("The Waymo AV was stopped at a red light. A vehicle in the left lane passed through the intersection and "
             "then swerved right, striking the front left of the Waymo AV.", [('R5', 'left')]),
            ("The Cruise AV was traveling in the right lane. A vehicle in the left lane, passing by at speed, swerved "
             "into the Cruise AV's lane and struck the Cruise AV's front left fender.", [('R6', 'left')]),
            ("The Cruise AV was traveling in the right lane. A pedestrian passing in front of the Cruise AV from the "
             "right curb was struck.", [('R5', 'right')]),
            ("The Zoox vehicle was traveling in the right lane. An oncoming vehicle passed the Zoox vehicle and "
             "clipped its left mirror.", [('R7', 'left')]),
            ("The Zoox vehicle was traveling on Main Street. A vehicle going past the parked cars on the left side of "
             "the street pulled into the Zoox vehicle's lane ahead of it and braked, and the Zoox vehicle struck its "
             "rear.", [('R5', 'left')]),
            ("The AV was stopped at a stop sign. A vehicle passing through the intersection on the cross street from "
             "the right struck the front of the AV.", [('R3', None)]),
            ("The AV was stopped at a stop sign. A vehicle that went past the AV's stop line and then reversed struck "
             "the front of the AV.", [('R5', 'same')]),
    )),
    Probe("the AV named by its operator, its vehicle or its role",
          "{W} was stopped at a red light on Main Street. A sedan traveling behind {w} failed to stop and struck the "
          "rear of {w}.",
          ("the Kodiak truck", "the Nuro R2", "the Beep shuttle", "the May Mobility vehicle",
           "the Motional IONIQ            5", "the Zoox robotaxi", "the Aurora truck", "the Tesla Robotaxi",
           "the ADS-equipped vehicle", "the            Ghost vehicle", "the Waymo Jaguar I-PACE",
           "the Cruise Bolt", "the autonomous shuttle", "the automated            vehicle", "the ego vehicle",
           "the reporting vehicle", "the Gatik box truck", "the Argo test vehicle", "the Lyft AV",
           "the Pony.ai test car", "the WeRide robotaxi", "the AutoX vehicle", "the DiDi vehicle",
           "the Apollo vehicle", "the Mercedes-Benz vehicle", "the Toyota Research Institute vehicle",
           "the TRI            vehicle", "the Volvo XC90 test vehicle", "the Nvidia test vehicle",
           "the Qualcomm test vehicle", "the            Valeo test vehicle", "the Plus truck",
           "the TuSimple truck", "the Einride pod", "the Avride robot", "the            Serve robot",
           "the Starship robot", "the Cruise Origin", "the Wayve vehicle", "the Vay vehicle",
           "the            Imagry vehicle", "the Applied Intuition test vehicle", "the Woven Planet vehicle"),
          lambda sk: (sk.ego.start, [(p.category, p.position, p.lane) for p in sk.npcs]),
          ("stopped", [("car", "R6", "same")])),
    Probe("lane change into the AV's lane from the right",
          "A Zoox vehicle was traveling northbound on Koval Lane in the left lane. A sedan traveling northbound in the "
          "right lane {w} and made contact with the Zoox vehicle.",
          ("changed lanes into the Zoox vehicle's lane", "made a lane change into the Zoox vehicle's lane",
           "began to change lanes to the left", "merged into the Zoox vehicle's lane", "moved over into the Zoox "
           "vehicle's lane", "entered the Zoox vehicle's lane", "encroached into the Zoox vehicle's lane",
           "crossed into the Zoox vehicle's lane", "swerved into the Zoox vehicle's lane", "veered into the Zoox "
           "vehicle's lane", "drifted into the Zoox vehicle's lane", "cut into the Zoox vehicle's lane",
           "cut in front of the Zoox vehicle", "cut off the Zoox vehicle", "merged left", "moved left",
           "initiated a left lane change", "attempted to merge into the Zoox vehicle's lane",
           "crossed the lane line into the Zoox vehicle's lane", "changed lanes in front of the Zoox vehicle",
           "made an abrupt lane change", "switched lanes", "changed lanes", "began to encroach into the Zoox "
           "vehicle's lane", "crossed over into the Zoox vehicle's lane", "drifted over the lane line"),
          _party, [("R5", "right", "af")]),
    Probe("a party behind the standing AV",
          "A Zoox vehicle was stopped at a red light on Koval Lane. A sedan {w} struck the rear of the Zoox vehicle.",
          ("traveling behind the Zoox vehicle", "following the Zoox vehicle", "trailing the Zoox vehicle",
           "directly behind the Zoox vehicle", "that had been following the Zoox vehicle", "approaching from behind",
           "approaching from the rear", "coming up behind the Zoox vehicle", "to the rear of the Zoox vehicle",
           "close behind the Zoox vehicle", "following too closely", "tailgating the Zoox vehicle",
           "which was following the Zoox vehicle"),
          _party, [("R6", "same", "a")]),
    Probe("a party passing the standing AV on its left",
          "A Zoox vehicle was stopped at a red light on Koval Lane. A motorcycle {w} and made contact with the Zoox "
          "vehicle's left mirror.",
          ("passed the Zoox vehicle on the left", "attempted to pass the Zoox vehicle on the left", "overtook the "
           "Zoox vehicle on the left", "tried to get around the Zoox vehicle on the left side", "squeezed past the "
           "Zoox vehicle on the left", "drove past the Zoox vehicle on its left", "passed on the left of the Zoox "
           "vehicle", "was passing the Zoox vehicle on the driver side", "came around the left side of the Zoox "
           "vehicle", "attempted to overtake the Zoox vehicle on the left", "passed to the left of the Zoox vehicle",
           "passed the left side of the Zoox vehicle"),
          _party, [("R6", "left", "a")]),
    # Session 17: the part of the AV touched, in the words owners, police and operators use for it (story.py
    # REAR_PARTS / FRONT_PARTS, the "LF"/"RR" corners, a possessive inside the part's words).
    Probe("the AV's rear told by a part of its body: the party was behind it",
          "The Waymo AV was stopped at a red light on Mission Street. A sedan made contact with the Waymo AV's {w}.",
          ("tailgate", "trunk", "liftgate", "rear hatch", "license plate", "taillight", "tail lamp", "back bumper",
           "rear bumper cover", "boot", "RR bumper", "trailer hitch", "rear sensor", "rear end"),
          _position, [("R6", "same")]),
    Probe("a rear corner of the AV told by a part of its body: the party in the next lane was level with it or behind",
          "The Waymo AV was traveling northbound on Mission Street. A sedan in the left lane drifted right and made "
          "contact with the Waymo AV's {w}.",
          ("left taillight", "left tail lamp", "driver side rear wheel", "left rear tire", "LR quarter panel",
           "left rear quarter panel", "driver's side rear corner", "left tail light"),
          _position, [("R6", "left")]),
    Probe("a front corner of the AV told by a part of its body: the party in the next lane was ahead of its tail",
          "The Waymo AV was traveling northbound on Mission Street. A sedan in the left lane drifted right and made "
          "contact with the Waymo AV's {w}.",
          ("left headlight", "driver side headlamp", "hood", "LF fender", "left front wheel", "front driver side",
           "front left corner"),
          _position, [("R5", "left")]),
    Probe("a party going around the standing AV on a side, told by any verb of a move with 'around'",
          "The Waymo AV was stopped at a red light on Mission Street. A sedan {w} the Waymo AV on its left and "
          "sideswiped it.",
          ("swerved around", "veered around", "pulled around", "cut around", "moved around", "went around",
           "drove around", "maneuvered around", "steered around", "darted around", "swung around", "whipped around",
           "was going around", "began to go around", "went past", "zipped past", "overtook", "attempted to pass"),
          _position, [("R6", "left")]),
    Probe("a party following the AV too closely",
          "The Cruise AV was traveling northbound on Geary Boulevard. A pickup truck {w} the Cruise AV struck its "
          "rear.",
          ("tailgating", "tail-gating", "riding the bumper of", "following too closely behind", "following closely "
           "behind", "close behind", "right behind", "just behind", "directly to the rear of", "queued behind"),
          _position, [("R6", "same")]),
    Probe("a party in the lane beside the standing AV striking its rear quarter: 'the adjacent lane' is no place "
          "level with it", "The Waymo AV was stopped at a red light on Mission Street. A sedan {w} sideswiped the "
          "Waymo AV's left rear quarter panel.",
          ("traveling in the same direction in the adjacent lane to the left", "in the adjacent left lane",
           "traveling in the adjacent travel lane on the left", "moving in the left adjacent lane",
           "driving in the adjacent lanes to the left"),
          _position, [("R6", "left")]),
    _scenes("a party heading across the AV's road away from a junction: it came from the side opposite its heading",
            _partner_position, (
            ("The Waymo AV was traveling northbound on [XXX] when an SUV traveling eastbound exited a driveway and "
             "the front of the SUV made contact with the driver side of the Waymo AV.", ("R5", "left")),
            ("The Waymo AV was traveling northbound on [XXX] when an SUV traveling westbound exited a parking lot "
             "and the front of the SUV made contact with the passenger side of the Waymo AV.", ("R5", "right")),
            ("The Zoox vehicle was traveling south on Main Street when a sedan heading west out of an alley struck "
             "the Zoox vehicle.", ("R5", "left")),
            ("The Zoox vehicle was traveling southbound on Main Street when a westbound sedan pulled out of a "
             "parking garage and struck the Zoox vehicle.", ("R5", "left")),
            ("The Cruise AV was driving eastbound on Pine Street when a pedestrian walking northbound across Pine "
             "Street mid-block stepped into its path and was struck.", ("R5", "right")),
    )),
    Probe("a party on a road crossing the AV's, told without its name, striking the AV's left side (R1)",
          "The Zoox vehicle was proceeding northbound through the intersection of Main Street and 5th Street on a green light. A sedan {w} ran the red light and struck the Zoox vehicle's driver side.",
          ("on the cross street", "on the crossing street", "on the side street", "on the intersecting street",
           "on the perpendicular street", "on the intersecting roadway", "on the cross road", "from the cross street",
           "traveling on the cross street", "on the intersecting road", "on the perpendicular roadway",
           "on the adjoining street", "on a side street", "out of the cross-street", "in cross traffic",
           "traveling perpendicular to the Zoox vehicle"),
          _position, [("R1", None)]),
    Probe("a party on a road crossing the AV's, told without its name, striking the AV's right side (R3)",
          "The Zoox vehicle was proceeding northbound through the intersection of Main Street and 5th Street on a green light. A sedan {w} ran the red light and struck the Zoox vehicle's passenger side.",
          ("on the cross street", "on the side street", "on the intersecting roadway", "on the cross road",
           "from a side road", "on the perpendicular avenue"),
          _position, [("R3", None)]),
    Probe("a party entering the junction from a side of the AV, told as a direction",
          "The Zoox vehicle was proceeding northbound through the intersection of Main Street and 5th Street on a green light. A sedan {w} entered the intersection against the red light and struck the Zoox vehicle.",
          ("from the left", "from its left", "from the Zoox vehicle's left", "from the left side", "approaching from "
           "the left", "coming from the left", "from left to right", "traveling from left to right"),
          _position, [("R1", None)]),
    Probe("a party on the opposite approach turning left across the AV, told by its direction",
          "The Zoox vehicle was proceeding northbound through the intersection of Main Street and 5th Street on a green light. {W} turned left in front of the Zoox vehicle and the two collided.",
          ("an oncoming sedan", "a sedan approaching from the opposite direction", "a sedan traveling in the "
           "opposite direction", "a sedan traveling the opposite way", "a sedan coming the other way",
           "a sedan traveling toward the Zoox vehicle", "a sedan facing the Zoox vehicle", "a sedan from the "
           "opposite side of the intersection", "a sedan in the opposing left turn lane", "a southbound sedan on Main "
           "Street", "a sedan traveling southbound on Main Street", "a sedan going south on Main Street",
           "a sedan on Main Street heading south", "a sedan traveling south"),
          _position, [("R2", None)]),
    Probe("a walker coming into the road mid-block from the AV's right, told by its roadside or its direction",
          "The Zoox vehicle was traveling northbound on Main Street. A pedestrian {w} and was struck by the front of the Zoox vehicle.",
          ("stepped off the curb from the right", "ran into the road from the right side of the street",
           "walked into the roadway from the east sidewalk", "crossed the street mid-block from right to left",
           "entered the roadway from the eastern curb", "darted out from between parked cars on the right"),
          _position, [("R5", "right")]),
    Probe("a walker coming into the road mid-block from the AV's left, told by its roadside or its direction",
          "The Zoox vehicle was traveling northbound on Main Street. A pedestrian {w} and was struck by the front of the Zoox vehicle.",
          ("stepped off the curb from the left", "walked into the roadway from the west sidewalk",
           "crossed the street mid-block from left to right", "stepped off the left curb into the road",
           "came off the far sidewalk into the road", "stepped off the median into the Zoox vehicle's path"),
          _position, [("R5", "left")]),
    Probe("out from behind another thing is no place behind the AV",
          "The Zoox vehicle was traveling northbound on Main Street. A pedestrian {w} and was struck by the front of the Zoox vehicle.",
          ("came out from behind a parked truck", "stepped out from behind a bus", "emerged from behind a parked "
           "van", "ran out from behind a double-parked car", "appeared from behind the stopped bus"),
          lambda sk: next((p.position for p in sk.npcs if p.id == sk.collision.with_), None), "R5"),
    _scenes("lanes named by their use (fast, inside, HOV, carpool: the leftmost; slow, outside, curb: the rightmost)",
            _position, tuple(
                (f"The Cruise AV was traveling northbound on Geary Boulevard in the {own} lane. A sedan traveling "
                 f"northbound in the {theirs} lane drifted over and struck the Cruise AV.", [("R5", side)])
                for own, theirs, side in (("slow", "fast", "left"), ("curb", "inside", "left"), ("outside", "HOV", "left"),
                                          ("right", "carpool", "left"), ("fast", "slow", "right"),
                                          ("inside", "curb", "right"), ("left", "outside", "right"),
                                          ("HOV", "right", "right")))),
    Probe("an oncoming party in the lane beside the AV's, told by the other direction's lane, side of the road or "
          "meeting head-on", "The Zoox vehicle was traveling northbound on Main Street. {W} drifted across the double yellow line and sideswiped the Zoox vehicle's driver side.",
          ("a sedan traveling in the opposite lane", "a sedan in the opposite travel lane", "a sedan traveling on the "
           "other side of the road", "a sedan on the opposite side of the street", "a sedan approaching head-on",
           "a sedan coming head on", "a sedan headed the opposite direction", "a sedan traveling the other way"),
          _position, [("R7", "left")]),
    Probe("a party coming the wrong way in the AV's lane",
          "The Zoox vehicle was traveling northbound on Main Street. {W} struck the Zoox vehicle head-on.",
          ("a wrong-way sedan", "a sedan driving the wrong way", "a sedan going the wrong direction", "a sedan "
           "traveling against traffic", "a sedan driving against the flow of traffic", "a sedan traveling the "
           "wrong-way", "a sedan traveling southbound in the Zoox vehicle's lane"),
          _position, [("R7", "same")]),
    _scenes("what the AV came up on is in its path, unless told at the roadside or on a side", _partner_position, (
            ("The Cruise AV was traveling northbound on Geary Boulevard. The Cruise AV approached a box truck that "
             "was stopped in the left lane. The truck reversed into the Cruise AV's front bumper.", ("R5", "same")),
            ("The Cruise AV was traveling northbound on Geary Boulevard. The Cruise AV came to a stop behind a sedan "
             "in the rightmost lane. The sedan reversed and struck the Cruise AV's front bumper.", ("R5", "same")),
            ("The Cruise AV was traveling northbound on Geary Boulevard. The Cruise AV approached a cyclist riding "
             "in the bike lane. The cyclist swerved left and struck the Cruise AV.", ("R5", "right")),
            ("The Cruise AV was traveling northbound on Geary Boulevard. The Cruise AV approached a box truck "
             "stopped on the right. The truck pulled out and struck the Cruise AV.", ("R5", "right")),
    )),
    Probe("a party standing ahead that the AV runs into",
          "A Zoox vehicle was traveling northbound on Koval Lane. The Zoox vehicle failed to stop and struck the rear "
          "of {w}.",
          ("a sedan stopped ahead of it", "a sedan that had stopped in front of it", "a stalled sedan in its lane",
           "a sedan waiting at the light ahead", "a sedan stopped in traffic ahead", "a sedan that was stationary "
           "ahead", "a sedan that had come to a stop in front of it", "a sedan idling in the lane ahead", "a sedan "
           "queued ahead of it", "a sedan stopped at the stop sign ahead"),
          lambda sk: ([(p.position, p.lane, p.start, p.actions) for p in sk.npcs], sk.ego.actions, sk.collision.type),
          ([("R5", "same", "stopped", "")], "a", "rear_end")),
    Probe("an oncoming party",
          "A Zoox vehicle was traveling northbound on Koval Lane. {W} crossed the center line and struck the front "
          "of the Zoox vehicle.",
          ("an oncoming sedan", "a sedan traveling in the opposite direction", "a sedan coming from the opposite "
           "direction", "a southbound sedan", "a sedan traveling southbound on Koval Lane", "a sedan heading south on "
           "Koval Lane", "a sedan going the other way", "a sedan in the opposing lane", "a sedan traveling toward the "
           "Zoox vehicle", "a sedan heading toward the Zoox vehicle"),
          _position, [("R7", "left")]),
    Probe("a party turning left across the AV's path from the opposite approach",
          "A Zoox vehicle was traveling northbound on Koval Lane and proceeded through the intersection with Flamingo "
          "Road on a green light. {W} and the Zoox vehicle struck its passenger side.",
          ("an oncoming sedan turned left in front of the Zoox vehicle", "a sedan traveling in the opposite direction "
           "made a left turn across the Zoox vehicle's path", "a southbound sedan turned left onto Flamingo Road",
           "a sedan coming from the opposite direction turned left across its path", "a sedan approaching from the "
           "opposite direction attempted a left turn", "a sedan traveling southbound on Koval Lane made an "
           "unprotected left turn", "a sedan in the opposing left turn lane turned left", "a sedan from the opposite "
           "approach turned left in front of the Zoox vehicle", "an oncoming sedan made a left turn into the Zoox "
           "vehicle's path"),
          lambda sk: [(p.position, p.lane, p.actions[-1:]) for p in sk.npcs], [("R2", None, "d")]),
    Probe("a party crossing from the AV's left",
          "A Zoox vehicle was traveling northbound on Koval Lane and entered the intersection with Flamingo Road on a "
          "green light. {W} ran the red light and struck the driver side of the Zoox vehicle.",
          ("a sedan traveling eastbound on Flamingo Road", "a sedan heading east on Flamingo Road", "an eastbound "
           "sedan on Flamingo Road", "a sedan approaching from the left on Flamingo Road", "a sedan coming from the "
           "Zoox vehicle's left", "a sedan on the cross street approaching from the left", "a sedan traveling on "
           "Flamingo Road from the west", "a sedan entering from the left"),
          _position, [("R1", None)]),
    Probe("a pedestrian on the leg the AV turns onto",
          "A Zoox vehicle was traveling northbound on Koval Lane and turning right onto Flamingo Road at the "
          "intersection. The Zoox vehicle made contact with {w}.",
          ("a pedestrian crossing in the crosswalk", "a pedestrian who was walking in the crosswalk", "a pedestrian "
           "crossing Flamingo Road in the crosswalk", "a pedestrian in the crosswalk", "a pedestrian who stepped "
           "into the crosswalk", "a pedestrian walking across Flamingo Road", "a pedestrian crossing Flamingo Road",
           "a jogger crossing in the marked crosswalk"),
          lambda sk: [(p.category, p.position, p.lane, p.actions) for p in sk.npcs], [("pedestrian", "R4", None, "m")]),
    Probe("a pedestrian crossing mid-block from the right",
          "A Zoox vehicle was traveling northbound on Koval Lane between Flamingo Road and Harmon Avenue. The Zoox "
          "vehicle braked but made contact with {w}.",
          ("a pedestrian who darted into the street from the right", "a pedestrian who ran into the road from "
           "between parked cars on the right", "a pedestrian jaywalking from the right side of the road",
           "a pedestrian crossing mid-block from the right", "a pedestrian who walked out from the right curb"),
          lambda sk: [(p.category, p.position, p.lane, p.actions) for p in sk.npcs],
          [("pedestrian", "R5", "right", "m")]),
    Probe("a parked party pulling out into the AV's path",
          "A Zoox vehicle was traveling northbound on Koval Lane in the right lane. A sedan that had been parked on "
          "the right side of the road {w} into the path of the Zoox vehicle and the Zoox vehicle struck its driver "
          "side.",
          ("pulled out of a parking space", "pulled away from the curb", "merged into traffic from the curb",
           "pulled out from a parked position", "left its parking spot", "pulled out of a parallel parking spot",
           "exited a parking space", "pulled out from the curb"),
          lambda sk: [(p.position, p.lane, p.start, p.actions) for p in sk.npcs], [("R5", "right", "stopped", "if")]),
    Probe("the weather told",
          "A Zoox vehicle was stopped at a red light on Koval Lane. A sedan traveling behind it struck its rear "
          "bumper. {W}",
          ("it was raining at the time.", "conditions were rainy.", "weather conditions were clear.", "there was "
           "heavy fog.", "it was snowing.", "the weather was clear."),
          lambda sk: sk.environment.weather,
          lambda w: "rain" if "rain" in w else "fog" if "fog" in w else "snow" if "snow" in w else "clear"),
    Probe("the AV changing lanes",
          "A Zoox vehicle was traveling northbound on Koval Lane in the middle lane. The Zoox vehicle {w} and made "
          "contact with a sedan that was traveling in that lane.",
          ("changed lanes to the left", "moved into the left lane", "merged left", "began a lane change to the left",
           "initiated a left lane change", "shifted into the left lane", "switched into the left lane", "made a lane "
           "change into the left lane", "moved over to the left lane", "changed into the lane to its left", "moved "
           "one lane to the left", "steered into the left lane", "changed lanes to the right", "moved into the right "
           "lane", "merged into the lane to its right", "moved one lane over to the right"),
          lambda sk: sk.ego.actions, lambda w: "ag" if "right" in w else "af"),
    Probe("the road's layout",
          "A Zoox vehicle was stopped {w} when a sedan traveling behind it struck its rear bumper.",
          ("at the intersection of Koval Lane and Flamingo Road", "at the T-intersection with Flamingo Road", "at a "
           "three-way intersection", "in a parking lot", "in the parking garage", "in a roundabout", "at the traffic "
           "circle", "on the freeway", "on Interstate 280", "on a curved section of Koval Lane", "at the four-way stop "
           "at Flamingo Road", "at the crossroads with Flamingo Road", "at the junction with Flamingo Road", "at a "
           "T-junction", "mid-block on Koval Lane"),
          lambda sk: sk.road.layout,
          lambda w: ("junction3" if ("T-" in w or "three-way" in w) else "parking" if "parking" in w else
                     "roundabout" if ("roundabout" in w or "circle" in w) else "curve" if "curved" in w else
                     "straight" if any(x in w for x in ("freeway", "Interstate", "mid-block")) else "junction4")),
    Probe("the AV's light",
          "A Zoox vehicle was traveling northbound on Koval Lane and entered the intersection with Flamingo Road {w}. "
          "A sedan traveling eastbound on Flamingo Road struck the driver side of the Zoox vehicle.",
          ("on a green light", "on a solid green", "while the signal was red", "on a yellow light", "as the light "
           "changed to yellow", "at a red signal", "with the green traffic signal", "on a flashing yellow"),
          lambda sk: sk.signal_state, lambda w: next(c for c in ("green", "red", "yellow") if c in w)),
    Probe("the AV stopping",
          "A Zoox vehicle was traveling northbound on Koval Lane. The Zoox vehicle {w} for a pedestrian and a sedan "
          "traveling behind it struck its rear bumper.",
          ("came to a stop", "came to a complete stop", "stopped", "braked to a stop", "slowed to a stop", "halted",
           "came to a halt", "was brought to a stop", "stopped abruptly", "made a sudden stop", "came to rest",
           "pulled to a stop"),
          _ego, ("moving", "ah")),
    Probe("the AV moving off",
          "A Zoox vehicle was stopped at a red light on Koval Lane. When the light turned green, the Zoox vehicle {w} "
          "and a sedan traveling behind it struck its rear bumper.",
          ("began to move forward", "started moving", "proceeded forward", "moved forward", "pulled away from the "
           "stop line", "started to proceed", "resumed travel", "moved off", "inched forward", "crept forward",
           "began to proceed through the intersection", "proceeded into the intersection"),
          _ego, ("stopped", "i")),
    Probe("the AV turning at a junction",
          "A Zoox vehicle was traveling northbound on Koval Lane. At the intersection with Flamingo Road, the Zoox "
          "vehicle {w} and a sedan traveling behind it struck its rear bumper.",
          ("turned left", "made a left turn", "executed a left turn", "completed a left turn", "made an unprotected "
           "left turn", "took a left", "hung a left", "performed a left turn", "turned right", "made a right turn",
           "took a right", "made a right-hand turn", "made a U-turn", "made a three-point turn"),
          lambda sk: sk.ego.actions, lambda w: "a" + ("j" if "-turn" in w.lower() or "point" in w else
                                                     "d" if "left" in w else "e")),
    Probe("the AV named in the reports' ways",
          "{W} was stopped at a red light on Koval Lane. A sedan traveling behind {w} struck its rear bumper.",
          ("the Waymo AV", "the AV", "our AV", "the autonomous vehicle", "the self-driving car", "the robotaxi",
           "the driverless vehicle", "the test vehicle", "the ADS vehicle", "the subject vehicle", "the Zoox "
           "robotaxi", "the Cruise vehicle", "our test vehicle", "the automated vehicle", "the ego vehicle"),
          lambda sk: (sk.ego.start, sk.ego.actions, [(p.category, p.position, p.lane) for p in sk.npcs]),
          ("stopped", "", [("car", "R6", "same")])),
    Probe("contact told by its verb",
          "A Zoox vehicle was stopped at a red light on Koval Lane. A sedan traveling in the lane to its left moved "
          "right and {w} the left side of the Zoox vehicle.",
          ("made contact with", "struck", "hit", "collided with", "sideswiped", "bumped", "clipped", "scraped",
           "brushed", "grazed", "tapped", "impacted", "ran into", "crashed into", "made impact with", "came into "
           "contact with", "contacted", "smashed into", "slammed into", "rubbed against", "knocked into",
           "side-swiped", "touched"),
          lambda sk: (_party(sk), sk.collision.with_, sk.collision.type), ([("R5", "left", "ag")], "npc1",
                                                                           "side_swipe")),
    Probe("the AV named by a pronoun in the contact sentence",
          "The Zoox vehicle was stopped at a red light on Koval Lane. {W}",
          ("a sedan traveling behind it struck its rear bumper.", "a sedan behind it rear-ended it.", "a sedan that "
           "was following it struck it from behind.", "a sedan traveling behind it collided with its rear bumper."),
          lambda sk: (sk.collision.with_, sk.collision.type), ("npc1", "rear_end")),
    Probe("an object the AV struck",
          "A Zoox vehicle was traveling northbound on Koval Lane when it struck {w}.",
          ("a parked car", "a parked vehicle", "an unoccupied parked car", "a traffic cone", "a pole", "a light pole",
           "a utility pole", "a fire hydrant", "a street sign", "a bollard", "a curb", "a median", "a guardrail",
           "a concrete barrier", "a gate", "a tree", "debris in the road", "a ladder in the roadway", "a dog",
           "a deer", "a fence", "a fire hydrant on the curb", "a pole on the median"),
          lambda sk: [o.category for o in sk.obstacles] + [p.category for p in sk.npcs],
          lambda w: [next(c for c, words in (("parked_vehicle", ("parked",)), ("cone", ("cone",)),
                                            ("pole", ("pole", "hydrant", "sign", "bollard")),
                                            ("barrier", ("curb", "median", "guardrail", "barrier", "gate", "fence")),
                                            ("debris", ("debris", "ladder")), ("animal", ("dog", "deer")),
                                            ("other", ("tree",))) if any(x in w for x in words))]),
    Probe("a party's category",
          "A Waymo AV was stopped at a red light on Mission Street. {W} traveling behind the Waymo AV struck its rear "
          "bumper.",
          tuple(("an " if n[0].lower() in "aeiou" else "a ") + n for ns in _CATEGORIES.values() for n in ns),
          lambda sk: [p.category for p in sk.npcs],
          lambda w: [next(c for c, ns in _CATEGORIES.items() if w.split(" ", 1)[1] in ns)]),
    # Session 11: NPC action strings (sketch.md's codes and hard-case rules), one manoeuvre per set.
    Probe("a party standing behind the AV that moves off into it",
          _AV_STOPPED + "A sedan stopped behind the Waymo AV {w} and struck the rear bumper of the Waymo AV.",
          ("began to move forward", "started moving", "moved forward", "rolled forward", "crept forward",
           "inched forward", "began to roll forward", "pulled forward", "proceeded forward", "accelerated from a stop",
           "started to accelerate", "moved off", "began to proceed", "lurched forward", "suddenly accelerated forward",
           "released its brakes and rolled forward", "pulled away from the stop line", "drove forward",
           "accelerated", "began to creep forward"),
          _npc_actions, [("stopped", "i")]),
    Probe("a party stopped on the cross street that turns",
          "The Zoox vehicle was traveling northbound on Koval Lane through the intersection with Flamingo Road. "
          "A sedan {w} onto Koval Lane and made contact with the passenger side of the Zoox vehicle.",
          ("that had been stopped at the stop sign on Flamingo Road turned right",
           "stopped at the stop sign on Flamingo Road made a right turn",
           "waiting at the stop sign on Flamingo Road began to turn right",
           "that had come to a stop at the stop sign on Flamingo Road then turned right",
           "sitting at the stop sign on Flamingo Road started a right turn",
           "idling at the stop sign on Flamingo Road turned right",
           "that was stationary at the stop sign on Flamingo Road proceeded to turn right",
           "which had stopped at the stop sign on Flamingo Road began a right turn",
           "stopped at the red light on Flamingo Road began making a right turn",
           "that had been stopped at the stop sign on Flamingo Road turned left",
           "stopped at the stop sign on Flamingo Road made a left turn",
           "waiting at the stop sign on Flamingo Road began to turn left",
           "that was stopped at the limit line on Flamingo Road pulled out and turned left",
           "which had been waiting at the stop sign on Flamingo Road started a left turn"),
          _npc_actions, lambda w: [("stopped", "id" if "left" in w else "ie")]),
    Probe("a party ahead slowing to a stop",
          "The Waymo AV was traveling northbound on Mission Street behind a sedan. The sedan {w} and the Waymo AV "
          "made contact with its rear bumper.",
          ("slowed to a stop", "came to a stop", "came to a sudden stop", "braked to a stop", "stopped suddenly",
           "braked hard and stopped", "abruptly stopped", "came to a complete stop", "stopped short",
           "slammed on its brakes and stopped", "halted", "came to an abrupt halt", "decelerated to a stop",
           "slowed and stopped", "stopped in the travel lane", "suddenly stopped", "came to a standstill"),
          _npc_actions, [("moving", "ah")]),
    Probe("a party ahead slowing",
          "The Waymo AV was traveling northbound on Mission Street behind a sedan. The sedan {w} and the Waymo AV "
          "made contact with its rear bumper.",
          ("slowed down", "braked", "decelerated", "reduced its speed", "slowed suddenly", "braked abruptly",
           "hit its brakes", "slowed", "braked hard", "began to slow", "started to slow down", "abruptly slowed"),
          _npc_actions, [("moving", "ac")]),
    Probe("a party standing ahead that backs into the AV",
          _AV_STOPPED.replace("at a red light", "behind a sedan at a red light") +
          "The sedan {w} and made contact with the front bumper of the Waymo AV.",
          ("reversed", "backed up", "began to reverse", "rolled backward", "rolled back", "started backing up",
           "shifted into reverse and backed up", "drove in reverse", "moved backward", "traveled in reverse",
           "reversed toward the Waymo AV", "began backing up", "started to back up", "rolled backwards",
           "moved in reverse", "suddenly reversed", "transitioned into reverse and began to accelerate"),
          _npc_actions, [("stopped", "k")]),
    Probe("a party backing out of a space",
          "The Waymo AV was traveling slowly through a parking lot on Mission Street. A sedan {w} and made contact "
          "with the passenger side of the Waymo AV.",
          ("reversed out of a parking space", "backed out of a parking spot", "backed out of its parking stall",
           "reversed out of a driveway", "backed out of a driveway", "was backing out of a parking space",
           "began to back out of a parking spot", "reversed from a parallel parking spot",
           "pulled out of a parking space in reverse", "backed out of a parking stall", "reversed out of its space",
           "started to reverse out of a parking spot"),
          _npc_actions, [("stopped", "k")]),
    Probe("a party on the left changing into the AV's lane after a run",
          "The Zoox vehicle was traveling northbound on Koval Lane in the right lane. A sedan was traveling "
          "northbound in the left lane. The sedan {w} and made contact with the driver side of the Zoox vehicle.",
          ("changed lanes to the right", "moved right", "merged right", "made a right lane change",
           "changed into the right lane", "moved into the right lane", "cut over into the right lane",
           "swerved right", "veered into the right lane", "drifted into the right lane", "merged into the right lane",
           "began a lane change to the right", "changed lanes", "merged into the Zoox vehicle's lane",
           "cut into the Zoox vehicle's lane", "encroached into the Zoox vehicle's lane", "switched lanes"),
          _npc_actions, [("moving", "ag")]),
    Probe("a party beside the AV turning across it at the junction",
          "The Zoox vehicle was traveling northbound on Koval Lane in the right lane and entered the intersection "
          "with Flamingo Road. A sedan traveling northbound in the left lane {w} and made contact with the driver "
          "side of the Zoox vehicle.",
          ("turned right", "made a right turn", "began a right turn", "attempted a right turn", "initiated a right "
           "turn", "executed a right turn", "made a right-hand turn", "took a right", "began turning right",
           "started to turn right", "attempted to turn right", "turned right onto Flamingo Road",
           "made a sudden right turn", "made an illegal right turn from the left lane"),
          _npc_actions, [("moving", "ae")]),
    Probe("a party beside the AV turning left across it",
          "The Zoox vehicle was traveling northbound on Koval Lane in the left lane and entered the intersection "
          "with Flamingo Road. A sedan traveling northbound in the right lane {w} and made contact with the "
          "passenger side of the Zoox vehicle.",
          ("turned left", "made a left turn", "began a left turn", "attempted a left turn", "initiated a left turn",
           "executed a left turn", "made a left-hand turn", "took a left", "began turning left",
           "started to turn left", "attempted to turn left", "turned left onto Flamingo Road",
           "made a prohibited left turn", "made a sudden left turn"),
          _npc_actions, [("moving", "ad")]),
    Probe("an oncoming party making a U-turn",
          "The Zoox vehicle was traveling northbound on Koval Lane. A sedan traveling southbound on Koval Lane {w} "
          "and made contact with the front of the Zoox vehicle.",
          ("made a U-turn", "made a u-turn", "performed a U-turn", "executed a U turn", "attempted a U-turn",
           "began a U-turn", "made a three-point turn", "made an illegal U-turn", "turned around", "did a U-turn",
           "made a uturn", "began to make a U-turn", "attempted to make a U-turn", "pulled a U-turn"),
          _npc_actions, [("moving", "aj")]),
    Probe("a rider crossing the AV's path",
          "The Zoox vehicle was traveling northbound on Koval Lane between Flamingo Road and Harmon Avenue. "
          "A cyclist {w} and made contact with the front of the Zoox vehicle.",
          ("rode across the street", "crossed the street", "crossed in front of the Zoox vehicle",
           "darted across the road", "crossed Koval Lane mid-block", "rode off the sidewalk into the street",
           "cut across the road", "crossed the roadway", "rode across Koval Lane", "entered the roadway from the "
           "sidewalk", "crossed against the light", "rode out from between parked cars"),
          _npc_actions, [("moving", "m")]),
    Probe("a vehicle leaving a driveway or lot across the AV's path",
          "The Zoox vehicle was traveling northbound on Koval Lane between Flamingo Road and Harmon Avenue. "
          "A sedan {w} and made contact with the passenger side of the Zoox vehicle.",
          ("exited a driveway", "pulled out of a driveway", "emerged from a parking lot", "left a parking garage",
           "pulled out of an alley", "exited a private driveway", "came out of a driveway", "exited a parking lot",
           "pulled out of a parking lot", "drove out of a driveway", "exited an alley", "pulled out of a gas station",
           "exited a shopping center driveway"),
          _npc_actions, [("moving", "m")]),
    Probe("a party merging from an on-ramp",
          "The Zoox vehicle was traveling northbound on Interstate 15 in the rightmost lane. A pickup truck "
          "traveling on the on-ramp to the right of the Zoox vehicle {w} and made contact with its passenger side.",
          ("merged onto the freeway", "merged into the Zoox vehicle's lane", "merged left", "entered the freeway",
           "merged into traffic", "moved into the Zoox vehicle's lane", "attempted to merge", "began merging",
           "merged without yielding", "merged onto the interstate", "merged into the rightmost lane"),
          _npc_actions, [("moving", "af")]),
    Probe("a party changing lanes and then stopping",
          "The Waymo AV was traveling northbound on Mission Street in the right lane. A sedan traveling in the left "
          "lane changed lanes to the right in front of the Waymo AV and then {w}. The Waymo AV made contact with "
          "the rear bumper of the sedan.",
          ("stopped suddenly", "braked to a stop", "came to an abrupt stop", "slammed on its brakes and stopped",
           "came to a stop", "stopped", "abruptly stopped", "came to a complete stop", "halted", "slowed to a stop"),
          _npc_actions, [("moving", "agh")]),
    Probe("what a party did after the contact is left out",
          "The Waymo AV was stopped at a red light on Mission Street. A sedan traveling behind the Waymo AV struck "
          "its rear bumper and {w}.",
          ("fled the scene", "drove away", "left the scene without stopping", "then drove off",
           "continued on its way", "then pulled over to the curb", "came to a stop", "stopped a short distance ahead",
           "reversed and drove away", "made a U-turn and left", "turned right onto 16th Street and left the scene",
           "sped away", "accelerated away", "pulled into a parking lot", "changed lanes and drove off",
           "backed up and fled"),
          _npc_actions, [("moving", "a")]),
    Probe("what a party did after the contact, told in a sentence of its own",
          "The Waymo AV was stopped at a red light on Mission Street. A sedan traveling behind the Waymo AV struck "
          "its rear bumper. The sedan then {w}.",
          ("fled the scene", "drove away", "left the scene without stopping", "pulled over to the curb",
           "came to a stop", "reversed and drove away", "made a U-turn and left", "turned right onto 16th Street",
           "sped away", "accelerated away", "pulled into a parking lot", "changed lanes and drove off",
           "backed up and fled", "drove around the Waymo AV and left"),
          _npc_actions, [("moving", "a")]),
    Probe("a party standing still throughout that the backing AV strikes",
          "The Waymo AV was stopped on Mission Street. The Waymo AV reversed and made contact with a sedan {w}.",
          ("stopped behind it", "that was stopped behind it", "waiting behind it", "which was stationary behind it",
           "idling behind it", "that had stopped behind it", "sitting behind it", "queued behind it",
           "that was at a complete stop behind it", "stopped at the light behind it", "that was waiting behind it",
           "standing behind it"),
          _npc_actions, [("stopped", "")]),
    Probe("a party already turning when the story takes it up",
          "The Zoox vehicle was stopped at the stop line on Koval Lane at Flamingo Road. A sedan that {w} from "
          "Flamingo Road onto Koval Lane made contact with the Zoox vehicle's front left fender.",
          ("was making a right turn", "was in the process of turning right", "was turning right",
           "was completing a right turn", "was executing a right turn", "was in the middle of a right turn",
           "was negotiating a right turn", "was making a left turn", "was turning left",
           "was in the process of making a left turn"),
          _npc_actions, lambda w: [("moving", "d" if "left" in w else "e")]),
    Probe("a party already changing lanes when the story takes it up",
          "The Zoox vehicle was traveling northbound on Koval Lane in the right lane when a sedan in the left lane "
          "that {w} made contact with the driver side of the Zoox vehicle.",
          ("was changing lanes to the right", "was in the process of changing lanes to the right",
           "was merging right", "was moving into the right lane", "was changing lanes", "was merging into the "
           "right lane", "was in the middle of a lane change", "was making a lane change to the right"),
          _npc_actions, [("moving", "g")]),
    Probe("a party behind speeding up",
          "The Waymo AV was traveling northbound on Mission Street. A sedan traveling behind the Waymo AV {w} and "
          "struck the rear bumper of the Waymo AV.",
          ("accelerated", "sped up", "increased its speed", "picked up speed", "accelerated rapidly",
           "suddenly accelerated", "began to accelerate", "gained speed", "sped up suddenly", "increased speed"),
          _npc_actions, [("moving", "ab")]),
    Probe("a party standing behind the AV that moves off, told in a sentence of its own",
          "The Waymo AV was stopped at a red light on Mission Street. A passenger car was stopped behind the Waymo "
          "AV. {W} and made contact with the rear bumper of the Waymo AV.",
          ("the passenger car then began to move forward", "when the light turned green, the passenger car "
           "proceeded forward", "moments later, the passenger car rolled forward", "the passenger car then "
           "accelerated", "shortly thereafter, the passenger car started moving", "after the light turned green, "
           "the passenger car moved forward", "the passenger car then crept forward", "the passenger car then "
           "proceeded", "the passenger car then started to move", "the passenger car then drove forward",
           "subsequently, the passenger car moved forward", "the passenger car then pulled forward"),
          _npc_actions, [("stopped", "i")]),
    Probe("an oncoming party turning left across the AV, the whole string",
          "The Zoox vehicle was traveling northbound on Koval Lane and entered the intersection with Flamingo Road "
          "on a green light. A sedan traveling southbound on Koval Lane {w} and made contact with the front of the "
          "Zoox vehicle.",
          ("turned left onto Flamingo Road", "made a left turn", "began a left turn", "initiated a left turn",
           "proceeded to turn left", "attempted an unprotected left turn", "made a left turn in front of the Zoox "
           "vehicle", "turned left across the Zoox vehicle's path", "failed to yield and turned left",
           "began to turn left", "executed a left turn onto Flamingo Road", "made a sudden left turn",
           "started to make a left turn", "turned left in front of the Zoox vehicle"),
          _npc_actions, [("moving", "ad")]),
    Probe("a party ahead that stops and then backs into the AV",
          "The Waymo AV was traveling northbound on Mission Street behind a sedan. The sedan came to a stop and "
          "then {w}, making contact with the front bumper of the Waymo AV.",
          ("reversed", "backed up", "began to reverse", "rolled backward", "started backing up",
           "reversed toward the Waymo AV", "began backing up", "shifted into reverse", "moved backward",
           "started to reverse"),
          _npc_actions, [("moving", "ahk")]),
    Probe("a party ahead pulling over to the curb",
          "The Waymo AV was traveling northbound on Mission Street in the right lane. A sedan traveling ahead of "
          "the Waymo AV {w}, and the Waymo AV made contact with its rear bumper.",
          ("pulled over to the curb", "pulled over to the right", "pulled to the curb", "began to pull over",
           "attempted to parallel park", "pulled into a parking space", "began to park at the curb",
           "pulled over", "was pulling over", "started to pull over to the curb"),
          _npc_actions, lambda w: [("moving", "l" if w.startswith("was") else "al")]),
    Probe("a party beside the AV moving into its lane, told of the lane",
          "The Waymo AV was traveling northbound on Mission Street in the left lane. A sedan in the adjacent lane "
          "to the right of the Waymo AV {w} and made contact with its passenger side.",
          ("moved into the Waymo AV's path", "entered the lane occupied by the Waymo AV", "came into the Waymo "
           "AV's lane", "crossed into the lane the Waymo AV was traveling in", "began to drift into the Waymo AV's "
           "lane", "made an unsafe lane change", "changed lanes without signaling", "merged into the Waymo AV's "
           "lane of travel", "moved over into the Waymo AV's lane of travel", "cut over in front of the Waymo AV",
           "encroached upon the Waymo AV's lane", "crossed the dashed lane line", "failed to stay in its lane",
           "moved over into the Waymo AV's lane", "attempted a lane change into the Waymo AV's lane"),
          _npc_actions, [("moving", "af")]),
    Probe("an oncoming party crossing into the AV's lane",
          "The Waymo AV was traveling northbound on Mission Street. A sedan traveling southbound on Mission Street "
          "{w} and made contact with the front of the Waymo AV.",
          ("crossed the center line", "crossed the double yellow line", "drifted into the northbound lane",
           "veered into oncoming traffic", "swerved across the centerline", "crossed into the Waymo AV's lane",
           "entered the opposing lane", "drifted over the double yellow lines", "crossed over the median",
           "moved into the oncoming lane", "crossed the centerline into the Waymo AV's lane",
           "drifted across the center line", "veered into the Waymo AV's lane"),
          _npc_actions, [("moving", "af")]),
    Probe("a party standing beside the AV that moves off into its lane",
          "The Waymo AV was traveling northbound on Mission Street in the left lane. A sedan that was stopped in "
          "the right lane {w} and made contact with the passenger side of the Waymo AV.",
          ("pulled forward and merged into the Waymo AV's lane", "began to move and changed lanes to the left",
           "moved off and cut in front of the Waymo AV", "started moving and moved into the left lane",
           "proceeded forward and merged left", "accelerated and changed lanes into the Waymo AV's lane",
           "began to proceed and moved left", "pulled out and changed lanes to the left"),
          _npc_actions, [("stopped", "if")]),
    Probe("a party standing still throughout that the AV moves into",
          "The Waymo AV was traveling northbound on Mission Street in the right lane. The Waymo AV changed lanes to "
          "the left and made contact with a sedan {w}.",
          ("stopped in the left lane", "that was stopped in traffic in the left lane", "waiting in the left lane",
           "sitting in traffic in the left lane", "that was stationary in the left lane", "idling in the left lane",
           "that had stopped in the left lane", "queued in the left lane", "that was at a standstill in the left "
           "lane", "standing in the left lane"),
          _npc_actions, [("stopped", "")]),
    Probe("a party's manoeuvre told in the present tense",
          "At about 11:35 am our vehicle is traveling northbound on First Street in the left lane. A sedan "
          "traveling in the right lane {w} and strikes our passenger side.",
          ("changes lanes to the left", "merges left", "moves into our lane", "cuts in front of our vehicle",
           "swerves into our lane", "begins to change lanes", "turns left", "makes a left turn",
           "begins to make a left turn", "begins to turn left", "slows to a stop", "comes to a stop",
           "stops suddenly", "makes a U-turn", "speeds up", "accelerates", "slows down",
           "brakes", "pulls over", "drifts into our lane", "veers left", "crosses into our lane"),
          _npc_actions, lambda w: [("moving",
                             "a" + (
                                 "d" if "left turn" in w or "turn left" in w or w == "turns left" else
                                 "h" if "stop" in w else "j" if "U-turn" in w else "b" if w in ("speeds up",
                                 "accelerates") else "c" if w in ("slows down", "brakes") else "l" if "over" in w
                                 else "f"))]),
    Probe("a standing party's move off told in the present tense",
          "Our vehicle is stopped at a red light on First Street. A sedan that is stopped behind our vehicle {w} and "
          "strikes our rear bumper.",
          ("begins to move forward", "moves forward", "rolls forward", "creeps forward", "pulls forward",
           "starts moving", "proceeds forward", "begins to roll", "inches forward", "accelerates"),
          _npc_actions, [("stopped", "i")]),
    Probe("a standing party that strikes the AV moved off",
          "The Waymo AV was stopped at a red light on Mission Street. A sedan {w} struck the rear bumper of the "
          "Waymo AV.",
          ("that was stopped behind the Waymo AV", "waiting behind the Waymo AV", "stopped behind the Waymo AV",
           "that had stopped behind the Waymo AV", "which was stationary behind the Waymo AV",
           "idling behind the Waymo AV", "that was waiting behind the Waymo AV", "queued behind the Waymo AV"),
          _npc_actions, [("stopped", "i")]),
    Probe("a party the backing AV strikes, of which no motion is told",
          "The Waymo AV was stopped on Mission Street. The Waymo AV {w} and made contact with a passenger vehicle "
          "behind it.",
          ("reversed", "backed up", "began to reverse", "rolled backward", "switched to reverse gear",
           "started backing up", "moved backward", "reversed slowly", "began backing up"),
          _npc_actions, [("stopped", "")]),
    Probe("a party behind moving off at the light, told the reports' ways",
          "The Waymo AV was stopped at a red light on Mission Street with a sedan stopped behind it. When the light "
          "turned green, the sedan {w} and struck the rear of the Waymo AV, which had not yet moved.",
          ("began to proceed", "began to accelerate from its stop", "started to proceed", "began moving again",
           "resumed motion", "started up again", "released its brake", "began rolling", "departed from the stop",
           "pulled away from the light", "moved off from the stop line", "accelerated from a stop",
           "proceeded from a stop", "took off", "began to pull forward", "started to roll forward"),
          _npc_actions, [("stopped", "i")]),
    Probe("a party standing ahead that the AV moving off runs into",
          "The Waymo AV was stopped at a red light on Mission Street. When the light turned green, the Waymo AV "
          "proceeded forward and made contact with {w}.",
          ("a vehicle stopped ahead of it", "a stopped pickup truck", "a stationary SUV in its lane",
           "a disabled vehicle in its lane", "a vehicle waiting to turn left ahead of it",
           "a vehicle yielding to pedestrians ahead of it", "a vehicle that had stopped to let a passenger out",
           "a vehicle stopped in a queue ahead", "a vehicle that was stopped for the red light ahead",
           "the rear of a sedan that was stopped in traffic", "a sedan that remained stopped ahead of it",
           "a sedan that had not yet moved"),
          _npc_actions, [("stopped", "")]),
    Probe("a party on the right moving into the AV's lane, told the reports' ways",
          "The Waymo AV was traveling northbound on Mission Street in the left lane. A sedan traveling in the right "
          "lane {w} and made contact with the passenger side of the Waymo AV.",
          ("began to move into the Waymo AV's lane", "attempted to enter the Waymo AV's lane", "moved laterally "
           "into the Waymo AV's lane", "came over into the Waymo AV's lane", "made a lane change maneuver",
           "executed a lane change", "performed a lane change to the left", "initiated a lane change into the lane "
           "occupied by the Waymo AV", "shifted lanes", "darted into the Waymo AV's lane", "squeezed into the "
           "Waymo AV's lane", "began to merge in front of the Waymo AV", "merged in front of the Waymo AV",
           "made an abrupt lane change into the Waymo AV's lane", "changed lanes abruptly",
           "swung into the Waymo AV's lane", "pulled into the Waymo AV's lane", "moved from the right lane into "
           "the left lane", "entered the left lane from the right lane", "attempted to move over",
           "began changing lanes", "started to change lanes", "began to encroach on the Waymo AV's "
           "lane", "nosed into the Waymo AV's lane", "made an unsafe lane change to the left"),
          _npc_actions, [("moving", "af")]),
    Probe("a party on the cross street going straight through the junction",
          "The Zoox vehicle was traveling northbound on Koval Lane and entered the intersection with Flamingo Road "
          "on a green light. A {w} and struck the passenger side of the Zoox vehicle.",
          ("cyclist traveling westbound on Flamingo Road rode through the intersection",
           "cyclist traveling westbound on Flamingo Road crossed the intersection",
           "sedan traveling westbound on Flamingo Road ran the red light",
           "sedan traveling westbound on Flamingo Road crossed the intersection against the red light",
           "sedan traveling westbound on Flamingo Road proceeded into the intersection",
           "sedan traveling westbound on Flamingo Road drove through the intersection",
           "sedan traveling westbound on Flamingo Road failed to stop at the red light",
           "sedan traveling westbound on Flamingo Road entered the intersection",
           "sedan approaching from the right on Flamingo Road continued straight through the intersection",
           "motorcyclist heading west on Flamingo Road went through the intersection"),
          _npc_actions, [("moving", "a")]),
    Probe("a party's manoeuvres in order, up to the contact",
          "The Waymo AV was traveling northbound on Mission Street in the left lane. A sedan traveling ahead of the "
          "Waymo AV in the right lane {w}, and the Waymo AV made contact with it.",
          ("came to a stop and then proceeded forward", "stopped, then started moving again",
           "slowed down and then accelerated", "slowed, then sped up", "changed lanes to the left and then stopped",
           "merged left and then braked to a stop", "changed lanes to the left and then back to the right",
           "moved into the left lane and then moved back into the right lane", "stopped, reversed",
           "came to a stop and began to reverse", "accelerated and then changed lanes to the left",
           "sped up and merged left", "slowed and then changed lanes to the left",
           "braked and then moved into the left lane"),
          _npc_actions, lambda w: [("moving", {
              "came to a stop and then proceeded forward": "ahi", "stopped, then started moving again": "ahi",
              "slowed down and then accelerated": "acb", "slowed, then sped up": "acb",
              "changed lanes to the left and then stopped": "afh", "merged left and then braked to a stop": "afh",
              "changed lanes to the left and then back to the right": "afg",
              "moved into the left lane and then moved back into the right lane": "afg",
              "stopped, reversed": "ahk", "came to a stop and began to reverse": "ahk",
              "accelerated and then changed lanes to the left": "abf", "sped up and merged left": "abf",
              "slowed and then changed lanes to the left": "acf",
              "braked and then moved into the left lane": "acf"}[w])]),
    Probe("a party backing and then driving forward into the AV",
          "The Waymo AV was stopped at a red light on Mission Street. A sedan ahead of the Waymo AV {w} and made "
          "contact with the Waymo AV.",
          ("reversed, then drove forward and changed lanes to the left", "backed up and then pulled forward into "
           "the left lane", "reversed a few feet, then moved forward and merged left"),
          _npc_actions, [("stopped", "kif")]),
    Probe("a parked party beginning to pull out",
          "The Waymo AV was traveling northbound on Mission Street in the right lane. A sedan that was parked on the "
          "right side of the road {w} and made contact with the passenger side of the Waymo AV.",
          ("began to pull out", "started to pull out", "pulled out", "began pulling out", "attempted to pull out",
           "started pulling away from the curb", "began to merge into traffic", "pulled out from its parking spot",
           "began to move forward out of its parking space", "pulled away from the curb", "suddenly pulled out",
           "began to leave its parking spot", "pulled into the travel lane", "moved out of its parking space into "
           "the travel lane"),
          _npc_actions, [("stopped", "if")]),
    Probe("a party at the curb on the left pulling out",
          "The Waymo AV was traveling northbound on Mission Street, a one-way street, in the left lane. A sedan that "
          "was parked on the left side of the road {w} and made contact with the driver side of the Waymo AV.",
          ("began to pull out", "pulled out", "pulled away from the curb", "pulled out from its parking spot",
           "began pulling out", "started to pull out"),
          _npc_actions, [("stopped", "ig")]),
    Probe("a moving party entering the AV's lane by a verb of going forward",
          "The Waymo AV was traveling northbound on Mission Street in the left lane. A sedan traveling in the right "
          "lane {w} and made contact with the passenger side of the Waymo AV.",
          _LANE_ENTERED_GOING, _npc_actions, [("moving", "af")]),
    Probe("a standing party entering the AV's lane by a verb of going forward",
          "The Waymo AV was traveling northbound on Mission Street in the left lane. A sedan that was stopped in "
          "the right lane {w} and made contact with the passenger side of the Waymo AV.",
          _LANE_ENTERED_GOING, _npc_actions, [("stopped", "if")]),
    Probe("a party on the cross street that waited at its sign and then went",
          "The Zoox vehicle was traveling northbound on Koval Lane through the intersection with Flamingo Road. "
          "A sedan on Flamingo Road {w} and struck the passenger side of the Zoox vehicle.",
          ("stopped at the stop sign and then proceeded into the intersection",
           "came to a stop at the stop sign, then entered the intersection",
           "waited at the stop sign before proceeding into the intersection",
           "that had stopped at the stop sign pulled into the intersection",
           "stopped at the stop sign, then drove into the intersection",
           "which had been stopped at the red light, entered the intersection",
           "after stopping at the stop sign, proceeded into the intersection",
           "that was stopped at the stop sign began to proceed",
           "stopped at the limit line and then accelerated into the intersection",
           "waiting at the stop sign pulled out"),
          _npc_actions, [("stopped", "i")]),
    Probe("a party beside the AV getting in front of it",
          "The Waymo AV was traveling northbound on Mission Street in the left lane. A sedan traveling in the right "
          "lane {w}, and the Waymo AV made contact with its rear bumper.",
          ("moved in front of the Waymo AV", "got in front of the Waymo AV", "pulled in front of the Waymo AV",
           "came in front of the Waymo AV", "swerved in front of the Waymo AV", "cut the Waymo AV off",
           "merged in front of the Waymo AV", "darted in front of the Waymo AV", "moved over in front of the Waymo "
           "AV", "slid in front of the Waymo AV", "cut over in front of the Waymo AV", "squeezed in front of the "
           "Waymo AV", "nosed in front of the Waymo AV", "jumped in front of the Waymo AV",
           "moved directly in front of the Waymo AV", "pulled directly into the Waymo AV's path"),
          _npc_actions, [("moving", "af")]),
    Probe("a party standing in a lane named by its use, that the AV runs into",
          "The Waymo AV was traveling northbound on Mission Street when it made contact with a sedan {w}.",
          ("stopped in the left turn lane ahead of it", "waiting in the left-turn pocket ahead of it",
           "that was stopped in the oncoming lane", "stopped in the bike lane ahead of it",
           "that was stationary in the merge lane ahead of it", "stopped in the crosswalk ahead of it",
           "that was stopped in the right turn lane ahead of it", "idling in the bus lane ahead of it",
           "that had stopped in the center turn lane", "stopped across the lane line ahead of it"),
          _npc_actions, [("stopped", "")]),
    # Session 11 (obstacles, the road's layout and control, the AV's own start and actions, refusals): written from
    # the spec's definitions and the ways the companies' reports tell these facts.
    Probe("a parked, unattended vehicle the AV struck is an obstacle",
          "A Zoox vehicle was traveling northbound on Koval Lane when it made contact with {w}.",
          ("a vehicle parked along the curb", "a parked and unoccupied SUV", "a car parked on the right side of the "
           "street", "a parallel-parked sedan", "a vehicle that was parked at the curb", "an unattended vehicle",
           "a stationary, unoccupied vehicle", "a legally parked pickup truck", "an empty parked car", "a vehicle "
           "parked in a parking space", "a parked passenger vehicle", "a vehicle that was legally parked",
           "a box truck parked in the loading zone", "the mirror of an unoccupied car", "a vehicle that was parked "
           "and unoccupied", "a car that had been parked on the street", "a double-parked delivery van"),
          lambda sk: ([o.category for o in sk.obstacles], len(sk.npcs), sk.collision.type),
          (["parked_vehicle"], 0, "hit_object")),
    Probe("a door opened into the AV's path is an obstacle; its vehicle did not move",
          "A Zoox vehicle was traveling northbound on Koval Lane when {w}.",
          ("the driver of a parked car opened the driver side door into the Zoox vehicle", "the occupant of a parked "
           "vehicle opened a door into the side of the Zoox vehicle", "a passenger exiting a parked car opened the "
           "rear door and it made contact with the Zoox vehicle", "the door of a parked car swung open and struck the "
           "Zoox vehicle", "a parked vehicle's door was opened into the Zoox vehicle's path and made contact with it",
           "a person in a parked SUV opened the door into the Zoox vehicle", "it was struck by the opening door of a "
           "parked vehicle", "a car door opened into its path and struck it", "it made contact with the open door "
           "of a parked car", "the driver of a parked sedan flung the door open and it hit the Zoox vehicle"),
          lambda sk: ([o.category for o in sk.obstacles], [p.category for p in sk.npcs]), (["door"], [])),
    # Session 17: more nouns and noun phrases for a party, each one party of its kind.
    Probe("a party's category, told by more nouns and noun phrases (one party each)",
          "A Waymo AV was stopped at a red light on Mission Street. {W} traveling behind the Waymo AV struck its rear "
          "bumper.",
          ("a box-truck", "a pick-up", "a pick up truck", "a U-Haul", "a U-Haul truck", "a tricycle", "a pedicab",
           "a person in a wheelchair", "a man in a wheelchair", "a person on a mobility scooter", "a Ford Transit van",
           "a white Honda Odyssey minivan", "a Toyota Grand Highlander", "a Chevrolet Express van", "a train",
           "a tram", "a cable car", "a minibus", "a motorcoach", "a person on a hoverboard", "a Segway rider",
           "a person riding a motorbike", "a woman riding a tricycle", "a man on a dirt bike"),
          lambda sk: [p.category for p in sk.npcs],
          lambda w: [next(c for c, words in (("van", ("Transit", "Odyssey", "Express")),
                                            ("truck", ("box", "Haul")),
                                            ("pedestrian", ("wheelchair", "mobility")),
                                            ("bicycle", ("tricycle", "pedicab")),
                                            ("bus", ("train", "tram", "cable", "minibus", "motorcoach")),
                                            ("scooter", ("hoverboard", "Segway")),
                                            ("motorcycle", ("motorbike", "dirt bike")),
                                            ("car", ("pick", "Highlander")))
                          if any(x in w for x in words))]),
    Probe("a pick-up zone or a passenger pick-up is no pickup truck",
          "A Zoox vehicle was stopped {w} when a sedan traveling behind it struck its rear bumper.",
          ("in a pick-up and drop-off zone", "in a pickup and drop-off zone", "at a drop-off/pick-up spot",
           "for a passenger drop-off and pick-up", "in a pick-up lane", "in a pick-up area", "for a passenger pick-up",
           "at a pickup location"),
          lambda sk: [p.category for p in sk.npcs], ["car"]),
    Probe("a party named by its kind and then 'the passenger car/vehicle' is one party (unless placed ahead anew)",
          "The Waymo AV was stopped at a red light on [XXX]. {W} approached from behind and the front of the "
          "passenger car made contact with the rear of the Waymo AV.",
          ("a white sedan", "an SUV", "a pickup truck", "a Toyota Camry", "a hatchback"),
          lambda sk: (len(sk.npcs), sk.collision.with_), (1, "npc1")),
    Probe("'the vehicle' after the summary's 'a vehicle', as the subject of a sentence naming the AV after it, is "
          "that party",
          "On April [XXX], 2025 a Waymo Autonomous Vehicle (\"Waymo AV\") operating in Phoenix was in a collision "
          "involving a vehicle on [XXX]. The Waymo AV was stopped at a red light when {w}.",
          ("the vehicle approached from behind and struck the rear of the Waymo AV", "the vehicle struck the rear of "
           "the Waymo AV", "the vehicle, traveling behind the Waymo AV, made contact with its rear bumper"),
          lambda sk: ([p.category for p in sk.npcs], sk.collision.with_), (["car"], "npc1")),
    Probe("a vehicle the contact pushed the AV into is a party of its own",
          "The Waymo AV was stopped at a red light on [XXX]. An SUV approached from behind and struck the rear of the "
          "Waymo AV, {w}.",
          ("pushing it into the passenger car ahead", "pushing the Waymo AV into the passenger vehicle in front of it",
           "pushing it forward into the passenger car stopped ahead", "and the Waymo AV was pushed into the passenger "
           "car ahead of it", "causing the Waymo AV to strike the passenger vehicle in front of it", "which pushed the "
           "Waymo AV forward into a sedan stopped ahead", "propelling it into the rear of a pickup truck stopped ahead",
           "and the impact pushed the Waymo AV forward into a sedan stopped ahead", "forcing it into the rear of the "
           "passenger car ahead", "causing it to roll into the passenger vehicle stopped in front of it"),
          lambda sk: ([p.category for p in sk.npcs], sk.collision.with_), (["car", "car"], "npc1")),
    Probe("a contact told as an event ('a minor contact with ... occurred'), by the AV's operator named in short",
          "The May shuttle was traveling north on [XXX] in manual mode. {W}",
          ("The AVO steered to the right and a minor contact with a parked car occurred.",
           "The AVO steered to the right and a light contact with a parked car occurs.",
           "The VO steered to the right and a slight contact with a parked car occurred.",
           "The operator steered to the right and a contact with a parked car occurred.",
           "The TSO steered to the right, and a brief contact with a parked car occurred."),
          lambda sk: ([o.category for o in sk.obstacles], sk.collision.with_), (["parked_vehicle"], "obs1")),
    Probe("a row of cones, pylons or barricades the AV met or acted for is one obstacle",
          "A Zoox vehicle was traveling northbound on Koval Lane when {w}.",
          ("it made contact with construction cones in its lane", "it struck traffic cones placed in the roadway",
           "it swerved to avoid the pylons in its lane", "it ran over several delineators", "it came to a stop for "
           "barricades blocking its lane", "it slowed for a taxi and the cones ahead of it, then struck the cones",
           "it drove over traffic barrels", "it struck a row of bollards"),
          lambda sk: [o.category for o in sk.obstacles],
          lambda w: ["barrier" if "barricade" in w else "pole" if "bollard" in w else "cone"]),
    Probe("an AV named only 'the truck' by a report naming its operator; a vehicle's own parts are no party",
          "TuSimple's position is that this event does not meet the criteria for reporting. {W}",
          ("As the truck was being operated on the highway, the vehicle control unit steered it left and the truck "
           "struck the concrete barrier.",
           "The vehicle was traveling on the highway when the left front vehicle tire struck a concrete barrier.",
           "As the truck was traveling on the highway, the truck computer failed and the left front truck wheel "
           "struck a concrete barrier.",
           "The truck was traveling in the right lane when the truck control system steered it left and it struck a concrete "
           "barrier."),
          lambda sk: ([p.category for p in sk.npcs], [o.category for o in sk.obstacles], sk.collision.with_),
          ([], ["barrier"], "obs1")),
    Probe("a possessive printed without its apostrophe (redacted SGO text) names the same owner",
          "The Waymo AV was traveling north on [XXX] {w}.",
          ("and made contact with a parked cars driver side mirror", "and made contact with a bicyclists back tire", "when the Waymo AVs right "
           "side made contact with an unoccupied SUVs mirror", "and made contact with a parked vans rear bumper",
           "and made contact with a parked pickup trucks tailgate", "and made contact with a parked sedans rear "
           "passenger side door"),
          lambda sk: ([p.category for p in sk.npcs], [o.category for o in sk.obstacles], sk.collision.with_ or ""),
          lambda w: (["bicycle"], [], "npc1") if "bicyclist" in w else
          ([], ["parked_vehicle"], "obs1")),
    Probe("another party's contact with an object or a third party, or a contact only believed, is not the AV's",
          "The Waymo AV was traveling north on [XXX]. {W}",
          ("As a sedan was passing the Waymo AV, it swerved left and the driver side made contact with the median curb.",
           "A pickup truck passing the Waymo AV on the left struck a traffic cone.",
           "As the Waymo AV slowed, an SUV behind it made contact with a pole.",
           "The safety driver believed the Waymo AV had struck a rock, but no contact was found.",
           "The operator thought that the Waymo AV had run over debris."),
          lambda sk: (sk.collision.with_, sk.collision.type), (None, "none")),
    Probe("a move that ends in the AV itself is a contact",
          "The Cruise AV was stopped at a red light when an SUV ran the light and collided with a sedan. The SUV then "
          "{w} the Cruise AV.",
          ("spun and continued into", "skidded into", "slid into", "careened into", "drifted into", "spun into",
           "proceeded into", "rolled backward into"),
          lambda sk: next((p.category for p in sk.npcs if p.id == sk.collision.with_), None), "car"),
    Probe("a line stretched across the road is an object ('other'), as a fallen cable is",
          "A Zoox vehicle was traveling northbound on Koval Lane when it made contact with {w}.",
          ("a cord draped across the roadway", "a rope stretched across the road", "an extension cord lying in the "
           "road", "a garden hose across its lane", "caution tape strung across the street", "a banner that had "
           "fallen into the roadway", "a string of lights hanging over the road"),
          lambda sk: [o.category for o in sk.obstacles], ["other"]),
    Probe("more objects in the road and animals, by their names (session 17)",
          "A Zoox vehicle was traveling northbound on Koval Lane when it made contact with {w}.",
          ("a sheet of plywood in the roadway", "a cooler in the roadway", "a suitcase in the roadway", "a plastic "
           "container in the road", "a furniture dolly", "a brick in the road", "a cinder block", "a bumper cover "
           "lying in the lane", "a muffler in the road", "a jersey barrier", "a water barrier", "a garage door",
           "a parking gate", "a puppy", "a fox", "a chicken", "a peacock", "a goat", "scaffolding"),
          lambda sk: [o.category for o in sk.obstacles] + [p.category for p in sk.npcs],
          lambda w: [next(c for c, words in (("barrier", ("jersey", "water barrier", "garage", "gate")),
                                            ("animal", ("puppy", "fox", "chicken", "peacock", "goat")),
                                            ("other", ("scaffolding",)))
                          if any(x in w for x in words)) if any(x in w for x in ("jersey", "water barrier", "garage",
                                                                                   "gate", "puppy", "fox", "chicken",
                                                                                   "peacock", "goat", "scaffolding"))
                     else "debris"]),
    Probe("a numbered plural of a vehicle's kind is that many parties ('two SUVs', 'two other vans')",
          "The Waymo AV was stopped at a red light on [XXX] when it was struck by {w}.",
          ("two SUVs that had collided in the intersection", "two other vans that had collided in the intersection",
           "two sedans that had collided in the intersection", "two pickup trucks that had collided in the "
           "intersection", "two taxis that had collided in the intersection", "two buses that had collided in the "
           "intersection", "two minivans that had collided in the intersection"),
          lambda sk: len(sk.npcs), 2),
    Probe("parked vehicles joined by 'and' before 'that were parked' are all parked",
          "The Zoox vehicle was traveling north on Koval Lane when it made contact with {w} that were parked at the "
          "curb.",
          ("a van and a sedan", "two vans and a pickup truck", "a box truck and two SUVs", "an SUV and a minivan"),
          lambda sk: (len(sk.npcs), sum(o.category == "parked_vehicle" for o in sk.obstacles)),
          lambda w: (0, sum({"a": 1, "an": 1, "two": 2}[x.split()[0]] for x in w.split(" and ")))),
    # Session 17: the other party named by the NHTSA SGO form's role names and the forms' other numberings.
    Probe("the other party named by a role name or a form's number",
          "The SV was stopped at a red light on [XXX] when {w} approached from behind and made contact with the rear "
          "of the SV.",
          ("the Crash Partner (CP)", "the CP", "a CP vehicle", "the CP vehicle", "the crash partner", "CP",
           "the other vehicle (OV)", "the OV", "a third-party vehicle (TPV)", "the TPV", "a POV",
           "a privately owned vehicle (POV)", "Unit 2", "Unit #2", "Veh. 2", "Veh #2", "V-2", "Party 2",
           "the crash partner vehicle", "a Third-Party vehicle", "a non-ADS vehicle"),
          lambda sk: ([p.category for p in sk.npcs], sk.collision.with_, list(sk.missing)), (["car"], "npc1", [])),
    Probe("a party named again by a role name, or named by one and then by its kind, is one party",
          "The SV was traveling northbound on [XXX] when {w}",
          ("a pickup truck rear-ended the SV. The CP driver left the scene. The CP sustained damage.",
           "the Crash Partner (CP), a cyclist, made contact with the SV's right side. The CP fled.",
           "the CP, a bicyclist, made contact with the SV's right side.",
           "a cyclist made contact with the SV's right side. The CP was not injured.",
           "the CP made contact with the SV's rear. The CP, a sedan, left the scene.",
           "the other vehicle (OV) made contact with the rear of the SV. The OV left the scene.",
           "the OV made contact with the rear of the SV. The sedan then left the scene."),
          lambda sk: (len(sk.npcs), sk.collision.with_), (1, "npc1")),
    Probe("'another' or 'a second' vehicle after the opening sentence's party is a party of its own",
          "The Cruise AV was stopped at a red light when a sedan rear-ended it. {W}",
          ("Another sedan then rear-ended that sedan.", "A second sedan then rear-ended the first sedan.",
           "Another vehicle then struck the sedan.", "A third sedan then struck the sedan.",
           "Another car then struck the sedan from behind."),
          lambda sk: len(sk.npcs), 2),
    Probe("a note about the report before the story: the opening story sentence is its summary",
          "{W} A Zoox vehicle was struck by a passenger car on [XXX] at [XXX]. The Zoox vehicle was stopped at a red "
          "light when a passenger car traveling behind it made contact with its rear.",
          ("This report is meant to correct monthly report 30270-7719-1 (submitted 05/15/2024).",
           "The content of this report is unchanged from the original report.",
           "The content of this report is unchanged from the initial report submitted on May [XXX], 2022 [Report ID "
           "# 30270-3057-1].", "This is a duplicate of 30270-5962-1.", "This update supplements the previous "
           "report with additional information."),
          lambda sk: [p.category for p in sk.npcs], ["car"]),
    # Session 17: the AV's own door, opened by its rider, is no obstacle; the party that met it is the partner.
    Probe("the AV's own open door is no obstacle (a party met it)",
          "The Waymo AV was stopped at the curb on Mission Street for a passenger drop-off when {w}.",
          ("the Waymo AV passenger opened the rear passenger side door and a cyclist passing on the right made contact "
           "with the open door", "a passenger of the Waymo AV opened the rear door and a cyclist passing on the right "
           "made contact with the open rear door of the Waymo AV", "a cyclist passing on the right made contact with "
           "the Waymo AV's open rear passenger door", "a cyclist passing on the right made contact with the open right "
           "rear door of the Waymo AV", "the Waymo AV's rider opened the rear door and a cyclist passing on the right "
           "struck the door", "a rider in the Waymo AV opened the right rear door into the path of a cyclist, who "
           "struck the door", "an occupant of the Waymo AV opened the right rear door and a cyclist passing on the "
           "right struck it", "the Waymo AV's passengers opened the rear door and a cyclist passing on the right "
           "collided with the door"),
          lambda sk: ([o.category for o in sk.obstacles], [p.category for p in sk.npcs], sk.collision.with_),
          ([], ["bicycle"], "npc1")),
    Probe("the AV meeting the curb, told by its verb",
          "A Zoox vehicle was traveling northbound on Koval Lane when it {w} the curb.",
          ("mounted", "drove up onto", "jumped", "hopped", "rode up onto", "clipped", "scraped", "struck",
           "ran up onto", "went up on", "made contact with", "rubbed against", "bumped into", "drove over"),
          lambda sk: ([o.category for o in sk.obstacles], sk.collision.with_, sk.collision.type),
          (["barrier"], "obs1", "hit_object")),
    Probe("road furniture and objects in the road, by their names",
          "A Zoox vehicle was traveling northbound on Koval Lane when it made contact with {w}.",
          ("a street light", "a streetlight", "a lamp post", "a light standard", "a metal railing", "a tire in the "
           "roadway", "a wheel stop", "a parking gate arm", "a K-rail", "a traffic signal pole", "a stop sign",
           "a yield sign", "a parking sign", "a road closure sign", "a concrete column", "a construction barrel",
           "a traffic barricade", "a crash cushion", "a loose tire", "a mattress in the roadway",
           "a traffic delineator"),
          lambda sk: [o.category for o in sk.obstacles] + [p.category for p in sk.npcs],
          lambda w: [next(c for c, words in (("cone", ("barrel", "delineator")),
                                            ("pole", ("light", "lamp", "pole", "sign", "column")),
                                            ("barrier", ("railing", "wheel stop", "gate", "K-rail", "barricade",
                                                         "cushion")),
                                            ("debris", ("tire", "mattress"))) if any(x in w for x in words))]),
    Probe("more objects in or beside the road, by their names",
          "A Zoox vehicle was traveling northbound on Koval Lane when it made contact with {w}.",
          ("a piece of wood", "a wooden plank", "a chunk of concrete", "a hubcap", "a steel plate", "a wheel chock",
           "a railroad crossing arm", "a parking gate arm", "a drive-thru overhang", "an awning", "a sandwich board",
           "a newspaper stand", "a garbage can", "a sawhorse", "a parking bumper", "a concrete construction "
           "barrier"),
          lambda sk: [o.category for o in sk.obstacles] + [p.category for p in sk.npcs],
          lambda w: [next(c for c, words in (("debris", ("wood", "plank", "chunk", "hubcap", "plate", "chock")),
                                            ("barrier", ("arm", "sawhorse", "bumper", "barrier")),
                                            ("pole", ("sandwich",)),
                                            ("other", ("overhang", "awning", "stand", "can")))
                          if any(x in w for x in words))]),
    Probe("a sign, signal pole or stop line the AV struck is not its traffic control",
          "A Zoox vehicle was traveling northbound on Koval Lane between Flamingo Road and Harmon Avenue when it "
          "made contact with {w}.",
          ("a stop sign", "a traffic signal pole", "a stop sign on the right side of the road", "the post of a "
           "stop sign", "a traffic light pole"),
          lambda sk: (sk.road.layout, sk.road.control, sk.signal_state), ("straight", "none", "none")),
    Probe("scraped pavement is no obstacle",
          "A Zoox vehicle was traveling northbound on Koval Lane when {w}.",
          ("its undercarriage scraped the pavement", "it struck a pothole", "its front bumper scraped the driveway "
           "apron", "its underbody made contact with the roadway at the bottom of a steep hill", "it bottomed out "
           "on a dip in the road", "its front fascia contacted the ground", "its undercarriage made contact with a "
           "speed bump", "its front bumper scraped the road surface", "its underside scraped the street at the "
           "crest of the hill"),
          lambda sk: (len(sk.obstacles), len(sk.npcs), sk.collision.with_, sk.collision.type, "npcs" in sk.missing),
          (0, 0, None, "other", True)),
    Probe("an obstacle's lane",
          "A Zoox vehicle was traveling northbound on Koval Lane when it made contact with {w}.",
          ("a traffic cone in the adjacent left lane", "a traffic cone in the lane to its right", "a traffic cone "
           "in the middle of its lane", "debris on the shoulder", "a traffic cone in the left lane next to it",
           "debris in the right lane beside it", "a ladder lying in its lane", "a parked car on its right",
           "a vehicle parked in the bike lane", "a parked car in the parking lane", "a pole on the sidewalk",
           "a fire hydrant at the curb", "a traffic cone placed in the lane to its left"),
          lambda sk: [(o.position, o.lane) for o in sk.obstacles],
          lambda w: [("R5", "left" if "left" in w else "right" if "right lane" in w or "to its right" in w else
                      "same" if ("its lane" in w or "middle" in w) else "shoulder")]),
    Probe("a parked vehicle on the far side of a two-way street",
          "A Zoox vehicle was traveling northbound on Koval Lane when it made contact with {w}.",
          ("an unoccupied vehicle parked on the southbound side of Koval Lane", "a vehicle parked on the opposite "
           "side of the street", "a car parked on the other side of the road", "a parked car facing the oncoming "
           "direction on the opposite side of Koval Lane", "a vehicle parked along the opposite curb"),
          lambda sk: [(o.category, o.position, o.lane) for o in sk.obstacles], [("parked_vehicle", "R7", "shoulder")]),
    Probe("the AV's traffic control",
          "A Zoox vehicle was stopped {w} when a sedan traveling behind it struck its rear bumper.",
          ("at a stop sign on Koval Lane", "at the all-way stop at Koval Lane and Flamingo Road", "at a four-way "
           "stop-controlled intersection", "at the stop line of a stop-controlled intersection", "at the signalized "
           "intersection of Koval Lane and Flamingo Road", "at the traffic light at Koval Lane and Flamingo Road",
           "at an uncontrolled intersection", "at a 2-way stop at Flamingo Road", "at a two-way stop at Flamingo "
           "Road", "at a stop-sign-controlled intersection", "at the stoplight on Koval Lane", "at a stop light on "
           "Koval Lane", "at a traffic signal on Koval Lane", "at the signal at Flamingo Road", "at an unsignalized "
           "intersection", "at a three-way stop on Koval Lane"),
          lambda sk: (sk.road.layout, sk.road.control),
          lambda w: ("junction3" if "three-way" in w else "junction4",
                     "none" if ("uncontrolled" in w or "unsignalized" in w) else
                     "stop_sign" if "stop" in w.replace("stop light", "").replace("stoplight", "") else "signal")),
    Probe("the AV's traffic control, told as a control or a form field",
          "{W}. The Beep shuttle was stopped at the intersection of [XXX] and [XXX] when a sedan traveling behind it "
          "struck its rear bumper.",
          ("Traffic Control: Traffic Signal", "Traffic Control: Stop Sign", "Traffic Control: None", "the "
           "intersection is signal-controlled", "the intersection is signal controlled", "it is a light-controlled "
           "intersection", "the intersection is controlled by a traffic signal", "the intersection is controlled by "
           "stop signs", "the intersection has no traffic controls", "it is an uncontrolled intersection"),
          lambda sk: (sk.road.control, sk.signal_state),
          lambda w: ("stop_sign", "none") if "top" in w else ("none", "none") if ("None" in w or " no " in w or
                                                                                  "uncontrolled" in w) else
          ("signal", "unknown")),
    Probe("a junction's legs, told in more ways",
          "A Zoox vehicle was stopped {w} when a sedan traveling behind it struck its rear bumper.",
          ("at a 3-way intersection", "at a three-legged intersection", "at a tee intersection", "where Koval Lane "
           "ends at Flamingo Road", "at the end of Koval Lane where it meets Flamingo Road", "at a three way "
           "intersection", "at a Y-intersection", "at a five-way intersection", "at a 4-way intersection",
           "where the bike lane ends at the intersection", "at the T intersection of Koval Lane and Flamingo Road"),
          lambda sk: sk.road.layout,
          lambda w: "junction4" if any(x in w for x in ("five", "4-way", "bike lane")) else "junction3"),
    Probe("a place that is no junction",
          "A Zoox vehicle was stopped {w} when a sedan traveling behind it struck its rear bumper.",
          ("at a mid-block crosswalk on Koval Lane", "in a driveway on Koval Lane", "in a pick-up and drop-off zone",
           "at the curb on Koval Lane", "in traffic on Koval Lane", "on Koval Lane between Flamingo Road and Harmon "
           "Avenue", "on Koval Lane near Flamingo Road", "on [XXX] near [XXX]", "on the highway",
           "at a marked mid-block crosswalk", "in the drive-thru lane"),
          lambda sk: (sk.road.layout, sk.road.control, [p.category for p in sk.npcs]), ("straight", "none", ["car"])),
    Probe("the AV standing when the interaction begins",
          "A Zoox vehicle was {w} on Koval Lane when a sedan traveling behind it struck its rear bumper.",
          ("stationary", "at a standstill", "stopped in traffic", "queued in traffic", "completely stopped",
           "parked at the curb", "holding its position", "stopped and waiting", "sitting stationary", "fully "
           "stopped", "standing still", "at a complete stop", "at rest", "motionless", "not moving"),
          _ego, ("stopped", "")),
    Probe("the AV standing in a turn lane with the turn it means to make (session 13)",
          "A Waymo Autonomous Vehicle (\u201cWaymo AV\u201d) was stopped in the left turn lane on northbound Folsom "
          "Street at 16th Street {w}. A passenger vehicle traveling behind the Waymo AV made contact with the rear "
          "bumper of the Waymo AV.",
          ("waiting to make a left turn", "for an unprotected left turn onto 16th Street", "and was about to turn "
           "left", "planning a left turn onto 16th Street", "in anticipation of a left turn onto 16th Street",
           "waiting to proceed with a left turn", "preparing to turn left onto 16th Street", "for a left turn"),
          _ego, ("stopped", "")),
    Probe("the AV moving along its lane",
          "A Zoox vehicle was {w} on Koval Lane when a sedan traveling behind it struck its rear bumper.",
          ("driving northbound", "proceeding northbound", "operating northbound", "heading north", "in motion",
           "going straight", "cruising", "moving slowly", "northbound", "en route northbound", "traveling straight",
           "continuing straight", "moving forward", "rolling forward slowly"),
          _ego, ("moving", "a")),
    Probe("the AV slowing",
          "A Zoox vehicle was traveling northbound on Koval Lane. The Zoox vehicle {w} and a sedan traveling behind it "
          "struck its rear bumper.",
          ("slowed down", "decelerated", "reduced its speed", "braked", "applied its brakes", "began to slow",
           "was slowing for traffic ahead", "reduced speed", "lowered its speed", "began decelerating",
           "slowed for a pedestrian", "braked lightly"),
          _ego, ("moving", "ac")),
    # Session 13 (from the AV strings of new real narratives: a stop is an event of a moving AV unless made at a
    # light or a sign; a stop after moving off from where it waited keeps the start):
    Probe("the travelling AV's stop for traffic, told in more ways",
          "A Waymo Autonomous Vehicle (\u201cWaymo AV\u201d) was traveling northbound on Folsom Street in San Francisco. "
          "The Waymo AV {w}. A passenger vehicle traveling behind the Waymo AV made contact with the rear bumper of "
          "the Waymo AV.",
          ("slowed to a stop for a pedestrian", "braked to a stop for a pedestrian crossing", "stopped for a "
           "pedestrian in the crosswalk", "came to a stop behind a stopped vehicle", "came to a complete stop to yield "
           "to a cyclist", "stopped to let a pedestrian cross", "came to a stop due to traffic ahead", "brought itself "
           "to a stop", "began to slow down and came to a stop", "came to a gradual stop", "slowed to a controlled stop",
           "halted for a pedestrian", "had to stop for a pedestrian"),
          _ego, ("moving", "ah")),
    Probe("the AV moving off from a stop sign and stopping again",
          "A Zoox vehicle in autonomous mode was stopped at a stop sign on northbound 4th Street at Harrison Street. "
          "{W} A passenger car traveling behind the Zoox vehicle made contact with its rear bumper.",
          ("the Zoox vehicle began to creep forward and came to a stop again.", "the Zoox vehicle proceeded into the "
           "intersection and then stopped for a pedestrian.", "the Zoox vehicle moved forward a few feet and stopped "
           "to yield to cross traffic.", "after creeping forward, the Zoox vehicle stopped again for a cyclist.",
           "the Zoox vehicle inched forward to gain visibility and stopped.", "when it was its turn, the Zoox vehicle "
           "accelerated and then braked to a stop for a jaywalker.", "the Zoox vehicle proceeded forward before "
           "stopping for a pedestrian.", "the Zoox vehicle started moving and had to stop for a pedestrian.",
           "the Zoox vehicle advanced and then came to a stop as it yielded to cross traffic.", "the Zoox vehicle "
           "departed from the stop and came to a stop again for a pedestrian."),
          _ego, ("stopped", "ih")),
    Probe("the AV pulling over",
          "A Zoox vehicle was traveling northbound on Koval Lane. The Zoox vehicle {w} and a sedan traveling behind it "
          "struck its rear bumper.",
          ("pulled over to the curb", "pulled to the right side of the road to drop off a passenger", "was pulling "
           "over", "pulled over to pick up a passenger", "began pulling over to the curb", "pulled into a parking "
           "spot at the curb", "moved to the curb to drop off a passenger", "was pulling to the curb",
           "pulled to the right side of the street", "was pulling toward the right side of the roadway"),
          _ego, ("moving", "al")),
    Probe("the AV backing",
          "A Zoox vehicle was parked on Koval Lane. The Zoox vehicle {w} and struck a sedan that was stopped behind "
          "it.",
          ("reversed", "backed up", "was backing out of a parking space", "began reversing", "was reversing",
           "moved in reverse", "backed out of its parking spot", "began to back up", "reversed out of a parking "
           "space"),
          _ego, ("stopped", "k")),
    Probe("a party placed by where it touched the AV is no refusal",
          "A Zoox vehicle was {w}.",
          ("stopped on Koval Lane. A cyclist then made contact with the front of the Zoox vehicle",
           "stopped on Koval Lane. A pedestrian then made contact with the left side of the Zoox vehicle",
           "traveling on Koval Lane when a scooter rider made contact with the right side of the Zoox vehicle",
           "stopped on Koval Lane. A cyclist then made contact with the Zoox vehicle's rear bumper",
           "traveling on Koval Lane when a sedan made contact with the Zoox vehicle's front bumper",
           "traveling on Koval Lane when a sedan made contact with the Zoox vehicle",
           "traveling on Koval Lane when the Zoox vehicle made contact with a bicyclist's back tire",
           "traveling on Koval Lane when a sedan rear-ended the Zoox vehicle", "traveling on Koval Lane when the Zoox "
           "vehicle rear-ended a sedan", "traveling on Koval Lane when a sedan collided head-on with the Zoox vehicle",
           "traveling on Koval Lane when a sedan struck the Zoox vehicle from behind", "traveling on Koval Lane when "
           "a sedan T-boned the Zoox vehicle", "traveling on Koval Lane when a sedan sideswiped the Zoox vehicle"),
          lambda sk: [m for m in sk.missing if m in ("position", "actions")],
          # (a broadside or a sideswipe with no side named leaves the side unknown)
          lambda w: [] if any(part in w for part in ("front", "rear", "side ", "behind", "head-on")) else
          ["position", "actions"]),
    Probe("an AV standing at a light that turned green stood at a red",
          "A Zoox vehicle was stopped at the intersection of Koval Lane and Flamingo Road. {W} and a sedan traveling "
          "behind it struck its rear bumper.",
          ("when the light turned green, the Zoox vehicle proceeded", "after the signal turned green, the Zoox "
           "vehicle began to move", "the light then turned green", "once the traffic light changed to green, the "
           "Zoox vehicle moved forward", "the signal cycled to green and the Zoox vehicle started to proceed",
           "when its light turned green, the Zoox vehicle began to proceed", "the traffic signal subsequently "
           "turned green"),
          lambda sk: (sk.ego.start, sk.road.control, sk.signal_state), ("stopped", "signal", "red")),
    Probe("the moving AV's green, told in more ways",
          "A Zoox vehicle was traveling northbound on Koval Lane and entered the intersection with Flamingo Road {w} "
          "when a sedan traveling eastbound on Flamingo Road struck its driver side.",
          ("on a protected green arrow", "with a green traffic signal", "after the light turned green", "on a green "
           "signal", "with a steady green light", "on a green ball", "on a circular green", "while its light was "
           "green", "with the green light"),
          lambda sk: (sk.road.control, sk.signal_state), ("signal", "green")),
    Probe("the AV turning into or out of a driveway or lot: no junction",
          "A Zoox vehicle {w} when a sedan traveling behind it struck its rear bumper.",
          ("was turning right into a driveway", "was turning left into a parking lot entrance", "was exiting a "
           "parking lot and turning right onto Koval Lane", "was turning left out of a driveway onto Koval Lane",
           "was making a right turn into a gas station", "was turning right into the driveway of a grocery store",
           "was turning left into an alley"),
          lambda sk: (sk.road.layout, sk.ego.actions[-1:]),
          lambda w: ("straight", "d" if "left" in w else "e")),
    Probe("an object in the AV's lane that it went around took part",
          "A Zoox vehicle was traveling northbound on Koval Lane when it slowed behind {w} and began to change lanes "
          "to the left. A sedan traveling in the left lane struck its driver side.",
          ("a double-parked vehicle", "a double-parked delivery truck", "a vehicle double-parked in its lane",
           "a parked garbage truck blocking its lane", "a box truck that was double parked", "an unattended box "
           "truck in its lane", "an illegally parked car in its lane", "a delivery van parked in the travel lane",
           "a dumpster in the road", "debris in its lane", "a traffic cone in its lane", "a fallen tree branch in its "
           "lane", "a car that was double-parked ahead of it", "a vehicle parked in its lane"),
          lambda sk: ([(o.position, o.lane) for o in sk.obstacles], [(p.position, p.lane) for p in sk.npcs],
                      sk.ego.actions),
          ([("R5", "same")], [("R5", "left")], "acf")),
    Probe("the AV named by its operator and a vehicle noun, then by the noun alone",
          "The {w} was stopped at a red light on Koval Lane when a sedan traveling behind the {w} struck the {w}'s "
          "rear bumper.",
          ("May shuttle", "Beep shuttle", "Aurora truck", "Kodiak autonomous truck", "Nuro R2", "Kodiak "
           "Driver-equipped truck", "Zoox robotaxi", "Navya shuttle", "Gatik box truck", "Nuro delivery pod"),
          lambda sk: (sk.ego.start, [(p.category, p.position, p.lane) for p in sk.npcs], sk.collision.type),
          ("stopped", [("car", "R6", "same")], "rear_end")),
    Probe("a party named by a less common noun is a party (else the report is refused for `npcs`)",
          "The Waymo AV was stopped at a red light on Mission Street when {w} traveling behind the Waymo AV struck its "
          "rear bumper.",
          ("a motorist", "another motorist", "an Uber", "a police cruiser", "a golf cart", "an ambulance",
           "a street sweeper", "an RV", "a motorhome", "a forklift", "a bulldozer", "a farm tractor", "a unicyclist"),
          lambda sk: ([p.category for p in sk.npcs], sk.collision.with_, list(sk.missing)),
          lambda w: (["scooter" if "unicycl" in w else "car" if any(x in w for x in ("motorist", "Uber", "cruiser",
                                                                                       "golf")) else "truck"],
                     "npc1", [])),
    Probe("an object ahead stays ahead when another party is said to be behind the AV",
          "A Zoox vehicle was traveling northbound on Koval Lane. The Zoox vehicle {w} and a sedan traveling behind it "
          "struck its rear bumper.",
          ("moved into the left lane to go around a double-parked vehicle and then stopped", "stopped behind a "
           "double-parked box truck", "slowed for debris in its lane", "stopped for a traffic cone in its lane",
           "braked to avoid a ladder in the roadway", "stopped for a fallen tree in the road"),
          lambda sk: [(o.position, o.lane) for o in sk.obstacles], [("R5", "same")]),
    Probe("the AV already turning when the interaction begins",
          "The Zoox vehicle {w} when a cyclist in the bike lane struck its right side.",
          ("was traveling northbound on Koval Lane and turning right onto Flamingo Road", "was making a right turn "
           "from Koval Lane onto Flamingo Road", "was in the process of turning right onto Flamingo Road", "was "
           "completing a right turn onto Flamingo Road", "was executing a right turn onto Flamingo Road", "had begun "
           "a right turn onto Flamingo Road", "was turning right from Koval Lane onto Flamingo Road", "was traveling "
           "northbound on Koval Lane, turning right onto Flamingo Road,", "was proceeding to turn right onto "
           "Flamingo Road", "was in the middle of a right turn onto Flamingo Road", "was beginning to turn right "
           "onto Flamingo Road", "was starting its right turn onto Flamingo Road"),
          lambda sk: (sk.road.layout, sk.ego.start, sk.ego.actions), ("junction4", "moving", "e")),
    Probe("a place on a street told without a street's name, and no place at all (refused for `road`)",
          "The Waymo AV {w} when a sedan rear-ended it.",
          ("was stopped in a queue of vehicles", "was waiting behind a line of cars", "was stopped to drop off a "
           "passenger", "was stopped for a passenger pickup", "was backing out of a parking space", "was parked in "
           "a parking space", "was stopped at the curb", "was stopped in a bike lane", "was picking up a passenger",
           "was stopped", "was in motion", "was in autonomous mode"),
          lambda sk: ("road" in sk.missing, sk.road.layout),
          lambda w: (True, "unknown") if w in ("was stopped", "was in motion", "was in autonomous mode") else
          (False, "straight")),
    Probe("a party on its way pulling out of its lane",
          "The Waymo AV was traveling northbound on Mission Street in the left lane. A sedan traveling behind a bus "
          "in the right lane {w} and made contact with the passenger side of the Waymo AV.",
          ("pulled out from behind the bus into the Waymo AV's lane", "pulled out to pass the bus",
           "pulled out around the bus", "pulled out into the left lane", "suddenly pulled out",
           "pulled out and tried to pass the bus", "pulled out of its lane", "swung out around the bus",
           "pulled out from behind the bus", "swung out to pass the bus"),
          _npc_actions, [("moving", "af")]),
    Probe("a party standing partly in the AV's lane",
          "The Waymo AV was traveling northbound on Mission Street when it made contact with a sedan {w}.",
          ("that was stopped partially in its lane", "stopped partially encroaching into its lane",
           "that was stopped with its rear protruding into the Waymo AV's lane",
           "that had stopped straddling the lane line", "stopped partly in the Waymo AV's lane",
           "that was stationary and partially blocking the Waymo AV's lane",
           "that was stopped, encroaching into the Waymo AV's lane", "waiting partially in the Waymo AV's lane",
           "that was stopped at an angle across the lane line"),
          _npc_actions, [("stopped", "")]),
    Probe("a party's move after a phrase that names the AV",
          "The Waymo AV was traveling northbound on Mission Street in the left lane. A sedan {w} changed lanes to the "
          "left and made contact with the passenger side of the Waymo AV.",
          ("traveling to the right of the Waymo AV", "in the lane to the right of the Waymo AV",
           "traveling alongside the Waymo AV on its right", "that was next to the Waymo AV on the right",
           "which had been traveling beside the Waymo AV in the right lane", "driving in the right lane next to the "
           "Waymo AV", "that was traveling parallel to the Waymo AV in the right lane", "in the right lane, slightly "
           "ahead of the Waymo AV,", "traveling in the same direction as the Waymo AV in the right lane",
           "positioned to the right of the Waymo AV", "in the adjacent right lane, just ahead of the Waymo AV,",
           "traveling in the right lane, which was adjacent to the Waymo AV's lane,"),
          _npc_actions, [("moving", "af")]),
    Probe("a party's move told after the AV's own clause",
          "The Waymo AV was traveling northbound on Mission Street in the left lane {w} changed lanes to the left and "
          "made contact with the passenger side of the Waymo AV.",
          ("when a sedan in the right lane", "when a sedan traveling in the right lane", ", when a sedan in the "
           "right lane", "as a sedan in the right lane", "and a sedan in the right lane", "while a sedan in the right "
           "lane", ". Suddenly, a sedan in the right lane", ". At the same time, a sedan in the right lane",
           ". Shortly thereafter, a sedan in the right lane", ". Simultaneously, a sedan in the right lane",
           ". Moments later, a sedan in the right lane", "; a sedan in the right lane"),
          _npc_actions, [("moving", "af")]),
    # Session 12: the AV's own start and actions, read from the real dev narratives the extractor got wrong (a turn
    # told as done before the story, a counterfactual stop, parking that ended backing into a parked car, pulling
    # up behind a standing vehicle, a yield beside a run or as a state, a stop made for the party met, a take-over
    # made to turn, a move told again at the contact, a driveway or lot entered), each told in other words.
    Probe("the AV's turn told as done before the story",
          "The Waymo AV was traveling north on Jones Street. {W}, the Waymo AV's passenger side mirror made contact "
          "with the mirror of a parked car.",
          ("After completing a right turn onto Jones Street", "After making a left turn from Clay Street",
           "After the Waymo AV made a right turn from Pleasant Street", "After turning right onto Jones Street",
           "After the Waymo AV had completed a left turn onto Jones Street", "Shortly after turning left from Clay "
           "Street", "Having completed a right turn onto Jones Street", "After it finished a right turn onto Jones "
           "Street", "Just after making a right turn onto Jones Street"),
          _ego, ("moving", "a")),
    Probe("the AV's stop that would have happened (a counterfactual tells no manoeuvre)",
          "The Waymo AV was approaching a stop sign on Mission Street. {W} The operator then moved the vehicle past "
          "the stop line, colliding with a cyclist's back tire.",
          ("If left in autonomy, the vehicle would have come to a full stop before the stop line.",
           "If left in autonomy, the vehicle would have stopped at the line and remained stopped.",
           "The operator took over before the vehicle could have stopped.",
           "If the operator had not taken over, the AV would have come to a stop.",
           "Had the AV stayed in autonomy, it would have stopped before the line.",
           "The AV would have yielded at the line."),
          _ego, ("moving", "a")),
    Probe("the AV parking, its rear end meeting a parked car (it backed)",
          "While the test driver of the Waymo AV {w} on Vicente Street, the rear of the Waymo AV made contact with the "
          "front of a parked pickup truck.",
          ("was parallel parking", "was parallel parking in manual mode", "was attempting to parallel park",
           "was pulling into a parking space", "was maneuvering into a parking spot"),
          _ego, ("moving", "lk")),
    Probe("the AV pulling up behind a standing vehicle (a stop)",
          "While traveling southwest on Townsend Street, the Waymo AV approached a double-parked vehicle. The Waymo AV "
          "{w}. An SUV following behind the Waymo AV passed it on the left and made contact with its rear left sensor.",
          ("pulled behind the double-parked vehicle", "pulled up behind the double-parked vehicle",
           "pulled in behind the double-parked vehicle", "pulled behind the parked vehicle",
           "pulled up behind a stopped truck", "came to a stop behind the double-parked vehicle",
           "stopped behind the double-parked vehicle"),
          _ego, ("moving", "ah")),
    Probe("the AV yielding beside its run or its slowing (it slowed, no stop)",
          "A Zoox vehicle was {w} a pedestrian. A truck in the left adjacent lane abruptly turned right and cut in "
          "front of the Zoox vehicle, making contact with its left front sensor.",
          ("proceeding southbound in the right lane on Sixth Street, yielding to", "proceeding southbound in the right "
           "lane on Sixth Street while yielding to", "traveling south on Sixth Street, yielding to",
           "moving slowly along Sixth Street, yielding to", "driving south on Sixth Street and slowed when yielding to",
           "traveling south on Sixth Street and slowing for"),
          _ego, ("moving", "ac")),
    # The official gold's r376 ("was slowing and moving at approximately 2 mph ..., yielding to an oncoming vehicle",
    # `c`): a slowing told under way, with no run told before it, opens the AV's string.
    Probe("the AV's slowing told under way (what it was doing when the interaction began)",
          "A Zoox vehicle was {w} a pedestrian. A truck in the left adjacent lane abruptly turned right and cut in "
          "front of the Zoox vehicle, making contact with its left front sensor.",
          ("slowing on Sixth Street, yielding to", "decelerating on Sixth Street, yielding to",
           "slowing down on Sixth Street for", "braking for", "proceeding south on Sixth Street and was slowing for"),
          _ego, ("moving", "c")),
    Probe("the AV yielding as what it was doing (standing, a turn not begun)",
          "The Waymo AV {w} a pedestrian in the crosswalk. A SUV approaching from behind the Waymo AV passed on the "
          "left side, making contact with the Waymo AV's rear left sensor housing.",
          ("was attempting to make a right turn from 24th Street onto Capp Street while yielding to",
           "was trying to turn right onto Capp Street while yielding to", "was attempting to turn right onto Capp "
           "Street while waiting for", "was yielding to", "was preparing to turn right onto Capp Street while "
           "yielding to", "was waiting to make a right turn onto Capp Street, yielding to",
           "was stopped on 24th Street while yielding to", "was attempting to turn right from 24th St. onto Capp St. "
           "while yielding to", "was attempting to make a right turn onto Capp Street, yielding to"),
          _ego, ("stopped", "")),
    Probe("the AV stopping for the very party that struck it (the meeting began on its way)",
          "The Waymo AV came to a stop in the parking lot {w} an oncoming pickup truck. While the Waymo AV was stopped,"
          " the pickup truck passed it on the left, making contact with its rear left sensor.",
          ("while yielding to", "to yield to", "for", "while yielding to both pedestrians and", "when it yielded to",
           "yielding to"),
          _ego, ("moving", "ah")),
    Probe("the AV's driver taking over to make the turn (the purpose was carried out)",
          "The Cruise AV was yielding to an oncoming scooterist at the intersection with Howard Street. The driver of "
          "the Cruise AV {w} and, shortly thereafter, the scooterist made contact with the right side of the Cruise "
          "AV.",
          ("disengaged from autonomous mode to make the left turn", "disengaged autonomy to complete the left turn",
           "took manual control to make the left turn", "took over to turn left", "disengaged the AV to turn left",
           "took control of the vehicle to make the left turn", "transitioned to manual mode to make the left turn",
           "switched the vehicle to manual mode to turn left"),
          _ego, ("stopped", "id")),
    Probe("the AV's move told again at the contact (the string ends with it)",
          "The Waymo AV was stopped at a red light in the middle lane. When the light turned green, the Waymo AV "
          "attempted to merge into the left lane and make a left turn. {W}, the adjacent pickup truck began to "
          "proceed forward and made contact with the driver side of the Waymo AV.",
          ("As the Waymo AV moved into the left lane", "While the Waymo AV was moving into the left lane",
           "As the Waymo AV merged into the left lane", "Just as the Waymo AV changed lanes to the left",
           "When the Waymo AV moved into the left lane", "As the Waymo AV was merging into the left lane"),
          _ego, ("stopped", "if")),
    Probe("the AV entering a driveway or lot (a turn to the side it touched)",
          "The Zoox vehicle scraped a parked car at low speed as it was {w}, making contact with its left front "
          "bumper.",
          ("pulling into a driveway", "turning into a driveway", "entering a parking lot",
           "pulling into a parking garage", "entering a driveway", "driving into a parking lot",
           "pulling into the driveway on its left"),
          _ego, ("moving", "d")),
    Probe("the AV entering a lot or driveway, the right side touched",
          "The Waymo AV was {w} on Pacific Avenue when the front right sensor made contact with a fence.",
          ("entering a parking lot", "pulling into a driveway", "turning into a parking garage",
           "entering the lot of a gas station", "pulling into a parking lot"),
          _ego, ("moving", "e")),
    # Session 12, second batch: the AV's start and actions in the challenge narratives' wordings the rules missed
    # (a stop told after the move that followed it, a stop under way, waiting at a light behind a car, the same
    # moment after the contact, into the junction to turn, a braking told after the contact, a state after a comma,
    # a walker going into the AV's path, a party's state continued by a participle).
    Probe('the AV moving off after a stop told after it (it stood first)',
          'The Zoox vehicle was proceeding through a four-way stop intersection {w}. A pickup truck '
          'approaching from the right on the cross street failed to stop at its stop sign and hit the right '
          'side of the Zoox vehicle.',
          ('after stopping',
           'after coming to a stop',
           'after having stopped',
           'after coming to a complete stop',
           'after stopping at the stop sign',
           'after it had stopped'),
          _ego, ('stopped', 'i')),
    # Session 14: the annotators read a stop told under way as the string's opener (study2 s213 "was slowing to a stop
    # ... when", study3 30291-7677 "was coming to a stop as", `h`; the official gold's r376 slowing, `c`).
    Probe('the AV slowing to stop (a stop under way: moving, h)',
          'A Pony.ai vehicle in autonomous mode was {w} for a red light on southbound Main Street. A '
          'motorcycle traveling behind the AV in the same lane was unable to stop and struck the rear bumper '
          'of the AV.',
          ('slowing to stop',
           'braking to stop',
           'slowing to a stop',
           'decelerating to stop',
           'coming to a stop',
           'stopping',
           'slowing down to stop'),
          _ego, ('moving', 'h')),
    Probe('the AV stopped behind a car waiting at the light, then following it (stopped, i)',
          'A Cruise AV was traveling northbound on Larkin Street. The Cruise AV {w} for the red light. When '
          'the light turned green, the Nissan proceeded through the intersection and the Cruise AV began to '
          "follow. A Honda traveling eastbound on Geary Boulevard, from the Cruise AV's left, entered the "
          'intersection against the red light and made contact with the front driver side of the Cruise AV.',
          ('came to a stop behind a Nissan Sentra that was stopped',
           'stopped behind a Nissan Sentra that was waiting',
           'came to a stop behind a Nissan Sentra, which was stopped',
           'came to a stop behind a Nissan that was stopped',
           'came to a stop behind a Nissan that was waiting'),
          _ego, ('stopped', 'i')),
    Probe("the AV's move in an 'as' clause after the contact (same moment, in the string)",
          'A Zoox vehicle in autonomous mode was waiting at a red light on eastbound Harrison Street. A '
          "pedestrian walked into the Zoox vehicle's front bumper {w}.",
          ('as the light turned green and the Zoox vehicle began to move',
           'as the Zoox vehicle began to move',
           'while the Zoox vehicle was starting to move forward',
           'just as the light turned green and the Zoox vehicle started to move',
           'as the Zoox vehicle began moving'),
          _ego, ('stopped', 'i')),
    Probe('the AV moving into the junction to turn (the turn begun)',
          'A Waymo AV was stopped at a red light in the left turn lane on Van Ness Avenue. After the light '
          'turned green, the Waymo AV {w}. A passenger vehicle in the adjacent left turn lane drifted into the '
          "Waymo AV's lane, making contact with the Waymo AV's passenger side.",
          ('proceeded into the intersection to turn left',
           'entered the intersection to make a left turn',
           'moved into the intersection to turn left',
           'pulled into the intersection to make its left turn',
           'proceeded into the intersection to complete a left turn'),
          _ego, ('stopped', 'id')),
    Probe("the AV's braking told after the contact as before the impact",
          'An Apple test vehicle in autonomous mode was traveling southbound on De Anza Boulevard. A '
          "northbound vehicle made a left turn in front of the Apple vehicle, and the Apple vehicle's front "
          'bumper struck the right rear of the turning vehicle. {W}.',
          ('The Apple vehicle had braked before the impact',
           'The Apple vehicle braked prior to the collision',
           'The Apple vehicle had slowed before the contact',
           'The test driver had applied the brakes before the impact',
           'The Apple vehicle decelerated before impact'),
          _ego, ('moving', 'ac')),
    Probe("the AV's state told as ', stopped in traffic' (where it stood)",
          'The Zoox vehicle was in the right lane of Las Vegas Boulevard, {w}. A sport utility vehicle in the '
          "left lane passed the Zoox vehicle, and its right mirror struck the Zoox vehicle's left mirror.",
          ('stopped in traffic behind a bus',
           'stopped in traffic',
           'stopped behind a bus',
           'stopped at a red light',
           'stopped in a queue of vehicles',
           'stopped at the light'),
          _ego, ('stopped', '')),
    Probe("a walker going into the AV's path (no contact yet)",
          'The Waymo AV was making a right turn at the intersection when a pedestrian who was crossing the '
          'street {w} the path of the Waymo AV. The Waymo AV stopped, but its front bumper contacted the '
          "pedestrian's leg.",
          ('walked into',
           'ran into',
           'stepped into',
           'darted into',
           'walked directly into'),
          _ego, ('moving', 'eh')),
    Probe("a party's state told on by a participle ('stopped ... waiting to park')",
          'The AV was traveling westbound on Broadway when it approached a vehicle that was stopped in the '
          'travel lane {w}. The AV slowed, and the vehicle, which was reversing into a parking space, made '
          "contact with the AV's front right bumper.",
          ('waiting to parallel park',
           'waiting to park',
           'idling in front of a space',
           'sitting with its hazards on',
           'standing with its reverse lights on'),
          _ego, ('moving', 'ac')),
    # Session 12, third batch: who did a participle after a comma, the contact named again in the damage, contacts
    # told as a move into a part of the AV or onto it, a braking at the contact.
    Probe("the AV standing while a party behind it, going around, merges (a comma's participle is the subject's)",
          'The Waymo AV was stopped in the right lane while boarding a passenger. A passenger vehicle stopped '
          'behind the Waymo AV then attempted to go around the Waymo AV, {w} with traffic in the center lane '
          'and making contact with the Waymo AV.',
          ('attempting to merge',
           'trying to merge',
           'merging',
           'beginning to merge',
           'about to merge'),
          _ego, ('stopped', '')),
    Probe('the contact named again in the damage told after it (the partner stays the one that struck)',
          'The Waymo AV was stopped at a red light on Pine Street. A sedan stopped behind the Waymo AV then '
          'attempted to go around it, colliding instead with a third vehicle and also making contact with the '
          'Waymo AV. {W}',
          ('The Waymo AV and the sedan that made contact with it sustained minor damage.',
           'The Waymo AV and the sedan, which struck it, sustained minor damage.',
           'Both the Waymo AV and the sedan that collided with it sustained damage.',
           'The Waymo AV and the vehicle that hit it sustained moderate damage.'),
          _partner_told, ('npc1', ())),
    Probe("a party's move that ends in a part of the AV (a contact)",
          'The Waymo AV was stopped facing southwest on Fulton Street while yielding to pedestrians in a '
          'crosswalk when a passenger vehicle {w} of the Waymo AV. Both vehicles sustained minor damage.',
          ('reversed at a low speed from an adjacent driveway into the right rear bumper',
           'backed out of a driveway into the rear bumper',
           'rolled backward into the front bumper',
           'reversed into the right rear corner',
           'backed up into the front'),
          _partner_touched, ('npc1', True)),
    Probe('a walker jumping onto the AV (a contact)',
          'The Cruise AV stopped for a pedestrian on Hayes Street. The pedestrian approached the Cruise AV and '
          '{w} of the Cruise AV.',
          ('jumped onto the hood',
           'climbed onto the hood',
           'leaped onto the hood',
           'jumped up onto the hood',
           'climbed onto the roof'),
          _partner_id, 'npc1'),
    Probe('the AV braking just before the contact (a reaction, no manoeuvre)',
          'A Zoox vehicle was stopped in the left turn lane, yielding to cross traffic. The operator '
          'disengaged and proceeded to make the left turn. An SUV from the left continued straight, and the '
          "operator {w} the front of the Zoox vehicle made contact with the SUV's passenger side.",
          ('braked just before',
           'braked immediately before',
           'applied the brakes moments before',
           'braked right before',
           'braked a split second before'),
          _ego, ('stopped', 'id')),
    Probe("a party's turn told 'while making' it (under way: the string opens with the turn)",
          "The Apple test vehicle was stopped in the left turn lane at the park exit on Manet Drive. A Toyota "
          "Corolla, traveling at approximately 6 mph, {w} into the park entrance and struck the Apple test vehicle.",
          ("swung wide while making a right turn", "swung wide outside of its lane while making a right turn",
           "cut the corner while making a left turn", "went wide while completing a right turn",
           "swung wide while performing a left turn"),
          _npc_actions, lambda w: [("moving", "d" if "left turn" in w else "e")]),
    Probe("a party turning and ending in front of the AV (where the turn ends, no lane change)",
          "A Zoox vehicle in manual mode was proceeding southbound in the turn lane on Sixth Street with a green "
          "light. A large truck in the left adjacent lane abruptly {w} the Zoox vehicle, making contact with the "
          "left front sensor.",
          ("turned right and cut in front of", "turned right and pulled in front of",
           "made a right turn and moved in front of", "turned right and got in front of",
           "turned right and swerved in front of", "turned right and came in front of"),
          _party, [("R5", "left", "ae")]),

    # Session 13: from the first 106 of 213 real narratives new to the project (a public CSV of DMV reports; see
    # tests/text/csvr/README.md), each a reading they showed wrong, written out in other wordings.
    _scenes("the summary's party named again with its own noun ('the passenger vehicle'), never the AV", lambda sk: (
            sk.collision.with_, [(p.category, p.position, p.lane) for p in sk.npcs]), (
            ("A Waymo AV operating in San Francisco was in a collision involving a passenger vehicle at Bush Street "
             "and Grant Avenue. The Waymo AV was stopped in traffic when the passenger vehicle approached from "
             "behind. The passenger vehicle struck the rear of the Waymo AV.", ("npc1", [("car", "R6", "same")])),
            ("A Waymo AV was in a collision involving a passenger car on Pine Street. The Waymo AV was stopped at a "
             "red light. The passenger car behind the Waymo AV made contact with the rear of the Waymo AV.",
             ("npc1", [("car", "R6", "same")])),
            ("A Waymo AV was in a collision involving a heavy truck on Bayshore Boulevard. The Waymo AV came to a "
             "stop to yield for approaching traffic. The Waymo AV was rear ended by the truck.",
             ("npc1", [("truck", "R6", "same")])),
            ("A Waymo AV was traveling north on 3rd Street. A city bus in the right adjacent lane began to overtake "
             "the Waymo AV from the right. The passenger vehicle behind the Waymo AV made contact with the Waymo "
             "AV's rear bumper.", ("npc2", [("bus", "R6", "right"), ("car", "R6", "same")])),
    )),
    Probe("a light or stop sign the AV stood at, told in the opening summary sentence (a junction)",
          "A Waymo AV was stopped in autonomous mode {w} on southbound Rengstorff Avenue at Central Expressway "
          "when it was rear-ended by a passenger vehicle. The passenger vehicle made contact with the Waymo AV's "
          "rear bumper at approximately 1 MPH.",
          ("at a red light", "in traffic at a red light", "at a stop sign", "at a four-way stop",
           "for a red traffic signal", "at the traffic light"),
          lambda sk: sk.road.layout, "junction4"),
    Probe("a lane change further to the side a party was placed on: it began in the AV's lane",
          "The Waymo AV was stopped in the leftmost lane on Potrero Avenue. A truck that had been stopped behind the "
          "Waymo AV {w} to maneuver around the Waymo AV, and its passenger side made contact with the Waymo AV's "
          "rear driver side corner.",
          ("entered the oncoming lane", "moved into the left adjacent lane", "changed lanes to the left",
           "swerved into the oncoming lane", "crossed the double yellow line"),
          _position, [("R6", "same")]),
    Probe("a vehicle coming up behind an AV parked at the curb (in the travel lane, on its left)",
          "The Waymo AV was {w} on eastbound Harrison Street. A pickup truck traveling behind the Waymo AV made "
          "contact with the rear of the Waymo AV.",
          ("parked at the curb", "parallel parked along the curb", "stopped at the curb",
           "parked along the right curb"),
          _position, [("R6", "left")]),
    Probe("a party that turned onto the AV's street from a crossing one (its turn and where it ended up)",
          "A Cruise AV was traveling northbound on Grant Street between Clay and Washington Streets when another "
          "vehicle, {w}, made contact with the Cruise AV.",
          ("completing a left turn from Clay onto Grant Street behind the Cruise AV",
           "completing a left turn from Clay onto Grant, following the Cruise AV",
           "turning right from Clay Street onto Grant Street behind the Cruise AV",
           "after turning left from Clay onto Grant Street ahead of the Cruise AV"),
          _position, lambda w: [("R1" if ("left" in w) == ("behind" in w or "following" in w) else "R3", None)]),
    Probe("a lane change into the lane on a named side ('the right adjacent lane')",
          "A Cruise AV was stopped at a red light on Hyde Street when another vehicle behind the Cruise AV {w} and "
          "made contact with the Cruise AV's rear bumper.",
          ("attempted to change into the right adjacent lane", "moved into the right adjacent lane",
           "changed into the left adjacent lane", "attempted to merge into the left adjacent lane"),
          lambda sk: [("f" in p.actions, "g" in p.actions) for p in sk.npcs][:1],
          lambda w: [("left" in w, "right" in w)]),
    Probe("the part of the AV's rear a party met with nothing else told (a corner: that side; a bumper: behind)",
          "A Cruise AV was traveling southbound on Divisadero Street between Pine and Bush Streets when another "
          "vehicle made contact with {w}, damaging it. There were no injuries.",
          ("the left rear corner of the Cruise AV", "the Cruise AV's left rear corner", "the right rear corner of "
           "the Cruise AV", "the Cruise AV's rear right corner", "the driver side rear corner of the Cruise AV",
           "the rear bumper of the Cruise AV", "the left rear bumper of the Cruise AV",
           "the Cruise AV's right rear bumper"),
          _position, lambda w: [("R6", "same" if "bumper" in w else
                                 "left" if ("left" in w or "driver" in w) else "right")]),
    Probe("a rider running into the middle of the AV's rear (in line behind it, not at the lane's edge)",
          "The Zoox vehicle was stopped at a stop sign on Union St. when it was rear-ended by {w}. Its front tire "
          "made contact with the rear bumper of the Zoox vehicle.",
          ("an electric scooter", "a scooter rider", "a cyclist", "a bicyclist following closely behind",
           "an e-scooter rider"),
          _position, [("R6", "same")]),
    _scenes("a party behind a party behind the AV, told by what it did to that party", lambda sk: [
            (p.position, p.lane) for p in sk.npcs], (
            ("The Waymo AV was stopped at a red light with an SUV stopped directly behind it. A passenger car "
             "approached the stopped SUV from behind and made contact with the rear of the SUV. The SUV then made "
             "contact with the rear of the Waymo AV.", [("R6", "same"), ("R6", "same")]),
            ("The Waymo AV was stopped at a red light with an SUV stopped directly behind it. A pickup truck made "
             "contact with the rear bumper of the SUV, which then struck the rear of the Waymo AV.",
             [("R6", "same"), ("R6", "same")]),
    )),
    Probe("a party behind the AV moving into its lane: the side it came from (the AV's open side, or the side it hit)",
          "A Waymo AV was stopped in traffic {w} when it was rear-ended by a passenger vehicle maneuvering into the "
          "Waymo AV's lane. The Waymo AV sustained minor damage.",
          ("while in the leftmost lane on San Antonio Road", "in the leftmost lane on San Antonio Road",
           "in the far left lane of San Antonio Road", "while in the rightmost lane on San Antonio Road",
           "in the right-most lane of San Antonio Road"),
          _position, lambda w: [("R6", "right" if "left" in w else "left")]),
    Probe("the AV's stop at a sign or light told as an event, then a vehicle behind runs into it (ah)",
          "The Waymo AV was traveling eastbound on Jersey Street and {w}. While yielding to pedestrians, a pickup "
          "truck traveling directly behind the Waymo AV made contact with the rear of the Waymo AV.",
          ("stopped at a stop sign at the intersection of Church Street", "came to a stop at a stop sign",
           "came to a complete stop at the red light at Church Street", "stopped for a red light at Church Street",
           "came to a stop at the four-way stop at Church Street"),
          _ego, ("moving", "ah")),
    Probe("the AV 'about to' move off when struck from behind (an intention: it stood)",
          "The Waymo AV was stopped at a red light on Mission Street at 16th Street. The light turned green and the "
          "Waymo AV {w} when a passenger vehicle behind the Waymo AV made contact with its rear bumper.",
          ("was about to proceed", "was about to move forward", "was about to begin moving",
           "was just about to proceed through the intersection", "was about to accelerate"),
          _ego, ("stopped", "")),
    Probe("a party touching 'its' rear bumper in the AV's sentence (the AV's part: behind it)",
          "The Cruise AV was stopped in the left turn lane, waiting to turn left, when {w}.",
          ("another vehicle made contact with its rear bumper", "a sedan struck its rear",
           "an SUV rear-ended its rear bumper", "a pickup truck collided with its rear end",
           "a van hit its rear bumper"),
          _position, [("R6", "same")]),
    Probe("the AV in a turn lane when struck (turn lanes end at a junction)",
          "The Waymo AV was {w} on Market Street when a passenger vehicle approached from behind and made contact "
          "with the rear bumper of the Waymo AV.",
          ("approaching stopped traffic in the left turn lane", "traveling in the left turn lane",
           "stopped in the dedicated right turn lane", "proceeding in the left-turn lane",
           "driving in the rightmost left turn lane"),
          lambda sk: sk.road.layout, "junction4"),
    _scenes("the AV's stop at a light or sign told as an event in the contact's own sentence, or before a party said "
            "to be behind it (ah)", _ego, (
            ("The Waymo AV was traveling north on Mission Street and came to a stop at a red light when a vehicle "
             "behind made contact with the rear bumper of the Waymo AV.", ("moving", "ah")),
            ("The Waymo AV was traveling north on Mission Street and stopped at a stop sign, and a passenger car "
             "traveling behind the Waymo AV made contact with the rear of the Waymo AV.", ("moving", "ah")),
            ("The Waymo AV was traveling eastbound and slowed to a stop for a stop sign when it was struck from "
             "behind by an SUV.", ("moving", "ah")),
            ("The Waymo AV approached the intersection and came to a stop at the red light. Moments later, a sedan "
             "behind the Waymo AV struck its rear bumper.", ("moving", "ah")),
    )),
    # Session 17: the manoeuvre vocabularies above, of a party and of the AV.
    Probe("a party's left turn, in the ways English tells it (session 17)",
          "The Waymo AV was traveling northbound on Mission Street and entered the intersection with 16th Street on a "
          "green light. A sedan traveling southbound on Mission Street {w} in front of the Waymo AV and made contact "
          "with its front bumper.",
          _TURN_LEFT, _npc_actions, [("moving", "ad")]),
    Probe("a party's right turn, in the ways English tells it (session 17)",
          "The Waymo AV was traveling northbound on Mission Street. A sedan traveling northbound ahead of the Waymo AV "
          "in the same lane {w}, and the Waymo AV made contact with its rear bumper.",
          tuple(w.replace("left", "right") for w in _TURN_LEFT), _npc_actions, [("moving", "ae")]),
    Probe("the AV's left turn, in the ways English tells it (session 17)",
          "A Zoox vehicle was traveling northbound on Koval Lane in the middle lane. At the intersection with Flamingo "
          "Road, the Zoox vehicle {w} and a sedan traveling behind it struck its rear bumper.",
          _TURN_LEFT, _ego, ("moving", "ad")),
    Probe("a party's lane change to the left, in the ways English tells it (session 17)",
          "The Waymo AV was traveling northbound on Mission Street in the left lane. A sedan traveling in the right "
          "lane {w} and made contact with the front right bumper of the Waymo AV.",
          _LANE_CHANGE_LEFT, _npc_actions, [("moving", "af")]),
    Probe("a party's U-turn, in the ways English tells it (session 17)",
          "The Waymo AV was traveling northbound on Mission Street. A sedan traveling southbound on Mission Street {w} "
          "in front of the Waymo AV and made contact with its front bumper.",
          _U_TURN, _npc_actions, [("moving", "aj")]),
    Probe("the AV's U-turn, in the ways English tells it (session 17)",
          "A Zoox vehicle was traveling northbound on Koval Lane in the middle lane. At the intersection with Flamingo "
          "Road, the Zoox vehicle {w} and a sedan traveling behind it struck its rear bumper.",
          _U_TURN, _ego, ("moving", "aj")),
    Probe("a party backing, in the ways English tells it (session 17)",
          _AV_STOPPED + "A sedan ahead of the Waymo AV {w} and made contact with the front bumper of the Waymo AV.",
          _BACKING, _npc_actions, [("stopped", "k")]),
    Probe("the AV backing, in the ways English tells it (session 17)",
          "A Zoox vehicle was stopped on Koval Lane. The Zoox vehicle {w} and struck a sedan that was stopped behind "
          "it.",
          tuple(w.replace("the Waymo AV", "the sedan") for w in _BACKING), _ego, ("stopped", "k")),
    Probe("a party ahead stopping, in the ways English tells it (session 17)",
          "The Waymo AV was traveling northbound on Mission Street behind a sedan. The sedan {w} and the Waymo AV "
          "made contact with its rear bumper.",
          _STOPPING, _npc_actions, [("moving", "ah")]),
    Probe("the AV stopping, in the ways English tells it (session 17)",
          "A Zoox vehicle was traveling northbound on Koval Lane in the middle lane. The Zoox vehicle {w} and a sedan "
          "traveling behind it struck its rear bumper.",
          tuple(w.replace("the Waymo AV", "a sedan") for w in _STOPPING), _ego, ("moving", "ah")),
    Probe("a party ahead slowing, in the ways English tells it (session 17)",
          "The Waymo AV was traveling northbound on Mission Street behind a sedan. The sedan {w} and the Waymo AV "
          "made contact with its rear bumper.",
          _SLOWING, _npc_actions, [("moving", "ac")]),
    Probe("the AV slowing, in the ways English tells it (session 17)",
          "A Zoox vehicle was traveling northbound on Koval Lane in the middle lane. The Zoox vehicle {w} and a sedan "
          "traveling behind it struck its rear bumper.",
          _SLOWING, _ego, ("moving", "ac")),
    Probe("the AV moving off at the light, in the ways English tells it (session 17)",
          "A Zoox vehicle was stopped at a red light on Koval Lane. When the light turned green, the Zoox vehicle {w} "
          "and a sedan traveling behind it struck its rear bumper.",
          _MOVING_OFF, _ego, ("stopped", "i")),
    Probe("a party behind speeding up, in the ways English tells it (session 17)",
          "The Waymo AV was traveling northbound on Mission Street. A sedan traveling behind the Waymo AV {w} and "
          "struck the rear bumper of the Waymo AV.",
          _SPEEDING_UP, _npc_actions, [("moving", "ab")]),
    Probe("a walker crossing the AV's road, in the ways English tells it (session 17)",
          "The Waymo AV was traveling northbound on Mission Street between 16th Street and 17th Street. A pedestrian "
          "{w} and the Waymo AV made contact with the pedestrian.",
          _CROSSING_ON_FOOT, _npc_actions, [("moving", "m")]),
    Probe("a vehicle out of a driveway, a lot or an alley, in the ways English tells it (session 17)",
          "The Waymo AV was traveling northbound on Mission Street between 16th Street and 17th Street. A sedan {w} "
          "and made contact with the front of the Waymo AV.",
          _OUT_OF_A_DRIVEWAY, _npc_actions, [("moving", "m")]),
    Probe("the moving AV's light, green or yellow, in more ways (session 17)",
          "A Zoox vehicle was traveling northbound on Koval Lane and entered the intersection with Flamingo Road {w}. "
          "A sedan traveling eastbound on Flamingo Road struck the driver side of the Zoox vehicle.",
          (
           "on a green light", "on green", "on a green signal", "with a green light", "on a steady green",
           "on a solid green light", "on a green arrow", "on a protected green arrow", "on a green left-turn arrow",
           "during the green phase", "while its light was green", "after its light turned green",
           "with a green traffic light", "on a circular green indication", "on a green indication",
           "while it had a green light", "with a green signal", "as its signal was green", "on a stale green light",
           "with the right of way on a green light", "on a green ball", "under a green light", "on the green light",
           "on a green traffic signal", "on a yellow light", "on yellow", "on an amber light",
           "as the light turned yellow", "on a yellow signal", "during the yellow phase", "on a solid yellow light",
           "as the light changed to amber", "on a flashing yellow arrow", "with a yellow light", "on a yellow arrow",
          ),
          lambda sk: (sk.road.control, sk.signal_state),
          lambda w: ("signal", "yellow" if ("yellow" in w or "amber" in w) else "green")),
    Probe("the standing AV's red, in more ways (waiting for a green is standing at a red) (session 17)",
          "A Zoox vehicle was stopped {w} on Koval Lane at Flamingo Road when a sedan traveling behind it struck its "
          "rear bumper.",
          (
           "at a red light", "for a red light", "at a red signal", "at the red light", "at a red traffic light",
           "at a red traffic signal", "at a solid red light", "at a red arrow", "for a red arrow", "at a steady red",
           "facing a red light", "facing a red signal", "at a red indication", "waiting for the light to turn green",
           "waiting for a green light", "at a stoplight", "at a stop light", "at a traffic light", "at the signal",
           "for the signal", "at a red ball", "at a flashing red light",
          ),
          lambda sk: (sk.road.control, sk.signal_state), ("signal", "red")),
    Probe("a party standing ahead that the AV runs into, its state told in more ways (session 17)",
          "The Waymo AV was traveling northbound on Mission Street when it made contact with the rear bumper of a "
          "sedan {w} ahead of it.",
          (
           "that was stopped", "that was stationary", "that was idling", "that was at a standstill",
           "that was sitting", "that was queued", "that was standing", "that was stalled", "that was waiting",
           "that was at rest", "that was halted", "that was paused", "that was motionless", "that was not moving",
           "that was stopped in traffic", "that was at a stop", "that was at a complete stop", "that had stopped",
           "that had come to a stop", "that had come to a complete stop", "which was stopped", "which was stationary",
           "stopped", "standing still", "sitting", "idling", "waiting", "stalled", "that was stopped in the lane",
           "that was stopped at a red light", "that remained stopped", "that sat stationary",
           "that was holding its position", "that was broken down", "that had broken down", "that had stalled",
           "that was at a full stop", "that had halted", "that was waiting at the light", "that had been stopped",
           "that had been stationary", "that is stopped", "that was temporarily stopped",
           "that was momentarily stopped", "that was stuck in traffic", "that was standing in traffic",
           "that was waiting in traffic", "that was stopped in a queue", "that was in a queue of stopped traffic",
           "that was stopped with its hazard lights on",
          ),
          _npc_actions, [("stopped", "")]),
    Probe("the AV standing when struck, its state told in more ways (session 17)",
          "A Zoox vehicle was {w} on Koval Lane when a sedan traveling behind it struck its rear bumper.",
          (
           "stopped", "stationary", "idling", "at a standstill", "sitting", "queued", "standing", "waiting", "at rest",
           "halted", "paused", "motionless", "not moving", "stopped in traffic", "at a stop", "at a complete stop",
           "at a full stop", "holding its position", "stopped in lane", "stopped in the lane", "temporarily stopped",
           "momentarily stopped", "stuck in traffic", "standing still", "waiting in traffic", "stopped in a queue",
           "in a queue of stopped traffic", "parked", "double-parked", "stopped for a passenger pickup",
           "stopped at the curb", "pulled over at the curb", "in park", "sitting still", "sitting in traffic",
           "completely stopped", "fully stopped", "stationary in traffic", "yielding", "waiting to turn left",
           "stopped and waiting", "at a dead stop", "at a stand still", "immobile", "stalled",
          ),
          _ego, ("stopped", "")),
    Probe("a party behind the standing AV moving off, told under way and in the SGO form's words (session 17)",
          "The Waymo AV was stopped at a red light on Mission Street. A sedan behind the Waymo AV was {w} when it "
          "struck the rear bumper of the Waymo AV.",
          ("starting in traffic", "starting from a stop", "accelerating from a stop", "beginning to move",
           "just starting to move", "pulling forward", "moving forward", "creeping forward", "inching forward",
           "rolling forward", "starting to proceed", "beginning to roll forward"),
          _npc_actions, [("stopped", "i")]),
    Probe("the AV moving off after a stop, told in the present as in the past (session 17)",
          "At about 11:35 am our vehicle is traveling northbound on First Street. Our vehicle comes to a stop for a "
          "pedestrian and then {w}, and a sedan traveling in the left lane changes lanes and strikes our front bumper.",
          ("proceeds", "enters the intersection", "moves forward", "continues", "accelerates", "pulls forward",
           "drives on", "proceeded", "entered the intersection", "moved forward", "continued", "accelerated",
           "drove on"),
          _ego, ("moving", "ahi")),
    Probe("a dark or broken traffic light: the junction has a signal, the AV began on none (session 17)",
          "A Zoox vehicle was stopped {w} on Koval Lane at Flamingo Road when a sedan traveling behind it struck its "
          "rear bumper.",
          ("at a malfunctioning traffic light", "at an inoperative traffic signal", "at a dark traffic signal",
           "at a non-functioning traffic light", "at a traffic light that was not illuminated",
           "at a traffic signal that was not working", "at the intersection because the traffic lights were out",
           "at a traffic light that was dark during a power outage", "at an unlit traffic signal",
           "at a broken traffic light"),
          lambda sk: (sk.road.layout, sk.road.control, sk.signal_state), ("junction4", "signal", "none")),
    Probe("a party beside the AV cutting in front of it, in the ways English tells it (session 17)",
          "The Waymo AV was traveling northbound on Mission Street in the left lane. A sedan traveling in the right "
          "lane {w} and the front of the Waymo AV made contact with the sedan's rear bumper.",
          (
           "cut in front of the Waymo AV", "cut the Waymo AV off", "cut off the Waymo AV", "cut in",
           "cut over in front of the Waymo AV", "swerved in front of the Waymo AV", "moved in front of the Waymo AV",
           "pulled in front of the Waymo AV", "darted in front of the Waymo AV", "veered in front of the Waymo AV",
           "merged in front of the Waymo AV", "changed lanes in front of the Waymo AV",
           "squeezed in front of the Waymo AV", "slid in front of the Waymo AV", "jumped in front of the Waymo AV",
           "nosed in front of the Waymo AV", "cut into the Waymo AV's path", "moved into the Waymo AV's path",
           "pulled into the Waymo AV's path", "swerved into the Waymo AV's path", "entered the Waymo AV's path",
           "entered the path of the Waymo AV", "moved into the path of the Waymo AV",
           "cut into the path of the Waymo AV", "swerved into the path of the Waymo AV",
           "merged into the path of the Waymo AV", "drifted into the path of the Waymo AV",
           "veered into the path of the Waymo AV", "came into the Waymo AV's lane",
           "abruptly cut in front of the Waymo AV", "suddenly moved in front of the Waymo AV",
           "cuts in front of the Waymo AV", "cut sharply in front of the Waymo AV",
           "made an unsafe lane change in front of the Waymo AV",
           "made an abrupt lane change in front of the Waymo AV", "encroached into the path of the Waymo AV",
           "intruded into the Waymo AV's lane",
          ),
          _npc_actions, [("moving", "af")]),
    _scenes("a party's turn told only by headings: the side from its heading before to the one after (session 17)",
            lambda sk: [p.actions for p in sk.npcs], tuple(
                ("The Waymo AV was traveling northbound on Mission Street. A sedan traveling " + w + " and made "
                 "contact with the front bumper of the Waymo AV.", [want]) for w, want in (
                    ("eastbound on 16th Street turned onto northbound Mission Street", "ad"),
                    ("westbound on 16th Street turned onto northbound Mission Street", "ae"),
                    ("eastbound on 16th Street turned onto southbound Mission Street", "ae"),
                    ("westbound on 16th Street turned onto southbound Mission Street", "ad"),
                    ("southbound on Mission Street turned onto eastbound 16th Street", "ad"),
                    ("southbound on Mission Street turned onto westbound 16th Street", "ae"),
                    ("eastbound on 16th Street made a turn onto northbound Mission Street", "ad"),
                    ("east on 16th Street turned north onto Mission Street", "ad"),
                    ("west on 16th Street turned south onto Mission Street", "ad"),
                    ("eastbound on 16th Street was turning onto northbound Mission Street", "d")))),
    Probe("the AV's turn told only by compass words: the side from its heading before to the one after (session 17)",
          "A Zoox vehicle was traveling {w} when a sedan traveling behind it struck its rear bumper.",
          ("eastbound on Koval Lane and turned onto northbound Flamingo Road",
           "westbound on Koval Lane and turned onto northbound Flamingo Road",
           "east on Koval Lane and turned north onto Flamingo Road", "west on Koval Lane and turned south onto Flamingo Road",
           "north on Koval Lane and turned east onto Flamingo Road", "south on Koval Lane and turned east onto Flamingo Road"),
          lambda sk: sk.ego.actions, lambda w: "e" if w.startswith(("westbound", "north on")) else "d"),
    Probe("a party merging onto the freeway from its ramp, in the ways English tells it (session 17)",
          "The Zoox vehicle was traveling northbound on Interstate 15 in the rightmost lane. A pickup truck {w} and "
          "struck the passenger side of the Zoox vehicle.",
          (
           "merged onto the freeway from the on-ramp", "entered the freeway from the on-ramp",
           "merged from the on-ramp", "entering from the on-ramp merged into the Zoox vehicle's lane",
           "came down the on-ramp and merged", "joined the freeway from the on-ramp", "merged onto Interstate 15",
           "entered Interstate 15 from the on-ramp", "merged onto the highway", "entered the highway",
           "merged in from the ramp", "merged from the entrance ramp", "merged from the acceleration lane",
           "moved from the merge lane into the Zoox vehicle's lane", "merged from the onramp",
           "merged from the on ramp", "merged into traffic from the on-ramp", "on the on-ramp merged left",
           "traveling on the on-ramp merged into the rightmost lane", "attempted to merge onto the freeway",
           "began to merge onto the freeway", "tried to merge from the on-ramp", "merges onto the freeway",
          ),
          lambda sk: [(p.position, p.lane, p.actions) for p in sk.npcs], [("R5", "right", "af")]),
    Probe("the AV pulling over, in the ways the operators tell it (session 17)",
          "A Zoox vehicle was traveling northbound on Koval Lane. The Zoox vehicle {w} and a sedan traveling behind it "
          "struck its rear bumper.",
          (
           "pulled over", "pulled over to the curb", "pulled to the curb", "executed a pullover",
           "executed a pull-over maneuver", "performed a pullover", "began to pull over", "initiated a pullover",
           "pulled into a loading zone", "pulled into the loading zone", "pulled into a bus stop",
           "pulled over for a passenger pickup", "pulled over to pick up a passenger",
           "pulled over to drop off a passenger", "moved to the curb to pick up a rider", "pulled into a parking spot",
           "began to parallel park", "pulled over to the right side of the road", "pulled onto the shoulder",
           "pulled into the parking lane", "pulled to the side of the road", "pulled up to the curb",
           "pulled alongside the curb", "pulled in to the curb", "pulled into a pick-up zone",
           "pulled into the curb lane", "steered toward the curb", "started a pullover maneuver", "began its pullover",
          ),
          _ego, ("moving", "al")),
    Probe("a rider crossing the AV's road, in the ways English tells it (session 17)",
          "The Waymo AV was traveling northbound on Mission Street between 16th Street and 17th Street. A cyclist {w} "
          "and the Waymo AV made contact with the cyclist.",
          (
           "rode across the street", "crossed the street", "was riding across the street",
           "rode across Mission Street", "cut across the street", "darted across the street",
           "crossed in front of the Waymo AV", "entered the roadway from the sidewalk",
           "rode off the sidewalk into the street", "rode out from a driveway",
           "came off the sidewalk into the roadway", "crossed mid-block", "crossed against the light",
           "was crossing the street", "attempted to cross the street", "began to cross the street",
           "rode into the street", "rode into the roadway", "rode out into the street", "pedaled across the street",
           "was pedaling across the street", "crossed from the west side of the street", "crosses the street",
           "rides across the street",
          ),
          _npc_actions, [("moving", "m")]),
    Probe("a junction told by its line, light, arrow or stop, in more ways (session 17)",
          "A Zoox vehicle was traveling northbound on Koval Lane in the right lane. The Zoox vehicle was stopped {w} "
          "when a sedan traveling behind it struck its rear bumper.",
          ("at the limit line", "at the limit line at Flamingo Road", "at the stop bar", "at the cross street",
           "at a red left-turn arrow", "at the traffic control signal", "at the traffic-control signal",
           "at a four way stop", "at a 4 way stop", "at an all way stop", "at a two way stop",
           "at the limit line for a stop sign", "at the limit line for a red light", "at a red traffic-control signal",
           "at a signal-controlled intersection", "at a stop-controlled intersection"),
          lambda sk: (sk.road.layout, sk.road.control, sk.signal_state),
          lambda w: ("junction4", "stop_sign", "none") if ("way" in w or "stop sign" in w or "stop-" in w) else
          # (standing at a light of no told colour: the red it stood at, as "was stopped at a traffic light")
          ("junction4", "signal", "red") if ("red" in w or "signal" in w) else ("junction4", "unknown", "unknown")),
    Probe("a junction left behind, and a parking lot told by its parts (session 17)",
          "A Zoox vehicle was traveling northbound on Koval Lane {w} when a sedan traveling behind it struck its rear "
          "bumper.",
          ("after clearing the intersection with Flamingo Road", "having cleared the intersection",
           "after passing through the intersection", "in a parking deck", "in a car park", "in a parking aisle",
           "in the drive aisle of a parking lot", "in a parking lot aisle", "within a parking structure",
           "at the entrance of a parking lot", "at the exit of a parking garage", "at the parking lot entrance",
           "at the driveway of a parking lot", "at the parking garage exit", "at the gate of a parking lot"),
          lambda sk: sk.road.layout,
          lambda w: "straight" if any(x in w for x in ("intersection", "entrance", "exit", "driveway", "gate")) else
          "parking"),
    Probe("a parked party pulling out into traffic, in the ways English tells it (session 17)",
          "The Waymo AV was traveling northbound on Mission Street in the right lane. A sedan that was parked on the "
          "right side of Mission Street {w} and made contact with the front right bumper of the Waymo AV.",
          _PULLING_OUT, _npc_actions, [("stopped", "if")]),
    Probe("a party ahead pulling over or parking, in the ways English tells it (session 17)",
          "The Waymo AV was traveling northbound on Mission Street in the left lane. A sedan traveling in the right "
          "lane ahead of the Waymo AV {w}. The Waymo AV made contact with the sedan's rear bumper.",
          _PULLING_OVER, _npc_actions, [("moving", "al")]),
    Probe("a party behind moving off into the standing AV, in the ways English tells it (session 17)",
          _AV_STOPPED.replace("at 16th Street", "") + "A sedan that was stopped behind the Waymo AV {w} and made "
          "contact with the rear bumper of the Waymo AV.",
          _MOVING_OFF, _npc_actions, [("stopped", "i")]),
    # Session 18: a party told crossing the AV's way at a junction (running the light or the stop sign, cross traffic,
    # broadside) with no heading, side or street of its own (a redacted street): on the crossing road on the side of
    # the AV it struck, told by the part's many names, before or after the AV's name.
    Probe("a party told crossing the AV's way at a junction, by the side of the AV it struck (session 18)",
          "The Waymo AV was traveling northbound on [XXX] through the intersection with [XXX] on a green light when a "
          "sedan on [XXX] {w}.",
          ("ran the red light and struck the right side of the Waymo AV",
           "ran the red light and struck the Waymo AV on its passenger side",
           "ran the red light and made contact with the Waymo AV's right front fender",
           "ran the red light and broadsided the Waymo AV on its passenger side",
           "ran the red light and T-boned the Waymo AV on the passenger side",
           "failed to stop for the red light and collided with the passenger side of the Waymo AV",
           "entered the intersection against the red light and struck the Waymo AV's passenger side doors",
           "disregarded the stop sign and impacted the right side of the Waymo AV",
           "proceeded through the red light and contacted the Waymo AV's right rear quarter panel",
           "ran the stop sign and struck the left side of the Waymo AV",
           "ran the red light and struck the Waymo AV on its driver side",
           "violated the red light and broadsided the Waymo AV on the driver's side",
           "ran the red light and made contact with the Waymo AV's left rear corner",
           "failed to stop at the stop sign and T-boned the Waymo AV on its left side"),
          _position, lambda w: [("R1" if ("left" in w or "driver" in w) else "R3", None)]),
    Probe("a vehicle the AV gave way to at a junction, nothing else told of it (session 18)",
          "The Waymo AV was traveling northbound on [XXX] and came to a stop at a four-way stop sign intersection. "
          "The Waymo AV {w} at the intersection when a sedan rear-ended the Waymo AV.",
          ("stopped to yield to another vehicle", "was yielding to a pickup truck", "gave way to a van",
           "was yielding the right of way to a passenger car", "gave the right of way to a box truck",
           "yielded to an SUV"),
          lambda sk: [(p.position, p.lane) for p in sk.npcs], [("R1", None), ("R6", "same")]),
    Probe("a party going forward into the front of the standing AV came at it; one backing was ahead (session 18)",
          "The Waymo AV was stopped on [XXX] in the middle of the block. A sedan {w} the front of the Waymo AV.",
          ("made contact with", "struck", "collided with", "drove into", "hit", "then made contact with",
           "reversed and made contact with", "backed up and struck", "rolled back into"),
          _position, lambda w: [("R5" if any(x in w for x in ("revers", "back")) else "R7", "same")]),
    # Session 18: the AV's run before its stop, told by any verb of going or by its heading alone (put for "was
    # traveling" in the 158 studyable narratives that use it, each of these changed 10-21 AV strings on 78babff).
    Probe("the AV's run before its stop, told by other verbs of going (session 18)",
          "The Waymo AV was {w} on Mission Street and came to a stop at a red light. A sedan traveling behind the "
          "Waymo AV made contact with its rear bumper.",
          ("operating northbound", "going northbound", "en route northbound", "in motion northbound",
           "being driven northbound", "navigating northbound", "northbound", "cruising northbound",
           "headed northbound", "rolling northbound", "operating north", "going north"),
          _ego, ("moving", "ah")),
    Probe("states told after the AV's stop event are its result (session 18)",
          "The Waymo AV was traveling westbound on Mission Street when it came to a stop{w} the Waymo AV was "
          "stationary, a sedan traveling behind the Waymo AV made contact with its rear bumper.",
          (", yielding to stopped traffic ahead. While", " while yielding to a pedestrian. While",
           ", waiting for a pedestrian to cross. While", ", allowing a pickup truck to pass. As",
           " and was yielding to cross traffic. While", ", giving way to an oncoming bus. As"),
          _ego, ("moving", "ah")),
    Probe("the AV's move after a take-over, told in the present tense (session 18)",
          "Prior to the collision, the Nuro Prius came to a stop at the intersection of Main Street and Elm Street. The "
          "Nuro operator disengaged autonomy, switched to manual, and {w}. A passenger vehicle collided with the Nuro "
          "Prius before the operator completed the maneuver.",
          ("proceeds to make a left turn", "proceeds to turn left", "continues to make a left turn",
           "tries to make a left turn", "attempts to make a left turn", "begins to make a left turn",
           "starts to make a left turn", "goes on to make a left turn", "proceeds into the travel lane",
           "moves into the travel lane", "pulls into the travel lane"),
          _ego, lambda w: ("stopped", "if" if "lane" in w else "id")),
    Probe("a summary near a cross street: the intersection ahead is not the scene, a stop at it is (session 18)",
          "On May 3, 2024 at 2:10 PM PT a Waymo Autonomous Vehicle (\u201cWaymo AV\u201d) operating in San Francisco, "
          "California was in a collision involving a passenger car on Mission Street near 16th Street. The Waymo AV was "
          "traveling northbound on Mission Street {w}. A passenger car traveling in the right lane changed lanes to "
          "the left and made contact with the passenger side of the Waymo AV.",
          ("approaching the intersection with 16th Street", "as it approached the intersection with 16th Street",
           "toward the intersection with 16th Street", "preparing to turn left at the intersection with 16th Street",
           "about to enter the intersection with 16th Street", "and came to a stop at the intersection with 16th "
           "Street", "and was stopped in traffic at the intersection with 16th Street"),
          lambda sk: sk.road.layout, lambda w: "junction4" if "stop" in w else "straight"),
    Probe("an intersection the AV had gone through, the AV named or not: behind it, not the scene (session 19)",
          "On May 3, 2024 at 2:10 PM PT a Waymo Autonomous Vehicle (\u201cWaymo AV\u201d) operating in Tempe, Arizona "
          "was in a collision involving a passenger car on [XXX] at [XXX]. The Waymo AV was traveling southbound on "
          "[XXX] in the rightmost lane of three lanes. {W}, a passenger car in the middle lane moved into the "
          "rightmost lane and made contact with the front driver side of the Waymo AV.",
          ("after the Waymo AV crossed the intersection with [XXX]", "after the Waymo AV had cleared the intersection",
           "after it passed through the intersection", "after the Waymo AV proceeded through the intersection",
           "after traveling through the intersection", "having crossed the intersection",
           "after the Waymo AV exited the intersection", "after the Waymo AV went through the intersection",
           "after driving through the intersection", "after the Waymo AV had traversed the intersection"),
          lambda sk: sk.road.layout, "straight"),
    Probe("after the AV's stop and its state, a party that comes in or manoeuvres meets it standing; a follower "
          "running into its rear met it as it stopped (session 19), unless the AV is told standing on, \"remained "
          "stopped\" (session 20: study5's gold)",
          "The Waymo AV was traveling northbound on [XXX] and came to a stop in the travel lane for a passenger "
          "pick-up. {W}.",
          ("while the Waymo AV remained stopped, a passenger car traveling behind the Waymo AV maneuvered around the "
           "left side of the Waymo AV and made contact with its rear driver side",
           "while stopped, a vehicle approached from behind and made contact with the rear bumper of the Waymo AV",
           "while the Waymo AV remained stationary, an SUV in the left lane changed lanes to the right and made "
           "contact with the driver side of the Waymo AV",
           "as the Waymo AV remained stopped, a passenger car parked on the right reversed and made contact with the "
           "passenger side of the Waymo AV",
           "while the Waymo AV was stopped, a cyclist passed the Waymo AV on the right and made contact with its "
           "passenger side mirror",
           "while the Waymo AV remained stopped, a pickup truck traveling directly behind the Waymo AV made contact "
           "with the rear of the Waymo AV",
           "while the Waymo AV was stopped, the passenger car following the Waymo AV made contact with its rear bumper",
           "as the Waymo AV remained stopped, a sedan traveling behind the Waymo AV struck the rear of the Waymo AV"),
          _ego, lambda w: ("moving", "ah") if ("behind the Waymo AV made" in w or "following" in w or "sedan" in w)
          and "remained" not in w else ("stopped", "")),
    Probe("a manoeuvre told in progress with any manner adverb between the auxiliary and the participle (session 20)",
          "A Zoox vehicle in autonomous mode was {w} slowing to a stop for a red traffic signal on southbound Main "
          "Street when a sedan traveling behind made contact with its rear bumper.",
          ("gradually", "steadily", "carefully", "still slowly", "smoothly", "cautiously", "already gradually",
           "slowly"),
          _ego, ("moving", "h")),
    Probe("a queue's standing told in a relative clause is the queue's, not the AV's approaching it (session 20)",
          "The Waymo AV was traveling west on Main Street in the leftmost through lane when it began to slow as it "
          "approached {w} for a red light. A passenger car traveling behind the Waymo AV then began to change lanes "
          "into the right adjacent lane. As the passenger car was passing the Waymo AV, the driver side of the "
          "passenger car made contact with the rear passenger side of the Waymo AV.",
          ("a queue of traffic that was stopped", "a line of cars that were stopped", "traffic which was stopped",
           "vehicles that had been stopped", "a cue of traffic that was stopped", "a queue of traffic that was "
           "waiting", "traffic that was stationary", "a line of vehicles which were stopped"),
          _ego, ("moving", "ac")),
    Probe("a slowing told with the stop it prepared for is a stop (session 20)",
          "The Waymo AV was traveling northbound on Main Street in the leftmost lane as it was approaching the "
          "intersection with 1st Street. The signal was yellow as the Waymo AV approached the intersection. The "
          "Waymo AV {w}, and a van traveling directly behind the Waymo AV then made contact with the rear of the "
          "Waymo AV.",
          ("slowed, preparing to stop", "slowed in preparation to stop", "braked, preparing to stop",
           "decelerated in order to stop", "slowed down, getting ready to stop", "slowed to stop",
           "slowed down, preparing to stop", "braked in preparation to stop"),
          _ego, ("moving", "ah")),
    Probe("a turn the AV was attempting, its driving mode told inside the clause: at the junction (session 20)",
          "On May 3, 2024 at 2:10 PM PT a Waymo Autonomous Vehicle (\u201cWaymo AV\u201d) operating in Tempe, Arizona "
          "was in a collision involving a passenger car on Main Street and Elm Street. While {w} from westbound Main "
          "Street onto northbound Elm Street, the Waymo AV was yielding to traffic approaching from the left. A "
          "passenger car behind the Waymo AV proceeded forward and made contact with the rear of the Waymo AV.",
          ("attempting a right turn in autonomous mode", "attempting a right turn in manual mode",
           "attempting a right turn", "trying to make a right turn", "attempting to turn right in autonomous mode",
           "attempting a right turn in fully autonomous mode", "attempting a right turn in autonomous driving mode",
           "attempting to make a right turn in driverless mode"),
          lambda sk: sk.road.layout, "junction4"),
    Probe("a collision placed inside a lot the AV was exiting is in the lot; an exit alone is where it meets the road "
          "(session 20)",
          "On March 3, 2025 at 11:52 PM MT a Waymo Autonomous Vehicle (Waymo AV) operating in Tempe, Arizona was in a "
          "collision involving a passenger car {w} at Main Street when it slowed to a stop to yield for pedestrians "
          "entering the crosswalk ahead. As the Waymo AV remained stopped, a passenger car directly behind the Waymo "
          "AV made contact with the rear of the Waymo AV.",
          ("in a parking lot at Main Street. The Waymo AV was exiting a parking lot",
           "inside a parking garage at Main Street. The Waymo AV was leaving the parking garage",
           "in the parking lot at Main Street. The Waymo AV was exiting the parking lot",
           "within a parking structure at Main Street. The Waymo AV was exiting the parking structure",
           "in a shopping center parking lot at Main Street. The Waymo AV was exiting the parking lot",
           "on Main Street at Elm Street. The Waymo AV was exiting a parking lot"),
          lambda sk: sk.road.layout, lambda w: "junction4" if w.startswith("on Main") else "parking"),
    Probe("the AV told standing on after its stop, a follower running into its rear: it stood (session 20)",
          "The Waymo AV was traveling westbound on [XXX] when it slowed to a stop to yield to traffic ahead of it in "
          "the same lane. {W}, a passenger car traveling directly behind the Waymo AV made contact with the rear of "
          "the Waymo AV.",
          ("while the Waymo AV remained stopped", "while the Waymo AV remained stationary",
           "as the Waymo AV remained at a stop", "while the Waymo AV stayed stopped", "while the Waymo AV was still "
           "stopped", "while the Waymo AV continued to yield", "while the Waymo AV continued to wait",
           "while the Waymo AV had remained stopped"),
          _ego, ("stopped", "")),
    Probe("a yield sign the AV stopped at is a sign control, no signal (session 19)",
          "The AV was in a right-turn lane, turning onto [XXX] from [XXX]. The AV {w} before merging onto [XXX] and a "
          "silver Toyota rear-ended the AV.",
          ("stopped at a yield sign", "came to a stop at the yield sign", "was stopped for a yield sign",
           "was waiting at a yield sign", "stopped at the yield-controlled entrance", "yielded at a yield sign"),
          lambda sk: (sk.road.control, sk.signal_state), ("stop_sign", "none")),
    Probe("a turn lane the AV waits in, the summary near a cross street: short of the junction (session 19)",
          "On May 3, 2024 at 6:17 PM PT a Waymo Autonomous Vehicle (Waymo AV) operating in San Francisco, California "
          "was in a collision involving a van on [XXX] near [XXX]. The Waymo AV was {w}. While the Waymo AV remained "
          "stopped, a van traveling behind the Waymo AV maneuvered around the Waymo AV and made contact with the rear "
          "driver side of the Waymo AV.",
          ("stopped in traffic in the dedicated right turn lane of southwestbound [XXX]", "waiting in the left turn lane",
           "stopped in the left-turn pocket", "queued in the rightmost right turn lane",
           "stopped in traffic in a right turn only lane", "waiting in a left-turn lane"),
          lambda sk: sk.road.layout, "straight"),
    Probe("the AV's stop told again in progress in a clause of the same moment: no slowing of its own (session 19)",
          "The Waymo AV was traveling northwestbound on [XXX] and slowed to a stop in anticipation of turning right "
          "into a driveway. A passenger car made a U-turn just behind and to the left of the Waymo AV {w}, and the "
          "front of the passenger car made contact with the rear driver side of the Waymo AV.",
          ("as the AV was slowing", "as the Waymo AV was braking", "while the Waymo AV was decelerating",
           "as the Waymo AV was stopping", "as the AV was still slowing", "as the Waymo AV was coming to a stop",
           "while it was slowing down", "as the Waymo AV was slowing to a stop"),
          _ego, ("moving", "ah")),
    Probe("a speed told after the AV's turn or lane change under way is that move's (session 19)",
          "The Waymo AV was {w}. A passenger car traveling in the adjacent lane made contact with the passenger side "
          "of the Waymo AV.",
          ("making a right turn onto Main Street, traveling at 16 mph",
           "making a right turn along Main Street, traveling at 16 mph",
           "turning right onto Main Street, moving at approximately 5 mph",
           "making a left turn onto Main Street, going at about 10 mph",
           "changing lanes to the left on Main Street, traveling at a speed of 12 mph",
           "executing a right turn, proceeding at less than 5 mph",
           "making a right turn along the [XXX], traveling at 16 mph", "turning left, traveling at approximately 8 mph"),
          _ego, lambda w: ("moving", "f" if "lanes" in w else "d" if "left" in w else "e")),
    Probe("the AV's road told single-lane, a turn lane named ahead: one lane (session 19)",
          "The Waymo AV was stopped {w}, just before the road widened to include a dedicated left turn lane ahead. A "
          "sedan traveling behind the Waymo AV struck its rear bumper.",
          ("in traffic in a one-lane section of northbound [XXX]", "at a stop sign in the single lane of "
           "southwestbound [XXX]", "on the single lane on [XXX]", "in the single travel lane of [XXX]",
           "on a one lane road", "in a single-lane portion of Main Street", "on a one lane section of Main Street"),
          lambda sk: sk.road.lanes, 1),
    Probe("a pull-over finished before the party comes in, the AV met standing: it stood (session 19)",
          "The Waymo AV was traveling east on [XXX], {w}. An SUV traveling east on [XXX] attempted to pass the Waymo "
          "AV on the left and made contact with the driver side mirror of the stationary Waymo AV.",
          ("then pulled over at the curb for a passenger drop-off", "and pulled to the curb to pick up a passenger",
           "then pulled over to the right curb", "and pulled up to the curb for a drop-off", "then pulled over",
           "and executed a pullover maneuver at the curb"),
          _ego, ("stopped", "")),
    Probe("a yield the AV kept up as it moved off is no stop (session 19)",
          "The Waymo AV was stopped in a queue of traffic at a red light. After the light turned green, the Waymo AV "
          "began to slowly move ahead {w} when the front of the pickup truck following behind the Waymo AV made "
          "contact with the rear of the Waymo AV.",
          ("while continuing to yield to the traffic ahead", "while continuing to yield for pedestrians",
           "as it continued to yield to the traffic ahead", "while it kept yielding to the traffic ahead",
           "continuing to yield to cross traffic"),
          _ego, ("stopped", "i")),
    Probe("a road's curve told by any of its nouns (session 19)",
          "The May autonomous vehicle was traveling in the right lane of a two-lane road with {w} when it made "
          "contact with the curb.",
          ("a slight curvature", "a sharp curve", "a gentle bend", "several curves", "a curvy section",
           "winding sections", "two bends", "a curved section"),
          lambda sk: sk.road.layout, "curve"),
    Probe("the AV's move into a curbside lane named by its kind is to the right (session 18)",
          "The Waymo AV was traveling northbound on Mission Street. The Waymo AV {w}, and a sedan traveling behind the "
          "Waymo AV made contact with its rear bumper.",
          ("moved into the bus lane", "maneuvered into the bus and taxi lane", "merged into the bike lane",
           "entered the bus lane", "moved into the curb lane", "swerved into the bike lane",
           "shifted into the transit lane", "moved over into the bus only lane"),
          _ego, ("moving", "ag")),
    Probe("the AV merging onto a named road is at a T (session 18)",
          "The Waymo AV was {w} when a passenger car traveling behind the Waymo AV made contact with its rear bumper.",
          ("stopped at the end of the on-ramp, preparing to merge onto northbound Mission Street",
           "stopped on the slip road, waiting to merge into [XXX]", "yielding before merging onto eastbound Market "
           "Street", "preparing to make a right turn and merge into Market Street from a side street",
           "on the interchange from Alma Street merging onto southbound Oregon Expressway"),
          lambda sk: sk.road.layout, "junction3"),
    Probe("the AV's run before its lane change, told by other verbs of going (session 18)",
          "The Waymo AV was {w} on Mission Street in the right lane when it changed lanes to the left. A sedan "
          "traveling in the left lane made contact with the driver side of the Waymo AV.",
          ("operating northbound", "going northbound", "en route northbound", "in motion northbound",
           "being driven northbound", "navigating northbound", "northbound", "cruising northbound",
           "headed northbound", "rolling northbound"),
          _ego, ("moving", "af")),
    Probe("a rider splitting lanes past the standing AV, no side named (session 18)",
          "The Waymo AV was stopped in traffic on northbound [XXX]. A motorcyclist {w} clipped the mirror of the "
          "Waymo AV.",
          ("splitting lanes", "that was lane splitting", "lane-splitting through traffic", "riding between the two "
           "lanes of traffic", "traveling between lanes", "filtering between the stopped cars", "riding on the lane "
           "line", "splitting traffic", "straddling the lane line", "white-lining between the cars"),
          _position, [("R6", "left")]),
    Probe("a party driving into an AV standing throughout, no part of the AV and no place told (session 18)",
          "The Waymo AV was stopped at a red light on northbound [XXX]. {W}.",
          ("a sedan was unable to stop in time and collided with the Waymo AV",
           "the driver of a sedan was distracted and struck the Waymo AV",
           "a pickup truck failed to stop and made contact with the Waymo AV",
           "a sedan did not stop and hit the Waymo AV", "an SUV collided with the Waymo AV",
           "a motorcyclist struck the Waymo AV", "a box truck bumped into the Waymo AV"),
          _position, [("R6", "same")]),
    Probe("a party standing at the curb that pulls out into the standing AV stays beside it (session 18)",
          "The Waymo AV was stopped at a red light on northbound [XXX]. A car {w} and struck the Waymo AV.",
          ("that was parked at the curb pulled out", "that was parked along the right curb pulled out",
           "parked at the curb pulled away", "that was stopped at the curb pulled out"),
          _position, [("R5", "right")]),
    Probe("a chain behind the standing AV, the striker named first (session 18)",
          "The Waymo AV was stopped in traffic. A sedan traveling at a high rate of speed {w} an SUV that was stopped "
          "behind the Waymo AV, and the SUV then struck the rear of the Waymo AV.",
          ("rear-ended", "struck", "struck the rear of", "hit the back of", "collided with", "made contact with the "
           "rear of", "impacted", "contacted"),
          lambda sk: [(p.position, p.lane) for p in sk.npcs], [("R6", "same"), ("R6", "same")]),
    Probe("a party going the other way in the lanes of the AV's direction, told by their heading (session 18)",
          "The Waymo AV was traveling westbound on [XXX] when a passenger car {w} made contact with the front of the "
          "Waymo AV.",
          ("traveling eastbound in the westbound lanes of [XXX]", "traveling east in the westbound lane",
           "heading eastbound within the westbound travel lane", "driving eastbound down the westbound lanes",
           "traveling eastbound in the westbound through lanes"),
          _position, [("R7", "same")]),
    Probe("a party behind moving over toward the AV's rear corner came from that side; moving out, from its lane "
          "(session 18)",
          "The Waymo AV was stopped at a red light on northbound [XXX]. A sedan approached from behind, {w}.",
          tuple(_REAR_CORNER_MOVES), _position, lambda w: [("R6", _REAR_CORNER_MOVES[w])]),
    Probe("the lane a party came out of is where it was, not the lanes it went through or into (session 19)",
          "The Waymo AV was traveling northbound on [XXX] in the center lane of three lanes. A passenger car "
          "traveling behind the Waymo AV {w}. The passenger car passed the Waymo AV in the leftmost lane and made "
          "contact with the driver side of the Waymo AV.",
          ("began to change lanes from the rightmost lane to the leftmost lane",
           "changed lanes from the right lane to the left lane", "moved from the right lane into the left lane",
           "merged from the rightmost lane into the leftmost lane", "crossed from the right lane to the left lane",
           "swerved from the right lane into the left lane",
           "was changing lanes from the rightmost lane toward the leftmost lane",
           "moved over from the right lane to the left lane", "veered from the rightmost lane into the leftmost lane",
           "cut across from the right lane to the left lane",
           "attempted a lane change from the right lane to the left lane",
           "made an abrupt lane change from the rightmost lane into the leftmost lane",
           "came from the right lane and moved into the left lane"),
          _position, [("R6", "right")]),
    Probe("the AV standing on one street approaching the cross street: a place, no move off (session 19)",
          "A Zoox vehicle in autonomy {w} on [XXX] approaching [XXX] in Las Vegas. A passenger car traveling behind "
          "the Zoox vehicle rear-ended the stopped Zoox vehicle.",
          ("was stopped behind traffic for a red traffic signal", "was stopped at a red light",
           "was stationary in the left turn lane", "was waiting at the red light",
           "was stopped in the left turn lane (lane 2) for a red traffic signal", "was idling in traffic",
           "remained stopped for the red signal", "was at a stop", "was stopped in a queue of traffic",
           "was sitting at a red light", "was stopped in traffic"),
          _ego, ("stopped", "")),
    _scenes("the collision party's place told as SGO and DMV narratives tell it: contact parts, lanes beside, "
            "oncoming, crossing, driveways, followed and following (session 19, 84 scenes, all read right when "
            "written)",
            _partner_position, _SESSION19_SCENES),
    Probe("an oncoming party turning off into a roadside place or crossing the median, the AV waiting for a junction: "
          "on the AV's own road, not the opposite approach (session 19)",
          "The Waymo AV was stopped in a queue of northbound traffic for a red light at the intersection with [XXX]. "
          "A passenger car traveling southbound on [XXX] {w} and made contact with the front of the Waymo AV.",
          ("made a left turn into a driveway", "turned left into a parking lot", "turned left into the entrance of a "
           "parking lot", "attempted to make a left turn across the Waymo AV's lane of travel to the entrance of a "
           "parking lot", "began a left turn toward a driveway", "turned left into a gas station",
           "made a left turn into an alley", "turned left into a parking garage", "crossed over the median",
           "swerved to the left, crossing the curbed median", "jumped the median", "drove across the center divider"),
          _position, [("R7", "left")]),
    Probe("'stopped' after an article or a preposition, before a traffic noun: what the AV went by (session 19)",
          "The Waymo AV was traveling southbound on [XXX] in the center lane, {w} in the leftmost lane, when a "
          "pedestrian stepped out from between the vehicles and crossed the path of the Waymo AV. The front of the "
          "Waymo AV made contact with the pedestrian.",
          ("passing a queue of stopped traffic", "passing a line of stopped cars", "going past stopped vehicles",
           "driving alongside stopped traffic", "passing stopped traffic", "overtaking a row of stopped cars",
           "moving past a line of stopped vehicles", "traveling beside stopped traffic", "passing the stopped traffic",
           "proceeding by stopped cars"),
          _ego, ("moving", "a")),
    Probe("a party on the compass side of the street opposite the AV's own is across the street, beyond the "
          "oncoming lane (session 19)",
          "The Waymo AV was parked at the curb facing eastbound on the south side of [XXX]. A pickup truck {w} and made "
          "contact with the driver side of the Waymo AV.",
          ("reversed out of a driveway on the north side of [XXX]", "backed out of a driveway on the north side of "
           "[XXX]", "reversed out of a driveway on the north side of the street", "pulled out of a parking space on "
           "the northern side of [XXX]", "backed out of a parking spot on the north curb of [XXX]",
           "was reversing out of a driveway on the north side of the road"),
          _position, [("R7", "left")]),
    Probe("an animal or a thing moving into the AV's path from one side is beside its lane on that side (session 19)",
          "The Waymo AV was traveling northbound on [XXX] when a dog {w}, and the front of the Waymo AV made contact "
          "with the dog.",
          tuple(_MOVING_THING_SIDES),
          lambda sk: [(o.position, o.lane) for o in sk.obstacles][:1], lambda w: [("R5", _MOVING_THING_SIDES[w])]),
    Probe("a barrier that closes the way (a gate, its arm, a barricade, a portable barrier) stands in the AV's lane; "
          "curbs and medians line the road (session 19)",
          "The Waymo AV was traveling northbound on [XXX] when the front of the Waymo AV made contact with {w}. The "
          "Waymo AV sustained damage.",
          ("a gate arm at the exit of a parking garage", "a construction barricade", "a portable metal barrier",
           "a parking lot gate", "a temporary barrier", "the gate of a parking lot", "a barricade",
           "a water-filled barrier"),
          lambda sk: [(o.category, o.position, o.lane) for o in sk.obstacles][:1], [("barrier", "R5", "same")]),
    # Session 20: a party backing out of a roadside place stood at the roadside beside the AV, not behind it, whatever
    # half of the AV's side it struck; no side named, the place lines the curb on the AV's right (relations.place).
    Probe("a party backing out of a roadside place struck the AV's rear door: beside it, on the curb side",
          "The Waymo AV was stopped on Mission Street for a passenger pickup when a sedan {w}. The rear of the sedan "
          "made contact with the rear passenger side door of the Waymo AV.",
          ("reversed out of a parking spot", "backed out of a parking space", "began reversing out of one of the "
           "parking stalls", "backed out of his parking space", "reversed out of a diagonal stall",
           "backed out of a parking bay", "reversed out of a driveway", "began backing out of a garage",
           "reversed out of her parking place", "backed out of one of the angled parking spaces"),
          _position, [("R5", "right")]),
    # Session 20: a party astride two lanes, one of them the AV's, is on the side of the other (relations.place).
    Probe("a party astride the AV's lane and the next passes the standing AV: behind it on the other lane's side",
          "The Waymo AV was stopped at a red light in the rightmost of two lanes on northbound Mission Street. A sedan "
          "traveling {w} approached the Waymo AV from behind. As the sedan was passing the stopped Waymo AV, the "
          "passenger side of the sedan made contact with the rear driver side of the Waymo AV.",
          ("partially in the rightmost lane and partially in the left lane", "straddling the lane line",
           "partly in the right lane and partly in the left-adjacent lane", "straddling two lanes",
           "half in the rightmost lane and half in the adjacent lane", "straddling the lanes",
           "partially in the rightmost lane and partially in the left-adjacent dedicated left turn lane",
           "partially in the Waymo AV's lane and partially in the lane to its left"),
          _position, [("R6", "left")]),
    # Session 20: "the adjacent lane" beside an AV in an edge lane is on its open side, also for a party told only
    # after the contact (relations.place).
    Probe("a party in the adjacent lane beside an AV in the right lane, told after the contact: on the AV's left",
          "The May vehicle was traveling in the right lane of a two-lane road when it made contact with the curb, "
          "causing a flat tire. The May vehicle chose to maneuver at the curb due to perceived risk from a car {w}.",
          _ADJACENT_NO_SIDE, _position, [("R5", "left")]),
    Probe("a party in the adjacent lane beside an AV in the leftmost lane, told after the contact: on the AV's right",
          "The May vehicle was traveling in the leftmost lane of a two-lane road when it made contact with the median "
          "curb, causing a flat tire. The May vehicle chose to maneuver at the curb due to perceived risk from a car "
          "{w}.",
          _ADJACENT_NO_SIDE, _position, [("R5", "right")]),
    # Session 20: lanes numbered from the left, the AV's own lane numbered in its clause ("(lane 2)"): a party's
    # numbered lane is read against that number (relations.av_lane_number).
    Probe("a party behind in a numbered lane, the AV's lane numbered in parentheses: lanes count from the left",
          "A Zoox vehicle (Vehicle 1) in autonomy was stopped for a red traffic signal in the right lane (lane 2) on "
          "northbound [XXX] in Las Vegas. A sedan (Vehicle 2) traveling northbound {w} struck the rear of the Zoox "
          "vehicle.",
          ("in lane 2", "in lane 1", "in lane 3", "in lane #1", "in lane number 3", "in lane two", "in lane one",
           "in lane three"),
          _position, lambda w: [("R6", _NUMBERED_SIDE[w.split()[-1].lstrip("#")])]),
    # Session 20: a party that struck the AV again is placed at its first contact, also where the opening sentence
    # alone tells that one (story.find_contact, relations._mention_windows).
    Probe("a party that struck the AV from behind, told in the opening sentence, then again as it passed: behind",
          "On July 14, 2021 at 4:47 PM PDT, a Waymo Autonomous Vehicle was proceeding straight westbound on Clement "
          "Street in San Francisco, when a passenger vehicle struck the Waymo AV from behind. The passenger vehicle "
          "then struck the Waymo AV {w}, on the left side of the Waymo AV, as it passed on the left, then fled the "
          "scene.",
          ("again", "a second time", "once more", "a third time"),
          _party, [("R6", "same", "a")]),
    # Session 20: a party behind that passes on a side no word names, with no lane change told, passed on the side
    # of the AV it struck (sketch.md; relations.place).
    Probe("a party behind the AV passing it on no named side, striking its rear passenger side: behind, on the right",
          "The Cruise AV was traveling eastbound on Sacramento Street at low speed. A Honda Accord traveling behind the "
          "Cruise AV {w} and made contact with the Cruise AV, damaging the rear passenger side bumper of the Cruise "
          "AV.",
          ("attempted to pass the Cruise AV", "passed the Cruise AV", "tried to overtake the Cruise AV",
           "began to pass the Cruise AV", "was passing the Cruise AV", "overtook the Cruise AV",
           "attempted to drive past the Cruise AV"),
          _party, [("R6", "right", "a")]),
    # Session 20: a party moving off from the curb or a space straight into a U-turn: its way out is the turn, no
    # lane change before it (extractor).
    Probe("a parked party pulling out straight into a U-turn ahead of the AV: `ij`, no lane change between",
          "A Zoox vehicle in autonomy was double parked on northbound Koval Lane. A passenger car which had been "
          "parallel parked in the adjacent right curb lane {w} ahead of the Zoox vehicle. During the maneuver, the "
          "rear door of the passenger car made contact with the front left fender of the Zoox vehicle.",
          ("pulled out of the parking spot and began attempting a multi-point U-turn",
           "pulled out of its parking space and made a U-turn", "pulled away from the curb and began a U-turn",
           "left its parking spot and attempted a U-turn", "pulled out from the curb and began to make a U-turn",
           "pulled out of the parking spot and began a three-point turn"),
          _npc_actions, [("stopped", "ij")]),
    # Session 20: a lane change from one outer lane of a three-lane road to the other is two changes (extractor).
    Probe("a party changing from the far left lane to the far right lane of three ahead of the AV: two changes",
          "The Waymo AV was traveling westbound on Winston Drive, a road of three lanes, in the far right lane. An SUV "
          "also proceeding westbound on Winston Drive {w} in front of the Waymo AV. The Waymo AV then made contact "
          "with the SUV.",
          ("made a continuous right lane change from the far left lane, through the middle lane, and entered the far "
           "right lane", "changed lanes from the leftmost lane to the rightmost lane",
           "merged from the left lane to the right lane", "made a lane change from the far left lane to the far right "
           "lane"),
          _npc_actions, [("moving", "agg")]),
    # Session 21: who counts and what the AV struck (extractor: lexicon.CONTACT, mentions.resolve, story).
    Probe("a party's move that ends in the AV, told by the move's verb and a particle, is the contact",
          "The Cruise AV was stopped at a pick-up location on Mission Street. A sedan parked ahead of the Cruise AV "
          "{w} the Cruise AV.",
          ("backed up into", "slowly backed up into", "reversed back into", "rolled backward into", "rolled back "
           "into", "backed into", "reversed into", "crept backward into", "rolled backwards into"),
          lambda sk: (sk.collision.with_, [p.category for p in sk.npcs]), ("npc1", ["car"])),
    Probe("a party behind the standing AV moving into a part of it is the contact",
          "The Cruise AV was stopped at a red light on Mission Street. A pickup truck stopped behind the Cruise AV "
          "then {w} the rear bumper of the Cruise AV.",
          ("slowly pushed into", "pushed into", "crept forward into", "inched forward into", "rolled forward into",
           "crept into", "rolled into", "moved forward into", "slid into"),
          lambda sk: (sk.collision.with_, sk.collision.type), ("npc1", "rear_end")),
    Probe("the AV crashing or running into an object is its contact with it",
          "A Zoox vehicle was traveling northbound on Koval Lane when the Zoox vehicle lost control, resulting in the "
          "Zoox vehicle {w} a light pole.",
          ("crashing into", "running into", "striking", "hitting", "colliding with", "making contact with",
           "slamming into", "smashing into", "plowing into"),
          lambda sk: ([o.category for o in sk.obstacles], sk.collision.with_, sk.collision.type),
          (["pole"], "obs1", "hit_object")),
    Probe("a door opened into the AV's path, its owner named between the door and the opening",
          "A Zoox vehicle was traveling northbound on Koval Lane when {w} and made contact with the Zoox vehicle.",
          ("the driver's side door of a stopped passenger vehicle in the right adjacent lane opened", "the rear door "
           "of a taxi stopped in the adjacent lane opened", "the driver side door of a parked car suddenly opened",
           "the passenger door of a parked SUV was opened", "the rear passenger door of a stopped rideshare vehicle "
           "opened"),
          lambda sk: ([o.category for o in sk.obstacles], [p.category for p in sk.npcs], sk.collision.with_),
          (["door"], [], "obs1")),
    Probe("a summary's ride and the telling's rider (or the reverse) are one party",
          "{w}",
          tuple(f"On May 1, 2024 at 4:12 PM PT a Waymo Autonomous Vehicle operating in San Francisco was in a "
                f"collision involving a {a}. The Waymo AV was stopped in traffic on eastbound Market Street. A {b} "
                f"then approached from behind the stopped Waymo AV. As the {b} passed, the {a} made contact with the "
                f"rear passenger side corner of the Waymo AV."
                for a, b in (("motorcycle", "motorcyclist"), ("motorcyclist", "motorcycle"), ("bicycle", "cyclist"),
                             ("bicyclist", "bicycle"), ("cyclist", "bicyclist"), ("scooter", "scooter rider"),
                             ("pedestrian", "man"), ("motorbike", "motorcyclist"), ("moped", "motorcyclist"))),
          lambda sk: (len(sk.npcs), sk.collision.with_), (1, "npc1")),
    Probe("what 'the other vehicle' struck after the AV is a third vehicle, not the other vehicle",
          "A Zoox vehicle was proceeding northbound on Koval Lane when a passenger vehicle in the right adjacent lane "
          "swerved into the Zoox vehicle's lane and made contact with its right side. {W}",
          ("the other vehicle also made contact with the vehicle in front of them after contacting the Zoox vehicle.",
           "the other vehicle also struck the car ahead of it.", "the other vehicle collided with the vehicle "
           "in front of it.", "the other car also hit the sedan ahead of it."),
          lambda sk: (len(sk.npcs), sk.collision.with_), (2, "npc1")),
    Probe("a vehicle that struck the object before the story takes no part",
          "A Waymo AV was traveling eastbound on Mission Street when it made contact with {w} and was lying in the "
          "roadway.",
          ("a small dog that had apparently been previously struck by a preceding vehicle", "a deer that had been "
           "struck by another vehicle", "a cat that had been hit by a passing car", "a dog which had earlier been "
           "struck by an unknown vehicle"),
          lambda sk: ([o.category for o in sk.obstacles], len(sk.npcs), sk.collision.with_), (["animal"], 0, "obs1")),
    Probe("a road-works machine is a truck",
          "A Waymo AV was stopped in a construction zone on Mission Street. {W} passing the Waymo AV made contact with "
          "its rear passenger side.",
          ("an asphalt roller vehicle", "an asphalt roller", "a road roller", "a steamroller", "a front-end loader",
           "a motor grader", "a construction vehicle", "a skid steer", "a paving machine", "an asphalt paver",
           "a crane"),
          lambda sk: [p.category for p in sk.npcs], ["truck"]),
    Probe("a truck's cab is part of the truck, no taxi",
          "An Aurora truck was traveling in the rightmost lane on Interstate 45 when a semi-truck in the adjacent left "
          "lane changed lanes to the right and made contact with {w}.",
          ("the driver side of the Aurora truck cab", "the Aurora truck's cab", "the left side of the Aurora truck's "
           "cab", "the driver side of the cab of the Aurora truck"),
          lambda sk: [p.category for p in sk.npcs], ["truck"]),
    Probe("a thing the AV struck that no word list names is an object ('other'), no empty report",
          "A Zoox vehicle was traveling northbound on Koval Lane when it {w}.",
          ("made contact with a vending machine", "struck a carport", "made contact with a hedge", "struck an EV "
           "charger", "made contact with a gas pump", "hit a kiosk", "struck a statue", "collided with a "
           "scaffold", "made contact with a set of tire spikes at the exit", "struck the awning of a building"),
          lambda sk: (len(sk.obstacles), sk.npcs, sk.collision.with_, sk.collision.type, sk.missing),
          (1, (), "obs1", "hit_object", ())),
    Probe("the ground the AV met is still contact with nothing",
          "A Zoox vehicle was traveling northbound on Koval Lane when it {w}.",
          ("struck the pavement", "ran over a pothole", "made contact with the raised pavement", "made contact with "
           "a speed bump", "scraped the road surface", "made contact with the ground"),
          lambda sk: (sk.obstacles, sk.npcs, sk.collision.with_, "npcs" in sk.missing), ((), (), None, True)),
    Probe("a thing thrown or flying at the AV: the collision is 'other', not hitting an object",
          "A Zoox vehicle was traveling northbound on Koval Lane when {w}.",
          ("its windshield was struck by a rock", "the front windshield was struck by an unknown object",
           "debris thrown from an overpass struck the Zoox vehicle", "a piece of debris flew into the windshield of "
           "the Zoox vehicle", "a nearby truck ran over road debris, which was projected onto the Zoox vehicle",
           "a rock kicked up by a truck ahead struck its windshield"),
          lambda sk: (sk.collision.with_[:3] if sk.collision.with_ else None, sk.collision.type), ("obs", "other")),
)


def run(probe: Probe) -> list[str]:
    """The wordings of `probe` not read as wanted, each with what was read."""
    misses = []
    for w in probe.wordings:
        sk = extract(probe.template.format(w=w, W=w[:1].upper() + w[1:]), "probe")
        want = probe.expected(w) if callable(probe.expected) else probe.expected
        got = probe.want(sk)
        if got != want:
            misses.append(f"{w!r}: read {got}, want {want}")
    return misses


def main() -> None:
    for probe in PROBES:
        misses = run(probe)
        print(f"{probe.name:<72} {len(probe.wordings) - len(misses):>3} / {len(probe.wordings)}")
        for m in misses:
            print("    miss:", m)


if __name__ == "__main__":
    main()
