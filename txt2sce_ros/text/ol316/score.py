"""How well OL 316 PDFs are read, against `forms.jsonl` (each file's kind, narrative and boxes, read by eye).

Per file: how it was read (text layer, form fields, OCR, refused), the narrative's match (equal up to whitespace;
an OCR-tolerant similarity: difflib's ratio over lower-case letters and digits, so "S horeline"/"Shoreline" and
quote styles do not count), and the weather / lighting / surface boxes in the sketch vocabulary. Beside it, in the
same run, the baseline: the page text layer alone (pdfminer's text, section 5 caption to section 6 caption,
marked boxes before the option), as txt2sce read PDFs before this reader.
"""

from __future__ import annotations

import difflib
import json
import re
from dataclasses import dataclass, field
from pathlib import Path

from ...errors import InputError
from ..forms import form_sketch_fields
from ..pdf import FormFields, read_ol316

#: Similarity at or above which a narrative counts as read (equal up to OCR slips).
MATCH = 0.95
ENV = ("weather", "lighting", "surface")


def normalise(text: str) -> str:
    return re.sub(r"\s+", " ", text).strip()


def similarity(got: str, want: str) -> float:
    """OCR-tolerant similarity in [0, 1]: lower-case letters and digits only, spaces and punctuation dropped."""
    a, b = (re.sub(r"[^a-z0-9]", "", t.lower()) for t in (got, want))
    if not a or not b:
        return 0.0
    return difflib.SequenceMatcher(None, a, b, autojunk=False).ratio()


@dataclass
class FileScore:
    file: str
    kind: str  # forms.jsonl's text_layer: yes, form_fields, garbled, none
    read_as: str  # text, form_fields, ocr, refused
    exact: bool = False
    similarity: float = 0.0
    boxes_right: int = 0
    boxes_total: int = 0  # boxes the form fills (forms.jsonl's sketch_fields not null)
    boxes_extra: int = 0  # boxes read where the form fills none
    error: str = ""
    wrong: list[str] = field(default_factory=list)

    @property
    def matched(self) -> bool:
        return self.exact or self.similarity >= MATCH


def _score(row: dict, narrative: str | None, form: FormFields | None, read_as: str, error: str = "") -> FileScore:
    s = FileScore(row["file"], row["text_layer"], read_as, error=error)
    want = row.get("narrative") or ""
    if narrative:
        s.exact = normalise(narrative) == normalise(want)
        s.similarity = similarity(narrative, want)
    got = form_sketch_fields(form) if form is not None else {}
    for key in ENV:
        truth, mine = row["sketch_fields"].get(key), got.get(key)
        if truth is None:
            s.boxes_extra += mine is not None
            continue
        s.boxes_total += 1
        if mine == truth:
            s.boxes_right += 1
        else:
            s.wrong.append(f"{key} {mine or '-'}≠{truth}")
    return s


def score_reader(row: dict, path: Path) -> FileScore:
    try:
        doc = read_ol316(path)
    except InputError as exc:
        return _score(row, None, None, "refused", str(exc))
    return _score(row, doc.narrative, doc.form, doc.text_source)


_B_SECTION5 = re.compile(r"(?:SECTION\s*5\b|5\s*[.)]?\s*ACCIDENT\s+DETAILS\s*[-–]\s*DESCRIPTION)[^\n]*\n", re.I)
_B_END = re.compile(r"\n\s*(?:SECTION\s*6\b|6\s*[.)]\s*[A-Z]|OL\s*316\s*\(REV|PAGE\s+\d+\s+OF)", re.I)
_B_BOX = re.compile(r"(?:\[\s*[Xx✓✔]\s*\]|☒|☑|■)\s*([A-Za-z][A-Za-z /*\-]+?)(?=\s*(?:\[|☐|☒|☑|□|■|$))")
_B_CAPTIONS = {"WEATHER": "weather", "LIGHTING": "lighting", "ROADWAY SURFACE": "roadway_surface"}


def score_baseline(row: dict, path: Path) -> FileScore:
    """The text-layer-only reading (the reader txt2sce had before): no form fields, no OCR, boxes only as
    marked glyphs before the option on the caption's line."""
    import logging

    from pdfminer.high_level import extract_text

    logging.getLogger("pdfminer").setLevel(logging.ERROR)
    try:
        text = extract_text(str(path))
    except Exception as exc:  # the baseline's own failure is a refusal, as it was
        return _score(row, None, None, "refused", type(exc).__name__)
    if not text.strip():
        return _score(row, None, None, "refused", "no text layer")
    m = _B_SECTION5.search(text)
    if not m:
        return _score(row, None, None, "refused", "no section 5")
    rest = text[m.end():]
    end = _B_END.search(rest)
    narrative = normalise(rest[:end.start()] if end else rest)
    fields: dict[str, list[str]] = {}
    current = None
    for line in text.splitlines():
        cap = line.strip().upper()
        current = next((name for c, name in _B_CAPTIONS.items() if cap.startswith(c)), current)
        if current:
            fields.setdefault(current, []).extend(o.strip().lower() for o in _B_BOX.findall(line))
    form = FormFields({k: tuple(v) for k, v in fields.items() if v})
    return _score(row, narrative, form, "text")


