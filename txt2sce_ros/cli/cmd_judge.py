"""`txt2sce judge BAG...`: re-judge recordings offline and print one verdict per run.

Any rosbag2 MCAP directory (or bare .mcap file) with the contract topics works, e.g. one made with
`ros2 bag record` around a real stack. A damaged or unfinished recording prints a clear error line, then the verdict
for the part that could be read. When the recording holds the live monitor's verdicts, they are compared.

Exit status: 0 all runs pass; 1 some run failed or errored; 2 a bag could not be read at all or was damaged.
"""

from __future__ import annotations

import argparse
import json
import sys

from txt2sce_ros.errors import Txt2SceError

HELP = "re-judge recorded runs (rosbag2 MCAP) offline: pass / fail with categories / error, per run"


def register(parser: argparse.ArgumentParser) -> None:
    parser.epilog = __doc__
    parser.add_argument("bags", nargs="+", metavar="BAG", help="rosbag2 directories or .mcap files")
    parser.add_argument("--config", default=None, help="oracle thresholds YAML (default config/oracle.yaml)")
    parser.add_argument("--json", action="store_true", help="one JSON object per run on stdout")
    parser.add_argument("-v", "--verbose", action="store_true", help="list every violation and the notes")


def run(args: argparse.Namespace) -> int:
    from oracle_monitor import OracleParams
    from oracle_monitor.judge import judge_bag

    params = OracleParams.from_config(args.config)
    worst = 0
    for bag in args.bags:
        try:
            result = judge_bag(bag, params)
        except Txt2SceError as exc:
            print(f"txt2sce judge: error: {exc}", file=sys.stderr)
            worst = 2
            continue
        for issue in result.issues:
            print(f"txt2sce judge: error: {bag}: {issue}", file=sys.stderr)
        if result.issues:
            worst = 2
            print(f"txt2sce judge: {bag}: verdict below is for the readable part ({result.messages} messages)",
                  file=sys.stderr)
        agree = result.agrees_with_live()
        for i, v in enumerate(result.verdicts):
            if args.json:
                d = v.to_dict()
                d["bag"] = str(bag)
                d["complete"] = result.complete
                print(json.dumps(d, sort_keys=True))
            else:
                sid = v.scenario_id or f"run{i + 1}"
                print(f"{bag}\t{sid}\t{v.summary()}")
                if args.verbose:
                    for viol in v.violations:
                        who = ",".join(viol.entities)
                        print(f"    {viol.t:8.3f}s {viol.rule.value:<20} {viol.category.value if viol.category else '-':<10} "
                              f"{viol.observed:.4g} vs {viol.threshold:.4g} {viol.units} {who} {viol.detail}")
                    for note in v.notes:
                        print(f"    note: {note}")
            if v.verdict.value != "pass":
                worst = max(worst, 1)
        if not result.verdicts:
            print(f"txt2sce judge: error: {bag}: no run found (no frames, scenario or run status)", file=sys.stderr)
            worst = 2
        if agree is not None and not args.json:
            print(f"{bag}\tlive verdicts recorded: {'same' if agree else 'DIFFERENT'}")
            if not agree:
                worst = max(worst, 1)
    return worst
