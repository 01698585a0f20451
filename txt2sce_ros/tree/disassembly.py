"""δ: split a seed into a template T with insertion points and the set of mutable blocks B (paper §III-C).

Blocks are found by tag name and `name`/`entityRef` attributes, as `docs/seed_format.md` fixes them:

| block | elements |
|---|---|
| weather | `Storyboard/Init/Actions/GlobalAction/EnvironmentAction/Environment` |
| ego | `Init/Actions/Private[@entityRef='ego']` (its ScenarioObject stays in T: the AV is not mutated) + the StopTrigger's condition that the ego reached its goal (`ego_goal_condition`: a version that carries the route through a light moves the run's end with it) |
| npc | `Entities/ScenarioObject[@name=X]` + `Init/Actions/Private[@entityRef=X]` for each party X |
| signal | the Init `GlobalAction`s that set lights + the signal Story (`seed.signal_story`: timed state actions) |
| event | each `Story/Act/ManeuverGroup/Maneuver/Event` |
| obstacle | `ScenarioObject[@name='obs…']` + its Private |
| new_obstacle | an empty ScenarioObject slot after the last entity and an empty Private slot after the last Private |
| new_party | as new_obstacle, plus an empty Story slot after the last Story (a party inserted on the AV's path) |
| new_signal | for a seed without a signal Story: an empty slot after the last Init `GlobalAction` (before the Privates, as the schema orders them) and an empty Story slot (TLS writes a plan for the map's lights there) |

A signal block's parts are rewritten whole by the TLS mutation (`environment.tls`, and `dilemma_yellow` for a yellow
that waits for the ego's dilemma zone); the events of the signal Story are not event blocks of their own.

Each block element is replaced in the tree by a comment marker (keeping the element's tail whitespace), the tree is
serialised once, and the text is cut at the markers. Assembly is then a string join (fast: no tree per node).
"""

from __future__ import annotations

import re

from lxml import etree

from ..errors import InputError
from ..seed.signal_story import is_signal_init, is_signal_story
from .blocks import Block, BlockKind, Disassembly, Template
from .parties import free_name
from .xml import parse_bytes, to_text

_MARK = "@txt2sce-slot:"
_MARK_RE = re.compile(r"<!--@txt2sce-slot:(\d+)-->")
DEFAULT_ORDER = ("ego", "weather", "new_party", "signal", "npc", "event", "new_signal", "obstacle", "new_obstacle")


def ego_goal_condition(root: etree._Element) -> etree._Element | None:
    """The Storyboard StopTrigger's Condition that ends the run when the ego reaches its goal (a
    ReachPositionCondition the ego triggers), or None."""
    for cond in root.iterfind("Storyboard/StopTrigger/ConditionGroup/Condition"):
        by = cond.find("ByEntityCondition")
        if by is not None and by.find("EntityCondition/ReachPositionCondition") is not None and \
                [e.get("entityRef") for e in by.iterfind("TriggeringEntities/EntityRef")] == ["ego"]:
            return cond
    return None


def entity_kind(name: str) -> BlockKind:
    """Which block kind an entity belongs to, by its name (seed_format.md: ego, npc<k>/sketch ids, obs<k>)."""
    if name == "ego":
        return BlockKind.EGO
    if name.startswith("obs"):
        return BlockKind.OBSTACLE
    return BlockKind.NPC


class _Cutter:
    """Replaces elements by numbered markers and remembers what each slot held."""

    def __init__(self) -> None:
        self.fragments: list[str] = []

    def cut(self, el: etree._Element) -> int:
        slot = len(self.fragments)
        self.fragments.append(to_text(el))
        marker = etree.Comment(f"{_MARK}{slot}")
        marker.tail = el.tail
        el.getparent().replace(el, marker)
        return slot

    def empty_after(self, parent: etree._Element, after: etree._Element | None) -> tuple[int, etree._Element]:
        """An empty insertion point after `after` (or first in `parent`): where OIM puts a new obstacle. Returns
        the slot and its marker (the place for the next slot that must follow this one)."""
        slot = len(self.fragments)
        self.fragments.append("")
        marker = etree.Comment(f"{_MARK}{slot}")
        if after is None:
            marker.tail = parent.text
            parent.insert(0, marker)
        else:
            marker.tail = after.tail
            after.addnext(marker)
        return slot, marker


