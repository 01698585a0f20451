"""`txt2sce campaign INPUT... --out DIR`: the whole pipeline, resumable, from any stage."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from .argtypes import count, SHARE, TIME_LIMIT

#: Refused items listed one per line; the rest are counted (all of them are in the manifest).
MAX_LISTED = 20

HELP = "reports/sketches/seeds/trees/scenarios -> closed-loop runs -> verdicts -> analysis report (resumable)"


def add_campaign_options(parser: argparse.ArgumentParser) -> None:
    from standin_planner.faults import Faults

    from ..campaign.executors import EXECUTORS

    parser.add_argument("--seed", type=count(ge=0), default=0, help="RNG seed of every stage (default 0)")
    parser.add_argument("--backend", choices=("offline", "llm", "hybrid"), default="offline",
                        help="extractor for report inputs (default offline)")
    parser.add_argument("--mutations", type=count(ge=0), default=None,
                        help="mutated versions per block (default: config/mutation.yaml, the paper's 2)")
    parser.add_argument("--prune", type=SHARE, default=None,
                        help="share of each cluster kept when pruning (default: config, 0.5)")
    parser.add_argument("--max-seeds", type=count(), default=None, help="grow trees from the first N seeds only")
    parser.add_argument("--max-nodes", type=count(), default=None,
                        help="node budget per tree (default: config/mutation.yaml)")
    parser.add_argument("--executor", choices=EXECUTORS, default="pool",
                        help="serial | pool (local processes, default) | ray (a Ray cluster: --ray-address, "
                             "RAY_ADDRESS, the one `ray start` started on this machine, else a local instance)")
    parser.add_argument("--ray-address", default=None, metavar="HOST:PORT",
                        help="Ray cluster to run on with --executor ray (default: RAY_ADDRESS, else the cluster "
                             "`ray start` recorded on this machine, else a local instance)")
    parser.add_argument("--workers", type=count(), default=None,
                        help="parallel workers (default: CPU count); with --executor ray only the CPUs of a local "
                             "instance started here (a running cluster brings its own)")
    parser.add_argument("--fault", action="append", default=[], metavar="NAME",
                        help="switch on a stand-in planner fault mode (repeatable): "
                             f"{', '.join(Faults.names())}")
    parser.add_argument("--planner", choices=("standin", "commonroad", "none"), default="standin",
                        help="planner under test: the stand-in (default), CommonRoad's reactive planner "
                             "(make sut-commonroad; runs over ROS), or none (your stack on $ROS_DOMAIN_ID)")
    parser.add_argument("--planner-settings", default="", metavar="YAML",
                        help="settings of a third-party planner adapter (default: its built-in settings)")
    parser.add_argument("--baseline", choices=("standin",), default=None,
                        help="also run the stand-in on the same scenarios; the report separates the planner's own "
                             "failures (the baseline passes) from scenarios that defeat both")
    parser.add_argument("--ros", action="store_true",
                        help="run each scenario over the ROS 2 node graph (separate processes, DDS) instead of "
                             "the in-process cores")
    parser.add_argument("--time-limit", type=TIME_LIMIT, default=None,
                        help="simulated seconds per run (default: the player's limit); part of the run key")
    parser.add_argument("--limit", type=count(ge=0), default=None,
                        help="stop after N new runs (rerun without it to finish: the campaign resumes)")
    parser.add_argument("--no-progress", action="store_true", help="no progress bars")
    parser.add_argument("--retry-errors", action="store_true",
                        help="run again the runs stored with verdict error (harness or graph faults)")


def register(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("inputs", nargs="+", help="report files (.jsonl/.txt/.pdf or a directory), a sketch "
                                                 "JSONL, a seed directory, tree directories or .xosc files")
    parser.add_argument("--out", required=True, help="campaign directory (rerun the same command to resume)")
    add_campaign_options(parser)
    parser.add_argument("--no-report", action="store_true", help="skip the analysis report")


def config_from_args(args: argparse.Namespace, out: Path):
    from ..campaign.pipeline import CampaignConfig

    return CampaignConfig(out=out, seed=args.seed, backend=args.backend, mutations=args.mutations,
                          prune=args.prune, executor=args.executor, workers=args.workers,
                          ray_address=args.ray_address,
                          faults=tuple(args.fault), ros=args.ros, max_seeds=args.max_seeds,
                          limit=args.limit, time_limit=args.time_limit, max_nodes=args.max_nodes,
                          progress=not args.no_progress, report=not getattr(args, "no_report", False),
                          retry_errors=getattr(args, "retry_errors", False),
                          planner=getattr(args, "planner", "standin"),
                          planner_settings=getattr(args, "planner_settings", ""),
                          baseline=getattr(args, "baseline", None))


def print_summary(summary) -> None:
    runs = summary.runs
    print(f"started at: {summary.start_stage}")
    if summary.sketches:
        print(f"sketches:   {summary.sketches}")
    if summary.seeds or summary.refused:
        print(f"seeds:      {summary.seeds} built, {len(summary.refused)} refused")
    print(f"scenarios:  {summary.scenarios}" + (f" in {summary.trees} trees" if summary.trees else ""))
    for r in summary.refused[:MAX_LISTED]:
        print(f"refused {r['report_id']}: {r['error']}", file=sys.stderr)
    if len(summary.refused) > MAX_LISTED:
        print(f"... and {len(summary.refused) - MAX_LISTED} more refused (see seeds/manifest.json)", file=sys.stderr)
    if runs is not None:
        verdicts = ", ".join(f"{v} {n}" for v, n in sorted(runs.verdicts.items())) or "none new"
        line = f"runs:       {runs.ran} new ({verdicts}), {runs.skipped} already judged in an earlier run"
        if runs.duplicates:
            line += f", {runs.duplicates} duplicates (same bytes as another scenario, judged once)"
        if runs.left:
            line += f", {runs.left} left for later (--limit; rerun without it to finish)"
        print(line)
        p = summary.planner
        settings = ", ".join(f"{k}={v}" for k, v in sorted(p.get("settings", {}).items()))
        print(f"planner:    {p['name']} {p.get('version', '')} ({settings})")
    rs = summary.baseline_runs  # the nominal planner's runs beside a faulty one (the runs line is above)
    if rs is not None:
        verdicts = ", ".join(f"{v} {n}" for v, n in sorted(rs.verdicts.items())) or "none new"
        print(f"{'baseline:':<11} {rs.ran} new ({verdicts}), {rs.skipped} already done")
    if summary.report:
        print(f"report:     {summary.report} (+ report.html)")


def _print_errors(out: Path) -> None:
    """One line per stored run with verdict error (a harness or graph fault), so the reason is seen, not only
    counted; `--retry-errors` runs them again."""
    from ..campaign.store import ResultStore

    with ResultStore(out / "results.sqlite") as store:
        errors = [r for r in store.runs() if r.verdict == "error"]
    for r in errors[:MAX_LISTED]:
        print(f"txt2sce campaign: error: run {r.scenario_id}: {r.record.get('error') or 'no reason stored'}",
              file=sys.stderr)
    if len(errors) > MAX_LISTED:
        print(f"txt2sce campaign: ... and {len(errors) - MAX_LISTED} more runs with verdict error", file=sys.stderr)
    if errors:
        print(f"txt2sce campaign: {len(errors)} run(s) with verdict error; rerun with --retry-errors to run them "
              f"again", file=sys.stderr)


def _print_attribution(out: Path) -> None:
    """The console's word on which failures say something about the planner (the report has the same line)."""
    from ..analysis.behaviours import attribution
    from ..campaign.store import ResultStore

    with ResultStore(out / "results.sqlite") as store:
        who = attribution((r.verdict, tuple(r.categories), r.record) for r in store.runs())
    if who.failed:
        print(f"verdicts:   {who.line()}")


def run(args: argparse.Namespace) -> int:
    from ..campaign.pipeline import run_campaign

    summary = run_campaign(args.inputs, config_from_args(args, Path(args.out)))
    print_summary(summary)
    _print_attribution(Path(args.out))
    _print_errors(Path(args.out))
    # 1: some item failed and was recorded (a refused sketch, a run with verdict error); fail verdicts are results.
    errors = summary.runs.verdicts.get("error", 0) if summary.runs is not None else 0
    return 1 if errors or summary.refused else 0
