"""The typed sketch model against the real gold sketches (dev_gold.jsonl) and the project's schema."""

from __future__ import annotations

import copy
import json

import pytest

from txt2sce_ros.errors import InputError
from txt2sce_ros.paths import shared_dir
from txt2sce_ros.sketch import (ACTION_CODES, ErrorRecord, Sketch, SCHEMA_PATH, action_names, load_sketches,
                                validate_sketch_dict)

GOLD = shared_dir() / "data" / "reports" / "dev_gold.jsonl"


@pytest.fixture(scope="module")
def gold_lines() -> list[str]:
    return [line.rstrip("\n") for line in GOLD.read_text(encoding="utf-8").splitlines() if line.strip()]


def test_bundled_schema_is_the_project_contract() -> None:
    spec = json.loads((shared_dir() / "spec" / "sketch.schema.json").read_text(encoding="utf-8"))
    assert json.loads(SCHEMA_PATH.read_text(encoding="utf-8")) == spec


def test_gold_round_trips_byte_for_byte(gold_lines: list[str]) -> None:
    assert len(gold_lines) == 60
    for line in gold_lines:
        d = json.loads(line)
        s = Sketch.from_dict(d)
        # Canonical key order: re-serialising gives the very same bytes as the spec-ordered gold line.
        assert json.dumps(s.to_dict(), ensure_ascii=False) == json.dumps(d, ensure_ascii=False)
        assert Sketch.from_dict(s.to_dict()) == s


def test_load_sketches_reads_all_gold() -> None:
    out = list(load_sketches(GOLD))
    assert len(out) == 60 and all(isinstance(s, Sketch) for s in out)
    buildable = [s for s in out if isinstance(s, Sketch) and s.is_buildable]
    assert 0 < len(buildable) < 60  # the gold set has both kinds


def test_action_codes_are_the_thirteen() -> None:
    assert "".join(ACTION_CODES) == "abcdefghijklm"
    assert action_names("ad") == ["go_straight", "turn_left"]
    assert ACTION_CODES["m"] == "cross" and ACTION_CODES["k"] == "reverse"
    with pytest.raises(InputError):
        action_names("az")


def test_from_dict_names_report_and_field(gold_lines: list[str]) -> None:
    d = json.loads(gold_lines[1])
    bad = copy.deepcopy(d)
    bad["npcs"][0]["category"] = "airplane"
    with pytest.raises(InputError) as exc:
        Sketch.from_dict(bad)
    assert d["report_id"] in str(exc.value) and "npcs[0].category" in str(exc.value)


def test_cross_field_rules(gold_lines: list[str]) -> None:
    d = next(json.loads(x) for x in gold_lines if json.loads(x)["npcs"])
    assert validate_sketch_dict(d) == []
    bad = copy.deepcopy(d)
    bad["collision"]["with"] = "npc9"
    assert any(p.startswith("collision.with") for p in validate_sketch_dict(bad))
    bad = copy.deepcopy(d)
    bad["npcs"][0]["id"] = "npc2"
    assert any("numbered in order" in p for p in validate_sketch_dict(bad))
    bad = copy.deepcopy(d)
    bad["npcs"][0]["position"], bad["npcs"][0]["lane"] = "R5", None
    assert any("required for R5" in p for p in validate_sketch_dict(bad))
    bad = copy.deepcopy(d)
    bad["ego"]["actions"] = "az"
    assert validate_sketch_dict(bad)


def test_bad_lines_become_error_records(tmp_path, gold_lines: list[str]) -> None:
    f = tmp_path / "mixed.jsonl"
    broken = json.loads(gold_lines[0])
    del broken["road"]
    f.write_text("\n".join([gold_lines[0], "{not json", json.dumps(broken),
                            ErrorRecord("r9", "no text").to_json()]) + "\n", encoding="utf-8")
    out = list(load_sketches(f))
    assert [type(x).__name__ for x in out] == ["Sketch", "ErrorRecord", "ErrorRecord", "ErrorRecord"]
    assert "line 2" in out[1].error
    assert "road" in out[2].error and out[2].report_id == broken["report_id"]
    assert out[3].report_id == "r9" and out[3].error == "no text"
