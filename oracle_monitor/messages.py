"""Violations and verdicts as `diagnostic_msgs/DiagnosticArray` on `/oracle/violations` (viewable in Foxglove and
`ros2 topic echo`, recorded in the bag).

One status per violation: name `oracle/<Category or info>/<rule>`, level ERROR for the exclusive categories, WARN
for PlanFail / Smooth, OK for events reported beside the verdict; message = the detail; values t, observed,
threshold, units, entities. At the end of a run, one status named `oracle/verdict`: level OK (pass), ERROR (fail)
or STALE (error), message = the one-line summary, value `json` = the whole RunVerdict.
"""

from __future__ import annotations

import json
from typing import Any, Iterable

from txt2sce_ros.ros_io import make_diagnostics

from . import cdr

from .records import EXCLUSIVE, RunVerdict, Violation

OK, WARN, ERROR, STALE = 0, 1, 2, 3
VERDICT_STATUS = "oracle/verdict"


def _violation_statuses(violations: Iterable[Violation]) -> list[tuple[str, int, str, dict[str, str]]]:
    statuses = []
    for v in violations:
        level = OK if v.category is None else ERROR if v.category in EXCLUSIVE else WARN
        cat = v.category.value if v.category else "info"
        statuses.append((f"oracle/{cat}/{v.rule.value}", level, v.detail, {
            "t": repr(v.t), "observed": repr(v.observed), "threshold": repr(v.threshold), "units": v.units,
            "entities": ",".join(v.entities)}))
    return statuses


def _verdict_statuses(verdict: RunVerdict) -> list[tuple[str, int, str, dict[str, str]]]:
    level = {"pass": OK, "fail": ERROR, "error": STALE}[verdict.verdict.value]
    return [(VERDICT_STATUS, level, verdict.summary(), {
        "verdict": verdict.verdict.value, "scenario_id": verdict.scenario_id, "json": verdict.to_json()})]


def violations_to_diagnostics(t: float, violations: Iterable[Violation]) -> Any:
    return make_diagnostics(t, _violation_statuses(violations))


def verdict_to_diagnostics(verdict: RunVerdict) -> Any:
    return make_diagnostics(verdict.t_end, _verdict_statuses(verdict))


def violations_cdr(t: float, violations: Iterable[Violation]) -> bytes:
    """`violations_to_diagnostics` serialised (padding zeroed, no rclpy message made): what a recorder writes."""
    return cdr.encode_diagnostics(t, _violation_statuses(violations))


def verdict_cdr(verdict: RunVerdict) -> bytes:
    """`verdict_to_diagnostics` serialised (padding zeroed, no rclpy message made)."""
    return cdr.encode_diagnostics(verdict.t_end, _verdict_statuses(verdict))


def verdicts_in(msg: Any) -> list[dict[str, Any]]:
    """The verdicts (as dicts) carried by one `/oracle/violations` message, if any."""
    out = []
    for st in msg.status:
        if st.name == VERDICT_STATUS:
            values = {kv.key: kv.value for kv in st.values}
            if "json" in values:
                out.append(json.loads(values["json"]))
    return out
