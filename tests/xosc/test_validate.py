"""XSD validation and the ASAM checker on the esmini conformance scenarios (real third-party files)."""

from __future__ import annotations

from pathlib import Path

import pytest
from lxml import etree

from txt2sce_ros.errors import InputError
from txt2sce_ros.paths import shared_dir
from txt2sce_ros.xosc import qc_check, validate_xosc
from txt2sce_ros.xosc.schema import safe_parser

XOSC_DIR = shared_dir() / "data" / "conformance" / "esmini" / "xosc"


def _xosc(name: str) -> Path:
    p = XOSC_DIR / name
    if not p.is_file():
        pytest.skip(f"shared data missing: {p}")
    return p


def test_esmini_examples_are_valid() -> None:
    files = sorted(XOSC_DIR.glob("*.xosc"))
    assert len(files) >= 10
    for f in files:
        assert validate_xosc(f.read_bytes(), source=str(f)) == [], f.name


def test_schema_error_names_the_line_and_element() -> None:
    text = _xosc("cut-in_simple.xosc").read_text(encoding="utf-8")
    broken = text.replace('dynamicsShape="', 'dynamicsShape="wobbly', 1)
    errors = validate_xosc(broken)
    assert errors, "an invalid enumeration member must be reported"
    line = next(i for i, l in enumerate(broken.splitlines(), 1) if "wobbly" in l)
    assert errors[0].startswith(f"line {line}:")
    assert "dynamicsShape" in errors[0]


def test_tree_input_and_explicit_version() -> None:
    tree = etree.parse(str(_xosc("straight_500m.xosc")), safe_parser())
    assert tree.getroot().find("FileHeader").get("revMinor") != "0"
    assert validate_xosc(tree) == []
    # The same file checked as 1.0 fails on an attribute 1.0 does not know: the version really selects the XSD.
    errors = validate_xosc(tree.getroot(), version="1.0")
    assert errors and "model3d" in errors[0]


def test_missing_required_element_is_reported() -> None:
    tree = etree.parse(str(_xosc("straight_500m.xosc")), safe_parser())
    sb = tree.getroot().find("Storyboard")
    sb.remove(sb.find("Init"))
    errors = validate_xosc(tree)
    assert any("Init" in e for e in errors)


def test_malformed_and_headerless_inputs_raise() -> None:
    with pytest.raises(InputError):
        validate_xosc(b"<OpenSCENARIO><FileHeader", source="x.xosc")
    with pytest.raises(InputError) as info:
        validate_xosc(b"<OpenSCENARIO/>", source="x.xosc")
    assert "FileHeader" in str(info.value)


def test_qc_check_clean_and_dirty() -> None:
    assert [i for i in qc_check(_xosc("cut-in_simple.xosc")) if i.level == "error"] == []
    # esmini's traffic_lights.xosc names three ManeuverGroups alike: the ASAM checker flags it.
    dirty = [i for i in qc_check(_xosc("traffic_lights.xosc")) if i.level == "error"]
    assert dirty and "unique_element_names" in dirty[0].checker_id


def test_qc_check_missing_file() -> None:
    with pytest.raises(InputError):
        qc_check("/nonexistent/file.xosc")
