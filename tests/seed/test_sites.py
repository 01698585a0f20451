"""Map sites are the map database's answers re-shaped into lane references (bundled and esmini maps)."""

from __future__ import annotations

from pathlib import Path

import pytest

from txt2sce_ros.mapdb import Control, load_map_database
from txt2sce_ros.paths import BUNDLED_MAPS, shared_dir
from txt2sce_ros.seed.sites import junction_sites, road_sites

ESMINI = shared_dir() / "data" / "conformance" / "esmini" / "xodr"


def _esmini(name: str) -> Path:
    p = ESMINI / name
    if not p.is_file():
        pytest.skip(f"shared data missing: {p}")
    return p


def test_junction_sites_follow_the_database() -> None:
    path = BUNDLED_MAPS / "junction4_signal.xodr"
    db = load_map_database(path)
    sites = junction_sites(path)
    assert len(sites) == sum(len(db.approaches(j.id)) for j in db.junctions())
    for site in sites:
        rel = db.relative_approaches(site.junction_id, site.ego.road_id)
        assert {k: v.road_id for k, v in site.legs.items()} == {k: v.road_id for k, v in rel.items() if v}
        app = db.approach(site.junction_id, site.ego.road_id)
        assert [r.lane_id for r in site.ego.lanes] == [ln.lane_id for ln in app.lanes]
        assert site.signalised and site.kind == "junction4"
        # every turn leads into a connecting road of this junction, entered where its lane starts
        for ref, conns in site.ego.turns:
            for turn, conn in conns:
                assert conn.road_id in db.junction_infos[site.junction_id].connecting_roads
                assert turn in {t.value for t in db.approach(site.junction_id, ref.road_id).lanes[
                    site.ego.lanes.index(ref)].turns}


def test_stop_lines_at_lights_are_not_stop_signs() -> None:
    """multi_intersections has lights and stop lines (DE 294) on its approaches: signalised, not stop-sign
    approaches (the database's control classification)."""
    path = _esmini("multi_intersections.xodr")
    db = load_map_database(path)
    sites = junction_sites(path)
    lit = [s for s in sites if db.approach(s.junction_id, s.ego.road_id).control is Control.SIGNAL]
    assert lit and all(s.signalised and not s.ego.stop_sign for s in lit)


def test_road_sites_curb_lanes_stop_at_the_carriageway_edge() -> None:
    """On the left-hand-traffic e6mini the lanes right of the AV's rightmost lane are the outer border lanes, never
    the other carriageway's driving lanes."""
    sites = road_sites(_esmini("e6mini-lht.xodr"))
    assert sites
    for s in sites:
        assert "driving" not in s.curb_lanes
        assert len(s.lanes) == 3 and s.kind in ("straight", "curve")
