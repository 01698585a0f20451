"""`txt2sce maps ...` end to end through the real entry point."""

from __future__ import annotations

from txt2sce_ros.cli.main import main


def test_maps_check_prints_the_table_and_passes(esmini_dir, capsys) -> None:
    rc = main(["maps", "check", str(esmini_dir / "xodr"), "--reference", str(esmini_dir / "reference")])
    out = capsys.readouterr().out
    assert rc == 0, out
    assert out.count("  ok    ") == 20
    assert "cut-in " in out and "multi_intersections.xodr" in out
    total = [ln for ln in out.splitlines() if ln.startswith("all ")][0].split()
    assert total[3] == "100.00%" and total[4] == "100.00%"


def test_maps_check_fails_on_a_tighter_tolerance(esmini_dir, capsys) -> None:
    # at 1 mm, esmini's own s of off-centre entities on curves (rounded, from its polyline inverse) disagrees
    rc = main(["maps", "check", str(esmini_dir / "xodr"), "--reference", str(esmini_dir / "reference"),
               "--tol", "0.001"])
    assert rc == 1
    assert "below 99%" in capsys.readouterr().out


def test_bad_map_prints_one_line_without_traceback(tmp_path, capsys) -> None:
    bad = tmp_path / "broken.xodr"
    bad.write_text("<OpenDRIVE><road id='1' length='x'>")
    rc = main(["maps", "info", str(bad)])
    err = capsys.readouterr().err
    assert rc == 2
    assert "broken.xodr" in err and "Traceback" not in err and len(err.strip().splitlines()) == 1


def test_maps_info_and_locate(esmini_dir, capsys) -> None:
    assert main(["maps", "info", str(esmini_dir / "xodr" / "multi_intersections.xodr")]) == 0
    out = capsys.readouterr().out
    assert "roads: 63" in out and "junctions: 5" in out
    assert main(["maps", "locate", str(esmini_dir / "xodr" / "straight_500m.xodr"), "100", "-1.5"]) == 0
    assert "road 1 section 0 lane -1" in capsys.readouterr().out
