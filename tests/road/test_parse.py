"""Parsing real maps, and refusing bad input with an error that names file and element."""

from __future__ import annotations

import pytest

from txt2sce_ros.errors import InputError
from txt2sce_ros.road import RoadNetwork, load_network

from .conftest import XODR, esmini_map

MINIMAL = """<?xml version="1.0"?>
<OpenDRIVE><header revMajor="1" revMinor="6"/>
  <road id="7" length="100" junction="-1" {rule}>
    <planView><geometry s="0" x="0" y="0" hdg="0" length="100"><line/></geometry></planView>
    <lanes><laneSection s="0">
      <left><lane id="1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></left>
      <center><lane id="0" type="none"/></center>
      <right><lane id="-1" type="driving"><width sOffset="0" a="3.0" b="0" c="0" d="0"/></lane>
             <lane id="-2" type="sidewalk"><width sOffset="0" a="2.0" b="0" c="0" d="0"/></lane></right>
    </laneSection></lanes>
  </road>
</OpenDRIVE>"""


def test_every_esmini_map_loads(esmini_dir) -> None:
    maps = sorted(XODR.glob("*.xodr"))
    assert len(maps) == 20
    for path in maps:
        net = load_network(path)
        assert net.roads, path.name
        for road in net.roads.values():
            assert road.length >= 0 and road.sections


def test_multi_intersections_junctions_signals_controllers(esmini_dir) -> None:
    net = esmini_map("multi_intersections")
    assert len(net.roads) == 63 and len(net.junctions) == 5
    assert sum(len(j.connections) for j in net.junctions.values()) == 42
    assert net.controllers["1"].signal_ids == ("294", "295", "287", "288")
    lights = [s for s in net.signals.values() if s.is_traffic_light]
    assert lights and all(s.dynamic for s in lights)
    # every controlled signal exists and sits next to its road
    for ctrl in net.controllers.values():
        for sig in net.signals_of_controller(ctrl.id):
            x, y, _ = net.road_to_world(sig.road_id, sig.s, sig.t)
            assert (sig.x, sig.y) == pytest.approx((x, y))


def test_signal_validity_limits_controlled_lanes(esmini_dir) -> None:
    net = esmini_map("fabriksgatan_traffic_lights")
    sig = net.signals["2"]           # <validity fromLane="-1" toLane="1"/>, orientation "+"
    assert sig.validity and sig.dynamic
    assert set(sig.controlled_lanes) <= {-1, 1}
    assert all(net.lane_forward(sig.road_id, i) for i in sig.controlled_lanes)


def test_left_hand_traffic_rule_flips_driving_direction(esmini_dir) -> None:
    rht, lht = esmini_map("e6mini"), esmini_map("e6mini-lht")
    assert {r.rule for r in lht.roads.values()} == {"LHT"}
    assert rht.lane_forward("0", -2) and not rht.lane_forward("0", 2)
    assert lht.lane_forward("0", 2) and not lht.lane_forward("0", -2)
    _, _, h_r = rht.lane_to_world("0", -2, 100.0)
    _, _, h_l = lht.lane_to_world("0", -2, 100.0)
    assert abs(abs(h_r - h_l) - 3.14159265) < 1e-6


def test_minimal_road_from_string() -> None:
    net = RoadNetwork.from_string(MINIMAL.format(rule='rule="LHT"'), source="minimal.xodr")
    assert net.roads["7"].rule == "LHT"
    assert net.lane_ids("7", 10.0) == [1, -1]
    assert net.lane_ids("7", 10.0, types=None) == [1, -1, -2]
    assert net.lane_center_t("7", -2, 50.0) == pytest.approx(-4.0)
    assert net.lane_width("7", 1, 50.0) == pytest.approx(3.5)
    assert net.lane_type("7", -2, 0.0) == "sidewalk"


