"""California DMV OL 316 PDFs: section 5's narrative and the form's check boxes, from the PDF text layer.

A filled OL 316 carries its check boxes in the text layer as marked boxes before each option ("[X] CLEAR", "☒ CLEAR",
"X CLEAR" in a box column) under a field caption (WEATHER, LIGHTING, ROADWAY SURFACE, MOVEMENT PRECEDING COLLISION,
TYPE OF COLLISION, ...), and the narrative after the section 5 caption ("ACCIDENT DETAILS - DESCRIPTION"). A scanned
form without a text layer cannot be read here (no OCR): it is rejected with an error naming the file.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

from ..errors import InputError

#: Field captions of the form (upper case in the text layer) -> our field name.
_FIELDS = {
    "WEATHER": "weather",
    "LIGHTING": "lighting",
    "ROADWAY SURFACE": "roadway_surface",
    "ROADWAY CONDITIONS": "roadway_conditions",
    "MOVEMENT PRECEDING COLLISION": "movement_preceding_collision",
    "TYPE OF COLLISION": "type_of_collision",
    "OTHER ASSOCIATED FACTORS": "other_associated_factors",
    "PEDESTRIAN/BICYCLIST INVOLVED": "involved",
    "INVOLVED": "involved",
}
_CHECKED = re.compile(r"(?:\[\s*[Xx✓✔]\s*\]|☒|☑|■)\s*([A-Za-z][A-Za-z /*\-]+?)"
                      r"(?=\s*(?:\[|☐|☒|☑|□|■|$))")
_SECTION5 = re.compile(r"(?:SECTION\s*5\b|5\s*[.)]?\s*ACCIDENT\s+DETAILS\s*[-–]\s*DESCRIPTION)[^\n]*\n", re.I)
_SECTION_END = re.compile(r"\n\s*(?:SECTION\s*6\b|6\s*[.)]\s*[A-Z]|OL\s*316\s*\(REV|PAGE\s+\d+\s+OF)", re.I)
_REPORT_ID = re.compile(r"(?:REPORT\s+(?:ID|NUMBER|NO\.?)|DATE\s+OF\s+ACCIDENT)\s*[:#]?\s*([\w/-]+)", re.I)


@dataclass(frozen=True)
class FormFields:
    """The form's check boxes, lower-case option labels per field (as in dev_form_labels.jsonl's `ol316`)."""

    fields: dict[str, tuple[str, ...]] = field(default_factory=dict)

    def get(self, name: str) -> tuple[str, ...]:
        return self.fields.get(name, ())


@dataclass(frozen=True)
class Ol316:
    narrative: str
    form: FormFields
    source: str


def text_layer(path: str | Path) -> str:
    """All text of a PDF; InputError when the file is no PDF or has no text layer (a scan)."""
    from pdfminer.high_level import extract_text
    from pdfminer.pdfparser import PDFSyntaxError

    p = Path(path)
    try:
        text = extract_text(str(p))
    except FileNotFoundError as exc:
        raise InputError("file not found", source=str(p)) from exc
    except (PDFSyntaxError, ValueError, TypeError, KeyError) as exc:
        raise InputError(f"not a readable PDF ({type(exc).__name__}: {exc})", source=str(p)) from exc
    except Exception as exc:  # pdfminer raises many private types on damaged files
        raise InputError(f"not a readable PDF ({type(exc).__name__})", source=str(p)) from exc
    if not text or not text.strip():
        raise InputError("PDF has no text layer (a scanned form?); run OCR first, txt2sce reads text only",
                         source=str(p))
    return text


def parse_ol316(text: str, source: str) -> Ol316:
    """Split an OL 316 text layer into section 5's narrative and the checked boxes."""
    m = _SECTION5.search(text)
    if not m:
        raise InputError("no section 5 (ACCIDENT DETAILS - DESCRIPTION) in the PDF text layer", source=source,
                         element="section 5")
    rest = text[m.end():]
    end = _SECTION_END.search(rest)
    narrative = re.sub(r"\s+", " ", rest[:end.start()] if end else rest).strip()
    if not narrative:
        raise InputError("section 5 narrative is empty", source=source, element="section 5")
    fields: dict[str, list[str]] = {}
    current: str | None = None
    for line in text[:m.start()].splitlines() + (text[m.end() + (end.end() if end else len(rest)):].splitlines()):
        caption = line.strip().rstrip(":").upper()
        for cap, name in _FIELDS.items():
            if caption.startswith(cap):
                current = name
                line = line.strip()[len(cap):]
                break
        if current is None:
            continue
        for opt in _CHECKED.findall(line):
            fields.setdefault(current, []).append(opt.strip().lower())
    return Ol316(narrative=narrative, form=FormFields({k: tuple(v) for k, v in fields.items()}), source=source)


def read_ol316(path: str | Path) -> Ol316:
    """Read an OL 316 PDF: narrative plus check boxes."""
    return parse_ol316(text_layer(path), str(path))
