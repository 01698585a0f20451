"""Load an OpenSCENARIO file into one resolved XML tree: parameters substituted, CatalogReferences replaced by
their (parameter-assigned) catalog entries. The typed parse (`syntax.scenario`) then reads only literal values.

XML is read with entity resolution and network access off; malformed XML raises `InputError` with its line.
"""

from __future__ import annotations

import copy
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path

from lxml import etree

from txt2sce_ros.errors import InputError
from txt2sce_ros.xmlsafe import refuse_doctype

from .params import ParameterScope

_PARSER_KW = dict(resolve_entities=False, no_network=True, huge_tree=False, remove_comments=True)


def parse_xml(data: str | bytes, source: str) -> etree._Element:
    """Parse XML text safely; a syntax error becomes an InputError naming the file and line."""
    parser = etree.XMLParser(**_PARSER_KW)
    raw = data.encode("utf-8") if isinstance(data, str) else data
    refuse_doctype(raw, source)
    try:
        root = etree.fromstring(raw, parser)
    except etree.XMLSyntaxError as exc:
        raise InputError(f"malformed XML: {exc.msg}", source=source, line=exc.lineno) from exc
    if root is None:
        raise InputError("empty document", source=source)
    return root


@lru_cache(maxsize=64)
def _catalog_file(path: str, mtime: float) -> etree._Element:
    with open(path, "rb") as fh:
        return parse_xml(fh.read(), path)


@dataclass
class CatalogIndex:
    """Catalog entries found under the CatalogLocations directories, by (catalog name, entry name)."""

    entries: dict[tuple[str, str], tuple[etree._Element, str]] = field(default_factory=dict)

    @classmethod
    def from_locations(cls, root: etree._Element, base_dir: Path, scope: ParameterScope,
                       source: str) -> "CatalogIndex":
        index = cls()
        locations = root.find("CatalogLocations")
        if locations is None:
            return index
        for loc in locations:
            if not isinstance(loc.tag, str):
                continue
            for directory in loc.findall("Directory"):
                rel = scope.resolve(directory.get("path", ""), source=source, element="Directory",
                                    line=directory.sourceline)
                path = (base_dir / rel).resolve()
                if not path.is_dir():
                    continue  # a missing catalog only matters if a reference needs it (reported there)
                for file in sorted(path.glob("*.xosc")):
                    cat_root = _catalog_file(str(file), file.stat().st_mtime)
                    for catalog in cat_root.iter("Catalog"):
                        for entry in catalog:
                            if isinstance(entry.tag, str) and entry.get("name"):
                                index.entries.setdefault((catalog.get("name", ""), entry.get("name")),
                                                         (entry, str(file)))
        return index


@dataclass
class ResolvedDocument:
    root: etree._Element
    source: str
    base_dir: Path
    parameters: dict[str, str]


def _declare(decls: etree._Element, scope: ParameterScope, source: str,
             overrides: dict[str, str] | None = None) -> None:
    for decl in decls.findall("ParameterDeclaration"):
        name = decl.get("name")
        if not name:
            raise InputError("ParameterDeclaration without name", source=source, element="ParameterDeclaration",
                             line=decl.sourceline)
        if overrides and name in overrides:
            value = overrides[name]
        else:
            value = scope.resolve(decl.get("value", ""), source=source, element="ParameterDeclaration",
                                  line=decl.sourceline)
        scope.values[name] = value
        decl.set("value", value)


class _Resolver:
    def __init__(self, source: str, catalogs: CatalogIndex) -> None:
        self.source = source
        self.catalogs = catalogs

    def walk(self, el: etree._Element, scope: ParameterScope) -> None:
        # Every element of the document passes here, so its children and their tags are read once (lxml makes a
        # new str for each `.tag` read, and `find` goes through ElementPath): the first ParameterDeclarations
        # child is the one `el.find` would return.
        children = list(el)
        tags = [child.tag for child in children]
        if "ParameterDeclarations" in tags:
            scope = scope.child()
            _declare(children[tags.index("ParameterDeclarations")], scope, self.source)
        for key, value in el.items():
            if "$" in value and el.tag != "ParameterDeclaration":
                el.set(key, scope.resolve(value, source=self.source, element=el.tag, line=el.sourceline))
        for child, tag in zip(children, tags):
            if not isinstance(tag, str) or tag == "ParameterDeclarations":
                continue
            if tag == "CatalogReference":
                self._replace_reference(child, scope)
                continue
            self.walk(child, scope)

    def _replace_reference(self, ref: etree._Element, scope: ParameterScope) -> etree._Element | None:
        line = ref.sourceline
        cat = scope.resolve(ref.get("catalogName", ""), source=self.source, element="CatalogReference", line=line)
        name = scope.resolve(ref.get("entryName", ""), source=self.source, element="CatalogReference", line=line)
        found = self.catalogs.entries.get((cat, name))
        if found is None:
            raise InputError(f"catalog entry {cat}/{name} not found in CatalogLocations", source=self.source,
                             element="CatalogReference", line=line)
        entry, entry_file = found
        assigned: dict[str, str] = {}
        for pa in ref.iter("ParameterAssignment"):
            assigned[pa.get("parameterRef", "")] = scope.resolve(
                pa.get("value", ""), source=self.source, element="ParameterAssignment", line=pa.sourceline)
        clone = copy.deepcopy(entry)
        # The entry's own declarations take the assigned values; it may also see the scenario's globals (esmini).
        inner = scope.child()
        decls = clone.find("ParameterDeclarations")
        if decls is not None:
            _declare(decls, inner, entry_file, assigned)
            clone.remove(decls)
        clone.set("_catalog", f"{cat}/{name}")
        parent = ref.getparent()
        parent.replace(ref, clone)
        self.walk_entry(clone, inner, entry_file)
        return None

    def walk_entry(self, el: etree._Element, scope: ParameterScope, entry_file: str) -> None:
        saved, self.source = self.source, entry_file
        try:
            self.walk(el, scope)
        finally:
            self.source = saved


#: Whether a document holds anything `_Resolver.walk` would act on: an attribute with a `$` (a reference or
#: expression to substitute), a CatalogReference to replace, or a ParameterDeclarations below the root's own
#: (declared, and checked, where the walk meets it). Where there is none the walk changes nothing and raises
#: nothing, so it is skipped (generated seeds have none); one XPath pass in C instead of a Python visit per element.
_NEEDS_WALK = etree.XPath("boolean(//@*[contains(., '$')] | //CatalogReference | /*/*//ParameterDeclarations)")


def resolve_document(text: str | bytes, *, source: str, base_dir: Path) -> ResolvedDocument:
    """Parse and resolve a scenario: the returned tree holds literal values only."""
    root = parse_xml(text, source)
    if root.tag != "OpenSCENARIO":
        raise InputError(f"root element is <{root.tag}>, expected <OpenSCENARIO>", source=source,
                         element=root.tag, line=root.sourceline)
    scope = ParameterScope()
    decls = root.find("ParameterDeclarations")
    if decls is not None:
        _declare(decls, scope, source)
    catalogs = CatalogIndex.from_locations(root, base_dir, scope, source)
    if not _NEEDS_WALK(root):
        return ResolvedDocument(root=root, source=source, base_dir=base_dir, parameters=dict(scope.values))
    resolver = _Resolver(source, catalogs)
    for child in list(root):
        if isinstance(child.tag, str) and child.tag not in ("ParameterDeclarations", "CatalogLocations"):
            resolver.walk(child, scope)
    return ResolvedDocument(root=root, source=source, base_dir=base_dir, parameters=dict(scope.values))
