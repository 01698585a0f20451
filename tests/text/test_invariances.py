"""What must not change a sketch (`tests/text/invariance.py`): every rewrite a new user's reports make without
changing the accident, on every studyable narrative, leaves the sketch as it was, but for the cases listed below
with the reason each still reads differently. On the session-9 start code 520 of 2,095 rewritten narratives read
differently (the AV taken for another party under a new operator's name in 99 of 130); now 10. Session 10 added
nine rewrites (manoeuvre, speed, clock, party and state paraphrases): 5 of the 243 narratives they change read
differently at first (a red light the AV was "stationary" at, a turn told as "making a right turn", "a person on
foot crossing the street" taken for the AV's crossing); now 1. Session 11 added 47 (the AV's part told the other way
round, lane and junction synonyms, "halted", "the left traffic lane", "going north", "gave way", "reduced speed",
"was impacted", "to the rear of", "a parallel-parked car", "a motorist", "continued", words reports use
interchangeably): 103 of their 1,321 rewritten narratives read differently on that session's start code (39a178f: those
spellings not read as their usual ones); now 2. Session 12 added 6 on the AV's own moves ("after having completed"
a turn, stop words, ", yielding" / "while yielding", "transitioned to manual mode", "Just as the AV", a driveway or
lot "turned into" and "parallel-parking"): 4 of their 67 rewritten narratives read differently on 746ca19, now 0;
and 2 more ("slowed to stop", a stop behind a standing vehicle told two ways): 4 of 9 then, now 0; and 3 more
("yielded to" -> "stopped for", "was stopped" -> "was waiting", "started accelerating/moving/proceeding"): 2 of 34
then (both "started accelerating"), now 0. Session 21 added 16 (NEW_REWRITES: the AV as "V1", "Vehicle 1", "the test
vehicle", "the SV"; "hit", "struck", "made contact with" for one another; speeds in words; "a car"; "N/B"; a party
numbered or described in parentheses; a sentence split at ", and"; the mode boilerplate moved to the end; "was
moving"): over all 602 studyable narratives (`python -m tests.text.invariance --all`) 23 of their 4,645 rewritten
narratives read differently on the session's start code (dbaa454); here, on the dev sample, the two listed."""

from __future__ import annotations

import pytest

from txt2sce_ros.text.extractor import extract

from .invariance import C4_REWRITES, NEW_REWRITES, REWRITES, Rewrite, changed

