"""Where the OpenSCENARIO XSDs live: loaded from the installed `qc_openscenario` package (ASAM's licence terms
forbid copying them into the repo), one file per version, parsed once per process. Also the project's safe XML
parser (one per thread, reused) and `parse_document`, the one place XML text becomes an element tree."""

from __future__ import annotations

import threading
from functools import lru_cache
from pathlib import Path

from lxml import etree

from ..errors import InputError, UnsupportedFeature
from ..xmlsafe import refuse_doctype

#: The version every seed and mutant is written in (see docs/seed_format.md).
DEFAULT_VERSION = "1.0"

XSD_NS = "http://www.w3.org/2001/XMLSchema"


_local = threading.local()


def safe_parser() -> etree.XMLParser:
    """The project's XML parser: no entity expansion, no network, no huge trees (CONTRIBUTING.md).

    One instance per thread, reused: building a parser costs more than parsing a small scenario, and lxml parsers
    must not be shared between threads. Callers only parse with it; never configure the returned parser."""
    parser = getattr(_local, "parser", None)
    if parser is None:
        parser = etree.XMLParser(resolve_entities=False, no_network=True, huge_tree=False, remove_blank_text=False)
        _local.parser = parser
    return parser


def parse_document(data: bytes | str, *, source: str | None = None) -> etree._Element:
    """Root element of an XML text; InputError naming the source and line when it is not well-formed."""
    raw = data.encode("utf-8") if isinstance(data, str) else data
    refuse_doctype(raw, source)
    try:
        return etree.fromstring(raw, safe_parser())
    except etree.XMLSyntaxError as exc:
        raise InputError(f"not well-formed XML: {exc}", source=source, line=exc.lineno) from exc


def schema_dir() -> Path:
    try:
        import qc_openscenario.schema as pkg
    except ImportError as exc:  # pragma: no cover - a dependency of the package
        raise UnsupportedFeature("asam-qc-openscenarioxml is not installed; it ships the OpenSCENARIO XSDs") from exc
    return Path(pkg.__file__).resolve().parent


def normalise_version(version: str) -> str:
    """'1', '1.0', '1.0.0' -> the schema directory name ('1.0.0'); a minor version maps to its .0 schema, as the
    ASAM checker does. Cached: the answer needs file look-ups, and every validated document asks."""
    return _normalise_version(str(version).strip())


@lru_cache(maxsize=64)
def _normalise_version(version: str) -> str:
    # lru_cache does not cache exceptions: a bad version raises on every call, naming itself
    parts = [p for p in str(version).strip().split(".") if p != ""]
    if not parts or not all(p.isdigit() for p in parts):
        raise InputError(f"not an OpenSCENARIO version: {version!r}", element="FileHeader")
    major = parts[0]
    minor = parts[1] if len(parts) > 1 else "0"
    patch = parts[2] if len(parts) > 2 else "0"
    name = f"{major}.{minor}.{patch}"
    if not (schema_dir() / name / "OpenSCENARIO.xsd").is_file():
        fallback = f"{major}.{minor}.0"
        if (schema_dir() / fallback / "OpenSCENARIO.xsd").is_file():
            return fallback
        raise UnsupportedFeature(f"no OpenSCENARIO schema for version {version}", element="FileHeader")
    return name


def xsd_path(version: str = DEFAULT_VERSION) -> Path:
    return schema_dir() / normalise_version(version) / "OpenSCENARIO.xsd"


@lru_cache(maxsize=None)
def xsd_tree(version: str = DEFAULT_VERSION) -> etree._ElementTree:
    """The parsed XSD document (cached per version)."""
    return etree.parse(str(xsd_path(version)), safe_parser())


@lru_cache(maxsize=None)
def xml_schema(version: str = DEFAULT_VERSION) -> etree.XMLSchema:
    """The compiled validator (cached per version: compiling takes ~20 ms, validating a seed ~0.1 ms)."""
    return etree.XMLSchema(xsd_tree(normalise_version(version)))