def disassemble(seed: bytes | str, *, source: str = "<seed>", order: tuple[str, ...] = DEFAULT_ORDER,
                new_obstacle_slots: int = 0, new_party_slots: int = 0, new_signal_slot: bool = False) -> Disassembly:
    """δ(seed) -> (T, B). `order` lists block kinds in insertion order; kinds left out stay in the template.
    `new_obstacle_slots` empty slots are added for obstacle insertion (OIM), `new_party_slots` for parties
    (`parties.py`), and with `new_signal_slot` a seed without a signal Story gets an empty one (with its Init
    slot) that TLS can fill."""
    root = parse_bytes(seed, source)
    if root.tag != "OpenSCENARIO":
        raise InputError(f"root element is <{root.tag}>, not <OpenSCENARIO>", source=source, element=root.tag)
    entities = root.find("Entities")
    actions = root.find("Storyboard/Init/Actions")
    if entities is None or actions is None:
        raise InputError("seed lacks Entities or Storyboard/Init/Actions", source=source,
                         element="Entities" if entities is None else "Storyboard/Init/Actions")
    wanted = {BlockKind(k) for k in order}
    taken = {o.get("name") for o in entities.iter("ScenarioObject")}
    # Find all block elements first (on the intact tree), then cut, so XPaths are not disturbed by the markers.
    found: dict[BlockKind, list[tuple[str, list[etree._Element]]]] = {k: [] for k in BlockKind}
    env = actions.find("GlobalAction/EnvironmentAction/Environment")
    if env is not None:
        found[BlockKind.WEATHER].append((env.get("name", "environment"), [env]))
    privates = {p.get("entityRef"): p for p in actions.findall("Private")}
    for obj in entities.findall("ScenarioObject"):
        name = obj.get("name", "")
        kind = entity_kind(name)
        if kind is BlockKind.EGO:
            if "ego" in privates:
                goal = ego_goal_condition(root)
                found[kind].append(("ego", [privates["ego"]] + ([goal] if goal is not None else [])))
            continue
        parts = [obj] + ([privates[name]] if name in privates else [])
        found[kind].append((name, parts))
    signal_stories = [s for s in root.iterfind("Storyboard/Story") if is_signal_story(s)]
    if signal_stories:
        inits = [g for g in actions.findall("GlobalAction") if is_signal_init(g)]
        found[BlockKind.SIGNAL].append((signal_stories[0].get("name", ""), inits + [signal_stories[0]]))
    for story in root.iterfind("Storyboard/Story"):
        if story in signal_stories:
            continue
        for ev in story.iterfind("Act/ManeuverGroup/Maneuver/Event"):
            found[BlockKind.EVENT].append((ev.get("name", ""), [ev]))

    cutter = _Cutter()
    cut: dict[BlockKind, list[tuple[str, tuple[int, ...]]]] = {k: [] for k in BlockKind}
    for kind in BlockKind:
        if kind in (BlockKind.NEW_OBSTACLE, BlockKind.NEW_PARTY, BlockKind.NEW_SIGNAL) or kind not in wanted:
            continue
        for key, parts in found[kind]:
            cut[kind].append((key, tuple(cutter.cut(el) for el in parts)))
    if BlockKind.NEW_OBSTACLE in wanted:
        for _ in range(new_obstacle_slots):
            last_obj = _last_element(entities)
            last_priv = _last_element(actions)
            s_obj, _ = cutter.empty_after(entities, last_obj)
            s_priv, _ = cutter.empty_after(actions, last_priv)
            cut[BlockKind.NEW_OBSTACLE].append((free_name("obs", taken), (s_obj, s_priv)))

    if BlockKind.NEW_SIGNAL in wanted and new_signal_slot and not signal_stories:
        # Init actions: GlobalActions come before any Private (InitActions is a sequence), so the slot follows
        # the last GlobalAction, or opens the list
        globals_ = [c for c in actions if c.tag == "GlobalAction"]
        s_init, _ = cutter.empty_after(actions, globals_[-1] if globals_ else None)
        storyboard = root.find("Storyboard")
        s_story, _ = cutter.empty_after(storyboard, _last_story(storyboard))
        cut[BlockKind.NEW_SIGNAL].append(("signal_new", (s_init, s_story)))

    if BlockKind.NEW_PARTY in wanted:
        storyboard = root.find("Storyboard")
        for _ in range(new_party_slots):
            s_obj, _ = cutter.empty_after(entities, _last_element(entities))
            s_priv, _ = cutter.empty_after(actions, _last_element(actions))
            s_story, _ = cutter.empty_after(storyboard, _last_story(storyboard))
            cut[BlockKind.NEW_PARTY].append((free_name("npc", taken), (s_obj, s_priv, s_story)))

    text = etree.tostring(root, encoding="unicode")
    pieces: list[str] = []
    slot_at: list[int] = []
    pos = 0
    for m in _MARK_RE.finditer(text):
        pieces.append(text[pos:m.start()])
        slot_at.append(int(m.group(1)))
        pos = m.end()
    pieces.append(text[pos:])
    header = '<?xml version="1.0" encoding="UTF-8"?>\n'
    pieces[0] = header + pieces[0]
    template = Template(pieces=tuple(pieces), slot_at=tuple(slot_at))

    blocks: list[Block] = []
    for name in order:
        for key, slots in cut[BlockKind(name)]:
            blocks.append(Block(index=len(blocks), kind=BlockKind(name), key=key, slots=slots,
                                fragments=tuple(cutter.fragments[s] for s in slots)))
    return Disassembly(source=source, template=template, blocks=tuple(blocks))


def _last_story(storyboard: etree._Element) -> etree._Element | None:
    """The last Story of the storyboard, or the marker a cut Story or a new slot left (else its Init): where a new
    Story slot goes, before the StopTrigger."""
    kids = [c for c in storyboard if c.tag == "Story" or (c.tag is etree.Comment and _MARK in (c.text or ""))]
    return kids[-1] if kids else storyboard.find("Init")


def _last_element(parent: etree._Element) -> etree._Element | None:
    """Last child that is an element or one of our markers (new slots go after everything else)."""
    kids = [c for c in parent if isinstance(c.tag, str) or (c.tag is etree.Comment and _MARK in (c.text or ""))]
    return kids[-1] if kids else None


