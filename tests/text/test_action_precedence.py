"""Issue 13, what the parties do (start and action string), read from real narratives of the studyable sets
(tests/text/sgo/study3.jsonl, tests/text/csvr/study2.jsonl, ../shared/data/reports/dev.jsonl with the dev gold;
each entry's `source` beside its text). Session 16: readings that recur across the studyable reports, each test
asserting what sketch.md's rules and the gold give; removing the reading fails its test. Most tell a real narrative
two ways, as it is and in a phrasing or clause order another reporter uses for the same moves (found by rewriting
every studyable narrative so): the reading must not change.
"""

from __future__ import annotations

import re
from typing import Callable

from txt2sce_ros.sketch import Party, Sketch
from txt2sce_ros.text.extractor import extract

from .quoted import QUOTED

_TEXT = QUOTED  # report id -> (source, narrative): tests/text/quoted.py


def _party(rid: str, k: int = 0) -> Party:
    return extract(_TEXT[rid][1], rid).npcs[k]


def _told(rid: str, pattern: str, repl: str) -> Sketch:
    """The narrative with one phrasing changed to another a reporter uses for the same moves."""
    assert re.search(pattern, _TEXT[rid][1])
    return extract(re.sub(pattern, repl, _TEXT[rid][1]), rid)


def _both_ways(rid: str, pattern: str, repl: str | Callable[[re.Match[str]], str]) -> tuple[Sketch, Sketch]:
    """The narrative as told and with one clause moved (`pattern` -> `repl`): the two readings, which must agree."""
    text = _TEXT[rid][1]
    moved = re.sub(pattern, repl, text)
    assert moved != text
    return extract(text, rid), extract(moved, rid)


def test_the_lane_a_turn_from_a_heading_ends_in_is_no_lane_change() -> None:
    # "initiated a wide right turn from eastbound [XXX] into the left lane of southbound [XXX]": the lane named is
    # where the turn ends, as for "turned right into EGO's lane" (the gold: `e`).
    p = _party('nhtsa-sgo-ads-30270-9333-v1')
    assert p.actions == "e"


def test_a_run_told_in_the_simple_past_goes_back_to_the_av_on_its_way() -> None:
    # "... was stopped ... when it was involved in a collision. The Waymo AV traveled northbound on Miramonte Avenue,
    # when it reached a four-way stop sign intersection. The Waymo AV stopped to yield": the summary's state is the
    # AV's at the contact; the telling, gone back to it travelling, opens with the run ("was traveling": `ah`, gold).
    # ... or in the past perfect progressive ("had been traveling": a run under way, as "was traveling" is).
    for verb in ("was traveling", "traveled", "had been traveling"):
        sk = _told('csvr-waymo-20190226-s3', r"\bwas traveling\b", verb)
        assert (sk.ego.start, sk.ego.actions) == ("moving", "ah"), verb


def test_speeding_up_right_after_backing_up_is_the_backing() -> None:
    # "The passenger vehicle ahead of the Waymo AV transitioned into reverse and accelerated, making contact":
    # faster in reverse, as "began to accelerate" reads (the gold: stopped, `k`).
    for verb in ("began to accelerate", "accelerated"):
        sk = _told('dmvca-waymo-20220605-r349', r"\bbegan to accelerate\b", verb)
        assert (sk.npcs[0].start, sk.npcs[0].actions) == ("stopped", "k"), verb


def test_a_party_queued_behind_the_standing_av_that_speeds_up_moved_off() -> None:
    # "While the traffic light was still red, the vehicle immediately behind the Waymo AV accelerated and made
    # contact with the rear bumper": it stood behind the AV and started (the gold: stopped, `i`).
    for verb in ("began to accelerate", "accelerated"):
        sk = _told('csvr-waymo-20220214-s134', r"\bbegan to accelerate\b", verb)
        assert (sk.npcs[0].start, sk.npcs[0].actions) == ("stopped", "i"), verb


def test_the_av_passing_after_its_stop_moved_off() -> None:
    # "The truck stopped and the Waymo AV passed the truck on the left. ... the Waymo AV came to a stop": after its
    # stop the AV moved off to pass, then stopped again (the gold: `ahih`), as "began to pass" reads.
    for verb in ("began to pass", "passed", "began passing"):
        sk = _told('nhtsa-sgo-ads-30270-10673-v1', r"\bbegan to pass\b", verb)
        assert (sk.ego.start, sk.ego.actions) == ("moving", "ahih"), verb


