"""A tree writes no node whose AV starts overlapping another entity: two block versions that each move an initial
position (the AV's start state, a party placed close at the start) can land two footprints on one spot, and every
run of such a node would end as an invalid scenario. The study sketch below grew seven such nodes in session 8's
effectiveness draws (its AV's start shifts onto the motorcycle's path)."""

from __future__ import annotations

import json

from oracle_monitor.geometry import footprint, overlaps
from scenario_player import Simulation, SimulationConfig, load_scenario
from txt2sce_ros.seed import write_seeds
from txt2sce_ros.sketch import load_sketches
from txt2sce_ros.tree.build import build_tree, tree_config
from txt2sce_ros.tree.seeds import dev_gold_path

SKETCH = "nhtsa-sgo-ads-30610-7578-v2"


def test_nodes_whose_av_starts_on_another_entity_are_not_written(tmp_path) -> None:
    study = dev_gold_path().with_name("dev_gold_study.jsonl")
    manifest = write_seeds([s for s in load_sketches(study) if s.report_id == SKETCH], tmp_path / "s", seed=0)
    (built,) = manifest["built"]
    out = tmp_path / "tree"
    result = build_tree(tmp_path / "s" / built["file"], out, cfg=tree_config(max_nodes=150))
    tree = json.loads((out / "manifest.json").read_text())
    refused = [e for e in tree["errors"] if "entities overlap at t=0 (ego and npc1)" in e]
    assert refused and result.invalid == len(refused) == tree["invalid"]
    written = sorted((out / "nodes").glob("n*.xosc"))
    assert len(written) == result.nodes > 100
    for f in written:             # the player's own first frame, the oracle's contact test
        frame = Simulation(load_scenario(f), SimulationConfig(ego_mode="storyboard")).reset()
        ego = footprint(frame.ego)
        assert not [o.name for o in frame.objects if overlaps(ego, footprint(o))], f.name
    assert not {e.split(":")[0] for e in refused} & {f.stem for f in written}
