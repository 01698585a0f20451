"""Slot-by-slot measuring (sketch.md, "Measuring an extractor") on the real gold sketches."""

from __future__ import annotations

from dataclasses import replace

from txt2sce_ros.paths import shared_dir
from txt2sce_ros.sketch import Sketch, load_sketches
from txt2sce_ros.text.evaluate import (EXTRA, TABLE_IV, conflict_misses, evaluate, format_diagnostics,
                                     format_table)

GOLD = [s for s in load_sketches(shared_dir() / "data" / "reports" / "dev_gold.jsonl") if isinstance(s, Sketch)]


def test_gold_against_itself_is_perfect() -> None:
    ev = evaluate(GOLD, {g.report_id: g for g in GOLD})
    for slot in (*TABLE_IV, *EXTRA):
        assert ev.slots[slot].accuracy == 1.0, slot
    assert ev.slots["npc_type"].total == sum(len(g.npcs) for g in GOLD)


def test_unpaired_npc_counts_wrong_in_every_npc_slot() -> None:
    two = next(g for g in GOLD if len(g.npcs) == 2)
    keep = next(n for n in two.npcs if n.id == two.collision.with_)
    pred = replace(two, npcs=(replace(keep, id="npc1"),), collision=replace(two.collision, with_="npc1"))
    ev = evaluate([two], {two.report_id: pred})
    assert ev.slots["npc_quantity"].correct == 0
    for slot in ("npc_type", "npc_position", "npc_events"):
        assert (ev.slots[slot].correct, ev.slots[slot].total) == (1, 2), slot
    assert ev.slots["collision_with"].correct == 1  # paired through the renumbering


def test_swapped_ids_are_paired_by_content() -> None:
    two = next(g for g in GOLD if len(g.npcs) == 2 and g.npcs[0].category != g.npcs[1].category)
    a, b = two.npcs
    pred = replace(two, npcs=(replace(b, id="npc1"), replace(a, id="npc2")),
                   collision=replace(two.collision, with_={"npc1": "npc2", "npc2": "npc1"}.get(
                       two.collision.with_ or "", two.collision.with_)))
    ev = evaluate([two], {two.report_id: pred})
    assert all(ev.slots[s].accuracy == 1.0 for s in ("npc_type", "npc_position", "npc_events", "collision_with"))


def test_missing_prediction_scores_as_empty_and_is_listed() -> None:
    ev = evaluate(GOLD[:3], {})
    assert ev.unmatched_gold == [g.report_id for g in GOLD[:3]]
    assert "without a prediction" in format_table(ev)


def test_a_failed_conflict_is_counted_by_the_parts_it_misses() -> None:
    # One gold report with an NPC partner, read back with the partner's lane and the AV's actions wrong.
    g = next(x for x in GOLD if not x.missing and x.collision.with_ and x.collision.with_.startswith("npc")
             and x.party(x.collision.with_).lane in ("left", "right"))
    partner = g.party(g.collision.with_)
    flipped = {"left": "right", "right": "left"}[partner.lane]
    pred = replace(g, npcs=tuple(replace(n, lane=flipped) if n.id == partner.id else n for n in g.npcs),
                   ego=replace(g.ego, actions=g.ego.actions + "h"))
    assert conflict_misses(g, g) == []
    assert conflict_misses(g, pred) == ["AV actions", "collision party lane"]
    ev = evaluate([g], {g.report_id: pred})
    assert ev.conflict_ok == [] and ev.conflict_missed == {"AV actions": 1, "collision party lane": 1}
    assert "missed parts (a report can miss several): AV actions 1, collision party lane 1" in format_diagnostics(ev)
