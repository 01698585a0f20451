"""`txt2sce bench NAME`: run one benchmark and print its figures beside a baseline measured in the same run.

Benchmarks live in `txt2sce_ros/bench/<name>.py`, each with `DESCRIPTION` and `run(args) -> int`; they are
measurements, not tests.
"""

from __future__ import annotations

import argparse
import importlib
import pkgutil

from .argtypes import count

HELP = "run a benchmark (maps, extract, player, tree, judge, campaign) and print its figures"


def _benches() -> dict[str, str]:
    import txt2sce_ros.bench as pkg

    out = {}
    for info in pkgutil.iter_modules(pkg.__path__):
        if not info.name.startswith("_"):
            mod = importlib.import_module(f"{pkg.__name__}.{info.name}")
            out[info.name] = getattr(mod, "DESCRIPTION", "")
    return dict(sorted(out.items()))


def register(parser: argparse.ArgumentParser) -> None:
    benches = _benches()
    parser.add_argument("name", choices=sorted(benches), help="; ".join(f"{k}: {v}" for k, v in benches.items()))
    parser.add_argument("--quick", action="store_true", help="smaller sizes, for a smoke run")
    parser.add_argument("--seed", type=count(ge=0), default=0, help="RNG seed for generated inputs (default 0)")
    parser.add_argument("--scenarios", type=count(), default=None,
                        help="campaign: how many scenarios to run (default 4,000; --quick: 300)")


def run(args: argparse.Namespace) -> int:
    mod = importlib.import_module(f"txt2sce_ros.bench.{args.name}")
    return int(mod.run(args) or 0)
