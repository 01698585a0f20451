"""Slot-by-slot comparison of predicted sketches with gold ones (the paper's Table IV, measured as sketch.md says).

Pairing: the collision parties are paired first (when both sides name an NPC), then the remaining NPCs are paired to
maximise agreement (category, then position). An NPC left unpaired on either side counts wrong in every per-NPC
slot, so the per-NPC denominators are `max(len(gold), len(pred))` summed over reports.
"""

from __future__ import annotations

import itertools
from collections import Counter, defaultdict
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field

from ..sketch import LANED_POSITIONS, Obstacle, Party, Sketch

#: Table IV rows, then the extra slots, in print order.
TABLE_IV = ("npc_quantity", "npc_type", "npc_position", "npc_events",
            "obstacle_quantity", "obstacle_type", "obstacle_position")
EXTRA = ("weather", "lighting", "surface", "layout", "control", "one_way", "lanes", "signal_state",
         "ego_start", "ego_actions", "collision_type", "collision_with", "completeness")

#: The floors every gold set is held to (issue 13; fractions): `eval-extract` marks a slot below its floor.
TARGETS: dict[str, float] = {"npc_quantity": 0.95, "npc_type": 0.95, "npc_position": 0.85, "npc_events": 0.85,
                             "obstacle_quantity": 0.95, "completeness": 0.95}


@dataclass
class SlotTally:
    correct: int = 0
    total: int = 0
    # (gold value, predicted value, report id) for each miss: the confusion listing.
    misses: list[tuple[str, str, str]] = field(default_factory=list)

    @property
    def accuracy(self) -> float:
        return self.correct / self.total if self.total else float("nan")

    def add(self, ok: bool, gold: object, pred: object, rid: str) -> None:
        self.total += 1
        if ok:
            self.correct += 1
        else:
            self.misses.append((str(gold), str(pred), rid))


@dataclass
class Evaluation:
    slots: dict[str, SlotTally] = field(default_factory=lambda: defaultdict(SlotTally))
    reports: int = 0
    unmatched_gold: list[str] = field(default_factory=list)  # gold ids with no prediction (an error record)
    #: (gold, predicted) position-with-lane of every paired or unpaired NPC ("-" for no partner): the confusion.
    positions: list[tuple[str, str]] = field(default_factory=list)
    #: Complete gold reports (empty `missing`) and those whose conflict a seed would reproduce (`conflict_exact`).
    complete: list[str] = field(default_factory=list)
    conflict_ok: list[str] = field(default_factory=list)
    #: For each complete report whose conflict is not reproduced: the parts it misses (`conflict_misses`).
    conflict_missed: Counter[str] = field(default_factory=Counter)
    over_refused: list[str] = field(default_factory=list)  # complete in gold, `missing` in the prediction
    under_refused: list[str] = field(default_factory=list)  # incomplete in gold, buildable in the prediction

    def accuracy(self, slot: str) -> float:
        return self.slots[slot].accuracy

    @property
    def conflict_rate(self) -> float:
        """The user's figure: complete reports whose sketch reproduces the reported conflict exactly."""
        return len(self.conflict_ok) / len(self.complete) if self.complete else float("nan")


def _pos(p: Party | Obstacle) -> str:
    return f"{p.position}/{p.lane}" if p.position in LANED_POSITIONS or isinstance(p, Obstacle) else p.position


def _pair_score(g: Party | Obstacle, p: Party | Obstacle) -> int:
    return 4 * (g.category == p.category) + 2 * (_pos(g) == _pos(p)) + (getattr(g, "actions", None)
                                                                       == getattr(p, "actions", None))


