"""Table V from tree manifests, pruning helpers, and the `txt2sce tree` / `tree show` / `diversity` commands."""

from __future__ import annotations

import json

import numpy as np
import pytest

from txt2sce_ros.cli.main import main
from txt2sce_ros.errors import InputError
from txt2sce_ros.tree.build import build_tree, tree_config
from txt2sce_ros.tree.diversity import diversity, node_vectors
from txt2sce_ros.tree.prune import clusters, keep_count, prune, spread

from .conftest import CUT_IN, JUNCTION


def test_prune_keeps_ceil_share_of_every_cluster():
    vectors = ["a", "b", "a", "a", "c", "b"]
    assert clusters(vectors) == [[0, 2, 3], [1, 5], [4]]
    kept = prune(vectors, 0.5, np.random.default_rng(0))
    groups = {v: sum(1 for i in kept if vectors[i] == v) for v in "abc"}
    assert groups == {"a": 2, "b": 1, "c": 1}
    assert prune(vectors, 1.0, np.random.default_rng(0)) == list(range(6))
    assert prune(vectors, 0.5, np.random.default_rng(3)) == prune(vectors, 0.5, np.random.default_rng(3))
    assert keep_count(1, 0.1) == 1 and keep_count(10, 0.25) == 3
    assert spread([10, 11, 12, 13], ["x", "x", "y", "x"], 2) == [10, 12]


def test_table_v_counts_levels_and_categories(tmp_path):
    build_tree(JUNCTION, tmp_path / "j", seed=0, cfg=tree_config(max_nodes=0))
    build_tree(CUT_IN, tmp_path / "c", seed=0, cfg=tree_config(max_nodes=0))
    t = diversity([tmp_path])
    rows = {r.level: r for r in t.rows}
    assert t.trees == 2
    m_j = json.loads((tmp_path / "j" / "manifest.json").read_text())
    m_c = json.loads((tmp_path / "c" / "manifest.json").read_text())
    assert t.files == m_j["nodes_written"] + m_c["nodes_written"]
    assert rows["Weather"].abstract == 1               # both seeds are sunny
    assert rows["Event Sequence"].abstract == 2        # go_straight+turn_left, go_straight+lane_change_right
    assert rows["Entity Configuration"].abstract == 2  # {car, debris} and {car}
    # every weather type appears in both trees; binned parameters make more variants than types
    assert rows["Weather"].variants >= 5
    # the entity configuration enumerates 7 NPC categories x obstacle placements
    assert rows["Entity Configuration"].variants >= 7
    vecs = set(node_vectors(m_j)) | set(node_vectors(m_c))
    assert t.unique_categories == len(vecs) <= t.files


def test_cli_build_show_and_diversity(tmp_path, capsys):
    out = tmp_path / "trees"
    assert main(["tree", str(CUT_IN), "--out", str(out), "--seed", "2", "--mutations", "1", "--prune", "1",
                 "--jobs", "1"]) == 0
    text = capsys.readouterr().out
    # ego: a standing start + WPM-init; weather; the new party: 3 roles; npc1: 7 categories + WPM-near
    assert "highway_cut_in_seed" in text and "2x5x4x8x1x1x1" in text
    tree_dir = out / "highway_cut_in_seed"
    assert main(["tree", "show", str(tree_dir), "--depth", "2"]) == 0
    text = capsys.readouterr().out
    assert "npc1_e2_lane_change_right" in text and "+environment [WM]" in text
    png = tree_dir / "tree.png"
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert (tree_dir / "tree.dot").read_text().startswith("digraph")
    import networkx as nx

    g = nx.read_graphml(tree_dir / "tree.graphml")
    assert g.number_of_nodes() == g.number_of_edges() + 1  # a tree
    assert main(["diversity", str(out)]) == 0
    text = capsys.readouterr().out
    assert "Event Sequence" in text and "Unique scenario categories" in text


def test_cli_errors_are_one_line(tmp_path, capsys):
    assert main(["tree", str(tmp_path / "missing.xosc"), "--out", str(tmp_path)]) == 2
    assert "no such seed" in capsys.readouterr().err
    with pytest.raises(InputError):
        diversity([tmp_path / "nothing"])


def test_sample_check_runs_qc_and_player(tmp_path):
    from txt2sce_ros.tree.checks import check_sample, sample_files

    build_tree(CUT_IN, tmp_path / "c", seed=0, cfg=tree_config(max_nodes=200))
    files = sample_files([tmp_path / "c"], 6, seed=1)
    assert len(files) == 6 and files == sample_files([tmp_path / "c"], 6, seed=1)
    chk = check_sample([tmp_path / "c"], 6, seed=1)
    assert chk.checked == 6 and chk.qc_failed == 0 and chk.player_available and chk.player_failed == 0


def test_a_directory_without_trees_is_refused(tmp_path, capsys):
    (tmp_path / "empty").mkdir()
    for argv in (["diversity", str(tmp_path / "empty")], ["tree", "show", str(tmp_path / "empty")]):
        assert main(argv) == 2
        err = capsys.readouterr().err
        assert "holds no scenario tree" in err and "Traceback" not in err


def test_a_seed_directory_is_not_taken_for_a_tree(tmp_path, capsys):
    # Seeds and trees both keep a manifest.json; a seed directory given where trees are read is named as such.
    seeds = tmp_path / "seeds"
    seeds.mkdir()
    (seeds / "manifest.json").write_text(json.dumps({"built": [{"file": "a.xosc"}], "refused": []}))
    for argv in (["diversity", str(seeds)], ["tree", "show", str(seeds)]):
        assert main(argv) == 2
        err = capsys.readouterr().err
        assert "a seed directory, not a scenario tree" in err and "Traceback" not in err


def test_a_mutation_config_need_hold_only_what_it_changes(tmp_path, capsys):
    # Every setting a user's file leaves out keeps the bundled value; a misspelled section is refused.
    part = tmp_path / "mutation.yaml"
    part.write_text("tree:\n  mutations_per_block: 1\n")
    assert main(["tree", str(CUT_IN), "--out", str(tmp_path / "t"), "--config", str(part), "--max-nodes", "8"]) == 0
    (manifest,) = (tmp_path / "t").glob("*/manifest.json")
    assert json.loads(manifest.read_text())["settings"]["mutations_per_block"] == 1
    capsys.readouterr()
    typo = tmp_path / "typo.yaml"
    typo.write_text("tre:\n  mutations_per_block: 1\n")
    assert main(["tree", str(CUT_IN), "--out", str(tmp_path / "u"), "--config", str(typo)]) == 2
    err = capsys.readouterr().err
    assert "typo.yaml, <tre>: unknown section" in err and "Traceback" not in err
