"""`txt2sce fidelity SKETCHES.jsonl [--seed N] [--maps DIR]`: build each buildable sketch's seed, run it in the
scenario player with a storyboard-driven AV (its reported manoeuvre, non-reactive), and print the share of seeds
in which the reported party comes into conflict with the AV (contact, or TTC < 1.5 s), with the failing ids."""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from .argtypes import count, STEP

HELP = "fidelity of generated seeds: does the reported party meet the AV (contact or TTC < 1.5 s) in the player?"


def register(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("sketches", type=Path, help="JSONL of txt2sce.sketch/1 records")
    parser.add_argument("--seed", type=count(ge=0), default=0, help="RNG seed for the map pick (default 0)")
    parser.add_argument("--maps", type=Path, default=None, help="directory of .xodr maps (default: bundled)")
    parser.add_argument("--dt", type=STEP, default=0.05, help="player step, s (default 0.05)")
    parser.add_argument("--json", type=Path, default=None, help="also write every result as JSON lines here")


def run(args: argparse.Namespace) -> int:
    from dataclasses import asdict

    from ..sketch import ErrorRecord, load_sketches
    from ..seed.fidelity import fidelity_batch

    unreadable: list[ErrorRecord] = []

    def items():
        for item in load_sketches(args.sketches):
            if isinstance(item, ErrorRecord):
                unreadable.append(item)     # recorded and reported below; the batch carries on
            yield item

    results = fidelity_batch(items(), seed=args.seed, maps=args.maps, dt=args.dt)
    for bad in unreadable:
        print(f"txt2sce fidelity: error: {bad.report_id}: {bad.error}", file=sys.stderr)
    ok = [r for r in results if r.faithful]
    for r in results:
        if not r.faithful:
            gap = f"{r.min_gap:.2f} m" if r.min_gap is not None else "-"
            print(f"not faithful: {r.report_id} (party {r.target}: {r.kind}, closest gap {gap}) {r.note}".rstrip())
    kinds = {k: sum(1 for r in ok if r.kind == k) for k in ("contact", "ttc")}
    rate = 100.0 * len(ok) / len(results) if results else 0.0
    print(f"fidelity: {len(ok)}/{len(results)} = {rate:.1f}% faithful "
          f"(contact {kinds['contact']}, TTC<1.5 s {kinds['ttc']}); paper's manual check: 31/33 = 93.9%")
    if args.json:
        with open(args.json, "w", encoding="utf-8") as fh:
            for r in results:
                fh.write(json.dumps({k: (float(v) if hasattr(v, "item") else v) for k, v in asdict(r).items()})
                         + "\n")
    return 1 if unreadable else 0
