"""Wording probes: one slot at a time, many wordings of the same fact in one fixed sentence, the reading that must come
out. Where the invariance tool (`invariance.py`) rewrites real narratives, a probe asks for the wordings real
narratives happen not to use, so a gap shows before a user's report meets it. Session 10 wrote the sets below; on
that session's start code (2e462c3) 17 of 26 lane changes, 13 of 13 parties behind, 9 of 12 passing the standing AV
on its left, 5 of 10 standing ahead that the AV runs into, 7 of 10 oncoming, 8 of 9 opposite-approach left turns and
7 of 8 crossing parties, 6 of 8 pedestrians on the turning AV's exit leg and 3 of 5 mid-block, 6 of 8 parked cars
pulling out, 5 of 6 weather wordings, 14 of 15 road layouts, 6 of 8 lights, 7 of 12 stops, 11 of 12 starts, 12 of 16
lane changes of the AV, 11 of 14 turns, 15 of 15 names of the AV, 0 of 4 contacts told with a pronoun for the AV, 19
of 23 contact verbs, 21 of 23 objects struck and 49 of 56 party nouns came out right (251 of 313); now all of them
(`test_probes.py` holds that).

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


def _position(sk: Sketch) -> object:
    return [(p.position, p.lane) for p in sk.npcs][:1]


_CATEGORIES = {
    "car": ("sedan", "hatchback", "coupe", "SUV", "pickup truck", "taxi", "cab", "Tesla", "police car", "convertible",
            "limousine", "minicab", "jeep", "crossover", "passenger car"),
    "van": ("minivan", "delivery van", "cargo van", "Sprinter van", "panel van"),
    "truck": ("box truck", "tractor-trailer", "semi-truck", "dump truck", "garbage truck", "tow truck", "fire truck",
              "cement mixer", "big rig", "18-wheeler", "delivery truck"),
    "bus": ("city bus", "Muni bus", "school bus", "shuttle bus", "coach"),
    "motorcycle": ("motorcyclist", "moped", "motor scooter", "dirt bike", "motorbike"),
    "bicycle": ("cyclist", "bicyclist", "bike rider", "e-bike rider"),
    "scooter": ("scooter rider", "e-scooter rider", "skateboarder", "scooterist"),
    "pedestrian": ("pedestrian", "jogger", "man", "woman", "child", "person", "runner"),
}

PROBES: tuple[Probe, ...] = (
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
