"""Issue 13: the scene-reading placement, the evidence map, the length bound, and the figures held on the study and
check sets (the check set is scored only: its sketches are never read to write rules)."""

from __future__ import annotations

import json
import re
from dataclasses import replace
from pathlib import Path

import pytest

from txt2sce_ros.errors import InputError
from txt2sce_ros.paths import shared_dir
from txt2sce_ros.sketch import Sketch, load_sketches, validate_sketch_dict
from txt2sce_ros.text.evaluate import conflict_exact, evaluate, evaluate_by_source, format_diagnostics
from txt2sce_ros.text.extractor import MAX_NARRATIVE_CHARS, extract
from txt2sce_ros.text.spans import OffsetMap

REPORTS = shared_dir() / "data" / "reports"

#: What the extractor reaches on each gold set (fractions), held so a change cannot quietly lose it. The check
#: set's floors are below the issue's targets: see the closing note; raise them as the extractor improves.
HELD = {
    "dev_gold": {"npc_quantity": 0.95, "npc_type": 0.95, "npc_position": 0.91, "npc_events": 0.95,
                 "obstacle_quantity": 0.95, "completeness": 0.95, "ego_start": 1.0, "ego_actions": 0.98,
                 "layout": 0.96, "signal_state": 0.98},
    "dev_gold_study": {"npc_quantity": 0.98, "npc_type": 0.95, "npc_position": 0.88, "npc_events": 0.90,
                       "obstacle_quantity": 0.99, "completeness": 0.97, "ego_start": 1.0, "ego_actions": 0.96,
                       "layout": 0.96, "signal_state": 0.95},
    # (dev_gold_check obstacle quantity 0.925 -> 0.90 in session 19: one report's door obstacle went with a rule the
    # studyable sets decide - the AV's own door named after a word of its state, and the door of a vehicle that moved
    # and did the touching, are no obstacle; door readings over the 461 studyable gold sketches 455 -> 458 of 461,
    # study4's held half among the gains; the check set was not inspected)
    "dev_gold_check": {"npc_quantity": 0.97, "npc_type": 0.97, "npc_position": 0.64, "npc_events": 0.80,
                       "obstacle_quantity": 0.90, "completeness": 0.97, "ego_start": 1.0, "ego_actions": 0.90},
}
#: The user's figure (complete reports whose conflict is reproduced exactly), held as a count per set.
# (dev_gold_check 16 -> 15 in session 15: one report's layout moved by the spec's own reading, an intersection the AV
# is approaching is a junction, which 10 of the 11 studyable reports with the words follow; the 11th is a driveway
# exit, read as such. The same rule raised check2 and check3 layout; the check set was scored only, never read.)
CONFLICT_HELD = {"dev_gold": 52, "dev_gold_study": 69, "dev_gold_check": 18}