def pair(gold: Sequence[Party | Obstacle], pred: Sequence[Party | Obstacle],
         fixed: tuple[str, str] | None = None) -> list[tuple[Party | Obstacle | None, Party | Obstacle | None]]:
    """Pairs (gold, pred), None where one side has no partner; `fixed` = (gold id, pred id) paired first."""
    pairs: list[tuple[Party | Obstacle | None, Party | Obstacle | None]] = []
    g_left, p_left = list(gold), list(pred)
    if fixed:
        g0 = next((x for x in g_left if x.id == fixed[0]), None)
        p0 = next((x for x in p_left if x.id == fixed[1]), None)
        if g0 is not None and p0 is not None:
            pairs.append((g0, p0))
            g_left.remove(g0)
            p_left.remove(p0)
    # Exhaustive search is fine: narratives name at most a handful of parties.
    best: tuple[int, list[tuple[int, int]]] = (-1, [])
    small, large = (g_left, p_left) if len(g_left) <= len(p_left) else (p_left, g_left)
    for perm in itertools.permutations(range(len(large)), len(small)):
        idx = list(enumerate(perm))
        score = sum(_pair_score(small[i], large[j]) for i, j in idx)
        if score > best[0]:
            best = (score, idx)
    used_large = set()
    for i, j in best[1]:
        used_large.add(j)
        pairs.append((small[i], large[j]) if small is g_left else (large[j], small[i]))
    for j, x in enumerate(large):
        if j not in used_large:
            pairs.append((x, None) if large is g_left else (None, x))
    return pairs


def paired_npcs(gold: Sketch, pred: Sketch) -> list[tuple[Party | None, Party | None]]:
    """The NPC pairs a comparison scores: the two collision parties first (when both are NPCs), then the rest."""
    gw, pw = gold.collision.with_, pred.collision.with_
    fixed = (gw, pw) if gw and pw and gw[:3] == pw[:3] == "npc" else None
    return pair(gold.npcs, pred.npcs, fixed)  # type: ignore[return-value]


def compare(gold: Sketch, pred: Sketch, ev: Evaluation) -> None:
    """Add one report's slots to `ev`."""
    rid = gold.report_id
    ev.reports += 1
    s = ev.slots
    s["npc_quantity"].add(len(gold.npcs) == len(pred.npcs), len(gold.npcs), len(pred.npcs), rid)
    gw, pw = gold.collision.with_, pred.collision.with_
    npc_pairs = paired_npcs(gold, pred)
    mapping: dict[str, str] = {}
    for g, p in npc_pairs:
        if g is not None and p is not None:
            mapping[p.id] = g.id
        gc, pc = (g.category if g else "-"), (p.category if p else "-")
        s["npc_type"].add(g is not None and p is not None and gc == pc, gc, pc, rid)
        gp, pp = (_pos(g) if g else "-"), (_pos(p) if p else "-")
        s["npc_position"].add(g is not None and p is not None and gp == pp, gp, pp, rid)
        ga = getattr(g, "actions", "-") if g else "-"
        pa = getattr(p, "actions", "-") if p else "-"
        s["npc_events"].add(g is not None and p is not None and ga == pa, ga or "''", pa or "''", rid)
    s["obstacle_quantity"].add(len(gold.obstacles) == len(pred.obstacles), len(gold.obstacles),
                               len(pred.obstacles), rid)
    fixed_o = (gw, pw) if gw and pw and gw[:3] == pw[:3] == "obs" else None
    for g, p in pair(gold.obstacles, pred.obstacles, fixed_o):
        if g is not None and p is not None:
            mapping[p.id] = g.id
        gc, pc = (g.category if g else "-"), (p.category if p else "-")
        s["obstacle_type"].add(g is not None and p is not None and gc == pc, gc, pc, rid)
        gp, pp = (_pos(g) if g else "-"), (_pos(p) if p else "-")
        s["obstacle_position"].add(g is not None and p is not None and gp == pp, gp, pp, rid)
    for name, gv, pv in (
        ("weather", gold.environment.weather, pred.environment.weather),
        ("lighting", gold.environment.lighting, pred.environment.lighting),
        ("surface", gold.environment.surface, pred.environment.surface),
        ("layout", gold.road.layout, pred.road.layout),
        ("control", gold.road.control, pred.road.control),
        ("one_way", gold.road.one_way, pred.road.one_way),
        ("lanes", gold.road.lanes, pred.road.lanes),
        ("signal_state", gold.signal_state, pred.signal_state),
        ("ego_start", gold.ego.start, pred.ego.start),
        ("ego_actions", gold.ego.actions or "''", pred.ego.actions or "''"),
        ("collision_type", gold.collision.type, pred.collision.type),
        ("collision_with", gw, mapping.get(pw, pw) if pw else None),
    ):
        s[name].add(gv == pv, gv, pv, rid)
    s["completeness"].add(bool(gold.missing) == bool(pred.missing), sorted(gold.missing) or "[]",
                          sorted(pred.missing) or "[]", rid)
    ev.positions += [((_pos(g) if g else "-"), (_pos(p) if p else "-")) for g, p in npc_pairs]
    if not gold.missing:
        ev.complete.append(rid)
        if pred.missing:
            ev.over_refused.append(rid)
        elif conflict_exact(gold, pred):
            ev.conflict_ok.append(rid)
        else:
            ev.conflict_missed.update(conflict_misses(gold, pred))
    elif not pred.missing:
        ev.under_refused.append(rid)


