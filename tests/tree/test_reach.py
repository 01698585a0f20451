"""Reach (issue 16): the tree brings trigger conditions into seeds that lack them, where the road allows — a new
party on the AV's path (a cyclist ahead, a lead that brakes, a car close behind, a pedestrian who starts to
cross), a standing start — and layers under a node budget spread their versions over different parents."""

from __future__ import annotations

from pathlib import Path

import pytest
from lxml import etree

from txt2sce_ros.analysis.features import scenario_elements
from txt2sce_ros.road import load_network
from txt2sce_ros.seed.context import build_context
from txt2sce_ros.tree import BlockKind, assemble, disassemble
from txt2sce_ros.tree.build import seed_key, tree_config
from txt2sce_ros.tree.mutate import block_variants
from txt2sce_ros.tree.prune import diagonal
from txt2sce_ros.tree.xml import parse_bytes
from txt2sce_ros.xosc.validate import validate_xosc

from .conftest import CUT_IN


def _with(d, block, variant) -> str:
    frags = d.originals()
    for slot, frag in zip(block.slots, variant.fragments):
        frags[slot] = frag
    return assemble(d.template, frags)


def _write(path: Path, text: str) -> Path:
    path.write_text(text, encoding="utf-8")
    return path


def _new_party_nodes(seed: Path, out: Path) -> dict[str, Path]:
    data = seed.read_bytes()
    ctx = build_context(parse_bytes(data, str(seed)), source=str(seed), seed_path=seed)
    d = disassemble(data, source=str(seed), new_party_slots=1)
    block = next(b for b in d.blocks if b.kind is BlockKind.NEW_PARTY)
    assert block.fragments == ("", "", "") and block.key == "npc2"         # the seed has npc1
    vs = block_variants(block, ctx, tree_config(), seed=0, seed_key=seed_key(seed.name))
    nodes = {}
    for v in vs:
        text = _with(d, block, v)
        assert validate_xosc(text) == [], v.operator
        nodes[v.operator.split(":")[1]] = _write(out / f"{v.operator.split(':')[1]}.xosc", text)
    return nodes


@pytest.fixture(scope="module")
def party_nodes(tmp_path_factory) -> dict[str, Path]:
    # beside the seed, so its relative map path resolves
    out = CUT_IN.parent
    nodes = _new_party_nodes(CUT_IN, out)
    yield nodes
    for p in nodes.values():
        p.unlink()


def _elements(path: Path) -> frozenset[str]:
    ctx = build_context(parse_bytes(path.read_bytes(), str(path)), source=str(path), seed_path=path)
    return scenario_elements(path.read_bytes(), load_network(str(ctx.map_path)))


def test_new_party_roles_bring_their_trigger_conditions(party_nodes):
    assert set(party_nodes) == {"cyclist_ahead", "lead_brakes", "close_behind", "crossing"}
    cyc, lead, close = (_elements(party_nodes[r]) for r in ("cyclist_ahead", "lead_brakes", "close_behind"))
    assert {"category:bicycle", "position:R5/same"} <= cyc and "near_start:yes" not in cyc
    assert {"category:car", "position:R5/same", "events:h", "R5+h"} <= lead
    assert "position:R6/same" in close and "near_start:yes" not in close      # the seed's AV drives off...
    standing = party_nodes["close_behind"].read_bytes().replace(
        b'<Private entityRef="ego">', b'<Private entityRef="ego">', 1)
    root = parse_bytes(standing, "close_behind")
    root.find("Storyboard/Init/Actions/Private[@entityRef='ego']//AbsoluteTargetSpeed").set("value", "0")
    ctx = build_context(root, source="close_behind", seed_path=party_nodes["close_behind"])
    assert "near_start:yes" in scenario_elements(etree.tostring(root), load_network(str(ctx.map_path)))  # ...or stands
    seed = _elements(CUT_IN)
    assert not {"category:bicycle", "events:h", "near_start:yes"} & seed        # none of them was in the seed


