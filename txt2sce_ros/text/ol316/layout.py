"""What a PDF page shows, with where it shows it: text lines, their word-like pieces, filled form fields and marks.

Every kind of OL 316 PDF is brought to this one shape, so the narrative and the check boxes are read the same way
whatever the source: a text layer (typed, or an OCR layer added by the DMV's scanner), the values of a fillable
form's fields (drawn at their widget rectangles, as a viewer draws them), and Tesseract's words for a scan
(`ocr.py`). Coordinates are PDF points, origin bottom left, y up.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ...errors import InputError

#: Glyphs a filer or a scanner's OCR uses for a tick in a check-box column.
MARK_GLYPHS = frozenset("Xx✓✔✗✘√×☒☑■")


@dataclass(frozen=True, slots=True)
class Piece:
    """A run of text (or a mark) at a place on a page. `kind`: `text`, `field` (a form field's value) or `mark`."""

    text: str
    x0: float
    y0: float
    x1: float
    y1: float
    kind: str = "text"

    @property
    def yc(self) -> float:
        return (self.y0 + self.y1) / 2

    @property
    def xc(self) -> float:
        return (self.x0 + self.x1) / 2

    @property
    def height(self) -> float:
        return max(self.y1 - self.y0, 1.0)


@dataclass(frozen=True, slots=True)
class Page:
    """One page: `lines` in reading order (top to bottom, then left to right), `pieces` split at wide gaps and at
    isolated marks (what the check-box geometry works on)."""

    number: int
    width: float
    height: float
    lines: tuple[Piece, ...]
    pieces: tuple[Piece, ...]


def reading_order(items: list[Piece]) -> tuple[Piece, ...]:
    """Top to bottom, left to right; pieces whose vertical centres are within a third of a line count as one row."""
    rows: list[list[Piece]] = []
    for p in sorted(items, key=lambda q: -q.y1):
        for row in rows:
            ref = row[0]
            if abs(ref.yc - p.yc) < 0.35 * min(ref.height, p.height) and p.kind != "field" and ref.kind != "field":
                row.append(p)
                break
        else:
            rows.append([p])
    return tuple(p for row in rows for p in sorted(row, key=lambda q: q.x0))


def split_line(chars: list[tuple[str, float, float, float, float]]) -> list[Piece]:
    """Split one text line's characters into pieces at gaps wider than the line height and around lone marks
    (an OCR layer often merges a tick with the next column's label: "✓  O. PARKED")."""
    out: list[Piece] = []
    cur: list[tuple[str, float, float, float, float]] = []

    def flush() -> None:
        text = "".join(c[0] for c in cur).strip()
        if text:
            kind = "mark" if len(text) == 1 and text in MARK_GLYPHS else "text"
            out.append(Piece(text, min(c[1] for c in cur), min(c[2] for c in cur), max(c[3] for c in cur),
                             max(c[4] for c in cur), kind))
        cur.clear()

    for i, ch in enumerate(chars):
        if cur:
            prev = next((c for c in reversed(cur) if c[0].strip()), cur[-1])
            height = max(prev[4] - prev[2], 4.0)
            gap = ch[1] - prev[3]
            if ch[0].strip() and gap > 0.9 * height:
                flush()
        lone_mark = ch[0] in MARK_GLYPHS and _alone(chars, i)
        if lone_mark:
            flush()
            cur.append(ch)
            flush()
            continue
        cur.append(ch)
    flush()
    return out


def _alone(chars: list[tuple[str, float, float, float, float]], i: int) -> bool:
    """Is character i a word of its own (no letter touching it on either side)?"""
    def letter(j: int) -> bool:
        return 0 <= j < len(chars) and chars[j][0].isalnum()
    return not letter(i - 1) and not letter(i + 1)


def _decode(value: Any) -> str:
    from pdfminer.utils import decode_text

    if isinstance(value, bytes):
        return decode_text(value)
    return str(value) if value is not None else ""


def _name(value: Any) -> str:
    from pdfminer.psparser import PSLiteral

    return value.name if isinstance(value, PSLiteral) else _decode(value)


def _inherited(annot: dict, key: str) -> Any:
    """A field attribute, looked up through the widget's parents (PDF 32000 §12.7.3.1: FT, V, Ff inherit)."""
    from pdfminer.pdftypes import resolve1

    node: Any = annot
    for _ in range(12):
        if not isinstance(node, dict):
            return None
        if key in node:
            return resolve1(node[key])
        node = resolve1(node.get("Parent"))
    return None


def widget_pieces(page: Any) -> list[Piece]:
    """A fillable form's filled fields on one page: text values as `field` pieces at their rectangles, ticked
    check boxes (appearance state other than Off) as `mark` pieces."""
    from pdfminer.pdftypes import resolve1

    out: list[Piece] = []
    for ref in resolve1(page.annots) or []:
        annot = resolve1(ref)
        if not isinstance(annot, dict) or _name(annot.get("Subtype")) != "Widget":
            continue
        rect = resolve1(annot.get("Rect"))
        if not rect or len(rect) != 4:
            continue
        x0, y0, x1, y1 = (float(resolve1(v)) for v in rect)
        x0, x1, y0, y1 = min(x0, x1), max(x0, x1), min(y0, y1), max(y0, y1)
        ftype = _name(_inherited(annot, "FT"))
        if ftype == "Tx":
            text = _decode(_inherited(annot, "V")).replace("\r\n", "\n").replace("\r", "\n").strip()
            if text:
                # The value sits at the top of its box, where a viewer starts drawing it.
                out.append(Piece(text, x0, y1 - 12.0, x1, y1, "field"))
        elif ftype == "Btn":
            state = annot.get("AS")
            state = _name(resolve1(state)) if state is not None else _name(_inherited(annot, "V"))
            if state and state != "Off":
                out.append(Piece("X", x0, y0, x1, y1, "mark"))
    return out


def read_pages(path: Path) -> list[Page]:
    """The text-layer pages of a PDF with its filled form fields; InputError when it is not a readable PDF."""
    from pdfminer.high_level import extract_pages
    from pdfminer.layout import LAParams, LTChar, LTTextLine
    from pdfminer.pdfdocument import PDFDocument
    from pdfminer.pdfpage import PDFPage
    from pdfminer.pdfparser import PDFParser, PDFSyntaxError

    # pdfminer logs a warning for every form marked "no text extraction"; reading it is what the filer intended.
    logging.getLogger("pdfminer").setLevel(logging.ERROR)
    try:
        with open(path, "rb") as fh:
            doc = PDFDocument(PDFParser(fh))
            widgets = [widget_pieces(pg) for pg in PDFPage.create_pages(doc)]
        layouts = list(extract_pages(str(path), laparams=LAParams()))
    except FileNotFoundError as exc:
        raise InputError("file not found", source=str(path)) from exc
    except (PDFSyntaxError, ValueError, TypeError, KeyError) as exc:
        raise InputError(f"not a readable PDF ({type(exc).__name__}: {exc})", source=str(path)) from exc
    except Exception as exc:  # pdfminer raises many private types on damaged files
        raise InputError(f"not a readable PDF ({type(exc).__name__})", source=str(path)) from exc

    def text_lines(obj: Any) -> Any:
        if isinstance(obj, LTTextLine):
            yield obj
        elif hasattr(obj, "__iter__"):
            for child in obj:
                yield from text_lines(child)

    pages = []
    for number, layout in enumerate(layouts):
        lines: list[Piece] = []
        pieces: list[Piece] = []
        for line in text_lines(layout):
            text = line.get_text().strip()
            if not text:
                continue
            lines.append(Piece(text, line.x0, line.y0, line.x1, line.y1))
            chars = [(c.get_text(), c.x0, c.y0, c.x1, c.y1) for c in line if isinstance(c, LTChar)]
            pieces.extend(split_line(chars))
        extra = widgets[number] if number < len(widgets) else []
        lines.extend(p for p in extra if p.kind == "field")
        pieces.extend(extra)
        pages.append(Page(number, float(layout.width), float(layout.height), reading_order(lines),
                          tuple(pieces)))
    return pages
