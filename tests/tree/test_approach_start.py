"""The AV's approach start (issue 16): a seed whose AV waits at the light it faces (a report of an AV stopped at a
red light) has no dilemma zone, so its tree gets an ego version started back on the same lane at speed, and a
budget puts the dilemma-zone yellow under that start; the stand-in's `red_light_misread` then enters on red where
the nominal planner stops. Seeds built by the seed stage from dev_gold."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from lxml import etree

from txt2sce_ros.seed import write_seeds
from txt2sce_ros.seed.context import build_context
from txt2sce_ros.sketch import load_sketches
from txt2sce_ros.tree import BlockKind, disassemble
from txt2sce_ros.tree.build import build_tree, seed_key, tree_config
from txt2sce_ros.tree.environment import approach_start, signal_timing
from txt2sce_ros.tree.mutate import block_variants
from txt2sce_ros.tree.seeds import dev_gold_path
from txt2sce_ros.tree.trajectory import footprint_extent
from txt2sce_ros.tree.xml import parse_bytes

AT_LINE_ALONE = "dmvca-cruise-20230421-r455"     # the AV stands at its stop line, no party in its lane behind
AT_LINE_QUEUE = "dmvca-apple-20211111-r241"      # the AV stands at its line, a car 40 m behind it in its lane
FAR = "dmvca-waymo-20230405-r448"                # the AV drives at 8 m/s, ~50 m from its line
TURNING = "dmvca-waymo-20210712-r196"            # the AV near its line, its route turns left beyond it
TURNING_FAR = "dmvca-cruise-20210421-r176"       # the AV at 8 m/s ~53 m from its line, turning right beyond it


@pytest.fixture(scope="module")
def seeds(tmp_path_factory) -> dict[str, Path]:
    out = tmp_path_factory.mktemp("seeds")
    wanted = {AT_LINE_ALONE, AT_LINE_QUEUE, FAR, TURNING, TURNING_FAR}
    manifest = write_seeds([s for s in load_sketches(dev_gold_path()) if s.report_id in wanted], out, seed=0)
    return {b["report_id"]: out / b["file"] for b in manifest["built"]}


def _ctx(seed: Path):
    return build_context(parse_bytes(seed.read_bytes(), str(seed)), source=str(seed), seed_path=seed)


def _approach(seed: Path):
    init = tree_config()["trajectory"]["init_location"]
    return approach_start(_ctx(seed), speed=init["approach_speed"], margin=init["margin"], min_gap=init["min_gap"])


def _variants(seed: Path, kind: BlockKind):
    ctx = _ctx(seed)
    block = next(b for b in disassemble(seed.read_bytes(), source=str(seed)).blocks if b.kind is kind)
    return block_variants(block, ctx, tree_config(), seed=0, seed_key=seed_key(seed.name))


def test_approach_only_where_the_seed_start_is_too_close_and_the_lane_behind_is_free(seeds):
    timing = signal_timing()
    found = _approach(seeds[AT_LINE_ALONE])
    assert found is not None
    ctx = _ctx(seeds[AT_LINE_ALONE])
    ego = ctx.starts["ego"]
    front = footprint_extent(ctx.root.find("Entities/ScenarioObject[@name='ego']"))[1]
    sign = ctx.map.direction(ego.road, ego.lane)
    # from its new start the front bumper is `lead` s of travel short of the dilemma zone
    gap = sign * (found.line.s - found.s) - front
    assert gap == pytest.approx(found.speed * (timing.yellow + timing.margin + timing.lead), abs=0.01)
    assert found.speed == tree_config()["trajectory"]["init_location"]["approach_speed"]   # it stood: road speed
    assert found.line.road == ego.road and sign * (found.line.s - ego.s) < gap
    # the queue's order holds (the AV would have to start behind the car behind it) / the start already approaches
    assert _approach(seeds[AT_LINE_QUEUE]) is None
    assert _approach(seeds[FAR]) is None


def test_ego_version_and_the_yellow_that_needs_it(seeds):
    seed = seeds[AT_LINE_ALONE]
    ego = _variants(seed, BlockKind.EGO)
    assert [v.features[1] for v in ego if v.operator == "WPM-approach"] == ["approach"]
    assert [v.features[1] for v in ego if v.operator != "WPM-approach"].count("approach") == 0
    by_state = {v.features[1]: v for v in _variants(seed, BlockKind.SIGNAL)}
    assert by_state["yellow"].needs == (("ego", "approach"),)
    assert any("TimeToCollisionCondition" in f for f in by_state["yellow"].fragments)    # waits for the zone
    assert by_state["red"].needs == () and by_state["green"].needs == ()
    # a seed whose own start approaches the light: no such version, no premise
    assert all(v.operator != "WPM-approach" for v in _variants(seeds[FAR], BlockKind.EGO))
    assert all(v.needs == () for v in _variants(seeds[FAR], BlockKind.SIGNAL))


def test_thin_budget_keeps_the_yellow_under_the_approach_and_the_fault_enters_on_red(seeds, tmp_path):
    from txt2sce_ros.closed_loop import run_closed_loop

    out = tmp_path / "tree"
    build_tree(seeds[AT_LINE_ALONE], out, cfg=tree_config(max_nodes=14))
    nodes = json.loads((out / "manifest.json").read_text(encoding="utf-8"))["nodes"]
    by_id = {n["id"]: n for n in nodes}
    yellow = [n for n in nodes if n["block_kind"] == "signal"
              and "dilemma_zone" in (out / n["file"]).read_text(encoding="utf-8")]
    assert len(yellow) == 1
    chain = [yellow[0]]
    while chain[-1]["parent"] != "root":
        chain.append(by_id[chain[-1]["parent"]])
    assert chain[-1]["operator"] == "WPM-approach"
    node = out / yellow[0]["file"]
    faulty, _ = run_closed_loop(node, faults=("red_light_misread",))
    nominal, _ = run_closed_loop(node, faults=())
    assert "Misinterp" in faulty.categories, faulty
    assert "Misinterp" not in nominal.categories, nominal


def _configured(seed: Path, **overrides):
    from txt2sce_ros.tree.environment import configured_approach

    init = {**tree_config()["trajectory"]["init_location"], **overrides}
    return configured_approach(_ctx(seed), init)


def test_a_queue_behind_gets_a_shorter_slower_approach_clear_of_it(seeds):
    # r241: a car 40 m behind the AV in its lane. The full approach would start the AV behind it; the start
    # furthest back that keeps its footprint `min_gap` clear of the car's is used, at the speed that still gives
    # the `lead` before the dilemma zone.
    timing = signal_timing()
    init = tree_config()["trajectory"]["init_location"]
    seed = seeds[AT_LINE_QUEUE]
    found = _configured(seed)
    assert found is not None
    assert init["approach_min_speed"] <= found.speed < init["approach_speed"]
    ctx = _ctx(seed)
    ego = ctx.starts["ego"]
    sign = ctx.map.direction(ego.road, ego.lane)
    e_rear, e_front = footprint_extent(ctx.root.find("Entities/ScenarioObject[@name='ego']"))
    assert sign * (found.line.s - found.s) - e_front == pytest.approx(
        found.speed * (timing.yellow + timing.margin + timing.lead), abs=0.01)
    behind = [(name, pos) for name, pos in ctx.starts.items()
              if name != "ego" and (pos.road, pos.lane) == (ego.road, ego.lane)]
    assert behind
    for name, pos in behind:
        rear, front = footprint_extent(ctx.root.find(f"Entities/ScenarioObject[@name='{name}']"))
        assert sign * (found.s - pos.s) + e_rear - front >= init["min_gap"] - 1e-6      # its nose, our tail
    # below `approach_min_speed` there is none
    assert _configured(seed, approach_min_speed=found.speed + 0.01) is None


def test_the_approach_is_made_at_the_speed_of_the_turn_beyond_the_light(seeds):
    # r196: the AV turns left in the junction beyond its light; arriving at 8 m/s it would slow for the turn
    # after the yellow's onset (timed at its speed) and meet the red far enough back to stop, whatever it made of
    # the yellow. The approach is made at the turn's speed at `approach_lateral_accel`.
    from txt2sce_ros.tree.environment import turn_speed

    init = tree_config()["trajectory"]["init_location"]
    seed = seeds[TURNING]
    ctx = _ctx(seed)
    v_turn = turn_speed(ctx, init["approach_lateral_accel"])
    assert v_turn is not None and 3.0 < v_turn < init["approach_speed"]
    assert _configured(seed).speed == pytest.approx(v_turn)
    # a gentler comfort limit means a slower approach; a straight route has no turn speed
    assert turn_speed(ctx, 1.0) == pytest.approx(v_turn * (1.0 / init["approach_lateral_accel"]) ** 0.5)
    assert turn_speed(_ctx(seeds[FAR]), init["approach_lateral_accel"]) is None


def test_a_start_far_enough_but_faster_than_the_turn_keeps_its_place_at_the_turn_speed(seeds):
    # r176: far enough back for the dilemma zone at 8 m/s, but it would slow for its right turn after the onset;
    # the turn's own approach would start it ahead of its seed start, past positions it must still reach, so the
    # approach is its seed start at the turn's speed. Only that ego version counts as the approach (same place
    # as the seed's own start: told apart by its speed).
    from txt2sce_ros.tree.environment import turn_speed

    init = tree_config()["trajectory"]["init_location"]
    seed = seeds[TURNING_FAR]
    ctx = _ctx(seed)
    found = _configured(seed)
    assert found is not None and found.s == pytest.approx(ctx.starts["ego"].s)
    assert found.speed == pytest.approx(turn_speed(ctx, init["approach_lateral_accel"])) and found.speed < 8.0
    ego = _variants(seed, BlockKind.EGO)
    assert [v.operator for v in ego if v.features[1] == "approach"] == ["WPM-approach"]
    assert _approach(seed) is None          # without the turn limit: the seed's start already approaches


def test_the_red_comes_early_for_an_ego_that_speeds_up_and_catches_the_misreading_stack(seeds, tmp_path):
    # On r241's shorter approach (5 m/s) the AV speeds up toward its cruise after the onset: at the fixed 4 s of
    # yellow a stack that reads yellow as green would clear on yellow. The red comes once the AV is
    # `tls.arrival` s from the line (after `tls.min_yellow`): that stack enters on red, the nominal one stops.
    from txt2sce_ros.closed_loop import run_closed_loop
    from txt2sce_ros.tree.xml import parse_bytes as parse

    out = tmp_path / "tree"
    build_tree(seeds[AT_LINE_QUEUE], out, cfg=tree_config(max_nodes=20))
    nodes = json.loads((out / "manifest.json").read_text(encoding="utf-8"))["nodes"]
    node = next(out / n["file"] for n in nodes if n["block_kind"] == "signal"
                and "dilemma_zone" in (out / n["file"]).read_text(encoding="utf-8"))
    timing = signal_timing()
    states: list[tuple[float, str]] = []

    def light(frame):
        states.append((frame.t, "".join(sorted({li.state.value for li in frame.lights if li.id == "1010"}))))

    faulty, _ = run_closed_loop(node, faults=("red_light_misread",), on_frame=light)
    nominal, _ = run_closed_loop(node, faults=())
    assert "Misinterp" in faulty.categories, faulty
    assert "Misinterp" not in nominal.categories, nominal
    onset = next(t for t, s in states if s == "yellow")
    red = next(t for t, s in states if s == "red" and t > onset)
    assert timing.min_yellow - 0.06 <= red - onset < timing.yellow - 0.1          # early, after the minimum
    # the same node with only the fixed red: the faulty stack clears on yellow
    root = parse(node.read_bytes(), str(node))
    for group in root.iter("ConditionGroup"):
        if any(c.get("name", "").endswith("_early") for c in group):
            group.getparent().remove(group)
    fixed = node.with_name("fixed.xosc")
    fixed.write_bytes(etree.tostring(root, xml_declaration=True, encoding="UTF-8"))
    faulty_fixed, _ = run_closed_loop(fixed, faults=("red_light_misread",))
    assert "Misinterp" not in faulty_fixed.categories, faulty_fixed
