"""`txt2sce replay BAG [--rate 1.0]`: re-publish a recording on its topics with its original timing.

The recorded bytes are published unchanged (ROS 2 CDR), with the gaps between log times divided by `--rate`. The
recorded /oracle/violations are left out unless `--topics` names them (a live monitor listening would otherwise
see two sets). The road and the goal/light markers (/sim/map/markers, /sim/scenario/markers) are offered latched, as
the player offers them: a viewer that joins mid-replay still draws the road. DDS settings come from the environment (ROS_DOMAIN_ID, ROS_AUTOMATIC_DISCOVERY_RANGE, ...).
"""

from __future__ import annotations

import argparse
import sys
import time

from .argtypes import number, POSITIVE

HELP = "re-publish a recorded run on its ROS 2 topics with its original timing (× --rate)"


def register(parser: argparse.ArgumentParser) -> None:
    parser.epilog = __doc__
    parser.add_argument("bag", metavar="BAG", help="rosbag2 directory or .mcap file")
    parser.add_argument("--rate", type=POSITIVE, default=1.0, help="speed factor (2.0 = twice as fast; default 1.0)")
    parser.add_argument("--topics", nargs="+", default=None, help="only these topics (default: all but violations)")
    parser.add_argument("--discovery-timeout", type=number(ge=0.0), default=3.0,
                        help="wait up to this many seconds for a subscriber before starting (default 3)")


def run(args: argparse.Namespace) -> int:
    import rclpy

    from oracle_monitor.replay import replay_bag

    rclpy.init()
    try:
        t0 = time.monotonic()
        count, issues = replay_bag(args.bag, rate=args.rate, topics=frozenset(args.topics) if args.topics else None,
                                   discovery_timeout=args.discovery_timeout)
        for issue in issues:
            print(f"txt2sce replay: error: {args.bag}: {issue}", file=sys.stderr)
        print(f"replayed {count} messages from {args.bag} in {time.monotonic() - t0:.2f} s (rate {args.rate:g})")
        return 2 if issues else 0
    finally:
        if rclpy.ok():
            rclpy.shutdown()
