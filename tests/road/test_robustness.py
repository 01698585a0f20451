"""Damaged real maps: every failure is an InputError naming the file, never another exception."""

from __future__ import annotations

import numpy as np
from lxml import etree

from txt2sce_ros.errors import InputError
from txt2sce_ros.road import RoadNetwork

from .conftest import XODR

GARBAGE = ("", "x", "nan", "inf", "-1", "1e400", "0", "-0.5", "999999")


def _exercise(net: RoadNetwork) -> None:
    """Touch every part a consumer would: geometry, lanes, lookup, topology."""
    for road in net.roads.values():
        for lid in net.lane_ids(road.id, road.length / 2, types=None):
            net.lane_to_world(road.id, lid, road.length / 2)
    net.world_to_lane(np.array([0.0, 10.0]), np.array([0.0, -5.0]), lane_types=None)
    _ = net.routing_graph


def test_truncated_maps_raise_input_error(esmini_dir) -> None:
    rng = np.random.default_rng(7)
    for name in ("fabriksgatan.xodr", "e6mini.xodr", "multi_intersections.xodr"):
        data = (XODR / name).read_bytes()
        for cut in rng.integers(1, len(data) - 20, 15):
            try:
                RoadNetwork(data[:cut], f"{name}[:{cut}]")
            except InputError as exc:
                assert f"{name}[:{cut}]" in str(exc)
            else:
                raise AssertionError(f"{name} truncated at {cut} loaded")


def test_damaged_maps_never_escape_as_other_exceptions(esmini_dir) -> None:
    """Random damage (an attribute set to garbage, an element removed, an element's attributes dropped) either
    still loads and answers queries, or raises InputError naming the file."""
    rng = np.random.default_rng(11)
    for name in ("fabriksgatan_traffic_lights.xodr", "soderleden.xodr", "two_plus_one.xodr", "curves.xodr",
                 "e6mini-lht.xodr", "parking_demo.xodr"):
        original = (XODR / name).read_bytes()
        for trial in range(30):
            tree = etree.fromstring(original)
            els = [el for el in tree.iter() if isinstance(el.tag, str)]
            el = els[int(rng.integers(len(els)))]
            op = int(rng.integers(3))
            if op == 0 and el.attrib:
                att = list(el.attrib)[int(rng.integers(len(el.attrib)))]
                el.set(att, GARBAGE[int(rng.integers(len(GARBAGE)))])
            elif op == 1 and el.getparent() is not None:
                el.getparent().remove(el)
            else:
                for att in list(el.attrib):
                    del el.attrib[att]
            source = f"{name}#{trial}"
            try:
                _exercise(RoadNetwork(etree.tostring(tree), source))
            except InputError as exc:
                assert source in str(exc)
