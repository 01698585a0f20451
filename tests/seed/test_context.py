"""Seed context for the tree's context-aware mutations, on real generated seeds."""

from __future__ import annotations

import pytest

from txt2sce_ros.errors import InputError
from txt2sce_ros.seed import write_seeds
from txt2sce_ros.seed.context import SeedContext
from txt2sce_ros.seed.model import LanePose


@pytest.fixture(scope="module")
def seeds(tmp_path_factory, gold):
    d = tmp_path_factory.mktemp("ctx")
    ids = ["dmvca-waymo-20211008-r227", "dmvca-apple-20211111-r241"]
    manifest = write_seeds([gold[i] for i in ids], d)
    return {b["report_id"]: d / b["file"] for b in manifest["built"]}


def test_starts_match_the_plan(seeds) -> None:
    ctx = SeedContext.from_file(seeds["dmvca-apple-20211111-r241"])
    assert ctx.entities[:2] == ["ego", "npc1"]
    ego, npc = ctx.start("ego"), ctx.start("npc1")
    assert isinstance(ego, LanePose) and isinstance(npc, LanePose)
    assert ctx.is_drivable(ego.road_id, ego.lane_id, ego.s)
    assert not ctx.is_drivable(ego.road_id, 0, ego.s) and not ctx.is_drivable("nope", -1, 1.0)
    # the van starts behind the AV in the same lane (R6 same)
    assert (npc.road_id, npc.lane_id) == (ego.road_id, ego.lane_id)


def test_reachable_lanes_and_shift(seeds) -> None:
    ctx = SeedContext.from_file(seeds["dmvca-apple-20211111-r241"])
    lanes = ctx.reachable_lanes("npc1", max_back=60.0)
    assert lanes[0].distance == 0.0 and lanes[0].ref == ctx.start_lane("npc1")
    # with lane changes, the neighbour lanes of the same road lead there too
    assert len({r.ref.lane_id for r in lanes}) >= 2
    only_follow = ctx.reachable_lanes("npc1", max_back=60.0, lane_changes=False)
    assert len(only_follow) < len(lanes)
    st = ctx.start("npc1")
    back = ctx.shift_start("npc1", -10.0)
    assert back.road_id == st.road_id and abs(abs(back.s - st.s) - 10.0) < 1e-6
    with pytest.raises(InputError):
        ctx.shift_start("npc1", 500.0)   # past the junction: the lane branches
    with pytest.raises(InputError):
        ctx.start("npc9")


def test_tree_facing_fields_agree_with_the_seed_api(seeds) -> None:
    """The tree reads the same context: lane starts as written, the ego route from the start, the map view."""
    ctx = SeedContext.from_file(seeds["dmvca-waymo-20211008-r227"])
    ego, written = ctx.start("ego"), ctx.starts["ego"]
    assert (written.road, written.lane, written.s, written.offset) == (ego.road_id, ego.lane_id, ego.s, ego.offset)
    first = ctx.ego_route[0]
    assert (first.road, first.lane) == (written.road, written.lane)
    assert ctx.must_reach["ego"][:len(ctx.ego_route) - 1] == ctx.ego_route[1:]
    assert ctx.map is not None and ctx.map.lane_type(written.road, written.lane, written.s) == "driving"
    assert ctx.map.lane_type(written.road, 0, written.s) != "driving"
    assert ctx.categories["ego"] and set(ctx.starts) <= set(ctx.categories)


def test_seed_without_map_gives_a_context_whose_map_queries_raise(seeds) -> None:
    from lxml import etree

    path = seeds["dmvca-apple-20211111-r241"]
    root = etree.fromstring(path.read_bytes())
    rn = root.find("RoadNetwork")
    rn.remove(rn.find("LogicFile"))
    ctx = SeedContext.from_text(etree.tostring(root), base_dir=path.parent, source="nomap")
    assert ctx.map is None and "ego" in ctx.starts
    with pytest.raises(InputError, match="LogicFile"):
        ctx.start("ego")
