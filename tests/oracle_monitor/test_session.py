"""JudgeSession: runs cut out of a message stream in whatever order DDS delivered it."""

from __future__ import annotations

from dataclasses import replace

from oracle_monitor import OracleParams
from oracle_monitor.session import JudgeSession
from txt2sce_ros import contract as c
from txt2sce_ros import ros_io
from txt2sce_ros.contract import Goal, RunStatus, ScenarioEnvelope, Verdict

from .oracle_runs import car, esmini_map, straight_run

PARAMS = OracleParams.from_config()


def _feed(session: JudgeSession, frames) -> None:
    for f in frames:
        session.on_message(c.TOPIC_TRAFFIC_LIGHTS, ros_io.lights_to_diagnostics(f.lights, f.t))
        for o in f.objects:
            session.on_message(c.TOPIC_OBJECTS_ODOM, ros_io.entity_to_odometry(o))
        session.on_message(c.TOPIC_OBJECTS_MARKERS, ros_io.frame_to_markers(f))
        session.on_message(c.TOPIC_EGO_ODOM, ros_io.entity_to_odometry(f.ego))


def _env(sid: str) -> object:
    path = esmini_map("straight_500m.xodr")
    return ros_io.string_msg(ScenarioEnvelope(id=sid, xosc="", map_path=str(path)).to_json())


def _status(sid: str, state: str, t: float = 0.0, reason: str = "") -> object:
    return ros_io.string_msg(RunStatus(sid, state, t, reason).to_json())


def test_goal_before_scenario_duplicates_and_an_unfinished_run() -> None:
    s = JudgeSession(PARAMS)
    # Run a: its goal arrives before its scenario, the scenario is delivered twice (transient-local history).
    s.on_message(c.TOPIC_GOAL, ros_io.goal_to_pose(Goal(60.0, 0.0, 0.0)))
    s.on_message(c.TOPIC_SCENARIO, _env("a"))
    s.on_message(c.TOPIC_RUN_STATUS, _status("a", "started"))
    s.on_message(c.TOPIC_SCENARIO, _env("a"))
    _feed(s, straight_run(lambda t: 10.0, 6.0))
    s.on_message(c.TOPIC_RUN_STATUS, _status("a", "finished", 6.0, "goal_reached"))
    # Run b: never finishes; run c's scenario arrives, so b is judged as incomplete (no failure seen: error).
    s.on_message(c.TOPIC_SCENARIO, _env("b"))
    _feed(s, straight_run(lambda t: 10.0, 2.0))
    s.on_message(c.TOPIC_SCENARIO, _env("c"))
    # Run c: an entity named "Ego" on /sim/ego/odom (the scenario's own name) rear-ends a car; then input ends.
    frames = straight_run(lambda t: 10.0, 4.0, objects=lambda t: [car("lead", t, 30.0)])
    _feed(s, [replace(f, ego=replace(f.ego, name="Ego")) for f in frames])
    s.close()
    a, b, cc = s.verdicts
    assert (a.scenario_id, a.verdict) == ("a", Verdict.PASS) and a.frames == 121
    assert (b.scenario_id, b.verdict) == ("b", Verdict.ERROR) and "no final run status" in b.error
    assert cc.scenario_id == "c" and cc.verdict is Verdict.FAIL and cc.category_names() == ("Collisions",)
    assert not any("road network not loaded" in n for n in a.notes)


def test_a_bag_without_scenario_or_status_is_judged_as_one_incomplete_run() -> None:
    s = JudgeSession(PARAMS)
    _feed(s, straight_run(lambda t: 0.0, 7.0))                 # what `ros2 bag record` of odometry alone gives
    s.close()
    (v,) = s.verdicts
    assert v.verdict is Verdict.FAIL and v.category_names() == ("StartFail",)
    assert any("incomplete" in n for n in v.notes) and any("no road network" in n for n in v.notes)


