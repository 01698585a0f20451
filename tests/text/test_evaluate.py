"""Slot-by-slot measuring (sketch.md, "Measuring an extractor") on the real gold sketches."""

from __future__ import annotations

from dataclasses import replace

from txt2sce_ros.paths import shared_dir
from txt2sce_ros.sketch import Sketch, load_sketches
from txt2sce_ros.text.evaluate import TABLE_IV, EXTRA, evaluate, format_table

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
