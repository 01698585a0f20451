"""Page images (PDFium): what Tesseract reads, and where ticks drawn on a scan are seen as ink."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from ...errors import InputError

#: A tick-column cell with at least this share of dark pixels is ticked. On the shared scans an empty cell is
#: blank paper (0.000) and a tick covers 0.08-0.12 of the cell.
TICK_INK = 0.03


class PageImage:
    """A page rendered in grey levels, with PDF point -> pixel conversion (PDF y grows upwards)."""

    def __init__(self, image: Any, dpi: int, height_pt: float, width_pt: float) -> None:
        self.image = image  # PIL "L" image
        self.scale = dpi / 72
        self.height_pt = height_pt
        self.width_pt = width_pt
        self._array: Any = None

    def ticked(self, x0: float, y0: float, x1: float, y1: float) -> bool:
        """Is there a tick in this rectangle (PDF points)? Enough dark pixels, spread over most of its height and
        a good part of its width: a ruled line or a speck crossing the cell is not a tick."""
        import numpy as np

        if self._array is None:
            self._array = np.asarray(self.image)
        s = self.scale
        rows = slice(max(int((self.height_pt - y1) * s), 0), max(int((self.height_pt - y0) * s), 0))
        cols = slice(max(int(x0 * s), 0), max(int(x1 * s), 0))
        dark = self._array[rows, cols] < 140
        if not dark.size:
            return False
        return bool(dark.mean() >= TICK_INK and dark.any(axis=1).mean() >= 0.4 and dark.any(axis=0).mean() >= 0.3)


def render(path: Path, number: int, dpi: int) -> PageImage:
    """Page `number` of `path` in grey levels at `dpi`."""
    import pypdfium2 as pdfium

    try:
        doc = pdfium.PdfDocument(str(path))
    except Exception as exc:  # PDFium raises its own error type on damaged files
        raise InputError(f"cannot render the PDF ({exc})", source=str(path)) from exc
    try:
        page = doc[number]
        width, height = page.get_size()
        image = page.render(scale=dpi / 72).to_pil().convert("L")
    except Exception as exc:
        raise InputError(f"cannot render page {number + 1} ({exc})", source=str(path)) from exc
    finally:
        doc.close()
    return PageImage(image, dpi, float(height), float(width))
