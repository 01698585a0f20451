"""Writes small OL 316-like PDFs for the tests (no real DMV PDFs ship with the project).

The layout follows the form's parts that the reader uses: a header, section 2's condition boxes (WEATHER, LIGHTING,
ROADWAY SURFACE), section 3's per-vehicle boxes (MOVEMENT PRECEDING COLLISION, TYPE OF COLLISION), the
pedestrian/bicyclist box, section 5's narrative and a section 6 caption after it. A checked box is drawn as "[X]",
an empty one as "[ ]", as a filled form's text layer carries them.
"""

from __future__ import annotations

from pathlib import Path

from fpdf import FPDF

WEATHER = ("CLEAR", "CLOUDY", "RAINING", "SNOWING", "FOG/VISIBILITY", "OTHER")
LIGHTING = ("DAYLIGHT", "DUSK-DAWN", "DARK-STREET LIGHTS", "DARK-NO STREET LIGHTS")
SURFACE = ("DRY", "WET", "SNOWY-ICY", "SLIPPERY")
MOVEMENT = ("STOPPED", "PROCEEDING STRAIGHT", "MAKING RIGHT TURN", "MAKING LEFT TURN", "BACKING", "CHANGING LANES")
COLLISION = ("HEAD-ON", "SIDE SWIPE", "REAR END", "BROADSIDE", "HIT OBJECT", "VEHICLE/PEDESTRIAN", "OTHER")


def _boxes(pdf: FPDF, caption: str, options: tuple[str, ...], checked: set[str]) -> None:
    pdf.set_font("Helvetica", "B", 8)
    pdf.cell(0, 5, caption, new_x="LMARGIN", new_y="NEXT")
    pdf.set_font("Helvetica", "", 8)
    line = "  ".join(f"[{'X' if o in checked else ' '}] {o}" for o in options)
    pdf.multi_cell(0, 4, line, new_x="LMARGIN", new_y="NEXT")


def write_ol316(path: Path, narrative: str, *, weather: str = "CLEAR", lighting: str = "DAYLIGHT",
                surface: str = "DRY", movement_av: str = "STOPPED", collision: str = "REAR END",
                pedestrian: bool = False) -> Path:
    pdf = FPDF(format="letter")
    pdf.add_page()
    pdf.set_font("Helvetica", "B", 11)
    pdf.cell(0, 7, "REPORT OF TRAFFIC COLLISION INVOLVING AN AUTONOMOUS VEHICLE (OL 316)",
             new_x="LMARGIN", new_y="NEXT")
    pdf.set_font("Helvetica", "", 8)
    pdf.cell(0, 5, "SECTION 2 - ACCIDENT INFORMATION", new_x="LMARGIN", new_y="NEXT")
    _boxes(pdf, "WEATHER", WEATHER, {weather})
    _boxes(pdf, "LIGHTING", LIGHTING, {lighting})
    _boxes(pdf, "ROADWAY SURFACE", SURFACE, {surface})
    pdf.cell(0, 5, "SECTION 3 - VEHICLE 1 (AUTONOMOUS VEHICLE)", new_x="LMARGIN", new_y="NEXT")
    _boxes(pdf, "MOVEMENT PRECEDING COLLISION", MOVEMENT, {movement_av})
    _boxes(pdf, "TYPE OF COLLISION", COLLISION, {collision})
    _boxes(pdf, "PEDESTRIAN/BICYCLIST INVOLVED", ("PEDESTRIAN", "BICYCLIST"), {"PEDESTRIAN"} if pedestrian else set())
    pdf.ln(3)
    pdf.set_font("Helvetica", "B", 9)
    pdf.cell(0, 6, "SECTION 5 - ACCIDENT DETAILS - DESCRIPTION", new_x="LMARGIN", new_y="NEXT")
    pdf.set_font("Helvetica", "", 9)
    pdf.multi_cell(0, 5, narrative, new_x="LMARGIN", new_y="NEXT")
    pdf.ln(3)
    pdf.set_font("Helvetica", "B", 9)
    pdf.cell(0, 6, "SECTION 6 - CERTIFICATION", new_x="LMARGIN", new_y="NEXT")
    pdf.output(str(path))
    return path


def write_scanned(path: Path) -> Path:
    """A PDF with drawings only and no text layer, like a scanned form."""
    pdf = FPDF(format="letter")
    pdf.add_page()
    for k in range(12):
        pdf.rect(15, 20 + 12 * k, 180, 8)
    pdf.line(15, 200, 195, 260)
    pdf.output(str(path))
    return path
