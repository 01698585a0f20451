"""Road marks and the lane changes they permit, read straight from the OpenDRIVE file.

The shared road model does not keep `<roadMark>` (geometry does not need it), so this module reads just those
elements with the same hardened parser settings. A mark sits on a lane's outer border; the centre lane's mark
separates lane 1 from lane -1.
"""

from __future__ import annotations

from dataclasses import dataclass

from lxml import etree

from ..errors import InputError
from ..xmlsafe import refuse_doctype

#: Mark types that forbid crossing when the map gives no explicit `laneChange`.
_NO_CROSS = {"solid", "solid solid", "curb", "grass", "edge"}


@dataclass(frozen=True)
class Mark:
    type: str
    lane_change: str | None  # OpenDRIVE roadMark/@laneChange: increase | decrease | both | none

    def allows(self, increasing: bool) -> bool:
        """May a vehicle cross this mark toward higher lane ids (`increasing`, i.e. toward +t) or lower ones?

        OpenDRIVE numbers lanes ascending from right to left, and `laneChange` names the allowed direction in that
        numbering. Without it, solid-type lines forbid crossing and everything else (broken, none, combined
        solid/broken lines, of which one side may cross) permits it.
        """
        if self.lane_change:
            return self.lane_change == "both" or self.lane_change == ("increase" if increasing else "decrease")
        return self.type not in _NO_CROSS


#: (road id, section index in s order, lane id) -> the marks along that lane's outer border
MarkTable = dict[tuple[str, int, int], tuple[Mark, ...]]


def read_marks(data: bytes, source: str) -> MarkTable:
    """Every lane's road marks, keyed by road, lane-section index (sorted by s) and lane id."""
    refuse_doctype(data, source)
    parser = etree.XMLParser(resolve_entities=False, no_network=True, huge_tree=False, remove_comments=True)
    try:
        root = etree.fromstring(data, parser)
    except etree.XMLSyntaxError as exc:
        raise InputError(f"malformed XML: {exc}", source=source, element="OpenDRIVE") from exc
    table: MarkTable = {}
    for road in root.iterfind("road"):
        rid = road.get("id", "")
        sections = sorted(road.iterfind("lanes/laneSection"), key=lambda el: float(el.get("s", "0") or 0))
        for si, sec in enumerate(sections):
            for lane in sec.iterfind("*/lane"):
                marks = tuple(Mark((m.get("type") or "none").strip(), (m.get("laneChange") or None))
                              for m in lane.iterfind("roadMark"))
                if marks:
                    try:
                        table[(rid, si, int(lane.get("id", "")))] = marks
                    except ValueError:
                        continue  # the road model reports bad lane ids; marks only refine permissions
    return table


def crossing_allowed(table: MarkTable, road_id: str, section: int, lane_id: int, toward_plus_t: bool) -> bool | None:
    """Whether the marks let a vehicle leave `lane_id` toward +t (or -t); None when the map has no mark there.

    Allowed if any mark along the border permits it: a border broken somewhere lets a lane change happen there.
    """
    if toward_plus_t:
        owner = lane_id if lane_id > 0 else (0 if lane_id == -1 else lane_id + 1)
    else:
        owner = lane_id if lane_id < 0 else (0 if lane_id == 1 else lane_id - 1)
    marks = table.get((road_id, section, owner))
    if not marks:
        return None
    return any(m.allows(toward_plus_t) for m in marks)
