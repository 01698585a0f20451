"""Safety oracles: exact contact from oriented footprints, the paper's jerk rule beside it."""

from __future__ import annotations

import math

import pytest

from oracle_monitor import Category, Oracle, OracleParams, Rule
from oracle_monitor.geometry import box_at, footprint, overlaps, penetration
from txt2sce_ros.contract import Goal, Verdict
from txt2sce_ros.errors import InputError

from .oracle_runs import car, ego, esmini_frames, finished, judge, straight_run

PARAMS = OracleParams.from_config()


def test_rear_end_contact_time_and_entity() -> None:
    # Ego at 10 m/s from x=0 towards a stopped car: contact when its front bumper reaches the car's rear bumper,
    # at t = 2.5522 s, between the frames at 2.55 and 2.60 s.
    lead = lambda t: [car("lead", t, 30.022)]
    frames = straight_run(lambda t: 10.0, 4.0, objects=lead)
    verdict, online = judge(Oracle(None, None, PARAMS), frames)
    contacts = [v for v in online if v.rule is Rule.CONTACT]
    assert len(contacts) == 1, "a lasting overlap is one contact, not one per frame"
    c = contacts[0]
    gap = (30.022 + 1.4 - 2.25) - (0.0 + 1.4 + 2.25)      # rear bumper of lead - front bumper of ego
    assert c.t == pytest.approx(gap / 10.0, abs=1e-4)      # refined between frames, not rounded to 0.05 s
    assert c.entities == ("lead",) and c.category is Category.COLLISIONS
    assert verdict.verdict is Verdict.FAIL and verdict.category_names() == ("Collisions",)
    assert verdict.categories[0].entities == ("lead",)


def test_car_in_the_next_lane_is_not_hit() -> None:
    frames = straight_run(lambda t: 10.0, 4.0, objects=lambda t: [car("beside", t, 30.0, y=3.5)])
    verdict, online = judge(Oracle(None, None, PARAMS), frames)
    assert not [v for v in online if v.rule is Rule.CONTACT]
    assert "Collisions" not in verdict.category_names()


def test_oriented_boxes_are_exact_where_axis_aligned_boxes_overlap() -> None:
    # Two 4.5 × 1.8 boxes rotated 45° whose axis-aligned bounding boxes overlap but whose shapes do not.
    a = box_at(0.0, 0.0, math.pi / 4, 0.0, 4.5, 1.8)
    b = box_at(2.4, -2.4, math.pi / 4, 0.0, 4.5, 1.8)
    assert not overlaps(a, b) and penetration(a, b) < 0
    c = box_at(1.0, -1.0, math.pi / 4, 0.0, 4.5, 1.8)       # 1.41 m apart across their width of 1.8 m: overlap
    assert overlaps(a, c) and penetration(a, c) == pytest.approx(1.8 - math.sqrt(2), abs=1e-9)


def test_side_swipe_by_a_crossing_car() -> None:
    # A car crossing the ego's path from the right at 8 m/s; ego at 10 m/s: their paths cross at x = 40.
    cross = lambda t: [car("crosser", t, 40.0 - 1.4, -33.0 + 8.0 * t, heading=math.pi / 2, speed=8.0)]
    frames = straight_run(lambda t: 10.0, 6.0, objects=cross)
    verdict, online = judge(Oracle(None, None, PARAMS), frames)
    hit = next(v for v in online if v.rule is Rule.CONTACT)
    assert hit.entities == ("crosser",)
    # Check the refined time against a brute-force scan of the same motion at 0.1 ms resolution.
    t = 2.0
    while not overlaps(footprint(ego(t, 10.0 * t, speed=10.0)), footprint(cross(t)[0])):
        t += 1e-4
    assert hit.t == pytest.approx(t, abs=2e-4)


def test_jerk_rule_fires_on_a_hard_stop_and_not_on_braking() -> None:
    hard = straight_run(lambda t: 10.0 if t < 2.0 else 0.0, 4.0)        # 10 -> 0 m/s in one 50 ms step
    verdict, online = judge(Oracle(None, None, PARAMS), hard)
    jerks = [v for v in online if v.rule is Rule.JERK_COLLISION]
    assert jerks and jerks[0].t == pytest.approx(2.0) and jerks[0].observed > 300.0
    assert jerks[0].category is None, "with collision_rule=contact the jerk rule is reported beside, not counted"
    assert "Collisions" not in verdict.category_names()
    assert any("1 jerk event" in n or "jerk event(s)" in n for n in verdict.notes)

    soft = straight_run(lambda t: max(0.0, 10.0 - 3.0 * max(0.0, t - 1.0)), 6.0)   # 3 m/s² braking
    _, online = judge(Oracle(None, None, PARAMS), soft)
    assert not [v for v in online if v.rule is Rule.JERK_COLLISION]


