"""What the stack knows of the road condition: the friction coefficient from the scenario's environment.

A real stack reads road condition from a weather / road-surface service; in our closed loop the scenario's
`EnvironmentAction/Environment/RoadCondition/@frictionScaleFactor` is that service (the planner node gets the
scenario envelope anyway, for the map).
"""

from __future__ import annotations

from lxml import etree

from txt2sce_ros.errors import InputError
from txt2sce_ros.xmlsafe import refuse_doctype

_PARSER = etree.XMLParser(resolve_entities=False, no_network=True, huge_tree=False, remove_comments=True)


def friction_from_xosc(xosc: str | bytes, *, source: str = "<scenario>") -> float | None:
    """The first `RoadCondition/@frictionScaleFactor` in the scenario (its Init environment), or None."""
    data = xosc.encode("utf-8") if isinstance(xosc, str) else xosc
    refuse_doctype(data, source)
    try:
        root = etree.fromstring(data, _PARSER)
    except etree.XMLSyntaxError as exc:
        raise InputError(f"not XML: {exc}", source=source) from exc
    for node in root.iter("RoadCondition"):
        value = node.get("frictionScaleFactor")
        if value is None:
            continue
        try:
            return float(value)
        except ValueError as exc:
            raise InputError(f"frictionScaleFactor {value!r} is not a number", source=source,
                             element="RoadCondition") from exc
    return None
