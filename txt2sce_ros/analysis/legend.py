"""Words for the codes that reports and the review page print: positions R1–R7, action strings a–m, and the
analysis elements built from them (`R5+ag`, `position:R7/left`, `events:ah`, `weather:fog`, …).

    explain("R5+ag")   -> "a party at R5 (same road and direction, ahead of or beside the AV) that did: go
                          straight, then change lane to the right"
    legend_rows()      -> (code, meaning) rows for a legend table
"""

from __future__ import annotations

from ..sketch import ACTION_MEANINGS, POSITION_MEANINGS
from .features import NEAR_START_GAP

#: Element prefixes (features.scenario_elements) and what each names.
PREFIX_MEANINGS: dict[str, str] = {
    "position": "a party starts at this position relative to the AV (a lane after '/')",
    "category": "a party of this category",
    "npcs": "number of NPCs in the scenario",
    "events": "a party's manoeuvres, in order (action codes)",
    "obstacle": "a static obstacle (yes/no, or its category)",
    "weather": "the weather of the scenario ('default': none set)",
    "signal": "the state the AV's signal shows while the parties interact",
    "near_start": f"a party starts within {NEAR_START_GAP:g} m (bumper to bumper) ahead of or behind the standing AV in its lane",
}


def actions_text(codes: str) -> str:
    """`"ag"` -> "go straight, then change lane to the right"; unknown letters are shown as they are."""
    return ", then ".join(ACTION_MEANINGS.get(c, repr(c)) for c in codes) if codes else "no manoeuvre (stood still)"


def position_text(code: str) -> str:
    """`"R5"` or `"R5/left"` -> the position in words (with its lane)."""
    pos, _, lane = code.partition("/")
    text = f"{pos} ({POSITION_MEANINGS.get(pos, 'unknown position')})"
    return f"{text}, lane {lane}" if lane else text


def explain(element: str) -> str:
    """One analysis element in words; an element of an unknown form is returned unchanged. A joint condition
    (elements that occurred in exactly the same runs, `lift.JOINT`) reads as its parts, joined by "and"."""
    from .lift import joint_parts

    parts = joint_parts(element)
    if len(parts) > 1:
        return "; and ".join(explain(p) for p in parts)
    if "+" in element and ":" not in element:
        pos, _, codes = element.partition("+")
        return f"a party at {position_text(pos)} that did: {actions_text(codes)}"
    kind, _, value = element.partition(":")
    if kind == "position":
        return f"a party starts at {position_text(value)}"
    if kind == "events":
        return f"a party's manoeuvres: {actions_text(value)}"
    if kind in PREFIX_MEANINGS:
        return f"{PREFIX_MEANINGS[kind]}: {value}"
    return element


def legend_rows() -> list[tuple[str, str]]:
    """(code, meaning) rows: how combined elements read, every position R1–R7, every action code a–m, and the
    element kinds."""
    rows = [("R5+ag", "combined element: a party at position R5 whose manoeuvres were a, then g "
                      "(position + action string)"),
            ("a & b", "joint condition: elements that occurred in exactly the same runs, which no count can tell "
                      "apart (one mutation added them together)")]
    rows += [(p, m) for p, m in POSITION_MEANINGS.items()]
    rows += [(a, m) for a, m in ACTION_MEANINGS.items()]
    rows += [(f"{k}:…", v) for k, v in PREFIX_MEANINGS.items()]
    return rows
