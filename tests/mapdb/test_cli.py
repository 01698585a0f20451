"""`txt2sce mapdb ...` end to end through the real entry point."""

from __future__ import annotations

from pathlib import Path

from txt2sce_ros.cli.main import main
from txt2sce_ros.mapdb.bundled import BUNDLED
from txt2sce_ros.paths import BUNDLED_MAPS

from .conftest import ESMINI_XODR


def test_build_maps_into_a_directory_validates_and_matches_the_committed_maps(tmp_path: Path, capsys) -> None:
    assert main(["mapdb", "build-maps", "--out", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    assert out.count("XSD-valid (OpenDRIVE 1.7)") == len(BUNDLED)
    for name in BUNDLED:
        assert (tmp_path / name).read_bytes() == (BUNDLED_MAPS / name).read_bytes()
    assert main(["mapdb", "build-maps", "--check"]) == 0


def test_show_prints_the_summary_and_reports_the_cache(capsys) -> None:
    assert main(["mapdb", "show", "junction3_stop.xodr"]) == 0
    first = capsys.readouterr().out
    assert "junction 200 'stop_t_junction': junction3, 3 legs, control stop_sign" in first
    assert "from road    3 (stop_sign): -1:left/right" in first
    assert main(["mapdb", "show", "junction3_stop.xodr"]) == 0
    assert "cache hit" in capsys.readouterr().out


def test_show_json_round_trips_the_graph(capsys) -> None:
    import json

    import networkx as nx

    from txt2sce_ros.mapdb import load_map_database

    assert main(["mapdb", "show", "junction4_signal.xodr", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    graph = nx.node_link_graph(data["graph"], edges="edges")
    db = load_map_database(BUNDLED_MAPS / "junction4_signal.xodr")
    assert set(graph.nodes) == set(db.graph.nodes) and graph.number_of_edges() == db.graph.number_of_edges()
    assert data["junctions"][0]["layout"] == "junction4"
    assert data["junctions"][0]["approaches"][0]["lanes"][0] == {"id": -1, "turns": ["left", "uturn"]}


def test_query_lists_matching_approaches_and_roads(capsys) -> None:
    assert main(["mapdb", "query", "junction4_signal.xodr", "--layout", "junction4", "--lanes", "2",
                 "--control", "signal", "--turn", "left", "--need", "dedicated_left"]) == 0
    out = capsys.readouterr().out
    assert "4 matching approaches" in out and "lane -1: left/uturn" in out
    assert main(["mapdb", "query", "straight_3x3.xodr", "--layout", "straight", "--lanes", "3", "--two-way",
                 "--need", "bike_lane", "--need", "parking_lane"]) == 0
    assert "2 matching road directions" in capsys.readouterr().out
    # Nothing matches: exit status 1, still a clean listing.
    assert main(["mapdb", "query", str(ESMINI_XODR / "fabriksgatan.xodr"), "--control", "signal"]) == 1
    assert "0 matching approaches" in capsys.readouterr().out


def test_errors_print_one_line_without_traceback(tmp_path: Path, capsys) -> None:
    assert main(["mapdb", "show", str(tmp_path / "missing.xodr")]) == 2
    err = capsys.readouterr().err
    assert "missing.xodr" in err and "Traceback" not in err
    bad = tmp_path / "truncated.xodr"
    bad.write_bytes((BUNDLED_MAPS / "one_way.xodr").read_bytes()[:500])
    assert main(["mapdb", "show", str(bad)]) == 2
    err = capsys.readouterr().err
    assert "truncated.xodr" in err and "Traceback" not in err
    assert main(["mapdb", "query", "one_way.xodr", "--need", "helipad"]) == 2
    assert "helipad" in capsys.readouterr().err
