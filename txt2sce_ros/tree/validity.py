"""Per-node XSD validation on the hot path of tree building.

`txt2sce_ros.xosc.validate.validate_xosc` is the reference; per call it also rebuilds its parser and normalises the
version (a few path look-ups), which costs more than the validation itself at thousands of files a second. A tree's
nodes all share the seed's version, so this validator compiles the schema once (through the same
`xosc.schema.xml_schema` cache), reuses one parser, and asks `validate_xosc` for the messages only when a node fails.
"""

from __future__ import annotations

from lxml import etree

from ..xosc.schema import normalise_version, xml_schema
from ..xosc.validate import validate_xosc

_PARSER = etree.XMLParser(resolve_entities=False, no_network=True, huge_tree=False, remove_blank_text=False)


class NodeValidator:
    """Validates scenario texts of one OpenSCENARIO version (`'1.0'`)."""

    def __init__(self, version: str) -> None:
        self.version = normalise_version(version)
        self.schema = xml_schema(self.version)

    def errors(self, text: str, *, source: str) -> list[str]:
        """[] when valid; else the reference validator's messages (`line N: ...`)."""
        try:
            root = etree.fromstring(text.encode("utf-8"), _PARSER)
        except etree.XMLSyntaxError as exc:  # cannot come from α on well-formed blocks; reported, not raised
            return [f"line {exc.lineno}: not well-formed XML: {exc}"]
        if self.schema.validate(root):
            return []
        return validate_xosc(text, version=self.version, source=source) or ["schema-invalid"]
