"""The OL 316 reader on every real DMV PDF in ../shared/data/ol316, against forms.jsonl (read by eye).

Each PDF is read once per session (scans take Tesseract ~10 s a page). Skipped cleanly without the shared data.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from .ol316_fixture import write_scanned
from txt2sce_ros.errors import InputError
from txt2sce_ros.paths import shared_dir
from txt2sce_ros.text.forms import form_sketch_fields
from txt2sce_ros.text.ol316 import ocr
from txt2sce_ros.text.ol316.layout import read_pages
from txt2sce_ros.text.ol316.narrative import find_narrative
from txt2sce_ros.text.ol316.reader import READABLE, readability
from txt2sce_ros.text.ol316.score import MATCH, normalise, similarity
from txt2sce_ros.text.pdf import Ol316, read_ol316

OL316 = shared_dir() / "data" / "ol316"
pytestmark = pytest.mark.skipif(not (OL316 / "forms.jsonl").is_file(), reason="shared OL 316 PDFs not present")


def _rows() -> list[dict]:
    if not (OL316 / "forms.jsonl").is_file():
        return []
    return [json.loads(x) for x in (OL316 / "forms.jsonl").read_text(encoding="utf-8").splitlines() if x.strip()]


ROWS = _rows()
READABLE_ROWS = [r for r in ROWS if r["text_layer"] in ("yes", "form_fields") or r["file"] == "2019-Lyft_111919.pdf"]
SCANS = [r for r in ROWS if r["text_layer"] == "none" or r["file"] == "2017-GMCruise_021617.pdf"]


@pytest.fixture(scope="module")
def read_all() -> dict[str, Ol316 | InputError]:
    out: dict[str, Ol316 | InputError] = {}
    for r in ROWS:
        try:
            out[r["file"]] = read_ol316(OL316 / r["file"])
        except InputError as exc:
            out[r["file"]] = exc
    return out


def test_the_shared_set_covers_every_kind() -> None:
    kinds = {r["text_layer"] for r in ROWS}
    assert {"yes", "form_fields", "garbled", "none"} <= kinds and len(ROWS) == 29


@pytest.mark.parametrize("row", READABLE_ROWS, ids=lambda r: r["file"])
def test_narrative_of_text_layers_and_form_fields(row: dict, read_all: dict) -> None:
    doc = read_all[row["file"]]
    assert isinstance(doc, Ol316), doc
    # Equal up to whitespace where the PDF's text is typed; up to the scanner's OCR slips where it is an OCR layer.
    if row["text_layer"] != "yes":
        assert doc.text_source == "form_fields"
        assert normalise(doc.narrative) == normalise(row["narrative"])
    else:
        assert doc.text_source == "text"
        assert similarity(doc.narrative, row["narrative"]) >= MATCH, doc.narrative
    # Section 5 ends where the narrative ends: no table labels or certification text leak in.
    for leak in ("ITEMS MARKED", "DUSK - DAWN", "SECTION 6", "Additional information", "certify"):
        assert leak.lower() not in doc.narrative.lower()


def test_weather_lighting_surface_boxes(read_all: dict) -> None:
    right = total = extra = 0
    for r in ROWS:
        doc = read_all[r["file"]]
        got = form_sketch_fields(doc.form) if isinstance(doc, Ol316) else {}
        for key in ("weather", "lighting", "surface"):
            truth = r["sketch_fields"][key]
            if truth is None:
                extra += got.get(key) is not None
            else:
                total += 1
                right += got.get(key) == truth
    assert total >= 45
    assert right / total >= 0.95 and extra == 0, (right, total, extra)


def test_ticks_are_read_per_vehicle_column(read_all: dict) -> None:
    """REV. 2/2017 movement and collision-type ticks land in the VEH 1 / VEH 2 column they were made in."""
    checked = 0
    for r in ROWS:
        doc = read_all[r["file"]]
        if r["form"]["weather"] is None or not isinstance(doc, Ol316):
            continue
        want1 = [m.lower() for m in r["form"]["movement_v1"]]
        want2 = [m.lower() for m in r["form"]["movement_v2"]]
        assert list(doc.form.get("movement_preceding_collision")) == want1, r["file"]
        assert list(doc.form.get("movement_preceding_collision", 2)) == want2, r["file"]
        assert list(doc.form.get("type_of_collision")) == [t.lower() for t in r["form"]["type_of_collision"]]
        checked += 1
    assert checked >= 16


def test_form_reading_keeps_the_companys_collision_type(read_all: dict) -> None:
    """Zoox 2019: the only tick is HEAD-ON (VEH 2) while the narrative tells of a cyclist riding into the AV's rear:
    the form's reading is kept as filed, beside the sketch, not corrected."""
    doc = read_all["2019-Zoox_061919.pdf"]
    assert isinstance(doc, Ol316)
    assert form_sketch_fields(doc.form)["collision_type"] == "head_on"


