"""`txt2sce conformance XOSC_DIR --reference CSV_DIR`: run each scenario with the storyboard driving every entity
and print, per file, whether it ran, its unsupported elements, and the RMS / max position error per entity against
the reference player's CSV (same 0.05 s step)."""

from __future__ import annotations

import argparse
from pathlib import Path

from .argtypes import POSITIVE

HELP = "compare the scenario player with a reference player's trajectories (RMS/max position error per entity)"


def register(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("xosc_dir", type=Path, help="directory of .xosc files")
    parser.add_argument("--reference", type=Path, required=True, help="directory of <name>.csv reference runs")
    parser.add_argument("--only", nargs="*", help="scenario names to run (default: all)")
    parser.add_argument("--target", type=POSITIVE, default=0.5, help="RMS target in m (default 0.5)")
    parser.add_argument("--brief", action="store_true", help="one line per file (worst entity only)")


def run(args: argparse.Namespace) -> int:
    from scenario_player.conformance import run_directory

    from ..errors import InputError

    for what, d in (("scenario", args.xosc_dir), ("reference", args.reference)):
        if not d.is_dir():
            raise InputError(f"no such {what} directory", source=str(d))
    if not any(args.xosc_dir.glob("*.xosc")):
        raise InputError("no .xosc files", source=str(args.xosc_dir))
    table = run_directory(args.xosc_dir, args.reference, only=args.only)
    print(f"{'scenario':34s} {'ran':4s} {'rms m':>8s} {'max m':>8s}  worst entity / unsupported")
    for r in table.results:
        if not r.ran:
            print(f"{r.name:34s} {'no':4s} {'-':>8s} {'-':>8s}  {r.error}")
            continue
        worst = max(r.entities, key=lambda e: e.rms).name if r.entities else "-"
        flag = "" if r.rms < args.target else "  > target"
        print(f"{r.name:34s} {'yes':4s} {r.rms:8.3f} {r.max:8.3f}  {worst}{flag}")
        if not args.brief:
            for e in r.entities:
                print(f"{'':36s} {e.name:20s} rows {e.rows:5d} rms {e.rms:8.3f} max {e.max:8.3f}")
        for note in r.unsupported:
            print(f"{'':36s} {note}")
    n = len(table.results)
    ran = sum(r.ran for r in table.results)
    print(f"\nran {ran}/{n}; RMS < {args.target:g} m: {table.passed(args.target)}/{n}")
    # 1: some scenario could not be run (its reason is on its line); the RMS figures are results, not failures.
    return 1 if ran < n else 0
