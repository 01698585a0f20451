"""`txt2sce play FILE.xosc [--ego-mode keep-speed|storyboard|standin] [--csv OUT]`: run one scenario in batch (no ROS)
and print the result, including every contact between footprints.

Who drives the ego:
  keep-speed  (default) nobody: the ego holds its initial speed and heading (a smoke test of a seed)
  storyboard  the scenario's own storyboard, as esmini would (conformance runs, the reported manoeuvre)
  standin     the stand-in planner, in closed loop with the oracle judging (`--fault` switches faults on)
`planner` is the old name of keep-speed, still accepted with a warning."""

from __future__ import annotations

import argparse
import csv
import sys
import time
from pathlib import Path

from .argtypes import count, STEP, TIME_LIMIT

HELP = "run one OpenSCENARIO file in the batch player and print its result (optionally write a CSV trajectory)"

#: --ego-mode values -> what drives the ego (the player's own mode names are 'planner' and 'storyboard').
EGO_MODES = {"keep-speed": "nobody: holds its initial speed and heading",
             "storyboard": "the scenario's storyboard",
             "standin": "the stand-in planner (closed loop, judged by the oracle)"}
DEPRECATED_MODES = {"planner": "keep-speed"}


def register(parser: argparse.ArgumentParser) -> None:
    from standin_planner.faults import Faults

    parser.epilog = __doc__
    parser.add_argument("file", type=Path, help="the .xosc scenario")
    parser.add_argument("--csv", type=Path, help="write the trajectory: time,name,x,y,heading,speed per entity")
    parser.add_argument("--ego-mode", choices=(*EGO_MODES, *DEPRECATED_MODES), default="keep-speed",
                        help="who drives the ego: keep-speed (default), storyboard, or standin (see below)")
    parser.add_argument("--fault", action="append", default=[], metavar="NAME",
                        help=f"standin: switch on a planner fault (repeatable): {', '.join(Faults.names())}")
    parser.add_argument("--time-limit", type=TIME_LIMIT, help="s of simulation time (default: config/player.yaml)")
    parser.add_argument("--dt", type=STEP, default=None,
                        help="step in s, in (0, 1] (default: config/player.yaml, 0.05)")
    parser.add_argument("--seed", type=count(ge=0), default=0)
    parser.add_argument("--map", type=Path, help="OpenDRIVE file to use instead of RoadNetwork/LogicFile")


def _mode(args: argparse.Namespace) -> str:
    from ..errors import InputError

    mode = args.ego_mode
    if mode in DEPRECATED_MODES:
        mode = DEPRECATED_MODES[mode]
        print(f"txt2sce play: warning: --ego-mode {args.ego_mode} is deprecated, use --ego-mode {mode} (the ego "
              "keeps its speed and heading); --ego-mode standin lets the stand-in planner drive", file=sys.stderr)
    if args.fault and mode != "standin":
        raise InputError("--fault needs --ego-mode standin (faults belong to the stand-in planner)",
                         element="--fault")
    if mode == "standin" and args.map:
        raise InputError("--map is not available with --ego-mode standin (it drives on the scenario's own map)",
                         element="--map")
    return mode


def run(args: argparse.Namespace) -> int:
    from scenario_player import Simulation, SimulationConfig, load_scenario

    from ..seed.boxes import first_contacts

    mode = _mode(args)
    frames = []
    t0 = time.perf_counter()
    if mode == "standin":
        from standin_planner.faults import Faults

        from ..closed_loop import run_closed_loop

        Faults.from_names(args.fault)             # an unknown name is a one-line error, not an error run
        record, traj = run_closed_loop(args.file, faults=tuple(args.fault), seed=args.seed, dt=args.dt,
                                       time_limit=args.time_limit, keep_trajectory=True, on_frame=frames.append)
        if record.error:
            from ..errors import InputError

            raise InputError(record.error, source=str(args.file))
        traj = traj or {}
        wall = time.perf_counter() - t0
        print(f"scenario   {args.file}")
        print(f"entities   {', '.join(traj)} (ego driven by {EGO_MODES[mode]}"
              + (f", faults {', '.join(args.fault)}" if args.fault else "") + ")")
        print(f"finished   t={record.sim_time:.2f} s, end reason: {record.end_reason or '-'}")
        print(f"verdict    {record.verdict.value}" + (f": {', '.join(record.categories)}" if record.categories else ""))
        unsupported = list(record.unsupported)
    else:
        scenario = load_scenario(args.file, map_path=str(args.map) if args.map else None)
        config = SimulationConfig.from_config(dt=args.dt, ego_mode="storyboard" if mode == "storyboard" else "planner",
                                              seed=args.seed, time_limit=args.time_limit, scenario_id=args.file.stem)
        sim = Simulation(scenario, config)
        frames.append(sim.reset())
        while not sim.done:
            frames.append(sim.step(None))
        wall = time.perf_counter() - t0
        status = sim.status
        traj = sim.trajectory
        print(f"scenario   {args.file}")
        print(f"map        {scenario.map_path}")
        print(f"entities   {', '.join(scenario.entity_names)} (ego: {sim.ego_name}, driven by {EGO_MODES[mode]})")
        if sim.goal is not None:
            print(f"goal       x={sim.goal.x:.2f} y={sim.goal.y:.2f} tolerance {sim.goal.tolerance:g} m")
        print(f"finished   t={status.t:.2f} s, end reason: {status.end_reason or '-'}"
              f"{', verdict hint: ' + status.verdict_hint if status.verdict_hint else ''}")
        unsupported = list(status.unsupported)
    sim_t = frames[-1].t if frames else 0.0
    print(f"speed      {sim_t / wall if wall > 0 else float('inf'):.0f}x real time ({wall * 1000:.1f} ms wall)")
    contacts = first_contacts(frames)
    # a contact is a fact of the run whoever drives: say so in every mode (a touching rear-end used to be silent)
    print("contacts   " + ("; ".join(f"{a} - {b} at t={t:.2f} s" for a, b, t in contacts) if contacts else "none"))
    for name, rows in traj.items():
        last = rows[-1]
        print(f"  {name:20s} rows {len(rows):5d}  final x={last[1]:9.2f} y={last[2]:9.2f} "
              f"heading={last[3]:6.3f} speed={last[4]:6.2f}")
    for note in unsupported:
        print(f"  {note}")
    if args.csv:
        args.csv.parent.mkdir(parents=True, exist_ok=True)
        with open(args.csv, "w", newline="", encoding="utf-8") as fh:
            w = csv.writer(fh)
            w.writerow(["time", "name", "x", "y", "heading", "speed"])
            rows_all = sorted(((r[0], n, r) for n, rows in traj.items() for r in rows), key=lambda x: (x[0], x[1]))
            for t, n, r in rows_all:
                w.writerow([f"{t:.4f}", n, f"{r[1]:.4f}", f"{r[2]:.4f}", f"{r[3]:.4f}", f"{r[4]:.4f}"])
        print(f"wrote {args.csv}")
    return 0