def test_cyclist_ahead_is_hit_only_with_ignore_cyclists(party_nodes):
    from txt2sce_ros.closed_loop import run_closed_loop

    nominal, _ = run_closed_loop(party_nodes["cyclist_ahead"], time_limit=20.0)
    faulty, _ = run_closed_loop(party_nodes["cyclist_ahead"], faults=("ignore_cyclists",), time_limit=20.0)
    assert "Collisions" not in nominal.categories
    assert "Collisions" in faulty.categories


def test_standing_start_lets_no_start_when_close_refuse(party_nodes, tmp_path):
    """The close_behind car with the ego's standing start (TSM-start): the faulty planner never moves off."""
    from txt2sce_ros.closed_loop import run_closed_loop

    root = parse_bytes(party_nodes["close_behind"].read_bytes(), "close_behind")
    ego_speed = root.find("Storyboard/Init/Actions/Private[@entityRef='ego']//AbsoluteTargetSpeed")
    assert float(ego_speed.get("value")) > 0
    ego_speed.set("value", "0")          # what the ego layer's TSM-start version writes
    node = _write(CUT_IN.parent / "close_behind_standing.xosc", etree.tostring(root, encoding="unicode"))
    try:
        nominal, _ = run_closed_loop(node, time_limit=15.0)
        faulty, _ = run_closed_loop(node, faults=("no_start_when_close",), time_limit=15.0)
    finally:
        node.unlink()
    assert "StartFail" not in nominal.categories
    assert "StartFail" in faulty.categories


def test_diagonal_spreads_versions_over_parents():
    # 5 parents x 2 versions, room for 4: every parent but one gets a child, the versions alternate
    assert diagonal(list(range(10)), 2, 4) == [0, 3, 4, 7]
    # an enumerated layer of 3 values under 2 parents, room for 3: each value once, not all under parent 0
    assert diagonal(list(range(6)), 3, 3, cover=True) == [0, 2, 4]
    assert diagonal([1, 2], 3, 5) == [1, 2]                            # under the budget: all kept


def test_inert_faults_are_read_from_the_scenario(party_nodes):
    from standin_planner.faults import inert_faults

    def inert(p: Path) -> frozenset[str]:
        return inert_faults(parse_bytes(p.read_bytes(), str(p)))

    assert inert(CUT_IN) == {"ignore_cyclists", "red_light_misread"}
    assert inert(party_nodes["cyclist_ahead"]) == {"red_light_misread"}


def test_crossing_pedestrian_starts_when_the_av_is_near_and_is_hit_only_when_seen_late(party_nodes, tmp_path):
    """NCM-new crossing: a pedestrian beside the AV's lane walks across it once the AV's time to the crossing point
    is the walk's time to the lane centre. The nominal planner sees it start and brakes in time; `stale_tracking`
    (object states a second old) sees it late and hits it — from a moving start and from a standing one."""
    from txt2sce_ros.closed_loop import run_closed_loop

    elements = _elements(party_nodes["crossing"])
    assert {"category:pedestrian", "events:m"} <= elements and "events:m" not in _elements(CUT_IN)
    root = parse_bytes(party_nodes["crossing"].read_bytes(), "crossing")
    ttc = root.find(".//Event[@name='npc2_e1_cross']/StartTrigger//TimeToCollisionCondition")
    assert ttc is not None and 1.0 < float(ttc.get("value")) < 3.0
    ego_speed = root.find("Storyboard/Init/Actions/Private[@entityRef='ego']//AbsoluteTargetSpeed")
    assert float(ego_speed.get("value")) > 0
    ego_speed.set("value", "0")                 # the ego layer's TSM-start version
    standing = _write(CUT_IN.parent / "crossing_standing.xosc", etree.tostring(root, encoding="unicode"))
    try:
        for node in (party_nodes["crossing"], standing):
            nominal, _ = run_closed_loop(node, time_limit=20.0)
            faulty, _ = run_closed_loop(node, faults=("stale_tracking",), time_limit=20.0)
            assert nominal.verdict.value != "error" and "Collisions" not in nominal.categories, node.name
            assert "Collisions" in faulty.categories, node.name
    finally:
        standing.unlink()
