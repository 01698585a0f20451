"""California DMV OL 316 PDFs: section 5's narrative and the form's check boxes, for the extractor.

The reading itself lives in `text/ol316/` (one reader for text layers, fillable forms, OCR layers and scans); this
module gives the rest of txt2sce its typed result. A scan is read by Tesseract when it is installed and refused,
naming the file, when it is not.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

#: Fields of the environment that fall back to the VEH 2 column when the VEH 1 column is blank (companies tick
#: the shared conditions in one column or both).
_SHARED = ("weather", "lighting", "roadway_surface", "roadway_conditions")


@dataclass(frozen=True)
class FormFields:
    """The form's ticked options, lower-case printed labels per field: `fields` for VEH 1 (the AV; also a single
    column of boxes), `vehicle_2` for the VEH 2 column. Field names: weather, lighting, roadway_surface,
    roadway_conditions, movement_preceding_collision, type_of_collision, other_associated_factors, vehicle_was."""

    fields: dict[str, tuple[str, ...]] = field(default_factory=dict)
    vehicle_2: dict[str, tuple[str, ...]] = field(default_factory=dict)
    #: How the PDF was read (`text`, `form_fields`, `ocr`) and what the reader noted (OCR used, ...).
    read_as: str = "text"
    notes: tuple[str, ...] = ()

    def get(self, name: str, vehicle: int = 1) -> tuple[str, ...]:
        """The ticks of one vehicle's column; the shared conditions fall back to the other column when blank."""
        mine, other = (self.fields, self.vehicle_2) if vehicle == 1 else (self.vehicle_2, self.fields)
        got = mine.get(name, ())
        return got if got or name not in _SHARED else other.get(name, ())

    def to_dict(self) -> dict[str, dict[str, list[str]]]:
        return {"vehicle_1": {k: list(v) for k, v in self.fields.items()},
                "vehicle_2": {k: list(v) for k, v in self.vehicle_2.items()}}


@dataclass(frozen=True)
class Ol316:
    narrative: str
    form: FormFields
    source: str
    text_source: str = "text"  # text | form_fields | ocr
    notes: tuple[str, ...] = ()


def read_ol316(path: str | Path) -> Ol316:
    """Read an OL 316 PDF: narrative plus check boxes; InputError naming the file when no narrative is found."""
    from .ol316.reader import read

    r = read(path)
    form = FormFields(dict(r.vehicle_1), dict(r.vehicle_2), read_as=r.text_source, notes=r.notes)
    return Ol316(narrative=r.narrative, form=form, source=str(path), text_source=r.text_source, notes=r.notes)
