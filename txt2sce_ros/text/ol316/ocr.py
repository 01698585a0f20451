"""OCR of scanned OL 316 pages with Tesseract, into the same `Page` shape as a text layer.

Pages are rendered with PDFium (`pypdfium2`) and read by the `tesseract` program (Debian `tesseract-ocr`) through
`pytesseract`; Tesseract's words come back grouped into its lines, with boxes converted to PDF points. When the
program is not installed, `available()` is False and callers refuse the scan by name instead.
"""

from __future__ import annotations

import shutil
from functools import lru_cache
from pathlib import Path

from .layout import MARK_GLYPHS, Page, Piece, reading_order
from .raster import render

#: Render resolution: Tesseract reads 10-point form print best near 300 dpi.
DPI = 300


@lru_cache(maxsize=1)
def available() -> bool:
    """Is Tesseract installed (the program and its Python wrapper)?"""
    if shutil.which("tesseract") is None:
        return False
    try:
        import pytesseract  # noqa: F401
        import pypdfium2  # noqa: F401
    except ImportError:
        return False
    return True


def page_count(path: Path) -> int:
    import pypdfium2 as pdfium

    doc = pdfium.PdfDocument(str(path))
    try:
        return len(doc)
    finally:
        doc.close()


def ocr_page(path: Path, number: int, *, dpi: int = DPI) -> Page:
    """Render page `number` of `path` and read it with Tesseract."""
    import os

    import pytesseract

    # One thread per Tesseract: on a shared machine its OpenMP threads only contend (and are slower in total).
    os.environ.setdefault("OMP_THREAD_LIMIT", "1")
    rendered = render(path, number, dpi)
    image, width, height = rendered.image, rendered.width_pt, rendered.height_pt
    data = pytesseract.image_to_data(image, lang="eng", config="--psm 3",
                                     output_type=pytesseract.Output.DICT)
    k = 72 / dpi
    words: dict[tuple[int, int, int], list[Piece]] = {}
    for i, text in enumerate(data["text"]):
        text = (text or "").strip()
        if not text or float(data["conf"][i]) < 0:
            continue
        x0, top = data["left"][i] * k, data["top"][i] * k
        x1, bottom = x0 + data["width"][i] * k, top + data["height"][i] * k
        kind = "mark" if len(text) == 1 and text in MARK_GLYPHS else "text"
        words.setdefault((data["block_num"][i], data["par_num"][i], data["line_num"][i]), []).append(
            Piece(text, x0, height - bottom, x1, height - top, kind))
    lines: list[Piece] = []
    pieces: list[Piece] = []
    for ws in words.values():
        ws.sort(key=lambda w: w.x0)
        lines.append(Piece(" ".join(w.text for w in ws), min(w.x0 for w in ws), min(w.y0 for w in ws),
                           max(w.x1 for w in ws), max(w.y1 for w in ws)))
        pieces.extend(_merge(ws))
    return Page(number, float(width), float(height), reading_order(lines), tuple(pieces))


def _merge(words: list[Piece]) -> list[Piece]:
    """Words of one line joined into pieces, split where the gap is wider than the line is high (as the text layer
    is split in `layout.split_line`); marks stay pieces of their own."""
    out: list[Piece] = []
    for w in words:
        prev = out[-1] if out else None
        if (prev is None or w.kind == "mark" or prev.kind == "mark"
                or w.x0 - prev.x1 > 0.9 * max(prev.height, w.height)):
            out.append(w)
        else:
            out[-1] = Piece(f"{prev.text} {w.text}", prev.x0, min(prev.y0, w.y0), w.x1, max(prev.y1, w.y1))
    return out