def test_garbled_ocr_layer_is_recognised() -> None:
    garbled = find_narrative(read_pages(OL316 / "2017-GMCruise_021617.pdf"))
    clean = find_narrative(read_pages(OL316 / "2017-Zoox_092717.pdf"))
    assert garbled and clean
    assert readability(garbled.text) < READABLE <= readability(clean.text)


@pytest.mark.parametrize("row", SCANS, ids=lambda r: r["file"])
def test_scans_are_read_by_ocr_or_refused_by_name(row: dict, read_all: dict) -> None:
    doc = read_all[row["file"]]
    if not ocr.available():
        assert isinstance(doc, InputError) and row["file"] in str(doc) and "Tesseract" in str(doc)
        return
    assert isinstance(doc, Ol316), doc
    assert doc.text_source == "ocr" and any("OCR" in n for n in doc.notes)
    assert similarity(doc.narrative, row["narrative"]) >= 0.85, doc.narrative


def test_extract_exits_nonzero_when_a_pdf_gives_no_narrative(tmp_path: Path) -> None:
    scan = write_scanned(tmp_path / "blank_scan.pdf")
    good = OL316 / "2020-Cruise_013120.pdf"
    out = tmp_path / "s.jsonl"
    proc = subprocess.run([sys.executable, "-m", "txt2sce_ros.cli.main", "extract", str(good), str(scan),
                           "--out", str(out)], capture_output=True, text=True, timeout=300)
    assert proc.returncode == 1, proc.stderr
    assert "blank_scan" in proc.stderr and "Traceback" not in proc.stderr
    rows = [json.loads(x) for x in out.read_text(encoding="utf-8").splitlines()]
    assert rows[0]["schema"] == "txt2sce.sketch/1" and "blank_scan.pdf" in rows[1]["error"]
    # Beside the sketches: the form's own reading, how it was read.
    (reading,) = [json.loads(x) for x in (tmp_path / "s.ol316.jsonl").read_text(encoding="utf-8").splitlines()]
    assert reading["read_as"] == "form_fields"
    assert reading["form_reading"]["collision_type"] == "rear_end"
    assert reading["form"]["vehicle_1"]["movement_preceding_collision"] == ["making left turn"]


def test_ticks_drawn_on_the_scan_are_seen_without_the_ocr_layer_glyphs() -> None:
    """A hand tick the scanner's OCR did not turn into a glyph is still ink in its VEH column's cell: with the
    mark glyphs removed, the page image alone gives each OCR-layer REV. 2/2017 form's environment ticks."""
    from dataclasses import replace

    from txt2sce_ros.text.ol316 import boxes, raster
    from txt2sce_ros.text.pdf import FormFields

    rows = [r for r in ROWS if r["text_layer"] == "yes" and r["form"]["weather"] is not None]
    assert len(rows) >= 5
    for r in rows:
        pages = read_pages(OL316 / r["file"])
        (page,) = [p for p in pages if boxes.has_tables(p)]
        bare = replace(page, pieces=tuple(p for p in page.pieces if p.kind != "mark"))
        assert boxes.read_tables(bare) == ({}, {})  # no glyphs, no image: nothing
        v1, v2 = boxes.read_tables(bare, raster.render(OL316 / r["file"], page.number, 150))
        got = form_sketch_fields(FormFields(v1, v2))
        assert [got[k] for k in ("weather", "lighting", "surface")] == \
            [r["sketch_fields"][k] for k in ("weather", "lighting", "surface")], r["file"]
        assert list(v1.get("movement_preceding_collision", ())) == [m.lower() for m in r["form"]["movement_v1"]]
