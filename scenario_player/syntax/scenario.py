"""`load_scenario`: read an OpenSCENARIO file completely (parameters, catalogs, entities, storyboard, road
network), validate entity references, and collect what is unsupported. The parsed `Scenario` is immutable; each
Simulation builds its own fresh storyboard from it."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from lxml import etree

from txt2sce_ros.errors import InputError
from txt2sce_ros.road import RoadNetwork, load_network, load_network_text

from ..world.signals import Phase, SignalController
from .document import ResolvedDocument, resolve_document
from .entities import EntitySpec, entity_spec_from_xml
from .xml import ParseContext

#: attributes that name entities (validated at load).
_ENTITY_ATTRS = ("entityRef", "masterEntityRef")
#: The elements (in document order) holding any of those attributes: the only ones `_check_references` can refuse,
#: found in one XPath pass instead of reading every element's attributes in Python.
_WITH_ENTITY_ATTRS = etree.XPath("//*[" + " or ".join(f"@{a}" for a in _ENTITY_ATTRS) + "]")


@dataclass(frozen=True)
class Scenario:
    source: str
    doc: ResolvedDocument
    entities: tuple[EntitySpec, ...]
    network: RoadNetwork
    map_path: str
    controllers: tuple[SignalController, ...]
    unsupported: tuple[str, ...]
    description: str = ""
    revision: tuple[int, int] = (1, 0)
    meta: dict[str, str] = field(default_factory=dict)
    # The storyboard load_scenario built to validate the file, unused: the first Simulation takes it instead of
    # parsing the storyboard a second time (runtime objects are stateful, so it is handed out once only).
    prebuilt: list[Any] = field(default_factory=list, compare=False, repr=False)

    @property
    def root(self) -> etree._Element:
        return self.doc.root

    @property
    def entity_names(self) -> list[str]:
        return [e.name for e in self.entities]


def _controllers(ctx: ParseContext, root: etree._Element) -> tuple[SignalController, ...]:
    out = []
    for c in root.iterfind("RoadNetwork/TrafficSignals/TrafficSignalController"):
        phases = tuple(Phase(p.get("name", ""), ctx.float(p, "duration", 0.0),
                             tuple((s.get("trafficSignalId", ""), s.get("state", ""))
                                   for s in p.findall("TrafficSignalState")))
                       for p in c.findall("Phase"))
        out.append(SignalController(ctx.req(c, "name"), ctx.float(c, "delay", 0.0), phases))
    return tuple(out)


def _network(ctx: ParseContext, root: etree._Element, base_dir: Path, map_text: str | None,
             map_path: str | None) -> tuple[RoadNetwork, str]:
    if map_text:
        # Cached by content and name: a campaign worker gets the same map with every scenario of a tree, and the
        # parse, routing graph and lane index would otherwise be rebuilt per run (~10 % of a run's CPU).
        return load_network_text(map_text, source=map_path or "<map>"), map_path or "<map>"
    logic = root.find("RoadNetwork/LogicFile")
    if logic is None or not logic.get("filepath"):
        raise InputError("no RoadNetwork/LogicFile: the player needs an OpenDRIVE map", source=ctx.source,
                         element="RoadNetwork", line=None if logic is None else logic.sourceline)
    path = Path(logic.get("filepath", ""))
    candidates = [path] if path.is_absolute() else [base_dir / path, base_dir / path.name]
    if map_path:
        candidates.insert(0, Path(map_path))
    for cand in candidates:
        if cand.is_file():
            return load_network(cand), str(cand)
    raise InputError(f"OpenDRIVE file '{path}' not found (looked in {', '.join(str(c) for c in candidates)})",
                     source=ctx.source, element="LogicFile", line=logic.sourceline)


def _check_references(ctx: ParseContext, root: etree._Element, names: set[str]) -> None:
    for el in _WITH_ENTITY_ATTRS(root):
        for attr in _ENTITY_ATTRS:
            ref = el.get(attr)
            if el.tag == "TrailerRef" and not ref:
                continue        # catalog vehicles declare an optional trailer with an empty reference
            if ref is not None and ref not in names:
                raise InputError(f"unknown entity reference '{ref}' (entities: {', '.join(sorted(names))})",
                                 source=ctx.source, element=str(el.tag), line=el.sourceline)


def load_scenario(path_or_text: str | Path, *, source: str | None = None, map_text: str | None = None,
                  map_path: str | None = None, base_dir: str | Path | None = None) -> Scenario:
    """Parse a scenario completely. `path_or_text`: a file path, or the XML text itself (then `source` names it
    and relative paths — catalogs, a map not given as `map_text` — resolve against `base_dir`, default the current
    directory)."""
    text: str | bytes
    if isinstance(path_or_text, Path) or (isinstance(path_or_text, str) and "<" not in path_or_text[:512]):
        p = Path(path_or_text)
        try:
            text = p.read_bytes()
        except OSError as exc:
            raise InputError(f"cannot read scenario: {exc}", source=str(p)) from exc
        src, base = source or str(p), p.resolve().parent
    else:
        text, src, base = path_or_text, source or "<scenario>", Path(base_dir) if base_dir else Path.cwd()
    doc = resolve_document(text, source=src, base_dir=base)
    ctx = ParseContext(src)
    root = doc.root
    header = root.find("FileHeader")
    rev = (1, 0)
    if header is not None:
        rev = (ctx.int(header, "revMajor", 1), ctx.int(header, "revMinor", 0))
    entities_el = root.find("Entities")
    if entities_el is None:
        raise InputError("no <Entities>", source=src, element="OpenSCENARIO")
    specs = []
    for obj in entities_el:
        if obj.tag == "ScenarioObject":
            specs.append(entity_spec_from_xml(ctx, obj))
        elif isinstance(obj.tag, str):
            ctx.note_unsupported(obj)
    names = {s.name for s in specs}
    if len(names) != len(specs):
        raise InputError("duplicate ScenarioObject names", source=src, element="Entities")
    _check_references(ctx, root, names)
    if root.find("Storyboard") is None:
        raise InputError("no <Storyboard>", source=src, element="OpenSCENARIO")
    network, used_map = _network(ctx, root, base, map_text, map_path)
    controllers = _controllers(ctx, root)
    # Parse the storyboard once now so that errors and unsupported elements surface at load.
    from ..storyboard.build import build_storyboard

    board = build_storyboard(ctx, root)
    return Scenario(source=src, doc=doc, entities=tuple(specs), network=network, map_path=used_map,
                    controllers=controllers, unsupported=tuple(ctx.unsupported),
                    description="" if header is None else header.get("description", ""), revision=rev,
                    prebuilt=[board])