#: The same for the 213 real narratives new in session 13 (tests/text/csvr/README.md): study2 may be read, check2 is
#: scored only. Both sets' gold is one annotator's.
CSVR = Path(__file__).parent / "csvr"
HELD_CSVR = {
    "study2": {"npc_quantity": 0.99, "npc_position": 0.97, "npc_events": 0.91, "layout": 0.96, "ego_actions": 0.94,
               "ego_start": 0.97, "signal_state": 0.93},
    # (check2 position 0.80 -> 0.79, conflict 55 -> 54 in session 15: one party moved by a rule its studyable gold
    # holds 7 of 7 - a party parallel parking ahead of or behind the AV is in its lane; check2 was not inspected)
    # (check2 position 0.80 -> 0.79 again in session 18, from 0.802 to 0.793: one party moved by a rule its studyable
    # gold holds 4 of 4, the official r519 among them - a party behind the standing AV, not "from behind", that passes
    # it on the left began in its lane, R6/same af; check2 was not inspected)
    "check2": {"npc_quantity": 0.97, "npc_position": 0.79, "npc_events": 0.78, "layout": 0.88, "ego_actions": 0.82,
               "ego_start": 0.92},
}
# (check2 59 -> 58 in session 22: a collision party that touched the AV backing up is read ahead or alongside it, not
# behind (R5, not R6), by a rule decided on the studyable sets alone - POOLED H +1 position and +1 user's figure,
# study5 H +1 each, no studyable set lower; check2 was not inspected; back at 59 by the session's end, held there)
CONFLICT_HELD_CSVR = {"study2": 86, "check2": 59}
#: And for the 220 NHTSA SGO narratives new in session 14 (tests/text/sgo/README.md): study3 may be read, check3 is
#: scored only; one annotator's gold each (check3's first 44 labelled twice and adjudicated).
SGO = Path(__file__).parent / "sgo"
HELD_SGO = {
    "study3": {"npc_quantity": 0.96, "npc_type": 0.95, "npc_position": 0.90, "npc_events": 0.87, "layout": 0.98,
               "ego_actions": 0.85, "ego_start": 0.96, "signal_state": 0.96},
    # (check3 position 0.65 -> 0.64, events 0.63 -> 0.62 in session 15: one party moved by a rule its studyable gold
    # holds 8 of 8 - a party stopped behind the AV that passes it began in the AV's lane; check3 was not inspected)
    # (check3 events 0.62 -> 0.61 in session 18, from 0.620 to 0.619: one party's string moved by a wording rule
    # that moved two studyable sketches, one to its gold - a lane entered by any name is a lane change, as "moved
    # into" it is; check3 was not inspected)
    "check3": {"npc_quantity": 0.89, "npc_position": 0.67, "npc_events": 0.62, "layout": 0.91, "ego_actions": 0.78,
               "ego_start": 0.95},
}
# (study3 91 -> 90 in session 19: the AV met by a party that moved in while it "remained stopped" after a stop is
# stopped with '' (sketch.md, the official convention study4's three annotators follow); study3's one annotator reads
# `ah` for 9408, whose test in test_av_run_and_stop now asserts the official reading; 94 at session 19's end)
CONFLICT_HELD_SGO = {"study3": 94, "check3": 44}
#: And for the 173 NHTSA SGO narratives new in session 19 (tests/text/sgo4/README.md), labelled before the extractor
#: was run on them: study4 may be read, check4 is scored only; one annotator's gold each.
SGO4 = Path(__file__).parent / "sgo4"
HELD_SGO4 = {
    "study4": {"npc_quantity": 0.97, "npc_type": 0.97, "npc_position": 0.79, "npc_events": 0.79, "layout": 0.91,
               "ego_actions": 0.81, "ego_start": 0.89, "signal_state": 0.85},
    "check4": {"npc_quantity": 0.92, "npc_position": 0.72, "npc_events": 0.68, "layout": 0.93, "ego_actions": 0.70,
               "ego_start": 0.85},
}
# (check4 ego_actions 0.71 -> 0.70 and ego_start 0.86 -> 0.85 in session 20, one report: the AV told standing on
# after its stop ("remained stopped", "continued to yield") when a follower struck it is `stopped` with '', as
# study5's gold reads both W-half reports so told and 6 of the 7 studyable reports with a stop, a follower and the
# AV standing on; sgo4's three annotators did not all read this convention the same way (sgo4/README.md). Decided
# on the studyable sets alone, as the session's hygiene rule asks.)
CONFLICT_HELD_SGO4 = {"study4": 47, "check4": 39}  # (session 22 end: held where reached)
#: And for the 144 NHTSA SGO narratives new at the end of session 19 (tests/text/sgo5/README.md), kept from everyone
#: who wrote rules that session: study5 may be read from session 20 on, check5 is scored only.
SGO5 = Path(__file__).parent / "sgo5"
HELD_SGO5 = {
    "study5": {"npc_quantity": 0.89, "npc_type": 0.89, "npc_position": 0.71, "npc_events": 0.61, "layout": 0.87,
               "ego_actions": 0.77, "ego_start": 0.94},
    "check5": {"npc_quantity": 0.89, "npc_position": 0.68, "npc_events": 0.63, "layout": 0.94, "ego_actions": 0.65,
               "ego_start": 0.83},
}
# (check5 npc_position 0.70 -> 0.68 and npc_events 0.65 -> 0.64 in session 22, helper C4: a party's number label
# opening a sentence ("... (Vehicle 2) ... . Vehicle 2 continued") is now read back as "The <noun>", a capital, where
# it was "the <noun>" and the sentence splitter joined it to the sentence before. Over the 602 studyable narratives
# the change moves no gold-scored slot and makes 9 -> 0 of 209 narratives (each of 4 numberings) read as the
# original (tests/text/invariance.py); check5's narratives are not read, so which of its readings leaned on the
# joined sentence is not known. Decided on the studyable sets alone, as the session's hygiene rule asks.)
# (check5 npc_events 0.64 -> 0.63 in session 22, helper C4, one party: "private vehicle" / "private car" made a
# passenger vehicle's names, generic as "passenger vehicle" is; over the 602 studyable narratives no gold-scored
# slot moves and 3 of 78 narratives with "passenger vehicle" told "private vehicle" read as their originals. Decided
# on the studyable sets alone, as above.)
CONFLICT_HELD_SGO5 = {"study5": 25, "check5": 33}
#: And for the 167 NHTSA SGO narratives new in session 20 (tests/text/sgo6/README.md), labelled before the extractor
#: was run on them and kept from everyone who wrote rules that session: study6 may be read from session 21 on,
#: check6 is scored only.
SGO6 = Path(__file__).parent / "sgo6"
HELD_SGO6 = {
    "study6": {"npc_quantity": 0.88, "npc_type": 0.81, "npc_position": 0.61, "npc_events": 0.51, "layout": 0.84,
               "ego_actions": 0.66, "ego_start": 0.88},
    "check6": {"npc_quantity": 0.87, "npc_position": 0.64, "npc_events": 0.63, "layout": 0.90, "ego_actions": 0.68,
               "ego_start": 0.89},
}
CONFLICT_HELD_SGO6 = {"study6": 34, "check6": 30}  # (session 22 end: held where reached)
NEW_SETS = {name: (CSVR, held, CONFLICT_HELD_CSVR[name]) for name, held in HELD_CSVR.items()} | {
    name: (SGO, held, CONFLICT_HELD_SGO[name]) for name, held in HELD_SGO.items()} | {
    name: (SGO4, held, CONFLICT_HELD_SGO4[name]) for name, held in HELD_SGO4.items()} | {
    name: (SGO5, held, CONFLICT_HELD_SGO5[name]) for name, held in HELD_SGO5.items()} | {
    name: (SGO6, held, CONFLICT_HELD_SGO6[name]) for name, held in HELD_SGO6.items()}


