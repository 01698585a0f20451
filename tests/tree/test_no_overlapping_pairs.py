"""A tree never writes a node whose block versions cannot stand together: the car the new-party slot places close
behind the seed's AV overlaps an AV started back on its approach to a light, so no node's chain holds both (the
campaign bench's r195 tree wrote 30 such nodes, each an `invalid scenario: entities overlap at start` error)."""

from __future__ import annotations

import json

from txt2sce_ros.seed import write_seeds
from txt2sce_ros.sketch import load_sketches
from txt2sce_ros.tree.build import build_tree, tree_config
from txt2sce_ros.tree.seeds import dev_gold_path

SEED = "dmvca-cruise-20210710-r195"  # the AV stands at a light with its lane behind free: it gets an approach start


def test_no_node_holds_the_approach_start_and_a_car_close_behind(tmp_path) -> None:
    manifest = write_seeds([s for s in load_sketches(dev_gold_path()) if s.report_id == SEED], tmp_path / "s", seed=0)
    (built,) = manifest["built"]
    out = tmp_path / "tree"
    build_tree(tmp_path / "s" / built["file"], out, cfg=tree_config(max_nodes=500))  # the campaign bench's budget
    nodes = {n["id"]: n for n in json.loads((out / "manifest.json").read_text())["nodes"]}

    def chain(node_id: str) -> list[str]:
        ops = []
        while node_id in nodes:
            ops.append(nodes[node_id]["operator"])
            node_id = nodes[node_id]["parent"]
        return ops

    chains = [chain(k) for k in nodes]
    assert any("WPM-approach" in c for c in chains) and any("NCM-new:close_behind" in c for c in chains)
    assert not [c for c in chains if "WPM-approach" in c and "NCM-new:close_behind" in c]