def test_the_av_s_state_told_after_the_party_in_a_clause_of_the_same_moment() -> None:
    # "While the Waymo AV remained stopped at a stop sign yielding to traffic, a passenger car traveling directly
    # behind the Waymo AV made contact with the rear", told the other way round ("A passenger car ... made contact
    # with the rear of the Waymo AV while the Waymo AV remained stopped ..."): where the AV stood when the party came
    # in (the gold: stopped, no action), not a stop after it.
    for sk in _both_ways('nhtsa-sgo-ads-30270-10557-v1',
                         r"While (the Waymo AV remained stopped at a stop sign yielding to traffic), "
                         r"(a passenger car [^.]*)\.",
                         lambda m: f"{m.group(2)[0].upper()}{m.group(2)[1:]} while {m.group(1)}."):
        assert (sk.ego.start, sk.ego.actions) == ("stopped", "")


def test_a_run_told_after_the_av_s_move_in_a_clause_of_the_same_moment_came_first() -> None:
    # "As the Waymo AV entered the intersection, it slowed to yield to northbound traffic", told the other way round
    # ("It slowed to yield to northbound traffic on Stanyan Street as the Waymo AV entered the intersection"): the
    # run is the background the slowing happened against (the gold: `ac`), not a move after it.
    for sk in _both_ways('csvr-waymo-20220517-s160',
                         r"As (the Waymo AV entered the intersection), it (slowed [^.]*)\.", r"It \2 as \1."):
        assert (sk.ego.start, sk.ego.actions) == ("moving", "ac")


def test_a_turn_under_way_told_after_the_av_s_move_in_a_clause_of_the_same_moment_came_first() -> None:
    # "While completing a right turn from Martin Avenue onto Mullen Avenue in autonomous mode, the Waymo AV slowed
    # to a stop while entering a narrow roadway", told with the turn's clause last ("... slowed to a stop while
    # entering a narrow roadway while completing a right turn ..."): it was turning, then stopped (`ehi`, as read
    # in the order told).
    for sk in _both_ways('dmvca-waymo-20230711-r497',
                         r"While (completing a right turn [^,]*), the Waymo AV (slowed to a stop [^.]*)\.",
                         r"The Waymo AV \2 while \1."):
        assert (sk.ego.start, sk.ego.actions) == ("moving", "ehi")


def test_a_pass_told_as_going_past_reads_as_passed() -> None:
    # "a van traveling behind the Waymo AV went past the Waymo AV on the left to enter the dedicated left turn lane",
    # "an SUV that had been stopped partially in-lane behind the Waymo AV went past the Waymo AV on the left": the
    # same passes as "passed" (the gold: `af`; stopped, `if`), the lane entered by way of it no mere intention.
    for verb in ("passed", "went past"):
        p = _told('csvr-waymo-20240918-s334', r"\bpassed\b", verb).npcs[0]
        assert (p.start, p.actions) == ("moving", "af"), verb
        p = _told('nhtsa-sgo-ads-30270-8150-v1', r"\bpassed\b", verb).npcs[0]
        assert (p.start, p.actions) == ("stopped", "if"), verb


def test_a_state_told_with_had_reads_as_with_was() -> None:
    # "approached a motorized articulating boom lift ("ABL"), which had stopped in the Cruise AV's lane of travel":
    # the relative clause tells of the lift, not of the AV (the gold: `af`, as with "which was stopped");
    # "had stopped in autonomous mode turning right from eastbound Park Drive onto southbound Miramonte Avenue":
    # the AV was at the junction it turned at (the gold: junction4, control and signal unknown).
    for aux in ("was", "had"):
        sk = _told('csvr-cruise-20230615-s252', r"\bwas stopped\b", f"{aux} stopped")
        assert (sk.ego.start, sk.ego.actions) == ("moving", "af"), aux
        sk = _told('csvr-waymo-20200214-s53', r"\bwas stopped\b", f"{aux} stopped")
        assert (sk.road.layout, sk.road.control, sk.signal_state) == ("junction4", "unknown", "unknown"), aux


