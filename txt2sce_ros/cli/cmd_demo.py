"""`txt2sce demo`: the main job on bundled data — a campaign over the bundled narratives, plus one seed over DDS."""

from __future__ import annotations

import argparse
import json
import shutil
import sys
from pathlib import Path

HELP = "run the whole pipeline on the bundled narratives and maps (offline), and one seed over the ROS 2 graph"


def register(parser: argparse.ArgumentParser) -> None:
    from .cmd_campaign import add_campaign_options

    parser.add_argument("--out", default="demo_out", help="output directory (default demo_out)")
    parser.add_argument("--fresh", action="store_true", help="delete the output directory first")
    parser.add_argument("--no-ros", action="store_true", help="skip the run over the ROS 2 node graph")
    add_campaign_options(parser)
    # A demo should finish in a few minutes: the paper's mutation settings, but at most 60 nodes per tree (the
    # budget is spread over every layer, so each block is still inserted). `txt2sce campaign` has no such cap.
    parser.set_defaults(max_seeds=None, max_nodes=60)


def run(args: argparse.Namespace) -> int:
    from ..campaign.pipeline import run_campaign
    from ..paths import BUNDLED_REPORTS
    from .cmd_campaign import config_from_args, print_summary

    out = Path(args.out)
    if args.fresh and out.exists():
        shutil.rmtree(out)
    reports = sorted(BUNDLED_REPORTS.glob("*.jsonl"))
    if not reports:
        from ..errors import InputError

        raise InputError("no bundled narratives (*.jsonl) found", source=str(BUNDLED_REPORTS))
    print(f"demo: {', '.join(str(r) for r in reports)} -> {out}", file=sys.stderr)
    summary = run_campaign(reports, config_from_args(args, out / "campaign"))
    print_summary(summary)
    if args.no_ros:
        return 0
    # One seed through the real node graph: player, stand-in planner and oracle monitor as separate processes.
    from ..launcher import GraphConfig, run_graph

    manifest = json.loads((out / "campaign" / "seeds" / "manifest.json").read_text(encoding="utf-8"))
    if not manifest["built"]:
        print("demo: no seed was built, nothing to run over ROS", file=sys.stderr)
        return 1
    seed_file = out / "campaign" / "seeds" / manifest["built"][0]["file"]
    bags = out / "ros_bags"
    print(f"demo: running {seed_file.name} over the ROS 2 graph (lock-step), recording to {bags}", file=sys.stderr)
    earlier = set(bags.rglob("*.mcap"))  # a rerun into the same --out keeps the earlier runs' bags
    codes = run_graph(GraphConfig(scenarios=[str(seed_file)], bag_dir=str(bags), log_dir=str(out / "ros_logs")),
                      timeout=300)
    recorded = sorted(set(bags.rglob("*.mcap")) - earlier)
    print(f"ros graph:  exit codes {codes}; recorded now: {', '.join(str(p) for p in recorded) or 'none'}")
    if recorded:
        from ..cli.main import main as cli_main

        cli_main(["judge", str(recorded[-1].parent)])
    return 0 if codes.get("generator") == 0 and recorded else 1
