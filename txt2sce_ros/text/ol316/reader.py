"""One reader for every kind of OL 316 PDF: text layer, fillable form, OCR layer, scan.

Order of trust: the PDF's own text (typed text or a form's field values) when it reads as words; Tesseract when the
file has no text at all (a scan) or its OCR layer is garbage; a clear refusal naming the file when neither works.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

from ...errors import InputError
from . import ocr, raster
from .boxes import Boxes, has_tables, read_inline, read_tables, read_vehicle_was
from .layout import Page, read_pages
from .narrative import Section5, compact, find_narrative

#: Below this share of word-like tokens a narrative is OCR garbage ("A eruiSe anh:nlonious vchklc").
READABLE = 0.85
#: A page with fewer characters than this carries no text layer (a scan; stray marks aside).
_MIN_TEXT = 40
_WORD = re.compile(r"(?:[A-Z]?[a-z]+|[A-Z]+s?|[A-Z][a-z]+'s|[a-z]+'[a-z]+|\d[\d,.:/-]*(?:[a-zA-Z]{1,3})?"
                   r"|[A-Z]+-[A-Za-z]+|[a-z]+-[a-z]+|[A-Z]\.(?:[A-Z]\.)*|&|-+|/)")


@dataclass(frozen=True)
class ReadResult:
    """What was read from one PDF. `text_source`: `text` (text or OCR layer), `form_fields` (a fillable form's field
    values) or `ocr` (read here by Tesseract)."""

    narrative: str
    text_source: str
    vehicle_1: Boxes
    vehicle_2: Boxes
    notes: tuple[str, ...]


def readability(text: str) -> float:
    """Share of the tokens that look like words, numbers or abbreviations (a garbled OCR layer scores ~0.5)."""
    tokens = [t.strip("\"'()[],.;:!?“”‘’") for t in text.split()]
    tokens = [t for t in tokens if t]
    if not tokens:
        return 0.0
    return sum(1 for t in tokens if _WORD.fullmatch(t)) / len(tokens)


def _text_chars(pages: list[Page]) -> int:
    return sum(len(ln.text.strip()) for p in pages for ln in p.lines)


def _ocr_pages(path: Path, only: int | None = None) -> tuple[list[Page], Section5 | None]:
    """OCR page `only`, or page after page until section 5's narrative has closed (and, on REV. 2/2017, the
    tables' page after it); the rest of the form holds nothing a sketch uses."""
    pages: list[Page] = []
    found = None
    total = ocr.page_count(path)
    for number in ([only] if only is not None else range(total)):
        pages.append(ocr.ocr_page(path, number))
        found = find_narrative(pages)
        if found and found.closed:
            break
    if only is None and found and pages[-1].number + 1 < total and any(
            "316REV" in compact(ln.text) for pg in pages for ln in pg.lines):
        # REV. 2/2017 prints section 5's check-box tables on the page after the narrative.
        pages.append(ocr.ocr_page(path, pages[-1].number + 1))
    return pages, found


def read(path: str | Path) -> ReadResult:
    """Read an OL 316 PDF; InputError (naming the file) when no narrative can be read."""
    p = Path(path)
    pages = read_pages(p)
    notes: list[str] = []
    has_text = _text_chars(pages) >= _MIN_TEXT
    found = find_narrative(pages) if has_text else None
    source = "form_fields" if found and found.from_fields else "text"
    if not has_text or found is None or readability(found.text) < READABLE:
        # No text, a text layer without section 5 (an OCR layer that lost it), or one that reads as garbage.
        why = ("no text layer (a scanned form)" if not has_text else
               "no section 5 narrative in its text layer" if found is None else
               f"an unreadable OCR layer ({readability(found.text):.0%} word-like tokens)")
        if not ocr.available():
            if found is None and has_text:
                raise InputError("no section 5 narrative (ACCIDENT DETAILS - DESCRIPTION) found in the PDF",
                                 source=str(p), element="section 5")
            raise InputError(f"PDF has {why}; install Tesseract (Debian: apt-get install tesseract-ocr) to read it "
                             "by OCR", source=str(p))
        ocr_pages, ocr_found = _ocr_pages(p, found.page if found else None)
        if ocr_found is None:
            raise InputError(f"PDF has {why} and OCR found no section 5 narrative in it", source=str(p),
                             element="section 5")
        notes.append(f"PDF has {why}: narrative read by Tesseract OCR (may carry OCR slips)")
        if not has_text:
            pages = ocr_pages  # the boxes too can only come from the OCR
        found, source = ocr_found, "ocr"
    if found is None:
        raise InputError("no section 5 narrative (ACCIDENT DETAILS - DESCRIPTION) found in the PDF", source=str(p),
                         element="section 5")
    v1: dict[str, tuple[str, ...]] = {}
    v2: dict[str, tuple[str, ...]] = {}
    for page in pages:
        image = raster.render(p, page.number, 150) if has_tables(page) else None
        t1, t2 = read_tables(page, image)
        v1.update(t1)
        v2.update(t2)
    if not v1 and not v2:
        v1 = dict(read_inline(pages))
    was1, was2 = read_vehicle_was(pages)
    if was1:
        v1["vehicle_was"] = was1
    if was2:
        v2["vehicle_was"] = was2
    return ReadResult(found.text, source, v1, v2, tuple(notes))
