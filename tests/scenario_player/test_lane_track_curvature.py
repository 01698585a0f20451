"""A lane track's `ds_per_metre` skips the reference line's geometry look-up where every geometry under the track
has one constant curvature (lines, arcs): the answer must be the looked-up one, bit for bit, at any s."""

from __future__ import annotations

import math

import numpy as np
import pytest

from scenario_player.world.lanes import LaneTrack
from txt2sce_ros.paths import shared_dir
from txt2sce_ros.road import LaneRef, load_network

XODR = shared_dir() / "data" / "conformance" / "esmini" / "xodr"
MAPS = sorted(p.stem for p in XODR.glob("*.xodr")) if XODR.is_dir() else []


@pytest.mark.parametrize("name", MAPS)
def test_ds_per_metre_equals_the_looked_up_curvature(name: str) -> None:
    net = load_network(XODR / f"{name}.xodr")
    rng = np.random.default_rng(5)
    shortcut = 0
    for rid, road in net.roads.items():
        starts = [g.s for g in road.plan_view.geometries]
        for si, sec in enumerate(road.sections):
            for lid in sec.lanes:
                if lid == 0:
                    continue
                fast = LaneTrack(net, LaneRef(rid, si, lid))
                slow = LaneTrack(net, LaneRef(rid, si, lid))
                slow._k_lo, slow._k_hi = math.inf, -math.inf      # always the geometry look-up
                shortcut += fast._k_lo <= fast.s0
                # inside, at and just around the track's ends and every geometry start, and outside the road
                probes = list(rng.uniform(fast.s0, fast.s1, 40)) + [fast.s0, fast.s1, -5.0, road.length + 5.0]
                for g0 in starts:
                    probes += [g0, math.nextafter(g0, -math.inf), math.nextafter(g0, math.inf)]
                for s in probes:
                    for offset in (0.0, -1.3, 2.0):
                        assert fast.ds_per_metre(s, offset) == slow.ds_per_metre(s, offset), (name, rid, lid, s)
    if name in ("straight_500m", "fabriksgatan", "multi_intersections"):
        assert shortcut > 0         # maps of lines and arcs: the shortcut is taken (and checked above)
