"""Tree building: the Sum formula, one block per child, determinism, validity of every file."""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

from txt2sce_ros.tree import canonical, disassemble
from txt2sce_ros.tree.build import build_tree, build_trees, expected_nodes, tree_config
from txt2sce_ros.xosc.validate import qc_errors, validate_xosc

from .conftest import CUT_IN, JUNCTION


def _digest(root: Path) -> str:
    h = hashlib.sha256()
    for f in sorted(root.rglob("*")):
        if f.is_file():
            h.update(str(f.relative_to(root)).encode())
            h.update(f.read_bytes())
    return h.hexdigest()


def test_expected_nodes_is_the_papers_sum():
    assert expected_nodes([2, 2, 2]) == 2 + 4 + 8
    assert expected_nodes([5, 7, 3]) == 5 + 35 + 105
    assert expected_nodes([]) == 0


def test_unpruned_node_count_equals_sum_formula(tmp_path):
    cfg = tree_config(prune_share=1.0, mutations=2)
    cfg["tree"]["new_party_slots"] = 0      # the formula, not the new party (tests/tree/test_reach.py): fewer files
    res = build_tree(CUT_IN, tmp_path / "t", seed=3, cfg=cfg)
    # ego: a standing start + 2, weather 5 types, npc1 7 categories + one started close to the ego (WPM-near),
    # 2 events x 2, new obstacle 2
    assert res.block_counts == (3, 5, 8, 2, 2, 2)
    assert res.expected == 3 + 15 + 120 + 240 + 480 + 960
    assert res.nodes == res.expected and res.invalid == 0 and not res.truncated
    files = list((tmp_path / "t" / "nodes").glob("n*.xosc"))
    assert len(files) == res.expected
    manifest = json.loads((tmp_path / "t" / "manifest.json").read_text())
    assert len(manifest["nodes"]) == res.expected + 1  # + the root (the seed itself)
    by_depth = {}
    for n in manifest["nodes"]:
        by_depth[n["depth"]] = by_depth.get(n["depth"], 0) + 1
    assert [by_depth[d] for d in range(1, 7)] == [3, 15, 120, 240, 480, 960]


def test_mutation_count_changes_the_tree(tmp_path):
    res = build_tree(CUT_IN, tmp_path / "t", seed=3, cfg=tree_config(prune_share=1.0, mutations=1))
    # ego: WPM-init + standing start; weather; the new party: 4 roles; npc1: 7 categories + WPM-near
    assert res.block_counts == (2, 5, 4, 8, 1, 1, 1)
    assert res.nodes == expected_nodes(res.block_counts)


def test_each_child_adds_exactly_one_block(tmp_path):
    """Disassemble parent and child files: they differ in the fragments of the block the child added, nowhere
    else; and the manifest records the operator and the old -> new values of that block."""
    out = tmp_path / "t"
    build_tree(JUNCTION, out, seed=1, cfg=tree_config(prune_share=1.0, max_nodes=0))
    manifest = json.loads((out / "manifest.json").read_text())
    nodes = {n["id"]: n for n in manifest["nodes"]}
    checked = 0
    for n in manifest["nodes"][1::97]:  # a spread sample across all depths
        parent = nodes[n["parent"]]
        def blocks(node):
            d = disassemble((out / node["file"]).read_bytes())
            return {b.key: [canonical(f) for f in b.fragments if f] for b in d.blocks}

        bp, bc = blocks(parent), blocks(n)
        differing = sorted(k for k in set(bp) | set(bc) if bp.get(k) != bc.get(k))
        assert set(differing) <= {n["block_key"]}
        if n["changes"]:
            assert differing == [n["block_key"]]
        assert n["path"][:-1] == parent["path"] and n["depth"] == parent["depth"] + 1
        assert n["operator"] and isinstance(n["rng_seed"], int)
        checked += 1
    assert checked > 50


def test_same_seed_same_bytes_other_seed_other_bytes(tmp_path):
    cfg = tree_config()
    build_trees([JUNCTION, CUT_IN], tmp_path / "a", seed=7, cfg=cfg, jobs=1)
    build_trees([JUNCTION, CUT_IN], tmp_path / "b", seed=7, cfg=cfg, jobs=2)  # process count must not matter
    build_trees([JUNCTION, CUT_IN], tmp_path / "c", seed=8, cfg=cfg, jobs=1)
    assert _digest(tmp_path / "a") == _digest(tmp_path / "b")
    assert _digest(tmp_path / "a") != _digest(tmp_path / "c")


