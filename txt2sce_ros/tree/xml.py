"""Safe XML parsing and serialising shared by the tree modules."""

from __future__ import annotations

from lxml import etree

from ..xosc.schema import parse_document, safe_parser


def parse_bytes(data: bytes | str, source: str) -> etree._Element:
    """Root element of an XML document; InputError naming the file and line when it is not well-formed."""
    return parse_document(data, source=source)


def parse_fragment(text: str) -> etree._Element:
    """A block fragment (always produced by `to_text`, so well-formed)."""
    return etree.fromstring(text, safe_parser())


def to_text(el: etree._Element) -> str:
    """Serialise one element without its tail: the tail belongs to the template."""
    return etree.tostring(el, encoding="unicode", with_tail=False)


def fnum(value: float, digits: int = 4) -> str:
    """Numbers as written into mutated files: fixed precision, so the same draw gives the same bytes everywhere."""
    text = f"{value:.{digits}f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text
