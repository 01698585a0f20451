"""Report inputs: .txt, directories, JSONL with bad rows, and OL 316 PDFs written by the fixture generator."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from .ol316_fixture import write_ol316, write_scanned
from txt2sce_ros.errors import InputError
from txt2sce_ros.paths import shared_dir
from txt2sce_ros.sketch import ErrorRecord, Sketch
from txt2sce_ros.text.pdf import read_ol316
from txt2sce_ros.text.pipeline import run_batch
from txt2sce_ros.text.readers import ReportInput, iter_inputs

REPORTS = shared_dir() / "data" / "reports"


def _dev_rows(n: int) -> list[dict]:
    lines = (REPORTS / "dev.jsonl").read_text(encoding="utf-8").splitlines()
    return [json.loads(x) for x in lines[:n]]


def _latin1(text: str) -> str:
    # The PDF core fonts are Latin-1: curly quotes become straight ones, as a form filler would type them.
    return text.translate(str.maketrans({"\u201c": '"', "\u201d": '"', "\u2019": "'", "\u2018": "'"})) \
        .encode("latin-1", "replace").decode("latin-1")


def test_ol316_pdf_narrative_and_boxes(tmp_path: Path) -> None:
    row = next(r for r in _dev_rows(180) if r["id"] == "dmvca-cruise-20210421-r176")  # rear-ended while yielding
    pdf = write_ol316(tmp_path / "cruise.pdf", _latin1(row["text"]), weather="RAINING",
                      lighting="DARK-STREET LIGHTS", surface="WET", movement_av="MAKING RIGHT TURN",
                      collision="REAR END")
    doc = read_ol316(pdf)
    assert doc.narrative.startswith("A Cruise autonomous vehicle") and doc.narrative.endswith("were not called.")
    assert "SECTION 6" not in doc.narrative and "[X]" not in doc.narrative
    assert doc.form.get("weather") == ("raining",) and doc.form.get("lighting") == ("dark-street lights",)
    assert doc.form.get("roadway_surface") == ("wet",)
    assert doc.form.get("movement_preceding_collision") == ("making right turn",)
    assert doc.form.get("type_of_collision") == ("rear end",)
    assert doc.form.get("involved") == ()
    (out,) = list(run_batch(iter_inputs([pdf])))
    assert isinstance(out, Sketch) and out.report_id == "cruise"
    # The narrative says nothing of weather or light: the boxes fill them; the text still gives the rest.
    assert (out.environment.weather, out.environment.lighting, out.environment.surface) == ("rain", "night_lit",
                                                                                            "wet")
    assert out.collision.type == "rear_end" and len(out.npcs) == 2


def test_pdf_without_text_layer_is_a_clear_error(tmp_path: Path) -> None:
    pdf = write_scanned(tmp_path / "scan.pdf")
    with pytest.raises(InputError, match="no text layer"):
        read_ol316(pdf)
    (rec,) = list(iter_inputs([pdf]))
    assert isinstance(rec, ErrorRecord) and "scan.pdf" in rec.error and rec.report_id == "scan"


def test_not_a_pdf_is_an_error_record(tmp_path: Path) -> None:
    bad = tmp_path / "broken.pdf"
    bad.write_bytes(b"%PDF-1.4\nthis is not really a pdf\n")
    (rec,) = list(iter_inputs([bad]))
    assert isinstance(rec, ErrorRecord) and "broken.pdf" in rec.error


def test_directory_of_txt_and_bad_jsonl_rows_never_stop_the_batch(tmp_path: Path) -> None:
    rows = _dev_rows(3)
    d = tmp_path / "reports"
    d.mkdir()
    for r in rows:
        (d / f"{r['id']}.txt").write_text(r["text"], encoding="utf-8")
    (d / "empty.txt").write_text("  \n", encoding="utf-8")
    jl = tmp_path / "mixed.jsonl"
    jl.write_text("\n".join([json.dumps({"id": rows[0]["id"], "text": rows[0]["text"]}), "{oops",
                             json.dumps({"id": "no-text"}), json.dumps([1, 2]),
                             json.dumps({"id": rows[1]["id"], "text": rows[1]["text"]})]) + "\n", encoding="utf-8")
    inputs = list(iter_inputs([d, jl, tmp_path / "nowhere.txt"]))
    kinds = [type(x).__name__ for x in inputs]
    assert kinds == ["ReportInput"] * 3 + ["ErrorRecord"] + ["ReportInput", "ErrorRecord", "ErrorRecord",
                                                              "ErrorRecord", "ReportInput", "ErrorRecord"]
    assert [x.report_id for x in inputs if isinstance(x, ReportInput)][:3] == sorted(r["id"] for r in rows)
    errors = [x for x in inputs if isinstance(x, ErrorRecord)]
    assert "empty" in errors[0].error and "line 2" in errors[1].error and "<text>" in errors[2].error
    assert "not found" in errors[-1].error
    out = list(run_batch(inputs))
    assert len(out) == len(inputs)
    assert sum(isinstance(x, Sketch) for x in out) == 5
