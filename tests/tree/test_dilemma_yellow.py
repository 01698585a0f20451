"""The TLS mutation's yellow in the ego's dilemma zone (issue 9): on seeds the seed stage builds from dev_gold, the
yellow variant holds green until the ego is `yellow + margin` s from the stop line (standard OpenSCENARIO 1.0 that
esmini executes too: Init TrafficSignalStateActions + a signal Story whose yellow starts on a
TimeToCollisionCondition and whose later phases follow it by their delays), the scenario player executes it,
and the stand-in planner's `red_light_misread` fault is then caught as Misinterp while the nominal planner is not."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from lxml import etree

from txt2sce_ros.seed import write_seeds
from txt2sce_ros.seed.context import build_context
from txt2sce_ros.seed.signal_story import read_plan
from txt2sce_ros.sketch import load_sketches
from txt2sce_ros.tree import BlockKind, assemble, canonical, disassemble
from txt2sce_ros.tree.build import seed_key, tree_config
from txt2sce_ros.tree.environment import signal_timing, stop_line
from txt2sce_ros.tree.mutate import block_variants
from txt2sce_ros.tree.seeds import dev_gold_path
from txt2sce_ros.tree.xml import parse_bytes, parse_fragment
from txt2sce_ros.xosc.validate import validate_xosc

# r448 / r243: the ego drives at 8 m/s toward a signalised junction ~50 m ahead (r448 with a car close behind it,
# r243 with a party that turns across). r241: the ego stands at its stop line.
APPROACH = ("dmvca-waymo-20230405-r448", "dmvca-cruise-20211113-r243")
AT_LINE = "dmvca-apple-20211111-r241"


@pytest.fixture(scope="module")
def seeds(tmp_path_factory) -> dict[str, Path]:
    out = tmp_path_factory.mktemp("seeds")
    wanted = set(APPROACH) | {AT_LINE}
    manifest = write_seeds([s for s in load_sketches(dev_gold_path()) if s.report_id in wanted], out, seed=0)
    return {b["report_id"]: out / b["file"] for b in manifest["built"]}


def _signal_variants(seed: Path, cfg=None):
    data = seed.read_bytes()
    ctx = build_context(parse_bytes(data, str(seed)), source=str(seed), seed_path=seed)
    d = disassemble(data, source=str(seed))
    block = next(b for b in d.blocks if b.kind is BlockKind.SIGNAL)
    vs = block_variants(block, ctx, cfg or tree_config(), seed=0, seed_key=seed_key(seed.name))
    return d, block, {v.features[1]: v for v in vs}, ctx


def _node(seed: Path, state: str = "yellow", cfg=None) -> Path:
    """The seed with only its signal block replaced by the `state` variant, written beside it (maps resolve)."""
    d, block, by_state, _ = _signal_variants(seed, cfg)
    frags = d.originals()
    for slot, frag in zip(block.slots, by_state[state].fragments):
        frags[slot] = frag
    out = seed.parent / f"{seed.stem}_{state}.xosc"
    out.write_text(assemble(d.template, frags), encoding="utf-8")
    return out


def _plan(variant):
    parts = [parse_fragment(f) for f in variant.fragments]
    return read_plan(parts[:-1], parts[-1]), parts[-1]


def test_yellow_variant_waits_for_the_dilemma_zone_in_timed_state_actions(seeds):
    timing = signal_timing()
    for rid in APPROACH:
        seed = seeds[rid]
        d, block, by_state, ctx = _signal_variants(seed)
        sid = ctx.ego_signals[0]
        line = stop_line(ctx, sid)
        ego = ctx.starts["ego"]
        assert line is not None and line.road == ego.road and line.s - ego.s > 40.0, (rid, line, ego)
        # green and red run on the clock from t = 0; only yellow waits for the ego
        assert not _plan(by_state["green"])[0].triggered and not _plan(by_state["red"])[0].triggered
        plan, story = _plan(by_state["yellow"])
        assert plan.triggered
        assert [p.name for p in plan.plan.phases] == ["tls_yellow", "tls_red", "tls_red_clear", "tls_green"]
        assert dict(plan.waiting)[sid] == "green" and dict(plan.tested)[sid] == "yellow"
        # every phase starts on the dilemma-zone condition, delayed by its offset: 4 s of yellow, red, the red's
        # last 4 s clearing the crossing legs, then green
        events = story.findall(".//Event")
        delays = [float(e.find("StartTrigger//Condition").get("delay")) for e in events]
        assert delays == [0.0, timing.yellow, timing.red, timing.red + timing.yellow]
        assert all(next(e.iter("TimeToCollisionCondition")) is not None for e in events)
        assert not any(story.iter("TrafficSignalControllerAction"))     # only what esmini executes
        ttc = next(events[0].iter("TimeToCollisionCondition"))
        assert float(ttc.get("value")) == pytest.approx(timing.yellow + timing.margin)
        assert (ttc.get("rule"), ttc.get("freespace")) == ("lessThan", "true")
        assert next(story.iter("EntityRef")).get("entityRef") == "ego"
        lp = ttc.find("TimeToCollisionConditionTarget/Position/LanePosition")
        sig = ctx.network.signals[sid]
        assert (lp.get("roadId"), float(lp.get("s"))) == (str(sig.road_id), pytest.approx(sig.s))
        assert int(lp.get("laneId")) in sig.controlled_lanes
        # the written node validates and keeps the seed's stop trigger (goal, time limit)
        node = _node(seed)
        assert validate_xosc(node.read_bytes(), source=str(node)) == []
        stops = [canonical(etree.tostring(parse_bytes(f.read_bytes(), str(f)).find("Storyboard/StopTrigger")))
                 for f in (node, seed)]
        assert stops[0] == stops[1]


def _play(node: Path, faults: tuple[str, ...]):
    """Closed loop (player + stand-in planner + oracle) recording the ego's primary light and its front bumper's
    distance to that light's stop line."""
    from oracle_monitor import Oracle, OracleParams
    from scenario_player import Simulation, SimulationConfig, load_scenario
    from standin_planner import Faults, Planner, PlannerParams, friction_from_xosc

    sim = Simulation(load_scenario(str(node)), SimulationConfig(ego_mode="planner"))
    frame = sim.reset()
    planner = Planner(sim.network, sim.goal, PlannerParams.from_config(), faults=Faults.from_names(faults),
                      road_friction=friction_from_xosc(node.read_text(encoding="utf-8")))
    oracle = Oracle(sim.network, sim.goal, OracleParams.from_config())
    oracle.observe(frame)
    sid = build_context(parse_bytes(node.read_bytes(), str(node)), source=str(node), seed_path=node).ego_signals[0]
    rows = []
    while not sim.done:
        e = frame.ego
        light = next(li for li in frame.lights if li.id == sid)
        front = (e.x + (e.center_x + 0.5 * e.length) * math.cos(e.heading),
                 e.y + (e.center_x + 0.5 * e.length) * math.sin(e.heading))
        gap = (light.stop_x - front[0]) * math.cos(light.heading) + (light.stop_y - front[1]) * math.sin(light.heading)
        rows.append((frame.t, light.state.value, gap, e.speed))
        frame = sim.step(planner.step(frame))
        oracle.observe(frame)
    return rows, oracle.finish(sim.status)


