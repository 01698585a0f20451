"""TLS reach where the seed's route ends short of the light the AV faces (environment.through_light): the ego
block's approach version carries the route and the run's end through the junction, so a dilemma-zone yellow of
the new signal plan is met at all, and the stand-in's `red_light_misread` is caught there while the nominal
planner is not. r399: the AV drives on a signalised approach and its report's conflict (and goal) lies ~85 m
short of the stop line; its seed has no signal plan (the report named no light)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from lxml import etree

from txt2sce_ros.seed import write_seeds
from txt2sce_ros.seed.context import SeedContext
from txt2sce_ros.sketch import load_sketches
from txt2sce_ros.tree.build import build_tree, tree_config
from txt2sce_ros.tree.seeds import dev_gold_path

SEED = "dmvca-cruise-20221116-r399"


@pytest.fixture(scope="module")
def tree(tmp_path_factory) -> tuple[Path, Path, dict]:
    tmp = tmp_path_factory.mktemp("through")
    manifest = write_seeds([s for s in load_sketches(dev_gold_path()) if s.report_id == SEED], tmp / "s", seed=0)
    (built,) = manifest["built"]
    seed = tmp / "s" / built["file"]
    build_tree(seed, tmp / "tree", cfg=tree_config(max_nodes=150, mutations=1))   # the effectiveness study's
    return seed, tmp / "tree", json.loads((tmp / "tree" / "manifest.json").read_text())


def _yellow_nodes_through(manifest: dict) -> list[str]:
    nodes = {n["id"]: n for n in manifest["nodes"]}
    yellow = {(b["index"], v["index"]) for b in manifest["blocks"] if b["kind"] in ("signal", "new_signal")
              for v in b["variants"] if "yellow" in v["features"]}

    def chain(i: str) -> list[dict]:
        out = []
        while i in nodes:
            out.append(nodes[i])
            i = nodes[i]["parent"]
        return out

    return sorted(k for k in nodes if any(n["operator"] == "WPM-approach+route" for n in chain(k))
                  and any((n["block"], n["variant"]) in yellow for n in chain(k)))


def _goal_positions(root: etree._Element) -> list[tuple[str, str]]:
    route_end = root.find("Storyboard/Init/Actions/Private[@entityRef='ego']/PrivateAction/RoutingAction/"
                          "AssignRouteAction/Route/Waypoint[last()]/Position/LanePosition")
    stop = root.find("Storyboard/StopTrigger/ConditionGroup/Condition[@name='ego_goal_reached']//LanePosition")
    return [(lp.get("roadId"), lp.get("s")) for lp in (route_end, stop)]


def test_the_route_and_the_run_end_go_through_the_light(tree) -> None:
    seed, out, manifest = tree
    ctx = SeedContext.from_file(seed)
    ego = ctx.starts["ego"]
    sig = ctx.network.signals[ctx.ego_signals[0]]
    # the seed: the route ends on the start road short of the line, so no yellow is ever met
    assert {road for road, _ in _goal_positions(ctx.root)} == {ego.road}
    assert ctx.ego_route[-1].s < sig.s
    found = _yellow_nodes_through(manifest)
    assert found, "no yellow node under the approach carried through the light"
    node = SeedContext.from_file(out / "nodes" / f"{found[0]}.xosc")
    (road, s), stop = _goal_positions(node.root)
    assert stop == (road, s) and road != ego.road and not node.map.in_junction(road)
    start = node.starts["ego"]
    # started on the approach: ahead of the seed's start, short of the line
    assert ego.s < start.s < sig.s


def test_red_light_misread_is_caught_there_and_the_nominal_planner_is_not(tree) -> None:
    from txt2sce_ros.closed_loop import run_closed_loop

    _seed, out, manifest = tree
    node = out / "nodes" / f"{_yellow_nodes_through(manifest)[0]}.xosc"
    faulty, _ = run_closed_loop(node, faults=("red_light_misread",))
    nominal, _ = run_closed_loop(node, faults=())
    assert "Misinterp" in faulty.categories, faulty
    assert "Misinterp" not in nominal.categories, nominal
