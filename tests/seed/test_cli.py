"""`txt2sce seed` and `txt2sce xosc` through the real CLI entry point."""

from __future__ import annotations

import json

from txt2sce_ros.cli.main import main


def test_seed_cli_writes_seeds_maps_and_manifest(tmp_path, gold, capsys) -> None:
    src = tmp_path / "two.jsonl"
    picked = [gold["dmvca-apple-20211111-r241"], next(s for s in gold.values() if s.missing)]
    src.write_text("".join(s.to_json() + "\n" for s in picked))
    out = tmp_path / "out"
    assert main(["seed", str(src), "--out", str(out), "--qc"]) == 1     # one sketch refused (recorded)
    text = capsys.readouterr().out
    assert "1 seed(s) written" in text and "1 sketch(es) refused" in text and "1/1 clean" in text
    manifest = json.loads((out / "manifest.json").read_text())
    seed_file = out / manifest["built"][0]["file"]
    assert seed_file.is_file() and (out / manifest["built"][0]["map_ref"]).is_file()
    assert main(["xosc", "validate", str(seed_file)]) == 0
    assert "1/1 valid" in capsys.readouterr().out


def test_xosc_entitydb_cli(capsys) -> None:
    assert main(["xosc", "entitydb", "Precipitation", "precipitationType"]) == 0
    assert "dry, rain, snow" in capsys.readouterr().out
    assert main(["xosc", "entitydb", "Precipitation", "intensity", "--check", "1.5"]) == 2
    assert "outside" in capsys.readouterr().err
