"""TLS reach (issue 16): a seed whose report named no light, on a map with lights facing the AV, gets a signal plan of
its own from the tree (the `new_signal` slot), in the timed form both players execute; its yellow waits for the
AV's dilemma zone, so `red_light_misread` can be caught there. Seeds the road gives no reachable light get none."""

from __future__ import annotations

from pathlib import Path

import pytest

from txt2sce_ros.analysis.features import elements_of_file
from txt2sce_ros.seed import write_seeds
from txt2sce_ros.seed.context import build_context
from txt2sce_ros.seed.signal_story import plan_of
from txt2sce_ros.sketch import load_sketches
from txt2sce_ros.tree import BlockKind, assemble, disassemble
from txt2sce_ros.tree.build import reachable_elements, seed_key, tree_config
from txt2sce_ros.tree.mutate import block_variants
from txt2sce_ros.tree.seeds import dev_gold_path
from txt2sce_ros.tree.xml import parse_bytes
from txt2sce_ros.xosc.validate import validate_xosc

from tests.txt2sce_ros.test_analysis import _plain_elements_of_file

# r497: the AV drives toward a signalised junction whose lights the report never mentions (no plan in the seed).
# r537: lights on the map, but the AV's route never reaches a stop line. r150: a straight road, no lights at all.
# r448: the report names a signal (the seed has its own plan: the `signal` block, not a new one).
NO_PLAN, UNREACHABLE, NO_LIGHTS, WITH_PLAN = ("dmvca-waymo-20230711-r497", "dmvca-apple-20231013-r537",
                                              "dmvca-cruise-20210113-r150", "dmvca-waymo-20230405-r448")


@pytest.fixture(scope="module")
def seeds(tmp_path_factory) -> dict[str, Path]:
    out = tmp_path_factory.mktemp("seeds")
    wanted = {NO_PLAN, UNREACHABLE, NO_LIGHTS, WITH_PLAN}
    manifest = write_seeds([s for s in load_sketches(dev_gold_path()) if s.report_id in wanted], out, seed=0)
    return {b["report_id"]: out / b["file"] for b in manifest["built"]}


def _new_signal(seed: Path):
    data = seed.read_bytes()
    ctx = build_context(parse_bytes(data, str(seed)), source=str(seed), seed_path=seed)
    d = disassemble(data, source=str(seed), new_signal_slot=True)
    blocks = [b for b in d.blocks if b.kind is BlockKind.NEW_SIGNAL]
    vs = block_variants(blocks[0], ctx, tree_config(), seed=0, seed_key=seed_key(seed.name)) if blocks else []
    return d, blocks, vs


def _node(seed: Path, d, block, variant) -> tuple[Path, str]:
    """The seed with only its new-signal slot filled by `variant`, written beside it (its map resolves)."""
    frags = d.originals()
    for slot, frag in zip(block.slots, variant.fragments):
        frags[slot] = frag
    text = assemble(d.template, frags)
    node = seed.parent / f"{seed.stem}_{variant.features[1]}.xosc"
    node.write_text(text, encoding="utf-8")
    return node, text


def test_a_seed_without_a_plan_gets_one_per_state(seeds):
    seed = seeds[NO_PLAN]
    assert plan_of(parse_bytes(seed.read_bytes(), str(seed))) is None
    assert "signal:none" in elements_of_file(str(seed))
    d, blocks, vs = _new_signal(seed)
    assert len(blocks) == 1 and blocks[0].fragments == ("", "")          # empty in the seed: Init slot + Story slot
    assert [v.features[1] for v in vs] == ["yellow", "red", "green"]    # config signal_states, enumerated
    assert "signal:yellow" in reachable_elements(seed)                  # what seed picking counts
    for v in vs:
        node, text = _node(seed, d, blocks[0], v)
        assert validate_xosc(text) == [], v.features
        plan = plan_of(parse_bytes(text, str(node)))
        # the analysis labels the node by the state the AV's light shows in the plan's first phase
        assert f"signal:{v.features[1]}" in elements_of_file(str(node))
        assert elements_of_file(str(node)) == _plain_elements_of_file(str(node))     # parsed once, as per step
        assert plan is not None and plan.triggered == (v.features[1] == "yellow")   # yellow: dilemma-zone trigger


def test_red_light_misread_runs_the_new_yellow(seeds):
    from txt2sce_ros.closed_loop import run_closed_loop

    seed = seeds[NO_PLAN]
    d, blocks, vs = _new_signal(seed)
    node, _ = _node(seed, d, blocks[0], vs[0])
    nominal, _ = run_closed_loop(node, time_limit=20.0)
    faulty, _ = run_closed_loop(node, faults=("red_light_misread",), time_limit=20.0)
    assert "Misinterp" not in nominal.categories
    assert "Misinterp" in faulty.categories
    # the seed itself (lights off) does not catch it: the light is what the tree brought in
    seed_run, _ = run_closed_loop(seed, faults=("red_light_misread",), time_limit=20.0)
    assert "Misinterp" not in seed_run.categories


def test_no_new_signal_where_the_road_has_none_to_reach_or_the_seed_has_one(seeds):
    for rid in (UNREACHABLE, NO_LIGHTS):
        _, blocks, vs = _new_signal(seeds[rid])
        assert len(blocks) == 1 and vs == [], rid                        # a slot, but nothing the road allows
        assert "signal:yellow" not in reachable_elements(seeds[rid])
    _, blocks, _ = _new_signal(seeds[WITH_PLAN])
    assert blocks == []                                                  # its own plan is the `signal` block