def test_a_finished_status_overtaking_the_last_frames_is_held() -> None:
    frames = straight_run(lambda t: 10.0, 4.0, objects=lambda t: [car("lead", t, 36.2)])   # contact at ~3.1 s
    s = JudgeSession(PARAMS)
    s.on_message(c.TOPIC_SCENARIO, _env("a"))
    _feed(s, frames[:50])                                       # up to 2.45 s
    s.on_message(c.TOPIC_RUN_STATUS, _status("a", "finished", 4.0, "time_limit"))
    assert s.verdicts == []                                     # held: the frames up to 4.0 s are not in yet
    _feed(s, frames[50:])
    (v,) = s.verdicts
    assert v.frames == len(frames) and v.category_names() == ("Collisions",) and v.end_reason == "time_limit"
    # The next run's goal and scenario then start a new run, not a phantom one.
    s.on_message(c.TOPIC_GOAL, ros_io.goal_to_pose(Goal(60.0, 0.0, 0.0)))
    s.on_message(c.TOPIC_SCENARIO, _env("b"))
    _feed(s, straight_run(lambda t: 10.0, 6.0))
    s.on_message(c.TOPIC_RUN_STATUS, _status("b", "finished", 6.0, "goal_reached"))
    assert [x.scenario_id for x in s.verdicts] == ["a", "b"] and s.verdicts[1].verdict is Verdict.PASS


def test_frames_before_their_scenario_stay_in_one_run() -> None:
    # The player's goal, 'started' status and first frames overtake the generator's envelope.
    s = JudgeSession(PARAMS)
    frames = straight_run(lambda t: 10.0, 6.0)
    s.on_message(c.TOPIC_GOAL, ros_io.goal_to_pose(Goal(60.0, 0.0, 0.0)))
    _feed(s, frames[:5])
    s.on_message(c.TOPIC_RUN_STATUS, _status("a", "started"))
    _feed(s, frames[5:10])
    s.on_message(c.TOPIC_SCENARIO, _env("a"))
    _feed(s, frames[10:])
    s.on_message(c.TOPIC_RUN_STATUS, _status("a", "finished", 6.0, "goal_reached"))
    # The next run's frames come before its envelope too; the started status names it.
    s.on_message(c.TOPIC_RUN_STATUS, _status("b", "started"))
    _feed(s, frames[:3])
    s.on_message(c.TOPIC_SCENARIO, _env("b"))
    s.close()
    a, b = s.verdicts
    assert (a.scenario_id, a.verdict, a.frames) == ("a", Verdict.PASS, len(frames))
    assert b.scenario_id == "b" and b.frames == 3 and b.verdict is Verdict.ERROR


def _run_messages(sid: str, frames, goal: Goal, end: RunStatus) -> list[tuple[str, object]]:
    out = [(c.TOPIC_SCENARIO, _env(sid)), (c.TOPIC_RUN_STATUS, _status(sid, "started")),
           (c.TOPIC_GOAL, ros_io.goal_to_pose(goal))]
    for f in frames:
        out.append((c.TOPIC_TRAFFIC_LIGHTS, ros_io.lights_to_diagnostics(f.lights, f.t)))
        out.extend((c.TOPIC_OBJECTS_ODOM, ros_io.entity_to_odometry(o)) for o in f.objects)
        out.append((c.TOPIC_OBJECTS_MARKERS, ros_io.frame_to_markers(f)))
        out.append((c.TOPIC_EGO_ODOM, ros_io.entity_to_odometry(f.ego)))
    out.append((c.TOPIC_RUN_STATUS, ros_io.string_msg(end.to_json())))
    return out


def _lagging_delivery(messages, seed: int) -> list[tuple[str, object]]:
    """What a monitor that falls behind receives: the publisher runs ahead by random bursts; each executor round
    takes one available message per topic, topics in random order. Each topic keeps its own order."""
    import numpy as np

    rng = np.random.default_rng(seed)
    queues: dict[str, list[tuple[int, object]]] = {}
    for i, (topic, msg) in enumerate(messages):
        queues.setdefault(topic, []).append((i, msg))
    out, published = [], 0
    while any(queues.values()):
        published += int(rng.integers(1, 60))
        topics = [t for t, q in queues.items() if q and q[0][0] < published]
        for k in rng.permutation(len(topics)):
            out.append((topics[k], queues[topics[k]].pop(0)[1]))
    return out


