"""How far `hybrid` can take the rules, measured with no model at hand.

Each report is extracted again in `hybrid` mode with a perfect model in the server's place: it answers every question
`hybrid` asks from the gold sketch (each weak slot of a complete sketch; the whole dialogue for a sketch the rules
leave incomplete), through the same merge a real answer goes through (`llm.merge_slots`). The figure it gives is a
ceiling: a real model answers some of those questions wrongly. What stays wrong is where the rules are wrong without
flagging it, or a slot `hybrid` never asks about (the AV's actions, the road): only `--backend llm` or better rules
reach those.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ..sketch import Sketch
from .evaluate import Evaluation, paired_npcs
from .llm import SLOT_PATH, merge_slots

#: The NPC fields `hybrid` may ask about (`llm.SLOT_PATH`), in the order its slot paths name them.
ASKED_FIELDS: tuple[str, ...] = ("position", "lane", "actions")


def perfect_answers(offline: Sketch, gold: Sketch, slots: tuple[str, ...]) -> dict[str, object]:
    """The gold value of every asked slot whose NPC has a gold partner (a party gold does not have gets no
    answer: no value makes it right)."""
    partner = {p.id: g for g, p in paired_npcs(gold, offline) if g is not None and p is not None}
    out: dict[str, object] = {}
    for slot in slots:
        m = SLOT_PATH.fullmatch(slot)
        if m and int(m.group(1)) < len(offline.npcs) and (g := partner.get(offline.npcs[int(m.group(1))].id)):
            out[slot] = getattr(g, m.group(2))
    return out


@dataclass
class FlagTally:
    """How well the rules' weak flags point at their errors, over the asked fields of NPCs the rules give (a
    party the rules missed has no slot to flag)."""
    flagged_wrong: int = 0
    flagged_right: int = 0
    unflagged_wrong: int = 0
    unflagged_right: int = 0

    def add(self, offline: Sketch, gold: Sketch, weak: tuple[str, ...]) -> None:
        index = {p.id: k for k, p in enumerate(offline.npcs)}
        for g, p in paired_npcs(gold, offline):
            if p is None:
                continue
            for name in ASKED_FIELDS:
                right = g is not None and getattr(g, name) == getattr(p, name)
                flagged = f"npcs[{index[p.id]}].{name}" in weak
                attr = ("flagged_" if flagged else "unflagged_") + ("right" if right else "wrong")
                setattr(self, attr, getattr(self, attr) + 1)

    @property
    def recall(self) -> float:
        """The share of the rules' wrong NPC slots that they flag weak (what `hybrid` can reach at all)."""
        wrong = self.flagged_wrong + self.unflagged_wrong
        return self.flagged_wrong / wrong if wrong else float("nan")


@dataclass
class PerfectModel:
    """Takes the model's place in `pipeline.sketch_report(backend="hybrid")`: answers from `gold` (by report id),
    and counts the questions asked. A report with no gold sketch keeps the rules' reading."""
    gold: dict[str, Sketch]
    flags: FlagTally = field(default_factory=FlagTally)
    slot_questions: int = 0  # complete sketches asked about their weak slots
    slots_asked: int = 0
    dialogues: int = 0  # incomplete sketches asked the whole dialogue
    not_consulted: list[tuple[str, str]] = field(default_factory=list)  # (the pipeline's interface; never filled)

    def refine(self, offline: Sketch, narrative: str, weak: tuple[str, ...] = ()) -> Sketch:
        """As `LlmExtractor.refine`, with every answer right."""
        g = self.gold.get(offline.report_id)
        if g is None:
            return offline
        self.flags.add(offline, g, weak)
        if not offline.is_buildable:
            self.dialogues += 1
            return g if g.is_buildable else offline
        if not weak:
            return offline
        self.slot_questions += 1
        self.slots_asked += len(weak)
        return merge_slots(offline, perfect_answers(offline, g, weak), weak)


def format_ceiling(rules: Evaluation, ceiling: Evaluation, model: PerfectModel) -> str:
    """The rules' figures beside the ceiling's, the questions it took, and how well the weak flags point."""
    def figure(ev: Evaluation) -> str:
        return f"{len(ev.conflict_ok)}/{len(ev.complete)} ({ev.conflict_rate:.1%})"

    f = model.flags
    slots = ("npc_position", "npc_events", "completeness")
    lines = ["Hybrid ceiling: `hybrid` with a perfect model answering each question it asks (no model was run)",
             f"  user's figure: rules {figure(rules)} -> ceiling {figure(ceiling)}",
             "  " + ", ".join(f"{k} {rules.accuracy(k):.1%} -> {ceiling.accuracy(k):.1%}" for k in slots),
             f"  questions: {model.slot_questions} complete sketches asked about {model.slots_asked} weak slots; "
             f"{model.dialogues} incomplete sketches asked the whole dialogue",
             f"  weak flags on the NPCs' position/lane/actions: {f.flagged_wrong + f.flagged_right} flagged "
             f"({f.flagged_wrong} wrong), {f.unflagged_wrong + f.unflagged_right} not flagged ({f.unflagged_wrong} "
             f"wrong): {f.recall:.0%} of the wrong slots flagged",
             "  what the ceiling still misses (a report can miss several): "
             + (", ".join(f"{k} {n}" for k, n in sorted(ceiling.conflict_missed.items(), key=lambda kv: (-kv[1], kv[0])))
                or "none")]
    return "\n".join(lines)
