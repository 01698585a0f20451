"""Derivation analysis: a failing node whose parent passed points at the block its derivation added.

In the scenario tree each child adds exactly one block (original or mutated) to its parent, so when the parent
ran clean and the child shows a category, the added block — its kind, the operator that made it and the values
it changed — is the trigger candidate for that category. Aggregated over a campaign, this says which kinds of
block and which operators most often flip a run from pass to fail.
"""

from __future__ import annotations

from collections import Counter, defaultdict
from dataclasses import dataclass
from typing import Any, Iterable, Mapping


@dataclass(frozen=True)
class TriggerCandidate:
    node: str
    parent: str
    category: str
    block: str          # e.g. 'npc:npc2', 'weather', 'event:npc1_e2_turn_left'
    operator: str       # e.g. 'WM', 'TSM', 'original'
    changes: tuple[str, ...]


def trigger_candidates(nodes: Mapping[str, Mapping[str, Any]], results: Mapping[str, tuple[str, tuple[str, ...]]]
                       ) -> list[TriggerCandidate]:
    """`nodes`: tree manifest entries by node id (parent, block, operator, changes); `results`: node id ->
    (verdict, categories). Categories the parent already showed are not new, so not attributed."""
    out = []
    for nid, (verdict, cats) in sorted(results.items()):
        node = nodes.get(nid)
        if node is None or verdict != "fail":
            continue
        parent = node.get("parent")
        if not parent or parent not in results:
            continue
        p_verdict, p_cats = results[parent]
        if p_verdict == "error":
            continue
        new = sorted(set(cats) - set(p_cats if p_verdict == "fail" else ()))
        for cat in new:
            out.append(TriggerCandidate(
                node=nid, parent=parent, category=cat, block=str(node.get("block", "")),
                operator=str(node.get("operator", "")),
                changes=tuple(_change_text(c) for c in node.get("changes", ())),
            ))
    return out


def _change_text(change: Any) -> str:
    if isinstance(change, Mapping):
        return f"{change.get('path', '')}: {change.get('old')} -> {change.get('new')}"
    return str(change)


def aggregate(cands: Iterable[TriggerCandidate]) -> dict[str, list[tuple[str, int]]]:
    """Per category: (block kind / operator, count), most frequent first."""
    per: dict[str, Counter[str]] = defaultdict(Counter)
    for c in cands:
        kind = c.block.split(":", 1)[0]
        per[c.category][f"{kind} / {c.operator}"] += 1
    return {cat: sorted(cnt.items(), key=lambda kv: (-kv[1], kv[0])) for cat, cnt in sorted(per.items())}