def _party_key(p: Party | Obstacle | None) -> tuple[object, ...] | None:
    if p is None:
        return None
    return (p.category, p.position, p.lane, getattr(p, "actions", None))


def conflict_misses(gold: Sketch, pred: Sketch) -> list[str]:
    """The parts of the conflict the prediction gets wrong (empty when `conflict_exact`): where a report fails."""
    out = [name for name, g, p in (("AV start", gold.ego.start, pred.ego.start),
                                   ("AV actions", gold.ego.actions, pred.ego.actions),
                                   ("layout", gold.road.layout, pred.road.layout)) if g != p]
    gw, pw = gold.collision.with_, pred.collision.with_
    gp, pp = (gold.party(gw) if gw else None), (pred.party(pw) if pw else None)
    if (gp is None) != (pp is None) or (gp is not None and pp is not None and type(gp) is not type(pp)):
        out.append("collision party: none, or an NPC for an obstacle")
    elif gp is not None and pp is not None:
        out += [f"collision party {name}" for name, g, p in (
            ("category", gp.category, pp.category), ("position", gp.position, pp.position),
            ("lane", gp.lane, pp.lane), ("actions", getattr(gp, "actions", None), getattr(pp, "actions", None)))
            if g != p]
    return out


def conflict_exact(gold: Sketch, pred: Sketch) -> bool:
    """Does the prediction give the conflict a seed is built to reproduce: the AV's collision party exactly
    (category, position, lane, actions), the AV's start and actions, and the road layout?"""
    if (gold.ego.start, gold.ego.actions, gold.road.layout) != (pred.ego.start, pred.ego.actions, pred.road.layout):
        return False
    gw, pw = gold.collision.with_, pred.collision.with_
    if gw is None or pw is None:
        return gw is None and pw is None
    return _party_key(gold.party(gw)) == _party_key(pred.party(pw))


def evaluate(gold: Iterable[Sketch], predicted: dict[str, Sketch]) -> Evaluation:
    """Compare every gold sketch with the prediction of the same report id (a missing prediction scores as an
    empty sketch, so errors cost accuracy rather than vanish from the denominator)."""
    ev = Evaluation()
    for g in gold:
        p = predicted.get(g.report_id)
        if p is None:
            ev.unmatched_gold.append(g.report_id)
            p = Sketch(report_id=g.report_id, missing=("npcs",))
        compare(g, p, ev)
    return ev


def evaluate_by_source(gold: Iterable[Sketch], predicted: dict[str, Sketch]) -> dict[str, Evaluation]:
    """One evaluation per report source (the id's prefix: `dmvca`, `nhtsa`, ...)."""
    groups: dict[str, list[Sketch]] = defaultdict(list)
    for g in gold:
        groups[g.report_id.split("-", 1)[0]].append(g)
    return {src: evaluate(gs, predicted) for src, gs in sorted(groups.items())}