def test_collision_rule_jerk_makes_the_jerk_event_the_collision() -> None:
    params = PARAMS.with_overrides(safety={"collision_rule": "jerk"})
    hard = straight_run(lambda t: 10.0 if t < 2.0 else 0.0, 4.0, objects=lambda t: [car("lead", t, 80.0)])
    verdict, _ = judge(Oracle(None, None, params), hard)
    assert verdict.category_names() == ("Collisions",)
    assert verdict.categories[0].rule is Rule.JERK_COLLISION


def test_esmini_pedestrian_collision_reference_run() -> None:
    # esmini's own trajectory of its pedestrian_collision example: the ego at 9 m/s meets a crossing pedestrian.
    frames = esmini_frames("pedestrian_collision", categories={"pedestrian_adult": "pedestrian"})
    verdict, online = judge(Oracle(None, None, PARAMS), frames)
    hit = next(v for v in online if v.rule is Rule.CONTACT)
    assert hit.entities == ("pedestrian_adult",)
    assert 5.0 < hit.t < 6.0
    assert verdict.category_names() == ("Collisions",)


def test_esmini_slow_lead_vehicle_has_no_contact() -> None:
    frames = esmini_frames("slow-lead-vehicle")
    _, online = judge(Oracle(None, None, PARAMS), frames)
    assert not [v for v in online if v.rule in (Rule.CONTACT, Rule.JERK_COLLISION)]


# --- struck while standing still (not the ego's collision) --------------------------------------------------------

def _rear_ended(ego_speed: float) -> list:
    """The ego waits (or creeps at `ego_speed`) at x = 0; a car from behind at 8 m/s runs into it at t ≈ 1.67 s."""
    behind = lambda t: [car("npc1", t, -18.0 + 8.0 * t, speed=8.0)]
    return straight_run(lambda t: ego_speed, 2.5, objects=behind)


def test_stopped_ego_rear_ended_is_struck_not_collisions() -> None:
    frames = _rear_ended(0.0)
    verdict, online = judge(Oracle(None, None, PARAMS), frames, finished(frames[-1].t, "collision"))
    struck = [v for v in online if v.rule is Rule.STRUCK_WHILE_STOPPED]
    assert len(struck) == 1 and struck[0].entities == ("npc1",) and struck[0].category is None
    # Gap between the NPC's front bumper and the ego's rear bumper: 18 - 4.5 = 13.5 m at 8 m/s.
    assert struck[0].t == pytest.approx(13.5 / 8.0, abs=1e-3)
    assert not [v for v in online if v.rule is Rule.CONTACT]
    assert verdict.verdict is Verdict.PASS, verdict.summary()


def test_struck_run_ended_by_the_player_is_no_plan_fail() -> None:
    # The player ends a run on any ego contact; the goal 100 m ahead is then out of reach through no fault of
    # the ego: no PlanFail, and the event stays in the verdict's violations.
    frames = _rear_ended(0.0)
    goal = Goal(100.0, 0.0, 0.0, 2.0)
    verdict, _ = judge(Oracle(None, goal, PARAMS), frames, finished(frames[-1].t, "collision"))
    assert verdict.verdict is Verdict.PASS, verdict.summary()
    assert any(v.rule is Rule.GOAL_NOT_REACHED for v in verdict.violations)
    assert any("struck (standing still or rear-ended)" in n for n in verdict.notes)
    # The same run timing out without contact is still a PlanFail: only the struck ending is excused.
    alone = straight_run(lambda t: 0.0, 2.5)
    timed_out, _ = judge(Oracle(None, goal, PARAMS), alone, finished(alone[-1].t, "time_limit"))
    assert "PlanFail" in timed_out.category_names()


def test_moving_ego_rear_ended_is_struck_from_behind() -> None:
    # Creeping at 0.5 m/s (above struck_speed) the ego is rear-ended by a car closing at 7.5 m/s from behind, in
    # its lane: it did not crash into anything (the case of an ego braking for a light in front of a scripted NPC).
    frames = _rear_ended(0.5)
    verdict, online = judge(Oracle(None, None, PARAMS), frames, finished(frames[-1].t, "collision"))
    hit = [v for v in online if v.entities == ("npc1",)]
    assert [v.rule for v in hit] == [Rule.STRUCK_FROM_BEHIND] and hit[0].observed == pytest.approx(7.5)
    assert verdict.verdict is Verdict.PASS, verdict.summary()
    # Switched off, the same contact is the ego's Collision (exact contact, as before).
    off = PARAMS.with_overrides(safety={"struck_from_behind": False})
    verdict, online = judge(Oracle(None, None, off), frames, finished(frames[-1].t, "collision"))
    assert [v.rule for v in online if v.entities == ("npc1",)] == [Rule.CONTACT]
    assert verdict.category_names() == ("Collisions",)


