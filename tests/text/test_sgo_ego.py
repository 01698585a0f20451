"""Issue 13, the AV's own start and action string, read from real NHTSA SGO narratives the rules were not written
from (tests/text/sgo/study3.jsonl, session 14; each row's `source` beside its text). One test per reading; each
asserts the reading sketch.md's rules and the official gold's conventions give, and fails if the rule is removed.
"""

from __future__ import annotations

from txt2sce_ros.text.extractor import extract

# id -> (source, narrative)
_SGO: dict[str, tuple[str, str]] = {
    'nhtsa-sgo-ads-30291-7677-v1': (
        "github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30291-7677,"
        " version 1, column \"Narrative\"); original: NHTSA SGO-2021-01 ADS incident report data",
        "At approximately 12pm CST, May [XXX], 2024, a passenger vehicle rear-ended a Nuro Prius operating in "
        "autonomous mode at the intersection of [XXX] and [XXX] in Houston, Texas. The Nuro Prius was coming to a"
        " stop as the traffic signal changed from yellow to red. Shortly after the light turned red, a passenger "
        "vehicle rear-ended the Nuro Prius. No injuries were reported at the scene and law enforcement were not "
        "involved. Both vehicles sustained minimal damage."),
}


def _ego(report_id: str, text: str | None = None) -> tuple[str, str]:
    sk = extract(text if text is not None else _SGO[report_id][1], report_id)
    return sk.ego.start, sk.ego.actions


def test_a_stop_told_under_way_opens_the_string() -> None:
    # "The Nuro Prius was coming to a stop as the traffic signal changed": the stop was under way when the
    # interaction began (`h`, not `ah`).
    assert _ego("nhtsa-sgo-ads-30291-7677-v1") == ("moving", "h")
