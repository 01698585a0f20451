"""Section 5 of an OL 316: the narrative, from the caption (or the mode boxes under it) to where the text ends.

Both revisions put the "Autonomous Mode / Conventional Mode" boxes right under the caption and close the
narrative with an "Additional information attached" box; REV. 2/2017 goes on with the check-box tables on the next
page, which are not narrative. So the narrative is the lines after the mode boxes up to the first closing line:
that box, section 6, the form's footer or the tables' heading. Scanner OCR damages captions ("SECT ION 5",
"ACCIDENT DETAILS- DESCRIPTION"), so they are matched on their letters only.
"""

from __future__ import annotations

import re
from typing import NamedTuple

from .layout import Page, Piece


class Section5(NamedTuple):
    text: str  # whitespace collapsed
    closed: bool  # its closing line was seen (an OCR pass reads pages until it is)
    from_fields: bool  # all of it came from a fillable form's field values
    page: int  # the page it is on


def compact(text: str) -> str:
    """Upper-case letters and digits only: "ROA DWAY SU RFACE" -> "ROADWAYSURFACE"."""
    return re.sub(r"[^A-Z0-9]", "", text.upper())


_CAPTION = re.compile(r"SECTION5|ACCIDENTDETAILS")
#: The mode boxes' labels, OCR slips allowed ("Conventional Modo", "ventlonal Moda").
_MODE = re.compile(r"[A-Z]*(?:NOMOUS|NTIONA[A-Z]|NTLONA[A-Z])M[A-Z]D[A-Z]")
#: Both mode boxes in running text: what precedes them on an OCR line is the scanned caption's debris.
_MODES_INLINE = re.compile(r"a\w*onomous\s+mod\w\W{0,15}\w{0,3}\W{0,10}c\w{2,4}[ei]nt[il]onal\s+mod\w", re.I)
_END = re.compile(r"ADDITIONALINF|SECTION6|CERTIFICATION|CERTIFY|FOREGOING|PENALTYOFPERJURY|316(?:NEW|REV)"
                  r"|ITEMSMARKEDBELOW|PAGE\d+OF\d+")
#: A gap this many line heights wide after the narrative's last line ends it (a scan's garbled captions below).
_GAP = 4.0


def _is_mode_line(line: Piece) -> bool:
    """The mode boxes' line: their labels and box glyphs only (a narrative line that says "was operating in
    Autonomous Mode" has much more)."""
    c = compact(line.text)
    return line.kind != "field" and bool(_MODE.search(c)) and len(_MODE.sub("", c)) <= 4


def find_narrative(pages: list[Page]) -> Section5 | None:
    """Section 5's narrative, or None when there is none."""
    lines = [(page.number, ln) for page in pages for ln in page.lines]
    start = next((i for i, (_, ln) in enumerate(lines) if _CAPTION.search(compact(ln.text))
                  and ln.kind != "field"), None)
    if start is None:
        # An OCR layer may have lost the caption; the mode boxes under it still mark the section.
        start = next((i - 1 for i, (_, ln) in enumerate(lines) if _is_mode_line(ln)), None)
        if start is None:
            return None
    body: list[Piece] = []
    closed = False
    page = lines[start][0]
    for number, ln in lines[start + 1:]:
        if not body and _is_mode_line(ln):
            continue
        if ln.kind != "field" and _END.search(compact(ln.text)):
            closed = True
            break
        if body and (number != page or body[-1].y0 - ln.y1 > _GAP * max(body[-1].height, 8.0)):
            # The narrative box ends on its page; REV. 2/2017's tables follow on the next one.
            closed = True
            break
        if not body:
            page = number
        body.append(ln)
    parts = [ln.text for ln in body]
    # A scan's garbled caption can come before the mode boxes: the narrative starts after them.
    cut = None
    for i, ln in enumerate(body[:3]):
        m = _MODES_INLINE.search(ln.text) if ln.kind != "field" else None
        if m or (ln.kind != "field" and _is_mode_line(ln)):
            cut = (i, m.end() if m else len(ln.text))
    if cut:
        parts = [parts[cut[0]][cut[1]:]] + parts[cut[0] + 1:]
    text = re.sub(r"\s+", " ", " ".join(parts)).strip()
    return Section5(text, closed, all(ln.kind == "field" for ln in body), page) if text else None
