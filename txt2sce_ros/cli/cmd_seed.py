"""`txt2sce seed SKETCHES.jsonl --out DIR [--seed N] [--maps DIR]`: one OpenSCENARIO seed per buildable sketch,
the maps they use, and `manifest.json` (choices per seed, reasons per refused sketch)."""

from __future__ import annotations

import argparse
from pathlib import Path

from .argtypes import count

HELP = "turn report sketches into OpenSCENARIO 1.0 seeds on matching OpenDRIVE maps (writes a manifest)"


def register(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("sketches", type=Path, help="JSONL of txt2sce.sketch/1 records")
    parser.add_argument("--out", type=Path, required=True, help="output directory")
    parser.add_argument("--seed", type=count(ge=0), default=0, help="RNG seed for the map pick (default 0)")
    parser.add_argument("--maps", type=Path, default=None,
                        help="directory of .xodr maps to match against (default: the bundled maps)")
    parser.add_argument("--qc", action="store_true", help="also run the ASAM quality checker on every seed")


def run(args: argparse.Namespace) -> int:
    from ..errors import InputError
    from ..sketch import load_sketches
    from ..seed.generate import write_seeds

    if args.maps is not None and not args.maps.is_dir():
        raise InputError("--maps: no such directory", source=str(args.maps))
    if not args.sketches.is_file():
        raise InputError("cannot read: no such file", source=str(args.sketches))

    manifest = write_seeds(load_sketches(args.sketches), args.out, seed=args.seed, maps=args.maps)
    built, refused = manifest["built"], manifest["refused"]
    for r in refused:
        print(f"refused {r['report_id']}: {r['error']}")
    qc_bad = 0
    if args.qc:
        from ..xosc.validate import qc_errors

        for b in built:
            errs = qc_errors(args.out / b["file"])
            if errs:
                qc_bad += 1
                print(f"QC {b['file']}: {errs[0]}")
    from collections import Counter

    maps = Counter(b["map"] for b in built)
    relaxed = sum(1 for b in built if b["choices"].get("relaxed"))
    if built:
        print("maps: " + ", ".join(f"{m} {n}" for m, n in sorted(maps.items()))
              + f"; {relaxed} seed(s) with a relaxed road constraint (see manifest.json)")
    print(f"{len(built)} seed(s) written to {args.out}, {len(refused)} sketch(es) refused"
          + (f", {len(built) - qc_bad}/{len(built)} clean under the ASAM checker" if args.qc else ""))
    # 1: some sketch was refused (its reason is in manifest.json) or some seed is not clean under the checker.
    return 1 if qc_bad or refused else 0
