"""α: insert block fragments into the template (paper §III-D.1). A string join: one serialisation per node."""

from __future__ import annotations

from collections.abc import Sequence

from lxml import etree

from .blocks import Template
from .xml import parse_bytes


def assemble(template: Template, fragments: Sequence[str]) -> str:
    """The scenario text with `fragments[slot]` at every insertion point ('' leaves a slot empty)."""
    out = [template.pieces[0]]
    for slot, piece in zip(template.slot_at, template.pieces[1:]):
        out.append(fragments[slot])
        out.append(piece)
    return "".join(out)


def canonical(xml: bytes | str, source: str = "<xml>") -> bytes:
    """Canonical XML (C14N 2.0, whitespace-only text dropped, comments dropped): what "the same scenario" means for
    the round trip α(δ(seed)) == seed."""
    root = parse_bytes(xml, source)
    for el in root.iter():
        if isinstance(el.tag, str):
            if el.text is not None and not el.text.strip():
                el.text = None
            if el.tail is not None and not el.tail.strip():
                el.tail = None
    return etree.tostring(root, method="c14n2", with_comments=False)
