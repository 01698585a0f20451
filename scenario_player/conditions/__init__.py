"""Conditions and triggers; `trigger_from_xml` parses a StartTrigger/StopTrigger through dispatch tables."""

from __future__ import annotations

from lxml import etree

from ..syntax.xml import ParseContext, children, first
from .base import Check, Condition, ConditionGroup, Trigger
from .by_entity import BY_ENTITY, ByEntityCondition
from .by_value import BY_VALUE


class _Never(Check):
    """An unsupported condition (reported at load) never holds: the run goes on and lists it as unsupported."""

    def holds(self, world: object) -> bool:  # noqa: ARG002
        return False


def condition_from_xml(ctx: ParseContext, el: etree._Element) -> Condition:
    body = ctx.only_child(el)
    check: Check
    if body.tag == "ByValueCondition":
        inner = ctx.only_child(body)
        parser = BY_VALUE.get(str(inner.tag))
        if parser is None:
            ctx.note_unsupported(inner)
            check = _Never()
        else:
            check = parser(ctx, inner)
    elif body.tag == "ByEntityCondition":
        te = ctx.child(body, "TriggeringEntities")
        rule = ctx.req(te, "triggeringEntitiesRule")
        entities = tuple(ctx.req(r, "entityRef") for r in children(te, "EntityRef"))
        inner = ctx.only_child(ctx.child(body, "EntityCondition"))
        parser = BY_ENTITY.get(str(inner.tag))
        if parser is None:
            ctx.note_unsupported(inner)
            check = _Never()
        else:
            check = ByEntityCondition(entities, rule, parser(ctx, inner))
    else:
        raise ctx.error(body, f"unknown condition kind <{body.tag}>")
    return Condition(el.get("name", ""), el.get("conditionEdge", "none"), ctx.float(el, "delay", 0.0), check,
                     el.sourceline)


def trigger_from_xml(ctx: ParseContext, el: etree._Element | None) -> Trigger | None:
    if el is None or first(el, "ConditionGroup") is None:
        return None     # an empty <StartTrigger/> is no trigger at all: the element starts at once (as esmini)
    return Trigger([ConditionGroup([condition_from_xml(ctx, c) for c in children(g, "Condition")])
                    for g in children(el, "ConditionGroup")])


__all__ = ["Condition", "ConditionGroup", "Trigger", "trigger_from_xml", "condition_from_xml"]
