"""`txt2sce diversity TREE_DIR...`: Table V (abstraction levels, abstract representations, variants generated) and
the number of unique scenario categories over the generated trees."""

from __future__ import annotations

import argparse
import json

HELP = "print Table V (scenario variants per abstraction level) and the unique scenario categories of trees"


def register(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("trees", nargs="+", metavar="TREE_DIR",
                        help="tree directories (with manifest.json) or directories holding them")
    parser.add_argument("--json", action="store_true", help="print JSON instead of the table")


def run(args: argparse.Namespace) -> int:
    from dataclasses import asdict

    from ..tree.diversity import diversity, format_table

    table = diversity(args.trees)
    print(json.dumps(asdict(table), indent=1) if args.json else format_table(table))
    return 0