@pytest.fixture(scope="module")
def dev() -> dict[str, str]:
    rows = [json.loads(x) for x in (REPORTS / "dev.jsonl").read_text(encoding="utf-8").splitlines() if x.strip()]
    return {r["id"]: r["text"] for r in rows}


@pytest.fixture(scope="module")
def predicted(dev: dict[str, str]) -> dict[str, Sketch]:
    return {rid: extract(text, rid) for rid, text in dev.items()}


@pytest.mark.parametrize("name", sorted(HELD))
def test_figures_hold_on_every_gold_set(name: str, predicted: dict[str, Sketch]) -> None:
    gold = [s for s in load_sketches(REPORTS / f"{name}.jsonl") if isinstance(s, Sketch)]
    ev = evaluate(gold, predicted)
    below = {k: round(ev.accuracy(k), 3) for k, v in HELD[name].items() if ev.accuracy(k) < v}
    assert not below, f"{name}: below what was reached: {below}"


@pytest.mark.parametrize("name", sorted(CONFLICT_HELD))
def test_the_users_figure_holds_on_every_gold_set(name: str, predicted: dict[str, Sketch]) -> None:
    gold = [s for s in load_sketches(REPORTS / f"{name}.jsonl") if isinstance(s, Sketch)]
    ev = evaluate(gold, predicted)
    assert len(ev.conflict_ok) >= CONFLICT_HELD[name], f"{name}: {len(ev.conflict_ok)}/{len(ev.complete)}"


@pytest.mark.parametrize("name", sorted(NEW_SETS))
def test_figures_hold_on_the_new_real_narratives(name: str) -> None:
    folder, held, conflicts = NEW_SETS[name]
    rows = [json.loads(x) for x in (folder / f"{name}.jsonl").read_text(encoding="utf-8").splitlines() if x.strip()]
    predicted = {r["id"]: extract(r["text"], r["id"]) for r in rows}
    gold = [s for s in load_sketches(folder / f"{name}_gold.jsonl") if isinstance(s, Sketch)]
    assert [g.report_id for g in gold] == [r["id"] for r in rows]
    ev = evaluate(gold, predicted)
    below = {k: round(ev.accuracy(k), 3) for k, v in held.items() if ev.accuracy(k) < v}
    assert not below, f"{name}: below what was reached: {below}"
    assert len(ev.conflict_ok) >= conflicts, f"{name}: {len(ev.conflict_ok)}/{len(ev.complete)}"


def test_diagnostics_name_the_users_figure_and_the_confusions(predicted: dict[str, Sketch]) -> None:
    gold = [s for s in load_sketches(REPORTS / "dev_gold_study.jsonl") if isinstance(s, Sketch)]
    ev = evaluate(gold, predicted)
    text = format_diagnostics(ev, evaluate_by_source(gold, predicted))
    assert f"{len(ev.conflict_ok)}/{len(ev.complete)} complete reports" in text
    assert "Position confusion" in text and "dmvca" in text and "nhtsa" in text
    assert len(ev.complete) == sum(1 for g in gold if not g.missing)
    # Every complete report is counted once: reproduced, over-refused, or neither.
    assert len(ev.conflict_ok) + len(ev.over_refused) <= len(ev.complete)


