"""Build the runtime storyboard (Init actions + Stories + StopTrigger) from a resolved scenario tree."""

from __future__ import annotations

from dataclasses import dataclass

from lxml import etree

from txt2sce_ros.errors import InputError

from ..actions import ActionSpec, global_action_from_xml, private_action_from_xml
from ..conditions import Trigger, trigger_from_xml
from ..conditions.by_value import StoryboardElementStateCondition
from ..syntax.xml import ParseContext
from .tree import Story, index_elements, story_from_xml


@dataclass
class Storyboard:
    init: list[tuple[str | None, ActionSpec, int | None]]     # (entity or None for global, action, line)
    stories: list[Story]
    stop_trigger: Trigger | None


def build_storyboard(ctx: ParseContext, root: etree._Element) -> Storyboard:
    sb = root.find("Storyboard")
    if sb is None:
        raise ctx.error(root, "no <Storyboard>")
    init: list[tuple[str | None, ActionSpec, int | None]] = []
    actions = sb.find("Init/Actions")
    if actions is not None:
        for el in actions:
            if el.tag == "GlobalAction":
                init.append((None, global_action_from_xml(ctx, el), el.sourceline))
            elif el.tag == "Private":
                ent = ctx.req(el, "entityRef")
                for pa in el.findall("PrivateAction"):
                    init.append((ent, private_action_from_xml(ctx, pa), pa.sourceline))
            elif isinstance(el.tag, str):
                ctx.note_unsupported(el)
    stories = [story_from_xml(ctx, s) for s in sb.findall("Story")]
    board = Storyboard(init, stories, trigger_from_xml(ctx, sb.find("StopTrigger")))
    _check_element_references(ctx, board)
    return board


def _triggers(board: Storyboard) -> list[Trigger]:
    out = [board.stop_trigger] if board.stop_trigger else []
    for story in board.stories:
        for act in story.children:
            out += [t for t in (act.start_trigger, act.stop_trigger) if t]  # type: ignore[attr-defined]
            for mg in act.children:
                for man in mg.children:
                    out += [e.trigger for e in man.children if e.trigger]  # type: ignore[attr-defined]
    return out


def _check_element_references(ctx: ParseContext, board: Storyboard) -> None:
    """StoryboardElementStateConditions must name an element of the given type (else: InputError at load)."""
    index = index_elements(board.stories)
    for trig in _triggers(board):
        for group in trig.groups:
            for cond in group.conditions:
                chk = cond.check
                if isinstance(chk, StoryboardElementStateCondition) and (chk.element_type, chk.ref) not in index:
                    raise InputError(f"no {chk.element_type} named '{chk.ref}' in the storyboard",
                                     source=chk.where or ctx.source,
                                     element="StoryboardElementStateCondition", line=chk.line)
