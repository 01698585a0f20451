"""The AV's approach start (issue 16): a seed whose AV waits at the light it faces (a report of an AV stopped at a
red light) has no dilemma zone, so its tree gets an ego version started back on the same lane at speed, and a
budget puts the dilemma-zone yellow under that start; the stand-in's `red_light_misread` then enters on red where
the nominal planner stops. Seeds built by the seed stage from dev_gold."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

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


@pytest.fixture(scope="module")
def seeds(tmp_path_factory) -> dict[str, Path]:
    out = tmp_path_factory.mktemp("seeds")
    wanted = {AT_LINE_ALONE, AT_LINE_QUEUE, FAR}
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
