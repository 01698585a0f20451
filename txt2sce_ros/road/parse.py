"""Hardened OpenDRIVE (1.4–1.7) reader: XML text -> typed records (roads, junctions, signals, controllers).

Security: lxml with entity resolution, network access and huge trees off, and any DTD that declares entities is
rejected outright — an unresolved entity would otherwise leave holes in numeric attributes (XXE, billion laughs).
Every error is an `InputError` naming the source file, the element and its line.
Elevation, superelevation, road marks, objects and userData are accepted and ignored (the world is 2D).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from lxml import etree

from ..errors import InputError
from .geometry import Arc, Geometry, Line, ParamPoly3, PlanView, Poly3, Spiral
from .lanes import Cubic, Lane, LaneLink, LaneSection
from .model import Connection, Controller, Junction, Road, RoadLink, Signal, SignalValidity
from ..xmlsafe import refuse_doctype

_PARSER_OPTS = dict(resolve_entities=False, no_network=True, huge_tree=False, load_dtd=False,
                    remove_comments=True, remove_pis=True)

_SPEED_UNITS = {"m/s": 1.0, "km/h": 1 / 3.6, "mph": 0.44704}

#: Longest road, geometry or s coordinate accepted, m (the longest real roads in OpenDRIVE maps are a few km).
MAX_LENGTH = 100_000.0


@dataclass(slots=True)
class ParsedNetwork:
    header: dict[str, str]
    roads: dict[str, Road]
    junctions: dict[str, Junction]
    controllers: dict[str, Controller]
    geo_reference: str = ""
    signal_refs: list[Signal] = field(default_factory=list)


def _tag(el: etree._Element) -> str:
    return etree.QName(el).localname if isinstance(el.tag, str) else ""


class _Ctx:
    """Carries the source name so every helper can build an error that names file, element and line."""

    def __init__(self, source: str) -> None:
        self.source = source

    def error(self, el: etree._Element | None, message: str) -> InputError:
        if el is None:
            return InputError(message, source=self.source)
        return InputError(message, source=self.source, element=_tag(el) or None, line=el.sourceline)

    def num(self, el: etree._Element, name: str, default: float | None = None) -> float:
        raw = el.get(name)
        if raw is None or raw.strip() == "":
            if default is None:
                raise self.error(el, f"missing attribute {name!r}")
            return default
        try:
            value = float(raw)
        except ValueError:
            raise self.error(el, f"attribute {name}={raw!r} is not a number") from None
        if not math.isfinite(value):
            raise self.error(el, f"attribute {name}={raw!r} is not finite")
        return value

    def length(self, el: etree._Element, name: str = "length") -> float:
        """A length in [0, MAX_LENGTH] m: the road model samples every road, so an absurd length is refused here,
        where `maps check`, `maps info` and the player all load maps, with one message."""
        value = self.num(el, name)
        if value < 0:
            raise self.error(el, f"negative {name} {value}")
        if value > MAX_LENGTH:
            raise self.error(el, f"{name} {value:g} m is longer than the limit of {MAX_LENGTH:g} m")
        return value

    def int_(self, el: etree._Element, name: str, default: int | None = None) -> int:
        raw = el.get(name)
        if raw is None or raw.strip() == "":
            if default is None:
                raise self.error(el, f"missing attribute {name!r}")
            return default
        try:
            value = float(raw)      # OpenDRIVE writers emit ids like "-1.0"; accept them when integral
        except ValueError:
            value = math.nan
        if not math.isfinite(value) or not value.is_integer():
            raise self.error(el, f"attribute {name}={raw!r} is not an integer")
        return int(value)

    def text(self, el: etree._Element, name: str, default: str | None = None) -> str:
        raw = el.get(name)
        if raw is None:
            if default is None:
                raise self.error(el, f"missing attribute {name!r}")
            return default
        return raw.strip()


def _children(el: etree._Element, name: str) -> list[etree._Element]:
    return [c for c in el if _tag(c) == name]


def _child(el: etree._Element, name: str) -> etree._Element | None:
    for c in el:
        if _tag(c) == name:
            return c
    return None


def parse_xml(data: bytes, source: str) -> etree._Element:
    """Parse bytes into the <OpenDRIVE> root element, refusing entity declarations."""
    refuse_doctype(data, source)
    ctx = _Ctx(source)
    parser = etree.XMLParser(**_PARSER_OPTS)
    try:
        root = etree.fromstring(data, parser)
    except etree.XMLSyntaxError as exc:
        line = exc.lineno if getattr(exc, "lineno", None) else None
        if "entit" in str(exc.msg).lower():
            # libxml2 itself stops external entities in attributes and entity amplification (billion laughs).
            raise InputError(f"entity declarations/references refused (XXE / entity expansion): {exc.msg}",
                             source=source, element="!DOCTYPE", line=line) from exc
        raise InputError(f"malformed XML: {exc.msg}", source=source, element="OpenDRIVE", line=line) from exc
    except ValueError as exc:   # e.g. str with an encoding declaration
        raise InputError(f"malformed XML: {exc}", source=source, element="OpenDRIVE") from exc
    dtd = root.getroottree().docinfo.internalDTD
    if dtd is not None and (list(dtd.iterentities()) or "ENTITY" in (etree.tostring(dtd, encoding=str) or "")):
        raise InputError("DTD entity declarations are not allowed (XXE / entity expansion)", source=source,
                         element="!DOCTYPE")
    for el in root.iter(etree.Entity):
        raise ctx.error(el.getparent(), f"unresolved entity reference {el.text!r}")
    if _tag(root) != "OpenDRIVE":
        raise ctx.error(root, f"root element is <{_tag(root)}>, expected <OpenDRIVE>")
    return root


def parse_network(data: bytes, source: str) -> ParsedNetwork:
    """Parse OpenDRIVE bytes into records (geometry evaluation is left to `RoadNetwork`)."""
    root = parse_xml(data, source)
    ctx = _Ctx(source)
    header_el = _child(root, "header")
    header = dict(header_el.attrib) if header_el is not None else {}
    geo = ""
    if header_el is not None:
        g = _child(header_el, "geoReference")
        if g is not None and g.text:
            geo = g.text.strip()
    roads: dict[str, Road] = {}
    for el in _children(root, "road"):
        road = _parse_road(ctx, el)
        if road.id in roads:
            raise ctx.error(el, f"duplicate road id {road.id!r}")
        roads[road.id] = road
    if not roads:
        raise ctx.error(root, "no <road> elements")
    junctions: dict[str, Junction] = {}
    for el in _children(root, "junction"):
        j = _parse_junction(ctx, el)
        junctions[j.id] = j
    controllers: dict[str, Controller] = {}
    for el in _children(root, "controller"):
        cid = ctx.text(el, "id")
        seq = el.get("sequence")
        controllers[cid] = Controller(
            id=cid, name=el.get("name", ""), sequence=ctx.int_(el, "sequence") if seq else None,
            signal_ids=tuple(ctx.text(c, "signalId") for c in _children(el, "control")))
    _check_links(ctx, root, roads, junctions)
    return ParsedNetwork(header=header, roads=roads, junctions=junctions, controllers=controllers, geo_reference=geo)


def _check_links(ctx: _Ctx, root: etree._Element, roads: dict[str, Road], junctions: dict[str, Junction]) -> None:
    """Dangling connection references are an input error (routing would silently lose lanes otherwise)."""
    for j in junctions.values():
        for c in j.connections:
            for rid in (c.incoming_road, c.connecting_road):
                if rid not in roads:
                    raise InputError(f"junction {j.id} connection {c.id} names unknown road {rid!r}",
                                     source=ctx.source, element="connection")


def _parse_road(ctx: _Ctx, el: etree._Element) -> Road:
    rid = ctx.text(el, "id")
    length = ctx.length(el)
    pv_el = _child(el, "planView")
    if pv_el is None:
        raise ctx.error(el, f"road {rid}: missing <planView>")
    geoms = [_parse_geometry(ctx, g) for g in _children(pv_el, "geometry")]
    if not geoms:
        raise ctx.error(pv_el, f"road {rid}: <planView> has no <geometry>")
    plan_view = PlanView(geoms)
    lanes_el = _child(el, "lanes")
    if lanes_el is None:
        raise ctx.error(el, f"road {rid}: missing <lanes>")
    offsets = tuple(sorted((Cubic(ctx.num(o, "s"), ctx.num(o, "a", 0.0), ctx.num(o, "b", 0.0),
                                  ctx.num(o, "c", 0.0), ctx.num(o, "d", 0.0))
                            for o in _children(lanes_el, "laneOffset")), key=lambda c: c.start))
    sec_els = _children(lanes_el, "laneSection")
    if not sec_els:
        raise ctx.error(lanes_el, f"road {rid}: no <laneSection>")
    starts = [ctx.num(s, "s") for s in sec_els]
    order = sorted(range(len(sec_els)), key=lambda i: starts[i])
    sections: list[LaneSection] = []
    for k, i in enumerate(order):
        end = starts[order[k + 1]] if k + 1 < len(order) else length
        sections.append(_parse_section(ctx, sec_els[i], starts[i], end, rid))
    link = _child(el, "link")
    pred = succ = None
    if link is not None:
        p = _child(link, "predecessor")
        s = _child(link, "successor")
        pred = _parse_road_link(ctx, p) if p is not None else None
        succ = _parse_road_link(ctx, s) if s is not None else None
    rule = (el.get("rule") or "RHT").upper()
    if rule not in ("RHT", "LHT"):
        raise ctx.error(el, f"road {rid}: rule={rule!r} (expected RHT or LHT)")
    speed = None
    rtype = ""
    for t in _children(el, "type"):
        rtype = rtype or t.get("type", "")
        sp = _child(t, "speed")
        if sp is not None and speed is None:
            raw = sp.get("max", "")
            try:
                speed = float(raw) * _SPEED_UNITS.get(sp.get("unit", "m/s"), 1.0)
            except ValueError:
                speed = None   # 'no limit' / 'undefined' are legal values
    road = Road(id=rid, name=el.get("name", ""), length=length, junction=el.get("junction", "-1").strip() or "-1",
                plan_view=plan_view, sections=sections, lane_offsets=offsets, predecessor=pred, successor=succ,
                rule=rule, speed_limit=speed, road_type=rtype)
    sig_el = _child(el, "signals")
    if sig_el is not None:
        for s_el in _children(sig_el, "signal"):
            road.signals.append(_parse_signal(ctx, s_el, rid, reference=False))
        for s_el in _children(sig_el, "signalReference"):
            road.signals.append(_parse_signal(ctx, s_el, rid, reference=True))
    return road


def _parse_road_link(ctx: _Ctx, el: etree._Element) -> RoadLink:
    et = ctx.text(el, "elementType")
    if et not in ("road", "junction"):
        raise ctx.error(el, f"elementType={et!r} (expected road or junction)")
    return RoadLink(element_type=et, element_id=ctx.text(el, "elementId"), contact_point=el.get("contactPoint", ""))


def _parse_geometry(ctx: _Ctx, el: etree._Element) -> Geometry:
    base = dict(s=ctx.length(el, "s"), x=ctx.num(el, "x"), y=ctx.num(el, "y"), hdg=ctx.num(el, "hdg"),
                length=ctx.length(el))
    kinds = [c for c in el if _tag(c)]
    if len(kinds) != 1:
        raise ctx.error(el, f"expected exactly one primitive inside <geometry>, found {len(kinds)}")
    prim = kinds[0]
    kind = _tag(prim)
    if kind == "line":
        return Line(**base)
    if kind == "arc":
        return Arc(**base, k=ctx.num(prim, "curvature"))
    if kind == "spiral":
        return Spiral(**base, k0=ctx.num(prim, "curvStart"), k1=ctx.num(prim, "curvEnd"))
    if kind == "poly3":
        return Poly3(**base, a=ctx.num(prim, "a"), b=ctx.num(prim, "b"), c=ctx.num(prim, "c"), d=ctx.num(prim, "d"))
    if kind == "paramPoly3":
        p_range = prim.get("pRange", "normalized")
        if p_range not in ("normalized", "arcLength"):
            raise ctx.error(prim, f"pRange={p_range!r} (expected arcLength or normalized)")
        vals = {k: ctx.num(prim, k) for k in ("aU", "bU", "cU", "dU", "aV", "bV", "cV", "dV")}
        return ParamPoly3(**base, au=vals["aU"], bu=vals["bU"], cu=vals["cU"], du=vals["dU"], av=vals["aV"],
                          bv=vals["bV"], cv=vals["cV"], dv=vals["dV"], normalized=p_range == "normalized")
    raise ctx.error(prim, f"unknown planView primitive <{kind}>")


def _parse_section(ctx: _Ctx, el: etree._Element, s: float, end: float, rid: str) -> LaneSection:
    lanes: dict[int, Lane] = {}
    for side in ("left", "center", "right"):
        side_el = _child(el, side)
        if side_el is None:
            continue
        for lane_el in _children(side_el, "lane"):
            lane = _parse_lane(ctx, lane_el)
            want = {"left": lane.id > 0, "center": lane.id == 0, "right": lane.id < 0}[side]
            if not want:
                raise ctx.error(lane_el, f"road {rid}: lane id {lane.id} inside <{side}>")
            if lane.id in lanes:
                raise ctx.error(lane_el, f"road {rid}: duplicate lane id {lane.id} in laneSection s={s}")
            lanes[lane.id] = lane
    if 0 not in lanes:
        lanes[0] = Lane(id=0, type="none")
    # Lane ids must be contiguous from the centre out, or t of the outer lanes is undefined.
    for ids in (sorted(i for i in lanes if i > 0), sorted((-i for i in lanes if i < 0))):
        if ids and ids != list(range(1, len(ids) + 1)):
            raise ctx.error(el, f"road {rid}: lane ids not contiguous in laneSection s={s}")
    single = (el.get("singleSide") or "false").strip().lower() == "true"
    return LaneSection(s=s, lanes=lanes, single_side=single, end=end)


def _parse_lane(ctx: _Ctx, el: etree._Element) -> Lane:
    lid = ctx.int_(el, "id")
    widths = tuple(sorted((Cubic(ctx.num(w, "sOffset"), ctx.num(w, "a"), ctx.num(w, "b", 0.0), ctx.num(w, "c", 0.0),
                                 ctx.num(w, "d", 0.0)) for w in _children(el, "width")), key=lambda c: c.start))
    borders = tuple(sorted((Cubic(ctx.num(w, "sOffset"), ctx.num(w, "a"), ctx.num(w, "b", 0.0),
                                  ctx.num(w, "c", 0.0), ctx.num(w, "d", 0.0)) for w in _children(el, "border")),
                           key=lambda c: c.start))
    if lid != 0 and not widths and not borders:
        raise ctx.error(el, f"lane {lid} has neither <width> nor <border>")
    link_el = _child(el, "link")
    pred = succ = None
    if link_el is not None:
        p = _child(link_el, "predecessor")
        s = _child(link_el, "successor")
        pred = ctx.int_(p, "id") if p is not None else None
        succ = ctx.int_(s, "id") if s is not None else None
    level = (el.get("level") or "false").strip().lower() in ("true", "1")
    return Lane(id=lid, type=(el.get("type") or "none").strip(), widths=widths, borders=borders,
                link=LaneLink(pred, succ), level=level, direction=(el.get("direction") or "standard").strip())


def _parse_junction(ctx: _Ctx, el: etree._Element) -> Junction:
    jid = ctx.text(el, "id")
    conns = []
    for c in _children(el, "connection"):
        links = tuple((ctx.int_(ll, "from"), ctx.int_(ll, "to")) for ll in _children(c, "laneLink"))
        incoming = c.get("incomingRoad")
        connecting = c.get("connectingRoad")
        if incoming is None or connecting is None:
            # OpenDRIVE 1.7 direct junctions use linkedRoad; treat it as the connecting road.
            connecting = connecting or c.get("linkedRoad")
            if incoming is None or connecting is None:
                raise ctx.error(c, f"junction {jid}: connection needs incomingRoad and connectingRoad")
        conns.append(Connection(id=c.get("id", str(len(conns))), incoming_road=incoming.strip(),
                                connecting_road=connecting.strip(),
                                contact_point=(c.get("contactPoint") or "start").strip(), lane_links=links))
    ctrls = tuple(ctx.text(c, "id") for c in _children(el, "controller"))
    return Junction(id=jid, name=el.get("name", ""), type=el.get("type", "default"), connections=tuple(conns),
                    controllers=ctrls)


def _parse_signal(ctx: _Ctx, el: etree._Element, rid: str, *, reference: bool) -> Signal:
    validity = tuple(SignalValidity(ctx.int_(v, "fromLane"), ctx.int_(v, "toLane")) for v in _children(el, "validity"))
    value = el.get("value")
    try:
        val = float(value) if value not in (None, "") else None
    except ValueError:
        val = None
    return Signal(
        id=ctx.text(el, "id"), road_id=rid, s=ctx.num(el, "s"), t=ctx.num(el, "t", 0.0),
        orientation=(el.get("orientation") or "none").strip(), dynamic=(el.get("dynamic") or "no").strip() == "yes",
        type=(el.get("type") or "").strip(), subtype=(el.get("subtype") or "").strip(), name=el.get("name", ""),
        country=el.get("country", ""), value=val, h_offset=ctx.num(el, "hOffset", 0.0), validity=validity,
        is_reference=reference)
