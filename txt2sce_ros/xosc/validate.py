"""XSD validation of OpenSCENARIO documents, and the ASAM quality checker as a library call.

    from txt2sce_ros.xosc.validate import validate_xosc, qc_check
    errors = validate_xosc(xml_bytes)          # [] when valid; else "line N: <XSD message>" strings
    issues = qc_check("seed.xosc")             # list[QcIssue]; errors have level == "error"

The version comes from the document's FileHeader (revMajor/revMinor) unless given. Validation is lxml against the
schema shipped by `asam-qc-openscenarioxml`, compiled once per version; the parser and the version look-up are
cached too, so a call costs the parse plus the validation (the tree validates every node through it).
"""

from __future__ import annotations

import logging
from dataclasses import dataclass
from pathlib import Path
from typing import Union

from lxml import etree

from ..errors import InputError
from ..xmlsafe import refuse_doctype
from .schema import normalise_version, parse_document, xml_schema

XmlInput = Union[bytes, str, etree._ElementTree, etree._Element]


def _root_of(xml: XmlInput, source: str | None) -> etree._Element:
    if isinstance(xml, etree._ElementTree):
        return xml.getroot()
    if isinstance(xml, etree._Element):
        return xml
    return parse_document(xml, source=source)


def document_version(root: etree._Element, *, source: str | None = None) -> str:
    """'<revMajor>.<revMinor>' from the FileHeader; InputError naming the element when absent."""
    header = root.find("FileHeader")
    if header is None:
        raise InputError("no FileHeader: cannot tell the OpenSCENARIO version", source=source, element="FileHeader")
    major, minor = header.get("revMajor"), header.get("revMinor")
    if major is None or minor is None:
        raise InputError("FileHeader lacks revMajor/revMinor", source=source, element="FileHeader",
                         line=header.sourceline)
    return f"{major}.{minor}"


def validate_xosc(xml: XmlInput, *, version: str | None = None, source: str | None = None) -> list[str]:
    """Validate an OpenSCENARIO document against its XSD. Returns the schema errors as `line N: message`
    (empty when valid). Raises InputError when the text is not well-formed XML or has no version."""
    root = _root_of(xml, source)
    ver = normalise_version(version or document_version(root, source=source))
    schema = xml_schema(ver)
    if schema.validate(root):
        return []
    out = []
    for err in schema.error_log:
        where = f"line {err.line}" if err.line else (err.path or "?")
        out.append(f"{where}: {err.message}")
    return out


def is_valid(xml: XmlInput, *, version: str | None = None) -> bool:
    return not validate_xosc(xml, version=version)


@dataclass(frozen=True, slots=True)
class QcIssue:
    """One finding of the ASAM OpenSCENARIO checker bundle."""

    checker_id: str
    rule_uid: str
    level: str            # 'error' | 'warning' | 'information'
    description: str
    location: str = ""    # xpath or 'line N' when the checker gave one

    def __str__(self) -> str:
        loc = f" at {self.location}" if self.location else ""
        return f"[{self.level}] {self.checker_id}{loc}: {self.description}"


def _location_text(issue: object) -> str:
    parts = []
    for loc in getattr(issue, "locations", []) or []:
        for x in getattr(loc, "xml_location", []) or []:
            parts.append(str(getattr(x, "xpath", "")))
        for f in getattr(loc, "file_location", []) or []:
            parts.append(f"line {getattr(f, 'row', '?')}")
    return "; ".join(p for p in parts if p)


def qc_check(path: str | Path) -> list[QcIssue]:
    """Run the ASAM quality checker bundle (`qc_openscenario.main.run_checks`) on one file and return its issues.

    Checkers that could not run (status 'error', e.g. a crash inside the bundle) are reported as issues of level
    'error' too, so "0 errors" never hides a checker that did not look."""
    from qc_baselib import Configuration, Result, StatusType
    from qc_baselib.models.common import IssueSeverity
    from qc_openscenario import constants
    from qc_openscenario.main import run_checks

    p = Path(path)
    if not p.is_file():
        raise InputError("file not found", source=str(p))
    # The checker parses with lxml's defaults (entities resolved): it must never see a DOCTYPE.
    refuse_doctype(p.read_bytes(), str(p))
    config = Configuration()
    config.set_config_param(name="InputFile", value=str(p.resolve()))
    config.register_checker_bundle(checker_bundle_name=constants.BUNDLE_NAME)
    result = Result()
    result.register_checker_bundle(name=constants.BUNDLE_NAME, description="OpenScenario checker bundle",
                                   version=constants.BUNDLE_VERSION, summary="")
    result.set_result_version(version=constants.BUNDLE_VERSION)
    # The bundle logs every checker at INFO through the root logger; keep a batch's output readable.
    root_logger = logging.getLogger()
    old_level = root_logger.level
    root_logger.setLevel(logging.WARNING)
    try:
        run_checks(config, result)
    finally:
        root_logger.setLevel(old_level)
    levels = {IssueSeverity.ERROR: "error", IssueSeverity.WARNING: "warning", IssueSeverity.INFORMATION: "information"}
    issues: list[QcIssue] = []
    for checker in result.get_checker_results(constants.BUNDLE_NAME):
        for issue in checker.issues:
            issues.append(QcIssue(checker.checker_id, issue.rule_uid, levels.get(issue.level, str(issue.level)),
                                  issue.description, _location_text(issue)))
        if checker.status == StatusType.ERROR:
            issues.append(QcIssue(checker.checker_id, "", "error", f"checker failed to run: {checker.summary}"))
    return issues


def qc_errors(path: str | Path) -> list[QcIssue]:
    """Only the error-level findings of `qc_check`."""
    return [i for i in qc_check(path) if i.level == "error"]