def test_every_generated_file_is_schema_valid_and_a_sample_is_qc_clean(tmp_path):
    out = tmp_path / "t"
    res = build_tree(JUNCTION, out, seed=5, cfg=tree_config(validate=False, max_nodes=800))  # check here
    files = sorted((out / "nodes").glob("*.xosc"))
    assert len(files) == res.nodes + 1
    for f in files:
        assert validate_xosc(f.read_bytes(), source=str(f)) == [], f.name
    for f in files[:: max(1, len(files) // 12)]:
        assert qc_errors(f) == [], f.name


def test_generated_files_point_at_the_seeds_map(tmp_path):
    out = tmp_path / "deep" / "t"
    build_tree(CUT_IN, out, seed=0, cfg=tree_config(mutations=1))
    f = out / "nodes" / "n0.xosc"
    from lxml import etree

    logic = etree.parse(str(f)).find("RoadNetwork/LogicFile").get("filepath")
    assert (f.parent / logic).resolve().name == "e6mini.xodr"
    assert (f.parent / logic).resolve().is_file()


def test_pruning_keeps_at_least_half_of_each_cluster(tmp_path):
    full = build_tree(JUNCTION, tmp_path / "full", seed=2, cfg=tree_config(prune_share=1.0, max_nodes=0))
    half = build_tree(JUNCTION, tmp_path / "half", seed=2, cfg=tree_config(prune_share=0.5, max_nodes=0))
    assert half.pruned > 0 and half.nodes < full.nodes
    assert half.nodes >= full.nodes // 2 ** len(full.block_counts)


def test_node_budget_thins_layers_but_inserts_every_block(tmp_path):
    res = build_tree(JUNCTION, tmp_path / "t", seed=4, cfg=tree_config(prune_share=1.0, max_nodes=300))
    assert res.truncated and res.nodes <= 300
    manifest = json.loads((tmp_path / "t" / "manifest.json").read_text())
    depths = {n["depth"] for n in manifest["nodes"]}
    assert depths == set(range(0, len(res.block_counts) + 1))  # the deepest layer (obstacles) is still there
    # within a thinned layer, distinct categories go before repeats: all 7 NPC categories survive
    npc_nodes = [n for n in manifest["nodes"] if n["block_kind"] == "npc"]
    assert {n["variant"] for n in npc_nodes} == set(range(7))


def test_node_validation_reports_schema_errors():
    from txt2sce_ros.tree.build import _node_problems

    text = JUNCTION.read_text()
    assert _node_problems(text, "1.0") == []
    bad = _node_problems(text.replace('cloudState="free"', 'cloudState="drizzle"'), "1.0")
    assert bad and "drizzle" in bad[0]
    cut = _node_problems(text[:-40], "1.0")  # not well-formed: reported, not raised
    assert cut and cut[0].startswith("line ") and "not well-formed" in cut[0]


def test_node_budget_keeps_every_value_of_enumerated_blocks(tmp_path):
    # Cut-in seed: weather (5 types) and npc1 (7 categories) are enumerated. A budget far below the full tree
    # (1,065 nodes) must still insert every weather type and every category (a cyclist is a test condition of its
    # own), while staying within the cap and still inserting the deeper (event, obstacle) blocks.
    cap = 30
    res = build_tree(CUT_IN, tmp_path / "t", seed=3, cfg=tree_config(prune_share=1.0, mutations=2, max_nodes=cap))
    assert res.truncated and res.nodes <= cap
    manifest = json.loads((tmp_path / "t" / "manifest.json").read_text())
    counts = dict(zip(manifest["insertion"], manifest["block_counts"]))
    seen: dict[int, set[int]] = {}
    for n in manifest["nodes"][1:]:
        seen.setdefault(n["block"], set()).add(n["variant"])
    kinds = {n["block"]: n["block_kind"] for n in manifest["nodes"][1:]}
    assert set(kinds.values()) >= {"weather", "npc", "event"}
    for block, kind in kinds.items():
        if kind in ("weather", "npc"):
            assert seen[block] == set(range(counts[block])), (kind, seen[block])


def test_estimate_counts_exactly_what_the_build_writes(tmp_path):
    from txt2sce_ros.tree.build import estimate_tree

    for settings in ({"prune_share": 0.5, "max_nodes": 0}, {"prune_share": 1.0, "max_nodes": 300}):
        cfg = tree_config(**settings)
        est = estimate_tree(JUNCTION, seed=3, cfg=cfg)
        assert not any((tmp_path / "t").rglob("*.xosc"))          # the estimate writes nothing
        res = build_tree(JUNCTION, tmp_path / "t", seed=3, cfg=cfg)
        assert est.nodes == res.nodes
        written = sum(f.stat().st_size for f in (tmp_path / "t").rglob("*") if f.is_file())
        assert 0.8 * written < est.bytes < 1.25 * written
        for f in (tmp_path / "t").rglob("*"):
            if f.is_file():
                f.unlink()


def test_tree_cli_says_how_much_it_writes_and_dry_run_writes_nothing(tmp_path, capsys):
    from txt2sce_ros.cli.main import main

    assert main(["tree", str(JUNCTION), "--out", str(tmp_path / "dry"), "--dry-run"]) == 0
    assert "files" in capsys.readouterr().err and not (tmp_path / "dry").exists()
    assert main(["tree", str(JUNCTION), "--out", str(tmp_path / "t"), "--max-nodes", "40"]) == 0
    err = capsys.readouterr().err
    said = int(err.split("about ")[1].split(" files")[0].replace(",", ""))
    assert said == sum(1 for f in (tmp_path / "t").rglob("*") if f.is_file())
    assert str((tmp_path / "t").resolve()) in err


def test_node_budget_keeps_a_standing_and_a_moving_start(tmp_path):
    # The cut-in seed's AV drives off at speed; the ego layer's versions are a standing start (TSM-start) and
    # moved starts. A small budget keeps both start states (start refusals need one, a conflict timed for a moving
    # AV the other), and both meet later layers' versions (weather types spread over them).
    res = build_tree(CUT_IN, tmp_path / "t", seed=0, cfg=tree_config(mutations=1, max_nodes=14))
    assert res.truncated and res.nodes <= 14
    nodes = json.loads((tmp_path / "t" / "manifest.json").read_text())["nodes"][1:]
    ego = {n["id"]: n["operator"] for n in nodes if n["block_kind"] == "ego"}
    assert sorted(ego.values()) == ["TSM-start", "WPM-init"]
    under = {op: [n for n in nodes if n["block_kind"] == "weather" and n["parent"] == i] for i, op in ego.items()}
    assert under["TSM-start"] and under["WPM-init"]

