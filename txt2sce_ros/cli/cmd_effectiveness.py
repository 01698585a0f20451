"""`txt2sce effectiveness REPORTS_OR_SEEDS... --out DIR`: does the pipeline find each planted planner fault, and
does the lift ranking name the element the fault depends on? Prints one row per fault (resumable)."""

from __future__ import annotations

import argparse
from pathlib import Path

from .argtypes import count, TIME_LIMIT

HELP = "fault-injection study: per planner fault mode, found? and the rank of the right trigger (ground truth)"


def register(parser: argparse.ArgumentParser) -> None:
    from ..campaign.executors import EXECUTORS
    from ..campaign.effectiveness import FAULTS

    parser.add_argument("inputs", nargs="+", help="reports (.jsonl/.txt/.pdf), a sketch JSONL or a seed directory")
    parser.add_argument("--out", required=True, help="study directory (rerun the same command to resume)")
    parser.add_argument("--seeds", type=count(), default=10, help="seeds grown into trees, picked to cover the most "
                                                              "scenario elements (default 10)")
    parser.add_argument("--draws", type=count(ge=0), default=0,
                        help="draw the seeds at random this many times (each draw --seeds seeds) instead of "
                             "picking covering seeds; prints each draw's result and the min and median over draws")
    parser.add_argument("--draw-seed", type=count(ge=0), default=0, help="seed of the random draws (default 0)")
    parser.add_argument("--nodes", type=count(), default=150,
                        help="node budget per tree (default 150: a yellow light needs its dilemma-zone variants "
                             "under several parents; with 40 the study misses red_light_misread)")
    parser.add_argument("--mutations", type=count(ge=0), default=1,
                        help="mutations per non-enumerated block (default 1; weather, signal and NPC category "
                             "are enumerated)")
    parser.add_argument("--time-limit", type=TIME_LIMIT, default=25.0, help="simulated seconds per run (default 25)")
    parser.add_argument("--fault", action="append", default=[], choices=[f.name for f in FAULTS],
                        help="study only these faults (repeatable; default all)")
    parser.add_argument("--executor", choices=EXECUTORS, default="pool")
    parser.add_argument("--ray-address", default=None, metavar="HOST:PORT",
                        help="Ray cluster for --executor ray (default: as `txt2sce campaign`)")
    parser.add_argument("--workers", type=count(), default=None)
    parser.add_argument("--seed", type=count(ge=0), default=0)
    parser.add_argument("--no-progress", action="store_true")


def run(args: argparse.Namespace) -> int:
    from ..campaign.effectiveness import FAULTS, StudyConfig, format_draws, format_table, run_draws
    from ..errors import InputError

    if args.draws < 0 or args.seeds < 1:
        raise InputError("--draws must be >= 0 and --seeds >= 1")

    cfg = StudyConfig(out=Path(args.out), seeds=args.seeds, nodes=args.nodes, mutations=args.mutations,
                      time_limit=args.time_limit, executor=args.executor, workers=args.workers,
                      ray_address=args.ray_address,
                      faults=tuple(args.fault) or tuple(f.name for f in FAULTS), seed=args.seed,
                      progress=not args.no_progress, draws=args.draws, draw_seed=args.draw_seed)
    draws = run_draws(args.inputs, cfg)
    if args.draws:
        for d in draws:
            print(f"draw {d.index}: {', '.join(d.seeds)}")
            print(format_table(d.rows) + "\n")
        print(format_draws(draws))
    else:
        print(format_table(draws[0].rows))
    print(f"(details: {cfg.out / 'effectiveness.json'})")
    return 0
