"""Issue 13, session 17: the manoeuvre vocabularies widened to the ways English tells each one (the wordings
themselves are held by `tests/text/probes.py`, "in the ways English tells it"); here, each widening on a real
studyable narrative (tests/text/quoted.py), where the wider reading must not take what the text does not say.
"""

from __future__ import annotations

from txt2sce_ros.text.extractor import extract

from .quoted import QUOTED


def _parties(report_id: str, text: str | None = None) -> list[tuple[str, str]]:
    sk = extract(text if text is not None else QUOTED[report_id][1], report_id)
    return [(p.start, p.actions) for p in sk.npcs]


def test_a_stop_told_with_any_manner_word_but_a_near_stop_is_a_slowing() -> None:
    # "The passenger car immediately behind the Waymo AV slowed and came to a near stop when a second passenger car
    # ... made contact": a near stop is no standstill (gold `c`; the run told before it is read `a`, so `ac`). Any
    # other one word for the manner of the stop ("an unexpected stop", "an emergency stop") is a stop.
    rid = "nhtsa-sgo-ads-30270-3786-v1"
    assert _parties(rid)[0] == ("moving", "ac")
    for manner in ("an unexpected", "an emergency", "a rapid"):
        text = QUOTED[rid][1].replace("slowed and came to a near stop", f"came to {manner} stop")
        assert _parties(rid, text)[0] == ("moving", "ah"), manner


def test_moving_forward_from_the_curb_is_pulling_out() -> None:
    # "an SUV began to parallel park behind the Waymo AV. While parking, the SUV moved forward from the curb into the
    # roadway, maneuvering to the left of the Waymo AV": out from the curb by any verb of moving forward is a pull
    # out into the travel lane (gold `lf`: the parking, then the move left out of the curb side).
    assert _parties("nhtsa-sgo-ads-30270-9350-v1")[0] == ("moving", "lf")


def test_the_entrance_of_a_parking_lot_is_on_the_road() -> None:
    # "was in a collision involving a chain at the entrance of a parking lot ... As the Waymo AV was entering the
    # parking lot, it made contact with a chain hanging at the entrance": the entrance, an exit or the driveway of a
    # lot is where it meets the road, `straight` (sketch.md: a driveway is `straight`); inside a lot is `parking`.
    rid = "nhtsa-sgo-ads-30270-7936-v1"
    assert extract(QUOTED[rid][1], rid).road.layout == "straight"
    inside = QUOTED[rid][1].replace("at the entrance of a parking lot", "in a parking lot").replace(
        "hanging at the entrance of the parking lot", "hanging in the parking lot")
    assert extract(inside, rid).road.layout == "parking"


def test_a_dark_traffic_light_gives_no_signal_state() -> None:
    # "The Waymo AV was stopped facing a malfunctioning traffic light ... While the Waymo AV remained stopped and the
    # traffic light was not illuminated": a junction with a signal (control `signal`) that showed no colour, so the AV
    # began on none (gold `none`); the same light told lit is the red it stood at.
    rid = "csvr-waymo-20241214-s355"
    sk = extract(QUOTED[rid][1], rid)
    assert (sk.road.control, sk.signal_state) == ("signal", "none")
    lit = QUOTED[rid][1].replace("a malfunctioning traffic light", "a red traffic light").replace(
        "and the traffic light was not illuminated", "at the red light")
    assert extract(lit, rid).signal_state == "red"