#: Rewritten narratives that still read differently, and why.
KNOWN: dict[str, set[str]] = {
    # A form-style NHTSA report ("Beep Event Level: 1 ... the Beep shuttle attendant ...") never introduces its AV
    # as a vehicle of its operator's: only the known name tells it apart.
    **{f"operator renamed: {n}": {"nhtsa-sgo-ads-30490-3168-v1"} for n in ("Acme", "Avride", "Oxa Robotics")},
    # "from the opposite direction ... collided with the front/left side corner": the corner's side is taken for
    # where the party came from (R1 instead of R2).
    "driver side -> left side": {"dmvca-zoox-20191122-r95"},
    # "the sport utility vehicle driver": "vehicle driver" reads as the AV's driver (10294); r256 reads the
    # renamed SUV as crossing from the left (R1 instead of R5/left), cause not found yet.
    "SUV -> sport utility vehicle": {"dmvca-waymo-20211204-r256", "nhtsa-sgo-ads-30610-10294-v1"},
    # "St." inside a sentence before a lower-case word: the clause reading around the turn changes.
    "Street -> St.": {"dmvca-cruise-20190905-r66", "dmvca-cruise-20230303-r431"},
    # A "when" clause made a sentence of its own: the party's manoeuvre is read against another sentence's AV.
    # (r202: the rewrite cuts the AV's own sentence, "... on Cabrillo Street and. Then the intersection was clear,
    # began to proceed westbound": the AV's heading is lost, and the cyclist that struck its rear driver's side is
    # read as behind it.)
    "', when a' -> '. Then a'": {"dmvca-cruise-20201024-r143", "dmvca-waymo-20240809-r603",
                                 "dmvca-waymo-20210801-r202"},
    # "a person on foot on a scooter ... the pedestrian": a rider named "person" first and "pedestrian" later is
    # read as two parties (the scooter's rider and a pedestrian).
    "a pedestrian -> a person on foot": {"dmvca-cruise-20230617-r484"},
    # "the front of the pickup truck made contact with the stopped Waymo AV's rear driver side and with the rear
    # driver side of another pickup truck": the contact is given to the second pickup (the last party named before
    # the verb's object), and once the AV's part is read it places that pickup behind the AV.
    "the <part> of the AV -> the AV's <part>": {"dmvca-waymo-20241014-r619"},
    # "EGO then continued to enter the rightmost lane": "continued to <verb>" is not read as "proceeded to <verb>"
    # (it may be "continued to brake"), so the AV's move-off before the lane change is lost.
    "proceeded -> continued": {"nhtsa-sgo-ads-30270-9606-v1"},
    # "stopped in the lane on the right of a three lane, one-way street": the AV's lane so told is not read as the
    # rightmost, so the party behind it that merges into the center lane is read as in the AV's lane (R6/same,
    # `if`: the gold reading) instead of on its left (R6/left, `ifg`).
    "in the <side> lane -> in the lane on the <side>": {"dmvca-waymo-20220206-r282"},
    # "a passenger car entered the center southeast lane from a driveway ... As the passenger car entered the center
    # southeast lane just in front of the pickup truck": the retelling reads as the car's lane change (`af`; the
    # gold `e`, the way out of the driveway); as "a motorist" the retelling's "the passenger car" is no longer tied
    # to it and the car keeps `a`. Both readings miss the gold.
    "a passenger vehicle -> a motorist": {"dmvca-waymo-20241014-r619"},
    # "swung wide ... while making a right turn" reads the turn under way (`e`, the gold); "while turning right" does
    # not (`ae`): the challenge set reads "traveling in the opposite direction ... lost control while turning left"
    # as a run, then the turn (`ad`), and the two are not yet told apart.
    "making a left turn -> turning left": {"dmvca-apple-20190919-r70"},
    # "seeing the vehicle approaching from the opposite direction crossing the centerline": the party's crossing of
    # the centre line is no longer read as a lane change when the participle follows a participle.
    "an oncoming <party> -> a <party> approaching from the opposite direction": {"dmvca-cruise-20201024-r143"},
    # "Cyclist 3 traveling behind the Cruise AV veered left to avoid another vehicle pulling out of a curbside
    # parking spot": the original places that other vehicle behind the AV only because the cyclist's "behind EGO"
    # falls in its window; with "following" it does not, and the vehicle is read ahead (R5/right; gold R6/right).
    "traveling behind the AV -> following the AV": {"dmvca-cruise-20220129-r278"},
    # "EGO, in autonomous mode, was stopped in the right lane of a three lane, one-way street": the AV's own lane is
    # read in its clause, which the aside's comma ends, so the lane is lost (the party then reads R6/same, as gold).
    "the Waymo AV -> the Waymo AV, in autonomous mode, (an aside after its name)": {"dmvca-waymo-20220206-r282"},
    # "... an SUV ... entered the far right lane in front of EGO. It was decelerating when EGOD transitioned": after
    # a sentence whose last subject is the SUV, the pronoun is the SUV's (the rewrite, not the reading, changes who).
    "The <operator> AV was (second sentence on) -> It was": {"dmvca-waymo-20211204-r256"},
    # "a pickup truck traveled southeast on El Camino Real": a party's heading told in the simple past is not read
    # (the heading pattern takes "traveling", "heading", not "traveled"), so the pickup that crossed the median from
    # the opposite direction is placed behind the AV (R6/same) instead of on the opposite approach (R2). A position
    # reading, left to the session's position work.
    "was traveling -> traveled (the simple past)": {"dmvca-waymo-20241014-r619"},
    # "a cyclist ... began turning right onto Cabrillo Street but immediately veered left": the cyclist is placed on
    # the road the AV exits onto (R4) instead of the crossing road to its left (R1; the gold); its actions (`aef`) and
    # the AV's are read the same. A position reading, left to the position work.
    "began to <move> -> began <moving>": {"dmvca-waymo-20210801-r202"},
    # (session 21) "a passenger car" -> "a car": the same report as above (a second pickup truck, a car entering
    # from a driveway told again as it enters the lane): the car's retelling is tied to it by its noun.
    "passenger car -> car": {"dmvca-waymo-20241014-r619"},
    # (session 21) a held-half report (not read): a party's description in parentheses changes its reading.
    "a party described in parentheses": {"dmvca-zoox-20220104-r267"},
}


@pytest.mark.parametrize("rw", REWRITES + NEW_REWRITES + C4_REWRITES,
                         ids=[r.name for r in REWRITES + NEW_REWRITES + C4_REWRITES])
def test_a_rewrite_leaves_the_sketch_as_it_was(rw: Rewrite) -> None:
    told, ids = changed(rw)
    assert told >= 4, "the rewrite no longer applies to the narratives"
    assert set(ids) <= KNOWN.get(rw.name, set()), ids


def test_a_new_operator_and_a_make_named_party() -> None:
    # The operator's name defines the AV; a make ("a Toyota vehicle") stays another party.
    sk = extract("On June 3, 2025 at 4:10 PM an Avride autonomous vehicle (\u201cAvride AV\u201d) was stopped at a "
                 "red light on Main Street when a Toyota vehicle behind the Avride AV made contact with the rear "
                 "bumper of the Avride AV.", "avride-1")
    assert (sk.ego.start, sk.ego.actions) == ("stopped", "")
    assert [(n.category, n.position, n.lane) for n in sk.npcs] == [("car", "R6", "same")]
    assert sk.collision.with_ == "npc1" and sk.collision.type == "rear_end"


@pytest.mark.parametrize("text,ego,party", [
    # Some companies tell the accident in the present tense.
    ("The Acme AV is stopped at a red light on Main Street. Shortly after, contact is made with the Acme AV's rear "
     "bumper by a sedan that is traveling behind it.", ("stopped", ""), ("car", "R6", "same", "moving", "a")),
    ("The AV is traveling northbound on Main Street in the right lane. A van traveling southbound enters the "
     "oncoming lane and makes contact with the front of the AV.", ("moving", "a"), ("van", "R7", "left", "moving", "af")),
])
def test_a_report_told_in_the_present_tense(text: str, ego: tuple, party: tuple) -> None:
    sk = extract(text, "present")
    assert (sk.ego.start, sk.ego.actions) == ego
    assert [(n.category, n.position, n.lane, n.start, n.actions) for n in sk.npcs] == [party]
    assert sk.collision.with_ == "npc1"
