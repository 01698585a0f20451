"""Validation of OpenDRIVE files against the ASAM OpenDRIVE 1.7 XSD shipped by `scenariogeneration`.

The schema files are under ASAM's licence terms, so they are loaded from site-packages, never copied here.
"""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path

from lxml import etree

from ..errors import InputError, UnsupportedFeature
from ..xosc.schema import safe_parser

_SCHEMA_NAME = "opendrive_17_core.xsd"


def schema_path() -> Path:
    """Where the installed OpenDRIVE 1.7 core schema lives (raises UnsupportedFeature if it is not installed)."""
    try:
        import scenariogeneration
    except ImportError as exc:  # pragma: no cover - listed in requirements
        raise UnsupportedFeature("scenariogeneration is not installed; no OpenDRIVE XSD available",
                                 source=_SCHEMA_NAME) from exc
    # The wheel installs its schemas as a top-level `schemas/` folder beside the package.
    path = Path(scenariogeneration.__file__).resolve().parent.parent / "schemas" / _SCHEMA_NAME
    if not path.is_file():
        raise UnsupportedFeature("OpenDRIVE 1.7 XSD not found beside scenariogeneration", source=str(path))
    return path


@lru_cache(maxsize=1)
def _schema() -> etree.XMLSchema:
    return etree.XMLSchema(etree.parse(str(schema_path()), safe_parser()))


def validation_errors(xodr: str | Path | bytes) -> list[str]:
    """Schema errors of an OpenDRIVE document (a path or the bytes), as 'line N: message'; empty when valid."""
    parser = safe_parser()
    source = "<bytes>" if isinstance(xodr, bytes) else str(xodr)
    try:
        doc = etree.fromstring(xodr, parser) if isinstance(xodr, bytes) else etree.parse(str(xodr), parser)
    except (etree.XMLSyntaxError, OSError) as exc:
        raise InputError(f"cannot parse: {exc}", source=source) from exc
    schema = _schema()
    if schema.validate(doc):
        return []
    return [f"line {e.line}: {e.message}" for e in schema.error_log]
