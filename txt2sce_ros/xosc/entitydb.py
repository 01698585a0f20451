"""The OpenSCENARIO entity database (paper §III-A.1): the XSD as a networkx graph.

Nodes
- `XSDElement` for every complex type (`type:<Name>`): the things that appear as XML elements;
- `XSDAttribute` for every attribute of a complex type (`attr:<Type>@<name>`), with its simple type, whether it is
  required, its enumeration members (None for free values) and its numeric range (None when unbounded).
Edges (attribute `kind`)
- `contains`: type -> child type, with the child's tag, min/max occurrence and whether it sits in an `xsd:choice`;
- `extends`: type -> type it specialises: `xsd:extension` bases (inheritance), and the members of a pure
  `xsd:choice` container, which act as its substitution group (SpeedAction is one kind of LongitudinalAction);
- `has_attribute`: type -> attribute node.

The XSD carries no `xsd:documentation` in 1.0–1.3, so `documentation` holds a generated one-line description
(cardinality and kind); numeric ranges come from the XSD base types plus `ranges.DOCUMENTED_RANGES`.

    from txt2sce_ros.xosc.entitydb import entity_db
    db = entity_db()                               # version 1.0, cached on disk under paths.cache_dir()
    db.children("SpeedAction")                     # [Child(tag='SpeedActionDynamics', ...), ...]
    db.allowed_values("TransitionDynamics", "dynamicsShape")   # ['cubic', 'linear', 'sinusoidal', 'step']
    db.check_value("Precipitation", "precipitationType", "rain")   # raises InputError when not a member
    db.numeric_range("Precipitation", "intensity")             # (0.0, 1.0)

`element` arguments take a complex type name (`TransitionDynamics`), a tag (`SpeedActionDynamics`) or a
`Parent/Tag` path for the one ambiguous tag (`ByType`).
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass
from functools import lru_cache

import networkx as nx
from lxml import etree

from .. import signed_cache
from ..errors import InputError
from ..paths import cache_dir
from .ranges import BASE_TYPE_RANGES, DOCUMENTED_RANGES
from .schema import DEFAULT_VERSION, XSD_NS, normalise_version, xsd_path, xsd_tree

_XS = "{%s}" % XSD_NS
#: Bump when the graph layout changes, so stale disk caches are ignored.
_GRAPH_FORMAT = 3
UNBOUNDED = -1


@dataclass(frozen=True, slots=True)
class XSDElement:
    name: str                 # complex type name
    tags: tuple[str, ...]     # element names under which it appears
    kind: str                 # 'sequence' | 'choice' | 'all' | 'empty' | 'simple_content'
    documentation: str


@dataclass(frozen=True, slots=True)
class XSDAttribute:
    owner: str                # complex type
    name: str
    type: str                 # simple type name (e.g. 'Double', 'DynamicsShape')
    required: bool
    enumeration: tuple[str, ...] | None
    numeric_range: tuple[float | None, float | None] | None
    documentation: str


@dataclass(frozen=True, slots=True)
class Child:
    tag: str
    type: str
    min_occurs: int
    max_occurs: int           # UNBOUNDED (-1) for unbounded
    in_choice: bool


def _occurs(el: etree._Element, key: str, default: int = 1) -> int:
    v = el.get(key)
    if v is None:
        return default
    return UNBOUNDED if v == "unbounded" else int(v)


class _Builder:
    def __init__(self, tree: etree._ElementTree) -> None:
        root = tree.getroot()
        self.simple = {s.get("name"): s for s in root.findall(f"{_XS}simpleType")}
        self.complex = {c.get("name"): c for c in root.findall(f"{_XS}complexType")}
        self.groups = {g.get("name"): g for g in root.findall(f"{_XS}group")}
        self.root = root

    def enumeration(self, type_name: str) -> tuple[str, ...] | None:
        st = self.simple.get(type_name)
        if st is None:
            return None
        values = [e.get("value") for e in st.iter(f"{_XS}enumeration")]
        return tuple(sorted(values)) if values else None

    def numeric_range(self, owner: str, attr: str, type_name: str) -> tuple[float | None, float | None] | None:
        if (owner, attr) in DOCUMENTED_RANGES:
            rng = DOCUMENTED_RANGES[(owner, attr)]
            return None if rng == (None, None) else rng
        rng = BASE_TYPE_RANGES.get(type_name)
        return None if rng is None or rng == (None, None) else rng

    def particles(self, node: etree._Element, in_choice: bool, mult_min: int = 1):
        """Yield (tag, type, min, max, in_choice) of the element particles under a model group, through groups."""
        for ch in node:
            if not isinstance(ch.tag, str):
                continue
            local = etree.QName(ch).localname
            if local == "element":
                mn = _occurs(ch, "minOccurs") * mult_min
                yield ch.get("name"), ch.get("type"), mn, _occurs(ch, "maxOccurs"), in_choice
            elif local in ("sequence", "all"):
                yield from self.particles(ch, in_choice, min(mult_min, _occurs(ch, "minOccurs")))
            elif local == "choice":
                yield from self.particles(ch, True, min(mult_min, _occurs(ch, "minOccurs")))
            elif local == "group":
                grp = self.groups[ch.get("ref")]
                yield from self.particles(grp, in_choice, min(mult_min, _occurs(ch, "minOccurs")))

    def content_kind(self, ct: etree._Element) -> str:
        for ch in ct:
            if not isinstance(ch.tag, str):
                continue
            local = etree.QName(ch).localname
            if local in ("sequence", "choice", "all"):
                return local
            if local == "group":
                inner = [c for c in self.groups[ch.get("ref")] if isinstance(c.tag, str)]
                return etree.QName(inner[0]).localname if inner else "empty"
            if local == "simpleContent":
                return "simple_content"
        return "empty"

    def build(self, version: str) -> nx.MultiDiGraph:
        g = nx.MultiDiGraph(version=version, format=_GRAPH_FORMAT)
        tags: dict[str, set[str]] = {n: set() for n in self.complex}
        children: dict[str, list[Child]] = {}
        for name, ct in self.complex.items():
            found = [Child(t, ty, mn, mx, ic) for t, ty, mn, mx, ic in self.particles(ct, False)]
            children[name] = found
            for c in found:
                if c.type in tags:
                    tags[c.type].add(c.tag)
        for el in self.root.findall(f"{_XS}element"):  # the document element
            tags.setdefault(el.get("type"), set()).add(el.get("name"))
        for name, ct in self.complex.items():
            kind = self.content_kind(ct)
            doc = f"{name}: {kind} of {len(children[name])} child element(s)"
            g.add_node(f"type:{name}", node="XSDElement",
                       record=XSDElement(name, tuple(sorted(tags[name])), kind, doc))
        for name, ct in self.complex.items():
            kind = g.nodes[f"type:{name}"]["record"].kind
            for c in children[name]:
                if c.type in self.complex:
                    g.add_edge(f"type:{name}", f"type:{c.type}", kind="contains", child=c)
                    if kind == "choice":
                        g.add_edge(f"type:{c.type}", f"type:{name}", kind="extends", via="choice")
            for ext in ct.iter(f"{_XS}extension"):
                base = ext.get("base")
                target = f"type:{base}" if base in self.complex else f"builtin:{base}"
                if target not in g:
                    g.add_node(target, node="XSDBuiltin", record=None)
                g.add_edge(f"type:{name}", target, kind="extends", via="extension")
            for a in ct.iter(f"{_XS}attribute"):
                aname, atype = a.get("name"), a.get("type")
                enum = self.enumeration(atype)
                card = "required" if a.get("use") == "required" else "optional"
                rec = XSDAttribute(name, aname, atype, a.get("use") == "required", enum,
                                   self.numeric_range(name, aname, atype),
                                   f"{name}/@{aname}: {card} {atype}" + (f" in {{{', '.join(enum)}}}" if enum else ""))
                g.add_node(f"attr:{name}@{aname}", node="XSDAttribute", record=rec)
                g.add_edge(f"type:{name}", f"attr:{name}@{aname}", kind="has_attribute")
        return g


def _cache_file(version: str) -> "tuple[str, str]":
    data = xsd_path(version).read_bytes()
    digest = hashlib.sha256(data + str(_GRAPH_FORMAT).encode()).hexdigest()[:16]
    return str(cache_dir() / f"xosc_entitydb_{version}_{digest}.pickle"), digest


class EntityDB:
    """Query side of the graph; see the module docstring."""

    def __init__(self, graph: nx.MultiDiGraph) -> None:
        self.graph = graph
        self.version: str = graph.graph["version"]
        self._by_tag: dict[str, set[str]] = {}
        for node, data in graph.nodes(data=True):
            if data["node"] == "XSDElement":
                for tag in data["record"].tags:
                    self._by_tag.setdefault(tag, set()).add(data["record"].name)

    # -- resolution ---------------------------------------------------------------------------------------
    def resolve(self, element: str) -> str:
        """Complex type name for a type name, a tag, or a `Parent/Tag` path."""
        if "/" in element:
            parent, tag = element.rsplit("/", 1)
            ptype = self.resolve(parent)
            for c in self.children(ptype):
                if c.tag == tag:
                    return c.type
            raise InputError(f"{ptype} has no child <{tag}>", element=element)
        if f"type:{element}" in self.graph:
            return element
        types = self._by_tag.get(element)
        if not types:
            raise InputError(f"not an OpenSCENARIO {self.version} element", element=element)
        if len(types) > 1:
            raise InputError(f"ambiguous tag (types {sorted(types)}); name it as Parent/Tag", element=element)
        return next(iter(types))

    def element(self, element: str) -> XSDElement:
        return self.graph.nodes[f"type:{self.resolve(element)}"]["record"]

    def elements(self) -> list[str]:
        return sorted(d["record"].name for _, d in self.graph.nodes(data=True) if d["node"] == "XSDElement")

    # -- structure ----------------------------------------------------------------------------------------
    def children(self, element: str) -> list[Child]:
        """Child elements in schema order (only complex-typed children exist in OpenSCENARIO)."""
        node = f"type:{self.resolve(element)}"
        return [d["child"] for _, _, d in self.graph.out_edges(node, data=True) if d["kind"] == "contains"]

    def parents(self, element: str) -> list[str]:
        node = f"type:{self.resolve(element)}"
        return sorted({u[5:] for u, _, d in self.graph.in_edges(node, data=True) if d["kind"] == "contains"})

    def alternatives(self, element: str) -> list[str]:
        """Members of a pure-choice type (its substitution group): e.g. the kinds of PrivateAction."""
        node = f"type:{self.resolve(element)}"
        return sorted(u[5:] for u, _, d in self.graph.in_edges(node, data=True)
                      if d["kind"] == "extends" and d.get("via") == "choice")

    def bases(self, element: str) -> list[str]:
        node = f"type:{self.resolve(element)}"
        return sorted(v.split(":", 1)[1] for _, v, d in self.graph.out_edges(node, data=True) if d["kind"] == "extends")

    def attributes(self, element: str) -> list[XSDAttribute]:
        node = f"type:{self.resolve(element)}"
        return [self.graph.nodes[v]["record"] for _, v, d in self.graph.out_edges(node, data=True)
                if d["kind"] == "has_attribute"]

    def attribute(self, element: str, attribute: str) -> XSDAttribute:
        type_name = self.resolve(element)
        node = f"attr:{type_name}@{attribute}"
        if node not in self.graph:
            raise InputError(f"{type_name} has no attribute '{attribute}'", element=f"{element}/@{attribute}")
        return self.graph.nodes[node]["record"]

    # -- value domains ------------------------------------------------------------------------------------
    def allowed_values(self, element_or_type: str, attribute: str | None = None) -> list[str] | None:
        """Enumeration members of an attribute (or of a simple type when `attribute` is None); None when the
        value is free (a number or a string)."""
        if attribute is None:
            return self._simple_enum(element_or_type)
        rec = self.attribute(element_or_type, attribute)
        return list(rec.enumeration) if rec.enumeration is not None else None

    def _simple_enum(self, type_name: str) -> list[str] | None:
        for _, d in self.graph.nodes(data=True):
            rec = d["record"]
            if d["node"] == "XSDAttribute" and rec.type == type_name:
                return list(rec.enumeration) if rec.enumeration is not None else None
        raise InputError(f"no attribute uses simple type {type_name}", element=type_name)

    def enumerations(self, element: str | None = None) -> dict[tuple[str, str], list[str]]:
        """(type, attribute) -> members for every enumerated attribute (of one element, or of all): the value
        domains of enumerated mutations (weather cloudState, dynamicsShape, vehicleCategory, ...)."""
        owner = self.resolve(element) if element else None
        out = {}
        for _, d in self.graph.nodes(data=True):
            rec = d["record"]
            if d["node"] == "XSDAttribute" and rec.enumeration is not None and (owner is None or rec.owner == owner):
                out[(rec.owner, rec.name)] = list(rec.enumeration)
        return dict(sorted(out.items()))

    def numeric_range(self, element: str, attribute: str) -> tuple[float | None, float | None] | None:
        return self.attribute(element, attribute).numeric_range

    def check_value(self, element: str, attribute: str, value: object) -> str:
        """Return the value as written in XML; raise InputError naming element/attribute when it is not allowed
        (unknown attribute, not an enumeration member, not a number, out of range). `$param` references pass."""
        rec = self.attribute(element, attribute)
        where = f"{element}/@{attribute}"
        if isinstance(value, bool):
            text = "true" if value else "false"
        elif isinstance(value, float):
            text = repr(round(value, 6)) if value == value else "nan"
        else:
            text = str(value)
        if text.startswith("$"):
            return text
        if rec.enumeration is not None:
            if text not in rec.enumeration:
                raise InputError(f"'{text}' is not one of {list(rec.enumeration)}", element=where)
            return text
        if rec.type in ("Double", "Int", "UnsignedInt", "UnsignedShort"):
            try:
                num = float(text)
            except ValueError as exc:
                raise InputError(f"'{text}' is not a number ({rec.type})", element=where) from exc
            if num != num or num in (float("inf"), float("-inf")):
                raise InputError(f"'{text}' is not a finite number", element=where)
            if rec.type != "Double" and num != int(num):
                raise InputError(f"'{text}' is not an integer ({rec.type})", element=where)
            if rec.numeric_range is not None:
                lo, hi = rec.numeric_range
                if (lo is not None and num < lo) or (hi is not None and num > hi):
                    raise InputError(f"{text} outside [{lo}, {hi}]", element=where)
        elif rec.type == "Boolean" and text not in ("true", "false", "0", "1"):
            raise InputError(f"'{text}' is not a boolean", element=where)
        return text


@lru_cache(maxsize=None)
def entity_db(version: str = DEFAULT_VERSION) -> EntityDB:
    """The entity database of one OpenSCENARIO version, built from the installed XSD and cached on disk (keyed by
    the XSD's hash) and in memory."""
    ver = normalise_version(version)
    path, _ = _cache_file(ver)
    graph = signed_cache.load(path)      # None: missing, not ours (tag) or stale: rebuild
    if graph is not None and getattr(graph, "graph", {}).get("format") == _GRAPH_FORMAT:
        return EntityDB(graph)
    graph = _Builder(xsd_tree(ver)).build(ver)
    signed_cache.store(path, graph)      # atomic: parallel workers never read a half-written cache
    return EntityDB(graph)