def test_a_stop_reached_is_a_standing_for_the_road_readings() -> None:
    # "had come to a stop in traffic" is a queue (the summary's cross street then the junction ahead, as for "was
    # stopped in traffic": junction4); "had come to a stop at a traffic light" stood at its red, as "was stopped at a
    # traffic light" did (the gold: signal, red).
    # So is "was standing still".
    for verb in ("was stopped", "had come to a stop", "was standing still"):
        sk = _told('csvr-waymo-20210709-s89', r"\bwas stopped\b", verb)
        assert (sk.road.layout, sk.road.control, sk.signal_state) == ("junction4", "unknown", "unknown"), verb
        sk = _told('csvr-zoox-20220205-s130', r"\bwas stopped\b", verb)
        assert (sk.road.control, sk.signal_state) == ("signal", "red"), verb


def test_a_turn_under_way_told_as_executed_is_at_a_junction() -> None:
    # "The Waymo AV was executing a left turn from the rightmost dedicated left turn lane on Admiralty Way into lane
    # two of three lanes in the eastbound direction of Bali Way": a turn under way from one road into another, as
    # "was making a left turn" tells it (the gold: junction4).
    for verb in ("was making", "was executing"):
        sk = _told('csvr-waymo-20240603-s315', r"\bwas making\b", verb)
        assert sk.road.layout == "junction4", verb


def test_a_party_that_neared_the_av_was_on_its_way() -> None:
    # "a passenger vehicle approached from the rear and was attempting to pass the Zoox vehicle", told with "neared":
    # a run along its lane either way (the gold: moving, `a`).
    for verb in ("approached", "neared"):
        p = _told('dmvca-zoox-20220428-r329', r"\bapproached\b", verb).npcs[0]
        assert (p.start, p.actions) == ("moving", "a"), verb


def test_a_light_told_as_a_stoplight_or_by_its_colour_after_it() -> None:
    # "After the stoplight turned green and the Waymo AV had begun to accelerate, the passenger vehicle behind the
    # Waymo AV struck the rear": the queue's party moved off on that green (the gold: stopped, `i`), and the AV's light
    # was red, as with "traffic light"; "stopped at a light that was red" is a red light, as "at a red light" is.
    for word in ("traffic light", "stoplight"):
        sk = _told('csvr-waymo-20220128-s127', r"\btraffic light\b", word)
        assert (sk.npcs[0].start, sk.npcs[0].actions, sk.road.control, sk.signal_state) == \
            ("stopped", "i", "signal", "red"), word
    for told in ("at a red light", "at a light that was red"):
        sk = _told('csvr-zoox-20220205-s130', r"\bat a traffic light\b", told)
        assert (sk.road.layout, sk.road.control, sk.signal_state) == ("junction4", "signal", "red"), told


def test_a_turn_the_av_approached_is_ahead_not_made() -> None:
    # "As the Waymo AV approached a right turn from Cesar Chavez onto Evans Avenue, it braked behind stopped
    # traffic", told with the clause last ("It braked behind stopped traffic as the Waymo AV approached a right
    # turn ..."): the turn was ahead, not begun (the gold: `ah`), in either order.
    for sk in _both_ways('csvr-waymo-20211018-s101',
                         r"As (the Waymo AV approached a right turn [^,]*), it (braked [^.]*)\.", r"It \2 as \1."):
        assert (sk.ego.start, sk.ego.actions) == ("moving", "ah")


def test_a_run_told_by_a_trailing_participle_clause_came_first() -> None:
    # "While traveling northwest on Mission Street in autonomous mode, the Waymo AV navigated around a double-parked
    # vehicle", told with the clause last ("The Waymo AV navigated around a double-parked vehicle stopped in the right
    # lane while traveling northwest ..."): the run, then the way round (the gold: `afgh`), in either order.
    for sk in _both_ways('dmvca-waymo-20211008-r227',
                         r"While (traveling [^,]*), the Waymo AV (navigated [^.]*)\.", r"The Waymo AV \2 while \1."):
        assert (sk.ego.start, sk.ego.actions) == ("moving", "afgh")
