"""`txt2sce bag-plot BAG --out run.png [--run N] [--t T] [--whole-map]`: draw a recorded run from the bag alone.

The road comes from `/sim/map/markers`, the goal and the traffic lights' states from `/sim/scenario/markers`, the
entities (tracks up to T and their boxes at T) from `/sim/objects/markers`; no map or scenario file is read. A bag
recorded before the road was published (older recordings) is refused with a one-line error.
"""

from __future__ import annotations

import argparse

HELP = "draw a PNG of the road and the entities of a recorded run, from the bag alone"


def register(parser: argparse.ArgumentParser) -> None:
    parser.epilog = __doc__
    parser.add_argument("bag", metavar="BAG", help="rosbag2 directory or .mcap file")
    parser.add_argument("--out", required=True, help="PNG file to write")
    parser.add_argument("--run", type=int, default=1, help="which run of the bag, 1-based (default 1)")
    parser.add_argument("--t", type=float, default=None, help="sim time to draw (s; default: the run's last frame)")
    parser.add_argument("--whole-map", action="store_true", help="frame the whole road, not just the entities")


def run(args: argparse.Namespace) -> int:
    from oracle_monitor.bagplot import draw, read_runs
    from txt2sce_ros.errors import InputError

    runs = read_runs(args.bag)
    if not 1 <= args.run <= len(runs):
        raise InputError(f"--run {args.run}: the bag holds {len(runs)} run(s) with a road", source=args.bag)
    picture = runs[args.run - 1]
    path, t = draw(picture, args.out, t=args.t, whole_map=args.whole_map, title=f"run {args.run}/{len(runs)}: ")
    print(f"wrote {path}: run {args.run} of {len(runs)} at t = {t:.2f} s, {len(picture.road)} road lines, "
          f"{len(picture.frames)} frames")
    return 0
