"""The OL 316 check boxes, read by geometry as a person reads them.

REV. 2/2017 prints section 5's tables (WEATHER, LIGHTING, ROADWAY SURFACE, ROADWAY CONDITIONS, MOVEMENT PRECEDING
COLLISION, TYPE OF COLLISION, OTHER ASSOCIATED FACTORS) as lettered options with two tick columns, VEH 1 and VEH 2,
to the right of each option. A tick is a mark piece (an "X" or "✓" in the text layer, or a ticked widget of a
fillable form); it belongs to the option on its row nearest to its left, in the table whose caption is above that
option in the same column, and to the vehicle whose column header is nearest above it. Both revisions also have
"Vehicle was: [ ] Moving [ ] Stopped in Traffic" in sections 2 (VEH 1) and 3 (VEH 2), ticked left of the label.
A form that prints marked boxes inline ("[X] CLEAR") is read from the line text.
"""

from __future__ import annotations

import difflib
import re

from .layout import Page, Piece
from .narrative import compact
from .raster import PageImage

#: Table caption (letters only) -> field name, and the options each table prints (labels normalised as `label()`).
TABLES: dict[str, tuple[str, tuple[str, ...]]] = {
    "WEATHER": ("weather", ("clear", "cloudy", "raining", "snowing", "fog/visibility", "other", "wind")),
    "LIGHTING": ("lighting", ("daylight", "dusk-dawn", "dark-street lights", "dark-no street lights",
                              "dark-street lights not functioning")),
    "ROADWAYSURFACE": ("roadway_surface", ("dry", "wet", "snowy-icy", "slippery (muddy, oily, etc.)")),
    "ROADWAYCONDITIONS": ("roadway_conditions", (
        "holes, deep rut", "loose material on roadway", "obstruction on roadway", "construction-repair zone",
        "reduced roadway width", "flooded", "other", "no unusual conditions")),
    "MOVEMENTPRECEDING": ("movement_preceding_collision", (
        "stopped", "proceeding straight", "ran off road", "making right turn", "making left turn", "making u turn",
        "backing", "slowing/stopping", "passing other vehicle", "changing lanes", "parking manuever",
        "entering traffic", "other unsafe turning", "xing into opposing lane", "parked", "merging",
        "traveling wrong way", "other")),
    "TYPEOFCOLLISION": ("type_of_collision", ("head-on", "side swipe", "rear end", "broadside", "hit object",
                                              "overturned", "vehicle/pedestrian", "other")),
    "OTHERASSOCIATED": ("other_associated_factors", (
        "cvc sections violated", "vision obscurement", "inattention", "stop & go traffic", "entering/leaving ramp",
        "previous collision", "unfamiliar with road", "defective veh equip", "uninvolved vehicle", "other",
        "none apparent", "runaway vehicle")),
}
VEHICLE_WAS = ("moving", "stopped in traffic")
_OPTION = re.compile(r"^\s*([A-Ra-r0-9])\s*[.,]\s*(\S.*)$")
_INLINE = re.compile(r"(?:\[\s*[Xx✓✔]\s*\]|☒|☑|■)\s*([A-Za-z][A-Za-z /*\-]+?)(?=\s*(?:\[|☐|☒|☑|□|■|$))")
_INLINE_FIELDS = {"WEATHER": "weather", "LIGHTING": "lighting", "ROADWAYSURFACE": "roadway_surface",
                  "ROADWAYCONDITIONS": "roadway_conditions", "MOVEMENTPRECEDINGCOLLISION": "movement_preceding_collision",
                  "TYPEOFCOLLISION": "type_of_collision", "OTHERASSOCIATEDFACTORS": "other_associated_factors",
                  "PEDESTRIANBICYCLISTINVOLVED": "involved", "INVOLVED": "involved"}

Boxes = dict[str, tuple[str, ...]]


def label(text: str) -> str:
    """An option label as the form vocabulary spells it: lower case, no footnote star, "DARK -STREET" ->
    "dark-street", single spaces."""
    t = re.sub(r"\s*-\s*", "-", text.lower().replace("*", ""))
    return re.sub(r"\s+", " ", t).strip()


def _option(text: str, vocabulary: tuple[str, ...]) -> str | None:
    """The printed option a (possibly OCR-damaged, possibly first-line-only) label stands for."""
    mine = re.sub(r"[^a-z]", "", label(text))
    if not mine:
        return None
    best, score = None, 0.0
    for opt in vocabulary:
        ref = re.sub(r"[^a-z]", "", opt)
        head = ref[:max(len(mine), 4)]
        s = max(difflib.SequenceMatcher(None, mine, ref).ratio(), difflib.SequenceMatcher(None, mine, head).ratio())
        if s > score:
            best, score = opt, s
    return best if score >= 0.75 else None


def _captions(page: Page) -> list[tuple[Piece, str]]:
    out = []
    for ln in page.lines:
        c = compact(ln.text)
        for key in TABLES:
            if key in c and len(c) <= len(key) + 30:
                out.append((ln, key))
                break
    return out


def _options(page: Page, captions: list[tuple[Piece, str]]) -> list[tuple[Piece, str, str]]:
    """(piece, field, printed option) for every lettered option under a caption of its column."""
    out = []
    for p in page.pieces:
        if p.kind != "text":
            continue
        m = _OPTION.match(p.text)
        if not m:
            continue
        above = [(cap, key) for cap, key in captions
                 if cap.y0 > p.yc and p.x0 - 40 <= cap.xc <= p.x0 + 160]
        if not above:
            continue
        cap, key = min(above, key=lambda ck: ck[0].y0 - p.yc)
        field, vocabulary = TABLES[key]
        opt = _option(m.group(2), vocabulary)
        if opt:
            out.append((p, field, opt))
    return out