def format_diagnostics(ev: Evaluation, by_source: dict[str, Evaluation] | None = None, *, top: int = 12) -> str:
    """Where the extractor fails: the user's figure, refusals, the position confusion table, the most frequent
    action-string errors, and the main slots per source."""
    lines = [f"Conflict reproduced exactly (collision party category/position/lane/actions + AV start/actions + "
             f"layout): {len(ev.conflict_ok)}/{len(ev.complete)} complete reports = {ev.conflict_rate:.1%}",
             "  missed parts (a report can miss several): "
             + (", ".join(f"{k} {n}" for k, n in sorted(ev.conflict_missed.items(), key=lambda kv: (-kv[1], kv[0])))
                or "none"),
             f"Over-refusals (complete in gold, `missing` predicted): {len(ev.over_refused)}"
             + (f"  {', '.join(ev.over_refused[:6])}" if ev.over_refused else ""),
             f"Under-refusals (incomplete in gold, predicted buildable): {len(ev.under_refused)}"
             + (f"  {', '.join(ev.under_refused[:6])}" if ev.under_refused else ""), ""]
    labels = sorted({x for pair_ in ev.positions for x in pair_}, key=lambda v: (v == "-", v))
    conf = Counter(ev.positions)
    width = max(7, *(len(x) + 1 for x in labels)) if labels else 7
    lines.append("Position confusion (rows gold, columns predicted; '-' = no partner)")
    lines.append(" " * width + "".join(f"{x:>{width}}" for x in labels))
    for g in labels:
        lines.append(f"{g:<{width}}" + "".join(f"{(conf[(g, p)] or '.'):>{width}}" for p in labels))
    for slot in ("npc_events", "ego_actions"):
        errs = Counter((g, p) for g, p, _ in ev.slots[slot].misses)
        if errs:
            lines += ["", f"Most frequent {slot} errors (gold -> predicted x count)"]
            lines += [f"  {g:>8} -> {p:<8} x{k}" for (g, p), k in errs.most_common(top)]
    if by_source:
        keys = ("npc_quantity", "npc_type", "npc_position", "npc_events", "obstacle_quantity", "completeness")
        lines += ["", "Per source" + " " * 8 + "".join(f"{k[:13]:>14}" for k in keys) + "      conflict"]
        for src, e in by_source.items():
            lines.append(f"  {src:<8}({e.reports:>3})  " + "".join(f"{e.accuracy(k):>14.1%}" for k in keys)
                         + f"  {len(e.conflict_ok):>4}/{len(e.complete):<4}")
    return "\n".join(lines)


def format_table(ev: Evaluation, *, worst: int = 4, examples: int = 6) -> str:
    """Table IV, the extra slots and a confusion listing of the `worst` slots."""
    lines = [f"Extraction accuracy over {ev.reports} gold reports"
             + (f" ({len(ev.unmatched_gold)} without a prediction)" if ev.unmatched_gold else ""), "",
             f"{'slot':<20}{'accuracy':>9}{'correct':>9}{'total':>7}  target", "-" * 54]

    def row(name: str) -> str:
        t = ev.slots[name]
        tgt = TARGETS.get(name)
        mark = "" if tgt is None else f"  >= {tgt:.0%} " + ("ok" if t.accuracy >= tgt else "BELOW")
        return f"{name:<20}{t.accuracy:>9.1%}{t.correct:>9}{t.total:>7}{mark}"

    lines.append("Table IV (NPCs, obstacles)")
    lines += [row(n) for n in TABLE_IV]
    lines.append("Extra slots")
    lines += [row(n) for n in EXTRA]
    ranked = sorted((n for n in (*TABLE_IV, *EXTRA) if ev.slots[n].misses),
                    key=lambda n: (ev.slots[n].accuracy, n))[:worst]
    if ranked:
        lines += ["", "Worst slots: gold -> predicted (count; report ids)"]
    for n in ranked:
        lines.append(f"  {n} ({ev.slots[n].accuracy:.1%})")
        conf = Counter((g, p) for g, p, _ in ev.slots[n].misses)
        for (g, p), k in conf.most_common(examples):
            ids = [r for gg, pp, r in ev.slots[n].misses if (gg, pp) == (g, p)][:3]
            lines.append(f"    {g:>12} -> {p:<12} x{k}  {', '.join(ids)}")
    return "\n".join(lines)
