"""Refuse any XML document that carries a DOCTYPE, before any parser or third-party checker reads it.

OpenSCENARIO and OpenDRIVE files never need a DTD. A DOCTYPE is how external entities (XXE: `file:///etc/passwd`
pulled into the document) and entity expansion (billion laughs) get in, and third-party tools such as the ASAM
quality checker parse with lxml's defaults. So the check is on the raw bytes: only the prolog before the root
element is scanned (comments and processing instructions skipped), which is linear in its length.
"""

from __future__ import annotations

import re

from .errors import InputError

_BOMS = (("utf-16", b"\xff\xfe"), ("utf-16", b"\xfe\xff"), ("utf-32", b"\xff\xfe\x00\x00"),
         ("utf-32", b"\x00\x00\xfe\xff"))
# The prolog: optional BOM/whitespace, then any run of <?...?>, <!--...-->, whitespace; then whatever comes next.
_MISC = re.compile(rb"\s*(?:<\?.*?\?>|<!--.*?-->)?", re.S)


def _as_utf8(data: bytes) -> bytes:
    for enc, bom in sorted(_BOMS, key=lambda b: -len(b[1])):
        if data.startswith(bom):
            try:
                return data.decode(enc, errors="replace").encode("utf-8")
            except LookupError:  # pragma: no cover - both codecs ship with Python
                return data
    if len(data) > 1 and (data[0] == 0 or data[1] == 0):   # UTF-16 without a BOM
        return data.replace(b"\x00", b"")
    return data.removeprefix(b"\xef\xbb\xbf")


def refuse_doctype(data: bytes | str, source: str | None = None) -> None:
    """InputError if the document declares a DOCTYPE (anywhere before its root element)."""
    raw = _as_utf8(data.encode("utf-8") if isinstance(data, str) else data)
    pos = 0
    while pos < len(raw):
        m = _MISC.match(raw, pos)
        if m is None or m.end() == pos:
            break
        pos = m.end()
    if raw[pos:pos + 9].upper() == b"<!DOCTYPE":
        line = raw.count(b"\n", 0, pos) + 1
        raise InputError("a DOCTYPE is not allowed (external entities / entity expansion); remove it",
                         source=source, element="!DOCTYPE", line=line)