def _vehicle_headers(page: Page) -> list[tuple[float, float, int]]:
    """(x centre, y, vehicle number) of each "VEH 1" / "VEH 2" column header."""
    vehs = [p for p in page.pieces if p.kind == "text" and compact(p.text).startswith("VEH")]
    out = []
    for p in page.pieces:
        if p.kind == "text" and p.text.strip() in ("1", "2"):
            for v in vehs:
                # The digit sits under its "VEH" (which an OCR layer may have merged with the next caption).
                if 0 <= v.yc - p.yc < 25 and (abs(v.xc - p.xc) < 15 or (v.x0 - 5 <= p.xc <= v.x0 + 30)):
                    out.append((p.xc, p.yc, int(p.text.strip())))
                    break
        elif p.kind == "text" and re.fullmatch(r"VEH\s*[12]", p.text.strip()):
            out.append((p.xc, p.yc, int(p.text.strip()[-1])))
    return out


def has_tables(page: Page) -> bool:
    return bool(_captions(page))


def read_tables(page: Page, image: PageImage | None = None) -> tuple[Boxes, Boxes]:
    """The ticked options of section 5's tables on one page: (VEH 1 column, VEH 2 column). Ticks are mark pieces
    and, given the page image, ink in a tick column's cell on the option's row (a hand tick no OCR turned into a
    glyph)."""
    captions = _captions(page)
    if not captions:
        return {}, {}
    options = _options(page, captions)
    headers = _vehicle_headers(page)
    cols: tuple[dict[str, list[str]], dict[str, list[str]]] = ({}, {})
    if image is not None:
        starts = sorted({round(p.x0) for p, _, _ in options})
        for p, field, opt in options:
            right = next((x for x in starts if x > p.x0 + 25), page.width)
            for hx, hy, vehicle in headers:
                if p.x0 < hx < right and hy > p.yc and image.ticked(hx - 7, p.yc - 5, hx + 7, p.yc + 5):
                    got = cols[vehicle - 1].setdefault(field, [])
                    if opt not in got:
                        got.append(opt)
    for mark in (p for p in page.pieces if p.kind == "mark"):
        # The mark's column of options is the nearest one to its left; a mark right of another column's labels
        # (the CITED YES/NO boxes of OTHER ASSOCIATED FACTORS) is no tick of this column.
        left = [p.x0 for p, _, _ in options if p.x0 < mark.x0]
        if not left:
            continue
        column = max(left)
        row = [(p, f, o) for p, f, o in options
               if column - 25 <= p.x0 <= column and abs(p.yc - mark.yc) < max(p.height, 7.0)]
        if not row:
            continue
        p, field, opt = min(row, key=lambda r: abs(r[0].yc - mark.yc))
        # Nearest column header above the mark, within this table's column band (right of the option).
        near = [h for h in headers if h[1] > mark.yc and p.x0 < h[0] < mark.x1 + 40]
        vehicle = min(near, key=lambda h: abs(h[0] - mark.xc))[2] if near else 1
        got = cols[vehicle - 1].setdefault(field, [])
        if opt not in got:
            got.append(opt)
    return ({k: tuple(v) for k, v in cols[0].items()}, {k: tuple(v) for k, v in cols[1].items()})


def read_vehicle_was(pages: list[Page]) -> tuple[tuple[str, ...], tuple[str, ...]]:
    """Sections 2 and 3's "Vehicle was: Moving / Stopped in Traffic" ticks (VEH 1, VEH 2), where a tick piece sits
    just left of the label (a fillable form's widget, or a mark in the text layer)."""
    found: list[list[str]] = []
    for page in pages:
        labels = sorted((p for p in page.pieces if p.kind == "text" and label(p.text).endswith(VEHICLE_WAS)),
                        key=lambda p: -p.yc)
        ticked: set[int] = set()
        for m in (p for p in page.pieces if p.kind == "mark"):
            near = [i for i, lab in enumerate(labels)
                    if abs(m.yc - lab.yc) < max(lab.height, 6.0) and lab.x0 - 3 * lab.height <= m.xc <= lab.x0 + 2]
            if near:
                ticked.add(min(near, key=lambda i: abs(labels[i].yc - m.yc)))
        groups: list[tuple[Piece, list[str]]] = []
        for i, lab in enumerate(labels):
            opt = next(o for o in VEHICLE_WAS if label(lab.text).endswith(o))
            got = [opt] if i in ticked else []
            # "Moving" and "Stopped in Traffic" of one section are stacked within two lines of each other.
            if groups and abs(groups[-1][0].yc - lab.yc) < 3 * lab.height and opt == "stopped in traffic":
                groups[-1][1].extend(got)
            else:
                groups.append((lab, got))
        found.extend(g[1] for g in groups)
    v1 = tuple(found[0]) if found else ()
    v2 = tuple(found[1]) if len(found) > 1 else ()
    return v1, v2


def read_inline(pages: list[Page], skip: tuple[int, int] | None = None) -> Boxes:
    """Boxes printed as marked glyphs before each option on the caption's line or the next ("[X] CLEAR")."""
    fields: dict[str, list[str]] = {}
    current: str | None = None
    for page in pages:
        for ln in page.lines:
            if ln.kind == "field":
                continue
            c = compact(ln.text)
            text = ln.text
            for cap, name in _INLINE_FIELDS.items():
                if c.startswith(cap):
                    current = name
                    text = ""
                    break
            if current is None:
                continue
            for opt in _INLINE.findall(text):
                fields.setdefault(current, []).append(label(opt))
    return {k: tuple(v) for k, v in fields.items()}
