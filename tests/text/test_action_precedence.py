"""Issue 13, what the parties do (start and action string), read from real narratives of the studyable sets
(tests/text/sgo/study3.jsonl, tests/text/csvr/study2.jsonl, ../shared/data/reports/dev.jsonl with the dev gold;
each entry's `source` beside its text). Session 16: readings that recur across the studyable reports, each test
asserting what sketch.md's rules and the gold give; removing the reading fails its test.
"""

from __future__ import annotations

from txt2sce_ros.sketch import Party
from txt2sce_ros.text.extractor import extract

# id -> (source, narrative)
_TEXT: dict[str, tuple[str, str]] = {
    'nhtsa-sgo-ads-30270-9333-v1': (
        'github:vanshagg233/Risk_Function@1806947 SGO-2021-01_Incident_Reports_ADS.csv (Report ID 30270-9333,'
        ' version 1, column "Narrative"); original: NHTSA SGO-2021-01 ADS incident report data',
        'On December [XXX], 2024 at 10:19 PM PT a Waymo Autonomous Vehicle ("Waymo AV") operating in San '
        'Francisco, California was in a collision involving a mini coach bus on [XXX] at [XXX]. The Waymo AV '
        'was stopped facing south in the rightmost lane of [XXX] after a passenger dropoff when a mini coach '
        'bus initiated a wide right turn from eastbound [XXX] into the left lane of southbound [XXX]. As the '
        'bus passed the stopped Waymo AV, the passenger side of the bus made contact with the rear driver '
        "side of the Waymo AV. At the time of the impact, the Waymo AV's Level 4 ADS was engaged in "
        'autonomous mode. Both vehicles sustained damage. Waymo is reporting this crash under Request No. 1 '
        'of Standing General Order 2021-01 because a vehicle involved was towed away. Waymo may supplement or'
        ' correct its reporting with additional information as it may become available.'),
}


def _party(rid: str, k: int = 0) -> Party:
    return extract(_TEXT[rid][1], rid).npcs[k]


def test_the_lane_a_turn_from_a_heading_ends_in_is_no_lane_change() -> None:
    # "initiated a wide right turn from eastbound [XXX] into the left lane of southbound [XXX]": the lane named is
    # where the turn ends, as for "turned right into EGO's lane" (the gold: `e`).
    p = _party('nhtsa-sgo-ads-30270-9333-v1')
    assert p.actions == "e"