BAD = {
    "truncated": (MINIMAL.format(rule="")[:400], "OpenDRIVE"),
    "malformed": (MINIMAL.format(rule="").replace("</planView>", "</planVew>"), "OpenDRIVE"),
    "not_a_number": (MINIMAL.format(rule="").replace('length="100" junction', 'length="abc" junction'), "road"),
    "missing_attr": (MINIMAL.format(rule="").replace('hdg="0" ', ""), "geometry"),
    "unknown_geometry": (MINIMAL.format(rule="").replace("<line/>", "<bezier/>"), "bezier"),
    "bad_rule": (MINIMAL.format(rule='rule="XHT"'), "road"),
    "lane_on_wrong_side": (MINIMAL.format(rule="").replace('<lane id="1" type', '<lane id="-5" type'), "lane"),
    "wrong_root": ("<OpenSCENARIO/>", "OpenSCENARIO"),
    "no_roads": ("<OpenDRIVE><header/></OpenDRIVE>", "OpenDRIVE"),
    "xxe": ('<?xml version="1.0"?><!DOCTYPE r [<!ENTITY x SYSTEM "file:///etc/passwd">]>'
            + MINIMAL.format(rule="").split("?>", 1)[1].replace('name=""', "").replace(
                '<header revMajor="1" revMinor="6"/>', '<header revMajor="1" revMinor="6" name="&x;"/>'), "!DOCTYPE"),
    "xxe_text": ('<?xml version="1.0"?><!DOCTYPE r [<!ENTITY x SYSTEM "file:///etc/passwd">]>'
                 '<OpenDRIVE><header>&x;</header></OpenDRIVE>', "!DOCTYPE"),
    "billion_laughs": ('<?xml version="1.0"?><!DOCTYPE lolz [<!ENTITY lol "lol">'
                       + "".join(f'<!ENTITY lol{i} "{("&lol%s;" % (i - 1 if i > 1 else "")) * 10}">'
                                 for i in range(1, 10))
                       + ']><OpenDRIVE><header name="&lol9;"/></OpenDRIVE>', "!DOCTYPE"),
}


@pytest.mark.parametrize("case", sorted(BAD))
def test_bad_input_names_file_and_element(case: str) -> None:
    text, element = BAD[case]
    with pytest.raises(InputError) as info:
        RoadNetwork.from_string(text, source=f"{case}.xodr")
    err = info.value
    assert err.source == f"{case}.xodr"
    assert err.element == element
    assert f"{case}.xodr" in str(err)


def test_missing_file_is_input_error(tmp_path) -> None:
    with pytest.raises(InputError) as info:
        load_network(tmp_path / "nope.xodr")
    assert "nope.xodr" in str(info.value)


def test_unknown_road_and_lane_are_input_errors(esmini_dir) -> None:
    net = esmini_map("straight_500m")
    with pytest.raises(InputError, match="no road"):
        net.road_to_world("99", 0.0)
    with pytest.raises(InputError, match="no lane 9"):
        net.lane_to_world("1", 9, 10.0)


def test_load_network_caches_per_path_and_mtime(tmp_path) -> None:
    p = tmp_path / "m.xodr"
    p.write_text(MINIMAL.format(rule=""))
    a = load_network(p)
    assert load_network(p) is a
    import os

    p.write_text(MINIMAL.format(rule='rule="LHT"'))
    os.utime(p, ns=(1, 10**18))
    b = load_network(p)
    assert b is not a and b.roads["7"].rule == "LHT"


def test_load_network_text_caches_by_content_and_name() -> None:
    from txt2sce_ros.road import load_network_text

    a = load_network_text(MINIMAL.format(rule=""), source="envelope")
    assert load_network_text(MINIMAL.format(rule="").encode(), source="envelope") is a
    # the same content under another name is another network: error messages quote the name
    other = load_network_text(MINIMAL.format(rule=""), source="other")
    assert other is not a and other.source == "other"
    b = load_network_text(MINIMAL.format(rule='rule="LHT"'), source="envelope")
    assert b is not a and b.roads["7"].rule == "LHT"
