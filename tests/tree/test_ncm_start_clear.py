"""NCM never starts a party overlapping another entity: the category's new size is kept clear of every start in any
lane (trajectory.clear_of_starts). Study sketch r7578-v2's motorcycle starts beside the AV (a world start, the first
vertex of its own path); as a car, van or truck it reached into the AV, and every descendant of those versions
started in a collision (90 of the 147 nodes of its tree at the study's settings before). r107's party, on a lane, is moved back instead."""

from __future__ import annotations

import json
from pathlib import Path

from txt2sce_ros.paths import shared_dir
from txt2sce_ros.seed import write_seeds
from txt2sce_ros.sketch import load_sketches
from txt2sce_ros.tree.build import build_tree, tree_config
from txt2sce_ros.tree.overlaps import main as overlaps_main
from txt2sce_ros.tree.overlaps import overlapping_starts as _overlapping

STUDY = shared_dir() / "data" / "reports" / "dev_gold_study.jsonl"


def _tree(rid: str, tmp: Path) -> Path:
    manifest = write_seeds([s for s in load_sketches(STUDY) if s.report_id == rid], tmp / "s", seed=0)
    (built,) = manifest["built"]
    build_tree(tmp / "s" / built["file"], tmp / "tree", cfg=tree_config(max_nodes=150, mutations=1))
    return tmp / "tree"


def test_no_node_of_r7578_starts_a_party_inside_the_av(tmp_path) -> None:
    out = _tree("nhtsa-sgo-ads-30610-7578-v2", tmp_path)
    nodes = sorted((out / "nodes").glob("n*.xosc"))
    assert len(nodes) >= 100
    assert [n.name for n in nodes if _overlapping(n)] == []
    assert overlaps_main([str(out)]) == 0
    blocks = json.loads((out / "manifest.json").read_text())["blocks"]
    cats = [v["features"][1] for b in blocks if b["key"] == "npc1" for v in b["variants"]]
    # the categories whose footprint fits where the motorcycle starts stay; the ones that overlap go
    assert "motorcycle" in cats and "pedestrian" in cats and "car" not in cats


def test_a_lane_start_is_moved_back_clear_rather_than_dropped(tmp_path) -> None:
    out = _tree("dmvca-zoox-20200108-r107", tmp_path)
    blocks = json.loads((out / "manifest.json").read_text())["blocks"]
    cats = [v["features"][1] for b in blocks if b["key"] == "npc1" for v in b["variants"]]
    assert {"car", "van", "truck", "bus"} <= set(cats)
    nodes = sorted((out / "nodes").glob("n*.xosc"))
    assert [n.name for n in nodes if ("npc1", "ego") in _overlapping(n) or ("ego", "npc1") in _overlapping(n)] == []