def test_conflict_needs_the_collision_party_exactly() -> None:
    gold = [s for s in load_sketches(REPORTS / "dev_gold.jsonl") if isinstance(s, Sketch)]
    g = next(s for s in gold if s.collision.with_ and s.collision.with_.startswith("npc") and s.npcs[0].lane)
    assert conflict_exact(g, g)
    other = {"left": "right", "right": "left", "same": "left"}[g.npcs[0].lane]
    moved = replace(g, npcs=(replace(g.npcs[0], lane=other), *g.npcs[1:]))
    if g.collision.with_ == "npc1":
        assert not conflict_exact(g, moved)
    assert not conflict_exact(g, replace(g, ego=replace(g.ego, actions=g.ego.actions + "h")))


def test_evidence_points_at_the_narrative(dev: dict[str, str], predicted: dict[str, Sketch]) -> None:
    head = re.compile(r"[a-z]{3,}", re.I)
    with_party = 0
    for rid, sk in predicted.items():
        text = dev[rid]
        assert validate_sketch_dict(sk.to_dict()) == [], rid
        assert Sketch.from_dict(sk.to_dict()).evidence == sk.evidence  # survives the JSON round trip
        for slot, spans in sk.evidence:
            for a, b in spans:
                assert 0 <= a < b <= len(text), (rid, slot)
        for k, party in enumerate(sk.npcs):
            spans = sk.evidence_for(f"npcs[{k}].category")
            assert spans, (rid, k)
            named = " ".join(text[a:b] for a, b in spans)
            assert head.search(named) and "EGO" not in named, (rid, named)
            assert sk.evidence_for(f"npcs[{k}].position"), (rid, k)
            with_party += 1
    assert with_party > 150


def test_offset_map_survives_the_normaliser() -> None:
    original = 'A Waymo Autonomous Vehicle (“Waymo AV”)   was struck  by a white  minivan (Vehicle 2).'
    normalised = "EGO was struck by a white minivan."
    omap = OffsetMap(original, normalised)
    a = normalised.index("white minivan")
    span = omap.to_original(a, a + len("white minivan"))
    assert span is not None and original[span[0]:span[1]] == "white  minivan"
    ego = omap.to_original(0, 3)
    assert ego is not None and "Waymo" in original[ego[0]:ego[1]]


def test_over_long_narrative_is_refused_clearly() -> None:
    with pytest.raises(InputError, match="over the limit"):
        extract("The AV was struck by a car. " * (MAX_NARRATIVE_CHARS // 20), "long")
    # Just under the limit it is read (linear time; `txt2sce bench extract` prints the per-character cost).
    sk = extract(("The AV was traveling north when a car struck its rear bumper. " * 2000)[:MAX_NARRATIVE_CHARS // 4],
                 "long-ok")
    assert sk.npcs


@pytest.mark.parametrize("part, move, where", [
    ("rear quarter panel", "moved into the AV's lane", ("R6", "right")),  # its tail: it came from behind
    ("rear bumper", "moved into the AV's lane", ("R6", "right")),
    ("rear passenger door", "moved into the AV's lane", ("R5", "right")),  # the middle of the side: level with it
    ("front passenger side", "moved into the AV's lane", ("R5", "right")),
    ("rear quarter panel", "reversed", ("R5", "right")),  # backing up from level meets the AV's rear half
])
def test_contact_on_the_av_s_rear_half_puts_a_next_lane_party_behind(part: str, move: str,
                                                                     where: tuple[str, str]) -> None:
    text = (f"A Zoox vehicle was traveling eastbound on Harrison Street in the left lane. A sedan traveling "
            f"eastbound in the right lane {move} and made contact with the Zoox vehicle's {part}.")
    p = extract(text, "t").npcs[0]
    assert (p.position, p.lane) == where


@pytest.mark.parametrize("party, where", [
    ("A sedan going the other way", ("R7", "left")),
    ("A sedan traveling toward the Zoox vehicle", ("R7", "left")),
    ("A sedan heading toward the Zoox vehicle", ("R7", "left")),
    ("A pedestrian heading toward the Zoox vehicle", ("R5", "right")),  # on foot: from the curb, not oncoming
])
def test_a_party_running_at_the_av_head_on_is_oncoming(party: str, where: tuple[str, str]) -> None:
    text = (f"A Zoox vehicle was traveling northbound on Koval Lane. {party} crossed the center line and struck the "
            f"front of the Zoox vehicle.")
    p = extract(text, "t").npcs[0]
    assert (p.position, p.lane) == where


def test_a_bare_compass_origin_at_a_junction_places_a_crossing_party() -> None:
    text = ("A Zoox vehicle was traveling northbound on Koval Lane and entered the intersection with Flamingo Road on "
            "a green light. A sedan traveling on Flamingo Road from the west ran the red light and struck the driver "
            "side of the Zoox vehicle.")
    assert extract(text, "t").npcs[0].position == "R1"