def test_a_lagging_monitor_reaches_the_verdicts_of_in_order_delivery() -> None:
    goal = Goal(60.0, 0.0, 0.0)
    a = straight_run(lambda t: 10.0, 4.0, objects=lambda t: [car("lead", t, 36.2)])        # contact at ~3.17 s
    b = straight_run(lambda t: 10.0, 6.0, objects=lambda t: [car("far", t, 200.0, y=7.0)])  # reaches the goal
    msgs = (_run_messages("a", a, goal, RunStatus("a", "finished", 4.0, "time_limit"))
            + _run_messages("b", b, goal, RunStatus("b", "finished", 6.0, "goal_reached")))
    ref = JudgeSession(PARAMS)
    for topic, msg in msgs:
        ref.on_message(topic, msg)
    ref.close()
    expected = [v.to_dict() for v in ref.verdicts]
    assert [(v["scenario_id"], v["verdict"]) for v in expected] == [("a", "fail"), ("b", "pass")]
    for seed in range(12):
        s = JudgeSession(PARAMS)
        for topic, msg in _lagging_delivery(msgs, seed):
            s.on_message(topic, msg)
        s.close()
        assert [v.to_dict() for v in s.verdicts] == expected, seed


def test_a_run_broken_at_t0_then_a_run_from_t0() -> None:
    # The planner never answered: the player ends run a at t = 0 after one frame; run b starts at t = 0 too, so
    # no topic's stamps go back — the repeated stamps must still open run b.
    s = JudgeSession(PARAMS)
    s.on_message(c.TOPIC_SCENARIO, _env("a"))
    _feed(s, straight_run(lambda t: 10.0, 0.0, objects=lambda t: [car("x", t, 50.0), car("y", t, 80.0)]))
    s.on_message(c.TOPIC_RUN_STATUS, ros_io.string_msg(
        RunStatus("a", "finished", 0.0, "planner_not_responding", verdict_hint="error").to_json()))
    s.on_message(c.TOPIC_SCENARIO, _env("b"))
    _feed(s, straight_run(lambda t: 10.0, 6.0, objects=lambda t: [car("x", t, 150.0, y=7.0)]))
    s.on_message(c.TOPIC_RUN_STATUS, _status("b", "finished", 6.0, "goal_reached"))
    a, b = s.verdicts
    assert a.verdict is Verdict.ERROR and "planner_not_responding" in a.error
    assert (b.scenario_id, b.verdict, b.frames) == ("b", Verdict.PASS, 121)


def test_the_judged_runs_scenario_delivered_again_starts_no_run() -> None:
    # Transient-local history: a reader matched late gets run a's scenario again after a ended. That copy is no
    # run of its own (it was judged "nothing observed" beside a's real verdict); a replay of a, which the player
    # announces with a 'started' status, still is, and keeps a's scenario.
    s = JudgeSession(PARAMS)
    s.on_message(c.TOPIC_GOAL, ros_io.goal_to_pose(Goal(60.0, 0.0, 0.0)))
    s.on_message(c.TOPIC_SCENARIO, _env("a"))
    s.on_message(c.TOPIC_RUN_STATUS, _status("a", "started"))
    _feed(s, straight_run(lambda t: 10.0, 6.0))
    s.on_message(c.TOPIC_RUN_STATUS, _status("a", "finished", 6.0, "goal_reached"))
    s.on_message(c.TOPIC_SCENARIO, _env("a"))
    s.close()
    assert [(v.scenario_id, v.verdict) for v in s.verdicts] == [("a", Verdict.PASS)]
    s.on_message(c.TOPIC_RUN_STATUS, _status("a", "started"))
    s.on_message(c.TOPIC_GOAL, ros_io.goal_to_pose(Goal(60.0, 0.0, 0.0)))
    _feed(s, straight_run(lambda t: 10.0, 6.0))
    s.on_message(c.TOPIC_RUN_STATUS, _status("a", "finished", 6.0, "goal_reached"))
    replay = s.verdicts[-1]
    assert len(s.verdicts) == 2 and (replay.scenario_id, replay.verdict) == ("a", Verdict.PASS)
    assert not any("road network not loaded" in n for n in replay.notes)


