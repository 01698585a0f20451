"""`txt2sce accel`: the optional compiled build of the closed loop's hot modules (`txt2sce_ros/accel.py`).

  txt2sce accel build    compile the modules whose source has no build yet (Cython + a C compiler; `make setup`
                         runs it); exit 1 with the compiler log's path when it cannot
  txt2sce accel status   which modules load compiled, which run from the plain source (and why)

The same runs either way (bit for bit); a compiled module is used only while its source is unchanged.
"""

from __future__ import annotations

import argparse
import os
import sys

HELP = "build or inspect the optional compiled build of the player, planner and oracle (same results, less CPU)"


def register(parser: argparse.ArgumentParser) -> None:
    sub = parser.add_subparsers(dest="accel_command", metavar="SUBCOMMAND")
    b = sub.add_parser("build", help="compile the hot modules whose source has no build yet")
    b.add_argument("--jobs", type=int, default=os.cpu_count() or 2, help="parallel compiler jobs (default: cores)")
    sub.add_parser("status", help="which modules load compiled")


def run(args: argparse.Namespace) -> int:
    from .. import accel

    where = accel.cache_dir()
    if args.accel_command == "build":
        try:
            done = accel.build(jobs=max(1, args.jobs), note=lambda m: print(f"[accel] {m}", file=sys.stderr))
        except RuntimeError as exc:
            print(f"txt2sce accel: {exc}", file=sys.stderr)
            return 1
        built = sum(1 for v in done.values() if v == "built")
        fresh = sum(1 for v in done.values() if v == "up to date")
        left = {m: v for m, v in done.items() if v not in ("built", "up to date")}     # named by build's note
        print(f"[accel] {built} built, {fresh} up to date, {len(left)} left to the source, in {where}")
        return 0
    if args.accel_command == "status":
        state = accel.status()
        for name, s in state.items():
            print(f"  {name:40s} {s}")
        ready = sum(1 for s in state.values() if s == "built")
        off = " (switched off: TXT2SCE_ACCEL=0)" if accel.switched_off() else ""
        print(f"{ready}/{len(state)} modules load compiled{off}; builds in {where}")
        if ready < len(state) and not accel.switched_off():
            print("the others run from their plain source: `txt2sce accel build` compiles them")
        return 0
    print("txt2sce accel: choose a subcommand: build or status", file=sys.stderr)
    return 2