def load_forms(directory: Path) -> list[dict]:
    path = directory / "forms.jsonl"
    if not path.is_file():
        raise InputError("no forms.jsonl (the reading by eye to score against) in the directory", source=str(path))
    with open(path, encoding="utf-8") as fh:
        return [json.loads(line) for line in fh if line.strip()]


def totals(scores: list[FileScore]) -> dict[str, object]:
    """The counts the acceptance asks for."""
    readable = [s for s in scores if s.kind in ("yes", "form_fields", "garbled")]
    scans = [s for s in scores if s.kind == "none"]
    ocr = [s for s in scores if s.read_as == "ocr"]
    right = sum(s.boxes_right for s in scores)
    total = sum(s.boxes_total for s in scores)
    return {
        "files": len(scores),
        "narrative_matched": sum(s.matched for s in scores),
        "narrative_exact": sum(s.exact for s in scores),
        "text_or_fields_files": len(readable),
        "text_or_fields_matched": sum(s.matched for s in readable),
        "scans": len(scans),
        "scans_refused": sum(s.read_as == "refused" for s in scans),
        "ocr_files": len(ocr),
        "ocr_matched": sum(s.matched for s in ocr),
        "ocr_mean_similarity": round(sum(s.similarity for s in ocr) / len(ocr), 4) if ocr else None,
        "boxes_right": right,
        "boxes_total": total,
        "boxes_accuracy": round(right / total, 4) if total else None,
        "boxes_extra": sum(s.boxes_extra for s in scores),
        "refused": sum(s.read_as == "refused" for s in scores),
    }


def format_report(scores: list[FileScore], base: list[FileScore]) -> str:
    lines = [f"{'file':<34}{'kind':<12}{'read as':<12}{'exact':>6}{'sim':>7}{'boxes':>7}  "
             f"{'baseline: read as':<18}{'sim':>6}{'boxes':>7}", "-" * 121]
    for s, b in zip(scores, base):
        lines.append(f"{s.file:<34}{s.kind:<12}{s.read_as:<12}{'yes' if s.exact else 'no':>6}{s.similarity:>7.3f}"
                     f"{f'{s.boxes_right}/{s.boxes_total}':>7}  {b.read_as:<18}{b.similarity:>6.3f}"
                     f"{f'{b.boxes_right}/{b.boxes_total}':>7}"
                     + (f"  {'; '.join(s.wrong)}" if s.wrong else "") + (f"  [{s.error}]" if s.error else ""))
    t, tb = totals(scores), totals(base)

    def pct(a: object, b: object) -> str:
        return f"{a}/{b} ({a / b:.1%})" if isinstance(a, int) and isinstance(b, int) and b else f"{a}/{b}"

    lines += ["", f"{'total':<52}{'reader':<30}{'baseline (text layer only)'}", "-" * 110]
    rows = [
        ("narrative matched (exact or similarity >= %.2f)" % MATCH, pct(t["narrative_matched"], t["files"]),
         pct(tb["narrative_matched"], tb["files"])),
        ("  of files with a text layer or form fields", pct(t["text_or_fields_matched"], t["text_or_fields_files"]),
         pct(tb["text_or_fields_matched"], tb["text_or_fields_files"])),
        ("  equal up to whitespace", pct(t["narrative_exact"], t["files"]), pct(tb["narrative_exact"], tb["files"])),
        ("weather/lighting/surface boxes right", pct(t["boxes_right"], t["boxes_total"]),
         pct(tb["boxes_right"], tb["boxes_total"])),
        ("  boxes read where the form has none", str(t["boxes_extra"]), str(tb["boxes_extra"])),
        ("scans (no text layer) refused", pct(t["scans_refused"], t["scans"]), pct(tb["scans_refused"], tb["scans"])),
        ("read by OCR here: matched", pct(t["ocr_matched"], t["ocr_files"]), "-"),
        ("read by OCR here: mean similarity", str(t["ocr_mean_similarity"]), "-"),
        ("refused in all", str(t["refused"]), str(tb["refused"])),
    ]
    lines += [f"{a:<52}{b:<30}{c}" for a, b, c in rows]
    return "\n".join(lines)
