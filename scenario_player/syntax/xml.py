"""Small helpers to read typed attributes from resolved elements, with errors naming the element and line."""

from __future__ import annotations

from collections.abc import Iterator

from lxml import etree

from txt2sce_ros.errors import InputError


class ParseContext:
    """What every `from_xml` needs: the source name (for errors) and the list that collects unsupported notes."""

    def __init__(self, source: str) -> None:
        self.source = source
        self.unsupported: list[str] = []

    def where(self, el: etree._Element) -> str:
        """The file an element was read from: the scenario, or the catalog entry it was copied from."""
        node: etree._Element | None = el
        while node is not None:
            cat = node.get("_catalog") if isinstance(node.tag, str) else None
            if cat:
                return f"{self.source} (catalog entry {cat})"
            node = node.getparent()
        return self.source

    def error(self, el: etree._Element, message: str) -> InputError:
        return InputError(message, source=self.where(el), element=str(el.tag), line=el.sourceline)

    def note_unsupported(self, el: etree._Element, what: str | None = None) -> str:
        where = self.where(el)
        suffix = "" if where == self.source else f" of {where[len(self.source) + 2:-1]}"
        note = f"unsupported: {what or el.tag} at line {el.sourceline}{suffix}"
        if note not in self.unsupported:
            self.unsupported.append(note)
        return note

    # -- attributes ---------------------------------------------------------------------------------------------
    def req(self, el: etree._Element, name: str) -> str:
        value = el.get(name)
        if value is None:
            raise self.error(el, f"missing attribute '{name}'")
        return value

    def float(self, el: etree._Element, name: str, default: float | None = None) -> float:
        value = el.get(name)
        if value is None:
            if default is None:
                raise self.error(el, f"missing attribute '{name}'")
            return default
        try:
            return float(value)
        except ValueError as exc:
            raise self.error(el, f"attribute {name}='{value}' is not a number") from exc

    def int(self, el: etree._Element, name: str, default: int | None = None) -> int:
        return int(round(self.float(el, name, None if default is None else float(default))))

    def bool(self, el: etree._Element, name: str, default: bool = False) -> bool:
        value = el.get(name)
        if value is None:
            return default
        low = value.strip().lower()
        if low in ("true", "1"):
            return True
        if low in ("false", "0"):
            return False
        raise self.error(el, f"attribute {name}='{value}' is not a boolean")

    def child(self, el: etree._Element, tag: str) -> etree._Element:
        found = first(el, tag)
        if found is None:
            raise self.error(el, f"missing child <{tag}>")
        return found

    def only_child(self, el: etree._Element) -> etree._Element:
        kids = elements(el)
        if len(kids) != 1:
            raise self.error(el, f"expected exactly one child element, found {len(kids)}")
        return kids[0]


def first(el: etree._Element, tag: str) -> etree._Element | None:
    """`el.find(tag)` for a plain tag name: its first child of that tag, or None. lxml's `find` parses the path
    through ElementPath (cached) and runs a generator chain per call that ends in this `iterchildren`; the
    parse of a scenario asks this thousands of times, at about twice the cost."""
    for child in el.iterchildren(tag):
        return child
    return None


def children(el: etree._Element, tag: str) -> list[etree._Element]:
    """`el.findall(tag)` for a plain tag name (see `first`)."""
    return list(el.iterchildren(tag))


def elements(el: etree._Element) -> list[etree._Element]:
    """Child elements (comments and processing instructions skipped)."""
    return [c for c in el if isinstance(c.tag, str)]


def iter_tag(el: etree._Element, tag: str) -> Iterator[etree._Element]:
    return (c for c in el if c.tag == tag)