def test_player_turns_yellow_when_the_ego_enters_the_dilemma_zone(seeds, tmp_path):
    from txt2sce_ros.cli.cmd_planner_check import strip_npcs

    timing = signal_timing()
    # without r448's follower, which rear-ends the ego as it stops for the yellow (the run would end there)
    rows, _ = _play(strip_npcs(_node(seeds[APPROACH[0]]), tmp_path), ())
    onset = next(i for i, r in enumerate(rows) if r[1] == "yellow")
    t0, _, gap, v = rows[onset]
    assert t0 > 0.5 and all(r[1] == "green" for r in rows[:onset])   # green while the ego is far
    # the condition held on the step before the light changed: `yellow + margin` s of travel from the line
    t_prev, _, gap_prev, v_prev = rows[onset - 1]
    assert gap_prev / v_prev < timing.yellow + timing.margin < rows[onset - 2][2] / rows[onset - 2][3]
    red = next(r for r in rows if r[1] == "red")
    assert red[0] - t_prev == pytest.approx(timing.yellow, abs=0.06)


@pytest.mark.parametrize("rid", APPROACH)
def test_red_light_misread_is_caught_and_the_nominal_planner_is_not(seeds, tmp_path, rid):
    from txt2sce_ros.cli.cmd_planner_check import strip_npcs
    from txt2sce_ros.closed_loop import run_closed_loop

    node = _node(seeds[rid])
    faulty, _ = run_closed_loop(node, faults=("red_light_misread",))
    nominal, _ = run_closed_loop(node, faults=())
    assert "Misinterp" in faulty.categories, faulty
    assert "Misinterp" not in nominal.categories, nominal
    # Alone on the road (its follower would rear-end it as it stops), the nominal planner stops at the yellow,
    # waits out the red and reaches the goal; the faulty one enters on red.
    alone = strip_npcs(node, tmp_path)
    rows, verdict = _play(alone, ())
    assert verdict.verdict.value == "pass" and verdict.end_reason == "goal_reached", verdict
    assert any(r[1] == "red" and r[3] < 0.05 and 0.0 < r[2] < 10.0 for r in rows)     # standing before the line
    rows, verdict = _play(alone, ("red_light_misread",))
    assert [f.category.value for f in verdict.categories] == ["Misinterp"], verdict
    assert not any(r[1] == "red" and r[3] < 0.05 and r[2] > 0.0 for r in rows)


def test_yellow_keeps_the_fixed_schedule_when_the_ego_starts_at_the_line(seeds):
    # An ego standing at its stop line, with no approach start free behind it (here: a car queued 40 m behind
    # and a minimum approach speed the room left cannot give), meets the yellow from t = 0 (as before): no
    # dilemma zone to wait for, and another block may start it up to `max_shift` m further ahead, past the line,
    # where the trigger never fires.
    seed = seeds[AT_LINE]
    cfg = tree_config()
    cfg["trajectory"]["init_location"]["approach_min_speed"] = 7.9
    _, _, by_state, ctx = _signal_variants(seed, cfg)
    shift = cfg["trajectory"]["init_location"]["max_shift"]
    assert stop_line(ctx, ctx.ego_signals[0]) is not None
    assert stop_line(ctx, ctx.ego_signals[0], slack=shift) is None
    assert by_state["yellow"].needs == ()
    assert not _plan(by_state["yellow"])[0].triggered
    rows, _ = _play(_node(seed, cfg=cfg), ())
    assert rows[0][1] == "yellow"
    # with the default minimum the queue leaves room for a slower approach, and the yellow waits under it
    _, _, by_state, _ = _signal_variants(seed)
    assert by_state["yellow"].needs == (("ego", "approach"),) and _plan(by_state["yellow"])[0].triggered