def test_ego_driving_into_a_car_or_beside_one_is_not_struck() -> None:
    # Ego at 10 m/s into a slower car ahead: the other is ahead, not behind — the ego's Collision.
    ahead = straight_run(lambda t: 10.0, 3.0, objects=lambda t: [car("lead", t, 20.0 + 2.0 * t, speed=2.0)])
    verdict, _ = judge(Oracle(None, None, PARAMS), ahead)
    assert verdict.category_names() == ("Collisions",)
    # A car drifting in from the next lane alongside the ego (centre beside it, not behind): not a rear-end.
    side = lambda t: [car("npc1", t, 0.5 + 4.0 * t, y=max(0.9, 3.5 - 1.0 * t), speed=4.0)]
    verdict, online = judge(Oracle(None, None, PARAMS), straight_run(lambda t: 4.0, 3.0, objects=side))
    assert [v.rule for v in online if v.entities == ("npc1",)][:1] == [Rule.CONTACT]


def test_struck_rules_come_from_the_config() -> None:
    params = PARAMS.with_overrides(safety={"struck_speed": 0.0, "struck_from_behind": False})
    verdict, online = judge(Oracle(None, None, params), _rear_ended(0.0))
    assert verdict.category_names() == ("Collisions",)
    with pytest.raises(InputError):
        PARAMS.with_overrides(safety={"struck_speed": -1.0})


# --- contact already present in the first frame: an invalid scenario ----------------------------------------------

def test_overlap_in_the_first_frame_is_an_error_never_a_fail() -> None:
    debris = lambda t: [car("obs1", t, 1.0, category="obstacle", is_static=True)]
    frames = straight_run(lambda t: 0.0, 2.0, objects=debris)
    for status in (finished(frames[-1].t, "collision"), None):       # ended by the player, or cut short
        verdict, online = judge(Oracle(None, None, PARAMS), frames, status)
        assert [v.rule for v in online] == [Rule.OVERLAP_AT_START]
        assert verdict.verdict is Verdict.ERROR and not verdict.categories
        assert verdict.error == "invalid scenario: entities overlap at start (ego and obs1)"
    # The same debris reached after the start is a contact judged as usual (a static hit in view: Misinterp).
    later = straight_run(lambda t: 2.0, 4.0, objects=lambda t: [car("obs1", t, 8.0, category="obstacle",
                                                                   is_static=True)])
    verdict, online = judge(Oracle(None, None, PARAMS), later)
    assert verdict.verdict is Verdict.FAIL and not any(v.rule is Rule.OVERLAP_AT_START for v in online)


def test_real_seed_with_debris_moved_under_the_ego_is_an_invalid_scenario(tmp_path) -> None:
    # A real seed (r512 of dev_gold) with its debris obs1 teleported onto the ego's start: the closed-loop run must
    # be an error of the scenario, not a Collision of the planner. (The seed generator itself keeps starts apart.)
    import copy

    from lxml import etree

    from txt2sce_ros.closed_loop import run_closed_loop
    from txt2sce_ros.paths import shared_dir
    from txt2sce_ros.seed.generate import write_seeds
    from txt2sce_ros.sketch import Sketch, load_sketches

    gold = shared_dir() / "data" / "reports" / "dev_gold.jsonl"
    sketch = next(s for s in load_sketches(gold) if isinstance(s, Sketch)
                  and s.report_id == "dmvca-ghostauton-20230814-r512")
    manifest = write_seeds([sketch], tmp_path)
    path = tmp_path / manifest["built"][0]["file"]
    clean, _ = run_closed_loop(path, time_limit=5.0)
    assert clean.to_dict()["verdict"] != "error"
    root = etree.parse(str(path))

    def teleport(name: str) -> etree._Element:
        return root.find(f"Storyboard/Init/Actions/Private[@entityRef='{name}']//TeleportAction/Position")

    target = teleport("obs1")
    target.getparent().replace(target, copy.deepcopy(teleport("ego")))
    root.write(str(path))
    record, _ = run_closed_loop(path, time_limit=5.0)
    d = record.to_dict()
    assert d["verdict"] == "error", d
    why = d["details"]["error"]
    assert "invalid scenario: entities overlap at start" in why and "obs1" in why and not d["categories"]
