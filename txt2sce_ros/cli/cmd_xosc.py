"""`txt2sce xosc validate FILES` (XSD + ASAM checker) and `txt2sce xosc entitydb [ELEMENT [ATTRIBUTE]]` (query the
entity database built from the OpenSCENARIO XSD)."""

from __future__ import annotations

import argparse
from pathlib import Path

HELP = "OpenSCENARIO helpers: validate files (XSD + ASAM QC), query the entity database"


def register(parser: argparse.ArgumentParser) -> None:
    sub = parser.add_subparsers(dest="xosc_command", metavar="ACTION", required=True)
    v = sub.add_parser("validate", help="validate .xosc files against their XSD and the ASAM checker")
    v.add_argument("files", nargs="+", type=Path)
    v.add_argument("--version", default=None, help="force a schema version (default: the FileHeader's)")
    v.add_argument("--no-qc", action="store_true", help="XSD only, skip the ASAM quality checker")
    e = sub.add_parser("entitydb", help="print the entity database: elements, or one element's children and "
                                        "attributes, or one attribute's value domain")
    e.add_argument("element", nargs="?", help="complex type, tag or Parent/Tag")
    e.add_argument("attribute", nargs="?")
    e.add_argument("--version", default="1.0")
    e.add_argument("--check", metavar="VALUE", help="check VALUE for ELEMENT/@ATTRIBUTE (exit 2 when not allowed)")


def _validate(args: argparse.Namespace) -> int:
    from ..errors import Txt2SceError
    from ..xosc.validate import qc_check, validate_xosc

    bad = 0
    for f in args.files:
        try:
            errors = validate_xosc(f.read_bytes(), version=args.version, source=str(f))
            issues = [] if args.no_qc or errors else [i for i in qc_check(f) if i.level == "error"]
        except (Txt2SceError, OSError) as exc:
            print(f"{f}: ERROR {exc}")
            bad += 1
            continue
        if errors or issues:
            bad += 1
            for e in errors:
                print(f"{f}: {e}")
            for i in issues:
                print(f"{f}: {i}")
        else:
            print(f"{f}: ok")
    print(f"{len(args.files) - bad}/{len(args.files)} valid")
    return 1 if bad else 0


def _entitydb(args: argparse.Namespace) -> int:
    from ..xosc.entitydb import UNBOUNDED, entity_db

    db = entity_db(args.version)
    if not args.element:
        names = db.elements()
        print(f"OpenSCENARIO {db.version}: {len(names)} element types, "
              f"{db.graph.number_of_nodes()} nodes, {db.graph.number_of_edges()} edges")
        for n in names:
            print(n)
        return 0
    if args.attribute:
        rec = db.attribute(args.element, args.attribute)
        print(rec.documentation)
        if rec.numeric_range:
            print(f"range: {rec.numeric_range}")
        if args.check is not None:
            print(f"ok: {db.check_value(args.element, args.attribute, args.check)}")
        return 0
    el = db.element(args.element)
    print(f"{el.name} ({el.kind}); appears as {', '.join(el.tags) or '-'}")
    if db.bases(el.name):
        print(f"  is a: {', '.join(db.bases(el.name))}")
    for c in db.children(el.name):
        mx = "*" if c.max_occurs == UNBOUNDED else str(c.max_occurs)
        print(f"  <{c.tag}> {c.type} [{c.min_occurs}..{mx}]{' (choice)' if c.in_choice else ''}")
    for a in db.attributes(el.name):
        dom = f" in {list(a.enumeration)}" if a.enumeration else (
            f" range {a.numeric_range}" if a.numeric_range else "")
        print(f"  @{a.name}: {a.type}{' required' if a.required else ''}{dom}")
    return 0


def run(args: argparse.Namespace) -> int:
    return _validate(args) if args.xosc_command == "validate" else _entitydb(args)
