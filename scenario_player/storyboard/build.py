"""Build the runtime storyboard (Init actions + Stories + StopTrigger) from a resolved scenario tree."""

from __future__ import annotations

from dataclasses import dataclass

from lxml import etree

from ..actions import ActionSpec, global_action_from_xml, private_action_from_xml
from ..conditions import Trigger, trigger_from_xml
from ..syntax.xml import ParseContext
from .tree import Story, story_from_xml


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
    return Storyboard(init, stories, trigger_from_xml(ctx, sb.find("StopTrigger")))