def _player_messages(sid: str, frames, goal: Goal, end: RunStatus, late_scenario_at: int) -> list[tuple[str, object]]:
    """What the player node publishes for a run, the goal again with every frame, stamped with its time (before
    its ego odometry, as `PlayerNode.publish_frame` does), with the generator's envelope delivered late: after frame
    `late_scenario_at` (a reader matched to the generator after the run began gets it from transient-local
    history then)."""
    out = [(c.TOPIC_RUN_STATUS, _status(sid, "started"))]
    for k, f in enumerate(frames):
        if k == late_scenario_at:
            out.append((c.TOPIC_SCENARIO, _env(sid)))
        out.append((c.TOPIC_TRAFFIC_LIGHTS, ros_io.lights_to_diagnostics(f.lights, f.t)))
        out.extend((c.TOPIC_OBJECTS_ODOM, ros_io.entity_to_odometry(o)) for o in f.objects)
        out.append((c.TOPIC_OBJECTS_MARKERS, ros_io.frame_to_markers(f)))
        out.append((c.TOPIC_GOAL, ros_io.goal_to_pose(goal, f.t)))
        out.append((c.TOPIC_EGO_ODOM, ros_io.entity_to_odometry(f.ego)))
    out.append((c.TOPIC_RUN_STATUS, ros_io.string_msg(end.to_json())))
    return out


def test_the_goal_with_every_frame_and_a_scenario_arriving_mid_run() -> None:
    # Seen in the node graph under load: the goal repeated with every frame was deferred as the next run's, the
    # envelope arriving mid-run behind those repeats was deferred too, and after the verdict it opened a phantom
    # run ("nothing observed") while the real one had been judged without its road network.
    a = straight_run(lambda t: 10.0, 4.0, objects=lambda t: [car("lead", t, 36.2)])        # contact at ~3.17 s
    b = straight_run(lambda t: 10.0, 6.0, objects=lambda t: [car("far", t, 200.0, y=7.0)])  # reaches the goal
    msgs = (_player_messages("a", a, Goal(60.0, 0.0, 0.0), RunStatus("a", "finished", 4.0, "time_limit"), 22)
            + _player_messages("b", b, Goal(60.0, 0.0, 0.0), RunStatus("b", "finished", 6.0, "goal_reached"), 0))
    for seed in [None, *range(12)]:
        s = JudgeSession(PARAMS)
        for topic, msg in (msgs if seed is None else _lagging_delivery(msgs, seed)):
            s.on_message(topic, msg)
        s.close()
        got = [(v.scenario_id, v.verdict, v.frames) for v in s.verdicts]
        assert got == [("a", Verdict.FAIL, len(a)), ("b", Verdict.PASS, len(b))], (seed, got)
        assert s.verdicts[0].category_names() == ("Collisions",), seed
        assert not any("no road network" in n for v in s.verdicts for n in v.notes), seed


def test_a_run_named_by_its_status_then_its_late_scenario_starts_no_run() -> None:
    # The envelope of a run judged under the name its 'started' status gave arrives only after the verdict.
    s = JudgeSession(PARAMS)
    s.on_message(c.TOPIC_RUN_STATUS, _status("a", "started"))
    _feed(s, straight_run(lambda t: 10.0, 6.0))
    s.on_message(c.TOPIC_RUN_STATUS, _status("a", "finished", 6.0, "goal_reached"))
    s.on_message(c.TOPIC_SCENARIO, _env("a"))
    s.close()
    assert [(v.scenario_id, v.verdict) for v in s.verdicts] == [("a", Verdict.PASS)]
