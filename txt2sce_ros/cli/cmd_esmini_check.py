"""`txt2sce esmini-check PATHS... [--sample N]`: run scenarios in the reference player (esmini) and in ours.

Per file it prints esmini's `[error]` lines (a portable scenario has none) and the largest position error of any
entity at any step between the two players (storyboard driving every entity, 0.05 s step). For a scenario that sets
traffic lights it also runs a probe copy in esmini (`scenario_player.esmini.check_lights`) and checks that every
light changes state at the same time there as in ours. Exit status 1 when a file logs an error, differs by
`--target` m or more, or changes a light at another time."""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np

HELP = "run scenarios in esmini and in our player: esmini [error] lines and the worst position difference per file"


def register(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("paths", nargs="+", type=Path, help=".xosc files or directories (searched recursively)")
    parser.add_argument("--sample", type=int, default=0, help="check N files drawn at random (default: all)")
    parser.add_argument("--seed", type=int, default=0, help="RNG seed of --sample (default 0)")
    parser.add_argument("--target", type=float, default=0.5, help="max position difference in m (default 0.5)")
    parser.add_argument("--keep", type=Path, help="keep esmini's logs and CSVs in this directory")


def collect(paths: list[Path]) -> list[Path]:
    """The .xosc files named or found under the directories, sorted (catalog files excluded)."""
    from ..errors import InputError

    files: list[Path] = []
    for p in paths:
        if p.is_dir():
            files.extend(f for f in sorted(p.rglob("*.xosc")) if "Catalogs" not in f.parts)
        elif p.is_file():
            files.append(p)
        else:
            raise InputError(f"no such file or directory: {p}", source=str(p))
    return files


def run(args: argparse.Namespace) -> int:
    from scenario_player.esmini import check_file

    files = collect(args.paths)
    if args.sample and args.sample < len(files):
        rng = np.random.default_rng(args.seed)
        files = sorted(files[i] for i in rng.choice(len(files), size=args.sample, replace=False))
    bad = lit = lights_ok = 0
    worst = 0.0
    print(f"{'scenario':52s} {'errors':>6s} {'rms m':>8s} {'max m':>8s}  worst entity / first error")
    for f in files:
        res = check_file(f, work=args.keep / f.stem if args.keep else None)
        c = res.compared
        if c is None or not c.ran:
            why = res.run.errors[0] if res.run.errors else (c.error if c is not None else "no esmini recording")
            print(f"{f.name:52s} {len(res.run.errors):6d} {'-':>8s} {'-':>8s}  {why}")
            bad += 1
            continue
        ent = max(c.entities, key=lambda e: e.max).name if c.entities else "-"
        lights = res.lights
        if lights is not None:
            lit += 1
            lights_ok += lights.agree
        note = (res.run.errors[0] if res.run.errors else
                lights.first_difference() if lights is not None and not lights.agree else ent)
        flag = "" if res.ok(args.target) else "  FAIL"
        print(f"{f.name:52s} {len(res.run.errors):6d} {c.rms:8.3f} {c.max:8.3f}  {note}{flag}")
        worst = max(worst, c.max)
        bad += not res.ok(args.target)
    n = len(files)
    print(f"\n{n - bad}/{n} files: no esmini [error] and every entity within {args.target:g} m at every step "
          f"(worst {worst:.3f} m)")
    print(f"{lights_ok}/{lit} files that set lights: every light change at the same time in esmini as in ours")
    return 1 if bad else 0
