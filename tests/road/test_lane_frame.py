"""`lane_frame_array` gives, in one evaluation, the same bits as `lane_to_world_array`, `reference` and
`lane_bounds` called separately (the scenario player's lane tracks take all of them from it)."""

from __future__ import annotations

import numpy as np
import pytest

from .conftest import XODR, esmini_map

MAPS = sorted(p.stem for p in XODR.glob("*.xodr")) if XODR.is_dir() else []


@pytest.mark.parametrize("name", MAPS)
def test_lane_frame_is_the_separate_evaluations(esmini_dir, name: str) -> None:
    net = esmini_map(name)
    checked = 0
    for rid, road in net.roads.items():
        for si, sec in enumerate(road.sections):
            end = min(sec.end, road.length) if sec.end > sec.s else road.length
            s = np.linspace(sec.s, end, 57)
            s[-1] = end - 1e-9
            for lid in sec.lanes:
                if lid == 0:
                    continue
                for offset in (0.0, 0.4):
                    x, y, h, href, inner, outer = net.lane_frame_array(rid, lid, s, offset, section=si)
                    want = net.lane_to_world_array(rid, lid, s, offset, section=si)
                    assert all(a.tobytes() == b.tobytes() for a, b in zip((x, y, h), want))
                    assert href.tobytes() == net.reference(rid, s)[2].tobytes()
                    i2, o2 = net.lane_bounds(rid, lid, s, si)
                    assert inner.tobytes() == i2.tobytes() and outer.tobytes() == o2.tobytes()
                    checked += 1
    assert checked > 0
